// SpatialInertia: 6x6 form, momentum, energy, angular momentum, parallel axis, re-expression,
// principal axes, symmetry planes, composites, validity (report, tolerance, repair, opt-in).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>

#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"
#include "rigiddyn/inertia/validity.hpp"
#include "rigiddyn/so3/skew.hpp"

using namespace rigiddyn;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

std::mt19937 rng(7);

Matrix3d random_rotation() {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}
Vector3d random_vector(double s = 1.0) {
  std::uniform_real_distribution<double> u(-s, s);
  return Vector3d(u(rng), u(rng), u(rng));
}
// Tolerances in this file (Eigen's isApprox: |a - b| <= prec min(|a|, |b|)): one formula is a fixed
// sequence of <= ~30 roundings on the random bodies' numbers (mass, sizes <= 2, |com| <= 3.5), so
// it errs by ~30 eps of the largest term: 1e-14 where no term exceeds the result, 1e-12 where
// parallel-axis terms m |c|^2 (<= 25) meet inertias >= 2e-3 (ratio <= 1e4 x eps); larger figures
// are explained where they are asserted.
// A random valid body: a box of random size and mass, rotated and placed.
SpatialInertia random_body() {
  std::uniform_real_distribution<double> u(0.1, 2.0);
  return solid_box(Vector3d(u(rng), u(rng), u(rng)), Mass{u(rng)})
      .transformed(Transform(random_rotation(), random_vector(2.0)));
}

}  // namespace

TEST(SpatialInertia, MatrixMatchesFeatherstoneForm) {
  const SpatialInertia I = random_body();
  const Matrix3d c_hat = hat(I.com());
  Matrix6d expected;
  expected << I.inertia_com() - I.mass() * c_hat * c_hat, I.mass() * c_hat, -I.mass() * c_hat,
      I.mass() * Matrix3d::Identity();
  EXPECT_TRUE(I.matrix().isApprox(expected, 1e-13));
  EXPECT_TRUE(SpatialInertia::from_matrix(I.matrix()).is_approx(I, 1e-12));
  EXPECT_TRUE(I.matrix().isApprox(I.matrix().transpose(), 1e-14));
}

TEST(SpatialInertia, MomentumEnergyAndAngularMomentum) {
  for (int trial = 0; trial < 20; ++trial) {
    const SpatialInertia I = random_body();
    const Motion V(random_vector(), random_vector());
    const Force h = I.momentum(V);
    EXPECT_TRUE(h.to_vector().isApprox(I.matrix() * V.to_vector(), 1e-12));
    EXPECT_NEAR(I.kinetic_energy(V), 0.5 * V.to_vector().dot(I.matrix() * V.to_vector()), 1e-12);
    // T = 1/2 m v_C^2 + 1/2 w.I_C w with v_C = v_O + w x c (Craig)
    const Vector3d v_C = V.linear + V.angular.cross(I.com());
    EXPECT_NEAR(I.kinetic_energy(V), 0.5 * I.mass() * v_C.squaredNorm() + 0.5 * V.angular.dot(I.inertia_com() * V.angular),
                1e-12);
    // H_O from the spatial momentum equals H_P at P = origin (Craig), and L = m v_C
    EXPECT_TRUE(h.angular.isApprox(I.angular_momentum_about_point(V.angular, v_C, Vector3d::Zero()), 1e-12));
    EXPECT_TRUE(h.linear.isApprox(I.mass() * v_C, 1e-12));
    // H_P at another point equals the moment of the momentum moved to P
    const Vector3d p = random_vector();
    const Vector3d H_P = h.angular - p.cross(h.linear);
    EXPECT_TRUE(H_P.isApprox(I.angular_momentum_about_point(V.angular, v_C, p), 1e-12));
    EXPECT_TRUE(I.angular_momentum_about_com(V.angular).isApprox(I.inertia_com() * V.angular));
  }
}

