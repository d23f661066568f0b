#include "rigiddyn/scene/scene_frame.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/matrix.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace rigiddyn {

namespace {

// Every value of K finite.
bool all_finite(const FrameKinematics& K) {
  return K.R_PF.allFinite() && K.w_PF_P.allFinite() && K.alpha_PF_P.allFinite() && K.p_PF_P.allFinite() &&
         K.v_PF_P.allFinite() && K.a_PF_P.allFinite();
}

[[noreturn]] void throw_non_finite_motion(const FrameKinematics& K, double t) {
  std::ostringstream got;
  got << "R_WF = " << format_value(K.R_PF) << ", w_W = " << format_value(K.w_PF_P) << ", alpha_W = " << format_value(K.alpha_PF_P)
      << ", p_WO = " << format_value(K.p_PF_P) << ", v_WO = " << format_value(K.v_PF_P) << ", a_WO = " << format_value(K.a_PF_P);
  throw std::invalid_argument("frame: expected finite values from the motion function at t = " + format_value(t) + " s, got " +
                              got.str());
}

// The terms of a constant rotation at `rate` [rad/s] (none at rate 0: F is then at rest in W)
FictitiousTerms rotation_terms(double rate) {
  FictitiousTerms terms;
  terms.centrifugal = terms.coriolis = rate != 0.0;
  return terms;
}

// A value the frame's terms take as zero, checked at t [s] (frame_terms)
void require_zero(const Eigen::Vector3d& value, const char* name, const char* left_out, double t) {
  if (value.isZero(0.0)) return;
  throw_invalid("frame", std::string(name) + " = 0 at t = " + format_value(t) + " s (SceneFrame.moving's terms leave out the " +
                             left_out + ")",
                value);
}

}  // namespace

std::string fictitious_term_names(const FictitiousTerms& terms) {
  std::string out;
  const std::pair<bool, const char*> named[] = {
      {terms.origin, "origin"}, {terms.euler, "euler"}, {terms.centrifugal, "centrifugal"}, {terms.coriolis, "coriolis"}};
  for (const auto& [acts, name] : named) {
    if (acts) out += (out.empty() ? "" : ", ") + std::string(name);
  }
  return out.empty() ? "none" : out;
}

SceneFrame SceneFrame::rotating(const Eigen::Vector3d& axis_F, double rate) {
  require_finite(axis_F, "axis_F");
  if (axis_F.isZero(0.0)) throw_invalid("axis_F", "a non-zero vector", axis_F);
  require_finite(rate, "rate");
  return SceneFrame{FrameMotion::constant_rotation(axis_F, rate), true, rotation_terms(rate)};
}

SceneFrame SceneFrame::earth(double latitude) {
  constexpr double half_pi = 1.57079632679489661923;
  if (!(std::isfinite(latitude) && std::abs(latitude) <= half_pi)) {
    throw_invalid("latitude", "a finite angle in [-pi/2, pi/2] rad", latitude);
  }
  // x east, y north, z up: the Earth's axis points north, tilted up by the latitude
  return rotating(Eigen::Vector3d(0.0, std::cos(latitude), std::sin(latitude)), earth_rotation_rate);
}

SceneFrame SceneFrame::moving(FrameMotion motion) {
  const FrameMotion::Function& f = motion.function();
  if (const auto* rotation = f.target<ConstantRotation>()) return SceneFrame{std::move(motion), true, rotation_terms(rotation->rate)};
  if (f.target<FixedPlacement>() != nullptr) return SceneFrame{std::move(motion), true, FictitiousTerms{}};
  return SceneFrame{std::move(motion), false, every_fictitious_term};
}

SceneFrame SceneFrame::moving(FrameMotion motion, const FictitiousTerms& terms) {
  if (terms.centrifugal != terms.coriolis || (terms.euler && !terms.centrifugal)) {
    throw std::invalid_argument("terms: expected the centrifugal and Coriolis terms together (both act where the frame "
                                "turns), and the Euler term only with them (alpha = dOmega/dt), got " +
                                fictitious_term_names(terms));
  }
  SceneFrame frame = moving(std::move(motion));
  if (frame.constant_rotation && terms != frame.terms) {
    throw std::invalid_argument("terms: expected those of the motion, a constant rotation (" +
                                fictitious_term_names(frame.terms) + "), got " + fictitious_term_names(terms));
  }
  frame.terms = terms;
  return frame;
}

FrameTerms frame_terms(const SceneFrame& frame, double t) {
  const FrameKinematics K = frame.motion.at(t);
  if (!all_finite(K)) throw_non_finite_motion(K, t);
  const Eigen::Matrix3d R_WF = checked_rotation_matrix(K.R_PF, "frame");
  if (!frame.constant_rotation) {
    if (!frame.terms.origin) require_zero(K.a_PF_P, "a_WO", "FrameOriginForce", t);
    if (!frame.terms.euler) require_zero(K.alpha_PF_P, "alpha_W", "EulerForce", t);
    if (!frame.terms.centrifugal) require_zero(K.w_PF_P, "w_W", "CentrifugalForce and CoriolisForce", t);
  }
  FrameTerms out;
  out.w_F = R_WF.transpose() * K.w_PF_P;
  out.alpha_F = R_WF.transpose() * K.alpha_PF_P;
  out.a_O_F = R_WF.transpose() * K.a_PF_P;
  return out;
}

}  // namespace rigiddyn
