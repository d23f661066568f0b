// Tests of the SciPy-parity rotation operations in C++: the nearest rotation and the acceptance
// of nearly orthonormal matrices, Markley's matrix-to-quaternion branches, the canonical sign,
// slerp, the angular distance at its delicate angles and Wahba's problem (closed forms and
// properties; the comparisons with SciPy are in tests/python/test_so3_ops.py).
#include <gtest/gtest.h>

#include "test_numbers.hpp"
#include "rigiddyn/so3/align_vectors.hpp"
#include "rigiddyn/so3/angular_distance.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/nearest_rotation.hpp"
#include "rigiddyn/so3/quaternion.hpp"
#include "rigiddyn/so3/quaternion_kernels.hpp"
#include "rigiddyn/so3/slerp.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace rigiddyn {
namespace {

using rigiddyn::test::kPi;
using rigiddyn::test::kEps;

// deterministic random inputs
struct GaussianRandom {
  std::mt19937_64 engine{20261124};
  double normal() { return std::normal_distribution<double>()(engine); }
  Eigen::Quaterniond quaternion() { return Eigen::Quaterniond(Eigen::Vector4d(normal(), normal(), normal(), normal()).normalized()); }
  Eigen::Vector3d vector() { return Eigen::Vector3d(normal(), normal(), normal()); }
};

template <typename F>
void expect_invalid_prefix(F f, const std::string& prefix) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected one starting with " << prefix;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

// entries rounded to `digits` decimals
Eigen::Matrix3d rounded(const Eigen::Matrix3d& R, int digits) {
  const double scale = std::pow(10.0, digits);
  return (R * scale).array().round().matrix() / scale;
}

// ---------------------------------------------------------------- nearest rotation

// The scene model's kinematics normalise attitudes with unit_quaternion instead of Eigen's normalisation; a run's bits
// must not depend on which: every quaternion (of any norm, as RK4's stages leave them) gives Eigen's bits.
TEST(UnitQuaternion, GivesTheBitsOfEigensNormalisation) {
  std::mt19937_64 generator(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(-3.0, 3.0);
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::pow(10.0, exponent(generator));
    const double q[4] = {scale * normal(generator), scale * normal(generator), scale * normal(generator), scale * normal(generator)};
    Eigen::Quaterniond eigen(q[3], q[0], q[1], q[2]);
    eigen.coeffs() *= 1.0 / eigen.coeffs().norm();
    const Eigen::Quaterniond unit = unit_quaternion(q);
    for (int k = 0; k < 4; ++k) ASSERT_EQ(unit.coeffs()[k], eigen.coeffs()[k]) << "q = " << q[0] << ", " << q[1] << ", " << q[2] << ", " << q[3];
  }
}

TEST(NearestRotation, IsAnOrthonormalProperMatrixAndIdempotent) {
  GaussianRandom rnd;
  for (int n = 0; n < 200; ++n) {
    // the noise drawn entry by entry: a NullaryExpr of the drawing lambda hung in GCC 12's -O3 build of this test in
    // some unity batches (the engine's draws rejected forever in normal_distribution's polar loop)
    const Eigen::Matrix3d rotation = quat_to_matrix(rnd.quaternion());
    Eigen::Matrix3d noise;
    for (Eigen::Index k = 0; k < noise.size(); ++k) noise(k) = rnd.normal();
    const Eigen::Matrix3d M = rotation + 0.1 * noise;
    const Eigen::Matrix3d R = nearest_rotation(M);
    // Jacobi SVD is backward stable: U and V are products of plane rotations, each of which moves their
    // orthonormality by at most 3 eps per entry (c x + s y: two products and a sum); two-sided Jacobi converges
    // quadratically (Golub & Van Loan, Matrix Computations, §8.6.3), in at most 4 sweeps of 3 rotations for these
    // well-conditioned M = R + 0.1 N, so |U^T U - I|, |V^T V - I| <= 36 eps, and
    // U D V^T adds 6 eps per entry: |R^T R - I| and |det R - 1| <= 2 * 36 + 2 * 6 < 96 eps. (Eigen applies each
    // rotation with a vector or a scalar loop depending on the matrices' addresses, so the rounding, not the
    // bound, varies from one process to the next.)
    EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 96 * kEps);
    EXPECT_NEAR(R.determinant(), 1.0, 96 * kEps);
    // a second projection moves R only by round-off (the polar factor of R + E, |E| <= 96 eps,
    // is R + O(|E|) since all singular values are 1)
    EXPECT_LT((nearest_rotation(R) - R).cwiseAbs().maxCoeff(), 192 * kEps);
    // optimality: no random rotation near R is closer to M in the Frobenius norm
    for (int k = 0; k < 5; ++k) {
      const Eigen::Matrix3d other = R * Eigen::AngleAxisd(0.01, rnd.vector().normalized()).toRotationMatrix();
      EXPECT_LE((M - R).norm(), (M - other).norm());
    }
  }
}

