// The exact torque-free motion: see free_body.hpp for the cases; the formulas are those of Landau &
// Lifshitz §37 and Celledoni, Fassò, Säfström, Zanna 2008 (with Leroy's errata).
#include "rigiddyn/exact/free_body.hpp"

#include "power_of_two.hpp"
#include "numbers.hpp"
#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rigiddyn {

namespace {

using detail::epsilon;
using detail::infinity;


// double-double arithmetic (value hi + lo, |lo| ≤ ulp(hi)/2) for the cancelling invariant Δ2
struct DoubleDouble {
  double hi;
  double lo;
};

DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

DoubleDouble renormalise(double hi, double lo) {
  const double s = hi + lo;
  return {s, lo - (s - hi)};
}

DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble p = two_prod(a.hi, b.hi);
  return renormalise(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble s = two_sum(a.hi, b.hi);
  return renormalise(s.hi, s.lo + (a.lo + b.lo));
}

// Δ2 I1 I3 = m1² (I1 − I2) I3 + m3² (I3 − I2) I1 in double-double: the two terms have opposite
// signs and cancel at the separatrix.
DoubleDouble delta2_times_I1_I3(double m1, double m3, const Eigen::Vector3d& I) {
  const DoubleDouble term1 = two_prod(m1, m1) * two_sum(I(0), -I(1)) * DoubleDouble{I(2), 0.0};
  const DoubleDouble term3 = two_prod(m3, m3) * two_sum(I(2), -I(1)) * DoubleDouble{I(0), 0.0};
  return term1 + term3;
}

double square(double x) { return x * x; }

// unit quaternion exp(v/2) of the rotation vector v [rad]
Eigen::Quaterniond rotation_vector_to_quaternion(const Eigen::Vector3d& v) {
  const double angle = v.stableNorm();  // no overflow of the squares for a finite v
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

using HalfAngle = TorqueFreeSolution::HalfAngle;

HalfAngle half_angle(double angle) { return {std::cos(0.5 * angle), std::sin(0.5 * angle)}; }

// e^(i(a + b)/2) = e^(ia/2) e^(ib/2)
HalfAngle operator*(const HalfAngle& a, const HalfAngle& b) { return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s}; }

// e^(iθ/2), θ = atan2(im, re) ∈ (−π, π): the cosine (> 0) or the sine (with the sign of im) from the root of a
// sum of like-signed terms, the other from sin θ = 2 sin(θ/2) cos(θ/2) (accurate at every θ)
HalfAngle half_angle_of(double re, double im) {
  const double r = std::sqrt(re * re + im * im);
  if (re >= 0.0) {
    const double c = std::sqrt((r + re) / (2.0 * r));
    return {c, im / (2.0 * r * c)};
  }
  const double s = std::copysign(std::sqrt((r - re) / (2.0 * r)), im);
  return {im / (2.0 * r * s), s};
}

Eigen::Quaterniond about_z(const HalfAngle& half) { return Eigen::Quaterniond(half.c, 0.0, 0.0, half.s); }

// q_NQ of Z-X-Z angles (φ, θ, ψ), φ given by its half-angle rotor, with θ and ψ read off m_Q = R_NQᵀ (0, 0, G):
// m_Q = G (sin θ sin ψ, sin θ cos ψ, cos θ), θ ∈ [0, π], ψ = atan2(m_a, m_b) ∈ (−π, π]. The transverse
// part comes as its magnitude rho = |(m_a, m_b)| (which may underflow: θ is then 0 or π to within it)
// and its direction (x, y), any positive multiple of (m_a, m_b) not both 0 (so that a tiny transverse
// part keeps its direction), r = |(x, y)|; rho and m_s in one unit, at most ~4 (no overflow in the squares). The
// half-angle cosines and sines come algebraically (the larger of each pair by a square root of a sum of
// like-signed terms, the other from sin x = 2 sin(x/2) cos(x/2)), accurate at both poles; then
// Rz(φ) Rx(θ) Rz(ψ) = Rz(φ) (cθ cψ, sθ cψ, −sθ sψ, cθ sψ) with c·, s· of the half angles.
Eigen::Quaterniond zxz_from_momentum(const HalfAngle& half_phi, double x, double y, double r, double rho, double m_s) {
  const double G = std::sqrt(rho * rho + m_s * m_s);
  double c_theta, s_theta;  // cos θ/2, sin θ/2 (both >= 0)
  if (m_s >= 0.0) {
    c_theta = std::sqrt((G + m_s) / (2.0 * G));
    s_theta = rho / (2.0 * G * c_theta);
  } else {
    s_theta = std::sqrt((G - m_s) / (2.0 * G));
    c_theta = rho / (2.0 * G * s_theta);
  }
  double c_psi, s_psi;  // cos ψ/2 >= 0, sin ψ/2 with the sign of m_a (of atan2's ψ)
  if (y >= 0.0) {
    c_psi = std::sqrt((r + y) / (2.0 * r));
    s_psi = x / (2.0 * r * c_psi);
  } else {
    s_psi = std::copysign(std::sqrt((r - y) / (2.0 * r)), x);
    c_psi = x / (2.0 * r * s_psi);
  }
  const Eigen::Quaterniond tilt(c_theta * c_psi, s_theta * c_psi, -s_theta * s_psi, c_theta * s_psi);
  return about_z(half_phi) * tilt;
}

double sign_of(double x) { return x < 0.0 ? -1.0 : 1.0; }

// R_PQ of case B's frame Q = (P2, P3, P1) (a cyclic relabelling, det +1)
Eigen::Matrix3d cyclic_relabelling() {
  Eigen::Matrix3d R_PQ;
  R_PQ << 0, 0, 1,  //
      1, 0, 0,      //
      0, 1, 0;
  return R_PQ;
}

// The parameters of the elliptic motion (Landau & Lifshitz §37) from the ascending principal moments I, in a
// common scale, and the invariants Δ_j = 4^t_j D_j (D1 > 0, D3 < 0, D2's sign the case, 0 in case A's form; 2^t_j a scale of the
// momentum's two components transverse to axis j). Case A (D2 > 0, the momentum about axis 3): in Q = P,
// ω_Q = (a_cn cn, a_sn sn, a_dn dn) up to the signs of the momentum's components; case B (D2 < 0): in the cyclic
// relabelling Q = (P2, P3, P1), ω_Q = (a_sn sn, a_cn cn, a_dn dn). The cn and sn amplitudes come over 2^t_trans,
// the dn amplitude and λ over 2^t_axis, kc² over 4^t_kc; m is exact.
struct EllipticMotion {
  bool case_A;
  double lambda, m, mc_hat, n;  // λ 2^−t_axis; m; kc² 4^−t_kc; the characteristic of Π
  Eigen::Vector3d amplitude;    // (a_cn, a_sn, a_dn) > 0
  Eigen::Vector3d I_cn_sn_dn;   // the moments about the cn, sn and dn axes
  int cn_axis, sn_axis;         // the axes of Q whose rates go as cn and sn (the dn axis is 2)
  double I_s, phi_sign;         // φ̇ = G/I_s + phi_sign (...) Π̇ (the axis the momentum circles)
  int t_trans, t_axis, t_kc;

