// Tests of the rotation parameters beyond Euler angles: Davenport angles about arbitrary axes
// (against the product of axis rotations that defines them, and against Euler angles on the
// coordinate axes), the gimbal-lock report, modified Rodrigues parameters (closed form tan(θ/4),
// shadow sets, extreme magnitudes) and the quaternion rate <-> angular velocity maps (against the
// exact flow of a constant angular velocity, round trips, body vs world).
#include <gtest/gtest.h>

#include "error_bounds.hpp"
#include "invalid_argument_message.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/so3/euler.hpp"
#include "rigiddyn/so3/integrate.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/mrp.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kPi;
using rigiddyn::test::kEps;
// Tolerances: one conversion is a fixed sequence of <= ~20 correctly rounded operations on unit
// numbers (unit quaternions, rotation entries, angles <= pi): <= 20 eps = 4.4e-15 per entry, 1e-14
// in a norm of the difference; where angles amplify round-off (1/sin φ near gimbal lock), the
// comment at the assertion says by how much.

struct RandomAxes {
  std::mt19937_64 engine{20261124};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
  Eigen::Vector3d unit_vector() {
    std::normal_distribution<double> normal;
    return Eigen::Vector3d(normal(engine), normal(engine), normal(engine)).normalized();
  }
  Eigen::Quaterniond quaternion() {
    std::normal_distribution<double> normal;
    return Eigen::Quaterniond(normal(engine), normal(engine), normal(engine), normal(engine)).normalized();
  }
  // rows n1, n2, n3 with n2 ⊥ n1 and n3 = R_n2(-lambda) n1 ⊥ n2 (so that lambda = atan2(n3 . (n1 × n2),
  // n3 . n1) as in euler.hpp), scaled by random lengths (DavenportAxes normalises them)
  Eigen::Matrix3d davenport_axes(double lambda) {
    const Eigen::Vector3d n1 = unit_vector();
    const Eigen::Vector3d n2 = Eigen::AngleAxisd(uniform(-kPi, kPi), n1) * n1.unitOrthogonal();
    const Eigen::Vector3d n3 = Eigen::AngleAxisd(-lambda, n2) * n1;
    Eigen::Matrix3d axes;
    axes << uniform(0.5, 2) * n1.transpose(), uniform(0.5, 2) * n2.transpose(), uniform(0.5, 2) * n3.transpose();
    return axes;
  }
};

using rigiddyn::test::rotation_distance;

using rigiddyn::test::expect_invalid;

// the definition: extrinsic R_n3(θ3) R_n2(θ2) R_n1(θ1), intrinsic R_n1(θ1) R_n2(θ2) R_n3(θ3)
Eigen::Matrix3d davenport_definition(const Eigen::Matrix3d& axes, bool intrinsic, const Eigen::Vector3d& angles) {
  Eigen::Matrix3d R[3];
  for (int n = 0; n < 3; ++n) R[n] = Eigen::AngleAxisd(angles[n], axes.row(n).transpose().normalized()).toRotationMatrix();
  return intrinsic ? (R[0] * R[1] * R[2]).eval() : (R[2] * R[1] * R[0]).eval();
}

// ---------------------------------------------------------------- Davenport angles

TEST(Davenport, ForwardMatchesTheDefinition) {
  RandomAxes rnd;
  for (bool intrinsic : {false, true}) {
    for (int n = 0; n < 200; ++n) {
      const Eigen::Matrix3d axes = rnd.davenport_axes(rnd.uniform(-kPi, kPi));
      const Eigen::Vector3d angles(rnd.uniform(-4, 4), rnd.uniform(-4, 4), rnd.uniform(-4, 4));
      const Eigen::Quaterniond q = davenport_to_quat(DavenportAxes(axes, intrinsic), angles);
      EXPECT_LT((quat_to_matrix(q) - davenport_definition(axes, intrinsic, angles)).norm(), 1e-14);
    }
  }
}

