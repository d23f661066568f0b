// Planes of symmetry (Craig "Plane of Symmetry"): boxes, tetrahedra, a prism, a cube grid,
// random mirrored sets at random orientations, broken symmetry, consistency with
// SpatialInertia::admits_symmetry_plane, bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>
#include <vector>

#include "inertia_test_meshes.hpp"
#include "rigiddyn/inertia/point_masses.hpp"
#include "rigiddyn/inertia/symmetry.hpp"

namespace rigiddyn {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

// A closed mesh from outward (counter-clockwise) polygons; polygons with more than three corners are
// fanned around an added centre vertex, so the triangulation keeps the polygon's own mirror symmetries.
test::Mesh polyhedron(const std::vector<Vector3d>& corners, const std::vector<std::vector<int>>& polygons) {
  std::vector<Vector3d> V = corners;
  std::vector<std::array<std::int64_t, 3>> F;
  for (const auto& poly : polygons) {
    const int k = static_cast<int>(poly.size());
    if (k == 3) {
      F.push_back({poly[0], poly[1], poly[2]});
      continue;
    }
    Vector3d centre = Vector3d::Zero();
    for (const int i : poly) centre += corners[i] / k;
    V.push_back(centre);
    const std::int64_t c = static_cast<std::int64_t>(V.size()) - 1;
    for (int j = 0; j < k; ++j) F.push_back({c, poly[j], poly[(j + 1) % k]});
  }
  test::Mesh m;
  m.V.resize(static_cast<Eigen::Index>(V.size()), 3);
  for (size_t i = 0; i < V.size(); ++i) m.V.row(static_cast<Eigen::Index>(i)) = V[i].transpose();
  m.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (size_t i = 0; i < F.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) << F[i][0], F[i][1], F[i][2];
  return m;
}

// Box with edges `size`, each face split into four triangles around its centre.
test::Mesh symmetric_box(const Vector3d& size) {
  std::vector<Vector3d> c;
  for (int i = 0; i < 8; ++i)
    c.emplace_back(((i & 1) ? 0.5 : -0.5) * size(0), ((i & 2) ? 0.5 : -0.5) * size(1), ((i & 4) ? 0.5 : -0.5) * size(2));
  return polyhedron(c, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

// Prism over the isosceles triangle (-1, 0), (1, 0), (0, 2) in xy, z in [-h/2, h/2]: planes x = 0, z = 0.
test::Mesh isosceles_prism(double h) {
  std::vector<Vector3d> c = {{-1, 0, -h / 2}, {1, 0, -h / 2}, {0, 2, -h / 2}, {-1, 0, h / 2}, {1, 0, h / 2}, {0, 2, h / 2}};
  return polyhedron(c, {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
}

std::vector<Vector3d> regular_tetrahedron() { return {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}; }

PointPositions rows(const std::vector<Vector3d>& points) {
  PointPositions P(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  return P;
}

bool has_normal(const std::vector<SymmetryPlane>& planes, const Vector3d& n) {
  for (const auto& p : planes)
    if (p.normal.cross(n.normalized()).norm() < 1e-9) return true;  // normals to eps |I|/gap <= 1e-12
  return false;
}

// Every detected plane passes the inertia's necessary condition and contains the centre of mass.
void expect_consistent(const std::vector<SymmetryPlane>& planes, const SpatialInertia& body) {
  for (const auto& p : planes) {
    // the plane's normal and point come from an eigen-decomposition and sums: eps |I|/gap (gap/|I|
    // >= 1e-3 here) and a few eps of the body's size; the symmetry check at 1e-9 is far above that
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
    EXPECT_TRUE(body.admits_symmetry_plane(p.normal, 1e-9)) << p.normal.transpose();
    EXPECT_LT((p.point - body.com()).norm(), 1e-12);
  }
}

TEST(SymmetryPlanes, SymmetricBoxMeshHasThreeCoordinatePlanes) {
  const test::Mesh box = symmetric_box(Vector3d(1, 2, 3));
  const auto planes = mesh_symmetry_planes(box.V, box.F);
  ASSERT_EQ(planes.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(has_normal(planes, Vector3d::Unit(k)));
  expect_consistent(planes, solid_mesh(box.V, box.F, Density{1.0}));
}

TEST(SymmetryPlanes, BoxMeshRotatedAndShifted) {
  const test::Mesh box = symmetric_box(Vector3d(1, 2, 3));
  const Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vector3d t(0.3, -4, 2);
  const MeshVertices V = (box.V * R.transpose()).rowwise() + t.transpose();
  const auto planes = mesh_symmetry_planes(V, box.F);
  ASSERT_EQ(planes.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(has_normal(planes, R.col(k)));
  for (const auto& p : planes) EXPECT_LT((p.point - t).norm(), 1e-12);  // centroid sums: <= 48 eps |t| (4.5)
}

TEST(SymmetryPlanes, TwelveTriangleBoxTriangulationKeepsTheSolidsMirrors) {
  // Each square face is split by one diagonal, which the mirrors parallel to its edges swap: the face
  // set is not mapped onto itself, but the solid box is, and its planes are what is reported.
  const test::Mesh box = test::box_mesh(Vector3d(1, 2, 3));
  const auto planes = mesh_symmetry_planes(box.V, box.F);
  ASSERT_EQ(planes.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(has_normal(planes, Vector3d::Unit(k)));
  MeshVertices bent = box.V;
  bent(0, 0) += 1e-4;  // one corner moved along an edge: the box is no longer symmetric
  bent(0, 1) -= 0.7e-4;
  EXPECT_TRUE(mesh_symmetry_planes(bent, box.F).empty());
}

TEST(SymmetryPlanes, BoxPointGridHasThreePlanes) {
  std::vector<Vector3d> pts;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 5; ++k) pts.emplace_back(0.5 * i, 0.7 * j, 1.1 * k);
  const VectorXd m = VectorXd::Constant(static_cast<Eigen::Index>(pts.size()), 2.0);
  const auto planes = symmetry_planes(m, rows(pts));
  ASSERT_EQ(planes.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(has_normal(planes, Vector3d::Unit(k)));
  expect_consistent(planes, from_point_masses(m, rows(pts)));
}

TEST(SymmetryPlanes, CubeGridIsDegenerateAndHasNinePlanes) {
  // all principal moments equal: 3 coordinate planes + 6 diagonal planes (normals e_i +- e_j)
  std::vector<Vector3d> pts;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) pts.emplace_back(i, j, k);
  const VectorXd m = VectorXd::Ones(27);
  const auto planes = symmetry_planes(m, rows(pts));
  EXPECT_EQ(planes.size(), 9u);
  for (int a = 0; a < 3; ++a) {
    EXPECT_TRUE(has_normal(planes, Vector3d::Unit(a)));
    const int b = (a + 1) % 3;
    EXPECT_TRUE(has_normal(planes, Vector3d::Unit(a) + Vector3d::Unit(b)));
    EXPECT_TRUE(has_normal(planes, Vector3d::Unit(a) - Vector3d::Unit(b)));
  }
  expect_consistent(planes, from_point_masses(m, rows(pts)));
}

TEST(SymmetryPlanes, RegularTetrahedronHasSixPlanes) {
  // each plane contains one edge and the midpoint of the opposite edge: normals e_i +- e_j
  const auto v = regular_tetrahedron();
  const auto planes = symmetry_planes(VectorXd::Ones(4), rows(v));
  EXPECT_EQ(planes.size(), 6u);
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    EXPECT_TRUE(has_normal(planes, Vector3d::Unit(a) + Vector3d::Unit(b)));
    EXPECT_TRUE(has_normal(planes, Vector3d::Unit(a) - Vector3d::Unit(b)));
  }
  test::Mesh mesh = polyhedron(v, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
  if (mesh_volume(mesh.V, mesh.F) < 0) mesh.F.col(1).swap(mesh.F.col(2));
  const auto mesh_planes = mesh_symmetry_planes(mesh.V, mesh.F);
  EXPECT_EQ(mesh_planes.size(), 6u);
  expect_consistent(mesh_planes, solid_mesh(mesh.V, mesh.F, Density{1.0}));
}

TEST(SymmetryPlanes, IrregularTetrahedronHasNone) {
  const std::vector<Vector3d> v = {{0, 0, 0}, {1.3, 0.1, 0}, {0.2, 0.9, 0.1}, {0.3, 0.4, 1.7}};
  EXPECT_TRUE(symmetry_planes(VectorXd::Ones(4), rows(v)).empty());
  test::Mesh mesh = polyhedron(v, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  ASSERT_GT(mesh_volume(mesh.V, mesh.F), 0.0);
  EXPECT_TRUE(mesh_symmetry_planes(mesh.V, mesh.F).empty());
}

TEST(SymmetryPlanes, IsoscelesPrismHasTwoPlanes) {
  const test::Mesh prism = isosceles_prism(1.5);
  const auto planes = mesh_symmetry_planes(prism.V, prism.F);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_TRUE(has_normal(planes, Vector3d::UnitX()));
  EXPECT_TRUE(has_normal(planes, Vector3d::UnitZ()));
  expect_consistent(planes, solid_mesh(prism.V, prism.F, Density{1.0}));
}

// k random points with random masses in z > 0, and their mirror images about z = 0, then rotated by
// R and shifted by t: the plane with normal R e_z is a plane of symmetry.
struct Mirrored {
  VectorXd masses;
  PointPositions positions;
};
Mirrored random_mirrored_set(std::mt19937& rng, int k, const Matrix3d& R, const Vector3d& t) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.5, 2.0);
  Mirrored s{VectorXd(2 * k), PointPositions(2 * k, 3)};
  for (int i = 0; i < k; ++i) {
    const Vector3d p(u(rng), u(rng), 0.1 + std::abs(u(rng)));
    s.masses(2 * i) = s.masses(2 * i + 1) = mass(rng);
    s.positions.row(2 * i) = (R * p + t).transpose();
    s.positions.row(2 * i + 1) = (R * Vector3d(p.x(), p.y(), -p.z()) + t).transpose();
  }
  return s;
}

TEST(SymmetryPlanes, RandomMirroredSetsAtAnyOrientation) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const Matrix3d R = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Vector3d t(5 * u(rng), 5 * u(rng), 5 * u(rng));
    const Mirrored s = random_mirrored_set(rng, 3 + trial % 10, R, t);
    const auto planes = symmetry_planes(s.masses, s.positions);
    ASSERT_EQ(planes.size(), 1u) << "trial " << trial;
    EXPECT_TRUE(has_normal(planes, R.col(2))) << "trial " << trial;
    expect_consistent(planes, from_point_masses(s.masses, s.positions));

    Mirrored moved = s;  // one point moved by 1e-4 of the body size: broken
    moved.positions(0, 0) += 1e-4;
    EXPECT_TRUE(symmetry_planes(moved.masses, moved.positions).empty()) << "trial " << trial;
    Mirrored heavier = s;  // same geometry, unequal masses at a mirrored pair: broken
    heavier.masses(1) *= 1.01;
    EXPECT_TRUE(symmetry_planes(heavier.masses, heavier.positions).empty()) << "trial " << trial;
  }
}

TEST(SymmetryPlanes, ToleranceIsRelativeToTheBodySize) {
  std::mt19937 rng(7);
  Mirrored s = random_mirrored_set(rng, 6, Matrix3d::Identity(), Vector3d::Zero());
  s.positions(0, 0) += 1e-7;
  EXPECT_TRUE(symmetry_planes(s.masses, s.positions).empty());
  EXPECT_EQ(symmetry_planes(s.masses, s.positions, 1e-5).size(), 1u);
  const PointPositions scaled = 1e3 * s.positions;  // same shape, 1000 times larger: same answer
  EXPECT_TRUE(symmetry_planes(s.masses, scaled).empty());
  EXPECT_EQ(symmetry_planes(s.masses, scaled, 1e-5).size(), 1u);
}

TEST(SymmetryPlanes, BadInputNamesTheArgument) {
  const PointPositions P = rows(regular_tetrahedron());
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(message([&] { symmetry_planes(VectorXd::Ones(3), P); }).rfind("positions:", 0), 0u);
  EXPECT_EQ(message([&] { symmetry_planes(VectorXd::Ones(0), P.topRows(0)); }).rfind("positions:", 0), 0u);
  EXPECT_EQ(message([&] { symmetry_planes(Eigen::Vector4d(1, 0, 1, 1), P); }).rfind("masses[1]:", 0), 0u);
  EXPECT_EQ(message([&] { symmetry_planes(Eigen::Vector4d(1, 1, -2, 1), P); }).rfind("masses[2]:", 0), 0u);
  PointPositions bad = P;
  bad(2, 1) = std::nan("");
  EXPECT_EQ(message([&] { symmetry_planes(VectorXd::Ones(4), bad); }).rfind("positions:", 0), 0u);
  EXPECT_EQ(message([&] { symmetry_planes(VectorXd::Ones(4), P, 0.0); }).rfind("tolerance:", 0), 0u);
  test::Mesh open = symmetric_box(Vector3d(1, 1, 1));
  const MeshFaces first_faces = open.F.topRows(open.F.rows() - 1);
  EXPECT_EQ(message([&] { mesh_symmetry_planes(open.V, first_faces); }).rfind("faces", 0), 0u);
}

}  // namespace
}  // namespace rigiddyn