  Eigen::Matrix3d R_PQ() const { return case_A ? Eigen::Matrix3d::Identity() : cyclic_relabelling(); }
  // v_Q = R_PQᵀ v_P and v_P = R_PQ v_Q, as the permutations they are
  Eigen::Vector3d to_Q(const Eigen::Vector3d& v_P) const {
    return case_A ? v_P : Eigen::Vector3d(v_P(1), v_P(2), v_P(0));
  }
  Eigen::Vector3d to_P(const Eigen::Vector3d& v_Q) const {
    return case_A ? v_Q : Eigen::Vector3d(v_Q(2), v_Q(0), v_Q(1));
  }
};

inline EllipticMotion elliptic_motion(const Eigen::Vector3d& I, double D1, double D2, double D3, const int t[3]) {
  const double I1 = I(0), I2 = I(1), I3 = I(2);
  EllipticMotion e;
  e.case_A = !(D2 < 0.0);  // the separatrix (D2 = 0) in case A's form
  if (e.case_A) {
    e.t_trans = t[2], e.t_axis = t[0], e.t_kc = t[1] - t[0];
    e.amplitude << std::sqrt(-D3 / (I1 * (I3 - I1))), std::sqrt(-D3 / (I2 * (I3 - I2))), std::sqrt(D1 / (I3 * (I3 - I1)));
    e.I_cn_sn_dn = I;
    e.lambda = std::sqrt((I3 - I2) * D1 / (I1 * I2 * I3));
    e.m = times_pow2((I2 - I1) * -D3 / ((I3 - I2) * D1), 2 * (t[2] - t[0]));
    e.mc_hat = (I3 - I1) * D2 / ((I3 - I2) * D1);
    e.n = -I3 * (I2 - I1) / (I1 * (I3 - I2));
    e.cn_axis = 0, e.sn_axis = 1;
    e.I_s = I3, e.phi_sign = 1.0;
  } else {
    e.t_trans = t[0], e.t_axis = t[2], e.t_kc = t[1] - t[2];
    e.amplitude << std::sqrt(D1 / (I3 * (I3 - I1))), std::sqrt(D1 / (I2 * (I2 - I1))), std::sqrt(-D3 / (I1 * (I3 - I1)));
    e.I_cn_sn_dn << I3, I2, I1;
    e.lambda = std::sqrt((I2 - I1) * -D3 / (I1 * I2 * I3));
    e.m = times_pow2((I3 - I2) * D1 / ((I2 - I1) * -D3), 2 * (t[0] - t[2]));
    e.mc_hat = (I3 - I1) * -D2 / ((I2 - I1) * -D3);
    e.n = -I1 * (I3 - I2) / (I3 * (I2 - I1));
    e.sn_axis = 0, e.cn_axis = 1;
    e.I_s = I1, e.phi_sign = -1.0;
  }
  return e;
}

// The factor of the reduced Π in the precession angle, φ(t) = (G/I_s) t + phi_pi [Π]_{u0}^{u}: the closed form's
// −G Δ_s/(I_s (G² − B²) λ) simplified (G² − B² = I1(−Δ3)/(I3 − I1) in case A, I3 Δ1/(I3 − I1) in case B)
double phi_pi_factor(const Eigen::Vector3d& I, const EllipticMotion& e, double G, double lambda) {
  return e.phi_sign * (G * (I(2) - I(0)) / (I(0) * I(2) * lambda));
}

// |(a, b)|: the root of the sum of squares where the larger is above 2^-500 (then no square that matters
// underflows), std::hypot below. The transverse mantissas are O(1) except a hair from the separatrix (kc below
// ~1e-150), where past K/2 both are of the order of kc^{3/4} and their squares underflowed to a zero norm.
double transverse_norm(double a, double b) {
  const double r = std::sqrt(a * a + b * b);
  return r >= 0x1p-500 ? r : std::hypot(a, b);
}

// The principal frame of a finite, symmetric, positive definite I_B that, under InertiaCheck::physical,
// satisfies the triangle inequality (ascending I0 + I1 >= I2) within the tolerance of validity.hpp (the
// message names the moments and the margin). The frame is principal_decomposition's, which reproduces I_B to
// round-off for any spacing of the moments; principal_axes' canonical axes for moments within 1e-9 of each
// other do not, and the closed form, which keeps moments apart down to 64 eps, would follow another body.
PrincipalAxes checked_principal_axes(const Eigen::Matrix3d& I_B, InertiaCheck check) {
  require_finite(I_B, "inertia");
  if (!((I_B - I_B.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * I_B.cwiseAbs().maxCoeff())) {
    throw_invalid("inertia", "a symmetric matrix (to 1e-12 relative)", I_B);
  }
  PrincipalAxes axes = principal_decomposition(0.5 * (I_B + I_B.transpose()));
  if (!(axes.moments(0) > 0.0)) throw_invalid("inertia", "a positive definite matrix", I_B);
  if (check == InertiaCheck::physical) {
    const InertiaReport report = inertia_report(1.0, I_B);  // the mass plays no part in the moments' checks
    if (!report.triangle_inequality) {
      throw std::invalid_argument(
          "inertia: expected principal moments satisfying the triangle inequality I0 + I1 >= I2 (a realizable "
          "body), got " + report.summary());
    }
  }
  return axes;
}

const Eigen::Quaterniond& checked_attitude(const Eigen::Quaterniond& q_WB) {
  require_finite(q_WB.coeffs(), "q_WB");
  if (!(std::abs(q_WB.norm() - 1.0) <= 1e-6)) {
    throw_invalid("q_WB", "a unit quaternion (norm within 1e-6 of 1)", q_WB.coeffs());
  }
  return q_WB;
}

const Eigen::Vector3d& checked_angular_velocity(const Eigen::Vector3d& w_B) {
  require_finite(w_B, "w_B");
  return w_B;
}

// v 2^e, componentwise
Eigen::Vector3d times_pow2(const Eigen::Vector3d& v, int e) {
  return {rigiddyn::times_pow2(v(0), e), rigiddyn::times_pow2(v(1), e), rigiddyn::times_pow2(v(2), e)};
}

// The exponent of max |v_i| (0 for v = 0).
int exponent_of_largest(const Eigen::Vector3d& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  return largest > 0.0 ? exponent_of(largest) : 0;
}

}  // namespace

std::string to_string(TorqueFreeCase c) {
  switch (c) {
    case TorqueFreeCase::sphere: return "sphere";
    case TorqueFreeCase::symmetric: return "symmetric";
    case TorqueFreeCase::A: return "A";
    case TorqueFreeCase::B: return "B";
    case TorqueFreeCase::separatrix: return "separatrix";
  }
  return "unknown";
}

TorqueFreeSolution::TorqueFreeSolution(const Eigen::Matrix3d& I_B, const Eigen::Quaterniond& q_WB,
                                       const Eigen::Vector3d& w_B, InertiaCheck check)
    : TorqueFreeSolution(checked_principal_axes(I_B, check), checked_attitude(q_WB), checked_angular_velocity(w_B),
                         true) {
  if (!parameters_in_range_) {
    throw_invalid("inertia",
                  "principal moments whose spread keeps the parameters of the closed form (up to ~(I_max/I_min)² in "
                  "scaled units) within the double range for this w_B (I_min/I_max = " +
                      format_value(I_principal_(0) / I_principal_(2)) + ")",
                  I_B);
  }
  // the motion is formed in scaled units: only its rates (of the order of |w_B| I_max/I_min) can overflow
  if (!std::isfinite(max_rate())) {
    throw_invalid("w_B", "an angular velocity whose rates of motion (up to |w_B| I_max/I_min) stay within the double range",
                  w_B);
  }
}

TorqueFreeSolution::TorqueFreeSolution(const PrincipalAxes& axes, const Eigen::Quaterniond& q_WB,
                                       const Eigen::Vector3d& w_B, bool for_many_times)
    : I_principal_(axes.moments), R_BP_(axes.axes), pi_complete_known_(for_many_times) {
  q_WB0_ = q_WB.normalized();
  w_B0_ = w_B;
  const Eigen::Vector3d& I = I_principal_;
  const Eigen::Vector3d w_P = R_BP_.transpose() * w_B;
  // the momentum as L̃ = Î w̃ with Î = 2^−e_I I (the largest moment in [1, 2)) and w̃ = 2^−e_w w_P (the
  // largest rate in [1, 2)), exact scalings: representable for any finite inertia and w_B, m = 2^(e_I + e_w) L̃.
  // The motion depends only on Î and w̃ (rates scale with 2^e_w); L_W and T alone are formed in SI units.
  const int e_I = exponent_of(I(2)), e_w = exponent_of_largest(w_P);
  const Eigen::Vector3d I_hat = times_pow2(I, -e_I), w_tilde = times_pow2(w_P, -e_w);
  const Eigen::Vector3d L_tilde = I_hat.cwiseProduct(w_tilde);
  L_W_ = times_pow2(q_WB0_ * (R_BP_ * L_tilde), e_I + e_w);                 // ±inf beyond the double range
  kinetic_energy_ = rigiddyn::times_pow2(0.5 * w_tilde.dot(L_tilde), e_I + 2 * e_w);  // +inf beyond it

  const double tol = 64.0 * epsilon * I(2);
  if (I(2) - I(0) <= tol) {
    case_ = TorqueFreeCase::sphere;
    init_rotation_about_axis(Eigen::Vector3d::Ones(), R_BP_.col(2), 1.0);
    return;
  }
  if (I(1) - I(0) <= tol || I(2) - I(1) <= tol) {
    case_ = TorqueFreeCase::symmetric;
    const bool oblate_pair = I(1) - I(0) <= tol;  // the two smallest moments are equal: axis 3
    const double I_t = oblate_pair ? 0.5 * (I(0) + I(1)) : 0.5 * (I(1) + I(2));
    const double I_a = oblate_pair ? I(2) : I(0);
    const Eigen::Vector3d I_sym = oblate_pair ? Eigen::Vector3d(I_t, I_t, I_a) : Eigen::Vector3d(I_a, I_t, I_t);
    init_rotation_about_axis(I_sym, R_BP_.col(oblate_pair ? 2 : 0), I_a);
    return;
  }

  if ((L_tilde.array() == 0.0).count() >= 2) {
    // steady spin about a principal axis (or rest); about axis 2 the unstable equilibrium on the
    // separatrix. The Z-X-Z angles are singular there (θ = 0), so rotate about the fixed axis.
    case_ = L_tilde(0) != 0.0 ? TorqueFreeCase::B : L_tilde(2) != 0.0 ? TorqueFreeCase::A : TorqueFreeCase::separatrix;
    about_axis_ = true;
    nu_W_ = q_WB0_ * w_B;
    beta_ = 0.0;
    period_ = infinity;
    return;
  }
  init_elliptic(I_hat, L_tilde, e_w);
}

// Sphere and symmetric body: ω = m/I_t + β e with β = (I_t − I_a) ω_a / I_t, so that
// R(t) = exp(t (L_W/I_t)^) R0 exp(t β ê) and m(t) = exp(−t β ê) m0 (Landau & Lifshitz §33). Only the
// ratios of the moments enter (m/I_t = (I_Q/I_t) ω): any common scale of I_Q and I_axial.
void TorqueFreeSolution::init_rotation_about_axis(const Eigen::Vector3d& I_Q, const Eigen::Vector3d& axis_B,
                                                  double I_axial) {
  about_axis_ = true;
  const double I_t = I_Q(1);  // the transverse moment (the middle one is always transverse)
  const Eigen::Vector3d m_over_I_t_B = R_BP_ * (I_Q / I_t).cwiseProduct(R_BP_.transpose() * w_B0_);
  e_B_ = axis_B;
  beta_ = (I_t - I_axial) / I_t * e_B_.dot(w_B0_);
  nu_W_ = q_WB0_ * m_over_I_t_B;
  period_ = beta_ == 0.0 ? infinity : 2.0 * M_PI / std::abs(beta_);
}

// The invariants Δ_j = G² − 2T I_j = Σ_{i≠j} m_i² (I_i − I_j)/I_i (Δ1 ≥ 0, Δ3 ≤ 0 sums of like-signed
// terms; Δ2 cancels at the separatrix, see delta2_times_I1_I3) of the momentum m̂ = 2^−e L̃ (largest
// component in [1, 2)), each as Δ_j = 4^(e + t_j) D_j with 2^t_j the scale of the two components it
// involves: a transverse part down to the smallest subnormal is not squared to zero.
// Then, with the amplitudes, λ, m and kc = √(1 − m) of the closed form (Landau & Lifshitz §37) in these units:
// case A: ω = (σ1 A1 cn, σ1 s A2 sn, s A3 dn) on (1, 2, 3), s = sign m3, σ1 = sign m1 on the separatrix (there
// cn ≥ 0), else 1; case B: ω = (s A1 dn, s A2 sn, A3 cn), s = sign m1, in the frame Q = (P2, P3, P1) (a cyclic
// relabelling, det +1).
void TorqueFreeSolution::init_elliptic(const Eigen::Vector3d& I, const Eigen::Vector3d& L_tilde, int e_rate) {
  const double I1 = I(0), I2 = I(1), I3 = I(2);  // the largest in [1, 2): products of three stay in range
  const int e = exponent_of(L_tilde.cwiseAbs().maxCoeff()), e_w = e + e_rate;  // ω = 2^e_w m̂/I
  const Eigen::Vector3d mh = times_pow2(L_tilde, -e);
  int t[3];
  for (int j = 0; j < 3; ++j) t[j] = exponent_of(std::max(std::abs(mh((j + 1) % 3)), std::abs(mh((j + 2) % 3))));
  const auto scaled = [&](int i, int j) { return times_pow2(mh(i), -t[j]); };  // m̂_i 2^−t_j
  const double D1 = square(scaled(1, 0)) * (I2 - I1) / I2 + square(scaled(2, 0)) * (I3 - I1) / I3;
  const double D3 = square(scaled(0, 2)) * (I1 - I3) / I1 + square(scaled(1, 2)) * (I2 - I3) / I2;
  const double D2 = delta2_times_I1_I3(scaled(0, 1), scaled(2, 1), I).hi / (I1 * I3);
  case_ = D2 > 0.0 ? TorqueFreeCase::A : D2 < 0.0 ? TorqueFreeCase::B : TorqueFreeCase::separatrix;

  const EllipticMotion motion = elliptic_motion(I, D1, D2, D3, t);
  const double s = sign_of(mh(motion.case_A ? 2 : 0));  // the sign of the rate about the axis the momentum circles
  const double sigma1 = case_ == TorqueFreeCase::separatrix ? sign_of(mh(0)) : 1.0;  // there cn ≥ 0
  t_trans_ = motion.t_trans, cn_axis_ = motion.cn_axis, sn_axis_ = motion.sn_axis, n_ = motion.n;
  const int t_axis = motion.t_axis, t_kc = motion.t_kc;
  const Eigen::Vector3d A = motion.case_A ? Eigen::Vector3d(sigma1 * motion.amplitude(0), sigma1 * s * motion.amplitude(1), s * motion.amplitude(2))
                                     : Eigen::Vector3d(motion.amplitude(0), s * motion.amplitude(1), s * motion.amplitude(2));
  const double lambda = motion.lambda;
  double m = motion.m, kc = std::sqrt(motion.mc_hat);
  // In these units the amplitudes, λ and n are of the order of I3/I1 and their squares (I3/I1)²: beyond the
  // double range when the moments span more than ~1e150 and the momentum has a part along the smallest. Such a
  // motion is not formed (the elliptic integrals would receive infinities): evaluate() gives NaN and the public
  // constructor refuses the inertia.
  if (!(A.allFinite() && std::isfinite(lambda) && std::isfinite(m) && std::isfinite(kc) && std::isfinite(n_))) {
    parameters_in_range_ = false;
    return;
  }
  // m and kc are each accurate; make them consistent from the smaller of m and mc = kc²
  const double kc_hat = kc;
  kc = times_pow2(kc_hat, t_kc);
  double log_kc = 0.0;  // needed only for kc < 2^−27 (K = ln(4/kc) + ...)
  if (kc * kc <= 0.5) {
    m = 1.0 - kc * kc;
    if (kc < 0x1p-27) log_kc = std::log(kc_hat) + t_kc * M_LN2;
  } else {
    m = std::min(std::max(m, 0.0), 1.0);
    kc = std::sqrt(1.0 - m);
  }
  elliptic_ = elliptic_parameter_kc(m, kc, log_kc);

  const double G_hat = mh.norm();
  lambda_ = times_pow2(lambda, t_axis + e_w);
  phi_rate_ = times_pow2(G_hat / motion.I_s, e_w);
  phi_pi_ = times_pow2(phi_pi_factor(I, motion, G_hat, lambda), -t_axis);
  w_amplitude_ << times_pow2(A(0), t_trans_ + e_w), times_pow2(A(1), t_trans_ + e_w), times_pow2(A(2), t_axis + e_w);
  kc_w_amplitude_ << times_pow2(A(0) * kc_hat, t_trans_ + t_kc + e_w), times_pow2(A(2) * kc_hat, t_axis + t_kc + e_w);
  const Eigen::Vector3d M_hat = motion.I_cn_sn_dn.cwiseProduct(A);
  M_ << M_hat(0), M_hat(1), times_pow2(M_hat(2), t_axis);
  kc_M_ << times_pow2(M_hat(0) * kc_hat, t_kc), times_pow2(M_hat(2) * kc_hat, t_axis + t_kc);

  const Eigen::Vector3d mh_Q = motion.to_Q(mh);
  init_phase(mh_Q, M_hat(2) * kc_hat, t[1]);
  if (pi_complete_known_) {
    pi_complete_ = complete_pi();
    if (EllipticTheta::applies(n_, elliptic_)) {
      theta_.emplace(n_, elliptic_, pi_complete_);
      sigma_ = motion.phi_sign;  // phi_pi_ S = 1 in magnitude (both are algebraic in the moments and the momentum)
      const EllipticTheta::Phase at_w0 = theta_->evaluate(w0_, l0_ == 1.0 || l0_ == -1.0).phase;
      linear0_ = at_w0.linear;
      const HalfAngle half = half_angle_of(at_w0.re, at_w0.im);
      theta0_ = {half.c, -sigma_ * half.s};
    }
  }
  period_ = elliptic_.kc == 0.0 ? infinity : 4.0 * elliptic_.K / lambda_;

  q_BQ_ = Eigen::Quaterniond(R_BP_ * motion.R_PQ());
  q_BQ_.normalize();
  const double x = times_pow2(mh_Q(0), -t_trans_), y = times_pow2(mh_Q(1), -t_trans_), r = std::sqrt(x * x + y * y);
  q_WN_ = q_WB0_ * q_BQ_ * zxz_from_momentum({1.0, 0.0}, x, y, r, times_pow2(r, t_trans_), mh_Q(2)).conjugate();
}

// The phase u0 = l0 K + w0 (|w0| ≤ K/2) and the reduced Π at it, from the initial (sn, cn, dn) =
// (m_sn/M_sn, m_cn/M_cn, m_s/M_dn), each ratio taken between like-scaled numbers: near the saddle
// (|sn0| dn0 > |cn0|: the odd quarters l0 = ±1) the functions of w0 = u0 ∓ K follow from DLMF Table
// 22.4.3 inverted: (sn, cn, dn)(w0) = (∓cn0/dn0, |sn0| kc/dn0, kc/dn0), ratios of two small numbers
// formed without forming either (kc dn0 is kc_M_dn/m_s with m_s scaled by 2^−t2, the scale of the two
// components transverse to axis 2, both O(1) there). On the separatrix, u0 = asinh(sn0/cn0).
void TorqueFreeSolution::init_phase(const Eigen::Vector3d& mh_Q, double kc_M_dn_hat, int t2) {
  const double q_cn = mh_Q(cn_axis_), q_sn = mh_Q(sn_axis_), q_s = mh_Q(2);
  const double sn0 = std::min(std::max(times_pow2(q_sn, -t_trans_) / M_(1), -1.0), 1.0);
  const double cn0 = times_pow2(q_cn, -t_trans_) / M_(0);
  const double dn0 = q_s / M_(2);
  if (elliptic_.kc == 0.0) {  // separatrix: sn = tanh, cn = dn = sech > 0
    const double X = (q_sn / q_cn) * (M_(0) / M_(1));  // sinh u0
    w0_ = std::abs(X) < 0x1p60 ? std::asinh(X)
                               : std::copysign(M_LN2 + std::log(std::abs(q_sn)) - std::log(std::abs(q_cn)) +
                                                   std::log(std::abs(M_(0) / M_(1))),
                                               X);
    const double a = std::sqrt(-n_);
    pi0_ = a * std::atan(a * std::tanh(w0_));
    return;
  }
  const double cn_over_dn = times_pow2(q_cn, -t_trans_) / q_s * (M_(2) / M_(0));  // scaled before dividing
  JacobiSnCnDn f;
  const bool odd = std::abs(sn0) > std::abs(cn_over_dn);
  if (odd) {
    const double sigma = sign_of(sn0);
    l0_ = sigma;
    f.sn = -sigma * cn_over_dn;
    f.dn = kc_M_dn_hat / times_pow2(q_s, -t2);
    f.cn = std::abs(sn0) * f.dn;
  } else {
    l0_ = cn0 >= 0.0 ? 0.0 : 2.0;
    const double sigma = cn0 >= 0.0 ? 1.0 : -1.0;
    f = {sigma * sn0, sigma * cn0, dn0};
  }
  const EllipticFPi at_w0 = elliptic_f_pi_reduced(f, odd, n_, elliptic_);
  w0_ = at_w0.f;
  pi0_ = at_w0.pi;
}

double TorqueFreeSolution::max_rate() const {
  return std::max({std::abs(lambda_), std::abs(phi_rate_), nu_W_.cwiseAbs().maxCoeff(), std::abs(beta_),
                   w_amplitude_.cwiseAbs().maxCoeff(), kc_w_amplitude_.cwiseAbs().maxCoeff(), std::abs(phi_pi_ * lambda_)});
}

TorqueFreeState TorqueFreeSolution::state_at(double t) const {
  if (!std::isfinite(t)) throw_invalid("t", "a finite number", t);
  const TorqueFreeState s = evaluate(t);
  // with finite rates only a phase (rate × t) can overflow
  if (!(s.q_WB.coeffs().allFinite() && s.w_B.allFinite())) {
    throw_invalid("t", "a time whose phases (rates up to " + format_value(max_rate()) + " rad/s) times t stay finite", t);
  }
  return s;
}

TorqueFreeState TorqueFreeSolution::evaluate(double t) const {
  if (!parameters_in_range_) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    return {Eigen::Quaterniond(nan, nan, nan, nan), Eigen::Vector3d::Constant(nan)};
  }
  return about_axis_ ? state_about_axis(t) : state_elliptic(t);
}

