// Validity of mass properties (mass m, rotational inertia I_C about the centre of mass):
//   finite, m > 0, I_C symmetric, positive semi-definite, and the triangle inequality on the
//   principal moments I0 <= I1 <= I2:  I0 + I1 >= I2  (which implies I0 >= 0).
// The triangle inequality holds for every real mass distribution (I0 + I1 - I2 = 2 * integral of
// rho x2^2 dV >= 0 along the axis of I2); PSD alone is "mathematically valid".
//
// Tolerance (why no false positives from round-off): a computed inertia carries an error of a few
// ulps of the numbers it was computed from, not of its own entries. Each check therefore allows
//   tolerance = inertia_relative_tolerance * max(scale, trace(I_C))   [kg m^2]
// where `scale` is the size of those numbers (e.g. trace of the inertia about a distant point the
// user shifted from, m |r|^2 + trace). Operations that preserve validity exactly in exact
// arithmetic (rotation, re-expression, adding parts) do not re-check.
#pragma once
#include <Eigen/Core>

#include <string>

namespace rigiddyn {

// Relative tolerance of the PSD and triangle-inequality checks (see above). 1e-10 sits far above
// round-off (~1e-15 per operation) and far below any physical measurement of an inertia.
inline constexpr double inertia_relative_tolerance = 1e-10;

// What a constructor requires of the rotational inertia.
enum class InertiaCheck {
  physical,            // default: symmetric, PSD and triangle inequality (a realizable body)
  allow_unrealizable,  // opt-in: symmetric PSD only. For test problems with an inertia no body has,
                       // e.g. Hairer-Lubich-Wanner's I = diag(2, 1, 2/3) (1 + 2/3 < 2). Never the default.
};

// The diagnostic report of one (mass, inertia about the centre of mass).
struct InertiaReport {
  double mass = 0.0;                                         // [kg]
  bool mass_positive = false;                                // finite and > 0
  bool finite = false;                                       // every entry of I_C finite
  double asymmetry = 0.0;                                    // max |I - I^T| [kg m^2]
  double asymmetry_tolerance = 0.0;                          // 1e-12 max |I_ij| [kg m^2]
  bool symmetric = false;                                    // asymmetry <= asymmetry_tolerance
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  // ascending I0 <= I1 <= I2 [kg m^2]
  // (I1 + I2 - I0, I0 + I2 - I1, I0 + I1 - I2) [kg m^2]; the last is the smallest, the binding one.
  Eigen::Vector3d triangle_margins = Eigen::Vector3d::Zero();
  double condition_number = 0.0;  // I2 / I0 (+inf when I0 <= 0)
  double tolerance = 0.0;         // absolute tolerance of the two checks below [kg m^2] (not of symmetric)
  bool positive_semidefinite = false;  // I0 >= -tolerance
  bool triangle_inequality = false;    // I0 + I1 - I2 >= -tolerance

  // True when every check that `check` requires passes.
  bool valid(InertiaCheck check = InertiaCheck::physical) const;
  // One line with the key numbers (moments, margins, condition number, tolerance, failures).
  std::string summary() const;
};

// The report of (mass [kg], inertia_com [kg m^2] about the centre of mass). scale: see the header
// comment (0 = use trace(inertia_com) only).
InertiaReport inertia_report(double mass, const Eigen::Matrix3d& inertia_com, double scale = 0.0);

// The inertia to store: throws std::invalid_argument naming "mass" or `name` with the report's
// summary unless the report is valid under `check`; otherwise returns the symmetric part of
// `inertia_com`, and, under InertiaCheck::physical, when it violates PSD or the triangle inequality
// by less than the tolerance (round-off, e.g. after a shift from a distant point), its projection
// nearest_valid_inertia: so a stored inertia is valid to round-off of its own size, and stays valid
// through any number of later shifts and rotations. The change is below the tolerance.
Eigen::Matrix3d checked_inertia(double mass, const Eigen::Matrix3d& inertia_com, InertiaCheck check,
                                double scale = 0.0, const std::string& name = "inertia_com");

// Explicit repair: the nearest (Frobenius norm) symmetric matrix satisfying the triangle inequality
// (hence PSD) to the symmetric part of `inertia`. Keeps the principal axes and projects the moments
// onto the convex cone {Ii + Ij >= Ik}; a valid inertia is returned unchanged. Never applied
// implicitly: call it yourself and look at what changed (inertia_report before and after).
Eigen::Matrix3d nearest_valid_inertia(const Eigen::Matrix3d& inertia);

}  // namespace rigiddyn
