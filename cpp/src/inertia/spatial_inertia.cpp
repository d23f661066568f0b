#include "rigiddyn/inertia/spatial_inertia.hpp"

#include <Eigen/Geometry>

#include <cmath>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn {

Eigen::Matrix3d point_inertia(double mass, const Eigen::Vector3d& r) {
  require_positive(mass, "mass");
  return mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

Eigen::Matrix3d inertia_from_second_moment(const Eigen::Matrix3d& C) {
  return C.trace() * Eigen::Matrix3d::Identity() - C;
}

SpatialInertia::SpatialInertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com,
                               InertiaCheck check)
    : mass_(mass), com_(com), inertia_com_(checked_inertia(mass, inertia_com, check)) {
  require_finite(com, "com");
}

SpatialInertia SpatialInertia::from_inertia_about_point(double mass, const Eigen::Vector3d& com,
                                                        const Eigen::Matrix3d& inertia_about_point,
                                                        const Eigen::Vector3d& point, InertiaCheck check) {
  require_positive(mass, "mass");
  require_finite(com, "com");
  require_finite(point, "point");
  require_finite(inertia_about_point, "inertia_about_point");
  // parallel axis, Craig: I_C = I_P - m (|r|^2 1 - r r^T), r = c - p
  const Eigen::Matrix3d I_C = inertia_about_point - point_inertia(mass, com - point);
  const double scale = std::abs(inertia_about_point.trace()) + 2.0 * mass * (com - point).squaredNorm();
  return SpatialInertia(mass, com,
                        checked_inertia(mass, I_C, check, scale, "inertia_about_point (shifted to the centre of mass)"),
                        Trusted{});
}

SpatialInertia SpatialInertia::from_inertia_about_origin(double mass, const Eigen::Vector3d& com,
                                                         const Eigen::Matrix3d& inertia_about_origin,
                                                         InertiaCheck check) {
  return from_inertia_about_point(mass, com, inertia_about_origin, Eigen::Vector3d::Zero(), check);
}

SpatialInertia SpatialInertia::from_matrix(const Matrix6d& matrix, InertiaCheck check) {
  require_finite(matrix, "matrix");
  const double m = matrix(3, 3);
  require_positive(m, "matrix (mass entry (3, 3))");
  const Eigen::Vector3d c = vee(matrix.block<3, 3>(0, 3)) / m;
  Matrix6d expected = Matrix6d::Zero();
  expected.block<3, 3>(0, 0) = matrix.block<3, 3>(0, 0);
  expected.block<3, 3>(0, 3) = m * hat(c);
  expected.block<3, 3>(3, 0) = m * hat(c).transpose();
  expected.block<3, 3>(3, 3) = m * Eigen::Matrix3d::Identity();
  if ((matrix - expected).cwiseAbs().maxCoeff() > 1e-12 * matrix.cwiseAbs().maxCoeff()) {
    throw_invalid("matrix", "a spatial inertia [[I_O, m hat(c)], [m hat(c)^T, m 1]]", matrix);
  }
  return from_inertia_about_origin(m, c, matrix.block<3, 3>(0, 0), check);
}

SpatialInertia SpatialInertia::point_mass(double mass, const Eigen::Vector3d& position) {
  return SpatialInertia(mass, position, Eigen::Matrix3d::Zero());
}

Eigen::Matrix3d SpatialInertia::inertia_about_point(const Eigen::Vector3d& point) const {
  return inertia_com_ + point_inertia(mass_, com_ - point);
}

Eigen::Matrix3d SpatialInertia::inertia_about_origin() const { return inertia_com_ + point_inertia(mass_, com_); }

Matrix6d SpatialInertia::matrix() const {
  const Eigen::Matrix3d c_hat = hat(com_);
  Matrix6d M;
  M << inertia_about_origin(), mass_ * c_hat, mass_ * c_hat.transpose(), mass_ * Eigen::Matrix3d::Identity();
  return M;
}

Force SpatialInertia::momentum(const Motion& twist) const {
  const Eigen::Vector3d& w = twist.angular;
  const Eigen::Vector3d& v = twist.linear;
  return Force(inertia_about_origin() * w + mass_ * com_.cross(v), mass_ * (v + w.cross(com_)));
}

double SpatialInertia::kinetic_energy(const Motion& twist) const { return 0.5 * twist.dot(momentum(twist)); }

Eigen::Vector3d SpatialInertia::angular_momentum_about_com(const Eigen::Vector3d& angular_velocity) const {
  return inertia_com_ * angular_velocity;
}

Eigen::Vector3d SpatialInertia::angular_momentum_about_point(const Eigen::Vector3d& angular_velocity,
                                                             const Eigen::Vector3d& com_velocity,
                                                             const Eigen::Vector3d& point) const {
  // Craig: H_P = r_PC x L + H_C
  return (com_ - point).cross(mass_ * com_velocity) + angular_momentum_about_com(angular_velocity);
}

namespace {
// R I R^T, symmetrised: the rounding of the product differs in the last bits between (i, j) and (j, i);
// the stored inertia stays exactly symmetric (as the constructors store it), so that rebuilding a
// body from its members (pickle, repr) gives it back bitwise.
Eigen::Matrix3d rotated_inertia(const Eigen::Matrix3d& R, const Eigen::Matrix3d& I) {
  const Eigen::Matrix3d RIRt = R * I * R.transpose();
  return 0.5 * (RIRt + RIRt.transpose());
}
}  // namespace

