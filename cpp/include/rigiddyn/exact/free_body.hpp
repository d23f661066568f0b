// The exact motion of a torque-free rigid body (Euler–Poinsot), as a function of time.
//
// Body angular momentum L_B = I ω (about the centre of mass, in the body's principal frame), Euler's
// equations L̇_B = L_B × ω, attitude Ṙ_WB = R_WB ω̂, spatial L_W = R_WB L_B constant
// (Landau & Lifshitz, Mechanics §37; Celledoni, Fassò, Säfström, Zanna 2008). Principal moments are
// sorted I1 < I2 < I3 by a rotation (a signed permutation when I is diagonal) of determinant +1.
// With G² = |L_B|², 2T = Σ L_i²/I_i and Δ_j = G² − 2T I_j (computed without cancellation):
//
// case           | when                                   | ω(t)                                   | attitude
// ---------------|----------------------------------------|----------------------------------------|----------------------------------
// sphere         | I3 − I1 ≤ tol                           | constant                               | exp(ω_W t) q0
// symmetric      | I2 − I1 ≤ tol or I3 − I2 ≤ tol          | rotates about the symmetry axis        | exp(L_W t/I_t) q0 exp(β t e_B)
// A              | Δ2 > 0 (L_B circulates about axis 3)    | (cn, sn, dn)(λt + u0 | m) on (1, 2, 3) | Z-X-Z about L, φ via Π(am u, n|m)
// B              | Δ2 < 0 (L_B circulates about axis 1)    | (dn, sn, cn)(λt + u0 | m) on (1, 2, 3) | Z-X-Z about L, φ via Π(am u, n|m)
// separatrix     | Δ2 = 0 exactly (in double-double)       | (sech, tanh, sech)(λt + u0) on (1,2,3) | as A with m = 1
// (A, B, sep.)   | steady spin: two of L1, L2, L3 are 0    | constant                               | exp(ω_W t) q0
//
// tol = 64 eps I3: moments closer than this are not resolvable from a Matrix3d inertia (its
// eigen-decomposition is only that accurate); the equal pair is replaced by its mean, which changes
// the motion by less than 64 eps relative per radian turned. Δ2 is evaluated in double-double
// (FMA two-products and compensated sums), so that 1 − m keeps full relative precision down to the
// separatrix. Accuracy: a few ulps in ω and attitude at t = 0, growing as eps·|phase| with t.
#pragma once
#include "rigiddyn/exact/elliptic.hpp"
#include "rigiddyn/exact/elliptic_theta.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/inertia/validity.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>

namespace rigiddyn {

// Which closed form a TorqueFreeSolution uses (table above).
enum class TorqueFreeCase { sphere, symmetric, A, B, separatrix };

// "sphere", "symmetric", "A", "B" or "separatrix".
std::string to_string(TorqueFreeCase c);

// The state of the body at one time: attitude q_WB (unit) and angular velocity w_B [rad/s] of B in
// W, expressed in B.
struct TorqueFreeState {
  Eigen::Quaterniond q_WB;
  Eigen::Vector3d w_B;
};

class TorqueFreeSolution {
 public:
  // e^(iφ/2) of an angle φ about z as (cos φ/2, sin φ/2): the precession angle, kept as this rotor where it
  // comes from a theta function (EllipticTheta::Phase)
  struct HalfAngle {
    double c;
    double s;
  };

  // I_B: rotational inertia about the centre of mass, expressed in B [kg m²], symmetric positive
  // definite and, under InertiaCheck::physical (the default, as every inertia in rigiddyn), satisfying
  // the triangle inequality I1 + I2 >= I3 on its principal moments (validity.hpp: a body exists with
  // it); InertiaCheck::allow_unrealizable accepts any symmetric positive definite matrix (test
  // problems such as Hairer-Lubich-Wanner's diag(2, 1, 2/3));
  // q_WB: initial attitude (norm within 1e-6 of 1; normalised); w_B: initial angular velocity of
  // B, expressed in B [rad/s], finite. Throws std::invalid_argument on bad input, and naming w_B when a
  // rate of the motion (of the order of |w_B| I_max/I_min) exceeds the double range. Any magnitudes are
  // accepted otherwise (the motion is formed with the inertia and w_B scaled by powers of two); the
  // invariants L_W and T alone may overflow to inf (angular_momentum_W(), kinetic_energy()). Throws naming the
  // inertia when its principal moments span so many orders (~1e150 and more) that the parameters of the
  // elliptic functions, up to ~(I_max/I_min)² in the scaled units, exceed the double range for this w_B.
  TorqueFreeSolution(const Eigen::Matrix3d& I_B, const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& w_B,
                     InertiaCheck check = InertiaCheck::physical);

