// Primitives against handbook formulas and against converging mesh / point-cloud approximations;
// exact mesh integrals (box, tetrahedron), mesh errors; density quadrature with error estimates.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "inertia_test_meshes.hpp"
#include "rigiddyn/inertia/density.hpp"
#include "rigiddyn/inertia/mesh.hpp"
#include "rigiddyn/inertia/point_masses.hpp"
#include "rigiddyn/inertia/primitives.hpp"

using namespace rigiddyn;
using rigiddyn::test::Mesh;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

Matrix3d diag(double a, double b, double c) { return Vector3d(a, b, c).asDiagonal(); }

double relative_error(const SpatialInertia& approx, const SpatialInertia& exact) {
  const double L = std::sqrt(exact.inertia_com().trace() / exact.mass());
  return std::max({std::abs(approx.mass() / exact.mass() - 1.0), (approx.com() - exact.com()).norm() / L,
                   (approx.inertia_com() - exact.inertia_com()).norm() / exact.inertia_com().norm()});
}

// The mesh approximation at resolution n and 2n: errors shrink (~ 1/n^2) and the finer is close.
void expect_converges(const std::function<SpatialInertia(int)>& approx, const SpatialInertia& exact, double fine_tol) {
  const double e1 = relative_error(approx(16), exact), e2 = relative_error(approx(32), exact),
               e3 = relative_error(approx(128), exact);
  // second order in 1/n: e(2n)/e(n) = 1/4 (1 + O(1/n)), 0.4 at n = 16; an inscribed polygon of n
  // sides misses (2 pi^2/3)/n^2 of a circle's area (4e-4 at n = 128; callers pass 1e-3), point
  // masses at cell midpoints miss 1/n^2 of a rod's inertia (6e-5: 1e-4)
  EXPECT_LT(e2, 0.4 * e1);
  EXPECT_LT(e3, fine_tol) << "errors " << e1 << " " << e2 << " " << e3;
}

Mesh cylinder_mesh(double r, double h, int n) { return test::revolution_mesh({{0, -h / 2}, {r, -h / 2}, {r, h / 2}, {0, h / 2}}, n); }

}  // namespace

TEST(Primitives, HandbookFormulas) {
  const double m = 2.0;
  // handbook formulas with small rational results: 2-3 roundings each (isApprox: relative)
  EXPECT_TRUE(solid_sphere(0.5, Mass{m}).inertia_com().isApprox(diag(0.2, 0.2, 0.2), 1e-15));
  EXPECT_TRUE(spherical_shell(0.5, Mass{m}).inertia_com().isApprox(diag(1, 1, 1) / 3.0, 1e-15));
  EXPECT_TRUE(solid_box(Vector3d(1, 2, 3), Mass{12.0}).inertia_com().isApprox(diag(13, 10, 5), 1e-15));
  EXPECT_TRUE(solid_cylinder(1.0, 2.0, Mass{12.0}).inertia_com().isApprox(diag(7, 7, 6), 1e-15));
  EXPECT_TRUE(hollow_cylinder(2.0, 1.0, 2.0, Mass{12.0}).inertia_com().isApprox(diag(19, 19, 30), 1e-15));
  EXPECT_TRUE(thin_rod(3.0, Mass{4.0}).inertia_com().isApprox(diag(3, 3, 0), 1e-15));
  EXPECT_TRUE(thin_disk(2.0, Mass{1.0}).inertia_com().isApprox(diag(1, 1, 2), 1e-15));
  EXPECT_TRUE(thin_plate(1.0, 2.0, Mass{12.0}).inertia_com().isApprox(diag(4, 1, 5), 1e-15));
  EXPECT_TRUE(solid_cone(1.0, 4.0, Mass{80.0}).inertia_com().isApprox(diag(60, 60, 24), 1e-15));
  EXPECT_TRUE(solid_ellipsoid(Vector3d(1, 2, 3), Mass{5.0}).inertia_com().isApprox(diag(13, 10, 5), 1e-15));
  // density: mass = density * measure
  EXPECT_NEAR(solid_sphere(1.0, Density{3.0}).mass(), 4.0 * M_PI, 1e-14);
  EXPECT_NEAR(box_shell(Vector3d(1, 2, 3), Density{1.0}).mass(), 22.0, 1e-14);
  EXPECT_NEAR(thin_rod(2.0, Density{1.5}).mass(), 3.0, 1e-15);
  EXPECT_NEAR(solid_capsule(1.0, 2.0, Density{1.0}).mass(), M_PI * 2.0 + 4.0 / 3.0 * M_PI, 1e-14);
  // hollow sphere = big sphere minus small sphere (composite removal), and its thin limit
  const SpatialInertia hollow = hollow_sphere(2.0, 1.0, Density{1.0});
  EXPECT_TRUE(hollow.is_approx(solid_sphere(2.0, Density{1.0}) - solid_sphere(1.0, Density{1.0}), 1e-14));
  // a shell 1e-6 thick tends to the spherical shell's 2/3 m R^2: the thickness changes it by O(1e-6)
  EXPECT_NEAR(hollow_sphere(1.0, 1.0 - 1e-6, Mass{1.0}).inertia_com()(0, 0), 2.0 / 3.0, 1e-5);
  // capsule with zero length is a sphere; tube = cylinder minus cylinder
  EXPECT_TRUE(solid_capsule(0.7, 0.0, Mass{1.0}).is_approx(solid_sphere(0.7, Mass{1.0}), 1e-14));
  EXPECT_TRUE(hollow_cylinder(2.0, 1.0, 3.0, Density{1.0})
                  .is_approx(solid_cylinder(2.0, 3.0, Density{1.0}) - solid_cylinder(1.0, 3.0, Density{1.0}), 1e-14));
}

