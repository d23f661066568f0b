// The exact torque-free motion: see free_body.hpp for the cases and
// ../shared/notes/free-rigid-body.md for the formulas (Landau & Lifshitz §37; Celledoni, Fassò,
// Säfström, Zanna 2008 with Leroy's errata).
#include "rigiddyn/exact/free_body.hpp"

#include "rigiddyn/check.hpp"


#include <algorithm>
#include <cmath>
#include <limits>

namespace rigiddyn {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

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
DoubleDouble delta2_times_I1_I3(const Eigen::Vector3d& m, const Eigen::Vector3d& I) {
  const DoubleDouble term1 = two_prod(m(0), m(0)) * two_sum(I(0), -I(1)) * DoubleDouble{I(2), 0.0};
  const DoubleDouble term3 = two_prod(m(2), m(2)) * two_sum(I(2), -I(1)) * DoubleDouble{I(0), 0.0};
  return term1 + term3;
}

// unit quaternion exp(v/2) of the rotation vector v [rad]
Eigen::Quaterniond rotation_vector_to_quaternion(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

Eigen::Quaterniond about_z(double angle) {
  return Eigen::Quaterniond(std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle));
}

// q_NQ of Z-X-Z angles (φ, θ, ψ) with θ and ψ read off m_Q = R_NQᵀ (0, 0, G):
// m_Q = G (sin θ sin ψ, sin θ cos ψ, cos θ), θ ∈ [0, π], ψ = atan2(m_a, m_b) ∈ (−π, π]. The half-angle
// cosines and sines come algebraically from m_Q (the larger of each pair by a square root of a sum of
// like-signed terms, the other from sin x = 2 sin(x/2) cos(x/2)), accurate at both poles; then
// Rz(φ) Rx(θ) Rz(ψ) = Rz(φ) (cθ cψ, sθ cψ, −sθ sψ, cθ sψ) with c·, s· of the half angles.
// Needs m_a² + m_b² > 0 (never 0 on the elliptic orbits).
Eigen::Quaterniond zxz_from_momentum(double phi, const Eigen::Vector3d& m_Q) {
  const double rho2 = m_Q(0) * m_Q(0) + m_Q(1) * m_Q(1);
  const double rho = std::sqrt(rho2), G = std::sqrt(rho2 + m_Q(2) * m_Q(2));
  double c_theta, s_theta;  // cos θ/2, sin θ/2 (both >= 0)
  if (m_Q(2) >= 0.0) {
    c_theta = std::sqrt((G + m_Q(2)) / (2.0 * G));
    s_theta = rho / (2.0 * G * c_theta);
  } else {
    s_theta = std::sqrt((G - m_Q(2)) / (2.0 * G));
    c_theta = rho / (2.0 * G * s_theta);
  }
  double c_psi, s_psi;  // cos ψ/2 >= 0, sin ψ/2 with the sign of m_a (of atan2's ψ)
  if (m_Q(1) >= 0.0) {
    c_psi = std::sqrt((rho + m_Q(1)) / (2.0 * rho));
    s_psi = m_Q(0) / (2.0 * rho * c_psi);
  } else {
    s_psi = std::copysign(std::sqrt((rho - m_Q(1)) / (2.0 * rho)), m_Q(0));
    c_psi = m_Q(0) / (2.0 * rho * s_psi);
  }
  const Eigen::Quaterniond tilt(c_theta * c_psi, s_theta * c_psi, -s_theta * s_psi, c_theta * s_psi);
  return about_z(phi) * tilt;
}

double sign_of(double x) { return x < 0.0 ? -1.0 : 1.0; }

// The principal frame (inertia/principal_axes.hpp) of a finite, symmetric, positive definite I_B.
PrincipalAxes checked_principal_axes(const Eigen::Matrix3d& I_B) {
  require_finite(I_B, "inertia");
  if (!((I_B - I_B.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * I_B.cwiseAbs().maxCoeff())) {
    throw_invalid("inertia", "a symmetric matrix (to 1e-12 relative)", I_B);
  }
  PrincipalAxes axes = principal_axes(0.5 * (I_B + I_B.transpose()));
  if (!(axes.moments(0) > 0.0)) throw_invalid("inertia", "a positive definite matrix", I_B);
  return axes;
}

const Eigen::Quaterniond& checked_attitude(const Eigen::Quaterniond& q_WB) {
  require_finite(q_WB.coeffs(), "q_WB");
  if (!(std::abs(q_WB.norm() - 1.0) <= 1e-6)) {
    throw_invalid("q_WB", "a unit quaternion (norm within 1e-6 of 1)", q_WB.coeffs());
  }
  return q_WB;
}

const Eigen::Vector3d& checked_finite(const Eigen::Vector3d& v, const char* name) {
  require_finite(v, name);
  return v;
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
                                       const Eigen::Vector3d& w_B)
    : TorqueFreeSolution(checked_principal_axes(I_B), checked_attitude(q_WB), checked_finite(w_B, "w_B"), true) {}

TorqueFreeSolution::TorqueFreeSolution(const PrincipalAxes& axes, const Eigen::Quaterniond& q_WB,
                                       const Eigen::Vector3d& w_B, bool eager_complete_pi)
    : I_principal_(axes.moments), R_BP_(axes.axes), pi_complete_known_(eager_complete_pi) {
  q_WB0_ = q_WB.normalized();
  w_B0_ = w_B;
  const Eigen::Vector3d& I = I_principal_;
  const Eigen::Vector3d w_P = R_BP_.transpose() * w_B;
  const Eigen::Vector3d m_P = I.cwiseProduct(w_P);
  L_W_ = q_WB0_ * (R_BP_ * m_P);
  kinetic_energy_ = 0.5 * w_P.dot(m_P);

  const double tol = 64.0 * kEps * I(2);
  if (I(2) - I(0) <= tol) {
    case_ = TorqueFreeCase::sphere;
    init_rotation_about_axis(Eigen::Vector3d::Constant(I.mean()), R_BP_.col(2), I.mean());
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

  // Δ1 ≥ 0 and Δ3 ≤ 0 are sums of like-signed terms; Δ2 cancels (see delta2_times_I1_I3)
  const Eigen::Vector3d m2 = m_P.cwiseProduct(m_P);
  const double delta1 = m2(1) * (I(1) - I(0)) / I(1) + m2(2) * (I(2) - I(0)) / I(2);
  const double delta3 = m2(0) * (I(0) - I(2)) / I(0) + m2(1) * (I(1) - I(2)) / I(1);
  const double delta2 = delta2_times_I1_I3(m_P, I).hi / (I(0) * I(2));
  case_ = delta2 > 0.0 ? TorqueFreeCase::A : delta2 < 0.0 ? TorqueFreeCase::B : TorqueFreeCase::separatrix;
  if ((m_P.array() == 0.0).count() >= 2) {
    // steady spin about a principal axis (or rest); about axis 2 the unstable equilibrium on the
    // separatrix. The Z-X-Z angles are singular there (θ = 0), so rotate about the fixed axis.
    about_axis_ = true;
    nu_W_ = q_WB0_ * w_B;
    beta_ = 0.0;
    period_ = kInf;
    return;
  }
  init_elliptic(m_P, delta1, delta3, delta2);
}

// Sphere and symmetric body: ω = m/I_t + β e with β = (I_t − I_a) ω_a / I_t, so that
// R(t) = exp(t (L_W/I_t)^) R0 exp(t β ê) and m(t) = exp(−t β ê) m0 (Landau & Lifshitz §33).
void TorqueFreeSolution::init_rotation_about_axis(const Eigen::Vector3d& I_Q, const Eigen::Vector3d& axis_B,
                                                  double I_axial) {
  about_axis_ = true;
  const Eigen::Vector3d m_B = R_BP_ * I_Q.cwiseProduct(R_BP_.transpose() * w_B0_);
  const double I_t = I_Q(1);  // the transverse moment (the middle one is always transverse)
  e_B_ = axis_B;
  beta_ = (I_t - I_axial) * e_B_.dot(w_B0_) / I_t;
  nu_W_ = q_WB0_ * (m_B / I_t);
  period_ = beta_ == 0.0 ? kInf : 2.0 * M_PI / std::abs(beta_);
}

void TorqueFreeSolution::init_elliptic(const Eigen::Vector3d& m_P, double delta1, double delta3, double delta2) {
  const Eigen::Vector3d& I = I_principal_;
  const double G = m_P.norm();
  const double I1 = I(0), I2 = I(1), I3 = I(2);
  const double A1 = std::sqrt(-delta3 / (I1 * (I3 - I1)));
  const double A3 = std::sqrt(delta1 / (I3 * (I3 - I1)));
  double m, mc;
  Eigen::Matrix3d R_PQ;
  if (case_ != TorqueFreeCase::B) {
    // case A (and the separatrix with m = 1): ω = (σ1 A1 cn, σ1 s A2 sn, s A3 dn), s = sign m3,
    // σ1 = sign m1 on the separatrix (there cn ≥ 0), else 1
    const double A2 = std::sqrt(-delta3 / (I2 * (I3 - I2)));
    const double s = sign_of(m_P(2));
    const double sigma1 = case_ == TorqueFreeCase::separatrix ? sign_of(m_P(0)) : 1.0;
    lambda_ = std::sqrt((I3 - I2) * delta1 / (I1 * I2 * I3));
    m = (I2 - I1) * -delta3 / ((I3 - I2) * delta1);
    mc = (I3 - I1) * delta2 / ((I3 - I2) * delta1);
    n_ = -I3 * (I2 - I1) / (I1 * (I3 - I2));
    R_PQ.setIdentity();
    cn_axis_ = 0;
    sn_axis_ = 1;
    w_amplitude_ = Eigen::Vector3d(sigma1 * A1, sigma1 * s * A2, s * A3);
    phi_pi_ = G * (I3 - I1) / (I1 * I3 * lambda_);
    phi_rate_ = G / I3;
    I_Q_ = I;
  } else {
    // case B: ω = (s A1 dn, s A2 sn, A3 cn), s = sign m1
    const double A2 = std::sqrt(delta1 / (I2 * (I2 - I1)));
    const double s = sign_of(m_P(0));
    lambda_ = std::sqrt((I2 - I1) * -delta3 / (I1 * I2 * I3));
    m = (I3 - I2) * delta1 / ((I2 - I1) * -delta3);
    mc = (I3 - I1) * -delta2 / ((I2 - I1) * -delta3);
    n_ = -I1 * (I3 - I2) / (I3 * (I2 - I1));
    R_PQ << 0, 0, 1,  // Q = (P2, P3, P1): a cyclic relabelling, det +1
        1, 0, 0,      //
        0, 1, 0;
    sn_axis_ = 0;
    cn_axis_ = 1;
    w_amplitude_ = Eigen::Vector3d(A3, s * A2, s * A1);
    phi_pi_ = -G * (I3 - I1) / (I1 * I3 * lambda_);
    phi_rate_ = G / I1;
    I_Q_ = Eigen::Vector3d(I2, I3, I1);
  }
  // m and mc are each accurate; make them consistent from the smaller one
  if (mc <= 0.5) {
    mc = std::max(mc, 0.0);
    m = 1.0 - mc;
  } else {
    m = std::min(std::max(m, 0.0), 1.0);
    mc = 1.0 - m;
  }
  elliptic_ = elliptic_parameter(m, mc);

  // phase u0 from the initial (sn, cn, dn) = ω_Q / amplitudes
  const Eigen::Vector3d w_Q = R_PQ.transpose() * m_P.cwiseQuotient(I);
  JacobiSnCnDn f0;
  f0.sn = std::min(std::max(w_Q(sn_axis_) / w_amplitude_(1), -1.0), 1.0);
  f0.cn = w_Q(cn_axis_) / w_amplitude_(0);
  f0.dn = w_Q(2) / w_amplitude_(2);
  // u0 = v0 + 2 j0 K: v0 = sn0 R_F(cn0², dn0², 1) ∈ [−K, K] (j0 = 0) when cn0 >= 0; else the point
  // (sn, cn) = (−sn0, −cn0) of [−K, K] shifted by 2 j0 K, j0 = sign(sn0) (sn, cn change sign under
  // u → u + 2K, DLMF 22.4.2)
  if (f0.cn < 0.0) {
    f0.sn = -f0.sn;
    f0.cn = -f0.cn;
    j0_odd_ = true;
  }
  const EllipticFPi at_v0 = elliptic_f_pi_sncndn(f0, n_);
  v0_ = at_v0.f;
  pi0_ = at_v0.pi;
  if (pi_complete_known_) pi_complete_ = complete_pi();
  period_ = elliptic_.mc == 0.0 ? kInf : 4.0 * elliptic_.K / lambda_;

  q_BQ_ = Eigen::Quaterniond(R_BP_ * R_PQ);
  q_BQ_.normalize();
  const Eigen::Vector3d m_Q = R_PQ.transpose() * m_P;
  q_WN_ = q_WB0_ * q_BQ_ * zxz_from_momentum(0.0, m_Q).conjugate();
}

TorqueFreeState TorqueFreeSolution::state_at(double t) const {
  if (!std::isfinite(t)) throw_invalid("t", "a finite number", t);
  return about_axis_ ? state_about_axis(t) : state_elliptic(t);
}

// Π(n|m) = K + (n/3) R_J(0, mc, 1, 1 − n) (DLMF 19.25.2); 0 on the separatrix (never used there)
double TorqueFreeSolution::complete_pi() const {
  return elliptic_.mc == 0.0 ? 0.0 : elliptic_.K + n_ / 3.0 * elliprj(0.0, elliptic_.mc, 1.0, 1.0 - n_);
}

TorqueFreeState TorqueFreeSolution::state_about_axis(double t) const {
  const Eigen::Quaterniond q_WB =
      rotation_vector_to_quaternion(nu_W_ * t) * q_WB0_ * rotation_vector_to_quaternion(e_B_ * (beta_ * t));
  const Eigen::Vector3d w_B = Eigen::AngleAxisd(-beta_ * t, e_B_) * w_B0_;
  return {q_WB.normalized(), w_B};
}

TorqueFreeState TorqueFreeSolution::state_elliptic(double t) const {
  const EllipticParameter& p = elliptic_;
  // u = λ t + u0 = v + 2jK with v ∈ [−K, K]; λ t kept as an exact two-product so that the reduction
  // loses nothing beyond the rounding of λ and K
  const DoubleDouble lambda_t = two_prod(lambda_, t);
  double j = 0.0;
  double v = lambda_t.hi + v0_;
  if (p.mc != 0.0) {
    j = std::nearbyint(v / (2.0 * p.K));
    v = (std::fma(-2.0 * p.K, j, lambda_t.hi) + lambda_t.lo) + v0_;
  }
  JacobiSnCnDn f = jacobi_ellipj(v, p);
  // Π(am u) − Π(am u0) = Π(am v) − Π(am v0) + 2j Π(n|m)   (quasi-periodicity)
  double delta_pi = ellippi_sncndn(f, n_) - pi0_;
  if (j != 0.0) delta_pi += 2.0 * j * (pi_complete_known_ ? pi_complete_ : complete_pi());
  if ((std::fmod(j, 2.0) != 0.0) != j0_odd_) {  // sn(v + 2(j + j0)K) = (−1)^(j + j0) sn v, cn likewise
    f.sn = -f.sn;
    f.cn = -f.cn;
  }
  Eigen::Vector3d w_Q;
  w_Q(cn_axis_) = w_amplitude_(0) * f.cn;
  w_Q(sn_axis_) = w_amplitude_(1) * f.sn;
  w_Q(2) = w_amplitude_(2) * f.dn;
  // φ(t) = (G/I_s) t − [G Δ_s/(I_s (G² − B²) λ)] [Π]_{u0}^{u}, the bracket's factor simplified
  // (G² − B² = I1(−Δ3)/(I3 − I1) in case A, I3 Δ1/(I3 − I1) in case B) to ±G(I3 − I1)/(I1 I3 λ)
  const double phi = phi_rate_ * t + phi_pi_ * delta_pi;
  const Eigen::Quaterniond q_NQ = zxz_from_momentum(phi, I_Q_.cwiseProduct(w_Q));
  const Eigen::Quaterniond q_WB = q_WN_ * q_NQ * q_BQ_.conjugate();
  return {q_WB.normalized(), q_BQ_ * w_Q};
}

}  // namespace rigiddyn

namespace rigiddyn {

FreeRotationFlow::FreeRotationFlow(const Eigen::Matrix3d& I_B) : I_B_(I_B), axes_(checked_principal_axes(I_B)) {}

void FreeRotationFlow::advance(Eigen::Quaterniond& q_WB, Eigen::Vector3d& w_B, double h) const {
  if (!(q_WB.coeffs().allFinite() && w_B.allFinite() && std::isfinite(h))) {
    q_WB.coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());
    w_B.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const TorqueFreeState s = TorqueFreeSolution(axes_, q_WB, w_B, false).state_at(h);
  q_WB = s.q_WB;
  w_B = s.w_B;
}

}  // namespace rigiddyn
