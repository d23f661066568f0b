// Every method of the registry stepped on every model type (particle, planar body, rigid body with a
// spherical, a principal and a full inertia) under every load kind (none, fixed, turning), against
// the numpy reference (tests/reference/rigiddyn_ref): the states the reference reaches are written
// by reference_states.py, which ctest runs as this test's fixture (RIGIDDYN_REFERENCE_STATES names
// the file). Each case is stepped twice: by `steps` calls of step() (the state) and through simulate() (the
// state and the work), both on the layout of the body's one-body scene; the case names the Euler form the body's
// inertia needs, so that a method falling back to a form without the gyroscopic term is seen (velocity Verlet
// is O(h²|ω|²) ~ 4e-4 off per step here).
#include <gtest/gtest.h>

#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace rigiddyn {
namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// One block of the fixture's file (reference_states.py documents the format).
struct Case {
  std::string model, form, kind, method;  // model: particle, planar, rigid; form: -, spherical, principal, full
  double mass = 0.0;
  std::vector<double> inertia;  // planar: I_zz; rigid: 3×3 row-major [kg m²]
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<AppliedLoad> loads;
  double h = 0.0;
  int steps = 0;
  std::vector<double> y0, y1;  // the model's coordinates before and after `steps` steps (reference)
  double reference_bound = 0.0;

  std::string name() const { return model + " " + form + " " + kind + " " + method; }
};