// Π(n|m) (elliptic.hpp); 0 on the separatrix (never used there)
double TorqueFreeSolution::complete_pi() const {
  return elliptic_.kc == 0.0 ? 0.0 : complete_ellippi(n_, elliptic_);
}

TorqueFreeState TorqueFreeSolution::state_about_axis(double t) const {
  const Eigen::Quaterniond q_WB =
      rotation_vector_to_quaternion(nu_W_ * t) * q_WB0_ * rotation_vector_to_quaternion(e_B_ * (beta_ * t));
  const Eigen::Vector3d w_B = Eigen::AngleAxisd(-beta_ * t, e_B_) * w_B0_;
  return {q_WB.normalized(), w_B};
}

TorqueFreeState TorqueFreeSolution::state_elliptic(double t) const {
  if (elliptic_.kc == 0.0) return state_separatrix(t);
  const EllipticParameter& p = elliptic_;
  // u = λ t + u0 = l K + w with |w| <= K/2; λ t kept as an exact two-product so that the reduction
  // loses nothing beyond the rounding of λ and K (repeated only when |λ t| ≳ K/eps)
  const DoubleDouble lambda_t = two_prod(lambda_, t);
  double l = std::nearbyint((lambda_t.hi + w0_) / p.K);
  double w = (std::fma(-p.K, l, lambda_t.hi) + lambda_t.lo) + w0_;
  for (int i = 0; std::abs(w) > 0.75 * p.K && i < 40; ++i) {
    const double l_more = std::nearbyint(w / p.K);
    w = std::fma(-p.K, l_more, w);
    l += l_more;
  }
  l += l0_;
  const double quarter = quarter_of(l);
  const bool odd_quarter = quarter == 1.0 || quarter == 3.0;
  if (theta_) {
    const EllipticTheta::Evaluation at_w = theta_->evaluate(w, odd_quarter);
    return state_from_functions(half_phi_from_theta(t, l, w, at_w.phase), at_w.f, quarter);
  }
  const JacobiSnCnDn f_w = jacobi_ellipj_reduced(w, p);
  // Π(am u) − Π(am u0) = (l − l0) Π(n|m) + reduced Π(w) − reduced Π(w0)
  double delta_pi = elliptic_f_pi_reduced(f_w, odd_quarter, n_, p).pi - pi0_;
  if (l != l0_) delta_pi += (l - l0_) * (pi_complete_known_ ? pi_complete_ : complete_pi());
  return state_from_functions(half_angle(phi_rate_ * t + phi_pi_ * delta_pi), f_w, quarter);
}

