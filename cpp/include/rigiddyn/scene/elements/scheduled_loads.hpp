// Applied loads with a time schedule on one body (models/loads.hpp: forces and torques, each in W or
// in B, each active on [t_start, t_end)), the forces applied at the point point_B of the body (from its
// centre of mass, in B), which adds the torque r_B × f_B about the centre of mass (Craig, "Rigid Body
// Dynamics" slides, moment of a force about G). No potential (the loads may do any work).
//
// The schedule is piecewise constant: the run loop (simulate_scene) splits every step at the switch
// times, as simulate does for one body, and sets the loads of the next piece (set_time) between the
// sub-steps; a derivative evaluation never looks at the time.
#pragma once
#include "rigiddyn/models/euler_equations.hpp"  // cross_3, times_3x3, transpose_times_3x3
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/scene/element_fields.hpp"
#include "rigiddyn/scene/element_traits.hpp"

#include <Eigen/Core>

#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace rigiddyn {

class ScheduledLoadsTerm;

// The spec: the schedule `loads` on body `body`, forces applied at point_B [m] (in B, from the centre of
// mass; zero: through the centre of mass).
struct ScheduledLoads {
  static constexpr const char* element_type = "ScheduledLoads";  // its name in records and messages
  static constexpr const char* doc =  // the Python class's docstring
      "The piecewise-constant schedule `loads` (AppliedLoad or a sequence: force [N] and torque [N m], each in "
      "W or B, active on [t_start, t_end) [s]) on body `body`, the forces applied at point_B (in B, from the "
      "centre of mass; adds the torque point_B x f_B). A run splits its steps at the switch times, as simulate "
      "does for one body.";
  static constexpr const char* example = R"py(A torque of 1 N m about z on for the first second of a sphere with I = 0.5 kg m²: ω = 2 rad/s after it:

>>> sphere = rd.RigidBody(1.0, [0.5, 0.5, 0.5])
>>> torque = rd.AppliedLoad(torque=(0.0, 0.0, 1.0), t_end=1.0)
>>> scene = rd.Scene([sphere], elements=[rd.ScheduledLoads(body=0, loads=torque)])
>>> result = rd.simulate(scene, [rd.RigidBodyState()], 0.01, duration=3.0, method="rk4")
>>> result.w_B[-1, 0].round(12)
array([0., 0., 2.]))py";  // the docstring's Examples (run as doctests)
  using Term = ScheduledLoadsTerm;  // what compile makes of it
  int body = 0;
  std::vector<AppliedLoad> loads;
  Eigen::Vector3d point_B = Eigen::Vector3d::Zero();

  // the field table (scene/element_fields.hpp)
  static constexpr auto fields() {
    return std::make_tuple(
        body_field("body", &ScheduledLoads::body, "index of the body the loads act on"),
        ElementField<ScheduledLoads, std::vector<AppliedLoad>>{"loads", &ScheduledLoads::loads, FieldKind::loads, "",
                                                               "tuple of AppliedLoad: the piecewise-constant schedule"},
        vector_field("point_B", &ScheduledLoads::point_B, "m",
                     "(3,) point of application of the forces in B, from the centre of mass [m]"));
  }

  // The times at which a run splits its steps: every load's t_start and t_end.
  const std::vector<AppliedLoad>& switches() const { return loads; }
};

// The compiled term: the schedule and the loads of the current piece.
class ScheduledLoadsTerm {
 public:
  // Throws std::invalid_argument naming "<name>.body", "<name>.point_B", "<name>.loads[i]..." for a body
  // index out of range, a non-finite point or load (check_loads), and for loads the body's kind cannot
  // take: a torque or a point off the centre of mass on a particle; an out-of-plane force, a torque
  // about x or y or a point off the plane on a planar body (the messages of the one-body simulate).
  ScheduledLoadsTerm(const ScheduledLoads& spec, const std::vector<Body>& bodies, const std::string& name)
      : body_(spec.body), schedule_(spec.loads), point_B_(spec.point_B) {
    check_body_index(spec.body, static_cast<int>(bodies.size()), name + ".body");
    require_finite(spec.point_B, name + ".point_B");
    check_loads_named(spec.loads, name);
    check_kind(bodies[spec.body], name);
    in_plane_ = has_attitude(bodies[spec.body]) && is_planar(bodies[spec.body]);
    set_time(0.0);
  }

  ElementTraits traits() const {
    bool turning = !point_B_.isZero(0.0), torque = !point_B_.isZero(0.0), force = false;
    for (const AppliedLoad& load : schedule_) {
      force = force || !load.force.isZero(0.0);
      const bool body_force = load.frame == Frame::body && !load.force.isZero(0.0);
      const bool world_torque = load.frame == Frame::world && !load.torque.isZero(0.0);
      turning = turning || body_force || world_torque;
      torque = torque || !load.torque.isZero(0.0);
    }
    ElementTraits t{};
    t.reads_attitude = turning, t.velocity_dependent = false, t.time_dependent = has_time_window(schedule_);
    t.has_potential = false, t.has_torque = torque, t.has_force = force;
    return t;
  }

  // Sets the loads of the piece that contains t [s] (between switch times the loads are constant).
  void set_time(double t) { set_piece(loads_at(schedule_, t)); }

  // A controller's command (scene/controller.hpp): the force f_B [N] in B at point_B alone, until the next one
  // (a thruster; the schedule's loads are replaced).
  void command(const Eigen::Vector3d& f_B) {
    ComLoads loads;
    loads.f_B = f_B;
    set_piece(loads);
  }

