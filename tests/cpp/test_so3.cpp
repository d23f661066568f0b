// Tests of the so3 layer: closed forms (Eigen::AngleAxis, Rodrigues, elementary products), round
// trips, the delicate angles (near 0, near pi, gimbal lock) and bad input.
#include <gtest/gtest.h>

#include "error_bounds.hpp"
#include "invalid_argument_message.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/so3/axis_angle.hpp"
#include "rigiddyn/so3/elementary.hpp"
#include "rigiddyn/so3/euler.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/integrate.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"
#include "rigiddyn/so3/skew.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kPi;
// Tolerances in this file: one conversion is a fixed sequence of <= ~20 correctly rounded
// operations on unit numbers (rotation entries, unit quaternions, angles <= pi), so it errs by
// <= ~20 eps per entry (4e-15), <= 1e-14 in the Frobenius norm of a 3x3 difference; 1e-15 where
// the result is exact up to one or two roundings (elementary rotations, copies); where a formula
// amplifies round-off (near a gimbal lock, near pi, tiny angles through a matrix), the comment at
// the assertion says by how much.

// deterministic random inputs
struct Random {
  std::mt19937_64 engine{20240611};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
  Eigen::Vector3d vector(double scale = 1.0) {
    return Eigen::Vector3d(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
  }
  Eigen::Vector3d unit_vector() {
    Eigen::Vector3d v;
    do {
      v = vector();
    } while (v.norm() < 0.1 || v.norm() > 1.0);
    return v.normalized();
  }
  Eigen::Quaterniond quaternion() {
    std::normal_distribution<double> normal;
    Eigen::Quaterniond q(normal(engine), normal(engine), normal(engine), normal(engine));
    return q.normalized();
  }
};

using rigiddyn::test::rotation_distance;

// Rodrigues' formula written out, the closed form of exp: R = I + sinθ/θ S + (1 - cosθ)/θ² S²
Eigen::Matrix3d rodrigues(const Eigen::Vector3d& rotvec) {
  const double theta = rotvec.norm();
  Eigen::Matrix3d S;
  S << 0, -rotvec.z(), rotvec.y(), rotvec.z(), 0, -rotvec.x(), -rotvec.y(), rotvec.x(), 0;
  return Eigen::Matrix3d::Identity() + std::sin(theta) / theta * S + (1 - std::cos(theta)) / (theta * theta) * S * S;
}

using rigiddyn::test::expect_invalid;

// ---------------------------------------------------------------- skew

TEST(Skew, HatIsTheCrossProductMatrix) {
  Random rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Vector3d v = rnd.vector(3), x = rnd.vector(3);
    EXPECT_LT((hat(v) * x - v.cross(x)).norm(), 1e-14);
    EXPECT_LT((hat(v) + hat(v).transpose()).norm(), 0.0 + 1e-300);
    EXPECT_EQ(vee(hat(v)), v);
  }
}

TEST(Skew, VeeIgnoresTheSymmetricPart) {
  const Eigen::Vector3d v(1, -2, 3);
  Eigen::Matrix3d symmetric;
  symmetric << 1, 2, 3, 2, 4, 5, 3, 5, 6;
  EXPECT_LT((vee(hat(v) + symmetric) - v).norm(), 1e-15);
}

// ---------------------------------------------------------------- quaternion ops

TEST(Quaternion, MultiplyComposesMatrices) {
  Random rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Quaterniond q1 = rnd.quaternion(), q2 = rnd.quaternion();
    EXPECT_LT((quat_to_matrix(quat_multiply(q1, q2)) - quat_to_matrix(q1) * quat_to_matrix(q2)).norm(), 1e-14);
    EXPECT_LT(rotation_distance(quat_multiply(q1, quat_inverse(q1)), Eigen::Quaterniond::Identity()), 1e-15);
  }
}

TEST(Quaternion, RotateEqualsMatrixTimesVector) {
  Random rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Quaterniond q = rnd.quaternion();
    const Eigen::Vector3d v = rnd.vector(5);
    EXPECT_LT((quat_rotate(q, v) - quat_to_matrix(q) * v).norm(), 1e-14);
  }
  // 90 degrees about z takes x to y (active rotation)
  const Eigen::Quaterniond qz(std::cos(kPi / 4), 0, 0, std::sin(kPi / 4));
  EXPECT_LT((quat_rotate(qz, Eigen::Vector3d::UnitX()) - Eigen::Vector3d::UnitY()).norm(), 1e-15);
}