TEST(Primitives, SolidsConvergeToMeshApproximations) {
  expect_converges([](int n) { return solid_mesh(test::sphere_mesh(0.8, n, 2 * n).V, test::sphere_mesh(0.8, n, 2 * n).F, Density{1.0}); },
                   solid_sphere(0.8, Density{1.0}), 1e-3);
  expect_converges([](int n) { const Mesh c = cylinder_mesh(0.5, 2.0, n); return solid_mesh(c.V, c.F, Density{1.0}); },
                   solid_cylinder(0.5, 2.0, Density{1.0}), 1e-3);
  // cone: apex at +3h/4, base at -h/4
  expect_converges([](int n) { const Mesh c = test::revolution_mesh({{0, -0.25}, {0.6, -0.25}, {0, 0.75}}, n); return solid_mesh(c.V, c.F, Density{1.0}); },
                   solid_cone(0.6, 1.0, Density{1.0}), 1e-3);
  expect_converges([](int n) {
    Mesh s = test::sphere_mesh(1.0, n, 2 * n);
    s.V = s.V * Vector3d(0.5, 1.0, 1.5).asDiagonal();
    return solid_mesh(s.V, s.F, Density{1.0});
  }, solid_ellipsoid(Vector3d(0.5, 1.0, 1.5), Density{1.0}), 1e-3);
  expect_converges([](int n) {
    std::vector<std::pair<double, double>> p;  // hemisphere, cylinder, hemisphere
    const double r = 0.4, h = 1.0;
    for (int k = 0; k <= n; ++k) {
      const double phi = M_PI / 2 * k / n;
      p.emplace_back(r * std::sin(phi), -h / 2 - r * std::cos(phi));
    }
    for (int k = 0; k <= n; ++k) {
      const double phi = M_PI / 2 * k / n;
      p.emplace_back(r * std::cos(phi), h / 2 + r * std::sin(phi));
    }
    p.back().first = 0.0;
    const Mesh c = test::revolution_mesh(p, 2 * n);
    return solid_mesh(c.V, c.F, Density{1.0});
  }, solid_capsule(0.4, 1.0, Density{1.0}), 1e-3);
}

