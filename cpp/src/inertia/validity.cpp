#include "rigiddyn/inertia/validity.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

namespace {

constexpr double asymmetry_relative_tolerance = 1e-12;  // of max |I_ij|: a symmetric inertia up to round-off

std::string vector_string(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << v(0) << ", " << v(1) << ", " << v(2) << ")";
  return out.str();
}

}  // namespace

bool InertiaReport::valid(InertiaCheck check) const {
  const bool base = mass_positive && finite && symmetric && positive_semidefinite;
  return check == InertiaCheck::allow_unrealizable ? base : base && triangle_inequality;
}

std::string InertiaReport::summary() const {
  std::ostringstream out;
  out.precision(17);
  out << "principal moments " << vector_string(principal_moments) << " kg m^2, triangle margins "
      << vector_string(triangle_margins) << " (I0 + I1 - I2 = " << triangle_margins(2)
      << "), condition number " << condition_number << ", tolerance " << tolerance;
  if (!finite) out << "; not finite";
  if (!symmetric) {
    out << "; not symmetric (max |I - I^T| = " << asymmetry << " > symmetry tolerance " << asymmetry_tolerance
        << " = " << asymmetry_relative_tolerance << " max |I_ij|)";
  }
  if (!positive_semidefinite) out << "; not positive semi-definite (I0 = " << principal_moments(0) << ")";
  if (!triangle_inequality) {
    out << "; violates the triangle inequality I0 + I1 >= I2 (no real body has this inertia: "
           "repair it with nearest_valid_inertia, or opt in on purpose with the check allow_unrealizable of "
           "InertiaCheck)";
  }
  return out.str();
}

InertiaReport inertia_report(double mass, const Eigen::Matrix3d& inertia_com, double scale) {
  InertiaReport r;
  r.mass = mass;
  r.mass_positive = std::isfinite(mass) && mass > 0.0;
  r.finite = inertia_com.allFinite();
  if (!r.finite) return r;
  r.asymmetry = (inertia_com - inertia_com.transpose()).cwiseAbs().maxCoeff();
  r.asymmetry_tolerance = asymmetry_relative_tolerance * inertia_com.cwiseAbs().maxCoeff();
  r.symmetric = r.asymmetry <= r.asymmetry_tolerance;
  const Eigen::Matrix3d S = 0.5 * (inertia_com + inertia_com.transpose());
  r.principal_moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(S, Eigen::EigenvaluesOnly).eigenvalues();
  const Eigen::Vector3d& I = r.principal_moments;
  r.triangle_margins << I(1) + I(2) - I(0), I(0) + I(2) - I(1), I(0) + I(1) - I(2);
  r.condition_number = I(0) > 0.0 ? I(2) / I(0) : std::numeric_limits<double>::infinity();
  r.tolerance = inertia_relative_tolerance * std::max(scale, std::abs(S.trace()));
  r.positive_semidefinite = I(0) >= -r.tolerance;
  r.triangle_inequality = r.triangle_margins(2) >= -r.tolerance;
  return r;
}

Eigen::Matrix3d checked_inertia(double mass, const Eigen::Matrix3d& inertia_com, InertiaCheck check, double scale,
                                const std::string& name) {
  require_positive(mass, "mass");
  require_finite(inertia_com, name);
  const InertiaReport r = inertia_report(mass, inertia_com, scale);
  if (!r.valid(check)) {
    const std::string expected = check == InertiaCheck::physical
                                     ? "a symmetric inertia satisfying the triangle inequality"
                                     : "a symmetric positive semi-definite inertia";
    throw std::invalid_argument(name + ": expected " + expected + ", got " + format_value(inertia_com) + " [" +
                                r.summary() + "]");
  }
  const Eigen::Matrix3d S = 0.5 * (inertia_com + inertia_com.transpose());
  const bool round_off_violation = r.triangle_margins(2) < 0.0 || r.principal_moments(0) < 0.0;
  return (check == InertiaCheck::physical && round_off_violation) ? nearest_valid_inertia(S) : S;
}

Eigen::Matrix3d nearest_valid_inertia(const Eigen::Matrix3d& inertia) {
  require_finite(inertia, "inertia");
  const Eigen::Matrix3d S = 0.5 * (inertia + inertia.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S);
  const Eigen::Vector3d lambda = eig.eigenvalues();
  // the cone {A x >= 0}: row k is (1, 1, 1) - 2 e_k, i.e. x_i + x_j - x_k >= 0
  const Eigen::Matrix3d A = Eigen::Matrix3d::Ones() - 2.0 * Eigen::Matrix3d::Identity();
  const double slack = 1e-14 * lambda.cwiseAbs().maxCoeff();
  if ((A * lambda).minCoeff() >= 0.0) return S;
  // projection onto a polyhedral cone: the projection onto the span orthogonal to the active rows,
  // for the active set whose result is feasible and closest (8 sets: enumerate them)
  Eigen::Vector3d best = Eigen::Vector3d::Zero();  // all three active: the apex
  double best_distance = lambda.norm();
  for (int set = 1; set < 7; ++set) {
    Eigen::MatrixXd active(0, 3);
    for (int k = 0; k < 3; ++k) {
      if (set & (1 << k)) {
        active.conservativeResize(active.rows() + 1, Eigen::NoChange);
        active.row(active.rows() - 1) = A.row(k);
      }
    }
    const Eigen::MatrixXd gram = active * active.transpose();
    const Eigen::Vector3d x = lambda - active.transpose() * gram.inverse() * (active * lambda);
    if ((A * x).minCoeff() >= -slack && (x - lambda).norm() < best_distance) {
      best = x;
      best_distance = (x - lambda).norm();
    }
  }
  const Eigen::Matrix3d& V = eig.eigenvectors();
  return V * best.asDiagonal() * V.transpose();
}

}  // namespace rigiddyn
