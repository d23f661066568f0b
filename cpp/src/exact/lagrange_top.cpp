// The heavy symmetric top in Jacobi's elliptic functions and Legendre's third integral
// (exact/lagrange_top.hpp).
#include "rigiddyn/exact/lagrange_top.hpp"

#include "numbers.hpp"
#include "rigiddyn/check.hpp"
#include "power_of_two.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rigiddyn {

namespace {

using detail::epsilon;
using detail::infinity;


// Columns (e1, e2, e3) of a right-handed orthonormal frame in B with e3 = axis (unit).
Eigen::Matrix3d frame_about_axis(const Eigen::Vector3d& e3) {
  Eigen::Index i = 0;
  e3.cwiseAbs().minCoeff(&i);
  const Eigen::Vector3d helper = Eigen::Vector3d::Unit(i);
  const Eigen::Vector3d e1 = (helper - helper.dot(e3) * e3).normalized();
  Eigen::Matrix3d R;
  R << e1, e3.cross(e1), e3;
  return R;
}

// θ = 2 atan2(√(1 − u), √(1 + u)) from 1 − u and 1 + u (full precision near θ = 0 and π).
double angle_of(double one_minus_u, double one_plus_u) {
  return 2.0 * std::atan2(std::sqrt(std::max(one_minus_u, 0.0)), std::sqrt(std::max(one_plus_u, 0.0)));
}

// The two roots of x² + p x + q (real by the caller's construction: a negative discriminant from
// rounding is taken as 0), smaller first, without cancellation (the larger-magnitude root first, the
// other as q over it). The discriminant is scaled by S = max(|p|, 2√|q|): √(p² − 4q) = S √((p/S)² − 4 (q/S)/S),
// so that p² cannot overflow (|p| ~ a²/β ~ 1e200 for a fast spin) nor 4q underflow beside it harmfully.
Eigen::Vector2d quadratic_roots(double p, double q) {
  const double S = std::max(std::abs(p), 2.0 * std::sqrt(std::abs(q)));
  if (S == 0.0) return Eigen::Vector2d::Zero();
  const double p_s = p / S, D_s = std::max(p_s * p_s - 4.0 * ((q / S) / S), 0.0);
  const double big = -0.5 * (p + std::copysign(S * std::sqrt(D_s), p));
  const double other = big == 0.0 ? 0.0 : q / big;
  return Eigen::Vector2d(std::min(big, other), std::max(big, other));
}

}  // namespace

std::string to_string(LagrangeTopCase c) {
  switch (c) {
    case LagrangeTopCase::nutation: return "nutation";
    case LagrangeTopCase::sleeping: return "sleeping";
  }
  throw std::logic_error("to_string: unknown LagrangeTopCase");
}

