// The anomalies of a conic orbit of eccentricity e and their conversions: true anomaly ν, eccentric
// anomaly E (ellipse, 0 ≤ e < 1) or hyperbolic anomaly H (hyperbola, e > 1), and mean anomaly M.
//
//   ellipse:   tan(ν/2) = √((1 + e)/(1 − e)) tan(E/2),   M = E − e sin E         (Kepler's equation)
//   hyperbola: tanh(H/2) = √((e − 1)/(e + 1)) tan(ν/2),  M = e sinh H − H
//   parabola:  D = tan(ν/2),                              M = D/2 + D³/6          (Barker's equation)
// Curtis, "Orbital Mechanics for Engineering Students", ch. 3 (sec. 3.4 ellipse, 3.5 parabola, 3.6
// hyperbola); Vallado, "Fundamentals of Astrodynamics and Applications", ch. 2 (Kepler's equation).
// The mean anomaly grows linearly in time: M = n t, n = √(μ/a³) (ellipse), √(μ/(−a)³) (hyperbola), √(μ/p³) (parabola), t from periapsis.
// The elliptic angles keep their revolutions (ν and E differ by less than π, M = E − e sin E over
// every revolution); the hyperbolic and parabolic ones are single-valued, |ν| < acos(−1/e).
// Every function throws std::invalid_argument naming the argument for a non-finite value, e < 0, e = 1
// where E or H is asked, or (hyperbola) a true anomaly beyond the asymptotes.
#pragma once

namespace rigiddyn {

// E (0 ≤ e < 1) or H (e > 1) [rad] of the true anomaly ν [rad].
double true_to_eccentric_anomaly(double nu, double e);
// ν [rad] of E (0 ≤ e < 1) or H (e > 1) [rad].
double eccentric_to_true_anomaly(double E, double e);
// M [rad] of E or H: E − e sin E (e < 1), e sinh H − H (e > 1), free of cancellation near periapsis.
double eccentric_to_mean_anomaly(double E, double e);
// M [rad] of ν, for every e ≥ 0 (Barker's equation at e = 1).
double true_to_mean_anomaly(double nu, double e);
// ν [rad] of M, for every e ≥ 0 (kepler_equation.hpp for e ≠ 1; Barker's cubic in closed form at e = 1).
double mean_to_true_anomaly(double M, double e);

namespace orbit_detail {
// The checks shared by the orbit layer: e finite and ≥ 0 (named "e"); an angle finite (named `name`).
void check_eccentricity(double e);
void check_angle(double angle, const char* name);
// x − sin x and sinh x − x, accurate to a few ulps also for small |x| (series below 1).
double x_minus_sin(double x);
double sinh_minus_x(double x);
}  // namespace orbit_detail

}  // namespace rigiddyn