// e^(iφ/2) from the theta series: with reduced Π = (Π/K) w + S (linear + θ), θ = arg(re + i im), and
// phi_pi_ S = σ = ±1 (Jacobi: e^(iφ) is e^(i·linear in t) times a quotient of theta functions),
//   φ = phi_rate t + phi_pi [(l − l0) Π(n|m) + (Π/K)(w − w0)] + σ (linear − linear0) + σ (θ − θ0),
// whose last term's half angle follows from (re, im) without an atan2
TorqueFreeSolution::HalfAngle TorqueFreeSolution::half_phi_from_theta(double t, double l, double w,
                                                                      const EllipticTheta::Phase& at_w) const {
  const double linear = phi_rate_ * t + phi_pi_ * ((l - l0_) * pi_complete_ + theta_->slope() * (w - w0_)) +
                        sigma_ * (at_w.linear - linear0_);
  const HalfAngle half_theta = half_angle_of(at_w.re, at_w.im);
  return half_angle(linear) * HalfAngle{half_theta.c, sigma_ * half_theta.s} * theta0_;
}

// On the separatrix (kc = 0): (sn, cn, dn) = (tanh u, sech u, sech u) and Π(am u, n|1) in elementary
// form (ellippi_am_separatrix), whose difference keeps λ t apart: [Π]_{u0}^{u} =
// (λ t + a atan(a tanh u) − a atan(a tanh u0))/(1 − n), a = √−n (no cancellation of |u0| ~ ln(G/|m_⊥|)).
TorqueFreeState TorqueFreeSolution::state_separatrix(double t) const {
  const DoubleDouble lambda_t = two_prod(lambda_, t);
  const double u = (lambda_t.hi + w0_) + lambda_t.lo;
  const double a = std::sqrt(-n_), sech = 1.0 / std::cosh(u), tanh = std::tanh(u);
  const double delta_pi = ((lambda_t.hi + lambda_t.lo) + (a * std::atan(a * tanh) - pi0_)) / (1.0 - n_);
  return state_from_functions(half_angle(phi_rate_ * t + phi_pi_ * delta_pi), {tanh, sech, sech}, 0.0);
}

