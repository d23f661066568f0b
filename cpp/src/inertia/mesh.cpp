#include "rigiddyn/inertia/mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {

// Integrals over the mesh relative to the reference point `origin`: measure (volume or area),
// first moment int d and second moment int d d^T.
struct Moments {
  Eigen::Vector3d origin;
  double measure = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};

std::string edge_string(std::int64_t i, std::int64_t j) {
  return "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

void require_index_range(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices) {
  if (faces.rows() == 0) throw_invalid("faces", "at least one face", "0 faces");
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto i = faces(f, k);
      if (i < 0 || i >= n_vertices) {
        throw_invalid("faces[" + std::to_string(f) + "]", "vertex indices in [0, " + std::to_string(n_vertices) + ")",
                      i);
      }
    }
  }
}

void require_valid_indices(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices) {
  require_index_range(faces, n_vertices);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const auto a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
    if (a == b || b == c || c == a) {
      throw_invalid("faces[" + std::to_string(f) + "]", "three distinct vertex indices",
                    edge_string(a, b) + ", " + std::to_string(c));
    }
  }
}

// Union-find over vertex indices whose root is the lowest index of its set.
struct LowestIndexSets {
  std::vector<Eigen::Index> parent;
  explicit LowestIndexSets(Eigen::Index n) : parent(static_cast<size_t>(n)) {
    std::iota(parent.begin(), parent.end(), Eigen::Index{0});
  }
  Eigen::Index find(Eigen::Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
    return i;
  }
  void join(Eigen::Index a, Eigen::Index b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// A vertex in the weld grid: its cell (three 21-bit indices packed) and coordinates.
struct GridVertex {
  std::uint64_t cell;
  double x, y, z;
  Eigen::Index index;
  bool operator<(const GridVertex& o) const {
    return std::tie(cell, x, y, z, index) < std::tie(o.cell, o.x, o.y, o.z, o.index);
  }
  bool same_position(const GridVertex& o) const { return x == o.x && y == o.y && z == o.z; }
};

constexpr int grid_bits = 21;  // cells per axis < 2^21

// For each vertex, the lowest index of its weld cluster (header). Grid cells of side
// cell >= tolerance (at most 2^21 per axis), sorted by (cell, x, y, z): exact copies are adjacent
// and joined directly; distinct positions are compared, within a cell, with those whose x is within
// tolerance (a sweep), and across cells only when the position lies within tolerance of that face
// (or edge or corner) of its cell, with the neighbouring cell's positions whose x is within tolerance.
std::vector<Eigen::Index> weld_clusters(const Eigen::Ref<const MeshVertices>& V, double tolerance) {
  const Eigen::Index n = V.rows();
  LowestIndexSets sets(n);
  if (tolerance > 0.0 && n > 1) {
    const Eigen::RowVector3d lo = V.colwise().minCoeff();
    const double extent = (V.colwise().maxCoeff() - lo).maxCoeff();
    const double cell = std::max(tolerance, std::ldexp(extent, -(grid_bits - 1)));
    const double margin = tolerance / cell + 1e-9;  // a fraction of a cell, with room for rounding
    std::vector<GridVertex> grid(static_cast<size_t>(n));
    std::vector<Eigen::Vector3d> fraction(static_cast<size_t>(n));  // position within its cell, [0, 1)
    for (Eigen::Index i = 0; i < n; ++i) {
      std::uint64_t packed = 0;
      for (int k = 0; k < 3; ++k) {
        const double u = (V(i, k) - lo(k)) / cell;
        const double c = std::min(std::floor(u), std::ldexp(1.0, grid_bits) - 1);
        fraction[i](k) = u - c;
        packed |= static_cast<std::uint64_t>(c) << (grid_bits * k);
      }
      grid[i] = {packed, V(i, 0), V(i, 1), V(i, 2), i};
    }
    std::sort(grid.begin(), grid.end());
    // distinct positions (sites) in sorted order, exact copies joined to the first
    std::vector<GridVertex> sites;
    for (const GridVertex& g : grid) {
      if (!sites.empty() && sites.back().cell == g.cell && sites.back().same_position(g)) {
        sets.join(sites.back().index, g.index);
      } else {
        sites.push_back(g);
      }
    }
    const auto close = [&](const GridVertex& a, const GridVertex& b) {
      return Eigen::Vector3d(a.x - b.x, a.y - b.y, a.z - b.z).norm() <= tolerance;
    };
    // compares site a with the sites of cell `other` whose x is in [a.x - tolerance, a.x + tolerance]
    const auto compare_with_cell = [&](const GridVertex& a, std::uint64_t other) {
      auto it = std::lower_bound(sites.begin(), sites.end(), GridVertex{other, a.x - tolerance, -INFINITY, -INFINITY, 0});
      for (; it != sites.end() && it->cell == other && it->x <= a.x + tolerance; ++it)
        if (close(a, *it)) sets.join(a.index, it->index);
    };
    for (size_t s = 0; s < sites.size(); ++s) {
      const GridVertex& a = sites[s];
      for (size_t t = s + 1; t < sites.size() && sites[t].cell == a.cell && sites[t].x <= a.x + tolerance; ++t)
        if (close(a, sites[t])) sets.join(a.index, sites[t].index);
      const Eigen::Vector3d& f = fraction[static_cast<size_t>(a.index)];
      int reach[3][2];  // per axis, the offsets -1 / +1 allowed (near that face of the cell)
      for (int k = 0; k < 3; ++k) {
        reach[k][0] = f(k) <= margin ? -1 : 0;
        reach[k][1] = f(k) >= 1.0 - margin ? 1 : 0;
      }
      for (int dx = reach[0][0]; dx <= reach[0][1]; ++dx)
        for (int dy = reach[1][0]; dy <= reach[1][1]; ++dy)
          for (int dz = reach[2][0]; dz <= reach[2][1]; ++dz) {
            const int d[3] = {dx, dy, dz};
            if (dx == 0 && dy == 0 && dz == 0) continue;
            std::uint64_t other = 0;
            bool inside = true;
            for (int k = 0; k < 3; ++k) {
              const std::int64_t c = static_cast<std::int64_t>((a.cell >> (grid_bits * k)) & ((1u << grid_bits) - 1)) + d[k];
              inside = inside && c >= 0 && c < (std::int64_t{1} << grid_bits);
              other |= static_cast<std::uint64_t>(c < 0 ? 0 : c) << (grid_bits * k);
            }
            if (inside && other > a.cell) compare_with_cell(a, other);  // each pair of cells from one side
          }
    }
  }
  std::vector<Eigen::Index> root(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) root[i] = sets.find(i);
  return root;
}

// The mean of the vertices: a reference point inside the body keeps the signed sums' cancellation small.
Eigen::Vector3d vertex_mean(const Eigen::Ref<const MeshVertices>& vertices) {
  return vertices.colwise().mean().transpose();
}

Moments volume_moments(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces) {
  Moments M;
  M.origin = vertex_mean(vertices);
  double s_xx = 0, s_yy = 0, s_zz = 0, s_xy = 0, s_yz = 0, s_zx = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = vertices.row(faces(f, 0)).transpose() - M.origin;
    const Eigen::Vector3d b = vertices.row(faces(f, 1)).transpose() - M.origin;
    const Eigen::Vector3d c = vertices.row(faces(f, 2)).transpose() - M.origin;
    const double V = a.dot(b.cross(c)) / 6.0;  // signed tetrahedron (o, a, b, c)
    const Eigen::Vector3d s = a + b + c;
    M.measure += V;
    M.first += V * s;
    // V/20 (a a^T + b b^T + c c^T + s s^T), six distinct entries
    const double k = V / 20.0;
    s_xx += k * (a.x() * a.x() + b.x() * b.x() + c.x() * c.x() + s.x() * s.x());
    s_yy += k * (a.y() * a.y() + b.y() * b.y() + c.y() * c.y() + s.y() * s.y());
    s_zz += k * (a.z() * a.z() + b.z() * b.z() + c.z() * c.z() + s.z() * s.z());
    s_xy += k * (a.x() * a.y() + b.x() * b.y() + c.x() * c.y() + s.x() * s.y());
    s_yz += k * (a.y() * a.z() + b.y() * b.z() + c.y() * c.z() + s.y() * s.z());
    s_zx += k * (a.z() * a.x() + b.z() * b.x() + c.z() * c.x() + s.z() * s.x());
  }
  M.first /= 4.0;
  M.second << s_xx, s_xy, s_zx, s_xy, s_yy, s_yz, s_zx, s_yz, s_zz;
  return M;
}

Moments area_moments(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces) {
  Moments M;
  M.origin = vertex_mean(vertices);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = vertices.row(faces(f, 0)).transpose() - M.origin;
    const Eigen::Vector3d b = vertices.row(faces(f, 1)).transpose() - M.origin;
    const Eigen::Vector3d c = vertices.row(faces(f, 2)).transpose() - M.origin;
    const double A = 0.5 * (b - a).cross(c - a).norm();
    const Eigen::Vector3d s = a + b + c;
    M.measure += A;
    M.first += A / 3.0 * s;
    M.second += A / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  return M;
}

// mass m spread over the measured region with the given moments.
SpatialInertia from_moments(const Moments& M, double m) {
  const double rho = m / M.measure;
  const Eigen::Vector3d c = M.first / M.measure;  // Rigid-body notes (4.55), relative to origin
  return SpatialInertia::from_inertia_about_point(m, M.origin + c, inertia_from_second_moment(rho * M.second),
                                                  M.origin);
}

// The closed, consistently oriented check of require_closed_oriented_mesh (indices already valid);
// messages name vertex v as vertex_name[v] and face f as face_name[f] (the input's indices).
void require_closed(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices,
                    const std::vector<Eigen::Index>& vertex_name, const std::vector<Eigen::Index>& face_name) {
  // bucket the 3f half-edges by their smaller vertex (counting sort, linear time); within a bucket
  // (a vertex's few edges) each undirected edge must occur exactly twice, once in each direction
  struct HalfEdge {
    std::int64_t other;  // the larger vertex
    std::int64_t face;
    bool forward;        // traversed from the smaller vertex to the larger
  };
  std::vector<std::int64_t> start(static_cast<size_t>(n_vertices) + 1, 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++start[static_cast<size_t>(std::min(faces(f, k), faces(f, (k + 1) % 3))) + 1];
  for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<HalfEdge> edges(static_cast<size_t>(3 * faces.rows()));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t i = faces(f, k), j = faces(f, (k + 1) % 3);
      edges[static_cast<size_t>(fill[static_cast<size_t>(std::min(i, j))]++)] = {std::max(i, j), f, i < j};
    }
  for (std::int64_t v = 0; v < n_vertices; ++v) {
    const auto first = static_cast<size_t>(start[static_cast<size_t>(v)]), last = static_cast<size_t>(start[static_cast<size_t>(v) + 1]);
    for (size_t a = first; a < last; ++a) {
      const HalfEdge& E = edges[a];
      int forward = 0, backward = 0;
      std::int64_t twin_face = -1;
      for (size_t b = first; b < last; ++b) {
        if (edges[b].other != E.other) continue;
        (edges[b].forward ? forward : backward) += 1;
        if (b != a) twin_face = edges[b].face;
      }
      if (forward == 1 && backward == 1) continue;
      const std::int64_t i = vertex_name[static_cast<size_t>(v)], j = vertex_name[static_cast<size_t>(E.other)];
      const std::string where = "edge " + (E.forward ? edge_string(i, j) : edge_string(j, i)) + " of face " +
                                std::to_string(face_name[static_cast<size_t>(E.face)]);
      if (forward + backward == 1) {
        throw_invalid("faces", "a closed mesh (every edge shared by exactly two faces)",
                      where + " belongs to no other face (open boundary)");
      }
      if (forward + backward > 2) {
        throw_invalid("faces", "a closed mesh (every edge shared by exactly two faces)",
                      where + " is shared by " + std::to_string(forward + backward) + " faces (non-manifold edge)");
      }
      // two half-edges in the same direction
      throw_invalid("faces", "consistently oriented faces (each edge traversed once in each direction)",
                    where + " traversed in the same direction by face " +
                        std::to_string(face_name[static_cast<size_t>(twin_face)]) +
                        " (inconsistent orientation)");
    }
  }
}

std::vector<Eigen::Index> identity(Eigen::Index n) {
  std::vector<Eigen::Index> v(static_cast<size_t>(n));
  std::iota(v.begin(), v.end(), Eigen::Index{0});
  return v;
}

// weld_tolerance as given (nullopt: the default), checked finite and >= 0.
double resolve_weld_tolerance(const Eigen::Ref<const MeshVertices>& vertices, std::optional<double> weld_tolerance) {
  if (!weld_tolerance) return default_weld_tolerance(vertices);
  if (!(std::isfinite(*weld_tolerance) && *weld_tolerance >= 0.0)) {
    throw_invalid("weld_tolerance", "a finite distance >= 0 [m] (0: no welding)", *weld_tolerance);
  }
  return *weld_tolerance;
}

// The input welded for solid_mesh / mesh_shell (weld_vertices after checking the input as before).
WeldedMesh welded_input(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                        std::optional<double> weld_tolerance, WeldReport* report) {
  require_finite(vertices, "vertices");
  const double tolerance = resolve_weld_tolerance(vertices, weld_tolerance);
  WeldedMesh w = weld_vertices(vertices, faces, tolerance);
  if (w.faces.rows() == 0) {
    throw_invalid("faces", "at least one face with three distinct vertices after welding",
                  std::to_string(faces.rows()) + " faces, all degenerate (weld tolerance " + format_value(tolerance) +
                      " m)");
  }
  if (report != nullptr) *report = w.report;
  return w;
}

// The closed-mesh check on the welded mesh; its message says how the mesh was welded, or, welding
// off, how many vertices have a copy within the default tolerance (STL-like duplicates).
void require_closed_after_weld(const WeldedMesh& w, const Eigen::Ref<const MeshVertices>& input_vertices,
                               const Eigen::Ref<const MeshFaces>& input_faces) {
  try {
    require_closed(w.faces, w.vertices.rows(), w.vertex_index, w.face_index);
  } catch (const std::invalid_argument& error) {
    std::string note;
    if (w.report.tolerance > 0.0) {
      note = " (after welding " + std::to_string(w.report.welded_vertices) + " vertices within " +
             format_value(w.report.tolerance) + " m)";
    } else {
      const Eigen::Index copies =
          weld_vertices(input_vertices, input_faces, default_weld_tolerance(input_vertices)).report.welded_vertices;
      if (copies > 0) {
        note = "; welding is off (weld_tolerance=0) and " + std::to_string(copies) +
               " vertices lie within the default weld tolerance " +
               format_value(default_weld_tolerance(input_vertices)) + " m of another (duplicates, as in STL files)";
      }
    }
    throw std::invalid_argument(error.what() + note);
  }
}

}  // namespace

