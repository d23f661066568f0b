// Spatial force (wrench) f = [n; f], angular part first (Featherstone; docs/conventions.md):
// n is the moment [N m] about the origin of the frame of expression, f the force [N], both
// expressed in that frame. The frame and the reference point are not stored: a name says them
// (f_A = wrench expressed in A, moment about A's origin).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // Vector3d::cross

namespace rigiddyn {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct Motion;

struct Force {
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // n: moment about the frame's origin [N m]
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // f: force [N]

  Force() = default;
  Force(const Eigen::Vector3d& angular_, const Eigen::Vector3d& linear_) : angular(angular_), linear(linear_) {}

  static Force Zero() { return Force(); }
  // The force f [N] acting at the point r [m] from the reference point, both in the frame of expression: (r × f, f),
  // its moment about the reference point (Featherstone, ch. 2: a line force and its moment).
  static Force at_point(const Eigen::Vector3d& r, const Eigen::Vector3d& f) { return Force(r.cross(f), f); }
  // [n; f] (6,) <-> Force.
  Vector6d to_vector() const {
    Vector6d out;
    out << angular, linear;
    return out;
  }
  static Force from_vector(const Vector6d& nf) { return Force(nf.head<3>(), nf.tail<3>()); }

  Force operator+(const Force& o) const { return Force(angular + o.angular, linear + o.linear); }
  Force operator-(const Force& o) const { return Force(angular - o.angular, linear - o.linear); }
  Force operator-() const { return Force(-angular, -linear); }
  Force operator*(double s) const { return Force(s * angular, s * linear); }
  Force& operator+=(const Force& o) {
    angular += o.angular;
    linear += o.linear;
    return *this;
  }
  Force& operator-=(const Force& o) {
    angular -= o.angular;
    linear -= o.linear;
    return *this;
  }
  // Equal up to prec relative to the smaller norm of [n; f] (Eigen's isApprox on the 6-vectors).
  bool is_approx(const Force& o, double prec = 1e-12) const { return to_vector().isApprox(o.to_vector(), prec); }

  // Power pairing m . f = w . n + v . f [W] (defined in motion.hpp).
  double dot(const Motion& m) const;
};

inline Force operator*(double s, const Force& f) { return f * s; }

}  // namespace rigiddyn

// Force::dot(Motion) needs the complete Motion.
#include "rigiddyn/spatial/motion.hpp"
