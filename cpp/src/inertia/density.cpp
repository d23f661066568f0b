#include "rigiddyn/inertia/density.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {

void require_order(int order, const char* name) {
  if (order < 1 || order > 64) throw_invalid(name, "an integer in [1, 64]", order);
}

Eigen::VectorXd evaluate(const DensityFunction& rho, const QuadratureRule& rule) {
  Eigen::VectorXd values(rule.points.rows());
  for (Eigen::Index i = 0; i < values.size(); ++i) values(i) = rho(rule.points.row(i).transpose());
  return values;
}

}  // namespace

QuadratureRule gauss_legendre_1d(int n) {
  require_order(n, "order");
  // Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix of the Legendre recurrence,
  // off-diagonal k / sqrt(4 k^2 - 1); weight_i = 2 (first component of eigenvector i)^2
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J);
  QuadratureRule rule;
  rule.points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>::Zero(n, 3);
  rule.points.col(0) = eig.eigenvalues();
  rule.weights = 2.0 * eig.eigenvectors().row(0).transpose().cwiseAbs2();
  return rule;
}

QuadratureRule box_quadrature(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int order, int subdivisions) {
  require_finite(lower, "lower");
  require_finite(upper, "upper");
  if (!((upper - lower).minCoeff() > 0.0)) throw_invalid("upper", "> lower componentwise, lower = " + format_value(lower), upper);
  if (subdivisions < 1 || subdivisions > 64) throw_invalid("subdivisions", "an integer in [1, 64]", subdivisions);
  const QuadratureRule g = gauss_legendre_1d(order);
  // 1-D composite rule on [0, 1]: subdivisions cells of order points
  const int n1 = order * subdivisions;
  Eigen::VectorXd t(n1), wt(n1);
  for (int cell = 0; cell < subdivisions; ++cell) {
    for (int q = 0; q < order; ++q) {
      t(cell * order + q) = (cell + 0.5 * (g.points(q, 0) + 1.0)) / subdivisions;
      wt(cell * order + q) = 0.5 * g.weights(q) / subdivisions;
    }
  }
  const Eigen::Vector3d size = upper - lower;
  QuadratureRule rule;
  rule.points.resize(static_cast<Eigen::Index>(n1) * n1 * n1, 3);
  rule.weights.resize(rule.points.rows());
  Eigen::Index k = 0;
  for (int i = 0; i < n1; ++i)
    for (int j = 0; j < n1; ++j)
      for (int l = 0; l < n1; ++l, ++k) {
        rule.points.row(k) = (lower + size.cwiseProduct(Eigen::Vector3d(t(i), t(j), t(l)))).transpose();
        rule.weights(k) = wt(i) * wt(j) * wt(l) * size.prod();
      }
  return rule;
}

QuadratureRule mesh_quadrature(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                               int order) {
  require_finite(vertices, "vertices");
  require_closed_oriented_mesh(faces, vertices.rows());
  if (!(mesh_volume(vertices, faces) > 0.0)) {
    throw_invalid("faces", "outward orientation (positive volume)", "volume " + format_value(mesh_volume(vertices, faces)));
  }
  const QuadratureRule g = gauss_legendre_1d(order);
  const Eigen::VectorXd t = 0.5 * (g.points.col(0).array() + 1.0);  // nodes on [0, 1]
  const Eigen::VectorXd wt = 0.5 * g.weights;
  const Eigen::Vector3d o = vertices.colwise().mean().transpose();
  const Eigen::Index per_face = static_cast<Eigen::Index>(order) * order * order;
  QuadratureRule rule;
  rule.points.resize(faces.rows() * per_face, 3);
  rule.weights.resize(rule.points.rows());
  Eigen::Index k = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::Vector3d a = vertices.row(faces(f, 0)).transpose() - o;
    const Eigen::Vector3d b = vertices.row(faces(f, 1)).transpose() - o;
    const Eigen::Vector3d c = vertices.row(faces(f, 2)).transpose() - o;
    const double six_V = a.dot(b.cross(c));  // signed
    for (int i = 0; i < order; ++i)
      for (int j = 0; j < order; ++j)
        for (int l = 0; l < order; ++l, ++k) {
          const double u = t(i), v = t(j), w = t(l);
          const double l1 = u, l2 = (1.0 - u) * v, l3 = (1.0 - u) * (1.0 - v) * w;
          rule.points.row(k) = (o + l1 * a + l2 * b + l3 * c).transpose();
          rule.weights(k) = wt(i) * wt(j) * wt(l) * (1.0 - u) * (1.0 - u) * (1.0 - v) * six_V;
        }
  }
  return rule;
}

SpatialInertia integrate_density(const QuadratureRule& rule, const Eigen::Ref<const Eigen::VectorXd>& rho) {
  if (rho.size() != rule.weights.size()) {
    throw_invalid("rho", "one value per quadrature point (" + std::to_string(rule.weights.size()) + ")",
                  std::to_string(rho.size()) + " values");
  }
  for (Eigen::Index i = 0; i < rho.size(); ++i) {
    if (!(std::isfinite(rho(i)) && rho(i) >= 0.0)) {
      throw_invalid("rho", "finite values >= 0", format_value(rho(i)) + " at the point " +
                                                      format_value(Eigen::Vector3d(rule.points.row(i).transpose())));
    }
  }
  // moments about a reference point in the region (the mean point)
  const Eigen::Vector3d ref = rule.points.colwise().mean().transpose();
  double m = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < rho.size(); ++i) {
    const double dm = rule.weights(i) * rho(i);
    const Eigen::Vector3d d = rule.points.row(i).transpose() - ref;
    m += dm;                              // (4.56)
    first += dm * d;                      // (4.55)
    second += dm * (d * d.transpose());   // (4.70) via tr(C) 1 - C
  }
  require_positive(m, "mass (integral of rho)");
  return SpatialInertia::from_inertia_about_point(m, ref + first / m, inertia_from_second_moment(second), ref);
}

DensityIntegral compare_density_integrals(const QuadratureRule& low, const Eigen::Ref<const Eigen::VectorXd>& rho_low,
                                          const QuadratureRule& high, const Eigen::Ref<const Eigen::VectorXd>& rho_high) {
  const SpatialInertia lo = integrate_density(low, rho_low);
  const SpatialInertia hi = integrate_density(high, rho_high);
  return DensityIntegral{hi, std::abs(hi.mass() - lo.mass()), (hi.com() - lo.com()).norm(),
                         (hi.inertia_com() - lo.inertia_com()).norm(), rho_low.size() + rho_high.size()};
}

DensityIntegral integrate_density_over_box(const DensityFunction& rho, const Eigen::Vector3d& lower,
                                           const Eigen::Vector3d& upper, int order, int subdivisions) {
  require_order(order, "order");
  const QuadratureRule low = box_quadrature(lower, upper, order, subdivisions);
  const QuadratureRule high = box_quadrature(lower, upper, 2 * order, subdivisions);
  return compare_density_integrals(low, evaluate(rho, low), high, evaluate(rho, high));
}

DensityIntegral integrate_density_over_mesh(const DensityFunction& rho, const Eigen::Ref<const MeshVertices>& vertices,
                                            const Eigen::Ref<const MeshFaces>& faces, int order) {
  require_order(order, "order");
  const QuadratureRule low = mesh_quadrature(vertices, faces, order);
  const QuadratureRule high = mesh_quadrature(vertices, faces, 2 * order);
  return compare_density_integrals(low, evaluate(rho, low), high, evaluate(rho, high));
}

}  // namespace rigiddyn
