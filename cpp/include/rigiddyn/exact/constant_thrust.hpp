// The exact motion of a particle whose mass changes at a constant rate, under a thrust along a fixed
// world direction and uniform gravity (the shipped `rocket` scene), as a function of time.
//
// Momentum bookkeeping ("Rigid body kinematics and dynamics" notes, eq. (4.36), f = d(mv)/dt for the
// particle and the mass it gains or loses: d(mv)/dt = m g + ṁ (v + u_rel)) gives m v̇ = m g + ṁ u_rel, with
// m(t) = m0 + ṁ t. Integrating once and twice (x = ṁ t / m0, so m(t)/m0 = 1 + x):
//   v(t) = v0 + g t + u_rel ln(1 + x)                                   (Tsiolkovsky with gravity)
//   p(t) = p0 + v0 t + ½ g t² + u_rel t h(x)/x,   h(x) = ∫₀ˣ ln(1 + y) dy = (1 + x) ln(1 + x) − x,
// h(x)/x by its series x/2 − x²/6 + x³/12 − ... = Σ_{k≥2} (−1)^k x^(k−1)/(k (k − 1)) for |x| < 1/4 (the
// closed form cancels there), by the closed form otherwise (a loss of at most 1 + 2/|x| ≤ 9 ulps).
// The speed the thrust alone gives between the masses m0 and m1 is Tsiolkovsky's Δv = |u_rel| ln(m0/m1).
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

// Position [m] and velocity [m/s] in the (inertial) scene frame W, and the mass [kg], at one time.
struct ConstantThrustState {
  Eigen::Vector3d p_W;
  Eigen::Vector3d v_W;
  double mass;
};

class ConstantThrustSolution {
 public:
  // m0: mass at t = 0 [kg], finite > 0; rate: ṁ [kg/s], finite (negative: losing mass); u_rel_W: velocity
  // of the ejected (or gained) mass relative to the particle, in W [m/s] (the thrust is ṁ u_rel_W); g_W:
  // uniform gravity in W [m/s²]; p0_W [m], v0_W [m/s]: the state at t = 0. Throws std::invalid_argument
  // naming the argument for a non-finite value or m0 ≤ 0.
  ConstantThrustSolution(double m0, double rate, const Eigen::Vector3d& u_rel_W, const Eigen::Vector3d& g_W,
                         const Eigen::Vector3d& p0_W, const Eigen::Vector3d& v0_W);

  // The state at time t [s]; throws std::invalid_argument naming t unless t is finite and the mass
  // m0 + ṁ t is positive at t (t < burnout_time(), and t > −m0/ṁ when the particle gains mass).
  ConstantThrustState at(double t) const;
  // m(t) = m0 + ṁ t [kg] (not checked: may be ≤ 0 beyond the burn-out).
  double mass_at(double t) const { return m0_ + rate_ * t; }
  // Tsiolkovsky: the speed the thrust gives while the mass goes from m0 to m1 [m/s], |u_rel| ln(m0/m1)
  // (negative when m1 > m0). Throws std::invalid_argument naming m1 unless finite and > 0.
  double delta_v(double m1) const;
  // The time at which the mass reaches zero, −m0/ṁ [s]; +inf when ṁ ≥ 0.
  double burnout_time() const;

  double m0() const { return m0_; }
  double rate() const { return rate_; }
  const Eigen::Vector3d& u_rel_W() const { return u_rel_W_; }
  const Eigen::Vector3d& g_W() const { return g_W_; }
  const Eigen::Vector3d& p0_W() const { return p0_W_; }
  const Eigen::Vector3d& v0_W() const { return v0_W_; }

 private:
  double m0_, rate_;
  Eigen::Vector3d u_rel_W_, g_W_, p0_W_, v0_W_;
};

}  // namespace rigiddyn
