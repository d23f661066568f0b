// Golden states: the refactoring of the models and integrators into the scene
// pipeline must not move a single bit of any trajectory. Every method of method_table() runs, through
// the PUBLIC simulate and step, on every one-body model (particle, planar body, rigid body with a
// spherical, a principal and a full inertia) under every load kind (none; fixed: world force, body
// torque, gravity; turning: body force, world torque; forces: world force and gravity only) and under a schedule that switches inside a
// step; the recorded states are compared BITWISE with golden_states.txt, written as hex floats (%a)
// by this same program from the code before the refactoring:
//   test_golden_states --generate tests/cpp/integrators/golden_states.txt
// The tolerance is zero on purpose: the refactoring only moves code, so the compiled arithmetic, and
// hence every rounding, must be the same (no -ffp-contract/-march flag is set by the project; a build
// that adds one may contract differently and must regenerate the file from its own HEAD build).
// Regenerated only for a deliberate change of arithmetic, named here: RK4's final update as one sum
// times h/6 (only the rk4 lines changed); the splittings' principal axes of a full inertia from the
// iterative eigensolver, computed once per inertia (only the splitting_dlm and splitting_dlm_yoshida4
// lines of the full-inertia body changed); a step's closing kick merged with the next step's opening kick between
// records (first same as last, simulate/run_loop.hpp: only the simulate lines of splitting_dlm,
// splitting_dlm_yoshida4 and exact_flow_kick under loads changed, by at most 6.4e-14 of their largest value); step of a
// body on its one-body scene's layout, the model simulate runs (scene/one_body_scene.hpp: only the step lines of
// implicit_midpoint on the rigid bodies changed, by at most 8.7e-17 of their largest value: the layout solves the
// midpoint as the scene model does); simulate of a body on its one-body scene's layout, as step (the one-body models
// deleted: 187 of the 250 simulate lines changed, no step line; the states by at most 1.0e-14 of their largest value,
// the energies 9.4e-14, |H_G| 2.9e-15, |q| − 1 by 3.3e-16, the work 4.0e-15, but for a planar body under body-frame
// loads in the kick–drift–kick methods, whose work moved by up to 3.3e-2 of its largest value: the layout counts
// a kick's work as the kinetic energy it gives, T − T0 = work exactly, where the planar model integrated the power
// along the drift, the two equal to the method's order); the torque-free closed form's Jacobi functions and
// third-kind integral from theta series, and its precession angle's half-angle rotor without an atan2
// (exact/elliptic_theta.hpp, for a solution evaluated at many times: only the simulate lines of the 'exact' method
// on the principal- and full-inertia bodies changed, by at most 3.9e-16 of their largest value); the exact free
// flow's short steps by the addition theorems of the Jacobi functions and of Π (exact/free_body.hpp,
// FreeRotationFlow: only the lines of exact_flow_kick and the step lines of 'exact' on the principal- and
// full-inertia bodies changed, by at most 6.1e-14 of their largest value over a run); the implicit midpoint's fixed
// point stopped by the change of the motion's coordinates alone, t and the works left out (integrators/
// implicit_midpoint.hpp, midpoint_converged: only four simulate lines of implicit_midpoint on the principal- and
// full-inertia bodies under loads changed, by at most 6.6e-17 of their largest value).
// A case that throws (the 'exact' method refuses a torque) stores its message; the test checks it
// still throws the same.
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace rigiddyn;

std::string hex_line(const std::vector<double>& values) {
  std::string out;
  char buffer[64];
  for (const double x : values) {
    std::snprintf(buffer, sizeof buffer, " %a", x);
    out += buffer;
  }
  return out;
}

void append(std::vector<double>& out, const std::vector<double>& values) { out.insert(out.end(), values.begin(), values.end()); }

// every recorded row of every field simulate returns, then the counters
std::vector<double> flatten(const Trajectory& r) {
  std::vector<double> out;
  for (const auto* field : {&r.t, &r.p_W, &r.q_WB, &r.v_W, &r.w_B, &r.kinetic_energy, &r.total_energy,
                            &r.angular_momentum_norm, &r.quaternion_norm_error, &r.work}) {
    append(out, *field);
  }
  out.push_back(r.diverged);
  out.push_back(r.interrupted);
  out.push_back(static_cast<double>(r.unconverged_steps));
  return out;
}

