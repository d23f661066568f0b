// Welding of duplicate vertices before the closed-mesh check (as trimesh merges them on load):
// STL-like meshes (unshared triangles, copies moved by 1e-33 and 1e-12 relative) give the shared
// mesh's mass properties and report the count; welding off refuses them with a message saying so;
// degenerate faces after welding are dropped; clusters across grid cells; symmetry planes of a
// faceted solid of revolution whose triangulation does not map faces onto faces.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "inertia_test_meshes.hpp"
#include "rigiddyn/inertia/mesh.hpp"
#include "rigiddyn/inertia/symmetry.hpp"

namespace rigiddyn {
namespace {

using Eigen::Vector3d;

// The mesh as STL stores it: three own vertex copies per face; each vertex's first copy exact, the
// others moved by `delta` [m] in a random direction.
test::Mesh unshared(const test::Mesh& m, double delta, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  std::vector<bool> seen(static_cast<size_t>(m.V.rows()), false);
  test::Mesh out;
  out.V.resize(3 * m.F.rows(), 3);
  out.F.resize(m.F.rows(), 3);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = m.F(f, k);
      Vector3d p = m.V.row(v).transpose();
      if (seen[static_cast<size_t>(v)]) p += delta * Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
      seen[static_cast<size_t>(v)] = true;
      out.V.row(3 * f + k) = p.transpose();
      out.F(f, k) = 3 * f + k;
    }
  return out;
}

std::string message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MeshWeld, StlDuplicatesGiveTheSharedMeshAndAreCounted) {
  std::mt19937 rng(3);
  test::Mesh box = test::box_mesh(Vector3d(1, 2, 0.5));
  box.V.rowwise() += Eigen::RowVector3d(0.5, 1.0, 0.25);  // a corner at the origin: zero coordinates
  const test::Mesh sphere = test::sphere_mesh(0.7, 12, 20);
  for (const test::Mesh* shared : {static_cast<const test::Mesh*>(&box), &sphere}) {
    const double size = (shared->V.colwise().maxCoeff() - shared->V.colwise().minCoeff()).norm();
    for (const double relative : {1e-33, 1e-12}) {
      const test::Mesh stl = unshared(*shared, relative * size, rng);
      WeldReport report;
      const SpatialInertia welded = solid_mesh(stl.V, stl.F, Density{2.0}, std::nullopt, &report);
      EXPECT_EQ(report.welded_vertices, stl.V.rows() - shared->V.rows());
      EXPECT_EQ(report.dropped_faces, 0);
      EXPECT_DOUBLE_EQ(report.tolerance, default_weld_tolerance(stl.V));
      // each cluster keeps its exact first copy: the shared mesh's coordinates, summed in another
      // order about another reference point (inside the body): round-off gamma_n, n = 4 faces
      // roundings on numbers <= the result, both sides
      const double bound = 2 * 4 * stl.F.rows() * 2.2e-16;
      EXPECT_TRUE(welded.is_approx(solid_mesh(shared->V, shared->F, Density{2.0}), bound));
      EXPECT_TRUE(mesh_shell(stl.V, stl.F, Density{2.0}).is_approx(mesh_shell(shared->V, shared->F, Density{2.0}), bound));
      const std::string refused = message([&] { solid_mesh(stl.V, stl.F, Density{2.0}, 0.0); });
      EXPECT_EQ(refused.rfind("faces: expected a closed mesh", 0), 0u) << refused;
      EXPECT_NE(refused.find("welding is off (weld_tolerance=0) and " + std::to_string(report.welded_vertices) +
                             " vertices lie within the default weld tolerance"),
                std::string::npos)
          << refused;
    }
  }
}

TEST(MeshWeld, DegenerateFacesDroppedAndIndicesKept) {
  test::Mesh box = test::box_mesh(Vector3d(1, 2, 3));
  MeshVertices V(9, 3);
  V << box.V, box.V.row(3) + Eigen::RowVector3d(1e-13, 0, 0);
  MeshFaces F(14, 3);
  F << box.F, 3, 8, 1, 8, 3, 1;  // two slivers that collapse to an edge once 8 is welded to 3
  const WeldedMesh w = weld_vertices(V, F, default_weld_tolerance(V));
  EXPECT_EQ(w.report.welded_vertices, 1);
  EXPECT_EQ(w.report.dropped_faces, 2);
  EXPECT_EQ(w.faces.rows(), 12);
  EXPECT_TRUE(w.faces == box.F);
  // exact box formulas both ways, a few dozen roundings: 64 eps
  EXPECT_TRUE(solid_mesh(V, F, Mass{1.0}).is_approx(solid_mesh(box.V, box.F, Mass{1.0}), 1e-14));
  // an open mesh after welding names input indices: the slivers put first shift the faces by 2
  MeshFaces open(13, 3);
  open << 3, 8, 1, 8, 3, 1, box.F.topRows(11);
  const std::string plain = message([&] { solid_mesh(box.V, box.F.topRows(11), Mass{1.0}, 0.0); });
  const std::string welded = message([&] { solid_mesh(V, open, Mass{1.0}); });
  const auto face = plain.find(" of face ");
  ASSERT_NE(face, std::string::npos) << plain;
  const int k = std::stoi(plain.substr(face + 9));
  EXPECT_NE(welded.find(plain.substr(plain.find("edge "), face - plain.find("edge ")) + " of face " +
                        std::to_string(k + 2)),
            std::string::npos)
      << plain << "\n" << welded;
  EXPECT_NE(welded.find("(after welding 1 vertices within"), std::string::npos) << welded;
  EXPECT_EQ(message([&] { solid_mesh(V, F, Mass{1.0}, -1.0); }).rfind("weld_tolerance: expected", 0), 0u);
}

TEST(MeshWeld, ClustersSpanGridCellsAndStopAtTheTolerance) {
  const double h = 1e-8;
  MeshVertices V(6, 3);
  V << 0, 0, 0, 1, 1, 1, 0.3 - 2e-9, 0, 0, 0.3 + 2e-9, 0, 0, 0.5, 0, 0, 0.5 + 1.1 * h, 0, 0;
  MeshFaces F(4, 3);
  F << 0, 1, 2, 0, 1, 3, 0, 1, 4, 0, 1, 5;
  const WeldedMesh w = weld_vertices(V, F, h);  // 0.3 -/+ 2e-9: both sides of the grid line at 0.3
  EXPECT_EQ(w.report.welded_vertices, 1);
  EXPECT_EQ(w.vertex_index, (std::vector<Eigen::Index>{0, 1, 2, 4, 5}));
  EXPECT_EQ(weld_vertices(V, F, 0.0).report.welded_vertices, 0);
}

TEST(MeshSymmetry, FacetedSolidOfRevolutionHasItsPolygonsPlanes) {
  // a sphere of 12 bands x 20 segments: quads split along one diagonal (faces do not map onto faces
  // under the mirrors through the axis), yet the solid has the 20 planes through the axis of the
  // regular 20-gon and the equator plane
  const test::Mesh sphere = test::sphere_mesh(0.7, 12, 20);
  const auto planes = mesh_symmetry_planes(sphere.V, sphere.F);
  EXPECT_EQ(planes.size(), 21u);
  // one vertex moved by 1e-4 of the size in a generic direction: no plane left
  MeshVertices bent = sphere.V;
  bent.row(37) += 1e-4 * Eigen::RowVector3d(0.3, -0.5, 0.8);
  EXPECT_TRUE(mesh_symmetry_planes(bent, sphere.F).empty());
}

}  // namespace
}  // namespace rigiddyn
