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

#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace rigiddyn {

using MeshVertices = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;     // (n, 3) [m]
using MeshFaces = Eigen::Matrix<std::int64_t, Eigen::Dynamic, 3, Eigen::RowMajor>;  // (f, 3) indices

// Throws std::invalid_argument naming "faces" unless every index is in [0, n_vertices), no face
// repeats a vertex, and the mesh is closed and consistently oriented: every directed edge (i, j)
// occurs in exactly one face and its reverse (j, i) in exactly one other. The message names the
// first offending edge and says whether the mesh is open there, non-manifold or inconsistently oriented.
void require_closed_oriented_mesh(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices);

// Signed volume [m^3] enclosed by the mesh (positive for outward-oriented faces). No topology check.
double mesh_volume(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces);

// The solid bounded by a closed, consistently oriented mesh (checked as above; an inward-oriented
// mesh, negative volume, is rejected with a message saying to reverse the winding). Volume density.
SpatialInertia solid_mesh(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md);

// The thin shell made of the faces (uniform area density; any orientation; the mesh need not be
// closed, so an open cup or a sheet is fine). Throws on bad indices or zero total area. Area density.
SpatialInertia mesh_shell(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md);

}  // namespace rigiddyn