LagrangeTopSolution::LagrangeTopSolution(const PivotedBody& body, const Eigen::Vector3d& g_W,
                                         const PivotedBodyState& state) {
  require_finite(g_W, "g_W");
  const double g = g_W.stableNorm();  // scaled: the squares of |g| ~ 1e-200 underflow
  if (!(g > 0.0)) throw_invalid("g_W", "a non-zero gravity (without it the top is torque-free: TorqueFreeSolution)", g_W.transpose().eval());
  const PivotedBodyState s0 = checked_state(state, "state");
  const Eigen::Vector3d c = body.p_OC_B();
  const double l = c.stableNorm();
  if (!(l > 0.0)) throw_invalid("body", "the centre of mass off the pivot (p_OC_B non-zero)", c.transpose().eval());
  // I_O symmetric about e3: I_O = I1 (1 − e3 e3ᵀ) + I3 e3 e3ᵀ to 1e-12 relative
  const Eigen::Vector3d e3 = c / l;
  const Eigen::Matrix3d& I_O = body.inertia_O();
  I3_ = e3.dot(I_O * e3);
  I1_ = 0.5 * (I_O.trace() - I3_);
  const Eigen::Matrix3d symmetric = I1_ * Eigen::Matrix3d::Identity() + (I3_ - I1_) * e3 * e3.transpose();
  if (!((I_O - symmetric).cwiseAbs().maxCoeff() <= 1e-12 * I_O.cwiseAbs().maxCoeff())) {
    throw_invalid("body", "an inertia about O symmetric about the axis O->C (I1 (1 - e eT) + I3 e eT to 1e-12 relative, e = p_OC_B/|p_OC_B|)", I_O);
  }
  R_BS_ = frame_about_axis(e3);
  q_SB_ = Eigen::Quaterniond(R_BS_.transpose());
  q_WB0_ = s0.q_WB;
  const Eigen::Vector3d z_N = -g_W / g;
  // the vertical and ω in S: z_S = R_SB R_BW z_N = (z1, z2, u0), ω_S = R_SB w_B
  const Eigen::Vector3d z_S = R_BS_.transpose() * (s0.q_WB.conjugate() * z_N);
  const Eigen::Vector3d w_S = R_BS_.transpose() * s0.w_B;
  const double z1 = z_S.x(), z2 = z_S.y(), w1 = w_S.x(), w2 = w_S.y();
  u0_ = z_S.z();
  omega3_ = w_S.z();
  energy_ = 0.5 * s0.w_B.dot(I_O * s0.w_B) - body.mass() * g_W.dot(s0.q_WB * c);
  const double s0_squared = z1 * z1 + z2 * z2, kappa = w1 * w1 + w2 * w2;
  // 1 ∓ u0 from sin²θ0 where the subtraction would cancel
  one_minus_u0_ = u0_ >= 0.0 ? s0_squared / (1.0 + u0_) : 1.0 - u0_;
  one_plus_u0_ = u0_ >= 0.0 ? 1.0 + u0_ : s0_squared / (1.0 - u0_);
  // Lagrange's constants (Goldstein §5.7): a, b, α, β
  beta_ = 2.0 * body.mass() * g * l / I1_;
  a_ = I3_ * omega3_ / I1_;
  rho0_ = w1 * z1 + w2 * z2;  // b − a u0 = φ̇0 sin²θ0
  b_ = rho0_ + a_ * u0_;
  alpha_ = kappa + beta_ * u0_;
  // sleeping: e3 vertical and ω along it, to the rounding of the state (|z⊥| ≤ 4 eps, |ω⊥| ≤ 4 eps |ω3|)
  const double tiny = 16.0 * epsilon * epsilon;
  if (s0_squared <= tiny) {
    if (kappa > tiny * omega3_ * omega3_) {
      throw_invalid("state", "a motion whose symmetry axis does not pass through the vertical (here e3 is vertical "
                             "at t = 0 while w_B has a part across it)", w_S.transpose().eval());
    }
    // sleeping: a uniform spin about the vertical e3
    case_ = LagrangeTopCase::sleeping;
    x_.setZero();
    theta_min_ = theta_max_ = angle_of(one_minus_u0_, one_plus_u0_);
    nutation_period_ = infinity;
    mean_precession_rate_ = 0.0;
    q_WN_ = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), z_N);
    return;
  }
  // N: z_N up, x_N the line of nodes z_N × e3 at t = 0 (so φ0 = 0), y_N = z_N × x_N
  const Eigen::Vector3d e3_W = s0.q_WB * e3;
  const Eigen::Vector3d x_N = z_N.cross(e3_W).normalized();
  Eigen::Matrix3d R_WN;
  R_WN << x_N, z_N.cross(x_N), z_N;
  q_WN_ = Eigen::Quaterniond(R_WN);
  psi0_ = std::atan2(z1, z2);  // z_S = (sin θ sin ψ, sin θ cos ψ, cos θ)
  // the cubic in x = u − u0: f(u0 + x) = f0 + f1 x + f2 x² + β x³ with
  //   f0 = u̇0² = (z1 ω2 − z2 ω1)²,  f1 = f'(u0) = −2 u0 κ − β sin²θ0 + 2 a ρ,  f2 = 2 β u0 − κ − a²,
  // κ = ω1² + ω2² = α − β u0, ρ = b − a u0
  const double u_dot0 = z1 * w2 - z2 * w1;
  const double f0 = u_dot0 * u_dot0, f1 = -2.0 * u0_ * kappa - beta_ * s0_squared + 2.0 * a_ * rho0_,
               f2 = 2.0 * beta_ * u0_ - kappa - a_ * a_;
  if (!(std::isfinite(f0) && std::isfinite(f1) && std::isfinite(f2))) {  // squares of ω beyond the range
    throw_invalid("state", "a spin whose Lagrange constants (a², |w_perp|²; a = I3 w3/I1) are within the double range",
                  s0.w_B.transpose().eval());
  }
  init_roots(f0, f1, f2);
  one_minus_u1_ = one_minus_u0_ - x_[0];
  one_plus_u1_ = one_plus_u0_ + x_[0];
  one_minus_u2_ = one_minus_u0_ - x_[1];
  if (!(one_minus_u2_ > 16.0 * epsilon && one_plus_u1_ > 16.0 * epsilon)) {
    throw_invalid("state", "a motion whose symmetry axis does not pass through the vertical (1 - u2 and 1 + u1 above 16 eps)",
                  Eigen::Vector2d(one_minus_u2_, one_plus_u1_).transpose().eval());
  }
  theta_min_ = angle_of(one_minus_u2_, 2.0 - one_minus_u2_);
  theta_max_ = angle_of(2.0 - one_plus_u1_, one_plus_u1_);
  // u = u1 + Δ sn²(λ t + τ0 | m), m = Δ/(u3 − u1), λ = √(β (u3 − u1))/2
  const double delta = x_[1] - x_[0], span = x_[2] - x_[0];
  const double m = delta / span, mc = (x_[2] - x_[1]) / span;
  p_ = m < mc ? elliptic_parameter(m, 1.0 - m) : elliptic_parameter(1.0 - mc, mc);
  lambda_ = 0.5 * std::sqrt(beta_ * span);
  // τ0 = ±F(φ0|m), sin² φ0 = (u0 − u1)/Δ, cos² φ0 = (u2 − u0)/Δ, 1 − m sin² φ0 = (u3 − u0)/(u3 − u1)
  // (DLMF 19.25.5), its sign that of u̇0 (u̇ = 2 λ Δ sn cn dn)
  tau0_ = delta == 0.0 ? 0.0
                       : std::copysign(std::sqrt(-x_[0] / delta) * elliprf(x_[1] / delta, x_[2] / span, 1.0), u_dot0);
  n_plus_ = delta / one_minus_u1_;
  n_minus_ = -delta / one_plus_u1_;
  c_plus_ = (rho0_ - a_ * one_minus_u0_) / (2.0 * lambda_ * one_minus_u1_);  // (b − a)/(2λ(1 − u1))
  c_minus_ = (rho0_ + a_ * one_plus_u0_) / (2.0 * lambda_ * one_plus_u1_);   // (b + a)/(2λ(1 + u1))
  pi_plus0_ = ellippi_am(tau0_, n_plus_, p_);
  pi_minus0_ = ellippi_am(tau0_, n_minus_, p_);
  nutation_period_ = 2.0 * p_.K / lambda_;
  // mean rate λ (c+ Π(n+) + c− Π(n−))/K with Π(n) = K + (n/3) R_J(0, mc, 1, 1 − n) (DLMF 19.25.2): the K
  // parts summed first, c+ + c− = (b − a u1)/(λ (1 − u1²)) with b − a u1 = ρ0 − a x1, since c± ≈ ∓a/(2λ)
  // cancel for a fast top (relative eps (I3 ω3)²/(m g l I1): 2e-5 at ω3 = 1e6 here); c± n± share a sign.
  // 1 − n+ = (1 − u2)/(1 − u1), 1 − n− = (1 + u2)/(1 + u1), without cancellation
  const double c_sum = (rho0_ - a_ * x_[0]) / (lambda_ * one_minus_u1_ * one_plus_u1_);
  const double rj_plus = elliprj(0.0, p_.mc, 1.0, one_minus_u2_ / one_minus_u1_);
  const double rj_minus = elliprj(0.0, p_.mc, 1.0, (one_plus_u1_ + delta) / one_plus_u1_);
  mean_precession_rate_ =
      lambda_ * (c_sum + (c_plus_ * n_plus_ * rj_plus + c_minus_ * n_minus_ * rj_minus) / (3.0 * p_.K));
}

