// The exact motion of the heavy symmetric (Lagrange) top about its fixed point, as a function of time.
//
// The body is pinned at O with its centre of mass C on its symmetry axis e3 = c/l (c = p_OC_B, l = |c|),
// the inertia about O symmetric about e3 (I_O = I1 (1 − e3 e3ᵀ) + I3 e3 e3ᵀ), under uniform gravity g_W.
// N is an inertial frame with z_N = −g_W/|g| (up) and x_N along the line of nodes at t = 0; S is fixed in
// B with axes (e1, e2, e3). The attitude is R_NS = Rz(φ) Rx(θ) Rz(ψ) (Euler angles Z-X-Z), so that
// u = cos θ = e3 · z_N. Lagrange's integrals (Goldstein, Classical Mechanics, §5.7; Landau & Lifshitz,
// Mechanics §35, problem 1), with ω = (ω1, ω2, ω3) in S and z_S = (z1, z2, u) the vertical in S:
//   a = I3 ω3 / I1,  b = H_z / I1 = ω1 z1 + ω2 z2 + a u,   (spin and vertical angular momentum about O)
//   α = 2 E'/I1 = ω1² + ω2² + β u,  β = 2 m |g| l / I1,     (E' the energy less ½ I3 ω3²)
//   u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)² = β (u − u1)(u − u2)(u − u3),  −1 ≤ u1 ≤ u ≤ u2 ≤ 1 ≤ u3,
//   φ̇ = (b − a u)/(1 − u²),  ψ̇ = ω3 − u φ̇.
// The cubic is solved in x = u − u0 from the state itself (f(u0) = u̇0² = (z1 ω2 − z2 ω1)², f'(u0),
// f''(u0)/2 and β: no cancellation of the potential in α), its largest root x3 by Newton's method from
// above (monotone: the cubic is convex there), the other two from the deflated quadratic, whose
// product −f(u0)/(β x3) ≤ 0 keeps them apart without cancellation. Then with Δ = u2 − u1,
//   u = u1 + Δ sn²(τ|m),  τ = λ t + τ0,  m = Δ/(u3 − u1),  λ = √(β (u3 − u1))/2,
// and, by partial fractions of φ̇ and ψ̇ over 1 ∓ u = (1 ∓ u1)(1 − n± sn²), n+ = Δ/(1 − u1), n− = −Δ/(1 + u1),
//   P± = (b ∓ a)/(2 λ (1 ∓ u1)) [Π(am τ, n±|m) − Π(am τ0, n±|m)],
//   φ = P+ + P−,  ψ = ψ0 + (ω3 − a) t − P+ + P−,
// (Π the incomplete integral of the third kind, exact/elliptic.hpp). The nutation period is 2K(m)/λ and the
// mean precession rate λ (c+ Π(n+|m) + c− Π(n−|m))/K(m), c± the coefficients above.
//
// case        | when                                         | motion
// ------------|----------------------------------------------|-----------------------------------------
// nutation    | u1 < u2 (or u1 = u2 found exactly: m = 0)     | the closed form above
// sleeping    | e3 vertical (up or down) and ω ∥ e3, to the   | a uniform spin about the vertical
//             | state's rounding: |z⊥| ≤ 4 eps, |ω⊥| ≤ 4 eps |ω3| | (a slow, unstable top leaves it
//             |                                              |  exponentially from any perturbation)
// Refused (std::invalid_argument naming state): the symmetry axis passing through a vertical, u2 = 1 or
// u1 = −1 to within 16 eps (there Euler's angles are singular; e.g. e3 vertical with ω not along it).
// Also refused (naming state): a spin whose a² or |ω⊥|² exceeds the double range (|ω| ≳ 1e154).
// Accuracy: a few ulps of the roots and the elliptic functions at t = 0, growing as eps·|λ t|; an axis
// that comes within 1 − u2 of the upward vertical loses ~eps/√(1 − u2) in φ and ψ (Π near n = 1). For a
// fast top P± ≈ ∓(a/2λ) τ cancel in φ = P+ + P−: φ(t) carries eps (I3 ω3)²/(I1 m g l) relative (the
// mean precession rate does not: its K parts are summed as c+ + c− = (b − a u1)/(λ (1 − u1²)) first). The
// cubic's coefficients and Newton's iterates are scaled by a power of two (no x³ overflow up to |A| ~ 1e300).
#pragma once
#include "rigiddyn/exact/elliptic.hpp"
#include "rigiddyn/models/pivoted_body.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace rigiddyn {

// Which closed form a LagrangeTopSolution uses (table above).
enum class LagrangeTopCase { nutation, sleeping };

// "nutation" or "sleeping".
std::string to_string(LagrangeTopCase c);

// Euler angles Z-X-Z of R_NS [rad]: precession φ, nutation θ, spin ψ.
struct EulerAnglesZXZ {
  double phi;
  double theta;
  double psi;
};