TEST(NearestRotation, ReflectionFlipsTheSmallestSingularDirection) {
  // M = diag(3, 2, -1): the orthogonal factor diag(1, 1, -1) is a reflection; flipping the direction
  // of the smallest singular value (1) gives I, |M - I|_F^2 = 4 + 1 + 4 = 9, while flipping another
  // (e.g. diag(1, -1, -1)) costs 4 + 9 + 0 = 13
  const Eigen::Matrix3d M = Eigen::Vector3d(3.0, 2.0, -1.0).asDiagonal();
  EXPECT_LT((nearest_rotation(M) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 4 * kEps);
  expect_invalid_prefix([] { nearest_rotation(Eigen::Matrix3d::Constant(NAN)); }, "M: expected finite values");
}

TEST(ProjectedRotationMatrix, KeepsScipyOrthonormalMatricesAndProjectsRoundedOnes) {
  GaussianRandom rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Matrix3d R = quat_to_matrix(rnd.quaternion());
    // within numpy.isclose(M M^T, I, atol=1e-12) (rtol 1e-5 on the diagonal): kept bit for bit
    const Eigen::Matrix3d scaled_row = Eigen::Vector3d(1.0 + 1e-6, 1.0, 1.0).asDiagonal() * R;
    EXPECT_TRUE(orthonormal_as_scipy(scaled_row));
    EXPECT_EQ(projected_rotation_matrix(scaled_row, "R"), scaled_row);
    // rounded to 3 decimals: off-diagonal (M M^T)_ij ~ 1e-3 > 1e-12, so projected
    const Eigen::Matrix3d M = rounded(R, 3);
    EXPECT_FALSE(orthonormal_as_scipy(M));
    const Eigen::Matrix3d P = projected_rotation_matrix(M, "R");
    EXPECT_LT((P - nearest_rotation(M)).cwiseAbs().maxCoeff(), 0.0 + 1e-300);  // the same computation
    // rounding errs by <= 5e-4 per entry, so |M - R|_2 <= 3 * 5e-4 and the projection, a
    // nearest point, lies within twice that of R
    EXPECT_LT((P - R).norm(), 2 * 3 * 5e-4 * std::sqrt(3.0));
  }
}

TEST(ProjectedRotationMatrix, RefusesReflectionsSingularAndFarMatrices) {
  expect_invalid_prefix([] { projected_rotation_matrix(Eigen::Vector3d(1, 1, -1).asDiagonal(), "R_WB"); },
                 "R_WB: expected a rotation matrix (det > 0");
  expect_invalid_prefix([] { projected_rotation_matrix(Eigen::Matrix3d::Zero(), "R"); }, "R: expected a rotation matrix (det > 0");
  expect_invalid_prefix([] { projected_rotation_matrix(1.1 * Eigen::Matrix3d::Identity(), "R"); },
                 "R: expected a rotation matrix (orthonormal up to rounding");
  expect_invalid_prefix([] { projected_rotation_matrix(Eigen::Matrix3d::Constant(INFINITY), "R"); }, "R: expected a rotation matrix of finite");
  // the limit itself: singular values 1.049 accepted, 1.051 refused
  EXPECT_NO_THROW(projected_rotation_matrix(1.049 * Eigen::Matrix3d::Identity(), "R"));
  expect_invalid_prefix([] { projected_rotation_matrix(1.051 * Eigen::Matrix3d::Identity(), "R"); }, "R: expected");
}

// ---------------------------------------------------------------- matrix -> quaternion

