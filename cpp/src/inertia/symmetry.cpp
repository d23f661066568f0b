#include "rigiddyn/inertia/symmetry.hpp"

#include "canonical_sign.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
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

using detail::canonical_sign;

bool parallel(const Vector3d& a, const Vector3d& b, double angle) { return a.cross(b).norm() <= angle; }

// Tests every candidate normal n (duplicates skipped) with `accept(n)`; the accepted planes, each once.
template <typename Accept>
std::vector<SymmetryPlane> verified_planes(const PointSet& s, const Vector3d& com, const Matrix3d& inertia_com,
                                           Accept&& accept) {
  constexpr double same_plane_angle = 1e-6;  // [rad] normals closer than this report one plane
  // normals tested already, rounded to a grid of side `tolerance` (a duplicate across a grid line is
  // tested twice, harmlessly)
  std::set<std::array<std::int64_t, 3>> tested;
  std::vector<SymmetryPlane> planes;
  for (const Vector3d& candidate : candidate_normals(s, inertia_com)) {
    const Vector3d n = canonical_sign(candidate);
    const std::array<std::int64_t, 3> key = {std::llround(n(0) / s.tolerance), std::llround(n(1) / s.tolerance),
                                             std::llround(n(2) / s.tolerance)};
    if (!tested.insert(key).second) continue;
    const auto found = [&](const SymmetryPlane& p) { return parallel(n, p.normal, same_plane_angle); };
    if (std::any_of(planes.begin(), planes.end(), found)) continue;
    if (accept(n)) planes.push_back({n, com});
  }
  return planes;
}

// The vertices that some face uses (candidate normals come from them, header).
PointPositions referenced_vertices(const WeldedMesh& w) {
  std::vector<char> used(static_cast<size_t>(w.vertices.rows()), 0);
  for (Index f = 0; f < w.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<size_t>(w.faces(f, k))] = 1;
  PointPositions out(std::count(used.begin(), used.end(), 1), 3);
  Index row = 0;
  for (Index i = 0; i < w.vertices.rows(); ++i)
    if (used[static_cast<size_t>(i)]) out.row(row++) = w.vertices.row(i);
  return out;
}
size_t referenced_count(const WeldedMesh& w) { return static_cast<size_t>(referenced_vertices(w).rows()); }

// A convex polygon in a plane: a triangle clipped by the three edges of another has <= 6 corners.
struct Polygon {
  std::array<Eigen::Vector2d, 9> corner;
  int size = 0;
};

// Area [m^2] of the intersection of two triangles in a plane (Sutherland-Hodgman clipping of
// `subject` by the counter-clockwise `clip`; shoelace formula).
double intersection_area(const Polygon& subject_triangle, const Polygon& clip) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  Polygon subject = subject_triangle;
  for (int e = 0; e < clip.size && subject.size > 0; ++e) {
    const Eigen::Vector2d& p = clip.corner[e];
    const Eigen::Vector2d edge = clip.corner[(e + 1) % clip.size] - p;
    Polygon kept;
    for (int k = 0; k < subject.size; ++k) {
      const Eigen::Vector2d& a = subject.corner[k];
      const Eigen::Vector2d& b = subject.corner[(k + 1) % subject.size];
      const double sa = cross(edge, a - p), sb = cross(edge, b - p);  // >= 0: inside (left of the edge)
      if (sa >= 0.0) kept.corner[kept.size++] = a;
      if ((sa >= 0.0) != (sb >= 0.0)) kept.corner[kept.size++] = a + (b - a) * (sa / (sa - sb));
    }
    subject = kept;
  }
  double twice_area = 0.0;
  for (int k = 0; k < subject.size; ++k) twice_area += cross(subject.corner[k], subject.corner[(k + 1) % subject.size]);
  return 0.5 * std::max(twice_area, 0.0);
}

