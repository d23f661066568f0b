#include "rigiddyn/models/pivoted_planar_body.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>

namespace rigiddyn {

PivotedPlanarBody::PivotedPlanarBody(double mass, double inertia_zz, const Eigen::Vector2d& p_OC_B, const Eigen::Vector2d& p_WO)
    : body_(mass, inertia_zz), p_OC_B_(p_OC_B), p_WO_(p_WO) {
  require_finite(p_OC_B, "p_OC_B");
  require_finite(p_WO, "p_WO");
  inertia_O_zz_ = inertia_zz + mass * p_OC_B.squaredNorm();  // parallel-axis theorem about z
  // a sum of positive terms: no digits lost, but it may overflow (then every energy and momentum is NaN)
  if (!std::isfinite(inertia_O_zz_)) {
    throw_invalid("p_OC_B",
                  "a pivot near enough to the centre of mass that the inertia about O, inertia_zz + m |c|² = " +
                      format_value(inertia_O_zz_) + " kg m², stays within the double range",
                  p_OC_B.transpose().eval());
  }
}

PivotedPlanarBodyState checked_state(const PivotedPlanarBodyState& state, const std::string& name) {
  require_finite(state.theta, name + ".theta");
  require_finite(state.omega, name + ".omega");
  return state;
}

BodyKinematics kinematics_of(const PivotedPlanarBody& body, const PivotedPlanarBodyState& state) {
  const Eigen::Vector2d c_W = pivoted_planar_c_W(body.p_OC_B(), state.theta);
  BodyKinematics k;
  k.p_W = Eigen::Vector3d(body.p_WO().x() + c_W.x(), body.p_WO().y() + c_W.y(), 0.0);
  set_attitude(k, Eigen::Quaterniond(Eigen::AngleAxisd(state.theta, Eigen::Vector3d::UnitZ())));
  k.v_W = Eigen::Vector3d(-state.omega * c_W.y(), state.omega * c_W.x(), 0.0);
  k.w_B = Eigen::Vector3d(0.0, 0.0, state.omega);
  k.m = body.mass();
  return k;
}

}  // namespace rigiddyn
