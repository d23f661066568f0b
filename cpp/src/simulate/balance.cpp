#include "rigiddyn/simulate/balance.hpp"

#include "numbers.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace rigiddyn {

namespace {

using detail::nan;
constexpr auto energy = static_cast<std::size_t>(BalanceQuantity::energy);
constexpr auto linear = static_cast<std::size_t>(BalanceQuantity::linear_momentum);
constexpr auto angular = static_cast<std::size_t>(BalanceQuantity::angular_momentum);

using Vector3Map = Eigen::Map<const Eigen::Vector3d>;

// The sum of f(x[0..n)) in the order numpy's pairwise summation takes (sum(axis=-1) of a row): sequential below 8
// terms, 8 interleaved partial sums up to 128, halves above; so that r_E equals T - T0 - work.sum(axis=1) to the bit.
template <class F>
double pairwise_sum_blocks(const double* x, std::size_t n, F f);

template <class F>
inline double pairwise_sum(const double* x, std::size_t n, F f) {
  if (n >= 8) return pairwise_sum_blocks(x, n, f);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += f(x[i]);
  return sum;
}

// pairwise_sum of n >= 8 terms
template <class F>
double pairwise_sum_blocks(const double* x, std::size_t n, F f) {
  if (n <= 128) {
    std::array<double, 8> r{};
    for (std::size_t j = 0; j < 8; ++j) r[j] = f(x[j]);
    std::size_t i = 8;
    for (; i < n - n % 8; i += 8) {
      for (std::size_t j = 0; j < 8; ++j) r[j] += f(x[i + j]);
    }
    double sum = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < n; ++i) sum += f(x[i]);
    return sum;
  }
  std::size_t half = n / 2;
  half -= half % 8;
  return pairwise_sum(x, half, f) + pairwise_sum(x + half, n - half, f);
}

inline double pairwise_sum(const double* x, std::size_t n) {
  return pairwise_sum(x, n, [](double v) { return v; });
}

// The sum of |x[0..n)|, in pairwise_sum's order.
inline double pairwise_abs_sum(const double* x, std::size_t n) {
  return pairwise_sum(x, n, [](double v) { return std::abs(v); });
}

// max(a, b) that keeps a NaN (as numpy's maximum): a running maximum stays NaN after a non-finite record.
double nan_max(double a, double b) { return (std::isnan(a) || std::isnan(b)) ? nan : std::max(a, b); }

// The running maximum max(x[0..i]) of the values given one record at a time (numpy's maximum.accumulate).
class RunningMax {
 public:
  double operator()(double x) {
    value_ = first_ ? x : nan_max(value_, x);
    first_ = false;
    return value_;
  }

 private:
  double value_ = 0.0;
  bool first_ = true;
};