TEST(Davenport, InverseReproducesTheRotationWithAnglesInRange) {
  RandomAxes rnd;
  for (bool intrinsic : {false, true}) {
    for (double lambda : {0.0, 0.3, kPi / 2, -kPi / 2, -2.0, 3.0, kPi}) {
      for (int n = 0; n < 100; ++n) {
        const Eigen::Matrix3d axes = rnd.davenport_axes(lambda);
        const DavenportAxes d(axes, intrinsic);
        const Eigen::Quaterniond q = rnd.quaternion();
        const Eigen::Vector3d e = quat_to_davenport(d, q);
        // λ as the axes give it, about the axes in the order applied (reversed when intrinsic); at
        // λ = 0 and pi its sign is that of a round-off, as in SciPy
        const Eigen::Vector3d m1 = intrinsic ? d.n3 : d.n1, m3 = intrinsic ? d.n1 : d.n3;
        const double l = std::atan2(m3.dot(m1.cross(d.n2)), m3.dot(m1));
        const double sign = l < 0.0 ? -1.0 : 1.0;
        // θ2 = sign (φ - |λ|), φ in [0, pi]: in [-λ, pi - λ] (λ >= 0) or [-pi - λ, -λ] (λ < 0); the
        // bounds hold up to the rounding of φ - |λ| (~4 eps)
        EXPECT_GE(e[1], std::min(-l, -kPi - l) - 1e-15);
        EXPECT_LE(e[1], std::max(kPi - l, -l) + 1e-15);
        EXPECT_LE(std::abs(e[0]), kPi);
        EXPECT_LE(std::abs(e[2]), kPi);
        EXPECT_LT(rotation_distance(davenport_to_quat(d, e), q), 1e-14);
        // angles in range away from the lock come back: they amplify q's round-off by 1/sin φ <= 1/sin 0.1 = 10
        const Eigen::Vector3d angles(rnd.uniform(-kPi, kPi), sign * (rnd.uniform(0.1, kPi - 0.1) - std::abs(l)), rnd.uniform(-kPi, kPi));
        EXPECT_LT((quat_to_davenport(d, davenport_to_quat(d, angles)) - angles).norm(), 20 * 20 * kEps);
      }
    }
  }
}

TEST(Davenport, CoordinateAxesGiveEulerAngles) {
  const std::vector<std::string> sequences = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
                                              "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};
  RandomAxes rnd;
  for (const std::string& name : sequences) {
    const EulerSequence seq(name);
    Eigen::Matrix3d axes;
    for (int n = 0; n < 3; ++n) axes.row(n) = Eigen::Vector3d::Unit(seq.axes[n]).transpose();
    const DavenportAxes d(axes, seq.intrinsic);
    for (int n = 0; n < 50; ++n) {
      const Eigen::Quaterniond q = rnd.quaternion();
      const Eigen::Vector3d e = quat_to_euler(seq, q);
      // two routes through atan2 on the same quaternion: each angle to ~20 eps times 1/sin φ
      const double phi = seq.axes[0] == seq.axes[2] ? e[1] : e[1] + kPi / 2;
      EXPECT_LT((quat_to_davenport(d, q) - e).norm(), 400 * kEps / std::sin(phi)) << name;
      EXPECT_LT(rotation_distance(davenport_to_quat(d, e), euler_to_quat(seq, e)), 1e-15) << name;
    }
  }
}

TEST(Davenport, BadAxesThrow) {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  axes(1, 0) = 1e-6;  // n2 not orthogonal to n1
  expect_invalid([&] { DavenportAxes d(axes, false); }, "axes");
  axes = Eigen::Matrix3d::Identity();
  axes.row(2).setZero();
  expect_invalid([&] { DavenportAxes d(axes, false); }, "axes[2]");
  axes(0, 0) = NAN;
  expect_invalid([&] { DavenportAxes d(axes, true); }, "axes[0]");
  // n1 = ±n3 is allowed (a proper sequence), as is n3 ⊥ n1 (Tait-Bryan)
  axes << 1, 0, 0, 0, 1, 0, -2, 0, 0;
  EXPECT_NO_THROW(DavenportAxes(axes, false));
}

// ---------------------------------------------------------------- gimbal lock

