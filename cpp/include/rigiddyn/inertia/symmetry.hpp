// Planes of symmetry of a mass distribution (Craig "Plane of Symmetry"): a plane is one when the
// reflection about it maps every mass element onto one of equal mass.
//
// Candidates. A symmetry plane passes through the centre of mass (the reflection fixes the com) and,
// by Craig's statement (the xy plane a symmetry plane => I_xz = I_yz = 0), the inertia about the
// com maps its normal n onto itself, I_C n = (n.I_C n) n: n is a principal axis. So with three
// distinct principal moments the three principal axes are the only candidates. When moments
// coincide (relative gap <= degenerate_moments_tolerance) every direction of that eigenspace E is a
// principal axis, and further candidates are taken from the points (r = position - com):
//  - always: the three axes returned by principal_axes (arbitrary within a degenerate eigenspace);
//  - E a plane, d the distinct axis: p0 = the point with the largest component in E; a symmetry
//    plane with normal in E either contains p0 (n = d x r0) or swaps p0 with a point q of equal mass
//    and equal distance to the com (n = the E-part of r0 - r_q, for every such q);
//  - E all of space: p0 = the point farthest from the com, p1 = the point farthest from the line
//    com-p0; the plane swaps p0 with some q (n = r0 - r_q), or contains p0 and swaps p1 with some q
//    (n = r1 - r_q), or contains both (n = r0 x r1).
// Every candidate is then verified: on the points for point masses, on the solid's boundary surface
// for a mesh (mesh_symmetry_planes below). This list contains every symmetry plane of a set
// of exactly symmetric points, but with a tolerance a candidate built from a pair of points close to
// each other is imprecise; so for a degenerate body (a cube, a regular tetrahedron, a sphere-like
// point set) the result is the set of planes found among these candidates, not a proof that no
// others exist. Points all on one line (a continuum of planes through the line) and a single point
// return representatives only: the planes of the principal axes spanning the degenerate eigenspace.
//
// Tolerance (point masses): a point matches the mirror image of another when they are within
// tolerance * (largest distance from the com to a point) [m] and their masses differ by at most
// tolerance * the larger mass. For a mesh, the points are its vertices (for the candidates only) and
// the tolerance is the one stated at mesh_symmetry_planes.
#pragma once
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "rigiddyn/inertia/mesh.hpp"

namespace rigiddyn {

// Principal moments closer than this fraction of the largest moment are treated as coincident
// (a degenerate eigenspace, whose candidate normals come from the points; see above).
inline constexpr double degenerate_moments_tolerance = 1e-6;
// Default relative tolerance of the symmetry test (see above).
inline constexpr double symmetry_tolerance = 1e-9;

// A plane of symmetry, in the frame of the input: unit normal (sign chosen so that its
// largest-magnitude component is positive) and a point on it, the centre of mass [m].
struct SymmetryPlane {
  Eigen::Vector3d normal;
  Eigen::Vector3d point;
};

using PointPositions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;  // (n, 3) [m]

// Symmetry planes of point masses: masses (n,) [kg], each finite and > 0; positions (n, 3) [m] in
// the frame of expression; tolerance > 0 relative (see above). Throws std::invalid_argument naming
// the argument on mismatched lengths, n = 0, a mass <= 0, non-finite positions or tolerance <= 0.
std::vector<SymmetryPlane> symmetry_planes(const Eigen::Ref<const Eigen::VectorXd>& masses,
                                           const Eigen::Ref<const PointPositions>& positions,
                                           double tolerance = symmetry_tolerance);

// Symmetry planes of the uniform solid bounded by a closed, outward-oriented triangle mesh
// (vertices (n, 3) [m], faces (f, 3)), welded and checked as in solid_mesh (mesh.hpp; weld_tolerance
// likewise). The planes of the solid, whatever its triangulation: a plane counts when the
// reflection maps the solid onto itself, decided on its oriented boundary surface (every reflected
// face covered by faces of the mesh in the same plane with the same outward side, up to an
// uncovered strip of width eps = tolerance * L along its edges, L = the largest distance from the
// com to a vertex; face planes equal when their unit normals differ by <= tolerance and their
// distances from the com by <= eps). Candidate normals as above, from the inertia of the solid and
// the mesh's vertices: vertices inside flat faces need not map onto vertices. A faceted solid of
// revolution (a cylinder or capsule of s sections) has the planes of its polyhedron: the s planes
// through its axis of the regular s-gon, and the plane normal to the axis when the ends match -
// not the continuum of the smooth solid. Normals and point in the frame of the vertices (the body
// frame when the mesh is given in it).
std::vector<SymmetryPlane> mesh_symmetry_planes(const Eigen::Ref<const MeshVertices>& vertices,
                                                const Eigen::Ref<const MeshFaces>& faces,
                                                double tolerance = symmetry_tolerance,
                                                std::optional<double> weld_tolerance = std::nullopt);

}  // namespace rigiddyn