double default_weld_tolerance(const Eigen::Ref<const MeshVertices>& vertices) {
  if (vertices.rows() == 0) return 0.0;
  return weld_relative_tolerance * (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

WeldedMesh weld_vertices(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                         double tolerance) {
  require_finite(vertices, "vertices");
  if (!(std::isfinite(tolerance) && tolerance >= 0.0)) {
    throw_invalid("tolerance", "a finite distance >= 0 [m]", tolerance);
  }
  require_valid_indices(faces, vertices.rows());  // a face repeating an index is bad input, not a weld
  const std::vector<Eigen::Index> root = weld_clusters(vertices, tolerance);
  WeldedMesh w;
  w.report.tolerance = tolerance;
  std::vector<Eigen::Index> new_index(root.size());
  for (Eigen::Index i = 0; i < vertices.rows(); ++i) {
    if (root[i] != i) continue;
    new_index[i] = static_cast<Eigen::Index>(w.vertex_index.size());
    w.vertex_index.push_back(i);
  }
  w.report.welded_vertices = vertices.rows() - static_cast<Eigen::Index>(w.vertex_index.size());
  w.vertices.resize(static_cast<Eigen::Index>(w.vertex_index.size()), 3);
  for (size_t k = 0; k < w.vertex_index.size(); ++k) w.vertices.row(k) = vertices.row(w.vertex_index[k]);
  w.faces.resize(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const std::int64_t a = new_index[root[faces(f, 0)]], b = new_index[root[faces(f, 1)]],
                       c = new_index[root[faces(f, 2)]];
    if (a == b || b == c || c == a) continue;  // degenerate after welding
    w.faces.row(static_cast<Eigen::Index>(w.face_index.size())) << a, b, c;
    w.face_index.push_back(f);
  }
  w.faces.conservativeResize(static_cast<Eigen::Index>(w.face_index.size()), 3);
  w.report.dropped_faces = faces.rows() - w.faces.rows();
  return w;
}

void require_closed_oriented_mesh(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices) {
  require_valid_indices(faces, n_vertices);
  require_closed(faces, n_vertices, identity(n_vertices), identity(faces.rows()));
}

double mesh_volume(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces) {
  require_finite(vertices, "vertices");
  require_valid_indices(faces, vertices.rows());
  return volume_moments(vertices, faces).measure;
}

SpatialInertia solid_mesh(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md, std::optional<double> weld_tolerance, WeldReport* report) {
  const WeldedMesh w = welded_input(vertices, faces, weld_tolerance, report);
  require_closed_after_weld(w, vertices, faces);
  const Moments M = volume_moments(w.vertices, w.faces);
  const double extent = (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
  if (M.measure < 0.0) {
    throw_invalid("faces", "outward orientation (counter-clockwise seen from outside, positive volume)",
                  "volume " + format_value(M.measure) + " m^3: the faces are oriented inward; reverse their winding");
  }
  if (!(M.measure > 1e-12 * extent * extent * extent)) {
    throw_invalid("vertices", "a mesh enclosing a nonzero volume", "volume " + format_value(M.measure) + " m^3");
  }
  return from_moments(M, md.mass_of(M.measure));
}

SpatialInertia mesh_shell(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md, std::optional<double> weld_tolerance, WeldReport* report) {
  const WeldedMesh w = welded_input(vertices, faces, weld_tolerance, report);
  const Moments M = area_moments(w.vertices, w.faces);
  const double extent = (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
  if (!(M.measure > 1e-12 * extent * extent)) {
    throw_invalid("vertices", "faces of nonzero total area", "area " + format_value(M.measure) + " m^2");
  }
  return from_moments(M, md.mass_of(M.measure));
}

}  // namespace rigiddyn