// The oriented boundary of the solid, faces indexed by their outward unit normal (grid of cells of
// side >= angle_tolerance, so that normals within it lie in the same or neighbouring cells).
//
// Symmetry test (header): the reflection sigma about the plane through the com with normal n maps
// the solid onto itself iff it maps the oriented boundary S into itself, sigma(S) subset S (sigma is
// an involution, so inclusion gives equality). Each face T is reflected (vertices sigma(a),
// sigma(c), sigma(b): outward again, normal sigma(n_T)); the part of sigma(T) covered by faces of S
// in the same plane (unit normals within angle_tolerance, offsets from the com within eps) with the
// same outward side is measured by clipping; the plane is accepted when every face's uncovered area
// is at most eps * perimeter(T), the strip that moving its vertices by eps [m] can open. Faces of a
// closed manifold mesh in one plane do not overlap, so the covered areas add up.
class Boundary {
 public:
  Boundary(const MeshVertices& V, const MeshFaces& F, const Vector3d& com, double eps, double angle_tolerance)
      : eps_(eps), angle_tolerance_(angle_tolerance), grid_(std::max(angle_tolerance, 1e-4)), com_(com) {
    for (Index f = 0; f < F.rows(); ++f) {
      Face face;
      for (int k = 0; k < 3; ++k) face.corner[k] = V.row(F(f, k)).transpose() - com;
      const Vector3d area_vector = 0.5 * (face.corner[1] - face.corner[0]).cross(face.corner[2] - face.corner[0]);
      face.area = area_vector.norm();
      if (!(face.area > 0.0)) continue;  // a zero-area face covers nothing and needs no cover
      face.normal = area_vector / face.area;
      face.offset = face.normal.dot(face.corner[0]);
      face.perimeter = (face.corner[1] - face.corner[0]).norm() + (face.corner[2] - face.corner[1]).norm() +
                       (face.corner[0] - face.corner[2]).norm();
      face.lower = face.corner[0].cwiseMin(face.corner[1]).cwiseMin(face.corner[2]);
      face.upper = face.corner[0].cwiseMax(face.corner[1]).cwiseMax(face.corner[2]);
      by_normal_[cell(face.normal)].push_back(faces_.size());
      faces_.push_back(face);
    }
  }

  bool reflection_lies_on_itself(const Vector3d& n) const {
    const auto reflect = [&n](const Vector3d& r) -> Vector3d { return r - 2.0 * n.dot(r) * n; };
    for (const Face& T : faces_) {
      Face image;
      image.corner = {reflect(T.corner[0]), reflect(T.corner[2]), reflect(T.corner[1])};
      image.normal = reflect(T.normal);
      image.offset = T.offset;  // sigma preserves distances to planes through the com
      image.lower = image.corner[0].cwiseMin(image.corner[1]).cwiseMin(image.corner[2]);
      image.upper = image.corner[0].cwiseMax(image.corner[1]).cwiseMax(image.corner[2]);
      if (covered_area(image, T.area - eps_ * T.perimeter) < T.area - eps_ * T.perimeter) return false;
    }
    return true;
  }

 private:
  struct Face {
    std::array<Vector3d, 3> corner;  // relative to the com [m]
    Vector3d normal;                 // outward unit normal
    double offset = 0.0;             // normal . corner [m]
    double area = 0.0, perimeter = 0.0;
    Vector3d lower, upper;           // bounding box
  };
  using Cell = std::array<std::int64_t, 3>;

  Cell cell(const Vector3d& normal) const {
    Cell c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<std::int64_t>(std::floor(normal(k) / grid_));
    return c;
  }

