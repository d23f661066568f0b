// Classical orbital elements ↔ Cartesian state of a body about a central body of gravitational
// parameter μ (Vallado, "Fundamentals of Astrodynamics and Applications", ch. 2, algorithms RV2COE and
// COE2RV; Curtis, "Orbital Mechanics for Engineering Students", algorithms 4.2 and 4.5).
//
// The elements: semi-latus rectum p = h²/μ (defined for every conic, the parabola included; a = p/(1 − e²)),
// eccentricity e, inclination i ∈ [0, π], right ascension of the ascending node Ω, argument of periapsis
// ω and true anomaly ν, the angles in [0, 2π) (ν of a hyperbola or parabola in (−π, π)). The frames: W
// is the inertial frame of the central body, its xy plane the reference plane, x the reference
// direction. The state: r_W = p/(1 + e cos ν) (cos ν P̂ + sin ν Q̂), v_W = √(μ/p) (−sin ν P̂ + (e + cos ν) Q̂)
// with [P̂ Q̂ Ŵ] = R_z(Ω) R_x(i) R_z(ω) (Curtis sec. 4.6).
//
// Where an angle is undefined, it is set to 0 and the next one carries it (Vallado's special cases), so
// that state_from_elements gives the state back:
//   - equatorial (sin i < equatorial_tolerance, i = 0 or π: no node line): Ω = 0 and ω is the
//     longitude of periapsis ϖ, the angle from x_W to the periapsis in the direction of motion;
//   - circular (e < circular_tolerance: no periapsis): ω = 0 and ν is the argument of latitude u, the
//     angle from the ascending node to r in the direction of motion;
//   - both: Ω = ω = 0 and ν is the true longitude λ, the angle from x_W to r in the direction of motion.
// The tolerances lie far above the round-off of e and of sin i computed from a state (about 1e-15) and
// far below any orbit a mission flies; setting an angle to 0 below them moves the state given back by
// at most 2 e |r| (circular) or 2 sin(i) |r| (equatorial: the plane tilted by i about x_W instead of the node line).
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

inline constexpr double circular_tolerance = 1e-12;
inline constexpr double equatorial_tolerance = 1e-12;

// (p [m], e, i, Ω, ω, ν [rad]) as above.
struct ClassicalElements {
  double p, e, i, raan, argp, nu;
};

// A position r_W [m] and velocity v_W [m/s] in the inertial frame W, about the central body's centre.
struct OrbitState {
  Eigen::Vector3d r_W, v_W;
};

// The elements of the state about a central body of gravitational parameter mu [m³/s²]. Throws
// std::invalid_argument naming mu (not finite and > 0), r_W or v_W (non-finite, r = 0) or "r_W, v_W"
// (r × v = 0: a rectilinear orbit has no plane).
ClassicalElements elements_from_state(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, double mu);

// The state of the elements. Throws std::invalid_argument naming mu, p (not finite and > 0), e (not
// finite, < 0), i, raan, argp (not finite) or nu (not finite, or at or beyond the asymptotes of a
// hyperbola or parabola: 1 + e cos ν ≤ 0).
OrbitState state_from_elements(const ClassicalElements& elements, double mu);

// p = a (1 − e²) [m] of the semi-major axis a [m]: a > 0 for an ellipse (0 ≤ e < 1), a < 0 for a
// hyperbola (e > 1). Throws std::invalid_argument naming a (not finite, 0, or of the wrong sign for e) or
// e (not finite, < 0, or 1: a parabola's a is infinite, give its p).
double semi_latus_rectum(double a, double e);

}  // namespace rigiddyn