TEST(GimbalLock, ReportsTheDistanceOfTheMiddleAngleFromTheLock) {
  RandomAxes rnd;
  const Eigen::Matrix3d tilted = rnd.davenport_axes(0.7);
  const DavenportAxes davenport(tilted, false);
  for (const char* name : {"xyz", "ZYX", "zxz", "XYX"}) {
    const EulerSequence seq(name);
    const bool proper = seq.axes[0] == seq.axes[2];
    // φ = θ2 (proper) or θ2 + pi/2: locks at θ2 = 0 and pi, or -pi/2 and pi/2; offsets well inside or
    // outside the thresholds 1e-13 and 1e-7 (θ2 is recovered to ~1e-16 at the lock)
    for (double lock : proper ? std::vector<double>{0.0, kPi} : std::vector<double>{-kPi / 2, kPi / 2}) {
      const double inward = lock == 0.0 || lock == -kPi / 2 ? 1.0 : -1.0;
      for (auto [offset, expected] : std::vector<std::pair<double, GimbalLock>>{
               {0.0, GimbalLock::at}, {1e-15, GimbalLock::at}, {1e-10, GimbalLock::near}, {1e-8, GimbalLock::near},
               {1e-6, GimbalLock::none}, {0.5, GimbalLock::none}}) {
        const Eigen::Vector3d angles(rnd.uniform(-3, 3), lock + inward * offset, rnd.uniform(-3, 3));
        const Eigen::Quaterniond q = euler_to_quat(seq, angles);
        GimbalLock got = GimbalLock::none;
        const Eigen::Vector3d e = quat_to_euler(seq, q, &got);
        EXPECT_EQ(got, expected) << name << " offset " << offset;
        if (expected == GimbalLock::at) {
          EXPECT_EQ(e[2], 0.0) << name;
        }
        // at the lock θ3 = 0 moves the rotation by <= 2 x offset (<= 2e-15); elsewhere the angles are exact
        EXPECT_LT(rotation_distance(euler_to_quat(seq, e), q), 1e-14) << name << " offset " << offset;
        // Davenport angles report the same way (λ = 0.7 here: φ = θ2 + 0.7)
        const Eigen::Vector3d d_angles(angles[0], (proper ? lock : lock + kPi / 2) - 0.7 + inward * offset, angles[2]);
        GimbalLock d_got = GimbalLock::none;
        const Eigen::Quaterniond qd = davenport_to_quat(davenport, d_angles);
        const Eigen::Vector3d de = quat_to_davenport(davenport, qd, &d_got);
        EXPECT_EQ(d_got, expected) << "davenport offset " << offset;
        EXPECT_LT(rotation_distance(davenport_to_quat(davenport, de), qd), 1e-14);
      }
    }
  }
}

// ---------------------------------------------------------------- modified Rodrigues parameters

TEST(Mrp, IsAxisTimesTanQuarterAngle) {
  RandomAxes rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d axis = rnd.unit_vector();
    const double angle = rnd.uniform(0, kPi);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
    // tan(θ/4) <= 1 and the quotient v/(1 + w): a few roundings of numbers <= 1
    EXPECT_LT((quat_to_mrp(q) - std::tan(angle / 4) * axis).norm(), 1e-15);
    // the other sign of q (w < 0) gives the same set with |p| <= 1
    EXPECT_LT((quat_to_mrp(Eigen::Quaterniond(-q.coeffs())) - quat_to_mrp(q)).norm(), 1e-15);
    EXPECT_LT(rotation_distance(mrp_to_quat(quat_to_mrp(q)), q), 1e-15);
  }
}

