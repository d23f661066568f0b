// Inputs several C++ tests share (a full inertia, a tumbling state, a load window, random rotations and vectors),
// defined once: the tests compile as a few translation units (tests/CMakeLists.txt), whose files share their
// anonymous namespaces.
#pragma once
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/models/loads.hpp"

#include <Eigen/Geometry>

#include <random>

namespace rigiddyn::test {

// Gravity along −z of the world frame, 9.81 m/s² (the value the tests and the docs use).
inline const Eigen::Vector3d kG(0.0, 0.0, -9.81);

// A rotational inertia with products of inertia: principal moments 1, 1.4, 2.1 [kg m²] about axes turned
// 0.8 rad about (1, −2, 0.5).
inline Eigen::Matrix3d full_inertia() {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  return R * Eigen::Vector3d(1.0, 1.4, 2.1).asDiagonal() * R.transpose();
}

// A body away from every special configuration: offset, turned 0.4 rad, moving and tumbling.
inline RigidBodyState tumbling_state() {
  RigidBodyState s;
  s.p_W = Eigen::Vector3d(0.5, -1.0, 2.0);
  s.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -1.0, 2.0).normalized()));
  s.v_W = Eigen::Vector3d(0.2, 0.0, -0.1);
  s.w_B = Eigen::Vector3d(0.3, 1.0, 0.2);
  return s;
}

// A body-frame force [N] and torque [N m] on from t_start to t_end [s].
inline AppliedLoad window(double t_start, double t_end) {
  AppliedLoad load{Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(0.3, -0.2, 0.4), Frame::body};
  load.t_start = t_start;
  load.t_end = t_end;
  return load;
}

// An attitude turned 0.7 rad about (1, 2, 3).
inline Eigen::Quaterniond initial_attitude() {
  return Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
}

// A uniformly distributed rotation (a normalised Gaussian 4-vector).
inline Eigen::Quaterniond random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

// A vector with entries uniform in [−scale, scale].
inline Eigen::Vector3d random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  return {uniform(rng), uniform(rng), uniform(rng)};
}

}  // namespace rigiddyn::test