TEST(SpatialInertia, ParallelAxisBothDirections) {
  const SpatialInertia I = random_body();
  const Vector3d p = random_vector(3.0);
  const Vector3d r = I.com() - p;
  // Craig [I]_2 = [I]_C + m [[b^2+c^2, -ab, -ac], ...] with (a, b, c) = r
  Matrix3d shift;
  shift << r.y() * r.y() + r.z() * r.z(), -r.x() * r.y(), -r.x() * r.z(), -r.x() * r.y(), r.x() * r.x() + r.z() * r.z(),
      -r.y() * r.z(), -r.x() * r.z(), -r.y() * r.z(), r.x() * r.x() + r.y() * r.y();
  EXPECT_TRUE(I.inertia_about_point(p).isApprox(I.inertia_com() + I.mass() * shift, 1e-13));
  const SpatialInertia back = SpatialInertia::from_inertia_about_point(I.mass(), I.com(), I.inertia_about_point(p), p);
  EXPECT_TRUE(back.is_approx(I, 1e-12));
  EXPECT_TRUE(SpatialInertia::from_inertia_about_origin(I.mass(), I.com(), I.inertia_about_origin()).is_approx(I, 1e-12));
}

TEST(SpatialInertia, TransformMatchesDenseSpatialTransform) {
  const SpatialInertia I_B = random_body();
  const Transform X_AB(random_rotation(), random_vector());
  const SpatialInertia I_A = I_B.transformed(X_AB);
  // I_A = X* I_B X^-1 (Featherstone 2.66): force_matrix * I * motion_matrix(inverse)
  const Matrix6d expected = X_AB.force_matrix() * I_B.matrix() * X_AB.inverse().motion_matrix();
  EXPECT_TRUE(I_A.matrix().isApprox(expected, 1e-12));
  EXPECT_TRUE(I_A.transformed(X_AB.inverse()).is_approx(I_B, 1e-12));
  const SpatialInertia rot = I_B.rotated(X_AB.rotation());
  EXPECT_TRUE(rot.inertia_com().isApprox(X_AB.rotation() * I_B.inertia_com() * X_AB.rotation().transpose()));
  EXPECT_THROW(I_B.rotated(2.0 * Matrix3d::Identity()), std::invalid_argument);
}

TEST(PrincipalAxes, DistinctMomentsReconstructAndRightHanded) {
  for (int trial = 0; trial < 50; ++trial) {
    const SpatialInertia I = random_body();
    const PrincipalAxes p = I.principal_axes();
    EXPECT_NEAR(p.axes.determinant(), 1.0, 1e-12);
    EXPECT_LE(p.moments(0), p.moments(1));
    EXPECT_LE(p.moments(1), p.moments(2));
    EXPECT_TRUE((p.axes * p.moments.asDiagonal() * p.axes.transpose()).isApprox(I.inertia_com(), 1e-12));
  }
}

TEST(PrincipalAxes, CoincidentMomentsAreCanonicalAndStable) {
  // cylinder about z: I0 = I1 < I2; the axes must not depend on round-off in the input
  const SpatialInertia cyl = solid_cylinder(1.0, 0.5, Mass{2.0});
  const PrincipalAxes p = cyl.principal_axes();
  EXPECT_TRUE(p.axes.col(2).isApprox(Vector3d::UnitZ(), 1e-12));
  EXPECT_NEAR(p.axes.determinant(), 1.0, 1e-12);
  Matrix3d perturbed = cyl.inertia_com();
  perturbed(0, 1) = perturbed(1, 0) = 1e-14;
  // canonical axes for a coincident pair: a perturbation 1e-14 (relative to moments ~0.3) below the
  // coincidence tolerance must not turn them; were it resolved, they would turn by O(1)
  EXPECT_TRUE(principal_axes(perturbed).axes.isApprox(p.axes, 1e-9));
  // rotated cylinder: the distinct axis is the rotated z
  const Matrix3d R = random_rotation();
  const PrincipalAxes q = cyl.rotated(R).principal_axes();
  EXPECT_NEAR(std::abs(q.axes.col(2).dot(R.col(2))), 1.0, 1e-12);
  EXPECT_TRUE((q.axes * q.moments.asDiagonal() * q.axes.transpose()).isApprox(cyl.rotated(R).inertia_com(), 1e-12));
  // rod along z: I0 < I1 = I2
  const PrincipalAxes r = thin_rod(2.0, Mass{1.0}).principal_axes();
  EXPECT_TRUE(r.axes.col(0).isApprox(Vector3d::UnitZ()));
  EXPECT_NEAR(r.axes.determinant(), 1.0, 1e-12);
  // sphere: identity
  EXPECT_TRUE(solid_sphere(1.0, Mass{1.0}).rotated(R).principal_axes().axes.isApprox(Matrix3d::Identity()));
}

