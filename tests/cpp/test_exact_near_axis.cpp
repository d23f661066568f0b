// The exact torque-free solution close to a principal axis: the transverse body
// momentum |m⊥| from the smallest subnormal to 1e-3 |L|, log-spaced, about each principal axis, with
// either sign of the axial momentum, for a triaxial body, a permuted one and (nearly) symmetric ones.
//  - state_at(0) is the initial state (no reference needed);
//  - the attitude at t against the steady-spin limit with its first-order correction (below);
//  - FreeRotationFlow (the one-step flow of `exact_flow_kick`) gives the same.
// The reference: m = G e_k + μ with μ ⊥ e_k from the linearised Euler equations
//   μ̇_i = −g a_j μ_j, μ̇_j = g a_i μ_i,  a = 1/I − 1/I_k  ((k, i, j) cyclic, g = m_k = ±G),
// harmonic (axes of the largest and smallest moment) or hyperbolic (the intermediate one), and
//   R(t) = exp(α(t) L̂_W/|L|) R0 B(t),  α = (2T/G) t,  B(t) = exp((m(t) × m0/G²)^)
// (B carries m(t) to m0 to first order, so R(t) m(t) = L_W: the exact decomposition, with α and B to
// first order). Writing the exact solution the same way, α̇ = 2T/G − b·m/G with b the body rate of B,
// |b·m/G| <= 3 G max|a| (|μ|/G)², and B errs by O((|μ|/G)²): the reference is exact to within
//   C (μ_max/G)² (1 + angle turned),  C = 8 I_max/I_min   (angle turned = G |t|/I_k).
// Below |m⊥|/G ~ 1e-9 that is under an ulp per radian; above it the tolerance grows with it, and
// tests/python/test_exact_near_axis.py checks the whole sweep against the closed form in mpmath.
#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/exact/free_body.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;
constexpr double kSmallestSubnormal = std::numeric_limits<double>::denorm_min();

using test::initial_attitude;

// exp(v^) as a unit quaternion (v a rotation vector [rad])
Eigen::Quaterniond exp_rotation(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

struct NearAxisReference {
  Eigen::Quaterniond q_WB;
  double bound;  // its own error [rad]
};

// The steady-spin limit about body axis k with the first-order correction (file comment); I diagonal.
NearAxisReference steady_spin_reference(const Eigen::Vector3d& I, int k, const Eigen::Vector3d& m0, double t) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double G = m0.norm();
  const Eigen::Vector3d a = I.cwiseInverse().array() - 1.0 / I(k);
  const double p = a(i) * a(j) * G * G;  // Ω² (harmonic) or −γ² (hyperbolic)
  const double rate = std::sqrt(std::abs(p));
  double c = 1.0, s = t;  // μ(t) = c μ0 + s (−g a_j μ_j0, g a_i μ_i0)
  if (p > 0.0) c = std::cos(rate * t), s = std::sin(rate * t) / rate;
  if (p < 0.0) c = std::cosh(rate * t), s = std::sinh(rate * t) / rate;
  const double g = m0(k);  // the signed axial momentum sets the sense of the transverse motion
  Eigen::Vector3d m = m0;
  m(i) = c * m0(i) - s * g * a(j) * m0(j);
  m(j) = c * m0(j) + s * g * a(i) * m0(i);
  const Eigen::Vector3d L_W = initial_attitude() * m0;
  const double two_T = m0.cwiseProduct(m0).cwiseQuotient(I).sum();
  const Eigen::Quaterniond q = exp_rotation(L_W / G * (two_T / G * t)) * initial_attitude() * exp_rotation(m.cross(m0) / (G * G));
  // |μ| over [0, t]: |c| <= cosh, |s| <= sinh(γ|t|)/γ (hyperbolic), |c| <= 1, |s| <= min(|t|, 1/Ω)
  const double mu0 = std::hypot(m0(i), m0(j)), a_max = std::max(std::abs(a(i)), std::abs(a(j)));
  const double c_max = p < 0.0 ? std::cosh(rate * t) : 1.0;
  const double s_max = p < 0.0 ? std::abs(s) : p > 0.0 ? std::min(std::abs(t), 1.0 / rate) : std::abs(t);
  const double mu_max = mu0 * (c_max + s_max * G * a_max);
  const double angle = G * std::abs(t) / I(k);
  const double C = 8.0 * I.maxCoeff() / I.minCoeff();
  return {q, C * (mu_max / G) * (mu_max / G) * (1.0 + angle)};
}

struct PrincipalBody {
  std::string name;
  Eigen::Vector3d I;  // diagonal inertia [kg m²]
};

// transverse magnitudes |m⊥|/G: 5e-324, then 1e-320 ... 1e-3 log-spaced (a decade step of 10^(1/2)
// below 1e-300 is not needed: the code's scales are powers of two, so every decade exercises them)
std::vector<double> transverse_magnitudes() {
  std::vector<double> out{kSmallestSubnormal, 1e-322, 1e-320, 1e-315, 1e-310, 1e-308, 2.2250738585072014e-308};
  for (double e = -307.0; e <= -3.0; e += 4.0) out.push_back(std::pow(10.0, e));
  out.push_back(1e-3);
  return out;
}

