// Spatial motion (twist, spatial velocity or acceleration) m = [w; v], angular part first
// (Featherstone; docs/conventions.md): w the angular velocity [rad/s], v the velocity [m/s] of the
// body-fixed point that coincides with the origin of the frame of expression, both expressed in
// that frame. The frame is not stored: a name says it (V_WB_A = twist of B in W, expressed in A).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // Vector3d::cross

#include "rigiddyn/spatial/force.hpp"

namespace rigiddyn {

struct Motion {
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // w [rad/s]
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // v [m/s] of the point at the frame's origin

  Motion() = default;
  Motion(const Eigen::Vector3d& angular_, const Eigen::Vector3d& linear_) : angular(angular_), linear(linear_) {}

  static Motion Zero() { return Motion(); }
  // [w; v] (6,) <-> Motion.
  Vector6d to_vector() const {
    Vector6d out;
    out << angular, linear;
    return out;
  }
  static Motion from_vector(const Vector6d& wv) { return Motion(wv.head<3>(), wv.tail<3>()); }

  Motion operator+(const Motion& o) const { return Motion(angular + o.angular, linear + o.linear); }
  Motion operator-(const Motion& o) const { return Motion(angular - o.angular, linear - o.linear); }
  Motion operator-() const { return Motion(-angular, -linear); }
  Motion operator*(double s) const { return Motion(s * angular, s * linear); }
  Motion& operator+=(const Motion& o) {
    angular += o.angular;
    linear += o.linear;
    return *this;
  }
  Motion& operator-=(const Motion& o) {
    angular -= o.angular;
    linear -= o.linear;
    return *this;
  }
  // Equal up to prec relative to the smaller norm of [w; v] (Eigen's isApprox on the 6-vectors).
  bool is_approx(const Motion& o, double prec = 1e-12) const { return to_vector().isApprox(o.to_vector(), prec); }

  // Motion cross product (Featherstone's crm): m1 x m2 = [w1 x w2; w1 x v2 + v1 x w2].
  Motion cross(const Motion& m2) const {
    return Motion(angular.cross(m2.angular), angular.cross(m2.linear) + linear.cross(m2.angular));
  }
  // Force cross product (Featherstone's crf, m x* f = -crm(m)^T f): [w x n + v x f; w x f].
  Force cross(const Force& f) const {
    return Force(angular.cross(f.angular) + linear.cross(f.linear), angular.cross(f.linear));
  }
  // Power pairing m . f = w . n + v . f [W]: invariant under change of frame.
  double dot(const Force& f) const { return angular.dot(f.angular) + linear.dot(f.linear); }

  // The velocity [m/s] of the body-fixed point at r [m] from the reference point, both in the frame of expression:
  // v + w × r (Featherstone, ch. 2: the same motion's linear part about a shifted point).
  Eigen::Vector3d velocity_at(const Eigen::Vector3d& r) const { return linear + angular.cross(r); }
};

inline Motion operator*(double s, const Motion& m) { return m * s; }

inline double Force::dot(const Motion& m) const { return m.dot(*this); }

}  // namespace rigiddyn