void LagrangeTopSolution::init_roots(double f0, double f1, double f2) {
  // monic: x³ + A x² + B x + C
  const double A = f2 / beta_, B = f1 / beta_, C = f0 / beta_;
  if (f0 == 0.0) {  // u0 is a root: x (x² + A x + B)
    const Eigen::Vector2d r = quadratic_roots(A, B);
    if (B < 0.0) {
      x_ = Eigen::Vector3d(r[0], 0.0, r[1]);  // u0 = u2, the highest point
    } else if (B > 0.0) {
      x_ = Eigen::Vector3d(0.0, r[0], r[1]);  // u0 = u1, the lowest point
    } else {
      x_ = Eigen::Vector3d(0.0, 0.0, -A);  // a double root at u0: steady precession
    }
    return;
  }
  // x3 by Newton's method from Fujiwara's bound on the roots, F = 2 max(|A|, √|B|, ∛|C/2|), which lies
  // above the inflection point −A/3: the iterates decrease monotonically to x3; stop when they no longer
  // decrease (round-off reached). In y = x/2^E (2^E ≤ F < 2^(E+1)) the coefficients A/2^E, B/2^2E, C/2^3E
  // are at most 1 by F's definition: no x³ overflows for a fast spin (A ~ −a²/β up to 1e300).
  const double F = 2.0 * std::max({std::abs(A), std::sqrt(std::abs(B)), std::cbrt(0.5 * std::abs(C))});
  const int E = exponent_of(F);
  const double A_s = times_pow2(A, -E), B_s = times_pow2(times_pow2(B, -E), -E),
               C_s = times_pow2(times_pow2(times_pow2(C, -E), -E), -E);
  double y = times_pow2(F, -E);
  for (int i = 0;; ++i) {
    if (i == 2000) throw std::runtime_error("LagrangeTopSolution: Newton's method did not converge on the cubic");
    const double value = ((y + A_s) * y + B_s) * y + C_s, slope = (3.0 * y + 2.0 * A_s) * y + B_s;
    if (!(value > 0.0 && slope > 0.0)) break;
    const double next = y - value / slope;
    if (!(next < y)) break;
    y = next;
  }
  const double x = times_pow2(y, E);
  // deflated: (x − x3)(x² + p x + q), q = x1 x2 = −C/x3 ≤ 0, and p = −(x1 + x2) by either of Vieta's
  //   p = A + x3        (absolute error ~ eps (|A| + |x3|): cancels when x3 ≫ |x1 + x2|, a fast top)
  //   p = (q − B)/x3    (from B = x1 x2 + x3 (x1 + x2); error ~ eps (|q| + |B|)/|x3|)
  // whichever bound is smaller
  const double q = -C / x;
  const double p = std::abs(A) + std::abs(x) <= (std::abs(q) + std::abs(B)) / std::abs(x) ? A + x : (q - B) / x;
  const Eigen::Vector2d r = quadratic_roots(p, q);
  x_ = Eigen::Vector3d(std::min(r[0], 0.0), std::clamp(r[1], 0.0, x), x);
}