TEST(Quaternion, CanonicalAndNormalize) {
  const Eigen::Quaterniond q(-0.5, 0.5, 0.5, 0.5);
  EXPECT_EQ(quat_canonical(q).coeffs(), (-q.coeffs()).eval());
  EXPECT_LT((quat_normalize(Eigen::Quaterniond(2, 0, 0, 0)).coeffs() - Eigen::Vector4d(0, 0, 0, 1)).norm(), 0.0 + 1e-300);
}

TEST(Quaternion, CheckedUnitQuaternionNormalisesWithinTolerance) {
  const Eigen::Quaterniond q(Eigen::Vector4d(0, 0, 0, 1 + 0.5e-6));  // (x, y, z, w)
  EXPECT_EQ(checked_unit_quaternion(q, "q").w(), 1.0);
}

// Every q / |q| that the library forms (normalise_quaternion, as the integrators' projection; checked_unit_quaternion;
// Eigen's normalized) is kept bit for bit by checked_attitude, so that a run restarted from a recorded state starts
// from the same bits; a quaternion farther from unit norm is normalised. Random directions at norms 1 ± 1e-7 and at
// scales from 2^-20 to 1 of each coefficient (small components: the sum's rounding differs).
TEST(Quaternion, CheckedAttitudeKeepsEveryNormalisedQuaternion) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> exponent(-20, 0);
  for (int trial = 0; trial < 200000; ++trial) {
    Eigen::Vector4d c;
    for (int i = 0; i < 4; ++i) c[i] = std::ldexp(normal(rng), exponent(rng));
    c *= (1.0 + 1e-7 * normal(rng)) / c.norm();
    Eigen::Vector4d projected = c;
    normalise_quaternion(projected.data());
    const Eigen::Quaterniond unit[3] = {Eigen::Quaterniond(projected), checked_unit_quaternion(Eigen::Quaterniond(c), "q"),
                                        Eigen::Quaterniond(c).normalized()};
    for (const Eigen::Quaterniond& q : unit) {
      ASSERT_EQ(checked_attitude(q, "q").coeffs(), q.coeffs()) << q.coeffs().transpose();
    }
    // |c| - 1 of order 1e-7: normalised, to unit norm within the 4 eps that keeps it
    const Eigen::Quaterniond normalised = checked_attitude(Eigen::Quaterniond(c), "q");
    ASSERT_LE(std::abs(normalised.norm() - 1.0), 4 * std::numeric_limits<double>::epsilon());
    ASSERT_EQ(normalised.coeffs(), unit[1].coeffs());
  }
  expect_invalid([] { checked_attitude(Eigen::Quaterniond(1 + 2e-6, 0, 0, 0), "q_WB"); }, "q_WB");
}

TEST(Quaternion, BadInputThrows) {
  expect_invalid([] { checked_unit_quaternion(Eigen::Quaterniond(0, 0, 0, 0), "q_WB"); }, "q_WB");
  expect_invalid([] { checked_unit_quaternion(Eigen::Quaterniond(1.1, 0, 0, 0), "q_WB"); }, "q_WB");
  expect_invalid([] { checked_unit_quaternion(Eigen::Quaterniond(1 + 2e-6, 0, 0, 0), "q"); }, "q");
  expect_invalid([] { checked_unit_quaternion(Eigen::Quaterniond(NAN, 0, 0, 0), "q"); }, "q");
  expect_invalid([] { checked_unit_quaternion(Eigen::Quaterniond(INFINITY, 0, 0, 0), "q"); }, "q");
  expect_invalid([] { quat_normalize(Eigen::Quaterniond(0, 0, 0, 0), "q"); }, "q");
  expect_invalid([] { quat_normalize(Eigen::Quaterniond(NAN, 1, 0, 0), "q"); }, "q");
}

// ---------------------------------------------------------------- matrices

TEST(Matrix, QuaternionRoundTripAndCanonicalSign) {
  Random rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Quaterniond q = rnd.quaternion();
    const Eigen::Matrix3d R = quat_to_matrix(q);
    EXPECT_LT((R - Eigen::AngleAxisd(q).toRotationMatrix()).norm(), 1e-14);
    const Eigen::Quaterniond back = matrix_to_quat(R);
    EXPECT_GE(back.w(), 0.0);
    EXPECT_LT(rotation_distance(back, q), 1e-14);
    EXPECT_EQ(checked_rotation_matrix(R, "R"), R);
  }
}