// ω and the attitude at the phase φ (its half-angle rotor) from the functions of the reduced argument w in the quarter
// (0..3) of u = l K + w: (sn, cn, dn)(u) = ±(sn, cn, dn)(w) for even quarters and
// (±cd w, ∓kc sd w, kc nd w) for odd ones (DLMF Table 22.4.3), with the momentum's direction in the
// (a, b) plane kept in the mantissas of the transverse amplitudes (M_ and kc_M_).
TorqueFreeState TorqueFreeSolution::state_from_functions(const HalfAngle& half_phi, const JacobiSnCnDn& f, double quarter) const {
  Eigen::Vector3d w_Q;
  double m_cn, m_sn, r, rho, m_s;  // (cn, sn) momentum direction and its norm, |transverse| and axial momentum (units of |m|)
  if (quarter == 0.0 || quarter == 2.0) {
    const double sign = quarter == 0.0 ? 1.0 : -1.0;
    w_Q(cn_axis_) = sign * w_amplitude_(0) * f.cn;
    w_Q(sn_axis_) = sign * w_amplitude_(1) * f.sn;
    w_Q(2) = w_amplitude_(2) * f.dn;
    m_cn = sign * M_(0) * f.cn;
    m_sn = sign * M_(1) * f.sn;
    r = transverse_norm(m_cn, m_sn);
    rho = times_pow2(r, t_trans_);
    m_s = M_(2) * f.dn;
  } else {
    const double sign = quarter == 1.0 ? 1.0 : -1.0, nd = 1.0 / f.dn;
    w_Q(cn_axis_) = -sign * kc_w_amplitude_(0) * f.sn * nd;
    w_Q(sn_axis_) = sign * w_amplitude_(1) * f.cn * nd;
    w_Q(2) = kc_w_amplitude_(1) * nd;
    m_cn = -sign * kc_M_(0) * f.sn;
    m_sn = sign * M_(1) * f.cn;
    r = transverse_norm(m_cn, m_sn);
    rho = times_pow2(r, t_trans_) * nd;
    m_s = kc_M_(1) * nd;
  }
  const Eigen::Quaterniond q_NQ = cn_axis_ == 0 ? zxz_from_momentum(half_phi, m_cn, m_sn, r, rho, m_s)
                                                : zxz_from_momentum(half_phi, m_sn, m_cn, r, rho, m_s);
  const Eigen::Quaterniond q_WB = q_WN_ * q_NQ * q_BQ_.conjugate();
  return {q_WB.normalized(), q_BQ_ * w_Q};
}

}  // namespace rigiddyn

