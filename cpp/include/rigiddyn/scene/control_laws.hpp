// The shipped laws of a Controller (scene/controller.hpp), the same as rigiddyn.control's BDot and PDAttitude in
// Python (the reference the tests hold them to); from Python, simulate runs these when given those laws, without
// taking the GIL at the samples:
//   BDotLaw        magnetic detumbling, m_B = −k dB_B/dt (Stickler & Alfriend, "Elementary magnetic attitude
//                  control system"): dB_B/dt = −ω_B × B_B (gyro: the field fixed in W over a sample) or
//                  (B_B(t_k) − B_B(t_k−1))/(t_k − t_k−1) (difference: zero at the first sample); each component of
//                  m_B saturated at ±m_max. Its torque m_B × B_B = −k (|B|² 1 − B Bᵀ) ω damps the rate normal to B.
//   PDAttitudeLaw  reaction-wheel pointing, τ_B = −k_p e − k_d ω_B (Wie, "Space Vehicle Dynamics and Control"),
//                  e = 2 sign(η) ε of the error q_e = q_t⁻¹ ⊗ q_WB = (ε, η); the wheels' motor torques u = P τ_B,
//                  P = −pinv([a_1 … a_n]) (their torque on the body is −Σ u_k a_k); the target fixed, or the LVLH
//                  frame of the body's sampled position and velocity (orbit/orbit_frame.hpp).
#pragma once
#include "rigiddyn/orbit/orbit_frame.hpp"
#include "rigiddyn/scene/controller.hpp"
#include "rigiddyn/scene/elements/magnetic_dipole.hpp"
#include "rigiddyn/so3/matrix.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <utility>
#include <vector>

namespace rigiddyn {

namespace detail {

// Row b of a row-major (nb, 3) block of a SampledState, and the attitude of body b (x, y, z, w rows).
inline Eigen::Vector3d sampled_row(const std::vector<double>& rows, int b) {
  return Eigen::Vector3d(rows[3 * b], rows[3 * b + 1], rows[3 * b + 2]);
}
inline Eigen::Quaterniond sampled_attitude(const std::vector<double>& q_WB, int b) {
  return Eigen::Quaterniond(q_WB[4 * b + 3], q_WB[4 * b], q_WB[4 * b + 1], q_WB[4 * b + 2]);
}

}  // namespace detail

// B-dot on the magnetorquer `element` (its term, whose field B(p_W) [T] the law reads) of body `body`.
class BDotLaw {
 public:
  enum class Rate { gyro, difference };

  // gain k [A m² s/T] > 0, m_max [A m²] > 0 (infinity: no saturation); the caller checks them.
  BDotLaw(double gain, MagneticDipoleTerm field, int element, int body, double m_max, Rate rate)
      : gain_(gain), field_(std::move(field)), element_(element), body_(body), m_max_(m_max), rate_(rate) {}

  ActuatorCommands operator()(const SampledState& s) {
    const Eigen::Quaterniond q_WB = detail::sampled_attitude(s.q_WB, body_).normalized();
    const Eigen::Vector3d B_B = q_WB.conjugate() * field_.field_W(detail::sampled_row(s.p_W, body_));
    Eigen::Vector3d B_dot = Eigen::Vector3d::Zero();
    if (rate_ == Rate::gyro) {
      B_dot = -detail::sampled_row(s.w_B, body_).cross(B_B);  // dB_B/dt = −ω_B × B_B
    } else {
      if (last_ && s.t > last_->first) B_dot = (B_B - last_->second) / (s.t - last_->first);
      last_ = std::make_pair(s.t, B_B);
    }
    const Eigen::Vector3d m_B = (-gain_ * B_dot).cwiseMax(-m_max_).cwiseMin(m_max_);
    return {{}, {{element_, m_B}}, {}};
  }

 private:
  double gain_;
  MagneticDipoleTerm field_;
  int element_, body_;
  double m_max_;
  Rate rate_;
  std::optional<std::pair<double, Eigen::Vector3d>> last_;  // the last sample's t [s] and B_B [T] (difference)
};

// PD pointing of body `body` by the wheels of the allocation P (nw, 3): to q_target_WB, or LVLH when none.
class PDAttitudeLaw {
 public:
  // k_p [N m/rad] > 0, k_d [N m s/rad] > 0; the caller checks them and P.
  PDAttitudeLaw(double k_p, double k_d, Eigen::MatrixXd allocation, std::optional<Eigen::Quaterniond> q_target_WB,
                int body)
      : k_p_(k_p), k_d_(k_d), P_(std::move(allocation)), q_target_WB_(std::move(q_target_WB)), body_(body) {}

  // e = 2 sign(η) ε of q_e = q_target⁻¹ ⊗ q_WB = (ε, η) [rad], in B
  static Eigen::Vector3d error(const Eigen::Quaterniond& q_WB, const Eigen::Quaterniond& q_target_WB) {
    const Eigen::Quaterniond q_e = q_target_WB.normalized().conjugate() * q_WB.normalized();
    return (q_e.w() < 0.0 ? -2.0 : 2.0) * q_e.vec();
  }

  ActuatorCommands operator()(const SampledState& s) const {
    const Eigen::Quaterniond q_t =
        q_target_WB_ ? *q_target_WB_
                     : matrix_to_quat(orbit_frame_rotation(detail::sampled_row(s.p_W, body_),
                                                           detail::sampled_row(s.v_W, body_), OrbitFrame::lvlh));
    const Eigen::Vector3d tau_B =
        -k_p_ * error(detail::sampled_attitude(s.q_WB, body_), q_t) - k_d_ * detail::sampled_row(s.w_B, body_);
    const Eigen::VectorXd u = P_ * tau_B;
    return {std::vector<double>(u.data(), u.data() + u.size()), {}, {}};
  }

 private:
  double k_p_, k_d_;
  Eigen::MatrixXd P_;                              // (nw, 3): u = P τ_B
  std::optional<Eigen::Quaterniond> q_target_WB_;  // none: LVLH
  int body_;
};

}  // namespace rigiddyn