TEST(Matrix, HalfTurnsAreExact) {
  // rotations by pi about each axis: w = 0, vector part ±e_i
  for (int i = 0; i < 3; ++i) {
    Eigen::Matrix3d R = -Eigen::Matrix3d::Identity();
    R(i, i) = 1.0;
    const Eigen::Quaterniond q = matrix_to_quat(R);
    EXPECT_EQ(q.w(), 0.0);
    EXPECT_EQ(std::abs(q.vec()[i]), 1.0);
  }
}

TEST(Matrix, BadInputThrows) {
  Eigen::Matrix3d scaled = 1.01 * Eigen::Matrix3d::Identity();
  Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity();
  reflection(2, 2) = -1.0;
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 2) = NAN;
  Eigen::Matrix3d sheared = Eigen::Matrix3d::Identity();
  sheared(0, 1) = 1e-3;
  expect_invalid([&] { checked_rotation_matrix(scaled, "R_WB"); }, "R_WB");
  expect_invalid([&] { checked_rotation_matrix(reflection, "R_WB"); }, "R_WB");
  expect_invalid([&] { checked_rotation_matrix(nan, "R"); }, "R");
  expect_invalid([&] { checked_rotation_matrix(sheared, "R"); }, "R");
  expect_invalid([&] { checked_rotation_matrix(Eigen::Matrix3d::Zero(), "R"); }, "R");
}

// ---------------------------------------------------------------- exp / log

TEST(ExpLog, ExpMatchesAngleAxisAndRodrigues) {
  Random rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d axis = rnd.unit_vector();
    const double angle = rnd.uniform(1e-3, 3 * kPi);  // also beyond pi: exp is defined for every angle
    const Eigen::Vector3d rotvec = angle * axis;
    EXPECT_LT((rotvec_to_quat(rotvec).coeffs() - Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)).coeffs()).norm(), 1e-14);
    EXPECT_LT((rotvec_to_matrix(rotvec) - rodrigues(rotvec)).norm(), 1e-13);
  }
}

TEST(ExpLog, LogInvertsExpForAnglesUpToPi) {
  Random rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Vector3d rotvec = rnd.uniform(0.0, kPi) * rnd.unit_vector();
    EXPECT_LT((quat_to_rotvec(rotvec_to_quat(rotvec)) - rotvec).norm(), 1e-14);
    EXPECT_LT((matrix_to_rotvec(rotvec_to_matrix(rotvec)) - rotvec).norm(), 1e-14);
  }
}

TEST(ExpLog, TinyAnglesKeepFullRelativeAccuracy) {
  // exp(r) = (r/2 (1 - |r|²/24 + |r|⁴/1920), cos(|r|/2)) to O(|r|^6), exact in double at these sizes
  // (1e-300: |r| underflows to 0, the result must still be r/2, not 0/0)
  for (double scale : {1e-300, 1e-12, 1e-8, 1e-5, 0.9e-3, 1.1e-3}) {
    const Eigen::Vector3d r = scale * Eigen::Vector3d(0.3, -0.4, 1.2);
    const double t2 = r.squaredNorm();
    const Eigen::Quaterniond q = rotvec_to_quat(r);
    // relative: the series' first omitted term is |r|^6/322560 < eps at |r| <= 1.1e-3, and each side
    // rounds a product or two of r (<= 2 eps relative per component); the log only scales v
    EXPECT_LE((q.vec() - 0.5 * (1 - t2 / 24 + t2 * t2 / 1920) * r).norm(), 1e-15 * r.norm());
    EXPECT_LE((quat_to_rotvec(q) - r).norm(), 2e-16 * r.norm());
    // through the matrix the angle is limited by round-off of R ~ I: absolute, not relative
    EXPECT_LT((matrix_to_rotvec(rotvec_to_matrix(r)) - r).norm(), 1e-15);
  }
  EXPECT_EQ(rotvec_to_quat(Eigen::Vector3d::Zero()).coeffs(), Eigen::Vector4d(0, 0, 0, 1));
  EXPECT_EQ(quat_to_rotvec(Eigen::Quaterniond::Identity()), Eigen::Vector3d::Zero());
}

