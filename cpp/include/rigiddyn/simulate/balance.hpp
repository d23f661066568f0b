// The energy and momentum balance of a run: three residuals per record that are zero for the exact dynamics
// (Craig, "Rigid Body Dynamics" slides, the work-energy principle T2 − T1 = U12 and the impulse-momentum principle;
// "Rigid body kinematics and dynamics" notes, section 4.11, f = dp/dt (4.36)):
//
//   energy            r_E = T − T0 − Σ_e W_e − Σ_b E_b − Σ_k W_motor,k   [J]  (signed: > 0 when the run gained energy)
//   linear momentum   r_P = |P − P0 − J|                                  [kg m/s]
//   angular momentum  r_H = |H − H0 − K|                                  [kg m²/s]
//
// W_e the work of every force element (the conservative ones' too), E_b the mass-flow energies, W_motor the wheels'
// motor works, J and K the linear and angular impulses of the external forces (integrated with the motion by the
// same method as the works). H is about W's origin for a scene (H = Σ p × m v + R I ω, K about W's origin) and about
// the centre of mass for one body (H = R I ω, K = 0: uniform gravity and a force through the centre of mass have no
// moment about it; one body's linear impulse under uniform gravity is exact, J = m g (t − t0)).
//
// Each residual comes with its round-off bound (8 ε per step times the size of the terms it is made of, summed over
// the steps: the global error estimate's bound) and its scale (what it is relative to): the motion's error is the
// balance's only other source, and accuracy_check.hpp compares the residuals with the global error estimate.
// A quantity whose balance does not apply (a pinned or planar body, whose constraint reaction's impulse is not
// integrated; a mass flow; a turning frame; loads on one body, whose impulse is not integrated on that path) has
// NaN residuals and a verdict "not applicable: <why>". Records that overflowed give non-finite residuals.
#pragma once
#include "rigiddyn/scene/scene_simulation.hpp"
#include "rigiddyn/simulate/simulate.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rigiddyn {

// The balanced quantities, in the order of RunBalance's arrays.
enum class BalanceQuantity { energy = 0, linear_momentum = 1, angular_momentum = 2 };
inline constexpr std::size_t balance_quantity_count = 3;

// The quantities' names and units ("energy", "J"; ...), indexed by BalanceQuantity.
inline constexpr std::array<const char*, balance_quantity_count> balance_quantity_names = {
    "energy", "linear_momentum", "angular_momentum"};
inline constexpr std::array<const char*, balance_quantity_count> balance_quantity_units = {"J", "kg m/s",
                                                                                          "kg m^2/s"};

// The balance of a run of n records, per quantity q (indexed by BalanceQuantity):
struct RunBalance {
  std::array<std::vector<double>, balance_quantity_count> residual;   // (n,) r_E signed, |r_P|, |r_H|
  std::array<std::vector<double>, balance_quantity_count> round_off;  // (n,) the round-off each residual can hold
  std::array<std::vector<double>, balance_quantity_count> scale;      // (n,) the size each residual is relative to
  std::array<std::string, balance_quantity_count> verdict;  // "closed", "open: ..." (accuracy_check.hpp) or
                                                            // "not applicable: <why>"
  std::string about;  // the point of the angular momentum: "W's origin" or "the centre of mass"

  std::size_t size() const { return residual[0].size(); }
  bool applies(BalanceQuantity q) const;  // its verdict is not "not applicable: ..."
};

// What one body's balance needs of the body: its mass [kg], its inertia about the centre of mass in B [kg m²]
// (diag(0, 0, I_zz) for a planar body; none for a particle, which has no attitude) and its kind ("Particle", ...).
struct BalanceBody {
  double mass = 0.0;
  std::optional<Eigen::Matrix3d> inertia_com;
  std::string kind;
};

// The balance of a one-body run `r` (q_WB as (x, y, z, w)) of `body` under options.gravity_W; with options.loads
// the momentum balances do not apply (their impulses are not integrated on a body's own path).
// Residuals: r_E = T − T0 − work (the work records hold the loads' and gravity's, simulate.hpp),
// r_P = |m v − m v0 − m g (t − t0)|, r_H = |R I ω − (R I ω)(t0)| about the centre of mass.
RunBalance body_balance(const Trajectory& r, const BalanceBody& body, const SimulationOptions& options);

// The balance of a scene's run `r` at step dt [s]: `not_applicable` the reason its momentum balances do not apply
// ("" when they do: then r.impulse_W and r.angular_impulse_W, (n, 3), hold the impulses, else they do not apply
// either). Residuals as above with every element's work, the mass-flow energies and the motor works, and H, K about
// W's origin (scene_model.hpp).
RunBalance scene_balance(const SceneSimulation& r, const std::string& not_applicable, double dt);

}  // namespace rigiddyn
