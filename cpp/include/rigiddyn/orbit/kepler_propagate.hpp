// The two-body (Keplerian) motion of a body about a central body of gravitational parameter μ: its state
// a time t after a given one. Through the elements (elements.hpp): the mean anomaly advances at the mean
// motion, M(t) = M₀ + n t, with n = √(μ/a³) (ellipse), √(μ/(−a)³) (hyperbola), √(μ/p³) (parabola, Barker's
// M = D/2 + D³/6), that is n = √(μ/p³) |1 − e²|^(3/2) for e ≠ 1 (Curtis, "Orbital Mechanics for
// Engineering Students", ch. 3), then ν(t) by Kepler's equation (anomaly.hpp). The other elements stay.
#pragma once
#include "rigiddyn/orbit/elements.hpp"

namespace rigiddyn {

// n [rad/s] of an orbit with semi-latus rectum p [m] and eccentricity e, as above.
double mean_motion(double p, double e, double mu);

// The state t [s] (any sign) after (r_W, v_W). Throws std::invalid_argument as elements_from_state does,
// or naming t (not finite).
OrbitState kepler_propagate(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, double mu, double t);

}  // namespace rigiddyn