TEST(MatrixToQuat, EveryMarkleyBranchRoundTrips) {
  // rotations by large angles about each axis pick the branch of that axis, small ones the trace
  GaussianRandom rnd;
  for (int n = 0; n < 400; ++n) {
    const Eigen::Quaterniond q = rnd.quaternion();
    const Eigen::Quaterniond back = matrix_to_quat(quat_to_matrix(q));
    EXPECT_GE(back.w(), 0.0);
    // <= ~20 roundings on unit numbers per side, divided by the largest |component| >= 1/2
    EXPECT_LT(angular_distance(back, q), 64 * kEps);
  }
  for (int i = 0; i < 3; ++i) {
    for (double angle : {kPi, kPi - 1e-9, 2.5, 1e-9}) {
      const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(i)));
      EXPECT_LT(angular_distance(matrix_to_quat(q.toRotationMatrix()), q), 64 * kEps) << i << " " << angle;
    }
  }
}

// ---------------------------------------------------------------- canonical sign

TEST(QuatCanonical, TiesAsScipy) {
  const auto canonical = [](double x, double y, double z, double w) {
    return quat_canonical(Eigen::Quaterniond(w, x, y, z)).coeffs();
  };
  EXPECT_EQ(canonical(0.6, 0.0, 0.0, -0.8), Eigen::Vector4d(-0.6, 0.0, 0.0, 0.8));
  EXPECT_EQ(canonical(-1.0, 0.0, 0.0, 0.0), Eigen::Vector4d(1.0, 0.0, 0.0, 0.0));
  EXPECT_EQ(canonical(0.0, -1.0, 0.0, 0.0), Eigen::Vector4d(0.0, 1.0, 0.0, 0.0));
  EXPECT_EQ(canonical(0.0, 0.0, -1.0, 0.0), Eigen::Vector4d(0.0, 0.0, 1.0, 0.0));
  EXPECT_EQ(canonical(0.6, -0.8, 0.0, 0.0), Eigen::Vector4d(0.6, -0.8, 0.0, 0.0));
  EXPECT_EQ(canonical(-0.0, -0.6, 0.8, -0.0), Eigen::Vector4d(0.0, 0.6, -0.8, 0.0));  // -0.0 counts as 0
}

// ---------------------------------------------------------------- slerp

TEST(Slerp, EndpointsAndConstantRate) {
  GaussianRandom rnd;
  for (int n = 0; n < 200; ++n) {
    const Eigen::Quaterniond q0 = rnd.quaternion(), q1 = rnd.quaternion();
    EXPECT_EQ(slerp(q0, q1, 0.0).coeffs(), q0.coeffs());  // exp(0) = 1 exactly, q0 * 1 = q0
    EXPECT_LT(angular_distance(slerp(q0, q1, 1.0), q1), 64 * kEps);
    const double total = angular_distance(q0, q1);
    for (double t : {0.1, 0.25, 0.5, 0.9}) {
      // log, scale, exp and product: a few tens of roundings on unit numbers, 64 eps
      EXPECT_NEAR(angular_distance(q0, slerp(q0, q1, t)), t * total, 64 * kEps);
      EXPECT_NEAR(angular_distance(slerp(q0, q1, t), q1), (1 - t) * total, 64 * kEps);
    }
  }
}

TEST(KeyedSlerp, InterpolatesSegmentsAndRefusesBadTimes) {
  GaussianRandom rnd;
  const std::vector<Eigen::Quaterniond> q{rnd.quaternion(), rnd.quaternion(), rnd.quaternion()};
  const KeyedSlerp interpolate({0.0, 1.0, 3.0}, q);
  EXPECT_LT(angular_distance(interpolate(2.0), slerp(q[1], q[2], 0.5)), 64 * kEps);
  EXPECT_LT(angular_distance(interpolate(1.0), q[1]), 64 * kEps);
  EXPECT_EQ(interpolate(0.0).coeffs(), q[0].coeffs());
  expect_invalid_prefix([&] { interpolate(3.5); }, "t: expected times within the key times [0, 3]");
  expect_invalid_prefix([&] { KeyedSlerp({0.0, 0.0, 1.0}, q); }, "times: expected strictly increasing");
  expect_invalid_prefix([&] { KeyedSlerp({0.0, 1.0}, q); }, "q: expected 2 key rotations");
  expect_invalid_prefix([&] { KeyedSlerp({0.0}, {q[0]}); }, "times: expected at least 2");
}