TEST(Mrp, ShadowSetsAndExtremeMagnitudesGiveTheSameRotation) {
  RandomAxes rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d p = rnd.unit_vector() * std::pow(10.0, rnd.uniform(-3, 3));
    const Eigen::Vector3d shadow = -p / p.squaredNorm();
    const Eigen::Quaterniond q = mrp_to_quat(p);
    EXPECT_LT(std::abs(q.norm() - 1.0), 4 * kEps);
    // either set: a few roundings of numbers <= 1 after the division by 1 + |p|² (or its mirror)
    EXPECT_LT(rotation_distance(mrp_to_quat(shadow), q), 1e-15);
    EXPECT_EQ(q.w() < 0.0, p.norm() > 1.0);
  }
  const Eigen::Vector3d axis(0.6, 0.0, 0.8);
  // |p| = 1e300: (2 p/(1 + |p|²), (1 - |p|²)/(1 + |p|²)) = (2e-300 axis, -1), no overflow
  const Eigen::Quaterniond huge = mrp_to_quat(1e300 * axis);
  EXPECT_EQ(huge.w(), -1.0);
  EXPECT_LT((huge.vec() - 2e-300 * axis).norm(), 4 * kEps * 2e-300);
  const Eigen::Quaterniond tiny = mrp_to_quat(1e-300 * axis);
  EXPECT_EQ(tiny.w(), 1.0);
  EXPECT_LT((tiny.vec() - 2e-300 * axis).norm(), 4 * kEps * 2e-300);
  expect_invalid([] { mrp_to_quat(Eigen::Vector3d(0.0, INFINITY, 0.0)); }, "mrp");
}

// ---------------------------------------------------------------- quaternion rate

TEST(QuatRate, IsTheDerivativeOfTheExactFlow) {
  RandomAxes rnd;
  for (Frame frame : {Frame::body, Frame::world}) {
    for (int n = 0; n < 50; ++n) {
      const Eigen::Quaterniond q = rnd.quaternion();
      const Eigen::Vector3d w = rnd.unit_vector() * rnd.uniform(0, 2);
      const double h = 1e-5;
      // central difference of quat_integrate (the exact flow for constant w): truncation
      // h²/6 |q'''| <= h²/6 (|w|/2)³ = 1.7e-11, round-off 4 eps / h = 9e-11
      const Eigen::Vector4d fd =
          (quat_integrate(q, w, h, frame).coeffs() - quat_integrate(q, w, -h, frame).coeffs()) / (2 * h);
      EXPECT_LT((fd - quat_rate(q, w, frame).coeffs()).norm(), 2e-10);
    }
  }
}

TEST(QuatRate, AngularVelocityInvertsIt) {
  RandomAxes rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Quaterniond q = rnd.quaternion();
    const Eigen::Vector3d w_B = rnd.unit_vector() * rnd.uniform(0, 10);
    const Eigen::Vector3d w_W = q * w_B;
    const Eigen::Quaterniond dq_dt = quat_rate(q, w_B, Frame::body);
    // the same motion in both frames: ½ q ⊗ w_B = ½ (R w_B) ⊗ q; two products of <= 10 roundings
    // on numbers <= |w| = 10
    EXPECT_LT((quat_rate(q, w_W, Frame::world).coeffs() - dq_dt.coeffs()).norm(), 40 * kEps * 10);
    EXPECT_LT(std::abs(q.coeffs().dot(dq_dt.coeffs())), 20 * kEps * 10);  // tangent to the unit sphere
    EXPECT_LT(std::abs(dq_dt.norm() - 0.5 * w_B.norm()), 20 * kEps * 10);
    EXPECT_LT((angular_velocity_from_quat_rate(q, dq_dt, Frame::body) - w_B).norm(), 40 * kEps * 10);
    EXPECT_LT((angular_velocity_from_quat_rate(q, dq_dt, Frame::world) - w_W).norm(), 40 * kEps * 10);
    // a part along q (a change of |q|, not a rotation) is ignored
    const Eigen::Quaterniond radial(dq_dt.coeffs() + 3.0 * q.coeffs());
    EXPECT_LT((angular_velocity_from_quat_rate(q, radial, Frame::body) - w_B).norm(), 40 * kEps * 13);
  }
  const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
  expect_invalid([&] { quat_rate(id, Eigen::Vector3d(NAN, 0, 0), Frame::body); }, "w");
  expect_invalid([&] { angular_velocity_from_quat_rate(id, Eigen::Quaterniond(INFINITY, 0, 0, 0), Frame::world); }, "dq_dt");
}

}  // namespace
}  // namespace rigiddyn
