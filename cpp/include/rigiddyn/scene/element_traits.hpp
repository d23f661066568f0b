// What a compiled force element depends on and provides: read once when a scene is
// compiled (method compatibility, which diagnostics to record), never per evaluation.
#pragma once

namespace rigiddyn {

struct ElementTraits {
  bool reads_attitude;      // its wrench depends on some body's q_WB (R_WB): without it and has_torque, it never reads R_WB
  bool velocity_dependent;  // its wrench depends on some v_W or w_B (drag, dampers)
  bool time_dependent;      // its wrench depends on t (schedules, user forces)
  bool has_potential;       // potential() is its potential energy V with f = −∇_p V, τ = −∂V/∂(rotation)
  bool has_torque;          // it may produce a non-zero tau_B
  bool has_force = true;        // it may produce a non-zero f_W
  bool needs_attitude = false;  // it acts only on bodies with an attitude (it skips particles)
  // its forces on the bodies sum to zero, and so do their moments about any point: internal forces, equal and opposite
  // along the line through their points of application (Newton's third law in its strong form), which add nothing to
  // the scene's impulses
  bool zero_net_wrench = false;
};

}  // namespace rigiddyn
