// The principal frame the structure-preserving methods are built on (inertia/principal_axes.hpp:
// principal_decomposition; FullEuler's cached frame, which the splittings read through principal_split) reproduces
// the inertia to round-off for equal, nearly equal and distinct moments in random orientations; principal_axes
// keeps its canonical axes and agrees bit for bit where the moments are distinct. The exact free flow of a body
// whose moments span beyond the double range gives NaN instead of an internal error.
#include "test_numbers.hpp"
#include "rigiddyn/exact/free_body.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/integrators/splitting_parts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

// moments repeated, nearly repeated (inside principal_axes' 1e-9 coincidence tolerance and outside it) and distinct
std::vector<Eigen::Vector3d> test_moments() {
  return {{1.0, 2.0, 2.0}, {1.0, 1.0, 2.0}, {3.0, 3.0, 3.0}, {1.0, 2.0, 2.0 + 4e-9}, {1.0, 2.0, 2.0 + 1e-12},
          {1.0, 1.0 + 1e-15, 2.0}, {1.0, 1.5, 2.0}, {0.004, 0.004, 0.006}};
}

std::vector<Eigen::Matrix3d> random_rotations(int n) {
  std::mt19937_64 rng(31);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Matrix3d> out;
  for (int i = 0; i < n; ++i) {
    out.push_back(Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix());
  }
  return out;
}

Eigen::Matrix3d turned(const Eigen::Vector3d& moments, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d I = R * moments.asDiagonal() * R.transpose();
  return 0.5 * (I + I.transpose());
}

// A backward-stable eigen-decomposition reproduces I to a few ε |I| (Golub & Van Loan, the symmetric QR algorithm:
// ~ n² ε for n = 3, here 16 ε |I| with |I| the largest moment), whatever the spacing of the moments, with axes
// orthonormal to a few ε.
void expect_reproduces(const Eigen::Matrix3d& I, const Eigen::Vector3d& moments, const Eigen::Matrix3d& axes) {
  const double size = moments.cwiseAbs().maxCoeff();
  EXPECT_LE((axes * moments.asDiagonal() * axes.transpose() - I).cwiseAbs().maxCoeff(), 16.0 * kEps * size);
  EXPECT_LE((axes.transpose() * axes - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 16.0 * kEps);
  EXPECT_NEAR(axes.determinant(), 1.0, 16.0 * kEps);
  EXPECT_LE(moments(0), moments(1));
  EXPECT_LE(moments(1), moments(2));
}

TEST(PrincipalDecomposition, ReproducesTheInertiaForAnySpacingOfTheMoments) {
  for (const Eigen::Vector3d& moments : test_moments()) {
    for (const Eigen::Matrix3d& R : random_rotations(50)) {
      const Eigen::Matrix3d I = turned(moments, R);
      const PrincipalAxes P = principal_decomposition(I);
      SCOPED_TRACE(moments.transpose());
      expect_reproduces(I, P.moments, P.axes);
    }
  }
}

TEST(PrincipalDecomposition, IsPrincipalAxesWhereTheMomentsAreDistinct) {
  for (const Eigen::Matrix3d& R : random_rotations(20)) {
    for (const Eigen::Vector3d& moments : {Eigen::Vector3d(1.0, 1.5, 2.0), Eigen::Vector3d(1.0, 2.0, 2.0 + 4e-9)}) {
      const Eigen::Matrix3d I = turned(moments, R);
      const PrincipalAxes a = principal_axes(I), d = principal_decomposition(I);
      EXPECT_EQ(a.moments, d.moments);
      EXPECT_EQ(a.axes, d.axes);
    }
  }
}

TEST(PrincipalSplit, FullEulerCarriesAnAccurateFrame) {
  // the splittings turn about these axes: moments 2 ∓ 2.8e-9 and axes 1.5e-9 from orthogonal from a closed-form
  // eigensolver for moments (1, 2, 2) made them integrate another body
  for (const Eigen::Vector3d& moments : test_moments()) {
    for (const Eigen::Matrix3d& R : random_rotations(50)) {
      const Eigen::Matrix3d I = turned(moments, R);
      const PrincipalSplit P = principal_split(FullEuler(I));
      SCOPED_TRACE(moments.transpose());
      // the quaternion of the axes adds a few ε to them
      expect_reproduces(I, P.moments, P.q_BP.toRotationMatrix());
      EXPECT_EQ(P.ascending, (std::array<int, 3>{0, 1, 2}));
    }
  }
}

// moments spanning ~1e275 (scaled: 2e-275, 4e-14, 1.4) with a momentum part along the smallest: the amplitudes
// of the elliptic functions, ~(I3/I1)² in the scaled units, overflow
const Eigen::Vector3d kSpreadMoments(5.194511142106372e-111, 9.969571844746376e+150, 3.2117577726940814e+164);
const Eigen::Vector3d kSpreadRate(-2.6120584954463155e+139, 1.249331742987632e-97, 2.450745157630913e-296);

TEST(TorqueFreeSolution, RefusesMomentsSpreadBeyondTheRangeNamingTheInertia) {
  try {
    TorqueFreeSolution(kSpreadMoments.asDiagonal().toDenseMatrix(), Eigen::Quaterniond::Identity(), kSpreadRate,
                       InertiaCheck::allow_unrealizable);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("inertia: expected principal moments whose spread", 0), 0u) << e.what();
  }
}

TEST(FreeRotationFlow, MomentsSpreadBeyondTheRangeGiveNaN) {
  // a stepping loop records the divergence: no exception (it was "Carlson duplication: no convergence")
  const FreeRotationFlow flow(kSpreadMoments.asDiagonal().toDenseMatrix());
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w = kSpreadRate;
  EXPECT_NO_THROW(flow.advance(q, w, 1e-3));
  EXPECT_TRUE(std::isnan(q.w()) && std::isnan(w.x()));
}

}  // namespace
}  // namespace rigiddyn
