#include "rigiddyn/models/rigid_body.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace rigiddyn {

namespace {

// Relative tolerance for "this inertia is spherical / diagonal" (see RigidBody::euler_form).
constexpr double form_tolerance = 1e-12;

EulerForm classify(const Eigen::Matrix3d& I) {
  const double scale = I.diagonal().cwiseAbs().maxCoeff();
  const double off_diagonal = std::max({std::abs(I(0, 1)), std::abs(I(0, 2)), std::abs(I(1, 2))});
  if (off_diagonal > form_tolerance * scale) return EulerForm::full;
  const double spread = I.diagonal().maxCoeff() - I.diagonal().minCoeff();
  return spread <= form_tolerance * scale ? EulerForm::spherical : EulerForm::principal;
}

}  // namespace

RigidBody::RigidBody(double mass, const Eigen::Matrix3d& inertia_com, InertiaCheck check)
    : mass_(mass), inertia_com_(0.5 * (inertia_com + inertia_com.transpose())) {
  // Validated by the inertia layer (same errors everywhere), but stored as given (its symmetric part),
  // not projected onto the valid set: a round-off violation (e.g. a turned flat plate) changes nothing
  // in the dynamics, and the body then integrates exactly the inertia the caller wrote.
  checked_inertia(mass, inertia_com, check);
  // Euler's equations need I⁻¹: a semi-definite inertia (a point mass, a thin rod) has none.
  const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_com_).eigenvalues()(0);
  if (!(smallest > inertia_relative_tolerance * inertia_com_.trace())) {
    throw_invalid("inertia_com", "a positive definite inertia (Euler's equations need its inverse)", inertia_com);
  }
  form_ = classify(inertia_com_);
}

RigidBody::RigidBody(const SpatialInertia& inertia, InertiaCheck check)
    : RigidBody(inertia.mass(), inertia.inertia_com(), check) {}

RigidBodyState checked_state(const RigidBodyState& state, const std::string& name) {
  require_finite(state.p_W, name + ".p_W");
  require_finite(state.v_W, name + ".v_W");
  require_finite(state.w_B, name + ".w_B");
  RigidBodyState out = state;
  out.q_WB = checked_attitude(state.q_WB, name + ".q_WB");
  return out;
}

RigidBodyCoordinates to_coordinates(const RigidBodyState& state, double work) {
  RigidBodyCoordinates y;
  y << state.p_W, state.q_WB.coeffs(), state.v_W, state.w_B, work;
  return y;
}

}  // namespace rigiddyn
