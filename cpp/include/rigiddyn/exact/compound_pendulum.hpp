// The exact motion of the compound pendulum (a planar body pinned at O, under uniform gravity), at any
// energy, as a function of time.
//
// Plane kinetics about the fixed point O (Craig, "Rigid Body Dynamics" slides, rotation about a fixed
// axis; models/pivoted_planar_body.hpp): I_O θ̈ = (c_W × m g)_z with c_W = Rz(θ) c. With d = |c|, γ the
// angle of c in B and θ_g the angle of g_W's in-plane part (g = its length), the angle from the stable
// equilibrium (where R c points along g) ϑ = θ + γ − θ_g obeys the pendulum equation
//   ϑ̈ = −ω0² sin ϑ,  ω0² = m g d / I_O,
// with the energy integral (ϑ̇/2ω0)² + sin²(ϑ/2) = k² (Landau & Lifshitz, Mechanics §11, problem 1; the
// functions as in DLMF §22.19(i)). With s = sin(ϑ0/2), c = cos(ϑ0/2), v = ϑ̇0/(2ω0):
//   m = k² = s² + v²,  mc = 1 − m = (c − |v|)(c + |v|)   (no cancellation beyond the energy's own:
//   near ϑ0 = π, c = sin((π − |ϑ0|)/2) is taken from π − |ϑ0|, not from 1 − s²)
// case        | when            | solution (u = λ t + u0)
// ------------|-----------------|------------------------------------------------------------------------
// rest        | ϑ̇0 = 0 at ϑ0 = 0 or π | constant (an equilibrium, also the unstable one)
// uniform     | m g d = 0        | ϑ = ϑ0 + ϑ̇0 t (no torque; constant if ϑ̇0 = 0)
// libration   | c > |v| (mc > 0) | sin(ϑ/2) = k sn(u|m), cos(ϑ/2) = dn(u|m), ϑ̇ = 2 k ω0 cn(u|m); λ = ω0
// rotation    | c < |v| (mc < 0) | ϑ/2 = σ am(u|1/m), ϑ̇ = 2 σ k ω0 dn(u|1/m); λ = k ω0, σ = sign ϑ̇0
// separatrix  | c = |v| (mc = 0) | as rotation with parameter 1: ϑ/2 = σ gd(u), ϑ̇ = 2 σ ω0 sech u
// ϑ is taken as 2 atan2(sin(ϑ/2), cos(ϑ/2)) (never an arcsine): full precision up to ϑ = π. Periods:
// libration 4 K(m)/ω0, rotation (one turn) 2 K(1/m)/(k ω0), separatrix +inf. The reported θ is
// continuous (as an integrator's): θ(t) = θ0 + (ϑ(t) − ϑ0). s, c and v span the double range (θ0 ~ 1e-300,
// |ω| ~ 1e300, c ~ |v| ~ 1e-300 at the top): the case is decided by c vs |v| (the sign of mc, which itself
// may underflow), kc = √(c − |v|) √(c + |v|), and the elliptic functions take the scaled s/k, v/k, 1/k, so
// that no square underflows or overflows on the way. Accuracy: a few ulps of the elliptic functions
// at t = 0 (m and mc as accurate as the state's rounding allows), growing as eps·|λ t|.
#pragma once
#include "rigiddyn/exact/elliptic.hpp"
#include "rigiddyn/models/pivoted_planar_body.hpp"

#include <Eigen/Core>

#include <string>

namespace rigiddyn {

// Which closed form a CompoundPendulumSolution uses (table above).
enum class PendulumCase { rest, uniform, libration, rotation, separatrix };

// "rest", "uniform", "libration", "rotation" or "separatrix".
std::string to_string(PendulumCase c);

class CompoundPendulumSolution {
 public:
  // body: the pinned planar body (mass m, I_O = inertia_O_zz(), c = p_OC_B); g_W: uniform gravity in the
  // scene frame [m/s²] (only its xy part acts: its z part is held by the pin); state: θ [rad] (B's angle
  // about z) and ω [rad/s] at t = 0. Throws std::invalid_argument naming g_W / state.theta / state.omega
  // for non-finite values.
  CompoundPendulumSolution(const PivotedPlanarBody& body, const Eigen::Vector3d& g_W, const PivotedPlanarBodyState& state);

  // The state at time t [s] (finite, also negative): θ continuous from θ0 (not wrapped), ω = θ̇.
  // Throws std::invalid_argument naming t for a non-finite t, or where the phase λ t (or θ) leaves the
  // double range.
  PivotedPlanarBodyState at(double t) const;

  // Period [s]: libration 4K(m)/ω0 (one full swing), rotation the time of one turn; +inf at rest, on the
  // separatrix, and for the uniform turn with ω = 0 (2π/|ω| otherwise).
  double period() const { return period_; }
  PendulumCase solution_case() const { return case_; }
  // ω0 = √(m g d / I_O) [rad/s] (0 without torque).
  double omega0() const { return omega0_; }
  // k² = sin²(ϑ0/2) + (ϑ̇0/2ω0)² and its complement 1 − k² (negative in rotation), computed without
  // cancellation; 0 and 1 unless libration, rotation or separatrix. Reported as computed: they round to 0
  // (or saturate to ±inf) where k² leaves the double range (s, v ~ 1e-170 or |v| > 1e154); the motion is
  // computed from scaled quantities and does not use them there.
  double k_squared() const { return m_; }
  double k_squared_complement() const { return mc_; }
  // Amplitude ϑ_max = 2 asin k [rad] of the libration about the stable equilibrium (π otherwise).
  double amplitude() const { return amplitude_; }
  // θ of the stable equilibrium (where R c points along g) [rad], in (−π, π].
  double theta_stable() const { return theta_stable_; }
  // The energy about O [J]: ½ I_O ω² − m g_W · c_W(θ) (zero potential at the pivot's level).
  double energy() const { return energy_; }

 private:
  double theta_at(double t, double& omega) const;

  PendulumCase case_ = PendulumCase::rest;
  double theta0_ = 0.0;        // θ at t = 0 as given [rad]
  double vartheta0_ = 0.0;     // ϑ0 reduced to (−π, π] [rad]
  double omega_init_ = 0.0;    // ϑ̇0 [rad/s]
  double omega0_ = 0.0;        // [rad/s]
  double m_ = 0.0, mc_ = 1.0;  // k², 1 − k²
  double k_ = 0.0;             // √m
  double sigma_ = 1.0;         // direction of turning (rotation, separatrix)
  double lambda_ = 0.0;        // rate of the elliptic argument [rad/s]
  double u0_ = 0.0;            // argument at t = 0
  EllipticParameter p_{0.0, 1.0, 1.0, 0.0};  // of the functions used (m or 1/m)
  double period_ = 0.0;
  double amplitude_ = 0.0;
  double theta_stable_ = 0.0;
  double energy_ = 0.0;
};

}  // namespace rigiddyn
