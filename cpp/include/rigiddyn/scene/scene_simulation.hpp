// What simulate records of a scene (docs/scenes.md §5) and what step returns.
#pragma once
#include "rigiddyn/scene/body.hpp"

#include <cstdint>
#include <vector>

namespace rigiddyn {

// Records of a scene run, one row per recorded step, row-major (n = size() records, nb = body_count
// bodies, ne = element_count elements). Bodies of every kind in the rigid-body layout: a particle has
// q_WB = identity and w_B = 0, a planar body p_W = (x, y, 0), q_WB = Rz(θ), v_W = (v_x, v_y, 0),
// w_B = (0, 0, ω); a gyrostat as the rigid body it is, its wheel speeds in wheel_speed; a pivoted body its centre of mass p_W = p_WO + R_WB p_OC_B and v_W = R_WB (ω × p_OC_B).
// "W" is the scene frame: W itself when the scene declares no moving frame, else F, and
// every record is relative to it (kinetic energy included; the potential includes the centrifugal one
// of a frame turning at a constant rate, so that total_energy is then the Jacobi integral).
struct SceneSimulation {
  std::int64_t body_count = 0;
  std::int64_t element_count = 0;
  std::vector<double> t;                  // (n,) time [s]
  std::vector<double> p_W;                // (n, nb, 3) centre of mass positions in W [m]
  std::vector<double> q_WB;               // (n, nb, 4) attitudes (x, y, z, w), as integrated (norm not forced)
  std::vector<double> v_W;                // (n, nb, 3) centre of mass velocities in W [m/s]
  std::vector<double> w_B;                // (n, nb, 3) angular velocities in B [rad/s]
  std::vector<double> kinetic_energy;     // (n,) Σ ½ m v·v + ½ ω·I ω [J]
  std::vector<double> potential_energy;   // (n,) Σ of the element potentials [J] (0 for those without one)
  std::vector<double> total_energy;       // (n,) kinetic + potential [J]
  std::vector<double> linear_momentum_W;  // (n, 3) Σ m v_W [kg m/s]
  std::vector<double> angular_momentum_W; // (n, 3) about W's origin: Σ p_W × m v_W + R_WB I ω_B [kg m²/s]
  std::vector<double> pivot_reaction_W;   // (n, nb, 3) the pivot's force on each body in W [N] (0 unpinned)
  std::vector<double> angular_momentum_O_W;  // (n, nb, 3) each body's H about its pivot O (about its
                                          // centre of mass when unpinned), in W [kg m²/s]
  std::vector<double> mass;               // (n, nb) each body's mass [kg]
  std::vector<double> work;               // (n, ne) each element's work since t0 [J]
  std::vector<double> power;              // (n, ne) each element's power at the record [W]
  std::vector<double> mass_flow_energy;   // (n, nb) each body's mass-flow energy since t0 [J]: the integral of
                                          // ½ ṁ |v|² + ½ ω·(dI/dt) ω, the kinetic energy its mass flow takes away
                                          // or brings (0 for a constant mass), so that kinetic_energy − its first
                                          // value = Σ work + Σ mass_flow_energy to the method's error
                                          // (scene_model.hpp); empty when no body has a MassFlow (all 0)
  std::vector<double> impulse_W;          // (n, 3) the linear impulse Σ ∫ f dt of all the elements since t0 [N s]
  std::vector<double> angular_impulse_W;  // (n, 3) their angular impulse about W's origin ∫ Σ (p × f + R τ_B) dt
                                          // [N m s] (scene_model.hpp; empty on the paths that do not integrate
                                          // them: the one-body path and the specialised models)
  std::vector<double> wheel_speed;        // (n, nw) each gyrostat wheel's speed relative to its body [rad/s], the
                                          // wheels of the gyrostats in the scene's order (empty without one)
  std::vector<double> motor_work;         // (n, nw) each wheel's motor work since t0 [J] (∫ u Ω dt): T − T(0) =
                                          // Σ work + Σ mass_flow_energy + Σ motor_work to the method's error
  std::vector<double> joint_q;            // (n, nq) the trees' configurations q as integrated (quaternions' norms
                                          // not forced), the trees in the scene's order (empty without one)
  std::vector<double> joint_v;            // (n, nv) their velocities v
  // The run recorded what the global error estimate reads of a coarse run alone (SimulationOptions'
  // estimate_records): potential_energy, linear_momentum_W, pivot_reaction_W, angular_momentum_O_W, mass, power and
  // the impulses stay empty (but on the one-body fast models' runs, which record every column).
  bool estimate_records = false;
  bool diverged = false;                  // the state became non-finite; the run stopped there
  bool interrupted = false;               // options.monitor returned true; the run stopped there
  std::int64_t unconverged_steps = 0;     // steps whose implicit solve stopped at its iteration cap
  double elapsed_seconds = 0.0;           // wall time of the stepping loop [s]

  std::size_t size() const { return t.size(); }
};

// The state of a scene after `step`: the time t [s], each body's state (the kind of its body), each
// body's mass [kg] (its mass flow's result for a body with one) and each element's work over the step [J].
struct SceneState {
  double t = 0.0;
  std::vector<BodyState> bodies;
  std::vector<double> mass;
  std::vector<double> work;
};

// Appends the N values at x to the record column `column`, value by value: push_back's inlined path where the run
// reserved its records (a range insert is a call and a size computation per column and record)
template <int N>
inline void append_values(std::vector<double>& column, const double* x) {
  for (int i = 0; i < N; ++i) column.push_back(x[i]);
}

}  // namespace rigiddyn