// ---------------------------------------------------------------- angular distance

TEST(AngularDistance, AccurateAtTinyAnglesAndNearPi) {
  GaussianRandom rnd;
  for (double angle : {1e-12, 1e-9, 1e-5, 1.0, kPi - 1e-9, kPi}) {
    for (int n = 0; n < 50; ++n) {
      const Eigen::Quaterniond q_a = rnd.quaternion();
      const Eigen::Quaterniond q_b = q_a * Eigen::Quaterniond(Eigen::AngleAxisd(angle, rnd.vector().normalized()));
      // absolute error: q_b's rounding and the product err by a few eps per component, and
      // angle = 2 atan2(|d_xyz|, |d_w|) doubles it: 32 eps. An acos(|d_w|) form would err by
      // sqrt(eps) ~ 1e-8 at tiny angles.
      EXPECT_NEAR(angular_distance(q_a, q_b), angle, 32 * kEps) << angle;
      EXPECT_NEAR(angular_distance(q_b, q_a), angle, 32 * kEps) << angle;
      EXPECT_LT(angular_distance(q_a, Eigen::Quaterniond(-q_a.coeffs())), 8 * kEps);
    }
  }
}

TEST(AngularDistance, SmallAngleSeriesMatchesAtan2) {
  // below |d_xyz| = 2^-9 |d_w| the series: within 2 ulps of 2 atan2(|d_xyz|, |d_w|) (the series' remainder is below
  // 2^-57 relative; its three roundings and atan2's own make up the rest), on both sides of the switch
  GaussianRandom rnd;
  for (double angle : {1e-300, 1e-12, 1e-6, 1e-3, 0.9 * 0x1p-8, 1.1 * 0x1p-8}) {
    for (int n = 0; n < 50; ++n) {
      const Eigen::Quaterniond q_a = rnd.quaternion();
      const Eigen::Quaterniond q_b = q_a * Eigen::Quaterniond(Eigen::AngleAxisd(angle, rnd.vector().normalized()));
      const Eigen::Quaterniond d = q_a.conjugate() * q_b;
      const double by_atan2 = 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
      EXPECT_NEAR(angular_distance(q_a, q_b), by_atan2, 4.0 * kEps * by_atan2) << angle;
    }
  }
}

// ---------------------------------------------------------------- Wahba's problem

TEST(AlignVectors, RecoversAnExactRotation) {
  GaussianRandom rnd;
  for (int n = 0; n < 100; ++n) {
    const Eigen::Quaterniond q = rnd.quaternion();
    Vectors3 b(5, 3), a(5, 3);
    for (int i = 0; i < 5; ++i) {
      b.row(i) = rnd.vector().transpose();
      a.row(i) = (q * Eigen::Vector3d(b.row(i).transpose())).transpose();
    }
    const VectorAlignment r = align_vectors(a, b, Eigen::VectorXd::Ones(5));
    EXPECT_TRUE(r.unique);
    // polar factor of B = R (sum b b^T) + E: error <= 2 |E| / (s2 + s3), E ~ 5 N eps |b|^2; random
    // Gaussian vectors keep s2 + s3 ~ |b|^2: 1e-13 leaves a margin of > 10
    EXPECT_LT(angular_distance(r.q, q), 1e-13);
    EXPECT_LT(r.rssd, 1e-13);
  }
}

