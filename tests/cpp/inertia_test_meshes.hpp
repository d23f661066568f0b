// Test meshes for the inertia tests: surfaces of revolution about z from a profile (r, z) running
// from a pole on the axis (r = 0) to another, outward oriented; a box; a tetrahedron.
#pragma once
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "rigiddyn/inertia/mesh.hpp"

namespace rigiddyn::test {

struct Mesh {
  MeshVertices V;
  MeshFaces F;
};

// profile: (r_k, z_k), first and last with r = 0 (the poles); n segments around z.
inline Mesh revolution_mesh(const std::vector<std::pair<double, double>>& profile, int n) {
  const int rings = static_cast<int>(profile.size()) - 2;
  Mesh m;
  m.V.resize(2 + rings * n, 3);
  m.V.row(0) << 0, 0, profile.front().second;
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < n; ++j) {
      const double t = 2 * M_PI * j / n, r = profile[k + 1].first;
      m.V.row(1 + k * n + j) << r * std::cos(t), r * std::sin(t), profile[k + 1].second;
    }
  const int top = 1 + rings * n;
  m.V.row(top) << 0, 0, profile.back().second;
  std::vector<std::array<std::int64_t, 3>> F;
  const auto ring = [n](int k, int j) { return 1 + k * n + (j % n); };
  for (int j = 0; j < n; ++j) {
    F.push_back({0, ring(0, j + 1), ring(0, j)});
    for (int k = 0; k + 1 < rings; ++k) {
      F.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      F.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
    }
    F.push_back({top, ring(rings - 1, j), ring(rings - 1, j + 1)});
  }
  m.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (size_t i = 0; i < F.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) << F[i][0], F[i][1], F[i][2];
  return m;
}

// Sphere of radius r: n_lat latitude bands, n segments.
inline Mesh sphere_mesh(double r, int n_lat, int n) {
  std::vector<std::pair<double, double>> p;
  for (int k = 0; k <= n_lat; ++k) {
    const double phi = M_PI * k / n_lat;
    p.emplace_back(k == 0 || k == n_lat ? 0.0 : r * std::sin(phi), -r * std::cos(phi));
  }
  return revolution_mesh(p, n);
}

// Box centred at the origin with edges `size`, outward oriented (12 triangles).
inline Mesh box_mesh(const Eigen::Vector3d& size) {
  Mesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i)
    m.V.row(i) << ((i & 1) ? 0.5 : -0.5) * size(0), ((i & 2) ? 0.5 : -0.5) * size(1), ((i & 4) ? 0.5 : -0.5) * size(2);
  m.F.resize(12, 3);
  m.F << 0, 2, 1, 1, 2, 3,  // z-
      4, 5, 6, 5, 7, 6,      // z+
      0, 1, 4, 1, 5, 4,      // y-
      2, 6, 3, 3, 6, 7,      // y+
      0, 4, 2, 2, 4, 6,      // x-
      1, 3, 5, 3, 7, 5;      // x+
  return m;
}

}  // namespace rigiddyn::test
