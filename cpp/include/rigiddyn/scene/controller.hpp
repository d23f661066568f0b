// A digital controller of a scene run (docs/guide/spacecraft.md): a law sampled every `period` seconds of
// the run, at t_k = t0 + k period, with the state of every body at t_k, whose actuator commands are held
// constant until the next sample (a zero-order hold):
//   gyrostat wheels    the motor torques u_k [N m] (scene/kinds/gyrostat_slot.hpp);
//   MagneticDipole     the dipole m_B [A m²] in B (a magnetorquer, scene/elements/magnetic_dipole.hpp);
//   ScheduledLoads     the force f_B [N] in B at its point_B (a thruster, scene/elements/scheduled_loads.hpp);
//   ReactionWheel      the speed Ω_c [rad/s] relative to the body (scene/elements/reaction_wheel.hpp): a
//                      rate-limited speed loop, the wheel ramping at a constant rate from its speed at t_k to Ω_c
//                      at t_k + period (ḣ = J (Ω_c − Ω(t_k))/period over the period), then holding Ω_c;
//   RevoluteMotor,     the joint torque τ [N m] or force [N] in a tree's joint (scene/elements/joint_motor.hpp),
//   PrismaticMotor     held until the next command.
// The sample times are switch times of the run loop (simulate/run_loop.hpp): a step that contains one is split
// there, so that no step straddles a sample and every method keeps its order (the inputs are constant over each
// sub-step, as between the switch times of a ScheduledLoads). A commanded actuator takes its command instead of
// its own schedule; the ones never commanded keep theirs.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/scene/compile.hpp"
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/run_loop.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rigiddyn {

// The state a law sees at a sample: t [s] and, for every body in the layout of SceneSimulation's records,
// row-major: p_W (nb, 3) [m], q_WB (nb, 4) (x, y, z, w), v_W (nb, 3) [m/s], w_B (nb, 3) [rad/s] in B, each
// gyrostat wheel's speed relative to its body (nw,) [rad/s], and the trees' joint coordinates (nq,) and
// velocities (nv,) (SceneSimulation::joint_q, joint_v).
struct SampledState {
  double t = 0.0;
  std::vector<double> p_W, q_WB, v_W, w_B, wheel_speed, joint_q, joint_v;
};

// A command to the element of index `element`: a MagneticDipole's m_B [A m²] in B, or a ScheduledLoads' force
// f_B [N] in B at its point_B.
struct ElementCommand {
  int element = 0;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

// A number commanded to the element of index `element`: a ReactionWheel's speed Ω_c [rad/s] relative to the body,
// reached at the next sample; a RevoluteMotor's torque [N m] or a PrismaticMotor's force [N], held.
struct ScalarCommand {
  int element = 0;
  double value = 0.0;
};

// What a law returns: the motor torques [N m] of every gyrostat wheel in the scene's order (the order of
// SceneSimulation::wheel_speed; empty: held), the commanded elements (the others hold their last command) and the
// commanded numbers (ReactionWheel speeds: the others keep their last ramp's end speed, or their own ramp; joint
// motors' forces: the others keep their last command, or their own window).
struct ActuatorCommands {
  std::vector<double> wheel_torque;
  std::vector<ElementCommand> elements;
  std::vector<ScalarCommand> scalars;
};

using ControlLaw = std::function<ActuatorCommands(const SampledState&)>;

// A law sampled every period [s] (> 0, finite) from the run's t0.
struct Controller {
  double period = 0.0;
  ControlLaw law;
};

// simulate (scene/simulate_scene.hpp) under `controller`, always on the scene's generic model (SceneModel).
// Throws std::invalid_argument naming "controller.period" (not positive and finite), "controller.law" (empty)
// and, at a sample, "controller.law(t=...)" for a command of the wrong size, a non-finite value, or an element
// that takes no such command (named with its type); an exception the law throws stops the run and propagates.
SceneSimulation simulate(const CompiledScene& compiled, const std::vector<BodyState>& initial,
                         const SimulationOptions& options, const Controller& controller);

namespace detail {

// Throws std::invalid_argument naming controller.period or controller.law.
void check_controller(const Controller& controller);

// `schedule` and a load starting at each sample time t0 + k period inside (t0, t_end) [s]: the run loop's
// switch times then include the samples (the loads are never applied, only their times read).
std::vector<AppliedLoad> with_sample_times(std::vector<AppliedLoad> schedule, double period, double t0, double t_end);

// The state of a controlled run (mutated between steps, never inside one): the next sample, the commands held; the
// hooks of the generic model's run (simulate_scene.hpp).
class ControlRun final : public RunHooks {
 public:
  // `element_types`: each element's type name (element_type_name), for the messages.
  ControlRun(const Controller& controller, const SimulationOptions& o, const Eigen::VectorXd& y0,
             std::vector<std::string> element_types, std::size_t wheels)
      : controller_(controller), t0_(o.t0), dt_(o.dt), y_(&y0), held_(element_types.size()),
        element_types_(std::move(element_types)), wheels_(wheels) {}

  // The run's coordinates after a (sub-)step: read at the next sample.
  void follow(const Eigen::VectorXd& y) override { y_ = &y; }

  // The piece that starts at t [s]: the model's own pieces (set_time), a sample when t is the next sample time
  // (a wheel's speed command starts its ramp there, a joint motor takes its force), then the commands held.
  void piece(SceneModel& model, double t) override {
    model.set_time(t);
    const double t_k = t0_ + static_cast<double>(k_) * controller_.period;
    if (t >= t_k - on_grid_tolerance(t_k, dt_)) {
      ++k_;
      scratch_ = SceneSimulation{};
      model.record(*y_, t_k, scratch_);
      SampledState s{t_k,
                     std::move(scratch_.p_W),
                     std::move(scratch_.q_WB),
                     std::move(scratch_.v_W),
                     std::move(scratch_.w_B),
                     std::move(scratch_.wheel_speed),
                     std::move(scratch_.joint_q),
                     std::move(scratch_.joint_v)};
      const ActuatorCommands c = controller_.law(s);
      hold(c, t_k, [&](std::size_t e) { return model.takes_command(e); });
      for (const ScalarCommand& command : checked_scalars(c, t_k, [&](std::size_t e) { return model.takes_scalar(e); })) {
        const double t_next = t0_ + static_cast<double>(k_) * controller_.period;  // the next sample's time
        model.command_scalar(static_cast<std::size_t>(command.element), command.value, t_k, t_next, t);
      }
    }
    if (!wheel_torque_.empty()) model.command_wheel_torques(wheel_torque_);
    for (std::size_t e = 0; e < held_.size(); ++e) {
      if (held_[e]) model.command_element(e, *held_[e]);
    }
  }

 private:
  // Checks the commands returned at t_k and holds them.
  template <class TakesCommand>
  void hold(const ActuatorCommands& c, double t_k, const TakesCommand& takes_command) {
    const std::string at = "controller.law(t=" + format_value(t_k) + ")";
    if (!c.wheel_torque.empty()) {
      if (c.wheel_torque.size() != wheels_) {
        throw std::invalid_argument(at + ": expected wheel_torque of " + std::to_string(wheels_) +
                                    " values (one per gyrostat wheel), got " + std::to_string(c.wheel_torque.size()));
      }
      for (const double u : c.wheel_torque) {
        if (!std::isfinite(u)) throw_invalid(at + ".wheel_torque", "finite motor torques [N m]", u);
      }
      wheel_torque_ = c.wheel_torque;
    }
    for (const ElementCommand& command : c.elements) {
      const std::string name = at + "[" + std::to_string(command.element) + "]";
      check_element_index(command.element, name);
      if (!takes_command(static_cast<std::size_t>(command.element))) {
        throw std::invalid_argument(name + ": expected a MagneticDipole or a ScheduledLoads (the elements that take "
                                           "a (3,) command), got element " + element_named(command.element));
      }
      require_finite(command.value, name);
      held_[command.element] = command.value;
    }
  }

  // Throws std::invalid_argument naming `name` unless `element` indexes an element of the scene.
  void check_element_index(int element, const std::string& name) const {
    if (element < 0 || static_cast<std::size_t>(element) >= held_.size()) {
      throw std::invalid_argument(name + ": expected the index of an element in [0, " + std::to_string(held_.size()) +
                                  "), got " + std::to_string(element));
    }
  }

  // The numbers commanded at t_k, checked: each to a ReactionWheel or a joint motor (takes_scalar), finite.
  template <class TakesScalar>
  const std::vector<ScalarCommand>& checked_scalars(const ActuatorCommands& c, double t_k, const TakesScalar& takes_scalar) {
    for (const ScalarCommand& command : c.scalars) {
      const std::string name = "controller.law(t=" + format_value(t_k) + ")[" + std::to_string(command.element) + "]";
      check_element_index(command.element, name);
      if (!takes_scalar(static_cast<std::size_t>(command.element))) {
        throw std::invalid_argument(name + ": expected a ReactionWheel (a speed [rad/s]), a RevoluteMotor (a torque "
                                           "[N m]) or a PrismaticMotor (a force [N]), the elements that take a number, "
                                           "got element " + element_named(command.element));
      }
      if (!std::isfinite(command.value)) throw_invalid(name, "a finite number", command.value);
    }
    return c.scalars;
  }

  // "3 (a MagneticDipole)"
  std::string element_named(int e) const { return std::to_string(e) + " (a " + element_types_[e] + ")"; }

  const Controller& controller_;
  double t0_, dt_;                                     // [s]
  std::int64_t k_ = 0;                                 // the next sample
  const Eigen::VectorXd* y_;                           // the run's coordinates
  std::vector<double> wheel_torque_;                   // held motor torques [N m] (empty: none commanded)
  std::vector<std::optional<Eigen::Vector3d>> held_;   // each element's held command (none: never commanded)
  std::vector<std::string> element_types_;             // each element's type name
  std::size_t wheels_;
  SceneSimulation scratch_;                            // the record a sample is read from
};

}  // namespace detail
}  // namespace rigiddyn
