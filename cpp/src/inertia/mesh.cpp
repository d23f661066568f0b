#include "rigiddyn/inertia/mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
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

void require_valid_indices(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices) {
  if (faces.rows() == 0) throw_invalid("faces", "at least one face", "0 faces");
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const auto a = faces(f, 0), b = faces(f, 1), c = faces(f, 2);
    for (const auto i : {a, b, c}) {
      if (i < 0 || i >= n_vertices) {
        throw_invalid("faces[" + std::to_string(f) + "]", "vertex indices in [0, " + std::to_string(n_vertices) + ")",
                      i);
      }
    }
    if (a == b || b == c || c == a) {
      throw_invalid("faces[" + std::to_string(f) + "]", "three distinct vertex indices",
                    edge_string(a, b) + ", " + std::to_string(c));
    }
  }
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

}  // namespace

void require_closed_oriented_mesh(const Eigen::Ref<const MeshFaces>& faces, Eigen::Index n_vertices) {
  require_valid_indices(faces, n_vertices);
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
      const std::string where = "edge " + (E.forward ? edge_string(v, E.other) : edge_string(E.other, v)) +
                                " of face " + std::to_string(E.face);
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
                    where + " traversed in the same direction by face " + std::to_string(twin_face) +
                        " (inconsistent orientation)");
    }
  }
}

double mesh_volume(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces) {
  require_finite(vertices, "vertices");
  require_valid_indices(faces, vertices.rows());
  return volume_moments(vertices, faces).measure;
}

SpatialInertia solid_mesh(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                          MassOrDensity md) {
  require_finite(vertices, "vertices");
  require_closed_oriented_mesh(faces, vertices.rows());
  const Moments M = volume_moments(vertices, faces);
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
                          MassOrDensity md) {
  require_finite(vertices, "vertices");
  require_valid_indices(faces, vertices.rows());
  const Moments M = area_moments(vertices, faces);
  const double extent = (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
  if (!(M.measure > 1e-12 * extent * extent)) {
    throw_invalid("vertices", "faces of nonzero total area", "area " + format_value(M.measure) + " m^2");
  }
  return from_moments(M, md.mass_of(M.measure));
}

}  // namespace rigiddyn
