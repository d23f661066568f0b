// Mass properties of a body of variable density rho(r) [kg/m^3] by numerical quadrature of
// Rigid-body notes (4.56) m = int rho dV, (4.55) c = (1/m) int rho r dV and (4.70) the inertia integral
// (written as I = tr(C) 1 - C with C = int rho d d^T dV, d = r - c), with an error estimate.
//
// Rules: tensor-product Gauss-Legendre (nodes and weights by Golub-Welsch, Eigen's symmetric
// eigensolver) over a box split into subdivisions^3 cells; over a closed mesh, the signed tetrahedra
// (o, a, b, c) of mesh.hpp, each mapped from the unit cube by collapsed coordinates
// (l1 = u, l2 = (1-u) v, l3 = (1-u)(1-v) w, Jacobian (1-u)^2 (1-v) 6V).
// Error estimate: the same integral with twice the order per axis; the higher-order result is
// returned and the difference reported (an upper estimate of its error when rho is smooth).
// On a mesh the signed tetrahedra reach the mesh's reference point o (mean vertex), so for a
// non-convex mesh rho is also evaluated outside the body, where the contributions cancel: rho must
// be defined and smooth on the convex hull of the mesh.
#pragma once
#include <Eigen/Core>

#include <functional>

#include "rigiddyn/inertia/mesh.hpp"
#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace rigiddyn {

// rho(r) [kg/m^3] at the point r [m] in the frame of expression; finite and >= 0.
using DensityFunction = std::function<double(const Eigen::Vector3d&)>;

// Quadrature points (n, 3) [m] and weights (n,) [m^3]: int f dV ~ sum_i weights(i) f(points.row(i)).
struct QuadratureRule {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> points;
  Eigen::VectorXd weights;
};

// Gauss-Legendre nodes and weights on [-1, 1], n >= 1 points (exact for degree 2n - 1).
// The nodes are in column 0 of `points` (columns 1-2 zero).
QuadratureRule gauss_legendre_1d(int n);

// The box [lower, upper] (lower < upper componentwise) split into subdivisions^3 cells, each with an
// order^3 Gauss-Legendre rule.
QuadratureRule box_quadrature(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int order,
                              int subdivisions = 1);
// The solid bounded by a closed, outward-oriented mesh (checked, mesh.hpp): order^3 points per face.
QuadratureRule mesh_quadrature(const Eigen::Ref<const MeshVertices>& vertices, const Eigen::Ref<const MeshFaces>& faces,
                               int order);

struct DensityIntegral {
  SpatialInertia inertia;  // from the higher-order rule
  double mass_error;       // |m_high - m_low| [kg]
  double com_error;        // |c_high - c_low| [m]
  double inertia_error;    // Frobenius norm of I_C,high - I_C,low [kg m^2]
  Eigen::Index evaluations;  // number of calls of rho
};

// The mass properties from a rule and rho at its points (n,) [kg/m^3] (finite, >= 0, positive mass).
SpatialInertia integrate_density(const QuadratureRule& rule, const Eigen::Ref<const Eigen::VectorXd>& rho);
// The result of the `high` rule with the differences to the `low` rule as error estimate.
DensityIntegral compare_density_integrals(const QuadratureRule& low, const Eigen::Ref<const Eigen::VectorXd>& rho_low,
                                          const QuadratureRule& high, const Eigen::Ref<const Eigen::VectorXd>& rho_high);

// rho over the box [lower, upper] with orders `order` and 2 * order (see above).
DensityIntegral integrate_density_over_box(const DensityFunction& rho, const Eigen::Vector3d& lower,
                                           const Eigen::Vector3d& upper, int order = 6, int subdivisions = 2);
// rho over the solid bounded by a closed mesh, orders `order` and 2 * order.
DensityIntegral integrate_density_over_mesh(const DensityFunction& rho, const Eigen::Ref<const MeshVertices>& vertices,
                                            const Eigen::Ref<const MeshFaces>& faces, int order = 4);

}  // namespace rigiddyn