EulerAnglesZXZ LagrangeTopSolution::angles_at(double t) const {
  require_finite(t, "t");
  if (case_ == LagrangeTopCase::sleeping) return {0.0, theta_min_, omega3_ * t};
  const double tau = lambda_ * t + tau0_;
  const JacobiSnCnDn f = jacobi_ellipj(tau, p_);
  const double delta = x_[1] - x_[0];
  const double one_minus_u = one_minus_u2_ + delta * f.cn * f.cn, one_plus_u = one_plus_u1_ + delta * f.sn * f.sn;
  const double P_plus = c_plus_ * (ellippi_am(tau, n_plus_, p_) - pi_plus0_);
  const double P_minus = c_minus_ * (ellippi_am(tau, n_minus_, p_) - pi_minus0_);
  return {P_plus + P_minus, angle_of(one_minus_u, one_plus_u), psi0_ + (omega3_ - a_) * t - P_plus + P_minus};
}

PivotedBodyState LagrangeTopSolution::at(double t) const {
  require_finite(t, "t");
  PivotedBodyState s;
  if (case_ == LagrangeTopCase::sleeping) {  // q(t) = exp(ω3 t e3_W) q0
    const Eigen::Vector3d e3_W = q_WB0_ * R_BS_.col(2);
    s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(std::remainder(omega3_ * t, 2.0 * M_PI), e3_W)) * q_WB0_;
    s.w_B = omega3_ * R_BS_.col(2);
    return s;
  }
  const double tau = lambda_ * t + tau0_;
  const JacobiSnCnDn f = jacobi_ellipj(tau, p_);
  const double delta = x_[1] - x_[0];
  const double one_minus_u = one_minus_u2_ + delta * f.cn * f.cn, one_plus_u = one_plus_u1_ + delta * f.sn * f.sn;
  const double P_plus = c_plus_ * (ellippi_am(tau, n_plus_, p_) - pi_plus0_);
  const double P_minus = c_minus_ * (ellippi_am(tau, n_minus_, p_) - pi_minus0_);
  const double psi = psi0_ + (omega3_ - a_) * t - P_plus + P_minus;
  // q_NS = qz(φ) qx(θ) qz(ψ) = (cos(θ/2) cos((φ+ψ)/2), sin(θ/2) cos((φ−ψ)/2), sin(θ/2) sin((φ−ψ)/2),
  // cos(θ/2) sin((φ+ψ)/2)) (w, x, y, z), with φ + ψ and φ − ψ formed directly
  const double half_sum = 0.5 * (psi0_ + (omega3_ - a_) * t) + P_minus;
  const double half_difference = P_plus - 0.5 * (psi0_ + (omega3_ - a_) * t);
  const double ch = std::sqrt(0.5 * one_plus_u), sh = std::sqrt(0.5 * one_minus_u);
  const Eigen::Quaterniond q_NS(ch * std::cos(half_sum), sh * std::cos(half_difference), sh * std::sin(half_difference),
                                ch * std::sin(half_sum));
  s.q_WB = q_WN_ * q_NS * q_SB_;
  // ω in S: ω⊥ = (θ̇ cos ψ + φ̇ sin θ sin ψ, −θ̇ sin ψ + φ̇ sin θ cos ψ), θ̇ = −u̇/sin θ with
  // u̇ = 2 λ Δ sn cn dn, φ̇ sin θ = (b − a u)/sin θ with b − a u = ρ0 − a (u − u0), u − u0 = x1 + Δ sn²
  const double sin_theta = std::sqrt(one_minus_u * one_plus_u);
  const double theta_dot = -2.0 * lambda_ * delta * f.sn * f.cn * f.dn / sin_theta;
  const double phi_dot_sin = (rho0_ - a_ * (x_[0] + delta * f.sn * f.sn)) / sin_theta;
  const double cp = std::cos(psi), sp = std::sin(psi);
  const Eigen::Vector3d w_S(theta_dot * cp + phi_dot_sin * sp, -theta_dot * sp + phi_dot_sin * cp, omega3_);
  s.w_B = R_BS_ * w_S;
  return s;
}

}  // namespace rigiddyn