std::vector<double> flatten(const RigidBodyState& s) {
  return {s.p_W.x(), s.p_W.y(), s.p_W.z(), s.q_WB.x(), s.q_WB.y(), s.q_WB.z(), s.q_WB.w(),
          s.v_W.x(), s.v_W.y(), s.v_W.z(), s.w_B.x(), s.w_B.y(), s.w_B.z()};
}
std::vector<double> flatten(const ParticleState& s) {
  return {s.p_W.x(), s.p_W.y(), s.p_W.z(), s.v_W.x(), s.v_W.y(), s.v_W.z()};
}
std::vector<double> flatten(const PlanarBodyState& s) {
  return {s.p_W.x(), s.p_W.y(), s.theta, s.v_W.x(), s.v_W.y(), s.omega};
}

// the result of one case: " <hex> <hex> ..." or " error: <message>"
std::string outcome(const std::function<std::vector<double>()>& run) {
  try {
    return hex_line(run());
  } catch (const std::invalid_argument& e) {
    return std::string(" error: ") + e.what();
  }
}

AppliedLoad load(const Eigen::Vector3d& force, const Eigen::Vector3d& torque, Frame frame, double t_start = -INFINITY,
                 double t_end = INFINITY) {
  AppliedLoad l;
  l.force = force, l.torque = torque, l.frame = frame, l.t_start = t_start, l.t_end = t_end;
  return l;
}

// The load cases of one body kind: name → (loads, gravity). `spatial` false restricts them to what the
// particle (no torque) or the planar body (in-plane forces, torques about z, no gravity along z) take.
enum class Kind { particle, planar, rigid };

struct LoadCase {
  std::string name;
  std::vector<AppliedLoad> loads;
  Eigen::Vector3d gravity_W;
};

std::vector<LoadCase> load_cases(Kind kind) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const bool torques = kind != Kind::particle, planar = kind == Kind::planar;
  const Eigen::Vector3d f_W = planar ? Eigen::Vector3d(0.7, -1.3, 0.0) : Eigen::Vector3d(0.7, -1.3, 2.1);
  const Eigen::Vector3d f_B = planar ? Eigen::Vector3d(-0.4, 0.9, 0.0) : Eigen::Vector3d(-0.4, 0.9, 0.5);
  const Eigen::Vector3d tau_B = !torques ? zero : planar ? Eigen::Vector3d(0.0, 0.0, 0.35) : Eigen::Vector3d(0.3, -0.2, 0.35);
  const Eigen::Vector3d tau_W = !torques ? zero : planar ? Eigen::Vector3d(0.0, 0.0, -0.25) : Eigen::Vector3d(-0.1, 0.45, -0.25);
  const Eigen::Vector3d g_W = planar ? Eigen::Vector3d(0.0, -9.81, 0.0) : standard_gravity();
  return {
      {"none", {}, zero},
      {"forces", {load(f_W, zero, Frame::world)}, g_W},  // no torque: the 'exact' method takes it
      {"fixed", {load(f_W, zero, Frame::world), load(zero, tau_B, Frame::body)}, g_W},
      {"turning", {load(f_B, zero, Frame::body), load(zero, tau_W, Frame::world)}, zero},
      // switches at 0.0123 s and 0.5017 s, inside steps of 0.01 s (a split step), and a body torque from 0.3 s on
      {"switching",
       {load(f_W, tau_W, Frame::world, 0.0123, 0.5017), load(f_B, zero, Frame::body, 0.0123, 0.5017),
        load(zero, tau_B, Frame::body, 0.3)},
       g_W},
  };
}

constexpr double dt = 0.01;

SimulationOptions options(Method method, const LoadCase& c) {
  SimulationOptions o;
  o.method = method;
  o.dt = dt;
  o.steps = 200;
  o.record_every = 50;
  o.t0 = 0.0;
  o.loads = c.loads;
  o.gravity_W = c.gravity_W;
  return o;
}

// step() from t0 = 0.005: the switch at 0.0123 falls inside the step to 0.015 for the switching case
SimulationOptions step_options(Method method, const LoadCase& c) {
  SimulationOptions o = options(method, c);
  o.t0 = 0.005;
  o.dt = 0.01;
  return o;
}

RigidBodyState rigid_initial() {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.q_WB = Eigen::Quaterniond(0.9, 0.1, 0.2, 0.3).normalized();
  s.v_W = Eigen::Vector3d(1.0, -0.5, 2.0);
  s.w_B = Eigen::Vector3d(0.3, 2.0, -0.7);  // near the intermediate axis of the principal body: a tumble
  return s;
}
ParticleState particle_initial() {
  ParticleState s;
  s.p_W = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.v_W = Eigen::Vector3d(1.0, -0.5, 2.0);
  return s;
}
PlanarBodyState planar_initial() {
  PlanarBodyState s;
  s.p_W = Eigen::Vector2d(0.1, -0.2);
  s.theta = 0.4;
  s.v_W = Eigen::Vector2d(1.0, -0.5);
  s.omega = 1.7;
  return s;
}