// |v| of a 3-vector, as sqrt(v·v).
double norm3(const Eigen::Vector3d& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The round-off a residual whose terms have size `size` can hold after `steps` steps (at least 1: steps_at): 8 ε
// |size| per step, summed (the global error estimate's bound, global_error.cpp).
double round_off_of(double size, double steps) { return 8.0 * DBL_EPSILON * std::abs(size) * steps; }

// The steps of each record of run r from its first, at least 1: max(rint((t − t0) / dt), 1), found once for the
// three quantities' round-offs.
std::vector<double> steps_at(const SceneSimulation& r, double dt) {
  std::vector<double> steps(r.size());
  for (std::size_t i = 0; i < steps.size(); ++i) steps[i] = std::max(std::nearbyint((r.t[i] - r.t[0]) / dt), 1.0);
  return steps;
}

// Sets quantity q of b to NaN residuals with the verdict "not applicable: <why>".
void set_not_applicable(RunBalance& b, std::size_t q, std::size_t n, const std::string& why) {
  std::fill_n(b.residual(q), n, nan);
  std::fill_n(b.round_off(q), n, nan);
  std::fill_n(b.scale(q), n, nan);
  b.verdict[q] = "not applicable: " + why;
}

// The energy balance of run r's records at `steps` (record i: steps[i] steps from t0, steps_at), with the works,
// mass-flow energies and motor works summed as inputs (`magnitude` the sum of their absolute values): r_E = T − T0 −
// inputs, its scale |E0| + T0 + the largest magnitude so far, its round-off from the terms T + |E − T| + magnitude.
void set_energy(RunBalance& b, const SceneSimulation& r, const std::vector<double>& steps) {
  const std::size_t n = r.size();
  const auto nb = static_cast<std::size_t>(r.body_count), ne = static_cast<std::size_t>(r.element_count);
  const std::size_t nw = n ? r.motor_work.size() / n : 0;
  const bool mass_flow = !r.mass_flow_energy.empty();  // empty: every body's mass-flow energy is 0
  const std::vector<double>& T = r.kinetic_energy;
  const std::vector<double>& E = r.total_energy;
  RunningMax largest, size;
  for (std::size_t i = 0; i < n; ++i) {
    // r_E = T − T0 − Σ W_e − Σ E_b − Σ W_motor (scene_simulation.hpp: the works hold every element's)
    const double* W = r.work.data() + i * ne;
    const double* W_motor = r.motor_work.data() + i * nw;
    const double* E_b = mass_flow ? r.mass_flow_energy.data() + i * nb : nullptr;
    const double inputs = pairwise_sum(W, ne) + (mass_flow ? pairwise_sum(E_b, nb) : 0.0) + pairwise_sum(W_motor, nw);
    const double magnitude = pairwise_abs_sum(W, ne) + (mass_flow ? pairwise_abs_sum(E_b, nb) : 0.0) +
                             pairwise_abs_sum(W_motor, nw);
    b.residual(energy)[i] = T[i] - T[0] - inputs;
    b.scale(energy)[i] = std::abs(E[0]) + T[0] + largest(magnitude);
    b.round_off(energy)[i] = round_off_of(size(T[i] + std::abs(E[i] - T[i]) + magnitude), steps[i]);
  }
}

// The momentum balances of run r's records at `steps`: r_P = |P − P0 − J|, r_H = |H − H0 − K| about W's origin
// (scene_model.hpp), their scales and round-offs from the sizes of the bodies' momenta and of the impulses.
void set_momenta(RunBalance& b, const SceneSimulation& r, const std::vector<double>& steps) {
  const std::size_t n = r.size();
  const auto nb = static_cast<std::size_t>(r.body_count);
  std::vector<double> parts(3 * nb);  // each body's |m v|, |p| |m v| and |H_C| at a record
  double* mv_norms = parts.data();
  double* moment_norms = mv_norms + nb;
  double* H_C_norms = moment_norms + nb;
  double mv_sum0 = 0.0, moments0 = 0.0;
  RunningMax largest_J, largest_K, linear_size, angular_size;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3Map J(&r.impulse_W[3 * i]), K(&r.angular_impulse_W[3 * i]);
    b.residual(linear)[i] = norm3(Vector3Map(&r.linear_momentum_W[3 * i]) - Vector3Map(&r.linear_momentum_W[0]) - J);
    b.residual(angular)[i] =
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
    const double mv_sum = pairwise_sum(mv_norms, nb);
    const double moments = pairwise_sum(moment_norms, nb) + pairwise_sum(H_C_norms, nb);
    if (i == 0) mv_sum0 = mv_sum, moments0 = moments;
    // the parts' size where they cancel (a gyrostat's body and wheels, H_C ~ 0): 2 T / |w| <= |H| of a turning body
    const double turning = w_max > 0 ? 2.0 * r.kinetic_energy[i] / w_max : 0.0;
    const double J_norm = norm3(J), K_norm = norm3(K);
    const double linear_size_i = linear_size(mv_sum + J_norm);
    const double angular_size_i = angular_size(moments + K_norm + turning);
    // the scale: the parts' momenta at t0 and the impulses so far, or the parts' largest momenta so far where those
    // are larger (a scene at rest at t0 set moving by internal forces: its totals stay 0 while its parts move)
    b.scale(linear)[i] = std::max(mv_sum0 + largest_J(J_norm), linear_size_i);
    b.scale(angular)[i] = std::max(moments0 + largest_K(K_norm), angular_size_i);
    b.round_off(linear)[i] = round_off_of(linear_size_i, steps[i]);
    b.round_off(angular)[i] = round_off_of(angular_size_i, steps[i]);
  }
}

}  // namespace

bool RunBalance::applies(BalanceQuantity q) const {
  return verdict[static_cast<std::size_t>(q)].rfind("not applicable", 0) != 0;
}

RunBalance scene_balance(const SceneSimulation& r, const std::string& not_applicable, double dt) {
  const std::size_t n = r.size();
  const std::vector<double> steps = steps_at(r, dt);
  RunBalance b(n);
  b.about = "W's origin";
  b.verdict.fill("closed");
  set_energy(b, r, steps);
  if (!not_applicable.empty() || r.impulse_W.size() != 3 * n || r.angular_impulse_W.size() != 3 * n) {
    const std::string why = not_applicable.empty() ? "its path does not integrate the impulses" : not_applicable;
    set_not_applicable(b, linear, n, why);
    set_not_applicable(b, angular, n, why);
    return b;
  }
  set_momenta(b, r, steps);
  return b;
}

}  // namespace rigiddyn
