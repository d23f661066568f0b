#include "rigiddyn/inertia/symmetry.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <string>

#include "rigiddyn/check.hpp"
#include "rigiddyn/inertia/point_masses.hpp"
#include "rigiddyn/inertia/primitives.hpp"
#include "rigiddyn/inertia/principal_axes.hpp"

namespace rigiddyn {

namespace {

using Eigen::Index;
using Eigen::Matrix3d;
using Eigen::Vector3d;

// Points r_i relative to the centre of mass with their masses, indexed by distance to the com
// (which the reflection about a plane through the com preserves).
struct PointSet {
  std::vector<Vector3d> r;
  std::vector<double> mass;
  std::vector<Index> by_radius;       // indices sorted by |r|
  std::vector<double> sorted_radius;  // |r| in that order
  double eps;                         // position tolerance [m]
  double tolerance;                   // relative mass tolerance

  PointSet(const Vector3d& com, const Eigen::Ref<const PointPositions>& positions, std::vector<double> masses,
           double tol)
      : mass(std::move(masses)), tolerance(tol) {
    double size = 0.0;
    for (Index i = 0; i < positions.rows(); ++i) {
      r.push_back(positions.row(i).transpose() - com);
      size = std::max(size, r.back().norm());
    }
    eps = tol * size;
    by_radius.resize(r.size());
    std::iota(by_radius.begin(), by_radius.end(), Index{0});
    std::sort(by_radius.begin(), by_radius.end(), [this](Index a, Index b) { return r[a].norm() < r[b].norm(); });
    for (const Index i : by_radius) sorted_radius.push_back(r[i].norm());
  }

  bool equal_mass(Index i, Index j) const {
    return std::abs(mass[i] - mass[j]) <= tolerance * std::max(mass[i], mass[j]);
  }

