#include "rigiddyn/models/pivoted_body.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace rigiddyn {

namespace {

// The form of Euler's equations an inertia I [kg m²] needs, by RigidBody::euler_form's rule: spherical if
// I = s 1, principal if diagonal, full otherwise, relative tolerance 1e-12 (dropping the terms changes the
// motion far below any integrator's error). RigidBody's classification is private to rigid_body.cpp and
// RigidBody itself cannot hold I_O (its check of a positive definite inertia is relative to trace(I), which
// a distant pivot makes large: it would refuse pivots that the digits_lost warning is meant to report).
EulerForm form_of(const Eigen::Matrix3d& I) {
  constexpr double form_tolerance = 1e-12;
  const double scale = I.diagonal().cwiseAbs().maxCoeff();
  const double off_diagonal = std::max({std::abs(I(0, 1)), std::abs(I(0, 2)), std::abs(I(1, 2))});
  if (off_diagonal > form_tolerance * scale) return EulerForm::full;
  const double spread = I.diagonal().maxCoeff() - I.diagonal().minCoeff();
  return spread <= form_tolerance * scale ? EulerForm::spherical : EulerForm::principal;
}

// I_O = I_C + m (|c|² 1 − c cᵀ) (parallel-axis theorem, Craig, "Rigid Body Dynamics" slides; the matrix
// holds the negated products of inertia off the diagonal, so the point-mass term is −m c_i c_j there).
Eigen::Matrix3d parallel_axis(double m, const Eigen::Matrix3d& I_C, const Eigen::Vector3d& c) {
  return I_C + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
}

}  // namespace

PivotedBody::PivotedBody(const RigidBody& body, const Eigen::Vector3d& p_OC_B, const Eigen::Vector3d& p_WO)
    : body_(body), p_OC_B_(p_OC_B), p_WO_(p_WO) {
  require_finite(p_OC_B, "p_OC_B");
  require_finite(p_WO, "p_WO");
  inertia_O_ = parallel_axis(body.mass(), body.inertia_com(), p_OC_B);
  const double smallest_C = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(body.inertia_com()).eigenvalues()(0);
  const double transfer = body.mass() * p_OC_B.squaredNorm();
  digits_lost_ = transfer > 0.0 ? std::max(0.0, std::log10(transfer / smallest_C)) : 0.0;
  const std::string transfer_against_C = "m|c|² = " + format_value(transfer) + " kg m² against the smallest moment " +
                                         format_value(smallest_C) + " kg m² about C: " + format_value(digits_lost_) +
                                         " digits lost";
  // digits_lost_ is NaN or inf where m|c|² overflows: refused here as well
  if (!(digits_lost_ <= max_digits_lost)) {
    throw_invalid("p_OC_B",
                  "a pivot near enough to the centre of mass that the inertia about O keeps at least one digit of the "
                  "inertia about C, at most " + format_value(max_digits_lost) + " of its 16 digits lost (" +
                      transfer_against_C + ")",
                  p_OC_B.transpose().eval());
  }
  const double smallest_O = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_O_).eigenvalues()(0);
  if (!(smallest_O > 0.0)) {
    throw_invalid("p_OC_B",
                  "a pivot near enough to the centre of mass that the inertia about O stays positive definite in double "
                  "precision (" + transfer_against_C + ")",
                  p_OC_B.transpose().eval());
  }
  form_ = form_of(inertia_O_);
}

PivotedBodyState checked_state(const PivotedBodyState& state, const std::string& name) {
  require_finite(state.w_B, name + ".w_B");
  PivotedBodyState out = state;
  out.q_WB = checked_attitude(state.q_WB, name + ".q_WB");
  return out;
}

BodyKinematics kinematics_of(const PivotedBody& body, const PivotedBodyState& state) {
  BodyKinematics k;
  const Eigen::Vector3d& c = body.p_OC_B();
  set_attitude(k, state.q_WB);
  k.w_B = state.w_B;
  k.p_W = body.p_WO() + state.q_WB * c;
  k.v_W = state.q_WB * state.w_B.cross(c);
  k.m = body.mass();
  return k;
}

Eigen::Vector3d angular_momentum_O_W(const PivotedBody& body, const PivotedBodyState& state) {
  return state.q_WB * (body.inertia_O() * state.w_B);
}

}  // namespace rigiddyn
