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

RigidBody::RigidBody(double mass, const Eigen::Matrix3d& inertia_com, bool require_triangle_inequality)
    : mass_(mass), inertia_com_(inertia_com) {
  require_positive(mass, "mass");
  require_finite(inertia_com, "inertia_com");
  const double scale = inertia_com.cwiseAbs().maxCoeff();
  if ((inertia_com - inertia_com.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw_invalid("inertia_com", "a symmetric matrix", inertia_com);
  }
  inertia_com_ = 0.5 * (inertia_com + inertia_com.transpose());
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_com_).eigenvalues();
  if (!(moments(0) > 0.0)) throw_invalid("inertia_com", "a positive definite matrix", inertia_com);
  // principal moments sorted ascending: the triangle inequality fails first as I1 + I2 < I3
  if (require_triangle_inequality && moments(0) + moments(1) < moments(2) * (1.0 - 1e-12)) {
    throw_invalid("inertia_com", "principal moments with I1 + I2 >= I3 (triangle inequality)", inertia_com);
  }
  form_ = classify(inertia_com_);
}

RigidBody::RigidBody(const SpatialInertia& inertia, bool require_triangle_inequality)
    : RigidBody(inertia.mass(), inertia.inertia_com(), require_triangle_inequality) {}

RigidBodyState checked_state(const RigidBodyState& state, const std::string& name) {
  require_finite(state.p_W, name + ".p_W");
  require_finite(state.v_W, name + ".v_W");
  require_finite(state.w_B, name + ".w_B");
  RigidBodyState out = state;
  out.q_WB = checked_unit_quaternion(state.q_WB, name + ".q_WB");
  return out;
}

RigidBodyCoordinates to_coordinates(const RigidBodyState& state, double work) {
  RigidBodyCoordinates y;
  y << state.p_W, state.q_WB.coeffs(), state.v_W, state.w_B, work;
  return y;
}

RigidBodyState to_rigid_body_state(const RigidBodyCoordinates& y) {
  RigidBodyState state;
  state.p_W = y.segment<3>(0);
  state.q_WB = Eigen::Quaterniond(Eigen::Vector4d(y.segment<4>(3)));
  state.v_W = y.segment<3>(7);
  state.w_B = y.segment<3>(10);
  return state;
}

}  // namespace rigiddyn