TEST(SpatialInertia, SymmetryPlane) {
  const SpatialInertia box = solid_box(Vector3d(1, 2, 3), Mass{1.0});
  EXPECT_TRUE(box.admits_symmetry_plane(Vector3d::UnitZ()));
  EXPECT_FALSE(box.admits_symmetry_plane(Vector3d(1, 1, 0)));
  const Matrix3d R = random_rotation();
  EXPECT_TRUE(box.rotated(R).admits_symmetry_plane(R.col(1)));
  EXPECT_THROW(box.admits_symmetry_plane(Vector3d::Zero()), std::invalid_argument);
}

TEST(SpatialInertia, CompositeSplitBoxEqualsWhole) {
  // a 2 x 1 x 1 box = two unit cubes at x = -0.5 and x = +0.5
  const SpatialInertia whole = solid_box(Vector3d(2, 1, 1), Density{3.0});
  const SpatialInertia cube = solid_box(Vector3d(1, 1, 1), Density{3.0});
  const Transform left(Matrix3d::Identity(), Vector3d(-0.5, 0, 0)), right(Matrix3d::Identity(), Vector3d(0.5, 0, 0));
  EXPECT_TRUE(composite({{left, cube}, {right, cube}}).is_approx(whole, 1e-14));
  EXPECT_TRUE((cube.transformed(left) + cube.transformed(right)).is_approx(whole, 1e-14));
  // removal cancels: the whole's inertia (shift terms m 0.25) against a cube's (0.5): ~10x eps more
  EXPECT_TRUE((whole - cube.transformed(left)).is_approx(cube.transformed(right), 1e-13));
  // removing more than the body's mass fails
  EXPECT_THROW(cube - whole, std::invalid_argument);
}

TEST(SpatialInertia, RandomCompositeAddRemoveRoundTrip) {
  std::vector<SpatialInertia> parts;
  for (int i = 0; i < 10; ++i) parts.push_back(random_body());
  const SpatialInertia all = composite(parts);
  SpatialInertia pairwise = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) pairwise = pairwise + parts[i];
  EXPECT_TRUE(all.is_approx(pairwise, 1e-12));
  SpatialInertia rest = all;
  for (size_t i = parts.size() - 1; i > 0; --i) rest = rest - parts[i];
  // nine removals cancel the whole's inertia (with its shift terms m |d|^2) down to one box's: each
  // rounds ~8 eps of |I_all|, relative to |I_0|
  const double cancellation = all.inertia_com().norm() / parts[0].inertia_com().norm();
  EXPECT_TRUE(rest.is_approx(parts[0], 9 * 8 * std::numeric_limits<double>::epsilon() * cancellation));
}

TEST(Validity, NoFalsePositivesAfterShiftsAndRotations) {
  // thin bodies sit exactly on the triangle-inequality boundary (I0 + I1 = I2)
  for (const SpatialInertia& thin : {thin_plate(1.0, 0.3, Mass{2.0}), thin_disk(0.7, Mass{1.0}), thin_rod(2.0, Mass{3.0})}) {
    SpatialInertia I = thin;
    for (int k = 0; k < 1000; ++k) {
      const Vector3d p = random_vector(100.0);
      I = SpatialInertia::from_inertia_about_point(I.mass(), I.com(), I.inertia_about_point(p), p);
      I = I.rotated(random_rotation());
    }
    EXPECT_TRUE(I.report().valid()) << I.report().summary();
    // each shift adds and removes m |p|^2 (|p| <= 173 m: <= 3e4 m), rounding ~eps of it: a random
    // walk over 1000 shifts, 5 sigma = 5 sqrt(1000) eps m 3e4, relative to the trace
    const double walk = 5 * std::sqrt(1000.0) * std::numeric_limits<double>::epsilon() * thin.mass() * 3e4;
    EXPECT_NEAR(I.inertia_com().trace(), thin.inertia_com().trace(), walk);
  }
}

TEST(Validity, RejectsTriangleViolationWithReportNumbers) {
  const Matrix3d hlw = Vector3d(2.0, 1.0, 2.0 / 3.0).asDiagonal();
  try {
    SpatialInertia(1.0, Vector3d::Zero(), hlw);
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("inertia_com"), std::string::npos);
    EXPECT_NE(msg.find("triangle"), std::string::npos);
    EXPECT_NE(msg.find("0.666666"), std::string::npos);
    EXPECT_NE(msg.find("condition number 3"), std::string::npos) << msg;
  }
  // the documented opt-in
  const SpatialInertia I(1.0, Vector3d::Zero(), hlw, InertiaCheck::allow_unrealizable);
  EXPECT_FALSE(I.report().valid());
  EXPECT_TRUE(I.report().valid(InertiaCheck::allow_unrealizable));
  EXPECT_NEAR(I.report().triangle_margins(2), 2.0 / 3.0 + 1.0 - 2.0, 1e-15);  // 2 roundings of numbers <= 2
  // not PSD is never accepted
  EXPECT_THROW(SpatialInertia(1.0, Vector3d::Zero(), Vector3d(-1, 1, 1).asDiagonal().toDenseMatrix(),
                              InertiaCheck::allow_unrealizable),
               std::invalid_argument);
}

