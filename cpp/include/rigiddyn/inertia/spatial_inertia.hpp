// The mass properties of one rigid body (docs/conventions.md "Inertia"): mass m, centre of mass c and
// rotational inertia I_C about the centre of mass, all expressed in one frame (the body frame B unless
// a name says otherwise; "the frame" below). Every other form is derived:
//   inertia about a point P (parallel axis, Craig [I]_2 = [I]_C + m[...], Rigid-body notes (4.71)):
//     I_P = I_C + m (|r|^2 1 - r r^T),  r = c - p_P   (= I_C - m hat(r) hat(r))
//   6x6 spatial inertia about the frame's origin O, angular first (Featherstone):
//     [[I_O, m hat(c)], [m hat(c)^T, m 1]],  I_O = I_C + m hat(c) hat(c)^T
//
// Validity (validity.hpp): every constructor checks mass > 0, finite, symmetric, and by default the
// triangle inequality on the principal moments (InertiaCheck::physical). Pass
// InertiaCheck::allow_unrealizable to accept a symmetric PSD inertia that no body has. Operations
// that preserve validity exactly (rotation, transform, adding parts) do not re-check; removing a
// part does. I_C is stored symmetrised, (I + I^T) / 2, and projected onto the valid set when
// round-off put it outside by less than the tolerance (validity.hpp, checked_inertia).
#pragma once
#include <Eigen/Core>

#include <vector>

#include "rigiddyn/inertia/principal_axes.hpp"
#include "rigiddyn/inertia/validity.hpp"
#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/motion.hpp"
#include "rigiddyn/spatial/transform.hpp"

namespace rigiddyn {

class SpatialInertia {
 public:
  // mass [kg] > 0; com: centre of mass [m] in the frame of expression;
  // inertia_com: rotational inertia about the centre of mass [kg m^2], symmetric, in that frame.
  // Throws std::invalid_argument naming the argument on non-finite input, mass <= 0, an asymmetric
  // inertia, or (unless `check` allows it) an inertia violating PSD / the triangle inequality; the
  // message carries the InertiaReport summary (principal moments, margins, condition number).
  SpatialInertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com,
                 InertiaCheck check = InertiaCheck::physical);

  // From the inertia I_P [kg m^2] about the point p_P [m] (both in the frame): I_C = I_P - m (|r|^2 1 - r r^T),
  // r = com - p_P. Validity is checked with the round-off scale of I_P (validity.hpp).
  static SpatialInertia from_inertia_about_point(double mass, const Eigen::Vector3d& com,
                                                 const Eigen::Matrix3d& inertia_about_point,
                                                 const Eigen::Vector3d& point,
                                                 InertiaCheck check = InertiaCheck::physical);
  // Same with P = the frame's origin.
  static SpatialInertia from_inertia_about_origin(double mass, const Eigen::Vector3d& com,
                                                  const Eigen::Matrix3d& inertia_about_origin,
                                                  InertiaCheck check = InertiaCheck::physical);
  // From the 6x6 spatial inertia about the origin (angular first); throws unless it has the structure
  // [[I_O, m hat(c)], [m hat(c)^T, m 1]] (to 1e-12 relative).
  static SpatialInertia from_matrix(const Matrix6d& matrix, InertiaCheck check = InertiaCheck::physical);
  // A point mass m [kg] at `position` [m] (I_C = 0).
  static SpatialInertia point_mass(double mass, const Eigen::Vector3d& position);

  // Mass m [kg]; centre of mass c [m] (3,) in the frame; rotational inertia I_C about the centre
  // of mass [kg m^2] (3, 3), expressed in the frame.
  double mass() const { return mass_; }
  const Eigen::Vector3d& com() const { return com_; }
  const Eigen::Matrix3d& inertia_com() const { return inertia_com_; }

  // Rotational inertia about the point p_P [m] (parallel axis, Craig) [kg m^2], in the frame.
  Eigen::Matrix3d inertia_about_point(const Eigen::Vector3d& point) const;
  // Rotational inertia about the frame's origin [kg m^2].
  Eigen::Matrix3d inertia_about_origin() const;
  // The 6x6 spatial inertia about the frame's origin, angular first [[kg m^2, kg m], [kg m, kg]].
  Matrix6d matrix() const;