  // The state at time t [s] (any finite real, also negative) after the initial one. Throws
  // std::invalid_argument naming t when a phase (a rate times t) overflows the double range.
  TorqueFreeState state_at(double t) const;

  // Period of w_B(t) [s] (4K/λ in cases A and B; 2π/|β| for a symmetric body); +inf when w_B is
  // constant, on the separatrix, or when the period exceeds the double range. One intermediate-axis
  // flip (Dzhanibekov) takes half of it.
  double period() const { return period_; }
  TorqueFreeCase solution_case() const { return case_; }
  // Parameter m of the elliptic functions and its complement 1 − m (0 and 1 unless case A or B;
  // 1 and 0 on the separatrix).
  double parameter_m() const { return elliptic_.m; }
  double parameter_mc() const { return elliptic_.mc; }
  // Principal moments I1 ≤ I2 ≤ I3 [kg m²] and R_BP (columns: principal axes in B, det +1).
  const Eigen::Vector3d& principal_moments() const { return I_principal_; }
  const Eigen::Matrix3d& R_BP() const { return R_BP_; }
  // The invariants: spatial angular momentum L_W [kg m²/s] and kinetic energy T [J] (±inf beyond the
  // double range, rounded towards 0 below it).
  const Eigen::Vector3d& angular_momentum_W() const { return L_W_; }
  double kinetic_energy() const { return kinetic_energy_; }

 private:
  friend class FreeRotationFlow;
  // axes: the principal frame of the inertia (checked); q_WB, w_B unchecked; for_many_times: compute Π(n|m) and
  // the theta series of the reduced Π now (else Π(n|m) only when an evaluation needs it, and Carlson's forms)
  TorqueFreeSolution(const PrincipalAxes& axes, const Eigen::Quaterniond& q_WB, const Eigen::Vector3d& w_B,
                     bool for_many_times);
  double complete_pi() const;
  TorqueFreeState evaluate(double t) const;  // state_at without its checks (NaN where a phase overflows)
  void init_rotation_about_axis(const Eigen::Vector3d& I_Q, const Eigen::Vector3d& axis_B, double I_axial);
  // I: principal moments scaled by a power of two (the largest in [1, 2)); L_tilde = I ∘ w̃ with the
  // body rate ω_P = 2^e_rate w̃
  void init_elliptic(const Eigen::Vector3d& I, const Eigen::Vector3d& L_tilde, int e_rate);
  double max_rate() const;  // the largest rate of the motion [rad/s] (inf if one overflowed)
  void init_phase(const Eigen::Vector3d& mh_Q, double kc_M_dn_hat, int t2);
  TorqueFreeState state_about_axis(double t) const;
  TorqueFreeState state_elliptic(double t) const;
  TorqueFreeState state_separatrix(double t) const;
  TorqueFreeState state_from_functions(const HalfAngle& half_phi, const JacobiSnCnDn& f_w, double quarter) const;
  HalfAngle half_phi_from_theta(double t, double l, double w, const EllipticTheta::Phase& at_w) const;

  TorqueFreeCase case_;
  Eigen::Vector3d I_principal_;
  Eigen::Matrix3d R_BP_;
  Eigen::Vector3d L_W_;
  double kinetic_energy_;
  double period_;
  Eigen::Quaterniond q_WB0_;
  Eigen::Vector3d w_B0_;

  // sphere, symmetric and steady spin (about_axis_):
  // q(t) = exp(nu_W t) q0 exp(beta t e_B), ω(t) = exp(−β t ê_B) ω0
  bool about_axis_ = false;
  Eigen::Vector3d nu_W_ = Eigen::Vector3d::Zero();  // L_W / I_t [rad/s]
  Eigen::Vector3d e_B_ = Eigen::Vector3d::UnitZ();  // symmetry axis in B
  double beta_ = 0.0;                               // body spin rate about e_B [rad/s]

