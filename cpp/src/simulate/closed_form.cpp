// The closed form of method 'exact' on one rigid body: no time stepping; the torque-free motion (exact/free_body.hpp)
// evaluated at each record time, so that the error stays at round-off (~eps × the angle turned) however large dt and
// the run. The centre of mass moves ballistically under the constant force f_W of the loads and gravity g_W:
// p = p0 + v0 s + ½ a s², v = v0 + a s, a = f_W/m + g_W, s = t − t0 (Newton's second law; Craig, "Rigid Body
// Dynamics" slides). The records are those of a run: T = ½ m v·v + ½ ω·I ω, V = −m g_W·p of gravity, the loads' work
// f_W·(p − p0), gravity's V0 − V (the work of a constant force); without loads the impulses of gravity,
// J = m g s and K = m (p0 s + v0 s²/2 + g s³/6) × g about W's origin (H' = p × m g).
#include "closed_form.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"
#include "rigiddyn/simulate/monitor_pace.hpp"

#include <chrono>
#include <string>

namespace rigiddyn::detail {

namespace {

void check_closed_form_loads(const std::vector<AppliedLoad>& loads, double t0) {
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const std::string name = "loads[" + std::to_string(i) + "]";
    if (!loads[i].torque.isZero(0.0)) {
      throw_invalid(name + ".torque", "zero for method 'exact' (torque-free body; use 'exact_flow_kick')", loads[i].torque);
    }
    if (loads[i].frame == Frame::body && !loads[i].force.isZero(0.0)) {
      throw_invalid(name + ".force", "a world-frame force for method 'exact' (use 'exact_flow_kick')", loads[i].force);
    }
  }
  if (!is_constant_from(loads, t0)) {
    throw_invalid("loads", "loads active for all t >= t0 for method 'exact'", "a time-varying schedule");
  }
}

// v's few coefficients at the end of out, one push_back each: the records are reserved
// (reserved_scene_simulation), and a range insert of three or four doubles would call memmove per record
template <class V>
void append(std::vector<double>& out, const V& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v[i]);
}

// The body's record at s = t − t0 of the closed form, with each element's work and power (gravity's and the
// loads'), into out
struct ClosedFormRecorder {
  double m;
  Eigen::Matrix3d I;
  Eigen::Vector3d p0, v0, g_W, f_W;  // f_W: the loads' constant force [N]
  int gravity_element, loads_element;
  std::size_t element_count;

  void record(double t, double s, const TorqueFreeState& rotation, SceneSimulation& out) const {
    const Eigen::Vector3d a_W = f_W / m + g_W;
    const Eigen::Vector3d p_W = p0 + s * v0 + (0.5 * s * s) * a_W, v_W = v0 + s * a_W;
    const Eigen::Vector3d w_B = rotation.w_B, h_B = I * w_B;
    out.t.push_back(t);
    append(out.p_W, p_W);
    append(out.q_WB, rotation.q_WB.coeffs());
    append(out.v_W, v_W);
    append(out.w_B, w_B);
    const double T = 0.5 * m * v_W.squaredNorm() + 0.5 * w_B.dot(h_B);
    const double V = gravity_element >= 0 ? -(m * g_W.dot(p_W)) : 0.0, V0 = gravity_element >= 0 ? -(m * g_W.dot(p0)) : 0.0;
    out.kinetic_energy.push_back(T);
    out.potential_energy.push_back(V);
    out.total_energy.push_back(T + V);
    const Eigen::Vector3d L = m * v_W, H_C = rotation.q_WB * h_B, H = p_W.cross(L) + H_C;
    append(out.linear_momentum_W, L);
    append(out.angular_momentum_W, H);
    append(out.pivot_reaction_W, Eigen::Vector3d::Zero());  // no pivot
    append(out.angular_momentum_O_W, H_C);
    out.mass.push_back(m);
    if (loads_element < 0) {
      const Eigen::Vector3d J = m * s * g_W, K = m * (p0 * s + v0 * (s * s / 2.0) + g_W * (s * s * s / 6.0)).cross(g_W);
      append(out.impulse_W, J);
      append(out.angular_impulse_W, K);
    }
    for (std::size_t e = 0; e < element_count; ++e) {
      const bool gravity = static_cast<int>(e) == gravity_element;
      out.work.push_back(gravity ? V0 - V : f_W.dot(p_W - p0));
      out.power.push_back(gravity ? m * g_W.dot(v_W) : f_W.dot(v_W));
    }
  }
};

}  // namespace

SceneSimulation closed_form_simulation(const CompiledScene& compiled, const std::vector<BodyState>& initial,
                                       const SimulationOptions& o) {
  const RigidBody& body = std::get<RigidBody>(compiled.scene().bodies[0]);
  const OneBodyPlan& plan = compiled.one_body_plan();
  check_closed_form_loads(plan.loads, o.t0);
  const RigidBodyState& s0 = std::get<RigidBodyState>(initial[0]);
  // the body's inertia was checked with the body; a state of any magnitude is accepted (free_body.hpp)
  const TorqueFreeSolution solution(body.inertia_com(), s0.q_WB, s0.w_B, InertiaCheck::allow_unrealizable);
  const std::size_t element_count = compiled.scene().elements.size();
  const ClosedFormRecorder recorder{body.mass(), body.inertia_com(), s0.p_W, s0.v_W, plan.gravity_W,
                                    loads_at(plan.loads, o.t0).f_W, plan.gravity_element, plan.loads_element,
                                    element_count};
  SceneSimulation out = reserved_scene_simulation(o.steps, o.record_every, 1, element_count);
  const auto start = std::chrono::steady_clock::now();
  // only the recorded steps are evaluated: 0, k, 2k, ... and the last (k = record_every); the monitor is paced in
  // evaluations (each one the cost of a step)
  MonitorPace pace;
  std::int64_t until_monitor = pace.interval();
  for (std::int64_t i = 0;; i = o.steps - i <= o.record_every ? o.steps : i + o.record_every) {
    const double s = static_cast<double>(i) * o.dt;
    recorder.record(o.t0 + s, s, solution.state_at(s), out);
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
}

}  // namespace rigiddyn::detail