SpatialInertia SpatialInertia::rotated(const Eigen::Matrix3d& R_AB) const {
  const Eigen::Matrix3d R = checked_rotation_matrix(R_AB, "R_AB");
  return SpatialInertia(mass_, R * com_, rotated_inertia(R, inertia_com_), Trusted{});
}

SpatialInertia SpatialInertia::transformed(const Transform& X_AB) const {
  return SpatialInertia(mass_, X_AB.act_point(com_), rotated_inertia(X_AB.rotation(), inertia_com_), Trusted{});
}

PrincipalAxes SpatialInertia::principal_axes() const { return rigiddyn::principal_axes(inertia_com_); }

InertiaReport SpatialInertia::report() const { return inertia_report(mass_, inertia_com_); }

bool SpatialInertia::admits_symmetry_plane(const Eigen::Vector3d& normal, double tolerance) const {
  require_finite(normal, "normal");
  if (normal.isZero(0.0)) throw_invalid("normal", "a nonzero vector", normal);
  const Eigen::Vector3d n = normal.stableNormalized();  // any length, 1e-300 or 1e300
  const Eigen::Vector3d In = inertia_com_ * n;
  return (In - n.dot(In) * n).norm() <= tolerance * inertia_com_.trace();
}

SpatialInertia SpatialInertia::operator+(const SpatialInertia& part) const {
  const double m = mass_ + part.mass_;
  const Eigen::Vector3d c = (mass_ * com_ + part.mass_ * part.com_) / m;  // Rigid-body notes (4.54)
  const Eigen::Matrix3d I = inertia_about_point(c) + part.inertia_about_point(c);
  // m |c - c_i|² beyond the largest double: centres of mass some 1e150 m apart or more
  if (!I.allFinite()) {
    throw_invalid("the distance between the centres of mass", "at most about 1e150 m (the sum's inertia overflows)",
                  (part.com_ - com_).stableNorm());
  }
  return SpatialInertia(m, c, I, Trusted{});
}

SpatialInertia SpatialInertia::remove(const SpatialInertia& part, InertiaCheck check) const {
  const double m = mass_ - part.mass_;
  if (!(m > 1e-12 * mass_)) {
    throw_invalid("part.mass", "less than the body's mass " + format_value(mass_), part.mass_);
  }
  const Eigen::Vector3d c = (mass_ * com_ - part.mass_ * part.com_) / m;
  const Eigen::Matrix3d whole = inertia_about_point(c);
  const Eigen::Matrix3d I = whole - part.inertia_about_point(c);
  return SpatialInertia(m, c, checked_inertia(m, I, check, std::abs(whole.trace()), "remove (inertia of the rest)"),
                        Trusted{});
}

bool SpatialInertia::is_approx(const SpatialInertia& o, double prec) const {
  const double length = std::sqrt(std::max(inertia_com_.trace(), o.inertia_com_.trace()) / mass_) + com_.norm();
  return std::abs(mass_ - o.mass_) <= prec * std::max(mass_, o.mass_) &&
         (com_ - o.com_).norm() <= prec * std::max(length, 1e-300) &&
         (inertia_com_ - o.inertia_com_).norm() <= prec * std::max(inertia_com_.norm(), o.inertia_com_.norm());
}

namespace {

// Sums of mass, first moment and inertia about a fixed reference point (Rigid-body notes (4.53)-(4.54)):
// a reference near the parts (the first centre) keeps the final shift's cancellation small.
struct CompositeSum {
  Eigen::Vector3d ref;
  double m = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_ref = Eigen::Matrix3d::Zero();

  void add(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com) {
    m += mass;
    first += mass * (com - ref);
    I_ref += inertia_com + point_inertia(mass, com - ref);
  }
  // a sum of valid parts is valid (the valid inertias form a convex cone): only PSD is re-checked
  // here, so that composites of deliberately unrealizable parts remain possible
  SpatialInertia result() const {
    return SpatialInertia::from_inertia_about_point(m, ref + first / m, I_ref, ref, InertiaCheck::allow_unrealizable);
  }
};

}  // namespace

SpatialInertia composite(const std::vector<std::pair<Transform, SpatialInertia>>& parts) {
  if (parts.empty()) throw_invalid("parts", "at least one part", 0);
  CompositeSum sum{parts.front().first.act_point(parts.front().second.com())};
  for (const auto& [X_AB, part] : parts) {
    const Eigen::Matrix3d& R = X_AB.rotation();
    sum.add(part.mass(), X_AB.act_point(part.com()), R * part.inertia_com() * R.transpose());
  }
  return sum.result();
}

SpatialInertia composite(const std::vector<SpatialInertia>& parts) {
  if (parts.empty()) throw_invalid("parts", "at least one part", 0);
  CompositeSum sum{parts.front().com()};
  for (const SpatialInertia& p : parts) sum.add(p.mass(), p.com(), p.inertia_com());
  return sum.result();
}

}  // namespace rigiddyn
