// The free particle seen from a uniformly turning frame (exact/rotating_frame.hpp).
#include "rigiddyn/exact/rotating_frame.hpp"

#include "rigiddyn/check.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace rigiddyn {

RotatingFrameFreeParticle::RotatingFrameFreeParticle(const Eigen::Vector3d& axis_F, double rate,
                                                     const Eigen::Vector3d& p0_F, const Eigen::Vector3d& v0_F) {
  require_finite(axis_F, "axis_F");
  require_finite(rate, "rate");
  const double length = axis_F.stableNorm();  // scaled: no overflow of the squares for |axis_F| > 1e154
  if (!(length > 0.0 && std::isfinite(length)) && rate != 0.0) {
    throw_invalid("axis_F", "a non-zero axis", axis_F.transpose().eval());
  }
  require_finite(p0_F, "p0_F");
  require_finite(v0_F, "v0_F");
  axis_ = length > 0.0 ? Eigen::Vector3d(axis_F / length) : Eigen::Vector3d::UnitZ();
  rate_ = rate;
  w_ = rate * axis_;
  // at t = 0 F = W: p_W0 = p_F0, v_W = v_F0 + ω × p_F0
  p_W0_ = p0_F;
  v_W_ = v0_F + w_.cross(p0_F);
  jacobi_ = 0.5 * v0_F.squaredNorm() - 0.5 * w_.cross(p0_F).squaredNorm();
}

namespace {

// ω_F of a constantly turning scene frame (frame named on anything else).
Eigen::Vector3d constant_rate_of(const SceneFrame& frame) {
  if (!frame.constant_rotation) {
    throw std::invalid_argument("frame: expected a frame turning at a constant rate about a fixed origin "
                                "(SceneFrame.rotating or SceneFrame.earth), got a general moving frame");
  }
  return frame_terms(frame, 0.0).w_F;
}

// Ω = |ω_F| [rad/s], scaled (stableNorm: |ω_F| up to the double range, where the plain norm's squares
// overflow beyond 1.3e154); frame named where even Ω is beyond the range.
double constant_rate_magnitude(const SceneFrame& frame) {
  const Eigen::Vector3d w_F = constant_rate_of(frame);
  const double rate = w_F.stableNorm();
  if (!std::isfinite(rate)) throw_invalid("frame", "a rotation rate |w_F| within the double range", w_F.transpose().eval());
  return rate;
}

}  // namespace

RotatingFrameFreeParticle::RotatingFrameFreeParticle(const SceneFrame& frame, const Eigen::Vector3d& p0_F,
                                                     const Eigen::Vector3d& v0_F)
    : RotatingFrameFreeParticle(constant_rate_of(frame), constant_rate_magnitude(frame), p0_F, v0_F) {}

RotatingFrameParticleState RotatingFrameFreeParticle::at(double t) const {
  require_finite(t, "t");
  // R_FW(t) = exp(−Ω t n̂); the angle reduced mod 2π so that a large Ω t keeps its absolute accuracy
  const Eigen::AngleAxisd R_FW(std::remainder(-rate_ * t, 2.0 * M_PI), axis_);
  const Eigen::Vector3d p_W = p_W_at(t);
  return {R_FW * p_W, R_FW * (v_W_ - w_.cross(p_W))};
}

}  // namespace rigiddyn