TEST(AlignVectors, SpecialCasesAsScipy) {
  // one pair: the shortest arc; antiparallel about e_i x a (i of the smallest |a_i|: here y)
  Vectors3 a(1, 3), b(1, 3);
  a << 1.0, 0.0, 0.0;
  b << -2.0, 0.0, 0.0;
  VectorAlignment r = align_vectors(a, b, Eigen::VectorXd::Ones(1));
  // e_y x e_x = -e_z: q = (0, 0, -1, cos(pi / 2)), w = 6e-17 > 0 so already canonical (SciPy
  // gives the same (0, 0, -1, 6.1e-17)); sin and cos of pi / 2 err by <= 1 ulp
  EXPECT_LT((r.q.coeffs() - Eigen::Vector4d(0.0, 0.0, -1.0, 0.0)).norm(), 4 * kEps);
  EXPECT_NEAR(r.rssd, 1.0, 4 * kEps);  // | |a| - |b| | with weight 1
  EXPECT_TRUE(std::isnan(r.sensitivity(0, 0)));
  // one infinite weight: the primary pair exactly, the others by a turn about a_0
  GaussianRandom rnd;
  for (int n = 0; n < 100; ++n) {
    Vectors3 a3(3, 3), b3(3, 3);
    for (int i = 0; i < 3; ++i) {
      a3.row(i) = rnd.vector().transpose();
      b3.row(i) = rnd.vector().transpose();
    }
    const VectorAlignment s = align_vectors(a3, b3, Eigen::Vector3d(std::numeric_limits<double>::infinity(), 1.0, 2.0));
    const Eigen::Vector3d c = s.q * Eigen::Vector3d(b3.row(0).transpose()).normalized();
    // the shortest arc's axis b x a / |b x a| errs by eps / |b x a| relative: bound it per case
    const double sin_angle = Eigen::Vector3d(b3.row(0).normalized()).cross(Eigen::Vector3d(a3.row(0).normalized())).norm();
    EXPECT_LT((c - a3.row(0).normalized().transpose()).norm(), 16 * kEps / sin_angle);
    // the turn about a_0 is optimal: small extra turns about a_0 do not lower the loss
    const auto loss = [&](const Eigen::Quaterniond& q) {
      return 1.0 * (a3.row(1).transpose() - q * Eigen::Vector3d(b3.row(1).transpose())).squaredNorm() +
             2.0 * (a3.row(2).transpose() - q * Eigen::Vector3d(b3.row(2).transpose())).squaredNorm();
    };
    const Eigen::Vector3d axis = a3.row(0).normalized().transpose();
    EXPECT_NEAR(std::sqrt(loss(s.q)), s.rssd, 1e-12 * (1.0 + s.rssd));
    for (double turn : {-1e-3, 1e-3}) EXPECT_LE(loss(s.q), loss(Eigen::Quaterniond(Eigen::AngleAxisd(turn, axis)) * s.q));
  }
}

TEST(AlignVectors, BadInputThrows) {
  Vectors3 a = Vectors3::Ones(2, 3), b = Vectors3::Ones(2, 3);
  const double inf = std::numeric_limits<double>::infinity();
  expect_invalid_prefix([&] { align_vectors(a, b, Eigen::Vector2d(-1.0, 1.0)); }, "weights: expected weights >= 0");
  expect_invalid_prefix([&] { align_vectors(a, b, Eigen::Vector2d(NAN, 1.0)); }, "weights: expected weights >= 0");
  expect_invalid_prefix([&] { align_vectors(a, b, Eigen::Vector2d(inf, inf)); }, "weights: expected at most one infinite");
  expect_invalid_prefix([&] { align_vectors(a, b, Eigen::Vector3d(1.0, 1.0, 1.0)); }, "weights: expected 2 weights");
  expect_invalid_prefix([&] { align_vectors(a, Vectors3::Ones(3, 3), Eigen::Vector2d(1.0, 1.0)); }, "b: expected 2 vectors");
  expect_invalid_prefix([&] { align_vectors(Vectors3(0, 3), Vectors3(0, 3), Eigen::VectorXd(0)); }, "a: expected at least one");
  expect_invalid_prefix([&] { align_vectors(Vectors3::Zero(1, 3), Vectors3::Ones(1, 3), Eigen::VectorXd::Ones(1)); },
                 "a: expected a non-zero primary vector");
}

TEST(AlignVectors, ParallelPairsAreFlaggedNotUnique) {
  Vectors3 a(2, 3), b(2, 3);
  a << 1.0, 0.0, 0.0, 2.0, 0.0, 0.0;
  b << 0.0, 1.0, 0.0, 0.0, 2.0, 0.0;
  const VectorAlignment r = align_vectors(a, b, Eigen::Vector2d(1.0, 1.0));
  EXPECT_FALSE(r.unique);
  EXPECT_LT(r.rssd, 1e-14);  // still a rotation taking b onto a: the y axis to the x axis
}

}  // namespace
}  // namespace rigiddyn