  // Calls f(j) for every point j whose distance to the com is within `width` of `radius`.
  template <typename F>
  void for_each_at_radius(double radius, double width, F&& f) const {
    auto k = std::lower_bound(sorted_radius.begin(), sorted_radius.end(), radius - width) - sorted_radius.begin();
    for (; k < static_cast<Index>(sorted_radius.size()) && sorted_radius[k] <= radius + width; ++k) f(by_radius[k]);
  }
};

// The permutation sigma mapping each point onto the mirror image (about the plane through the com with
// unit normal n) of equal mass, r_sigma(i) ~ r_i - 2 (n.r_i) n; empty when some image has no match.
std::vector<Index> mirror_map(const PointSet& s, const Vector3d& n) {
  const Index count = static_cast<Index>(s.r.size());
  std::vector<Index> sigma(count, -1);
  std::vector<char> taken(count, 0);
  for (Index i = 0; i < count; ++i) {
    const Vector3d image = s.r[i] - 2.0 * n.dot(s.r[i]) * n;
    s.for_each_at_radius(s.r[i].norm(), s.eps, [&](Index j) {
      if (sigma[i] < 0 && !taken[j] && s.equal_mass(i, j) && (s.r[j] - image).norm() <= s.eps) sigma[i] = j;
    });
    if (sigma[i] < 0) return {};
    taken[sigma[i]] = 1;
  }
  return sigma;
}

// Normals (projected by P onto the degenerate eigenspace) of the planes swapping point p with a point
// q of equal mass at the same distance from the com: n = P (r_p - r_q) / |.|.
void add_swap_candidates(const PointSet& s, Index p, const Matrix3d& P, std::vector<Vector3d>& out) {
  s.for_each_at_radius(s.r[p].norm(), 2.0 * s.eps, [&](Index q) {
    const Vector3d v = P * (s.r[p] - s.r[q]);
    if (q != p && s.equal_mass(p, q) && v.norm() > s.eps) out.push_back(v.normalized());
  });
}

// The index maximising |P r_i|.
Index farthest(const PointSet& s, const Matrix3d& P) {
  Index best = 0;
  for (Index i = 1; i < static_cast<Index>(s.r.size()); ++i)
    if ((P * s.r[i]).norm() > (P * s.r[best]).norm()) best = i;
  return best;
}

// Candidates with normal in the plane E orthogonal to the distinct axis d (header: "E a plane").
void add_plane_candidates(const PointSet& s, const Vector3d& d, std::vector<Vector3d>& out) {
  const Matrix3d P = Matrix3d::Identity() - d * d.transpose();
  const Index p0 = farthest(s, P);
  if (!((P * s.r[p0]).norm() > s.eps)) return;  // all points on the axis d: representatives only
  out.push_back(d.cross(s.r[p0]).normalized());  // the plane containing p0 and d
  add_swap_candidates(s, p0, P, out);
}

// Candidates when all three moments coincide (header: "E all of space").
void add_space_candidates(const PointSet& s, std::vector<Vector3d>& out) {
  const Matrix3d I = Matrix3d::Identity();
  const Index p0 = farthest(s, I);
  if (!(s.r[p0].norm() > s.eps)) return;  // a single point: representatives only
  add_swap_candidates(s, p0, I, out);
  const Vector3d u0 = s.r[p0].normalized();
  const Index p1 = farthest(s, I - u0 * u0.transpose());
  const Vector3d perp1 = s.r[p1] - s.r[p1].dot(u0) * u0;
  if (!(perp1.norm() > s.eps)) return;
  out.push_back(s.r[p0].cross(s.r[p1]).normalized());  // the plane containing p0 and p1
  add_swap_candidates(s, p1, I, out);
}

// Principal axes always; more from the points when principal moments coincide (header).
std::vector<Vector3d> candidate_normals(const PointSet& s, const Matrix3d& inertia_com) {
  const PrincipalAxes pa = principal_axes(inertia_com);
  std::vector<Vector3d> out = {pa.axes.col(0), pa.axes.col(1), pa.axes.col(2)};
  const double gap = degenerate_moments_tolerance * pa.moments(2);
  const bool low = pa.moments(1) - pa.moments(0) <= gap, high = pa.moments(2) - pa.moments(1) <= gap;
  if (low && high) {
    add_space_candidates(s, out);
  } else if (low) {
    add_plane_candidates(s, pa.axes.col(2), out);
  } else if (high) {
    add_plane_candidates(s, pa.axes.col(0), out);
  }
  return out;
}

// n with its largest-magnitude component positive.
Vector3d canonical_sign(const Vector3d& n) {
  Index k;
  n.cwiseAbs().maxCoeff(&k);
  return n(k) < 0.0 ? Vector3d(-n) : n;
}

bool parallel(const Vector3d& a, const Vector3d& b, double angle) { return a.cross(b).norm() <= angle; }

// Tests every candidate (duplicates skipped) with `accept(n, sigma)`; the accepted planes, each once.
template <typename Accept>
std::vector<SymmetryPlane> verified_planes(const PointSet& s, const Vector3d& com, const Matrix3d& inertia_com,
                                           Accept&& accept) {
  constexpr double same_plane_angle = 1e-6;  // [rad] normals closer than this report one plane
  std::vector<Vector3d> tested;
  std::vector<SymmetryPlane> planes;
  for (const Vector3d& candidate : candidate_normals(s, inertia_com)) {
    const Vector3d n = canonical_sign(candidate);
    const auto seen = [&](const Vector3d& m) { return parallel(n, m, s.tolerance); };
    if (std::any_of(tested.begin(), tested.end(), seen)) continue;
    tested.push_back(n);
    const auto found = [&](const SymmetryPlane& p) { return parallel(n, p.normal, same_plane_angle); };
    if (std::any_of(planes.begin(), planes.end(), found)) continue;
    const std::vector<Index> sigma = mirror_map(s, n);
    if (!sigma.empty() && accept(sigma)) planes.push_back({n, com});
  }
  return planes;
}

// A face as a cyclic triple, rotated so that its smallest index comes first.
std::array<std::int64_t, 3> cyclic_key(std::int64_t a, std::int64_t b, std::int64_t c) {
  if (b < a && b < c) return {b, c, a};
  if (c < a && c < b) return {c, a, b};
  return {a, b, c};
}

}  // namespace

std::vector<SymmetryPlane> symmetry_planes(const Eigen::Ref<const Eigen::VectorXd>& masses,
                                           const Eigen::Ref<const PointPositions>& positions, double tolerance) {
  require_positive(tolerance, "tolerance");
  if (masses.size() != positions.rows() || masses.size() == 0) {
    throw_invalid("positions", "one row per mass (" + std::to_string(masses.size()) + " masses, n >= 1)",
                  std::to_string(positions.rows()) + " rows");
  }
  for (Index i = 0; i < masses.size(); ++i) require_positive(masses(i), "masses[" + std::to_string(i) + "]");
  require_finite(positions, "positions");
  const SpatialInertia body = from_point_masses(masses, positions);
  const PointSet s(body.com(), positions, std::vector<double>(masses.data(), masses.data() + masses.size()),
                   tolerance);
  return verified_planes(s, body.com(), body.inertia_com(), [](const std::vector<Index>&) { return true; });
}

std::vector<SymmetryPlane> mesh_symmetry_planes(const Eigen::Ref<const MeshVertices>& vertices,
                                                const Eigen::Ref<const MeshFaces>& faces, double tolerance) {
  require_positive(tolerance, "tolerance");
  require_finite(vertices, "vertices");
  const SpatialInertia body = solid_mesh(vertices, faces, Density{1.0});  // checks the mesh
  const PointSet s(body.com(), vertices, std::vector<double>(vertices.rows(), 1.0), tolerance);
  std::set<std::array<std::int64_t, 3>> face_set;
  for (Index f = 0; f < faces.rows(); ++f) face_set.insert(cyclic_key(faces(f, 0), faces(f, 1), faces(f, 2)));
  // the image of face (a, b, c) is (s(a), s(c), s(b)): the reflection reverses the orientation
  const auto faces_map = [&](const std::vector<Index>& sigma) {
    for (Index f = 0; f < faces.rows(); ++f) {
      const auto key = cyclic_key(sigma[faces(f, 0)], sigma[faces(f, 2)], sigma[faces(f, 1)]);
      if (face_set.count(key) == 0) return false;
    }
    return true;
  };
  return verified_planes(s, body.com(), body.inertia_com(), faces_map);
}

}  // namespace rigiddyn