// every branch and axis: the attitude against the reference to 16 ulps of the angle turned (with
// an ulp of 1 rad below 1 rad: the phases φ, ψ are O(1) there) plus the reference's own bound
TEST(TorqueFreeSolution, NearEachPrincipalAxisKeepsTheAttitudeToUlps) {
  const std::vector<PrincipalBody> bodies = {{"triaxial", {2.0, 3.0, 5.0}},
                                             {"permuted", {3.0, 5.0, 2.0}},
                                             {"oblate symmetric", {2.0, 2.0, 5.0}},
                                             {"nearly oblate", {2.0, 2.0 * (1.0 + 1e-9), 5.0}},
                                             {"prolate symmetric", {2.0, 5.0, 5.0}},
                                             {"nearly prolate", {2.0, 5.0 * (1.0 - 1e-8), 5.0}}};
  const double times[] = {0.1, 1.0, 7.3, 20.0, -5.0};
  double worst_ulps[3] = {0.0, 0.0, 0.0};  // per axis, where the reference's bound is below an ulp
  for (const PrincipalBody& body : bodies) {
    for (int k = 0; k < 3; ++k) {
      for (double sign : {1.0, -1.0}) {
        for (double beta : {0.0, 0.9, 2.6}) {  // direction of the transverse part
          for (double eps_m : transverse_magnitudes()) {
            const int i = (k + 1) % 3, j = (k + 2) % 3;
            Eigen::Vector3d w0 = Eigen::Vector3d::Zero();  // G = 1.3 kg m²/s
            w0(k) = sign * 1.3 / body.I(k);
            w0(i) = 1.3 * eps_m * std::cos(beta) / body.I(i);
            w0(j) = 1.3 * eps_m * std::sin(beta) / body.I(j);
            const Eigen::Vector3d m0 = body.I.cwiseProduct(w0);  // as the solution sees it
            const Eigen::Matrix3d I = body.I.asDiagonal();
            const TorqueFreeSolution s(I, initial_attitude(), w0, InertiaCheck::allow_unrealizable);
            std::ostringstream what_stream;
            what_stream << body.name << ", axis " << k + 1 << ", sign " << sign << ", beta " << beta << ", |m⊥|/G = " << eps_m
                        << ", case " << to_string(s.solution_case());
            const std::string what = what_stream.str();
            // t = 0: the initial state to a few ulps (a phase round trip through sn, cn, dn and Π)
            const TorqueFreeState s0 = s.state_at(0.0);
            EXPECT_LE(s0.q_WB.angularDistance(initial_attitude()), 8 * kEps) << what;
            EXPECT_LE((s0.w_B - w0).norm(), 8 * kEps * w0.norm()) << what;
            const FreeRotationFlow flow(I);
            for (double t : times) {
              const NearAxisReference ref = steady_spin_reference(body.I, k, m0, t);
              const double angle = std::abs(1.3 * t / body.I(k));
              const double ulp = kEps * std::max(1.0, angle);
              const TorqueFreeState st = s.state_at(t);
              const double error = st.q_WB.angularDistance(ref.q_WB);
              EXPECT_LE(error, 16 * ulp + ref.bound) << what << ", t = " << t;
              if (ref.bound < 0.5 * ulp) worst_ulps[k] = std::max(worst_ulps[k], error / ulp);
              Eigen::Quaterniond q = initial_attitude();
              Eigen::Vector3d w = w0;
              flow.advance(q, w, t);  // one step of the exact flow: the same closed form
              EXPECT_LE(q.angularDistance(ref.q_WB), 16 * ulp + ref.bound) << what << ", flow, t = " << t;
              EXPECT_LE((w - st.w_B).norm(), 4 * kEps * w0.norm()) << what << ", flow, t = " << t;
            }
          }
        }
      }
    }
  }
  std::printf("worst attitude error where the reference is exact to < 0.5 ulp [ulps of max(1 rad, angle turned)]: "
              "axis 1 %.2f, axis 2 %.2f, axis 3 %.2f\n",
              worst_ulps[0], worst_ulps[1], worst_ulps[2]);
}

// The reported case: I = diag(2, 3, 5), body momentum (3.5 √(smallest subnormal), 0, 1): the
// elliptic parameter m ~ 1e-323 used to be a subnormal of a few bits (0.010 rad wrong at t = 0).
TEST(TorqueFreeSolution, ReportedCaseNearTheMajorAxis) {
  const Eigen::Vector3d I(2.0, 3.0, 5.0), m0(3.5 * std::sqrt(kSmallestSubnormal), 0.0, 1.0);
  const Eigen::Vector3d w0 = m0.cwiseQuotient(I);
  const TorqueFreeSolution s(I.asDiagonal(), initial_attitude(), w0, InertiaCheck::allow_unrealizable);
  EXPECT_EQ(s.solution_case(), TorqueFreeCase::A);
  EXPECT_LE(s.state_at(0.0).q_WB.angularDistance(initial_attitude()), 8 * kEps);
  for (double t : {0.5, 20.0}) {
    const NearAxisReference ref = steady_spin_reference(I, 2, I.cwiseProduct(w0), t);
    // the reference errs by ~1e-321 rad here; 16 ulps of the angle turned (t/5 rad)
    EXPECT_LE(s.state_at(t).q_WB.angularDistance(ref.q_WB), 16 * kEps * std::max(1.0, t / 5.0) + ref.bound) << t;
  }
}

}  // namespace
}  // namespace rigiddyn