TEST(Primitives, ShellsAndThinBodiesConverge) {
  expect_converges([](int n) { const Mesh s = test::sphere_mesh(0.8, n, 2 * n); return mesh_shell(s.V, s.F, Density{1.0}); },
                   spherical_shell(0.8, Density{1.0}), 1e-3);
  // thin disk: an open fan (the shell need not be closed)
  expect_converges([](int n) {
    const Mesh c = cylinder_mesh(0.9, 1.0, n);
    MeshFaces bottom(n, 3);
    for (int j = 0; j < n; ++j) bottom.row(j) = c.F.row(4 * j);  // per segment: bottom, 2 side, top
    MeshVertices V = c.V;
    V.col(2).setZero();
    return mesh_shell(V, bottom, Density{1.0});
  }, thin_disk(0.9, Density{1.0}), 1e-3);
  // thin rod: n equal point masses at the cell midpoints, I = m L^2/12 (1 - 1/n^2)
  expect_converges([](int n) {
    Eigen::VectorXd m = Eigen::VectorXd::Constant(n, 2.0 / n);
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p = Eigen::MatrixXd::Zero(n, 3);
    for (int i = 0; i < n; ++i) p(i, 2) = -0.5 + (i + 0.5) / n;
    return from_point_masses(m, p);
  }, thin_rod(1.0, Mass{2.0}), 1e-4);
  // box shell and thin plate are exact as meshes
  const Vector3d size(1.0, 2.0, 0.5);
  const Mesh b = test::box_mesh(size);
  EXPECT_TRUE(mesh_shell(b.V, b.F, Density{2.0}).is_approx(box_shell(size, Density{2.0}), 1e-14));
  MeshFaces plate(2, 3);
  plate << 0, 2, 1, 1, 2, 3;  // the z- face of the box
  MeshVertices V = b.V;
  V.col(2).setZero();
  EXPECT_TRUE(mesh_shell(V, plate, Mass{3.0}).is_approx(thin_plate(1.0, 2.0, Mass{3.0}), 1e-14));
}

TEST(Primitives, SolidsConvergeToPointClouds) {
  // midpoint-rule grids of point masses inside the shape (slower, independent of the mesh code)
  const auto grid = [](const std::function<bool(const Vector3d&)>& inside, double half, int n) {
    std::vector<Vector3d> pts;
    const double h = 2 * half / n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vector3d p(-half + (i + 0.5) * h, -half + (j + 0.5) * h, -half + (k + 0.5) * h);
          if (inside(p)) pts.push_back(p);
        }
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> P(pts.size(), 3);
    for (size_t i = 0; i < pts.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
    return from_point_masses(Eigen::VectorXd::Constant(P.rows(), 1.0 / P.rows()), P);
  };
  const auto in_sphere = [](const Vector3d& p) { return p.norm() < 1.0; };
  // lattice points in a smooth convex body: the count's discrepancy is O(R^(3/2)) in R = 40 cells
  // (Gauss-Landau), relative 40^(-3/2) = 4e-3; with edges (the cone) O(R^-1) = 2.5e-2, halved by the
  // grid's symmetry about the cone's axis
  EXPECT_LT(relative_error(grid(in_sphere, 1.0, 80), solid_sphere(1.0, Mass{1.0})), 5e-3);
  const auto in_cone = [](const Vector3d& p) {
    const double z = p.z() + 0.25;  // height above the base, h = 1, r = 1
    return z >= 0 && z <= 1 && p.head<2>().norm() < 1.0 - z;
  };
  EXPECT_LT(relative_error(grid(in_cone, 1.0, 80), solid_cone(1.0, 1.0, Mass{1.0})), 1e-2);
  // the box with a grid aligned to it is exact up to the midpoint rule: I = m/12 (a^2 (1 - 1/n^2) ...)
  EXPECT_LT(relative_error(grid([](const Vector3d&) { return true; }, 0.5, 60), solid_box(Vector3d::Ones(), Mass{1.0})),
            1e-3);
}

