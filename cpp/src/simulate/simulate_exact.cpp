#include "rigiddyn/simulate/simulate_exact.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "append_record.hpp"

#include <chrono>

namespace rigiddyn {

namespace {

void check_exact_loads(const SimulationOptions& o) {
  for (std::size_t i = 0; i < o.loads.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (!o.loads[i].torque.isZero(0.0)) {
      throw_invalid(name + ".torque", "zero for method 'exact' (torque-free body; use 'exact_flow_kick')",
                    o.loads[i].torque);
    }
    if (o.loads[i].frame == Frame::body && !o.loads[i].force.isZero(0.0)) {
      throw_invalid(name + ".force", "a world-frame force for method 'exact' (use 'exact_flow_kick')",
                    o.loads[i].force);
    }
  }
  if (!is_constant_from(o.loads, o.t0)) {
    throw_invalid("loads", "loads active for all t >= t0 for method 'exact'", "a time-varying schedule");
  }
}

}  // namespace

Trajectory simulate_exact(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& o) {
  check_exact_loads(o);
  const RigidBodyState s0 = checked_state(initial, "initial");
  const TorqueFreeSolution solution(body.inertia_com(), s0.q_WB, s0.w_B, InertiaCheck::allow_unrealizable);  // checked with the body
  const Eigen::Vector3d a_W = loads_at(o.loads, o.t0).f_W / body.mass() + o.gravity_W;
  return with_euler_form(body, [&](const auto& euler) {
    using Euler = std::decay_t<decltype(euler)>;
    const RigidBodyModel<Euler> model(body.mass(), euler, o.gravity_W);
    Trajectory out;
    reserve_records(out, o.steps, o.record_every);
    const auto start = std::chrono::steady_clock::now();
    // only the recorded steps are evaluated: 0, k, 2k, ... and the last (k = record_every); the monitor is
    // paced in evaluations (each one the cost of a step)
    MonitorPace pace;
    std::int64_t until_monitor = pace.interval();
    for (std::int64_t i = 0;; i = o.steps - i <= o.record_every ? o.steps : i + o.record_every) {
      const double t = static_cast<double>(i) * o.dt;
      const TorqueFreeState s = solution.state_at(t);
      RigidBodyState state;
      state.p_W = s0.p_W + t * s0.v_W + (0.5 * t * t) * a_W;
      state.q_WB = s.q_WB;
      state.v_W = s0.v_W + t * a_W;
      state.w_B = s.w_B;
      const double work = body.mass() * a_W.dot(state.p_W - s0.p_W);
      append_record(out, o.t0 + t, model.record(to_coordinates(state, work)));
      if (i == o.steps) break;
      if (o.monitor && i > 0 && --until_monitor == 0) {
        if (pace.check(o.monitor, i)) {
          out.interrupted = true;
          break;
        }
        until_monitor = pace.interval();
      }
    }
    out.elapsed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  });
}

}  // namespace rigiddyn
