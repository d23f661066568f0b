// Mass properties of a closed triangle mesh, exact (no quadrature error): the volume integrals of
// Rigid-body notes (4.55), (4.56), (4.70) become, by the divergence theorem, sums over the faces of signed
// tetrahedra (reference point o, face a b c), whose integrals are closed-form:
//   V_f = d_a . (d_b x d_c) / 6,  int d dV = V_f s/4,  int d d^T dV = V_f/20 (sum d_i d_i^T + s s^T),
// with d_i = v_i - o and s = d_a + d_b + d_c. A thin shell integrates over the faces instead:
//   A_f = |(d_b - d_a) x (d_c - d_a)|/2,  int d dA = A_f s/3,  int d d^T dA = A_f/12 (sum d_i d_i^T + s s^T).
//
// Layouts: vertices (n, 3) [m] row-major, in the frame of expression; faces (f, 3) vertex indices,
// counter-clockwise seen from outside (outward normals, as trimesh and most formats).
#pragma once
#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace rigiddyn {

using MeshVertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;     // (n, 3) [m]
using MeshFaces = Eigen::Matrix<std::int64_t, Eigen::Dynamic, 3, Eigen::RowMajor>;  // (f, 3) indices

// Welding (as trimesh merges vertices on load; CAD STL files repeat each vertex once per face, the
// copies up to round-off apart): vertices closer than the weld tolerance [m] (Euclidean distance
// <= tolerance) become one. Clusters are the connected components of that relation, found by
// hashing the vertices into a grid of cells of side >= tolerance and comparing each with the 27
// neighbouring cells (sort: O(n log n) for meshes whose cells hold few distinct positions; copies
// at exactly equal coordinates are joined without pairwise comparison). A cluster keeps its
// lowest-indexed vertex (coordinates unchanged); the others are "welded". Faces that repeat a vertex
// afterwards are degenerate (zero area up to the tolerance) and dropped.
// Default tolerance: weld_relative_tolerance times the diagonal of the vertices' bounding box; far
// above the round-off of computed coordinates (~1e-16 relative), far below any modelled feature.
inline constexpr double weld_relative_tolerance = 1e-8;

// weld_relative_tolerance * |max - min| over the vertices' bounding box [m] (0 for no vertices).
double default_weld_tolerance(const Eigen::Ref<const MeshVertices>& vertices);

// What a weld did: welded_vertices = input vertices merged into another; dropped_faces = faces
// repeating a vertex after welding; tolerance [m] used (0: welding off).
struct WeldReport {
  Eigen::Index welded_vertices = 0;
  Eigen::Index dropped_faces = 0;
  double tolerance = 0.0;
};

// A welded mesh: vertices = the kept vertices in input order; faces = the non-degenerate faces in
// input order, indexing them; vertex_index[k] / face_index[k] = the input index of vertex / face k.
struct WeldedMesh {
  MeshVertices vertices;
  MeshFaces faces;
  std::vector<Eigen::Index> vertex_index;
  std::vector<Eigen::Index> face_index;
  WeldReport report;
};

// Welds vertices (n, 3) [m] within `tolerance` [m] (finite, >= 0; 0: no welding) and drops the faces
// it makes degenerate, as described above. Throws std::invalid_argument naming the argument on
// non-finite vertices, a negative tolerance, face indices outside [0, n) or an input face repeating
// an index (malformed input, refused as by require_closed_oriented_mesh).
WeldedMesh weld_vertices(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                         double tolerance);

// Throws std::invalid_argument naming "faces" unless every index is in [0, n_vertices), no face
// repeats a vertex, and the mesh is closed and consistently oriented: every directed edge (i, j)
// occurs in exactly one face and its reverse (j, i) in exactly one other. The message names the
// first offending edge and says whether the mesh is open there, non-manifold or inconsistently oriented.
void require_closed_oriented_mesh(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices);

// Signed volume [m^3] enclosed by the mesh (positive for outward-oriented faces). No topology check, no welding.
double mesh_volume(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces);

// The solid bounded by a closed, consistently oriented mesh, after welding (weld_tolerance [m]:
// nullopt = default_weld_tolerance(vertices), 0 = off).
// The closed-mesh check (as above; messages give input vertex and face indices) runs on the welded
// mesh; an inward-oriented mesh, negative volume, is rejected with a message saying to reverse the
// winding. Volume density. `report`, when given, receives what the weld did.
SpatialInertia solid_mesh(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md, std::optional<double> weld_tolerance = std::nullopt,
                          WeldReport* report = nullptr);

// The thin shell made of the faces (uniform area density; any orientation; the mesh need not be
// closed, so an open cup or a sheet is fine), after welding as in solid_mesh (which here only drops
// the faces that welding makes degenerate). Throws on bad indices or zero total area. Area density.
SpatialInertia mesh_shell(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md, std::optional<double> weld_tolerance = std::nullopt,
                          WeldReport* report = nullptr);

}  // namespace rigiddyn