TEST(Mesh, BoxAndTetrahedronExact) {
  const Vector3d size(1.0, 2.0, 3.0);
  Mesh b = test::box_mesh(size);
  EXPECT_NEAR(mesh_volume(b.V, b.F), 6.0, 1e-14);  // 12 faces: a few dozen roundings of numbers <= 6
  EXPECT_TRUE(solid_mesh(b.V, b.F, Mass{5.0}).is_approx(solid_box(size, Mass{5.0}), 1e-14));
  // translated far away: same inertia about the centre, centre moved
  b.V.rowwise() += Eigen::RowVector3d(1e3, -2e3, 5e2);
  const SpatialInertia far = solid_mesh(b.V, b.F, Mass{5.0});
  EXPECT_TRUE(far.com().isApprox(Vector3d(1e3, -2e3, 5e2), 1e-14));
  // vertices at ~2e3 m are known to eps 2e3 = 4.4e-13 m; integrated about their mean (mesh code),
  // the inertia errs by ~2 x that relative to the box's size (~1 m): ~1e-12
  EXPECT_TRUE(far.inertia_com().isApprox(solid_box(size, Mass{5.0}).inertia_com(), 1e-9));
  // tetrahedron: mesh of its 4 faces vs the closed form; unit corner tetrahedron's known values
  MeshVertices V(4, 3);
  V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  MeshFaces F(4, 3);
  F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  const SpatialInertia tet = solid_tetrahedron(V.row(0), V.row(1), V.row(2), V.row(3), Density{6.0});
  EXPECT_TRUE(solid_mesh(V, F, Density{6.0}).is_approx(tet, 1e-14));
  // about the origin, unit density: I_xx = 1/30 (volume 1/6 * (y^2 + z^2) mean 2/10), I_xy = -1/120
  Matrix3d I_O;
  I_O << 1.0 / 30, -1.0 / 120, -1.0 / 120, -1.0 / 120, 1.0 / 30, -1.0 / 120, -1.0 / 120, -1.0 / 120, 1.0 / 30;
  EXPECT_TRUE(tet.inertia_about_origin().isApprox(6.0 * I_O, 1e-14));
  EXPECT_TRUE(tet.com().isApprox(Vector3d::Constant(0.25)));
}