std::vector<double> numbers(std::istringstream& in) {
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

std::vector<Case> read_cases() {
  const char* path = std::getenv("RIGIDDYN_REFERENCE_STATES");
  if (path == nullptr) throw std::runtime_error("RIGIDDYN_REFERENCE_STATES is not set (ctest sets it; see CMakeLists.txt)");
  std::ifstream file(path);
  if (!file) throw std::runtime_error(std::string("cannot read the reference states ") + path);
  std::vector<Case> cases;
  Case c;
  for (std::string line; std::getline(file, line);) {
    std::istringstream in(line);
    std::string key;
    in >> key;
    if (key == "case") {
      c = Case{};
      in >> c.model >> c.form >> c.kind >> c.method;
    } else if (key == "mass") {
      in >> c.mass;
    } else if (key == "inertia") {
      c.inertia = numbers(in);
    } else if (key == "gravity") {
      const std::vector<double> g = numbers(in);
      c.gravity = Eigen::Vector3d(g.at(0), g.at(1), g.at(2));
    } else if (key == "load") {
      std::string frame;
      in >> frame;
      const std::vector<double> x = numbers(in);
      c.loads.push_back(AppliedLoad{Eigen::Vector3d(x.at(0), x.at(1), x.at(2)), Eigen::Vector3d(x.at(3), x.at(4), x.at(5)),
                                    frame == "body" ? Frame::body : Frame::world});
    } else if (key == "h") {
      in >> c.h;
    } else if (key == "steps") {
      in >> c.steps;
    } else if (key == "y0") {
      c.y0 = numbers(in);
    } else if (key == "y1") {
      c.y1 = numbers(in);
    } else if (key == "reference_bound") {
      in >> c.reference_bound;
    } else if (key == "end") {
      cases.push_back(c);
    }
  }
  return cases;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = read_cases();
  return all;
}

// Any model's state in one form: p_W, q_WB, v_W, w_B, work (a particle has q = identity, ω = 0; a
// planar body p = (x, y, 0), q = Rz(θ), ω = (0, 0, θ̇)), as simulate records it.
struct Uniform {
  Eigen::Vector3d p, v, w;
  Eigen::Quaterniond q;
  double work;
};

Uniform uniform(const std::string& model, const std::vector<double>& y) {
  Uniform u;
  if (model == "particle") {
    u = {{y[0], y[1], y[2]}, {y[3], y[4], y[5]}, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(), y[6]};
  } else if (model == "planar") {
    u = {{y[0], y[1], 0.0}, {y[3], y[4], 0.0}, {0.0, 0.0, y[5]},
         Eigen::Quaterniond(Eigen::AngleAxisd(y[2], Eigen::Vector3d::UnitZ())), y[6]};
  } else {
    u = {{y[0], y[1], y[2]}, {y[7], y[8], y[9]}, {y[10], y[11], y[12]}, Eigen::Quaterniond(y[6], y[3], y[4], y[5]), y[13]};
  }
  u.q.normalize();
  return u;
}

Uniform last_record(const Trajectory& r) {
  const std::size_t n = r.size() - 1;
  const auto three = [&](const std::vector<double>& x) { return Eigen::Vector3d(x[3 * n], x[3 * n + 1], x[3 * n + 2]); };
  return {three(r.p_W), three(r.v_W), three(r.w_B),
          Eigen::Quaterniond(r.q_WB[4 * n + 3], r.q_WB[4 * n], r.q_WB[4 * n + 1], r.q_WB[4 * n + 2]).normalized(),
          r.work[n]};
}

// The max-norm of the difference with each of p, v, ω, work scaled by max(1, |reference value|)
// component by component and the attitude as the angle [rad] between the two (as the Python
// comparisons with the reference, tests/python/_error_bounds.py).
double scaled_difference(const Uniform& a, const Uniform& ref) {
  double d = a.q.angularDistance(ref.q);
  const auto add = [&](double x, double x_ref) { d = std::max(d, std::abs(x - x_ref) / std::max(1.0, std::abs(x_ref))); };
  for (int i = 0; i < 3; ++i) add(a.p[i], ref.p[i]), add(a.v[i], ref.v[i]), add(a.w[i], ref.w[i]);
  add(a.work, ref.work);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

// The bound on |core − reference| after N steps (scaled max-norm). Both sides compute the same
// discrete map, so they differ by round-off only, each step's carried forward by the map's
// Jacobian J (tests/python/_error_bounds.py):  |Δy_N| ≤ Σ_k ‖J(N, k)‖ (e_core + e_ref) + B_ref, with
//   e ≤ 16 ε κ S per step and side: S sub-steps (3 in Yoshida's triple jump), each y + an increment
//     of O(30) correctly rounded operations; κ = I_max/I_min from the passage ω → I ω → ω (1 without
//     attitude); plus, for implicit_midpoint, the core's Newton tolerance 1e-14 relative to ω̄
//     (implicit_midpoint_solver; the reference iterates to ε);
//   ‖J(N, k)‖ ≤ exp(N h Λ), Λ = 2 + 2κ max|ω| a Lipschitz bound of the vector field in these
//     units: 1 for ṗ = v and q̇ = ½ q ω, 2κ|ω| for the gyroscopic term, 1 for the loads (|f|/m and
//     |n|/I_min are below 1 s⁻² in every case);
//   B_ref the reference's own stated error beyond round-off (its closed free flow, written in the file).
double tolerance(const Case& c, double kappa, double w_max) {
  const double substeps = c.method == "splitting_dlm_yoshida4" ? 3.0 : 1.0;
  const double solver = c.method == "implicit_midpoint" ? implicit_midpoint_solver::tolerance * std::max(1.0, w_max) : 0.0;
  const double growth = std::exp(c.steps * c.h * (2.0 + 2.0 * kappa * w_max));
  return growth * (c.steps * (2.0 * 16.0 * eps * kappa * substeps + solver) + c.reference_bound);
}

Eigen::Matrix3d inertia_of(const Case& c) { return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(c.inertia.data()); }

SimulationOptions options_of(const Case& c) {
  SimulationOptions o;
  o.method = method_from_name(c.method);
  o.dt = c.h, o.steps = c.steps, o.record_every = c.steps;
  o.gravity_W = c.gravity, o.loads = c.loads;
  return o;
}

ParticleState particle_state(const std::vector<double>& y) { return {{y[0], y[1], y[2]}, {y[3], y[4], y[5]}}; }
PlanarBodyState planar_state(const std::vector<double>& y) { return {{y[0], y[1]}, y[2], {y[3], y[4]}, y[5]}; }
RigidBodyState rigid_state(const std::vector<double>& y) {
  return {{y[0], y[1], y[2]}, Eigen::Quaterniond(y[6], y[3], y[4], y[5]), {y[7], y[8], y[9]}, {y[10], y[11], y[12]}};
}

RigidBody rigid_body_of(const Case& c) {
  const RigidBody body(c.mass, inertia_of(c));
  const EulerForm form = c.form == "spherical" ? EulerForm::spherical : c.form == "principal" ? EulerForm::principal : EulerForm::full;
  EXPECT_EQ(body.euler_form(), form) << c.name();
  return body;
}

// ---- `steps` calls of step() ----------------------------------------------------------------------------
template <class Body, class State>
State stepped(const Body& body, State state, const Case& c) {
  SimulationOptions o = options_of(c);
  for (int k = 0; k < c.steps; ++k, o.t0 += c.h) state = step(body, state, o);
  return state;
}

// The stepped state in the uniform form (step returns no work: the expected one, checked through simulate)
Uniform step_directly(const Case& c, double work) {
  if (c.model == "particle") {
    const ParticleState s = stepped(Particle(c.mass), particle_state(c.y0), c);
    return {s.p_W, s.v_W, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(), work};
  }
  if (c.model == "planar") {
    const PlanarBodyState s = stepped(PlanarBody(c.mass, c.inertia.at(0)), planar_state(c.y0), c);
    return uniform("planar", {s.p_W.x(), s.p_W.y(), s.theta, s.v_W.x(), s.v_W.y(), s.omega, work});
  }
  const RigidBodyState s = stepped(rigid_body_of(c), rigid_state(c.y0), c);
  return {s.p_W, s.v_W, s.w_B, s.q_WB.normalized(), work};
}

// ---- through simulate() -----------------------------------------------------------------------------
Uniform simulated(const Case& c) {
  const SimulationOptions o = options_of(c);
  if (c.model == "particle") return last_record(simulate(Particle(c.mass), particle_state(c.y0), o));
  if (c.model == "planar") return last_record(simulate(PlanarBody(c.mass, c.inertia.at(0)), planar_state(c.y0), o));
  return last_record(simulate(rigid_body_of(c), rigid_state(c.y0), o));
}

double condition(const Case& c) {
  if (c.model != "rigid") return 1.0;
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_of(c)).eigenvalues();
  return moments(2) / moments(0);
}

void expect_matches_reference(const std::string& model) {
  int checked = 0;
  for (const Case& c : cases()) {
    if (c.model != model) continue;
    ++checked;
    const Uniform expected = uniform(c.model, c.y1);
    const double w_max = std::max(uniform(c.model, c.y0).w.norm(), expected.w.norm());
    const double tol = tolerance(c, condition(c), w_max);
    const double direct = scaled_difference(step_directly(c, expected.work), expected);
    EXPECT_LE(direct, tol) << c.name() << ": by calls of step()";
    if (c.model == "rigid" && c.method == "exact" && c.kind == "turning") {
      // simulate evaluates the closed form and refuses a body-fixed force (forces must be world-fixed)
      EXPECT_THROW(simulated(c), std::invalid_argument) << c.name();
      continue;
    }
    EXPECT_LE(scaled_difference(simulated(c), expected), tol) << c.name() << ": through simulate()";
  }
  EXPECT_EQ(checked, 3 * static_cast<int>(method_table().size()) * (model == "rigid" ? 3 : 1));
}

// The kind of a rigid case's loads: none (no load, no gravity), fixed (gravity, world forces, body torques: constant
// in W or B whatever the attitude) or turning (a body force or a world torque, which turn with the body)
std::string kind_of(const Case& c) {
  std::string kind = c.gravity.isZero(0.0) ? "none" : "fixed";
  for (const AppliedLoad& load : c.loads) {
    if (load.frame == Frame::body ? !load.force.isZero(0.0) : !load.torque.isZero(0.0)) return "turning";
    if (!(load.force.isZero(0.0) && load.torque.isZero(0.0))) kind = "fixed";
  }
  return kind;
}

// The file covers every (model, form, kind, method) once, each rigid case with loads of its kind.
TEST(EveryModel, TheReferenceCoversEveryMethodModelAndLoadKind) {
  std::map<std::tuple<std::string, std::string, std::string, std::string>, int> seen;
  for (const Case& c : cases()) {
    ++seen[{c.model, c.form, c.kind, c.method}];
    ASSERT_EQ(c.y0.size(), c.y1.size()) << c.name();
    ASSERT_EQ(c.y0.size(), c.model == "rigid" ? 14u : 7u) << c.name();
    if (c.model == "rigid") EXPECT_EQ(kind_of(c), c.kind) << c.name();
  }
  const std::vector<std::pair<std::string, std::string>> models = {
      {"particle", "-"}, {"planar", "-"}, {"rigid", "spherical"}, {"rigid", "principal"}, {"rigid", "full"}};
  for (const auto& [model, form] : models) {
    for (const char* kind : {"none", "fixed", "turning"}) {
      for (const MethodInfo& info : method_table()) {
        EXPECT_EQ((seen[{model, form, kind, info.name}]), 1) << model << " " << form << " " << kind << " " << info.name;
      }
    }
  }
  EXPECT_EQ(seen.size(), 5u * 3u * method_table().size());
}

TEST(EveryModel, ParticleMatchesTheReference) { expect_matches_reference("particle"); }
TEST(EveryModel, PlanarBodyMatchesTheReference) { expect_matches_reference("planar"); }
TEST(EveryModel, RigidBodyInEveryEulerFormMatchesTheReference) { expect_matches_reference("rigid"); }

}  // namespace
}  // namespace rigiddyn