  // cases A, B, separatrix: in the frame Q = (a, b, s) of principal axes, s carrying dn,
  // ω_Q = (A_cn cn, A_sn sn, A_dn dn) placed at (cn_axis, sn_axis, 2); u = λ t + u0, u0 = l0 K + w0.
  // Momenta are kept in units of 2^e |L_B| (the largest component in [1, 2)); the transverse
  // amplitudes (cn, sn) carry an extra 2^t_trans and kc = 2^t_kc k̂c, so that a transverse part down to
  // the smallest subnormal keeps its direction and nothing underflows before it must.
  EllipticParameter elliptic_{0.0, 1.0, 1.0, 0.0};
  Eigen::Quaterniond q_BQ_;
  Eigen::Quaterniond q_WN_;                         // N: inertial, z along L_W
  Eigen::Vector3d w_amplitude_ = Eigen::Vector3d::Zero();  // signed (A_cn, A_sn, A_dn) [rad/s]
  Eigen::Vector2d kc_w_amplitude_ = Eigen::Vector2d::Zero();  // kc (A_cn, A_dn) [rad/s] (odd quarters)
  Eigen::Vector3d M_ = Eigen::Vector3d::Zero();     // I_Q A: (cn, sn) mantissas (× 2^t_trans), dn in units of |L_B|
  Eigen::Vector2d kc_M_ = Eigen::Vector2d::Zero();  // kc times the cn mantissa and the dn momentum (odd quarters)
  int t_trans_ = 0;
  int cn_axis_ = 0;
  int sn_axis_ = 1;
  double lambda_ = 0.0;                             // [1/s]
  double w0_ = 0.0;                                 // reduced phase |w0| <= K/2 (the separatrix: u0)
  double l0_ = 0.0;                                 // quarter periods in u0, in {-1, 0, 1, 2}
  double n_ = 0.0;                                  // characteristic of Π
  bool pi_complete_known_ = false;
  double pi_complete_ = 0.0;                        // Π(n|m) (if known)
  double pi0_ = 0.0;                                // reduced Π at w0 (the separatrix: a atan(a tanh u0))
  // sn, cn, dn and the phase of Π by theta series, where they apply, in a solution made for many times (the public
  // constructor): a few terms per time instead of the argument halving and a Carlson sequence; else
  // jacobi_ellipj_reduced and elliptic_f_pi_reduced
  std::optional<EllipticTheta> theta_;
  double sigma_ = 1.0;                              // φ's coefficient of arg Θ, phi_pi_ S = ±1
  double linear0_ = 0.0;                            // the linear part of arg Θ at w0
  HalfAngle theta0_{1.0, 0.0};                      // e^(−iσ θ0/2), θ0 the rest of arg Θ at w0
  double phi_rate_ = 0.0;                           // G/I_s [rad/s]
  double phi_pi_ = 0.0;                             // coefficient of Π in φ [rad]
  bool parameters_in_range_ = true;                 // false: the elliptic parameters overflowed (evaluate gives NaN)
};

// The exact torque-free rotation over one step, for a fixed inertia: the principal frame is computed
// once here. A short step of an ordinary motion (distinct moments, ω neither near a principal axis nor near the
// separatrix, |λ h| ≤ π/4, moderate magnitudes) advances by the addition theorems: the Jacobi functions at the
// start are the momentum's own components over their amplitudes, those of the step λh come from its Maclaurin
// series, their sum's from the addition theorem (DLMF 22.8.1–3), and the third-kind integral over the step from
// Jacobi's addition of Π (Whittaker & Watson §22.74, at the imaginary point of n < 0):
//   Π(am(u + v)) − Π(am u) = Π(am v) − S atan2(√(−n(m − n)(1 − n)) sn u sn v sn w, 1 − n sn² w + n sn u sn v cn w dn w),
// w = u + v, S as in elliptic_theta.hpp: one Carlson evaluation at near-unit arguments and no inverse F of the
// initial phase. Every other step builds the closed form from the momentum (TorqueFreeSolution without its
// eigen-decomposition, no complete Π(n|m) unless the step crosses a half period of ω) and evaluates it at h. Both
// give TorqueFreeSolution(I_B, q_WB, w_B).state_at(h) to round-off.
class FreeRotationFlow {
 public:
  // I_B as for TorqueFreeSolution under InertiaCheck::allow_unrealizable (throws std::invalid_argument
  // unless symmetric positive definite): a stepper advances a body whose inertia was checked when
  // the body was built.
  explicit FreeRotationFlow(const Eigen::Matrix3d& I_B);
  const Eigen::Matrix3d& inertia() const { return I_B_; }
  // Advances the attitude q_WB (unit) and the angular velocity w_B [rad/s] (in B) by h [s]. A
  // non-finite state, and one whose motion exceeds the double range (where TorqueFreeSolution throws),
  // becomes NaN (no exception: a stepping loop records the divergence).
  void advance(Eigen::Quaterniond& q_WB, Eigen::Vector3d& w_B, double h) const;

 private:
  // The short step by the addition theorems (class comment); false, leaving q_WB and w_B alone, where it does not
  // apply.
  bool advance_short_step(Eigen::Quaterniond& q_WB, Eigen::Vector3d& w_B, double h) const;

  Eigen::Matrix3d I_B_;
  PrincipalAxes axes_;
  bool distinct_moments_;        // the three principal moments farther apart than TorqueFreeSolution's 64 eps I3
  Eigen::Quaterniond q_BQ_[2];   // the frame Q of the closed form in B: Q = P (L about axis 3), Q = (P2, P3, P1)
};

}  // namespace rigiddyn
