// Newtonian gravity between the listed bodies (the N-body problem), each a point mass at its centre of
// mass ("Rigid body kinematics and dynamics" notes, §4.11, Newton's law of gravitation), by the direct
// sum over the pairs i < j (O(N²)), with optional Plummer softening ε:
//   d = p_j − p_i,   f_i = G m_i m_j d / (|d|² + ε²)^{3/2} = −f_j,   V = Σ_{i<j} −G m_i m_j / √(|d|² + ε²).
// Each pair's force is computed once and added to i and subtracted from j, so Newton's third law holds
// exactly pair by pair in floating point (the total force differs from zero only by the rounding of the
// per-body sums, so total momentum is conserved to round-off). No torque about
// the centres of mass at this order. With ε = 0 two bodies that meet get non-finite forces.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_bodies.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"
#include "rigiddyn/scene/elements/element_checks.hpp"
#include "rigiddyn/scene/elements/pair_forces.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {

class MutualGravityTerm;

// The spec: gravitational constant G [m³/(kg s²)], softening length [m] (0: exact law), between the
// `bodies` (empty: every body; fewer than two: no pair, no force).
struct MutualGravity {
  static constexpr const char* element_type = "MutualGravity";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "Newtonian gravity between the listed bodies (direct O(N^2) sum over the pairs): f on i = -G m_i m_j "
      "r/(|r|^2 + softening^2)^(3/2), r = p_i - p_j [N], potential V = sum -G m_i m_j/sqrt(|r|^2 + softening^2)"
      " [J].";
  static constexpr const char* example = R"py(Two bodies attract each other: their momentum stays zero and their energy is kept to the method's error:

>>> bodies = [rd.Particle(1.0), rd.Particle(1.0)]
>>> scene = rd.Scene(bodies, elements=[rd.MutualGravity(G=1.0)])
>>> start = [rd.ParticleState(p_W=(-0.5, 0.0, 0.0), v_W=(0.0, -0.5, 0.0)),
...          rd.ParticleState(p_W=(0.5, 0.0, 0.0), v_W=(0.0, 0.5, 0.0))]
>>> result = rd.simulate(scene, start, 1e-3, duration=5.0, method="rk4")
>>> E = result.total_energy
>>> bool(np.allclose(result.linear_momentum_W[-1], 0.0, atol=1e-14)), bool(abs(E[-1] - E[0]) < 1e-9)
(True, True))py";  // the docstring's Examples (run as doctests)
  using Term = MutualGravityTerm;  // what compile makes of it
  double G = 6.67430e-11;
  double softening = 0.0;
  BodyList bodies;

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        scalar_field("G", &MutualGravity::G, "m^3/(kg*s^2)", "gravitational constant [m^3/(kg s^2)]").above_zero(),
        scalar_field("softening", &MutualGravity::softening, "m", "softening length epsilon [m] (0: none)").at_least_zero(),
        bodies_field(&MutualGravity::bodies, "None (every body) or a tuple of the indices of the bodies that attract each other"));
  }
};

// The compiled term: the listed bodies (their masses read from the kinematics, k.m, with
// the positions).
class MutualGravityTerm {
 public:
  // Throws std::invalid_argument "<name>.G: ..." unless G is finite and > 0, "<name>.softening: ..."
  // unless finite and >= 0, "<name>.bodies[k]: ..." for an index out of range or repeated.
  MutualGravityTerm(const MutualGravity& spec, const std::vector<Body>& bodies, const std::string& name)
      : G_(spec.G), softening2_(spec.softening * spec.softening),
        bodies_(detail::resolve_bodies(spec.bodies, bodies.size(), name)) {
    require_positive(spec.G, name + ".G");
    detail::require_nonnegative(spec.softening, name + ".softening");
  }

  static ElementTraits traits() {
    ElementTraits t{};
    t.reads_attitude = false, t.velocity_dependent = false, t.time_dependent = false;
    t.has_potential = true, t.has_torque = false;
    t.zero_net_wrench = true;  // each pair's forces are opposite, along the line between the two centres of mass
    return t;
  }

  // f_W += the pair forces on every listed body; returns Σ f_W·v_W [W].
  // Layout for speed: the positions are gathered into per-thread columns (x, y, z), so that the inner
  // loop over j > i is whole-array arithmetic on vector instructions (pair_forces.hpp: SSE2, or AVX2 with FMA
  // where the CPU has them); the element's forces collect in columns (f_x, f_y, f_z) and are added to `wrenches`
  // once per body, with the power Σ f·v. The scratch grows with the largest body count seen and is never freed:
  // no allocation per evaluation, and two threads evaluating one model do not share it.
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    const Eigen::Index n = static_cast<Eigen::Index>(bodies_.size());
    Eigen::ArrayXXd& columns = scratch(n);  // (n x 8): x, y, z, f_x, f_y, f_z, scratch, m
    auto f_x = columns.col(3), f_y = columns.col(4), f_z = columns.col(5);
    gather(kinematics, columns);
    columns.block(0, 3, n, 3).setZero();  // only this scene's n rows (the scratch may be longer)
    detail::add_pair_forces(columns, n, G_, softening2_);
    double power = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3d f(f_x(i), f_y(i), f_z(i));
      wrenches[bodies_[i]].f_W += f;
      power += f.dot(kinematics[bodies_[i]].v_W);
    }
    return power;
  }

  // V = Σ_{i<j} −G m_i m_j / √(|p_j − p_i|² + ε²) [J] (the same per-thread columns as add_wrenches, on the same
  // vector instructions: pair_forces.hpp)
  double potential(const std::vector<BodyKinematics>& kinematics) const {
    const Eigen::Index n = static_cast<Eigen::Index>(bodies_.size());
    Eigen::ArrayXXd& columns = scratch(n);
    gather(kinematics, columns);
    return detail::pair_potential(columns, n, G_, softening2_);
  }

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  // this thread's scratch columns, at least n rows (grown, never shrunk)
  static Eigen::ArrayXXd& scratch(Eigen::Index n) {
    thread_local Eigen::ArrayXXd columns;
    if (columns.rows() < n) columns.resize(n, 8);
    return columns;
  }

  // the listed bodies' positions into columns 0-2 and masses into column 7
  void gather(const std::vector<BodyKinematics>& kinematics, Eigen::ArrayXXd& columns) const {
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(bodies_.size()); ++i) {
      const BodyKinematics& k = kinematics[bodies_[i]];
      columns(i, 0) = k.p_W.x(), columns(i, 1) = k.p_W.y(), columns(i, 2) = k.p_W.z(), columns(i, 7) = k.m;
    }
  }

  double G_;                   // [m³/(kg s²)]
  double softening2_;          // ε² [m²]
  std::vector<int> bodies_;
};

}  // namespace rigiddyn