TEST(ExpLog, AnglesNearPi) {
  Random rnd;
  for (double gap : {0.0, 1e-12, 1e-9, 1e-6, 1e-3}) {
    for (int n = 0; n < 20; ++n) {
      const Eigen::Vector3d axis = rnd.unit_vector();
      const Eigen::Vector3d r = (kPi - gap) * axis;
      const Eigen::Matrix3d R = rodrigues(r);
      // the log is ±r (at exactly pi both are right), accurate to round-off
      const Eigen::Vector3d from_matrix = matrix_to_rotvec(R);
      const Eigen::Vector3d from_quat = quat_to_rotvec(rotvec_to_quat(r));
      const double sign = from_matrix.dot(r) >= 0 ? 1.0 : -1.0;
      const double sign_quat = from_quat.dot(r) >= 0 ? 1.0 : -1.0;
      // R's entries carry ~4 eps; Shepperd's quaternion reads the axis off the largest diagonal entry
      // (well conditioned at pi) and the angle by atan2: <= ~50 eps of pi through R, ~10 eps direct
      EXPECT_LT((from_matrix - sign * r).norm(), 1e-13) << "gap " << gap;
      EXPECT_LT((from_quat - sign_quat * r).norm(), 1e-14) << "gap " << gap;
      EXPECT_LE(from_matrix.norm(), kPi + 1e-15);
      if (gap > 0) {
        EXPECT_EQ(sign, 1.0) << "gap " << gap;
        EXPECT_EQ(sign_quat, 1.0) << "gap " << gap;
      }
    }
  }
  // just over pi the log wraps to the short way round
  const Eigen::Vector3d over = (kPi + 1e-6) * Eigen::Vector3d::UnitZ();
  EXPECT_LT((quat_to_rotvec(rotvec_to_quat(over)) - (1e-6 - kPi) * Eigen::Vector3d::UnitZ()).norm(), 1e-14);
}

// ---------------------------------------------------------------- axis-angle

TEST(AxisAngle, RoundTripAndClosedForm) {
  Random rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Vector3d axis = rnd.unit_vector();
    const double angle = rnd.uniform(1e-6, kPi);
    const Eigen::Quaterniond q = axis_angle_to_quat(3.5 * axis, angle);  // any length: normalised
    EXPECT_LT((q.coeffs() - Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis)).coeffs()).norm(), 1e-15);
    const AxisAngle back = quat_to_axis_angle(q);
    EXPECT_LT((back.axis - axis).norm(), 1e-9);  // the axis of a 1e-6 rotation is known to ~1e-10
    EXPECT_NEAR(back.angle, angle, 1e-15);
  }
  const AxisAngle identity = quat_to_axis_angle(Eigen::Quaterniond::Identity());
  EXPECT_EQ(identity.angle, 0.0);
  EXPECT_EQ(identity.axis, Eigen::Vector3d::UnitX());
  // negative angles come back as the positive angle about the opposite axis
  const AxisAngle negative = quat_to_axis_angle(axis_angle_to_quat(Eigen::Vector3d::UnitY(), -0.5));
  EXPECT_NEAR(negative.angle, 0.5, 1e-15);
  EXPECT_LT((negative.axis + Eigen::Vector3d::UnitY()).norm(), 1e-15);
}

TEST(AxisAngle, BadInputThrows) {
  expect_invalid([] { axis_angle_to_quat(Eigen::Vector3d::Zero(), 1.0); }, "axis");
  expect_invalid([] { axis_angle_to_quat(Eigen::Vector3d(NAN, 0, 1), 1.0); }, "axis");
  expect_invalid([] { axis_angle_to_quat(Eigen::Vector3d::UnitZ(), INFINITY); }, "angle");
}

// ---------------------------------------------------------------- elementary rotations