TEST(Mesh, ErrorsNameTheProblem) {
  const Mesh b = test::box_mesh(Vector3d::Ones());
  const auto message = [](const MeshVertices& V, const MeshFaces& F) {
    try {
      solid_mesh(V, F, Density{1.0});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  EXPECT_NE(message(b.V, b.F.topRows(11)).find("open boundary"), std::string::npos);
  MeshFaces flipped = b.F;
  std::swap(flipped(0, 1), flipped(0, 2));
  flipped(1, 0) = b.F(1, 0);
  EXPECT_NE(message(b.V, flipped).find("inconsistent orientation"), std::string::npos) << message(b.V, flipped);
  MeshFaces inward = b.F;
  inward.col(1).swap(inward.col(2));
  EXPECT_NE(message(b.V, inward).find("oriented inward"), std::string::npos);
  MeshFaces bad_index = b.F;
  bad_index(3, 1) = 8;
  EXPECT_NE(message(b.V, bad_index).find("faces[3]"), std::string::npos);
  MeshFaces repeated = b.F;
  repeated(2, 1) = repeated(2, 0);
  EXPECT_NE(message(b.V, repeated).find("distinct"), std::string::npos);
  MeshVertices nan = b.V;
  nan(0, 0) = NAN;
  EXPECT_EQ(message(nan, b.F).rfind("vertices:", 0), 0u);
}

TEST(Density, GaussLegendreExactForPolynomials) {
  for (int n : {1, 2, 5, 12}) {
    const QuadratureRule g = gauss_legendre_1d(n);
    for (int d = 0; d <= 2 * n - 1; ++d) {
      const double exact = (d % 2) ? 0.0 : 2.0 / (d + 1);
      // exact for degree <= 2n - 1: round-off of n terms <= 2 (weights sum to 2), nodes to a few ulps
      EXPECT_NEAR((g.weights.array() * g.points.col(0).array().pow(d)).sum(), exact, 1e-14) << n << " " << d;
    }
  }
}

TEST(Density, UniformDensityMatchesPrimitivesWithSmallErrorEstimate) {
  const auto one = [](const Vector3d&) { return 2.0; };
  const DensityIntegral box = integrate_density_over_box(one, Vector3d(-0.5, -1, -1.5), Vector3d(0.5, 1, 1.5), 3, 1);
  // a constant density: every rule is exact; round-off of 27 (box) or 12 faces x 8 (mesh) points
  EXPECT_TRUE(box.inertia.is_approx(solid_box(Vector3d(1, 2, 3), Density{2.0}), 1e-13));
  EXPECT_LT(box.mass_error, 1e-12);
  const Mesh b = test::box_mesh(Vector3d(1, 2, 3));
  const DensityIntegral mesh = integrate_density_over_mesh(one, b.V, b.F, 2);
  EXPECT_TRUE(mesh.inertia.is_approx(solid_box(Vector3d(1, 2, 3), Density{2.0}), 1e-12));
}

TEST(Density, LinearDensityClosedFormAndErrorEstimate) {
  // rho = 1 + x on the cube [0, 1]^3: m = 3/2, c_x = (1/2 + 1/3)/(3/2) = 5/9, c_y = c_z = 1/2
  const auto rho = [](const Vector3d& p) { return 1.0 + p.x(); };
  const DensityIntegral r = integrate_density_over_box(rho, Vector3d::Zero(), Vector3d::Ones(), 2, 1);
  EXPECT_NEAR(r.inertia.mass(), 1.5, 1e-14);  // polynomial density: exact rule, 8 points' round-off
  EXPECT_TRUE(r.inertia.com().isApprox(Vector3d(5.0 / 9.0, 0.5, 0.5), 1e-14));
  // I_xx about the origin = int rho (y^2 + z^2) = 3/2 * 2/3 = 1
  EXPECT_NEAR(r.inertia.inertia_about_origin()(0, 0), 1.0, 1e-14);
  // a non-polynomial density: the error estimate bounds the actual error of the low order
  const auto gauss = [](const Vector3d& p) { return std::exp(-p.squaredNorm()); };
  const DensityIntegral g = integrate_density_over_box(gauss, Vector3d::Constant(-1), Vector3d::Constant(1), 2, 1);
  const double exact_m = std::pow(std::sqrt(M_PI) * std::erf(1.0), 3);
  EXPECT_GT(g.mass_error, 0.0);
  EXPECT_LT(std::abs(g.inertia.mass() - exact_m), g.mass_error);
  const DensityIntegral fine = integrate_density_over_box(gauss, Vector3d::Constant(-1), Vector3d::Constant(1), 6, 2);
  // the result is the 12-point rule per axis on 2^3 cells (truncation ~h^24, negligible): round-off
  // of a sum of 8 x 12^3 positive terms, a random walk: 5 sigma = 5 sqrt(n) eps m; the estimate is the
  // 6-point rule's difference to it, a truncation O(h^12) ~ 1e-9 (below 1e-8)
  EXPECT_NEAR(fine.inertia.mass(), exact_m, 5 * std::sqrt(8.0 * 12 * 12 * 12) * std::numeric_limits<double>::epsilon() * exact_m);
  EXPECT_LT(fine.mass_error, 1e-8);
}

TEST(Density, SphereMeshWithRadialDensity) {
  // rho = r^2 on a finely meshed sphere vs the exact ball: m = 4 pi R^5/5, I = 2/3 int rho r^2 dV = 8 pi R^7/21
  const Mesh s = test::sphere_mesh(1.0, 48, 96);
  // (the inscribed mesh misses ~0.2% of the volume, more of the outer, denser shell)
  const auto rho = [](const Vector3d& p) { return p.squaredNorm(); };
  const DensityIntegral r = integrate_density_over_mesh(rho, s.V, s.F, 3);
  // the inscribed mesh (48 x 96) misses (2 pi^2/3)/48^2 ~ 3e-3 of the outer shell, weighted by r^2
  EXPECT_NEAR(r.inertia.mass() / (4 * M_PI / 5), 1.0, 5e-3);
  EXPECT_NEAR(r.inertia.inertia_com()(2, 2) / (8 * M_PI / 21), 1.0, 5e-3);
  // degree 2 times the collapsed Jacobian (degree 2 in u): 3 points per axis are exact already
  EXPECT_LT(r.mass_error, 1e-10);
  EXPECT_GT(integrate_density_over_mesh(rho, s.V, s.F, 1).mass_error, 1e-3);
  EXPECT_THROW(integrate_density_over_box([](const Vector3d&) { return -1.0; }, Vector3d::Zero(), Vector3d::Ones()),
               std::invalid_argument);
}
