// The compound pendulum in Jacobi's elliptic functions (exact/compound_pendulum.hpp).
#include "rigiddyn/exact/compound_pendulum.hpp"

#include "numbers.hpp"
#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rigiddyn {

namespace {

using detail::infinity;
using detail::ln_4;


// am(u|m) continued through every half period: am(u + 2K) = am(u) + π (DLMF 22.16.2), with |w| ≤ K
// where am(w) = atan2(sn w, cn w) ∈ [−π/2, π/2]; for m = 1 (K = ∞) the Gudermannian atan2(tanh, sech).
double amplitude_am(double u, const EllipticParameter& p, JacobiSnCnDn& f) {
  if (p.kc == 0.0) {
    f = jacobi_ellipj(u, p);
    return std::atan2(f.sn, f.cn);
  }
  const double half_periods = std::nearbyint(u / (2.0 * p.K));
  const double w = std::fma(-2.0 * p.K, half_periods, u);
  f = jacobi_ellipj(w, p);
  return half_periods * M_PI + std::atan2(f.sn, f.cn);
}

// R_F(a², b², 1) for a, b ∈ [0, 1], not both 0 (DLMF 19.16.1), also where a² and b² underflow: for
// a, b < 2^−40 the limit R_F(x, y, 1) = ln(4/(√x + √y)) + O(x + y) (from R_F(0, y, 1) = K(1 − y) ≈ ln(4/√y),
// DLMF 19.12.1, and R_F(x, x, 1) = R_C(1, x) = arccosh(1/√x)/√(1 − x), DLMF 19.2.19), relative error below
// 2^−79 · ln-factor ≪ eps; else elliprf, where a square that underflows beside the other's ≥ 2^−80
// changes R_F by O(a/b) < 1e-130 relative.
double elliprf_of_squares(double a, double b) {
  if (std::max(a, b) < 0x1p-40) return ln_4 - std::log(a + b);  // ln 4 − ln: 4/(a + b) may overflow
  return elliprf(a * a, b * b, 1.0);
}

}  // namespace

std::string to_string(PendulumCase c) {
  switch (c) {
    case PendulumCase::rest: return "rest";
    case PendulumCase::uniform: return "uniform";
    case PendulumCase::libration: return "libration";
    case PendulumCase::rotation: return "rotation";
    case PendulumCase::separatrix: return "separatrix";
  }
  throw std::logic_error("to_string: unknown PendulumCase");
}