TEST(Elementary, MatchAngleAxisAndQuaternion) {
  Random rnd;
  for (int n = 0; n < 50; ++n) {
    const double a = rnd.uniform(-4, 4);
    EXPECT_LT((rot_x(a) - Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix()).norm(), 1e-15);
    EXPECT_LT((rot_y(a) - Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix()).norm(), 1e-15);
    EXPECT_LT((rot_z(a) - Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix()).norm(), 1e-15);
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Matrix3d R = axis == 0 ? rot_x(a) : axis == 1 ? rot_y(a) : rot_z(a);
      EXPECT_LT((quat_to_matrix(elementary_quat(axis, a)) - R).norm(), 1e-15);
    }
  }
  // active: a quarter turn about z takes x to y, about x takes y to z, about y takes z to x
  EXPECT_LT((rot_z(kPi / 2) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  EXPECT_LT((rot_x(kPi / 2) * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_LT((rot_y(kPi / 2) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 1e-15);
}

// ---------------------------------------------------------------- Euler angles

const std::vector<std::string> all_sequences = {
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};

Eigen::Matrix3d elementary(int axis, double angle) {
  return axis == 0 ? rot_x(angle) : axis == 1 ? rot_y(angle) : rot_z(angle);
}

// the definition: extrinsic R_c(θ3) R_b(θ2) R_a(θ1); intrinsic R_A(θ1) R_B(θ2) R_C(θ3)
Eigen::Matrix3d euler_definition(const std::string& seq, const Eigen::Vector3d& angles) {
  const bool intrinsic = std::isupper(static_cast<unsigned char>(seq[0]));
  Eigen::Matrix3d R[3];
  for (int n = 0; n < 3; ++n) R[n] = elementary(std::tolower(static_cast<unsigned char>(seq[n])) - 'x', angles[n]);
  return intrinsic ? (R[0] * R[1] * R[2]).eval() : (R[2] * R[1] * R[0]).eval();
}

bool is_proper(const std::string& seq) { return std::tolower(seq[0]) == std::tolower(seq[2]); }

TEST(Euler, ForwardMatchesTheDefinitionForAll24Kinds) {
  Random rnd;
  for (const std::string& seq : all_sequences) {
    for (int n = 0; n < 50; ++n) {
      const Eigen::Vector3d angles = rnd.vector(4.0);
      EXPECT_LT((euler_to_matrix(seq, angles) - euler_definition(seq, angles)).norm(), 1e-14) << seq;
      EXPECT_LT((quat_to_matrix(euler_to_quat(seq, angles)) - euler_definition(seq, angles)).norm(), 1e-14) << seq;
    }
  }
}

TEST(Euler, InverseRecoversAnglesInTheirRanges) {
  Random rnd;
  for (const std::string& seq : all_sequences) {
    const bool proper = is_proper(seq);
    for (int n = 0; n < 100; ++n) {
      const Eigen::Vector3d angles(rnd.uniform(-kPi, kPi), proper ? rnd.uniform(1e-3, kPi - 1e-3) : rnd.uniform(-kPi / 2 + 1e-3, kPi / 2 - 1e-3),
                                   rnd.uniform(-kPi, kPi));
      EXPECT_LT((quat_to_euler(seq, euler_to_quat(seq, angles)) - angles).norm(), 1e-12) << seq;
      EXPECT_LT((matrix_to_euler(seq, euler_definition(seq, angles)) - angles).norm(), 1e-12) << seq;
    }
    // any rotation: angles in range, and they reproduce it
    for (int n = 0; n < 100; ++n) {
      const Eigen::Quaterniond q = rnd.quaternion();
      const Eigen::Vector3d e = quat_to_euler(seq, q);
      EXPECT_LE(std::abs(e[0]), kPi) << seq;
      EXPECT_LE(std::abs(e[2]), kPi) << seq;
      if (proper) {
        EXPECT_GE(e[1], 0.0) << seq;
        EXPECT_LE(e[1], kPi) << seq;
      } else {
        EXPECT_LE(std::abs(e[1]), kPi / 2) << seq;
      }
      EXPECT_LT((euler_definition(seq, e) - quat_to_matrix(q)).norm(), 1e-13) << seq;
    }
  }
}

TEST(Euler, GimbalLockSetsTheThirdAngleToZero) {
  Random rnd;
  for (const std::string& seq : all_sequences) {
    const bool proper = is_proper(seq);
    for (double middle : proper ? std::vector<double>{0.0, kPi} : std::vector<double>{-kPi / 2, kPi / 2}) {
      for (double offset : {0.0, 1e-15}) {  // exactly at the lock, and within its round-off tolerance
        for (int n = 0; n < 20; ++n) {
          const Eigen::Vector3d angles(rnd.uniform(-3, 3), middle + (middle > 0 ? -offset : offset), rnd.uniform(-3, 3));
          const Eigen::Matrix3d R = euler_definition(seq, angles);
          const Eigen::Vector3d e = matrix_to_euler(seq, R);
          EXPECT_EQ(e[2], 0.0) << seq;
          EXPECT_NEAR(e[1], middle, 1e-7) << seq;  // θ2 is known to ~1e-8 at the lock (sqrt of round-off)
          EXPECT_LT((euler_definition(seq, e) - R).norm(), 1e-13) << seq;
          EXPECT_LT((euler_definition(seq, quat_to_euler(seq, euler_to_quat(seq, angles))) - R).norm(), 1e-13) << seq;
        }
      }
    }
  }
}

TEST(Euler, NearGimbalLockStillReproducesTheRotation) {
  Random rnd;
  for (const std::string& seq : all_sequences) {
    const double lock = is_proper(seq) ? 0.0 : kPi / 2;
    for (double gap : {1e-14, 1e-13, 1e-12, 1e-10, 1e-8, 1e-6, 1e-3}) {
      const Eigen::Vector3d angles(rnd.uniform(-3, 3), lock - gap, rnd.uniform(-3, 3));
      const Eigen::Quaterniond q = euler_to_quat(seq, angles);
      // within the 1e-13 snapping tolerance the third angle is set to 0: the rotation moves by ~2 gap
      EXPECT_LT((euler_definition(seq, quat_to_euler(seq, q)) - quat_to_matrix(q)).norm(), 1e-12) << seq;
    }
  }
}

TEST(Euler, UnknownSequencesThrow) {
  for (const char* bad : {"", "xy", "xyzx", "xxy", "xyy", "xYz", "abc", "xyw", "XyZ", "x y"}) {
    expect_invalid([&] { EulerSequence s(bad); }, "seq");
  }
  expect_invalid([] { EulerSequence s("zzz", "sequence"); }, "sequence");
  const EulerSequence s("ZYX");
  EXPECT_TRUE(s.intrinsic);
  EXPECT_EQ(s.axes, (std::array<int, 3>{2, 1, 0}));
}

// ---------------------------------------------------------------- integration

TEST(Integrate, ConstantRateIsTheClosedFormRotation) {
  Random rnd;
  for (int n = 0; n < 50; ++n) {
    const Eigen::Quaterniond q0 = rnd.quaternion();
    const Eigen::Vector3d axis = rnd.unit_vector();
    const double rate = rnd.uniform(-10, 10), dt = rnd.uniform(0, 2);
    // body frame: q(t) = q0 ⊗ AngleAxis(rate t, axis_B); world frame: AngleAxis(rate t, axis_W) ⊗ q0
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(rate * dt, axis));
    // angles up to 20 rad, known to ~eps relative on each side (|rate axis| dt vs rate dt): 2 x 20 eps
    // = 8.9e-15 in the angle between the two
    EXPECT_LT(rotation_distance(quat_integrate(q0, rate * axis, dt, Frame::body), q0 * turn), 1e-14);
    EXPECT_LT(rotation_distance(quat_integrate(q0, rate * axis, dt, Frame::world), turn * q0), 1e-14);
    // the same motion: w_W = R(q) w_B (constant in both frames for a rotation about a fixed axis)
    EXPECT_LT(rotation_distance(quat_integrate(q0, q0 * (rate * axis), dt, Frame::world),
                                quat_integrate(q0, rate * axis, dt, Frame::body)), 1e-14);
    // two half steps are one step
    const Eigen::Quaterniond half = quat_integrate(q0, rate * axis, dt / 2, Frame::body);
    EXPECT_LT(rotation_distance(quat_integrate(half, rate * axis, dt / 2, Frame::body),
                                quat_integrate(q0, rate * axis, dt, Frame::body)), 1e-14);
  }
}

TEST(Integrate, SatisfiesTheKinematicEquation) {
  // q' = 1/2 q ⊗ (w_B, 0): central difference of the exact update at t = 0
  const Eigen::Quaterniond q0 = Random().quaternion();
  const Eigen::Vector3d w_B(0.3, -1.2, 2.0);
  const double h = 1e-5;
  const Eigen::Vector4d derivative =
      (quat_integrate(q0, w_B, h, Frame::body).coeffs() - quat_integrate(q0, w_B, -h, Frame::body).coeffs()) / (2 * h);
  const Eigen::Quaterniond w_pure(0.0, w_B.x(), w_B.y(), w_B.z());
  // central difference: truncation h^2/6 |d3q/dt3| <= 1.7e-11 |w|^3/8 (|w| = 2.4) plus round-off eps/h = 2e-11
  EXPECT_LT((derivative - 0.5 * (q0 * w_pure).coeffs()).norm(), 1e-9);
}

TEST(Integrate, BadInputThrows) {
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  expect_invalid([&] { quat_integrate(q, Eigen::Vector3d(NAN, 0, 0), 0.1, Frame::body); }, "w");
  expect_invalid([&] { quat_integrate(q, Eigen::Vector3d::UnitX(), INFINITY, Frame::world); }, "dt");
}

}  // namespace
}  // namespace rigiddyn