TEST(Validity, BadInputsNameTheArgument) {
  const auto message = [](auto f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  EXPECT_EQ(message([] { SpatialInertia(0.0, Vector3d::Zero(), Matrix3d::Identity()); }).rfind("mass: expected", 0), 0u);
  EXPECT_EQ(message([] { SpatialInertia(-1.0, Vector3d::Zero(), Matrix3d::Identity()); }).rfind("mass:", 0), 0u);
  EXPECT_EQ(message([] { SpatialInertia(1.0, Vector3d(NAN, 0, 0), Matrix3d::Identity()); }).rfind("com:", 0), 0u);
  Matrix3d asym = Matrix3d::Identity();
  asym(0, 1) = 0.1;
  EXPECT_EQ(message([&] { SpatialInertia(1.0, Vector3d::Zero(), asym); }).rfind("inertia_com:", 0), 0u);
  Matrix3d inf = Matrix3d::Identity();
  inf(2, 2) = INFINITY;
  EXPECT_EQ(message([&] { SpatialInertia(1.0, Vector3d::Zero(), inf); }).rfind("inertia_com:", 0), 0u);
  EXPECT_EQ(message([] { solid_sphere(-1.0, Mass{1.0}); }).rfind("radius:", 0), 0u);
  EXPECT_EQ(message([] { solid_sphere(1.0, Density{0.0}); }).rfind("density:", 0), 0u);
  EXPECT_EQ(message([] { hollow_sphere(1.0, 1.0, Mass{1.0}); }).rfind("inner_radius:", 0), 0u);
}

TEST(Validity, RepairIsNearestAndExplicit) {
  const Matrix3d hlw = Vector3d(2.0, 1.0, 2.0 / 3.0).asDiagonal();
  const Matrix3d fixed = nearest_valid_inertia(hlw);
  const InertiaReport r = inertia_report(1.0, fixed);
  EXPECT_TRUE(r.valid()) << r.summary();
  EXPECT_NEAR(r.triangle_margins(2), 0.0, 1e-14);  // on the boundary up to the rounding of moments <= 2
  // projection onto the plane I0 + I1 - I2 = 0: shift by deficit/3 along (1, 1, -1) in eigen-order
  const double deficit = 2.0 - 1.0 - 2.0 / 3.0;
  EXPECT_TRUE(fixed.isApprox(Vector3d(2.0 - deficit / 3, 1.0 + deficit / 3, 2.0 / 3.0 + deficit / 3).asDiagonal().toDenseMatrix(), 1e-14));
  // valid input unchanged; repaired result is closer than any random valid candidate
  const Matrix3d good = random_body().inertia_com();
  EXPECT_TRUE(nearest_valid_inertia(good).isApprox(good, 1e-15));  // valid: returned as is
  const Matrix3d R = random_rotation();
  const Matrix3d bad = R * Vector3d(-0.5, 1.0, 3.0).asDiagonal() * R.transpose();
  const Matrix3d rep = nearest_valid_inertia(bad);
  EXPECT_TRUE(inertia_report(1.0, rep).valid());
  for (int k = 0; k < 200; ++k) {
    const Matrix3d cand = random_body().inertia_com() * 3.0;
    EXPECT_LE((rep - bad).norm(), (cand - bad).norm() + 1e-12);  // norms of entries <= 10: ~16 eps 10 slack
  }
}

TEST(Validity, ReportDiagnostics) {
  const InertiaReport r = inertia_report(2.0, Vector3d(1.0, 2.0, 2.5).asDiagonal());
  EXPECT_TRUE(r.valid());
  EXPECT_TRUE(r.principal_moments.isApprox(Vector3d(1.0, 2.0, 2.5)));
  EXPECT_TRUE(r.triangle_margins.isApprox(Vector3d(3.5, 1.5, 0.5)));
  EXPECT_DOUBLE_EQ(r.condition_number, 2.5);
  EXPECT_DOUBLE_EQ(r.tolerance, inertia_relative_tolerance * 5.5);
}