CompoundPendulumSolution::CompoundPendulumSolution(const PivotedPlanarBody& body, const Eigen::Vector3d& g_W,
                                                   const PivotedPlanarBodyState& state) {
  require_finite(g_W, "g_W");
  const PivotedPlanarBodyState s0 = checked_state(state, "state");
  theta0_ = s0.theta;
  omega_init_ = s0.omega;
  const Eigen::Vector2d g_xy = g_W.head<2>(), c = body.p_OC_B();
  const double g = g_xy.stableNorm(), d = c.stableNorm(), I_O = body.inertia_O_zz();  // scaled: |g| ~ 1e-300
  // ϑ = θ + γ − θ_g: γ the angle of c in B, θ_g that of g in W's plane
  const double gamma = std::atan2(c.y(), c.x()), theta_g = std::atan2(g_xy.y(), g_xy.x());
  theta_stable_ = std::remainder(theta_g - gamma, 2.0 * M_PI);
  vartheta0_ = std::remainder(theta0_ + (gamma - theta_g), 2.0 * M_PI);  // γ − θ_g first: exact when they agree
  const double mgd = body.mass() * g * d;
  energy_ = 0.5 * (I_O * omega_init_) * omega_init_ - mgd * std::cos(vartheta0_);  // no ω² alone (overflow)
  omega0_ = std::sqrt(mgd / I_O);
  if (!(omega0_ > 0.0)) {  // no torque: a uniform turn
    case_ = PendulumCase::uniform;
    amplitude_ = M_PI;
    period_ = omega_init_ == 0.0 ? infinity : 2.0 * M_PI / std::abs(omega_init_);
    return;
  }
  // s = sin(ϑ0/2), c = cos(ϑ0/2) (from π − |ϑ0| near π: Sterbenz makes it exact), v = ϑ̇0/(2ω0).
  // Nothing below squares s, c or v alone: they span the double range (s ~ 1e-170, |v| ~ 1e160, c and |v|
  // ~ 1e-300 near the top), where s², v² and c² − v² underflow or overflow. The case follows from c vs |v|
  // (the sign of mc); the elliptic functions use the scaled ŝ = s/k, v̂ = v/k (libration) or 1/k = ω0/λ
  // (rotation), and the complementary modulus kc = √(c − |v|) √(c + |v|) (scaled by 1/k in rotation).
  const double half = 0.5 * vartheta0_, s = std::sin(half);
  const double cs = std::abs(vartheta0_) > 0.5 * M_PI ? std::sin(0.5 * (M_PI - std::abs(vartheta0_))) : std::cos(half);
  const double v = omega_init_ / (2.0 * omega0_), abs_v = std::abs(v);
  k_ = std::hypot(s, v);  // +inf only where |v| overflows (then only the rotation below uses λ, not k)
  m_ = k_ * k_;           // the accessors' k² and 1 − k²: they saturate to ±inf (or round to 0) beyond the range
  mc_ = (cs - abs_v) * (cs + abs_v);
  if (v == 0.0 && (s == 0.0 || cs == 0.0)) {  // an equilibrium (at ϑ0 = π: the unstable one)
    case_ = PendulumCase::rest;
    amplitude_ = std::abs(vartheta0_);
    period_ = infinity;
    return;
  }
  if (cs > abs_v) {
    // libration: sn(u0) = s/k, cn(u0) = v/k, dn(u0) = c; F(φ0|m) = sn R_F(cn², dn², 1) (DLMF 19.25.5),
    // and F(π − φ) = 2K − F(φ) when cn(u0) < 0
    case_ = PendulumCase::libration;
    const double kc = std::sqrt(cs - abs_v) * std::sqrt(cs + abs_v), mc = kc * kc;
    p_ = elliptic_parameter_kc(mc < 0.5 ? 1.0 - mc : m_, kc, std::log(kc));
    lambda_ = omega0_;
    const double F0 = (s / k_) * elliprf_of_squares(abs_v / k_, cs);
    u0_ = v >= 0.0 ? F0 : std::copysign(2.0 * p_.K, s) - F0;
    period_ = 4.0 * p_.K / omega0_;
    amplitude_ = 2.0 * std::atan2(k_, p_.kc);
    return;
  }
  // rotation (and the separatrix c = |v|, parameter 1): ϑ/2 = σ am(u|1/m), am(u0) = σ ϑ0/2 ∈ [−π/2, π/2]:
  // u0 = σ s R_F(c², 1 − s²/m, 1) with 1 − s²/m = v²/k²; λ = k ω0 = hypot(s ω0, ϑ̇0/2) (finite also where
  // v overflows); the parameter 1/m = (ω0/λ)² with kc = √(v² − c²)/k
  sigma_ = omega_init_ >= 0.0 ? 1.0 : -1.0;
  lambda_ = std::hypot(s * omega0_, 0.5 * omega_init_);
  if (cs == abs_v) {
    case_ = PendulumCase::separatrix;
    lambda_ = omega0_;  // k = 1
    p_ = elliptic_parameter(1.0, 0.0);
    u0_ = sigma_ * s * elliprf_of_squares(cs, cs);
    period_ = infinity;
    amplitude_ = M_PI;
    return;
  }
  case_ = PendulumCase::rotation;
  const double k_inv = omega0_ / lambda_;
  // |v| = inf: 1/k² < 1e-300, the turn is uniform to far below eps (kc = 1, m = (1/k)²)
  const double kc = std::isinf(v) ? 1.0 : std::min(1.0, std::sqrt(abs_v - cs) * std::sqrt(abs_v + cs) * k_inv);
  const double mc = kc * kc;
  p_ = elliptic_parameter_kc(mc < 0.5 ? 1.0 - mc : k_inv * k_inv, kc, std::log(kc));
  u0_ = sigma_ * s * elliprf_of_squares(cs, std::isinf(v) ? 1.0 : std::min(1.0, abs_v * k_inv));
  period_ = 2.0 * p_.K / lambda_;
  amplitude_ = M_PI;
}

double CompoundPendulumSolution::theta_at(double t, double& omega) const {
  switch (case_) {
    case PendulumCase::rest: omega = 0.0; return vartheta0_;
    case PendulumCase::uniform: omega = omega_init_; return vartheta0_ + omega_init_ * t;
    case PendulumCase::libration: {
      // sin(ϑ/2) = k sn, cos(ϑ/2) = dn, ϑ̇ = 2 k ω0 cn
      const JacobiSnCnDn f = jacobi_ellipj(lambda_ * t + u0_, p_);
      omega = 2.0 * k_ * omega0_ * f.cn;
      return 2.0 * std::atan2(k_ * f.sn, f.dn);
    }
    case PendulumCase::rotation:
    case PendulumCase::separatrix: {
      // ϑ = 2σ am(u|1/m), ϑ̇ = 2σ k ω0 dn
      JacobiSnCnDn f{};
      const double am = amplitude_am(lambda_ * t + u0_, p_, f);
      omega = 2.0 * sigma_ * lambda_ * f.dn;
      return 2.0 * sigma_ * am;
    }
  }
  throw std::logic_error("CompoundPendulumSolution: unknown case");
}

PivotedPlanarBodyState CompoundPendulumSolution::at(double t) const {
  require_finite(t, "t");
  if (!std::isfinite(lambda_ * t + u0_)) {  // the phase itself is beyond the range (θ(t) would be too)
    throw_invalid("t", "a time at which the phase λ t of the motion is within the double range", t);
  }
  PivotedPlanarBodyState s;
  const double vartheta = theta_at(t, s.omega);
  s.theta = theta0_ + (vartheta - vartheta0_);
  if (!(std::isfinite(s.theta) && std::isfinite(s.omega))) {  // the uniform turn's ω t beyond the range
    throw_invalid("t", "a time at which θ(t) is within the double range", t);
  }
  return s;
}

}  // namespace rigiddyn