  // Whether the current piece needs the body's R_WB: to turn its loads (a force in B, a torque in W, a force off
  // the centre of mass) or for the moment R_WB τ_B of its torque about W's origin (the impulses)
  bool piece_turns_vectors() const { return turns_ || torque_; }

  // f_W = f_W + R f_B, τ_B = τ_B + Rᵀ τ_W + r_B × Rᵀ f_W on the body (R = R_WB of its unit attitude, read only where
  // the current piece turns a load); returns f_W·v_W + τ_B·ω_B [W] (zero in a piece without a load).
  double add_wrenches(double /*t*/, const std::vector<BodyKinematics>& kinematics, std::vector<BodyWrench>& wrenches) const {
    return add_wrench(kinematics[body_], wrenches[body_]);
  }
  // The same on its body of kinematics k (the one-body layout, scene/one_body_scene_model.hpp)
  RIGIDDYN_ALWAYS_INLINE double add_wrench(const BodyKinematics& k, BodyWrench& wrench) const {
    if (!acts_) return 0.0;
    Eigen::Vector3d f_W = loads_.f_W, tau_B = loads_.tau_B;
    if (turns_) {  // written out: Eigen's products were calls out of the layouts' inlined steps
      if (body_force_) f_W += in_plane_ ? turned_about_z(k.R_WB, loads_.f_B) : times_3x3(k.R_WB, loads_.f_B);
      if (world_torque_) tau_B += transpose_times_3x3(k.R_WB, loads_.tau_W);
      if (off_centre_) tau_B += cross_3(point_B_, transpose_times_3x3(k.R_WB, f_W));
    }
    wrench.f_W += f_W;
    wrench.tau_B += tau_B;
    return f_W.dot(k.v_W) + tau_B.dot(k.w_B);
  }

  double potential(const std::vector<BodyKinematics>& /*kinematics*/) const { return 0.0; }

  // The loads a body of this kind can take, each named list_name[i]: no torque on a particle; in the plane (a force
  // with z = 0, a torque about z) on a planar body. std::invalid_argument naming the first that is not.
  static void check_loads_for_kind(const Body& body, const std::vector<AppliedLoad>& loads, const std::string& list_name) {
    for (std::size_t i = 0; i < loads.size(); ++i) {
      const std::string load = list_name + "[" + std::to_string(i) + "]";
      if (!has_attitude(body) && !loads[i].torque.isZero(0.0)) {
        throw_invalid(load + ".torque", "zero (a particle takes no torque)", loads[i].torque);
      }
      if (has_attitude(body) && is_planar(body)) {
        if (loads[i].force.z() != 0.0) throw_invalid(load + ".force", "a force in the xy plane (z = 0)", loads[i].force);
        if (!loads[i].torque.head<2>().isZero(0.0)) {
          throw_invalid(load + ".torque", "a torque about z only (x = y = 0)", loads[i].torque);
        }
      }
    }
  }

  int body() const { return body_; }
  const std::vector<AppliedLoad>& loads() const { return schedule_; }
  const Eigen::Vector3d& point_B() const { return point_B_; }

 private:
  // check_loads with the element's name in front of "loads[i]..."
  static void check_loads_named(const std::vector<AppliedLoad>& loads, const std::string& name) {
    try {
      check_loads(loads);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + "." + e.what());
    }
  }

  // R f for R = Rz(θ) (a planar body's): R's zeros left out of the products (the same sums but for zeros' signs)
  RIGIDDYN_ALWAYS_INLINE static Eigen::Vector3d turned_about_z(const Eigen::Matrix3d& R, const Eigen::Vector3d& f) {
    return Eigen::Vector3d(R(0, 0) * f(0) + R(0, 1) * f(1), R(1, 0) * f(0) + R(1, 1) * f(1), f(2));
  }

  void check_kind(const Body& body, const std::string& name) const {
    check_loads_for_kind(body, schedule_, name + ".loads");
    if (!has_attitude(body) && !point_B_.isZero(0.0)) throw_invalid(name + ".point_B", "zero (a particle is a point)", point_B_);
    if (has_attitude(body) && is_planar(body) && point_B_.z() != 0.0) {
      throw_invalid(name + ".point_B", "a point in the body's xy plane (z = 0)", point_B_);
    }
  }

  // loads_ ← `loads`, with what the piece needs (the parts that are zero cost nothing in an evaluation)
  void set_piece(const ComLoads& loads) {
    loads_ = loads;
    const bool force = !(loads.f_W.isZero(0.0) && loads.f_B.isZero(0.0));
    body_force_ = !loads.f_B.isZero(0.0);
    world_torque_ = !loads.tau_W.isZero(0.0);
    off_centre_ = force && !point_B_.isZero(0.0);
    turns_ = body_force_ || world_torque_ || off_centre_;
    torque_ = !(loads.tau_B.isZero(0.0) && loads.tau_W.isZero(0.0));
    acts_ = force || torque_;
  }

  int body_;
  std::vector<AppliedLoad> schedule_;
  Eigen::Vector3d point_B_;
  ComLoads loads_;      // the sum of the loads active in the current piece
  bool acts_ = false;   // the piece has a load
  bool turns_ = false;  // it has a force in B, a torque in W or a force off the centre of mass: it reads R_WB
  bool torque_ = false; // it has a torque (in B or W)
  // which of R f_B, Rᵀ τ_W and r_B × Rᵀ f_W the piece needs: a part that is zero is not evaluated (adding
  // it would leave the sums as they are)
  bool body_force_ = false, world_torque_ = false, off_centre_ = false;
  bool in_plane_ = false;  // the body turns about z alone (a planar body): R_WB = Rz(θ)
};

}  // namespace rigiddyn