namespace rigiddyn {

FreeRotationFlow::FreeRotationFlow(const Eigen::Matrix3d& I_B)
    : I_B_(I_B), axes_(checked_principal_axes(I_B, InertiaCheck::allow_unrealizable)) {
  const Eigen::Vector3d& I = axes_.moments;
  const double tol = 64.0 * epsilon * I(2);  // TorqueFreeSolution's: moments closer are one (symmetric body)
  distinct_moments_ = I(1) - I(0) > tol && I(2) - I(1) > tol;
  q_BQ_[0] = Eigen::Quaterniond(axes_.axes).normalized();
  q_BQ_[1] = Eigen::Quaterniond(axes_.axes * cyclic_relabelling()).normalized();
}

void FreeRotationFlow::advance(Eigen::Quaterniond& q_WB, Eigen::Vector3d& w_B, double h) const {
  if (!(q_WB.coeffs().allFinite() && w_B.allFinite() && std::isfinite(h))) {
    q_WB.coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());
    w_B.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  if (advance_short_step(q_WB, w_B, h)) return;
  const TorqueFreeState s = TorqueFreeSolution(axes_, q_WB, w_B, false).evaluate(h);  // NaN if it overflows
  q_WB = s.q_WB;
  w_B = s.w_B;
}

// The short step (class comment), in the units of init_elliptic: the moments over 2^e_I and the body rates over
// 2^e_w (the largest of each in [1, 2)), so that the invariants stay in range for any magnitude; the step's phase
// v = λ h in SI (λ̃ 2^e_w h). In the frame Q (case A: Q = P, L about axis 3, ω_Q = (a_cn cn u, s a_sn sn u,
// s a_dn dn u); case B: Q = (P2, P3, P1), ω_Q = (s a_sn sn u, a_cn cn u, s a_dn dn u)), s the sign of the dn axis'
// rate (init_elliptic's amplitudes).
bool FreeRotationFlow::advance_short_step(Eigen::Quaterniond& q_WB, Eigen::Vector3d& w_B, double h) const {
  const Eigen::Vector3d& I_SI = axes_.moments;
  if (!distinct_moments_ || !(I_SI(0) >= 0x1p-60 * I_SI(2))) return false;
  const Eigen::Vector3d w_P_SI = axes_.axes.transpose() * w_B;
  const double largest_rate = w_P_SI.cwiseAbs().maxCoeff();
  if (!(largest_rate > 0.0)) return false;
  const int e_w = exponent_of(largest_rate);
  const Eigen::Vector3d I = times_pow2(I_SI, -exponent_of(I_SI(2))), w = times_pow2(w_P_SI, -e_w);
  const double I1 = I(0), I2 = I(1), I3 = I(2);
  const Eigen::Vector3d L = I.cwiseProduct(w);
  const double G2 = L.squaredNorm();
  // Δ_j = G² − 2T I_j as sums (Δ1 ≥ 0, Δ3 ≤ 0); Δ2 in plain double: the separatrix's neighbourhood is refused below
  const double D1 = L(1) * L(1) * (I2 - I1) / I2 + L(2) * L(2) * (I3 - I1) / I3;
  const double D3 = L(0) * L(0) * (I1 - I3) / I1 + L(1) * L(1) * (I2 - I3) / I2;
  const double D2 = L(0) * L(0) * (I1 - I2) / I1 + L(2) * L(2) * (I3 - I2) / I3;
  // near a principal axis (a transverse part below 2^-15 G) the full path keeps the transverse direction to the last bit
  if (!(D1 >= 0x1p-30 * G2 && -D3 >= 0x1p-30 * G2)) return false;
  const int t[3] = {0, 0, 0};  // the momentum's components are at most ~2: no scaling of the invariants
  const EllipticMotion e = elliptic_motion(I, D1, D2, D3, t);
  const double lambda = e.lambda, n = e.n;
  double m = e.m, mc = e.mc_hat;
  // near the separatrix (kc below 2^-10) the full path keeps cn and dn to their relative precision past u = K
  if (!(mc >= 0x1p-20 && mc <= 1.0 && m >= 0.0)) return false;
  const double v = rigiddyn::times_pow2(lambda, e_w) * h;
  if (!(std::abs(v) <= 0.25 * M_PI)) return false;  // v ≤ K/2 (K ≥ π/2): the reduced functions' domain
  const double kc = std::sqrt(mc);
  if (mc <= 0.5) m = 1.0 - mc; else mc = 1.0 - m;  // consistent, each from the smaller
  const EllipticParameter p{m, mc, kc, std::numeric_limits<double>::quiet_NaN()};  // K is not read below

  // the functions at u (the rates over their amplitudes) and at v, and the addition theorem (DLMF 22.8.1–3)
  const Eigen::Vector3d w_Q = e.to_Q(w);
  const double s = w_Q(2) < 0.0 ? -1.0 : 1.0;
  const double a_cn = e.amplitude(0), a_sn = e.amplitude(1), a_dn = e.amplitude(2);
  const double cn_u = w_Q(e.cn_axis) / a_cn, sn_u = std::min(std::max(s * w_Q(e.sn_axis) / a_sn, -1.0), 1.0);
  const double dn_u = s * w_Q(2) / a_dn;
  const JacobiSnCnDn f_v = jacobi_ellipj_reduced(v, p);
  const double den = 1.0 - m * sn_u * sn_u * f_v.sn * f_v.sn;
  const double sn_sum = (sn_u * f_v.cn * f_v.dn + f_v.sn * cn_u * dn_u) / den;
  const double cn_sum = (cn_u * f_v.cn - sn_u * f_v.sn * dn_u * f_v.dn) / den;
  // back onto sn² + cn² = 1 and dn² = 1 − m + m cn² (the momentum's sphere and energy ellipsoid), the larger of sn and
  // cn from the smaller (its root of a product of like-signed factors keeps the relative precision), dn from cn: the
  // roundings of the sums would otherwise move both invariants by a biased fraction of an eps per step (a drift of
  // 2.4e-12 in the energy over 10⁶ steps; with the projection it stays at 2e-14, as on the full path)
  double sn_w = sn_sum, cn_w = cn_sum;
  if (std::abs(sn_w) <= std::abs(cn_w)) {
    cn_w = std::copysign(std::sqrt((1.0 - sn_w) * (1.0 + sn_w)), cn_w);
  } else {
    sn_w = std::copysign(std::sqrt((1.0 - cn_w) * (1.0 + cn_w)), sn_w);
  }
  const double dn_w = std::sqrt(mc + m * cn_w * cn_w);

  // Π over the step by Jacobi's addition (class comment), then φ = (G/I_s) h + phi_pi ΔΠ
  const double pi_v = elliptic_f_pi_reduced(f_v, false, n, p).pi;
  const double S = std::sqrt(-n / (m - n)) / std::sqrt(1.0 - n);
  const double delta_pi = pi_v - S * std::atan2(std::sqrt(-n * (m - n) * (1.0 - n)) * sn_u * f_v.sn * sn_w,
                                                1.0 - n * sn_w * sn_w + n * sn_u * f_v.sn * cn_w * dn_w);
  const double G = std::sqrt(G2);
  const double phi = rigiddyn::times_pow2(G / e.I_s, e_w) * h + phi_pi_factor(I, e, G, lambda) * delta_pi;

  // the attitude: q_WB(h) = q_WB q_BQ R_NQ(0, m_Q(0))⁻¹ R_NQ(φ, m_Q(h)) q_BQ⁻¹ (the frame N about L fixed in W)
  Eigen::Vector3d w_Q_h;
  w_Q_h(e.cn_axis) = a_cn * cn_w, w_Q_h(e.sn_axis) = s * a_sn * sn_w, w_Q_h(2) = s * a_dn * dn_w;
  const Eigen::Vector3d I_Q = e.to_Q(I);
  const auto momentum_attitude = [&](const HalfAngle& half_phi, const Eigen::Vector3d& rates_Q) {
    const Eigen::Vector3d m_Q = I_Q.cwiseProduct(rates_Q) / G;  // |m_Q| = 1 (to round-off)
    const double r = std::sqrt(m_Q(0) * m_Q(0) + m_Q(1) * m_Q(1));
    return zxz_from_momentum(half_phi, m_Q(0), m_Q(1), r, r, m_Q(2));
  };
  const Eigen::Quaterniond& q_BQ = q_BQ_[e.case_A ? 0 : 1];
  const Eigen::Quaterniond q_start = momentum_attitude({1.0, 0.0}, w_Q), q_end = momentum_attitude(half_angle(phi), w_Q_h);
  q_WB = (q_WB * q_BQ * q_start.conjugate() * q_end * q_BQ.conjugate()).normalized();
  w_B = axes_.axes * times_pow2(e.to_P(w_Q_h), e_w);
  return true;
}

}  // namespace rigiddyn
