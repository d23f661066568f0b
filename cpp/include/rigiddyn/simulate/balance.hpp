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
// same method as the works). H and K are about W's origin (H = Σ p × m v + R I ω; a body alone runs as its one-body
// scene).
//
// Each residual comes with its round-off bound (8 ε per step times the size of the terms it is made of, summed over
// the steps: the global error estimate's bound) and its scale (what it is relative to): the motion's error is the
// balance's only other source, and accuracy_check.hpp compares the residuals with the global error estimate.
// A quantity whose balance does not apply (a pinned or planar body, whose constraint reaction's impulse is not
// integrated; a mass flow; a turning frame; loads in a closed form, which does not integrate their impulses) has
// NaN residuals and a verdict "not applicable: <why>". Records that overflowed give non-finite residuals.
#pragma once
#include "rigiddyn/scene/scene_simulation.hpp"

#include <Eigen/Core>

#include <array>
#include <cstddef>
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

// The balance of a run of n records, per quantity q (indexed by BalanceQuantity): its residuals (n,) (r_E signed,
// |r_P|, |r_H|), the round-off each can hold and the size each is relative to, in one buffer of (9, n) values (the
// residuals of the three quantities, then their round-offs, then their scales), and its verdict.
class RunBalance {
 public:
  explicit RunBalance(std::size_t n = 0) : values_(3 * balance_quantity_count * n), n_(n) {}

  double* residual(std::size_t q) { return row(q); }
  double* round_off(std::size_t q) { return row(balance_quantity_count + q); }
  double* scale(std::size_t q) { return row(2 * balance_quantity_count + q); }
  const double* residual(std::size_t q) const { return row(q); }
  const double* round_off(std::size_t q) const { return row(balance_quantity_count + q); }
  const double* scale(std::size_t q) const { return row(2 * balance_quantity_count + q); }

  std::size_t size() const { return n_; }
  bool applies(BalanceQuantity q) const;  // its verdict is not "not applicable: ..."
  // The (9, n) values, row-major, taken (the balance is left without records)
  std::vector<double> take_values() {
    n_ = 0;
    return std::move(values_);
  }

  std::array<std::string, balance_quantity_count> verdict;  // "closed", "open: ..." (accuracy_check.hpp) or
                                                            // "not applicable: <why>"
  std::string about;  // the point of the angular momentum: "W's origin" or "the centre of mass"

 private:
  double* row(std::size_t k) { return values_.data() + k * n_; }
  const double* row(std::size_t k) const { return values_.data() + k * n_; }

  std::vector<double> values_;
  std::size_t n_ = 0;
};

// The balance of a scene's run `r` at step dt [s]: `not_applicable` the reason its momentum balances do not apply
// ("" when they do: then r.impulse_W and r.angular_impulse_W, (n, 3), hold the impulses, else they do not apply
// either). Residuals as above with every element's work, the mass-flow energies and the motor works, and H, K about
// W's origin (scene_model.hpp).
RunBalance scene_balance(const SceneSimulation& r, const std::string& not_applicable, double dt);

}  // namespace rigiddyn