// Every case of the net, name → outcome, in a fixed order.
std::vector<std::pair<std::string, std::string>> all_cases() {
  std::vector<std::pair<std::string, std::string>> out;
  Eigen::Matrix3d full;
  full << 1.1, 0.12, -0.05, 0.12, 2.3, 0.08, -0.05, 0.08, 2.9;
  const std::vector<std::pair<std::string, RigidBody>> rigid_bodies = {
      {"rigid_spherical", RigidBody(1.5, Eigen::Vector3d(0.8, 0.8, 0.8))},
      {"rigid_principal", RigidBody(1.5, Eigen::Vector3d(1.1, 2.3, 2.9))},
      {"rigid_full", RigidBody(1.5, full)},
  };
  const Particle particle(2.0);
  const PlanarBody planar(2.0, 0.6);
  for (const MethodInfo& info : method_table()) {
    const Method m = info.method;
    for (const LoadCase& c : load_cases(Kind::particle)) {
      const std::string name = info.name + " particle " + c.name;
      out.push_back({name + " simulate", outcome([&] { return flatten(simulate(particle, particle_initial(), options(m, c))); })});
      out.push_back({name + " step", outcome([&] { return flatten(step(particle, particle_initial(), step_options(m, c))); })});
    }
    for (const LoadCase& c : load_cases(Kind::planar)) {
      const std::string name = info.name + " planar " + c.name;
      out.push_back({name + " simulate", outcome([&] { return flatten(simulate(planar, planar_initial(), options(m, c))); })});
      out.push_back({name + " step", outcome([&] { return flatten(step(planar, planar_initial(), step_options(m, c))); })});
    }
    for (const auto& [body_name, body] : rigid_bodies) {
      for (const LoadCase& c : load_cases(Kind::rigid)) {
        const std::string name = info.name + " " + body_name + " " + c.name;
        out.push_back({name + " simulate", outcome([&] { return flatten(simulate(body, rigid_initial(), options(m, c))); })});
        out.push_back({name + " step", outcome([&] { return flatten(step(body, rigid_initial(), step_options(m, c))); })});
      }
    }
  }
  return out;
}

std::string golden_path() {
  const char* path = std::getenv("RIGIDDYN_GOLDEN_STATES");
  return path ? path : "";
}

std::map<std::string, std::string> read_golden(const std::string& path) {
  std::ifstream in(path);
  std::map<std::string, std::string> golden;
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');  // "<case>:<outcome>"
    if (line.empty() || line[0] == '#' || colon == std::string::npos) continue;
    golden[line.substr(0, colon)] = line.substr(colon + 1);
  }
  return golden;
}

TEST(GoldenStates, EveryMethodModelAndLoadKindIsBitwiseUnchanged) {
  const std::string path = golden_path();
  ASSERT_FALSE(path.empty()) << "RIGIDDYN_GOLDEN_STATES: expected the path of golden_states.txt, got nothing";
  const auto golden = read_golden(path);
  const auto cases = all_cases();
  // 10 methods × (5 particle + 5 planar + 15 rigid) load cases × (simulate, step)
  ASSERT_EQ(golden.size(), cases.size()) << path;
  int mismatches = 0;
  for (const auto& [name, result] : cases) {
    const auto it = golden.find(name);
    ASSERT_NE(it, golden.end()) << name << " is not in " << path;
    // zero tolerance: a pure refactoring keeps every rounding (see the top of this file)
    EXPECT_EQ(result, it->second) << name;
    mismatches += result != it->second;
  }
  EXPECT_EQ(mismatches, 0);
}

// The net must be able to fail: a change of one ulp in one input changes the outcome of a case.
TEST(GoldenStates, OneUlpInTheInitialStateIsSeen) {
  const RigidBody body(1.5, Eigen::Vector3d(1.1, 2.3, 2.9));
  const LoadCase c = load_cases(Kind::rigid)[2];  // fixed
  RigidBodyState nudged = rigid_initial();
  nudged.w_B.x() = std::nextafter(nudged.w_B.x(), 1.0);
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) continue;  // refuses the torque of this case
    EXPECT_NE(outcome([&] { return flatten(simulate(body, rigid_initial(), options(info.method, c))); }),
              outcome([&] { return flatten(simulate(body, nudged, options(info.method, c))); }))
        << info.name;
  }
}

}  // namespace

// `--generate <path>` writes the golden file from this build instead of running the tests.
int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--generate") == 0) {
    std::ofstream out(argv[2]);
    out << "# test_golden_states.cpp: <method> <body> <loads> <simulate|step>:<outcome> (hex floats, %a)\n";
    for (const auto& [name, result] : all_cases()) out << name << ':' << result << '\n';
    return out ? 0 : 1;
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