  // Area of `image` covered by the faces of the boundary in its plane, on the same side (the sum
  // stops once it reaches `enough`).
  double covered_area(const Face& image, double enough) const {
    const Vector3d& m = image.normal;
    const Vector3d e1 = m.unitOrthogonal(), e2 = m.cross(e1);  // (e1, e2, m) right-handed
    const auto in_plane = [&](const Vector3d& r) { return Eigen::Vector2d(e1.dot(r), e2.dot(r)); };
    const auto triangle = [&](const std::array<Vector3d, 3>& c) {
      Polygon t;
      t.corner[0] = in_plane(c[0]), t.corner[1] = in_plane(c[1]), t.corner[2] = in_plane(c[2]);
      t.size = 3;
      return t;
    };
    const Polygon subject = triangle(image.corner);
    // the faces in the image's plane, on its side, whose bounding box meets the image's
    std::vector<size_t> near;
    const Cell home = cell(m);
    int reach[3][2];  // per axis, the neighbouring cells within angle_tolerance of m
    for (int k = 0; k < 3; ++k) {
      const double fraction = m(k) / grid_ - static_cast<double>(home[k]);  // in [0, 1)
      reach[k][0] = fraction <= angle_tolerance_ / grid_ + 1e-9 ? -1 : 0;
      reach[k][1] = fraction >= 1.0 - angle_tolerance_ / grid_ - 1e-9 ? 1 : 0;
    }
    for (int dx = reach[0][0]; dx <= reach[0][1]; ++dx)
      for (int dy = reach[1][0]; dy <= reach[1][1]; ++dy)
        for (int dz = reach[2][0]; dz <= reach[2][1]; ++dz) {
          const auto it = by_normal_.find({home[0] + dx, home[1] + dy, home[2] + dz});
          if (it == by_normal_.end()) continue;
          for (const size_t g : it->second) {
            const Face& G = faces_[g];
            if ((G.normal - m).norm() > angle_tolerance_ || std::abs(G.offset - image.offset) > eps_) continue;
            if ((G.lower.array() > image.upper.array() + eps_).any() ||
                (image.lower.array() > G.upper.array() + eps_).any()) {
              continue;
            }
            near.push_back(g);
          }
        }
    // a face with the image's corners covers it whole (the common case: cheap, no clipping)
    for (const size_t g : near)
      if (same_corners(faces_[g], image)) return enough;
    double covered = 0.0;
    for (const size_t g : near) {
      covered += intersection_area(subject, triangle(faces_[g].corner));
      if (covered >= enough) break;
    }
    return covered;
  }

  // Whether every corner of `a` is within eps of a corner of `b` (both triangles).
  bool same_corners(const Face& a, const Face& b) const {
    return std::all_of(a.corner.begin(), a.corner.end(), [&](const Vector3d& p) {
      return std::any_of(b.corner.begin(), b.corner.end(), [&](const Vector3d& q) { return (p - q).norm() <= eps_; });
    });
  }

  double eps_, angle_tolerance_;
  double grid_;  // side of the grid of normals, >= angle_tolerance
  Vector3d com_;
  std::vector<Face> faces_;
  std::map<Cell, std::vector<size_t>> by_normal_;
};

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
  return verified_planes(s, body.com(), body.inertia_com(),
                         [&s](const Vector3d& n) { return !mirror_map(s, n).empty(); });
}

std::vector<SymmetryPlane> mesh_symmetry_planes(const Eigen::Ref<const MeshVertices>& vertices,
                                                const Eigen::Ref<const MeshFaces>& faces, double tolerance,
                                                std::optional<double> weld_tolerance) {
  require_positive(tolerance, "tolerance");
  const SpatialInertia body = solid_mesh(vertices, faces, Density{1.0}, weld_tolerance);  // checks the mesh
  const WeldedMesh w =
      weld_vertices(vertices, faces, weld_tolerance ? *weld_tolerance : default_weld_tolerance(vertices));
  const PointSet s(body.com(), referenced_vertices(w), std::vector<double>(referenced_count(w), 1.0), tolerance);
  const Boundary boundary(w.vertices, w.faces, body.com(), s.eps, tolerance);
  return verified_planes(s, body.com(), body.inertia_com(),
                         [&boundary](const Vector3d& n) { return boundary.reflection_lies_on_itself(n); });
}

}  // namespace rigiddyn
