// simulate for scenes (scene/simulate_scene.hpp): the generic model's runs (one per method), the one-body layouts'
// (one_body_runs_*.cpp) and the closed form of 'exact' on one body. step is in step_scene.cpp (its own
// instantiations, built in parallel).
#include "rigiddyn/scene/simulate_scene.hpp"

#include "append_record.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>
#include <optional>
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

// simulate(body, ...) of the one body with the plan's gravity and loads ('exact': the closed form)
Trajectory one_body_trajectory(const Body& body, const BodyState& initial, const OneBodyPlan& plan, const SimulationOptions& o) {
  SimulationOptions one = o;
  one.gravity_W = plan.gravity_W;
  one.loads = plan.loads;
  if (const auto* p = std::get_if<Particle>(&body)) return simulate(*p, std::get<ParticleState>(initial), one);
  if (const auto* s = std::get_if<PlanarBody>(&body)) return simulate(*s, std::get<PlanarBodyState>(initial), one);
  return simulate(std::get<RigidBody>(body), std::get<RigidBodyState>(initial), one);
}

// The closed form's records as a SceneSimulation: the states and energies as simulate(body, ...) recorded
// them; the potential, the momenta and each element's power from the scene's terms at each record; the work of
// gravity −ΔV (exact for a uniform field), the loads' the rest of the integrated work; without loads the impulses
// of gravity in closed form, J = m g s and K = m (p0 s + v0 s²/2 + g s³/6) × g with s = t − t0 (the centre of mass
// moves on p0 + v0 s + g s²/2; Newton's second law and its moment about W's origin, H' = p × m g).
SceneSimulation closed_form_simulation(const CompiledScene& compiled, const std::vector<BodyState>& initial,
                                    const SimulationOptions& o) {
  const Body& body = compiled.scene().bodies[0];
  const OneBodyPlan& plan = compiled.one_body_plan();
  const Trajectory tr = one_body_trajectory(body, initial[0], plan, o);
  const std::size_t n = tr.size(), ne = compiled.scene().elements.size();
  SceneSimulation out = detail::reserved_scene_simulation(o.steps, o.record_every, 1, ne);
  out.t = tr.t, out.p_W = tr.p_W, out.q_WB = tr.q_WB, out.v_W = tr.v_W, out.w_B = tr.w_B;
  out.kinetic_energy = tr.kinetic_energy, out.total_energy = tr.total_energy;
  out.diverged = tr.diverged, out.interrupted = tr.interrupted, out.unconverged_steps = tr.unconverged_steps;
  out.elapsed_seconds = tr.elapsed_seconds;
  const double m = mass_of(body);
  const Eigen::Matrix3d I = inertia_com_of(body);
  const auto& terms = compiled.model().terms();
  const UniformGravityTerm* gravity = plan.gravity_element >= 0 ? &std::get<UniformGravityTerm>(terms[plan.gravity_element]) : nullptr;
  std::optional<ScheduledLoadsTerm> loads;
  if (plan.loads_element >= 0) loads = std::get<ScheduledLoadsTerm>(terms[plan.loads_element]);
  std::vector<BodyKinematics> k(1);
  k[0].m = m;
  std::vector<BodyWrench> w(1);
  double V0 = 0.0;
  for (std::size_t r = 0; r < n; ++r) {
    k[0].p_W = Eigen::Vector3d(&tr.p_W[3 * r]);
    set_attitude(k[0], Eigen::Quaterniond(Eigen::Vector4d(&tr.q_WB[4 * r]).normalized()));
    k[0].v_W = Eigen::Vector3d(&tr.v_W[3 * r]);
    k[0].w_B = Eigen::Vector3d(&tr.w_B[3 * r]);
    const double V = gravity ? gravity->potential(k) : 0.0;
    if (r == 0) V0 = V;
    out.potential_energy.push_back(V);
    const Eigen::Vector3d L = m * k[0].v_W, H_C = k[0].q_WB * (I * k[0].w_B), H = k[0].p_W.cross(L) + H_C;
    out.linear_momentum_W.insert(out.linear_momentum_W.end(), L.data(), L.data() + 3);
    out.angular_momentum_W.insert(out.angular_momentum_W.end(), H.data(), H.data() + 3);
    out.pivot_reaction_W.insert(out.pivot_reaction_W.end(), 3, 0.0);  // no pivot
    out.angular_momentum_O_W.insert(out.angular_momentum_O_W.end(), H_C.data(), H_C.data() + 3);
    out.mass.push_back(m);
    if (!loads) {
      const double s = tr.t[r] - tr.t[0];
      const Eigen::Vector3d p0(&tr.p_W[0]), v0(&tr.v_W[0]), g = plan.gravity_W;
      const Eigen::Vector3d J = m * s * g, K = m * (p0 * s + v0 * (s * s / 2.0) + g * (s * s * s / 6.0)).cross(g);
      out.impulse_W.insert(out.impulse_W.end(), J.data(), J.data() + 3);
      out.angular_impulse_W.insert(out.angular_impulse_W.end(), K.data(), K.data() + 3);
    }
    double gravity_power = 0.0, loads_power = 0.0;
    if (gravity) gravity_power = gravity->add_wrenches(tr.t[r], k, w);
    if (loads) {
      loads->set_time(tr.t[r]);
      loads_power = loads->add_wrenches(tr.t[r], k, w);
    }
    const double gravity_work = V0 - V, loads_work = gravity ? tr.work[r] - gravity_work : tr.work[r];
    for (std::size_t e = 0; e < ne; ++e) {
      const bool is_gravity = static_cast<int>(e) == plan.gravity_element;
      out.work.push_back(is_gravity ? gravity_work : loads_work);
      out.power.push_back(is_gravity ? gravity_power : loads_power);
    }
  }
  return out;
}

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
    if (compiled.closed_form()) return closed_form_simulation(compiled, states, o);
    return run_one_body_model(compiled.one_body_model(), states, o, compiled.switch_schedule());
  }
  const SceneModel& model = compiled.model();
  return detail::run_generic_scene(model, model.coordinates(states, o.t0), o, compiled.switch_schedule(), nullptr);
}

SceneSimulation simulate(const Scene& scene, const std::vector<BodyState>& initial, const SimulationOptions& options) {
  return simulate(compile_scene(scene, options.method), initial, options);
}

}  // namespace rigiddyn
