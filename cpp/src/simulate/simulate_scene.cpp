// simulate for scenes (scene/simulate_scene.hpp): the generic model's runs (one per method), the one-body layouts'
// (one_body_runs_*.cpp) and the closed form of 'exact' on one rigid body (closed_form.cpp). step is in step_scene.cpp (its own
// instantiations, built in parallel).
#include "rigiddyn/scene/simulate_scene.hpp"

#include "check_options.hpp"
#include "closed_form.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace rigiddyn {

namespace detail {

std::vector<BodyState> checked_scene_input(const Scene& scene, Method compiled_method, const std::vector<BodyState>& initial,
                                           const SimulationOptions& o, bool stepping, const char* states_name) {
  check_options(o, stepping);
  if (!o.loads.empty()) {
    throw std::invalid_argument("loads: expected none in the options of a scene (declare a ScheduledLoads element), got " +
                                std::to_string(o.loads.size()) + " loads");
  }
  if (!o.gravity_W.isZero(0.0)) {
    throw_invalid("gravity", "zero in the options of a scene (declare a UniformGravity element)", o.gravity_W);
  }
  if (o.method != compiled_method) {
    throw std::invalid_argument("method: expected the method the scene was compiled for ('" +
                                method_info(compiled_method).name + "'), got '" + method_info(o.method).name + "'");
  }
  const std::string name = states_name;
  if (initial.size() != scene.bodies.size()) {
    throw std::invalid_argument(name + ": expected " + std::to_string(scene.bodies.size()) +
                                " body states (one per body), got " + std::to_string(initial.size()));
  }
  std::vector<BodyState> out;
  out.reserve(initial.size());
  for (std::size_t i = 0; i < initial.size(); ++i) {
    const std::string item = name + "[" + std::to_string(i) + "]";
    if (initial[i].index() != scene.bodies[i].index()) {
      throw std::invalid_argument(item + ": expected a " + state_type_name(scene.bodies[i].index()) + " (body " +
                                  std::to_string(i) + " '" + body_name(scene, i) + "' is a " + kind_name(scene.bodies[i]) +
                                  "), got a " + state_type_name(initial[i].index()));
    }
    if (const auto* link = std::get_if<TreeLink>(&scene.bodies[i])) {
      out.push_back(checked_state(*link, std::get<JointState>(initial[i]), item));  // its joint's sizes
      continue;
    }
    out.push_back(std::visit([&](const auto& s) -> BodyState { return checked_state(s, item); }, initial[i]));
    if (const auto* gyrostat = std::get_if<Gyrostat>(&scene.bodies[i])) {
      out.back() = checked_state(*gyrostat, std::get<GyrostatState>(out.back()), item);  // a speed per wheel
    }
  }
  return out;
}

void check_masses_over_run(const Scene& scene, const SimulationOptions& o, std::int64_t steps) {
  for (std::size_t i = 0; i < scene.mass_flows.size(); ++i) {
    if (!scene.mass_flows[i]) continue;
    check_mass_over_run(*scene.mass_flows[i], mass_of(scene.bodies[i]), o.t0, o.dt, steps,
                        "mass_flows[" + std::to_string(i) + "]", body_name(scene, i));
  }
}

SceneSimulation reserved_scene_simulation(std::int64_t steps, std::int64_t record_every, std::size_t bodies,
                                          std::size_t elements, std::size_t wheels) {
  const double records = std::floor(static_cast<double>(steps) / static_cast<double>(record_every)) + 2.0;
  // per record: t, 20 per body (state 13, pivot reaction 3, H_O 3, mass 1), 3 energies, 6 momenta,
  // 2 per element, 1 per gyrostat wheel, 6 impulses
  const double per_record = 16.0 + 20.0 * static_cast<double>(bodies) + 2.0 * static_cast<double>(elements) +
                            static_cast<double>(wheels);
  check_recording_fits(records * per_record * sizeof(double), steps, record_every);
  SceneSimulation out;
  out.body_count = static_cast<std::int64_t>(bodies);
  out.element_count = static_cast<std::int64_t>(elements);
  const auto n = static_cast<std::size_t>(records);
  for (auto* v : {&out.t, &out.kinetic_energy, &out.potential_energy, &out.total_energy}) v->reserve(n);
  for (auto* v : {&out.linear_momentum_W, &out.angular_momentum_W, &out.impulse_W, &out.angular_impulse_W}) v->reserve(3 * n);
  for (auto* v : {&out.p_W, &out.v_W, &out.w_B, &out.pivot_reaction_W, &out.angular_momentum_O_W}) {
    v->reserve(3 * bodies * n);
  }
  out.q_WB.reserve(4 * bodies * n);
  out.mass.reserve(bodies * n);
  for (auto* v : {&out.work, &out.power}) v->reserve(elements * n);
  for (auto* v : {&out.wheel_speed, &out.motor_work}) v->reserve(wheels * n);
  return out;
}

}  // namespace detail

namespace {

// The run of a one-body scene's fixed-size model: a layout (its loops compiled in one_body_runs_*.cpp) or one of the
// fast models (detail::FastOneBodyModels, run here)
SceneSimulation run_one_body_model(const OneBodyModel& one_body, const std::vector<BodyState>& initial,
                                   const SimulationOptions& o, const std::vector<AppliedLoad>& switch_schedule) {
  const auto run_layout = [&](const auto& layout) { return detail::run_one_body(layout, initial, o, switch_schedule); };
  const auto run_fast = [&](const auto& fast) {
    return detail::run_scene(fast, fast.coordinates(initial, o.t0), o, switch_schedule);
  };
  return visit_one_body(one_body, run_layout, run_fast);
}

}  // namespace

SceneSimulation detail::run_generic_scene(const SceneModel& model, const Eigen::VectorXd& y, const SimulationOptions& o,
                                          const std::vector<AppliedLoad>& switch_schedule, RunHooks* hooks) {
  return run_scene(model, y, o, switch_schedule, hooks);
}

SceneSimulation simulate(const CompiledScene& compiled, const std::vector<BodyState>& initial, const SimulationOptions& o) {
  const std::vector<BodyState> states =
      detail::checked_scene_input(compiled.scene(), compiled.method(), initial, o, true, "initial");
  detail::check_masses_over_run(compiled.scene(), o, o.steps);
  if (compiled.one_body_path()) {
    if (compiled.closed_form()) return detail::closed_form_simulation(compiled, states, o);
    return run_one_body_model(compiled.one_body_model(), states, o, compiled.switch_schedule());
  }
  const SceneModel& model = compiled.model();
  return detail::run_generic_scene(model, model.coordinates(states, o.t0), o, compiled.switch_schedule(), nullptr);
}

SceneSimulation simulate(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& options) {
  return simulate(compile_scene(scene, options.method), initial, options);
}

}  // namespace rigiddyn
