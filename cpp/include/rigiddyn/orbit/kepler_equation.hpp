// Kepler's equation solved for the eccentric anomaly: M = E − e sin E (0 ≤ e < 1, Curtis, "Orbital
// Mechanics for Engineering Students", sec. 3.4) and its hyperbolic form M = e sinh H − H (e > 1,
// sec. 3.6).
//
// The residual f(x) = M(x) − M is increasing in x (f' = 1 − e cos E ≥ 1 − e, e cosh H − 1 > 0), so the
// root lies in a bracket that every step keeps: [M, M + e] for 0 ≤ M ≤ π (E − M = e sin E ∈ [0, e]), and
// [asinh(M/e), asinh(M/(e − 1))] for M ≥ 0 (e sinh H = M + H ≥ M; sinh H ≥ H gives (e − 1) sinh H ≤ M);
// negative M by symmetry, the elliptic M first reduced to (−π, π] (its revolutions added back). Start, for
// |M| < 1: the root of the cubic (1 − e) x + e x³/6 = M (the series of M(x) to third order: exact as e → 1
// near periapsis), or M/(1 − e) for e ≤ 0.5; for |M| ≥ 1: M + 0.85 e (Danby's starter, "Fundamentals of
// Celestial Mechanics") or ln(2M/e + 1) (hyperbola, e sinh H ≈ e eᴴ/2). Then Halley's iteration, a
// bisection of the bracket whenever a step would leave it; it stops when a step no longer moves x beyond
// 2 ulps, after kepler_max_iterations steps at most: each bisection halves the bracket (or its exponent
// range), so round-off is reached well within the bound.
#pragma once

namespace rigiddyn {

// Steps of the solver at most (a bound, not a typical count: 3 to 5 Halley steps for double precision).
inline constexpr int kepler_max_iterations = 200;

// E (0 ≤ e < 1) or H (e > 1) [rad] with M(E) = M to round-off. Throws std::invalid_argument naming M
// or e for a non-finite value, e < 0 or e = 1 (the parabola has no eccentric anomaly: Barker's
// equation, mean_to_true_anomaly).
double mean_to_eccentric_anomaly(double M, double e);

}  // namespace rigiddyn
