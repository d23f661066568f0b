#include "rigiddyn/simulate/balance.hpp"

#include "numbers.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>

namespace rigiddyn {

namespace {

using detail::nan;
constexpr auto energy = static_cast<std::size_t>(BalanceQuantity::energy);
constexpr auto linear = static_cast<std::size_t>(BalanceQuantity::linear_momentum);
constexpr auto angular = static_cast<std::size_t>(BalanceQuantity::angular_momentum);

using Vector3Map = Eigen::Map<const Eigen::Vector3d>;

// The sum of x[0..n) in the order numpy's pairwise summation takes (sum(axis=-1) of a row): sequential below 8 terms,
// 8 interleaved partial sums up to 128, halves above; so that r_E equals T - T0 - work.sum(axis=1) to the bit.
double pairwise_sum(const double* x, std::size_t n) {
  if (n < 8) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += x[i];
    return sum;
  }
  if (n <= 128) {
    std::array<double, 8> r{};
    for (std::size_t j = 0; j < 8; ++j) r[j] = x[j];
    std::size_t i = 8;
    for (; i < n - n % 8; i += 8) {
      for (std::size_t j = 0; j < 8; ++j) r[j] += x[i + j];
    }
    double sum = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < n; ++i) sum += x[i];
    return sum;
  }
  std::size_t half = n / 2;
  half -= half % 8;
  return pairwise_sum(x, half) + pairwise_sum(x + half, n - half);
}

// The sum of |x[0..n)|, in pairwise_sum's order.
double pairwise_abs_sum(const double* x, std::size_t n, std::vector<double>& scratch) {
  scratch.resize(n);
  for (std::size_t i = 0; i < n; ++i) scratch[i] = std::abs(x[i]);
  return pairwise_sum(scratch.data(), n);
}

// max(a, b) that keeps a NaN (as numpy's maximum): a running maximum stays NaN after a non-finite record.
double nan_max(double a, double b) { return (std::isnan(a) || std::isnan(b)) ? nan : std::max(a, b); }

// x[i] = max(x[0..i]) in place (numpy's maximum.accumulate).
void running_max(std::vector<double>& x) {
  for (std::size_t i = 1; i < x.size(); ++i) x[i] = nan_max(x[i - 1], x[i]);
}

// |v| of a 3-vector, as sqrt(v·v).
double norm3(const Eigen::Vector3d& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The steps from t0 to each record: rint((t − t0) / dt).
std::vector<double> steps_of(const std::vector<double>& t, double dt) {
  std::vector<double> steps(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) steps[i] = std::nearbyint((t[i] - t[0]) / dt);
  return steps;
}

// The round-off a residual whose terms have size `size` (n,) can hold after `steps` (n,) steps: 8 ε |size| per
// step, summed (the global error estimate's bound, global_error.cpp).
std::vector<double> round_off_of(const std::vector<double>& size, const std::vector<double>& steps) {
  std::vector<double> out(size.size());
  for (std::size_t i = 0; i < size.size(); ++i) out[i] = 8.0 * DBL_EPSILON * std::abs(size[i]) * std::max(steps[i], 1.0);
  return out;
}

// Sets quantity q of b to NaN residuals with the verdict "not applicable: <why>".
void set_not_applicable(RunBalance& b, std::size_t q, std::size_t n, const std::string& why) {
  b.residual[q].assign(n, nan);
  b.round_off[q].assign(n, nan);
  b.scale[q].assign(n, nan);
  b.verdict[q] = "not applicable: " + why;
}

// The energy balance of records with kinetic energy T, total energy E and inputs (n,) (the works, mass-flow
// energies and motor works summed; `magnitude` the sum of their absolute values): r_E = T − T0 − inputs, its scale
// |E0| + T0 + the largest magnitude so far, its round-off from the terms T + |E − T| + magnitude.
void set_energy(RunBalance& b, const std::vector<double>& T, const std::vector<double>& E,
                const std::vector<double>& inputs, const std::vector<double>& magnitude, const std::vector<double>& steps) {
  const std::size_t n = T.size();
  std::vector<double>& r = b.residual[energy];
  std::vector<double>& scale = b.scale[energy];
  std::vector<double> size(n);
  r.resize(n), scale.resize(n);
  std::vector<double> largest = magnitude;
  running_max(largest);
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = T[i] - T[0] - inputs[i];
    scale[i] = std::abs(E[0]) + T[0] + largest[i];
    size[i] = T[i] + std::abs(E[i] - T[i]) + magnitude[i];
  }
  running_max(size);
  b.round_off[energy] = round_off_of(size, steps);
}

}  // namespace

bool RunBalance::applies(BalanceQuantity q) const {
  return verdict[static_cast<std::size_t>(q)].rfind("not applicable", 0) != 0;
}