  // Spatial momentum h = I V (about the frame's origin, angular first) of the twist V = [w; v_O]
  // (v_O the velocity of the body point at the origin): h = [I_O w + m c x v_O; m (v_O + w x c)].
  Force momentum(const Motion& twist) const;
  // Kinetic energy T = 1/2 V . I V [J] (Craig: 1/2 m v_C.v_C + 1/2 w.I_C w).
  double kinetic_energy(const Motion& twist) const;
  // H_C = I_C w [kg m^2/s]: angular momentum about the centre of mass, w [rad/s] in the frame.
  Eigen::Vector3d angular_momentum_about_com(const Eigen::Vector3d& angular_velocity) const;
  // H_P = r_PC x L + H_C (Craig), L = m v_C: angular momentum about the point p_P [m] of the body
  // moving with angular velocity w [rad/s] and centre-of-mass velocity v_C [m/s] (all in the frame).
  Eigen::Vector3d angular_momentum_about_point(const Eigen::Vector3d& angular_velocity,
                                               const Eigen::Vector3d& com_velocity,
                                               const Eigen::Vector3d& point) const;

  // Re-expressed in frame A from the frame B it is expressed in: c_A = R_AB c_B, I_C,A = R_AB I_C,B R_AB^T
  // (same point, same body; R_AB checked to be a rotation).
  SpatialInertia rotated(const Eigen::Matrix3d& R_AB) const;
  // Re-expressed in A: c_A = X_AB c_B (= R_AB c_B + p_AB), I_C,A = R_AB I_C,B R_AB^T.
  SpatialInertia transformed(const Transform& X_AB) const;

  // Principal moments (ascending) and right-handed axes of I_C (principal_axes.hpp).
  PrincipalAxes principal_axes() const;
  // The validity report of this inertia (validity.hpp).
  InertiaReport report() const;
  // Whether the plane through the centre of mass with this normal (any nonzero length, in the frame)
  // can be a plane of symmetry: Craig — if the xy plane is one, I_xz = I_yz = 0, i.e. the normal is
  // a principal axis: |I_C n - (n.I_C n) n| <= tolerance * trace(I_C). Necessary, not sufficient
  // (inertia alone cannot prove a geometric symmetry).
  bool admits_symmetry_plane(const Eigen::Vector3d& normal, double tolerance = 1e-9) const;

  // Composite of two bodies expressed in the same frame: masses add, the centre of mass is the
  // mass-weighted mean (Rigid-body notes (4.54)), inertias add about the common centre of mass.
  SpatialInertia operator+(const SpatialInertia& part) const;
  // This body with `part` removed (a hole): the inverse of operator+. Throws unless the rest has
  // mass > 0 and satisfies `check` (round-off scale: this body's inertia about the new centre).
  SpatialInertia remove(const SpatialInertia& part, InertiaCheck check = InertiaCheck::physical) const;
  SpatialInertia operator-(const SpatialInertia& part) const { return remove(part); }

  // Mass, centre of mass and I_C each equal up to prec relative to their size (the centre of mass
  // relative to the body's radius of gyration plus |c|).
  bool is_approx(const SpatialInertia& other, double prec = 1e-12) const;

 private:
  struct Trusted {};
  SpatialInertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com, Trusted)
      : mass_(mass), com_(com), inertia_com_(inertia_com) {}

  double mass_;
  Eigen::Vector3d com_;
  Eigen::Matrix3d inertia_com_;
};

// The composite of parts, each placed in the common frame A by X_AB (part i expressed in its B_i):
// sum of parts[i].second.transformed(parts[i].first), exact.
SpatialInertia composite(const std::vector<std::pair<Transform, SpatialInertia>>& parts);
// The composite of parts already expressed in one frame.
SpatialInertia composite(const std::vector<SpatialInertia>& parts);

// m (|r|^2 1 - r r^T) = -m hat(r) hat(r): the inertia of a point mass m at r about the origin.
// Throws std::invalid_argument naming "mass" unless m is finite and > 0.
Eigen::Matrix3d point_inertia(double mass, const Eigen::Vector3d& r);
// tr(C) 1 - C: the rotational inertia of a second moment of mass C = integral rho r r^T dV
// [kg m^2] (Rigid-body notes (4.70) written with r r^T).
Eigen::Matrix3d inertia_from_second_moment(const Eigen::Matrix3d& second_moment);

}  // namespace rigiddyn
