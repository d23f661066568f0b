// simulate: many fixed steps of one method on one body, recording every k-th state and diagnostics; step: one
// step. Usable from C++ directly; the Python binding releases the GIL around them. A body runs as the scene of that
// body alone (scene/one_body_scene.hpp: the body, UniformGravity(gravity_W) and ScheduledLoads(loads) where they
// act) on the model compile_scene chooses for it (a one-body layout; 'exact' on a rigid body: the closed form of the
// torque-free motion). Loads: see models/loads.hpp (piecewise constant; a step that crosses a switch time is split
// there). The work of all loads and gravity is integrated with the motion by the same method, so
// T(t) − T(t0) = work(t) up to the method's error (work–energy principle T2 − T1 = U12, Craig, "Rigid Body
// Dynamics" slides).
#pragma once
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/models/loads.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/models/planar_body.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/simulate/monitor_pace.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <vector>

namespace rigiddyn {

// Uniform gravity g_W = (0, 0, −9.81) m/s² (docs/conventions.md "Gravity").
inline Eigen::Vector3d standard_gravity() { return Eigen::Vector3d(0.0, 0.0, -9.81); }

struct SimulationOptions {
  Method method = Method::rk4;
  double dt = 1e-3;                  // step [s], finite > 0
  std::int64_t steps = 0;            // number of steps >= 0
  std::int64_t record_every = 1;     // record every k-th step (and always the first and the last)
  double t0 = 0.0;                   // initial time [s] (load schedules refer to it)
  std::vector<AppliedLoad> loads;    // applied loads (models/loads.hpp)
  Eigen::Vector3d gravity_W = Eigen::Vector3d::Zero();  // uniform gravity [m/s²]; zero = none
  // Called by simulate from the stepping thread between steps, after the first step and then about every
  // monitor_period_seconds of wall time whatever a step costs (simulate/monitor_pace.hpp), with the number
  // of steps done (a progress report, an interrupt check); returning true stops the run, which then
  // returns its records so far with Trajectory::interrupted set. Empty: never called.
  std::function<bool(std::int64_t steps_done)> monitor;
  // A scene's run records only what the global error estimate reads of its runs at 2h and 4h (SceneSimulation's
  // estimate_records): a coarse run of the estimate, whose other columns nothing reads.
  bool estimate_records = false;
};

// Records, one row per recorded step, row-major (n = size()):
struct Trajectory {
  std::vector<double> t;                      // (n,) time [s]
  std::vector<double> p_W;                    // (n, 3) centre of mass position in W [m]
  std::vector<double> q_WB;                   // (n, 4) attitude (x, y, z, w)
  std::vector<double> v_W;                    // (n, 3) centre of mass velocity in W [m/s]
  std::vector<double> w_B;                    // (n, 3) angular velocity in B [rad/s]
  std::vector<double> kinetic_energy;         // (n,) T [J]
  std::vector<double> total_energy;           // (n,) T + V of gravity [J]
  std::vector<double> angular_momentum_norm;  // (n,) |H_G| about the centre of mass [kg m²/s]
  std::vector<double> quaternion_norm_error;  // (n,) |q| − 1
  std::vector<double> work;                   // (n,) work of loads and gravity since t0 [J]
  bool diverged = false;                      // the state became non-finite; the run stopped there
  bool interrupted = false;                   // options.monitor returned true; the run stopped there
  std::int64_t unconverged_steps = 0;         // steps whose implicit solve stopped at its iteration cap
                                              // (implicit_midpoint; always 0 for explicit methods)
  double elapsed_seconds = 0.0;               // wall time of the stepping loop (for benchmarks)

  std::size_t size() const { return t.size(); }
};

// Throws std::invalid_argument naming the argument for dt <= 0, steps < 0, record_every < 1,
// non-finite t0 or gravity, a bad state or load, a recording larger than the available memory
// (record_every), loads the body cannot take (torques on a particle; out-of-plane forces, gravity or
// torques, for a planar body) and, for 'exact' on a rigid body, loads other than constant world-frame
// forces ("loads[i].torque", "loads[i].force", "loads").
Trajectory simulate(const RigidBody& body, const RigidBodyState& initial, const SimulationOptions& options);
Trajectory simulate(const Particle& particle, const ParticleState& initial, const SimulationOptions& options);
Trajectory simulate(const PlanarBody& body, const PlanarBodyState& initial, const SimulationOptions& options);

// One step of `options.method` from `state` at time t = options.t0 [s] to t + options.dt: the state
// at t + dt. The step of the body's one-body scene (scene/one_body_scene.hpp: the body under UniformGravity and
// ScheduledLoads where they act), on the layout simulate of that scene runs, so that its first step is bitwise
// simulate's; split at the switch times of options.loads inside (t, t + dt) as in simulate. options.steps,
// record_every and monitor are ignored. Same checks as simulate.
RigidBodyState step(const RigidBody& body, const RigidBodyState& state, const SimulationOptions& options);
ParticleState step(const Particle& particle, const ParticleState& state, const SimulationOptions& options);
PlanarBodyState step(const PlanarBody& body, const PlanarBodyState& state, const SimulationOptions& options);

}  // namespace rigiddyn