RunBalance scene_balance(const SceneSimulation& r, const std::string& not_applicable, double dt) {
  const std::size_t n = r.size();
  const auto nb = static_cast<std::size_t>(r.body_count), ne = static_cast<std::size_t>(r.element_count);
  const std::size_t nw = n ? r.motor_work.size() / n : 0;
  const bool mass_flow = !r.mass_flow_energy.empty();  // empty: every body's mass-flow energy is 0
  const std::vector<double> steps = steps_of(r.t, dt);
  RunBalance b;
  b.about = "W's origin";
  b.verdict.fill("closed");
  // r_E = T − T0 − Σ W_e − Σ E_b − Σ W_motor (scene_simulation.hpp: the works hold every element's)
  std::vector<double> inputs(n), magnitude(n), scratch;
  for (std::size_t i = 0; i < n; ++i) {
    const double* W = r.work.data() + i * ne;
    const double* W_motor = r.motor_work.data() + i * nw;
    const double* E_b = mass_flow ? r.mass_flow_energy.data() + i * nb : nullptr;
    inputs[i] = pairwise_sum(W, ne) + (mass_flow ? pairwise_sum(E_b, nb) : 0.0) + pairwise_sum(W_motor, nw);
    magnitude[i] = pairwise_abs_sum(W, ne, scratch) + (mass_flow ? pairwise_abs_sum(E_b, nb, scratch) : 0.0) +
                   pairwise_abs_sum(W_motor, nw, scratch);
  }
  set_energy(b, r.kinetic_energy, r.total_energy, inputs, magnitude, steps);
  if (!not_applicable.empty() || r.impulse_W.size() != 3 * n || r.angular_impulse_W.size() != 3 * n) {
    const std::string why = not_applicable.empty() ? "its path does not integrate the impulses" : not_applicable;
    set_not_applicable(b, linear, n, why);
    set_not_applicable(b, angular, n, why);
    return b;
  }
  // r_P = P − P0 − J, r_H = H − H0 − K about W's origin (scene_model.hpp)
  std::vector<double> linear_size(n), angular_size(n), largest_J(n), largest_K(n);
  double mv_sum0 = 0.0, moments0 = 0.0;
  for (auto* a : {&b.residual[linear], &b.residual[angular], &b.scale[linear], &b.scale[angular]}) a->resize(n);
  std::vector<double> mv_norms(nb), moment_norms(nb), H_C_norms(nb);
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3Map J(&r.impulse_W[3 * i]), K(&r.angular_impulse_W[3 * i]);
    b.residual[linear][i] = norm3(Vector3Map(&r.linear_momentum_W[3 * i]) - Vector3Map(&r.linear_momentum_W[0]) - J);
    b.residual[angular][i] =
        norm3(Vector3Map(&r.angular_momentum_W[3 * i]) - Vector3Map(&r.angular_momentum_W[0]) - K);
    double w_max = 0.0;
    for (std::size_t k = 0; k < nb; ++k) {
      const std::size_t at = (i * nb + k) * 3;
      const Eigen::Vector3d mv = r.mass[i * nb + k] * Vector3Map(&r.v_W[at]);
      mv_norms[k] = norm3(mv);
      // |p| |m v|, not |p × m v|: the size of the moment's rounding (ε |p| |m v|), which stays where p and v are
      // parallel and the moment cancels (a body moving along a line through W's origin)
      moment_norms[k] = norm3(Vector3Map(&r.p_W[at])) * mv_norms[k];
      H_C_norms[k] = norm3(Vector3Map(&r.angular_momentum_O_W[at]));
      w_max = k == 0 ? norm3(Vector3Map(&r.w_B[at])) : nan_max(w_max, norm3(Vector3Map(&r.w_B[at])));
    }
    const double mv_sum = pairwise_sum(mv_norms.data(), nb);
    const double moments = pairwise_sum(moment_norms.data(), nb) + pairwise_sum(H_C_norms.data(), nb);
    if (i == 0) mv_sum0 = mv_sum, moments0 = moments;
    // the parts' size where they cancel (a gyrostat's body and wheels, H_C ~ 0): 2 T / |w| <= |H| of a turning body
    const double turning = w_max > 0 ? 2.0 * r.kinetic_energy[i] / w_max : 0.0;
    largest_J[i] = norm3(J), largest_K[i] = norm3(K);
    linear_size[i] = mv_sum + norm3(J);
    angular_size[i] = moments + norm3(K) + turning;
  }
  running_max(largest_J), running_max(largest_K), running_max(linear_size), running_max(angular_size);
  // the scale: the parts' momenta at t0 and the impulses so far, or the parts' largest momenta so far where those
  // are larger (a scene at rest at t0 set moving by internal forces: its totals stay 0 while its parts move)
  for (std::size_t i = 0; i < n; ++i) {
    b.scale[linear][i] = std::max(mv_sum0 + largest_J[i], linear_size[i]);
    b.scale[angular][i] = std::max(moments0 + largest_K[i], angular_size[i]);
  }
  b.round_off[linear] = round_off_of(linear_size, steps);
  b.round_off[angular] = round_off_of(angular_size, steps);
  return b;
}

}  // namespace rigiddyn