class LagrangeTopSolution {
 public:
  // body: pinned at O, its inertia about O symmetric about the axis O→C (relative 1e-12) and C off O;
  // g_W: uniform gravity in the scene frame [m/s²], non-zero; state: q_WB, w_B [rad/s] (in B) at t = 0.
  // Throws std::invalid_argument naming body, g_W or state (bad values, or a motion through a vertical).
  LagrangeTopSolution(const PivotedBody& body, const Eigen::Vector3d& g_W, const PivotedBodyState& state);

  // The state at time t [s] (finite, also negative): q_WB and w_B [rad/s] in B. Throws
  // std::invalid_argument naming t for a non-finite t.
  PivotedBodyState at(double t) const;
  // Euler angles (φ, θ, ψ) of R_NS at t [rad] (φ(0) = 0; φ and ψ continuous, not wrapped).
  EulerAnglesZXZ angles_at(double t) const;

  LagrangeTopCase solution_case() const { return case_; }
  // Nutation bounds θ_min = acos u2, θ_max = acos u1 [rad] (tilt of e3 from the upward vertical −g_W).
  double theta_min() const { return theta_min_; }
  double theta_max() const { return theta_max_; }
  // Period of θ(t) [s], 2K(m)/λ (its small-nutation limit π/λ when u1 = u2; +inf when sleeping).
  double nutation_period() const { return nutation_period_; }
  // λ [1/s], the rate of the elliptic functions' argument τ = λ t + τ0 (0 when sleeping).
  double elliptic_rate() const { return lambda_; }
  // Mean precession rate: φ's change over one nutation period divided by it [rad/s] (φ̇ when sleeping: 0).
  double mean_precession_rate() const { return mean_precession_rate_; }
  // Lagrange's constants a, b [rad/s] and α, β [1/s²] (Goldstein's notation, above).
  double a() const { return a_; }
  double b() const { return b_; }
  double alpha() const { return alpha_; }
  double beta() const { return beta_; }
  // Roots u1 ≤ u2 ≤ u3 of the cubic f(u) (u1 = u2 = u3 = u0 when sleeping).
  Eigen::Vector3d roots() const { return Eigen::Vector3d(u0_ + x_[0], u0_ + x_[1], u0_ + x_[2]); }
  // Parameter m = (u2 − u1)/(u3 − u1) of sn² and its complement, computed without cancellation.
  double parameter_m() const { return p_.m; }
  double parameter_mc() const { return p_.mc; }
  // I1 = I2 and I3 [kg m²] about O; the symmetry axis e3 = c/|c| in B.
  double I1() const { return I1_; }
  double I3() const { return I3_; }
  Eigen::Vector3d e3_B() const { return R_BS_.col(2); }
  // The frame N of the Euler angles: z_N = −g_W/|g|, x_N the line of nodes at t = 0.
  const Eigen::Quaterniond& q_WN() const { return q_WN_; }
  // The conserved quantities: energy about O [J] (½ ω·I_O ω − m g_W·R c), H_z = H_O·z_N and H_3 = I3 ω3
  // [kg m²/s].
  double energy() const { return energy_; }
  double H_z() const { return I1_ * b_; }
  double H_3() const { return I3_ * omega3_; }

 private:
  void init_roots(double f0, double f1, double f2);

  LagrangeTopCase case_ = LagrangeTopCase::nutation;
  double I1_ = 0.0, I3_ = 0.0;
  Eigen::Matrix3d R_BS_;        // columns e1, e2, e3 in B
  Eigen::Quaterniond q_WN_;
  Eigen::Quaterniond q_SB_;
  Eigen::Quaterniond q_WB0_;    // the initial attitude (sleeping)
  double omega3_ = 0.0;         // [rad/s]
  double a_ = 0.0, b_ = 0.0, alpha_ = 0.0, beta_ = 0.0;
  double rho0_ = 0.0;           // b − a u0 [rad/s]
  double u0_ = 1.0;
  double one_minus_u0_ = 0.0, one_plus_u0_ = 2.0;
  Eigen::Vector3d x_ = Eigen::Vector3d::Zero();  // roots minus u0
  double one_minus_u2_ = 0.0, one_plus_u1_ = 2.0, one_minus_u1_ = 0.0;
  EllipticParameter p_{0.0, 1.0, 1.0, 0.5 * M_PI};
  double lambda_ = 0.0, tau0_ = 0.0;
  double n_plus_ = 0.0, n_minus_ = 0.0;     // characteristics n+, n−
  double c_plus_ = 0.0, c_minus_ = 0.0;     // coefficients of Π [rad]
  double pi_plus0_ = 0.0, pi_minus0_ = 0.0; // Π(am τ0, n±|m)
  double psi0_ = 0.0;
  double theta_min_ = 0.0, theta_max_ = 0.0;
  double nutation_period_ = 0.0, mean_precession_rate_ = 0.0;
  double energy_ = 0.0;
};

}  // namespace rigiddyn
