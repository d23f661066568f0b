// The exact references of the pinned, moving-frame and variable-mass models: each closed form against
// an independent integration of its ODE (classical RK4 written here, Richardson-extrapolated), the
// conserved quantities along at(t), the pendulum's period against a quadrature of its period integral,
// Tsiolkovsky, and every refusal.
#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/exact/compound_pendulum.hpp"
#include "rigiddyn/exact/constant_thrust.hpp"
#include "rigiddyn/exact/lagrange_top.hpp"
#include "rigiddyn/exact/rotating_frame.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;

using State = Eigen::VectorXd;
using Rate = std::function<State(const State&)>;

// n classical RK4 steps of ẏ = f(y) over [0, T], the increments added with Kahan's compensated summation
// (Higham, Accuracy and Stability, §4.3: the sum's rounding stays O(eps |y|) instead of O(n eps |y|));
// also the largest |f| met [units of y per second].
struct Integration {
  State y;
  double max_rate;
};
Integration rk4(const Rate& f, State y, double T, int n) {
  const double h = T / n;
  State carry = State::Zero(y.size());
  double max_rate = 0.0;
  for (int i = 0; i < n; ++i) {
    const State k1 = f(y), k2 = f(y + 0.5 * h * k1), k3 = f(y + 0.5 * h * k2), k4 = f(y + h * k3);
    max_rate = std::max(max_rate, k1.cwiseAbs().maxCoeff());
    const State increment = h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4) - carry;
    const State sum = y + increment;
    carry = (sum - y) - increment;
    y = sum;
  }
  return {y, max_rate};
}

// y(T) by RK4 at n, 2n and 4n steps, Richardson-extrapolated twice: R(h) = (16 y_{h/2} − y_h)/15 removes
// RK4's h⁴ error term, leaving O(h⁵); the value is R(h/2), its truncation error bounded by |R(h/2) − R(h)|
// (≈ 31 times R(h/2)'s own O(h⁵) error in the asymptotic regime). Round-off: each stage rounds f by a few
// ulps, a perturbation of at most 16 eps T max|f| over the run (the compensated sum adds 2 eps |y|), carried
// to T by the flow's Jacobian, whose growth over these integrable flows is at most linear in the phase:
// (1 + T max|f| / max|y|) counted. Both to the extrapolation's weights (17/15 each, twice: ×1.3).
struct Reference {
  State value;
  double error_bound;
};
Reference richardson_rk4(const Rate& f, const State& y0, double T, int n) {
  const Integration a = rk4(f, y0, T, n), b = rk4(f, y0, T, 2 * n), c = rk4(f, y0, T, 4 * n);
  const State r1 = (16.0 * b.y - a.y) / 15.0, r2 = (16.0 * c.y - b.y) / 15.0;
  const double size = std::max({1.0, y0.cwiseAbs().maxCoeff(), r2.cwiseAbs().maxCoeff()});
  const double travel = std::abs(T) * c.max_rate;
  const double roundoff = 1.3 * 16.0 * kEps * (size + travel) * (1.0 + travel / size);
  return {r2, (r2 - r1).cwiseAbs().maxCoeff() + roundoff};
}

// ---------------------------------------------------------------- compound pendulum

// θ̈ = (c_W × m g)_z / I_O, c_W = Rz(θ) c (models/pivoted_planar_body.hpp); y = (θ, ω)
Rate pendulum_rate(const PivotedPlanarBody& body, const Eigen::Vector3d& g_W) {
  return [&body, g_W](const State& y) {
    const Eigen::Vector2d c_W = pivoted_planar_c_W(body.p_OC_B(), y[0]);
    const double torque = body.mass() * (c_W.x() * g_W.y() - c_W.y() * g_W.x());
    State dy(2);
    dy << y[1], torque / body.inertia_O_zz();
    return dy;
  };
}

// The closed form against RK4 at n·(1, 2, 4) steps over [0, T].
void expect_pendulum_matches_ode(const PivotedPlanarBody& body, const Eigen::Vector3d& g_W, const PivotedPlanarBodyState& s0,
                                 double T, int n, PendulumCase expected) {
  const CompoundPendulumSolution solution(body, g_W, s0);
  EXPECT_EQ(to_string(solution.solution_case()), to_string(expected));
  State y0(2);
  y0 << s0.theta, s0.omega;
  const Reference ref = richardson_rk4(pendulum_rate(body, g_W), y0, T, n);
  const PivotedPlanarBodyState s = solution.at(T);
  // the closed form: a few ulps of the elliptic functions, growing as eps·|λ T| (compound_pendulum.hpp),
  // 64 eps (1 + ω0 T)(1 + |y|) counted; the reference: error_bound (richardson_rk4)
  const double closed = 64.0 * kEps * (1.0 + solution.omega0() * T) * (1.0 + y0.cwiseAbs().maxCoeff() + std::abs(s.theta));
  EXPECT_NEAR(s.theta, ref.value[0], ref.error_bound + closed) << to_string(expected);
  EXPECT_NEAR(s.omega, ref.value[1], ref.error_bound + closed) << to_string(expected);
  // the error bound is a meaningful one: far below the motion itself
  EXPECT_LT(ref.error_bound, 1e-8);
  // energy along at(t): ½ I_O ω² − m g·c_W(θ), a function of the state evaluated to a few ulps of its terms
  const double scale = body.inertia_O_zz() * s0.omega * s0.omega + body.mass() * g_W.norm() * body.p_OC_B().norm();
  for (double t : {0.0, 0.37 * T, T, -1.3 * T}) {
    const PivotedPlanarBodyState st = solution.at(t);
    const Eigen::Vector2d c_W = pivoted_planar_c_W(body.p_OC_B(), st.theta);
    const double energy = 0.5 * body.inertia_O_zz() * st.omega * st.omega - body.mass() * g_W.head<2>().dot(c_W);
    EXPECT_NEAR(energy, solution.energy(), 32 * kEps * scale) << "t = " << t;
  }
  // t = 0 returns the initial state to a few ulps
  EXPECT_NEAR(solution.at(0.0).theta, s0.theta, 8 * kEps * (1 + std::abs(s0.theta)));
  EXPECT_NEAR(solution.at(0.0).omega, s0.omega, 8 * kEps * (1 + solution.omega0() + std::abs(s0.omega)));
}

// a body whose stable equilibrium is θ = 0 under g = (0, −g): c along −y of B (then ϑ = θ exactly)
PivotedPlanarBody hanging_body() { return PivotedPlanarBody(2.0, 0.05, Eigen::Vector2d(0.0, -0.4)); }
const Eigen::Vector3d kDown(0.0, -9.81, 0.0);

TEST(CompoundPendulumSolution, MatchesTheOdeInEveryCase) {
  const PivotedPlanarBody body(1.7, 0.08, Eigen::Vector2d(0.3, -0.25), Eigen::Vector2d(1.0, 2.0));
  const Eigen::Vector3d g_W(1.2, -9.5, 3.0);  // any direction; only its xy part acts
  const double stable = CompoundPendulumSolution(body, g_W, {}).theta_stable();
  const double omega0 = CompoundPendulumSolution(body, g_W, {}).omega0();
  const double T0 = 2 * M_PI / omega0;
  expect_pendulum_matches_ode(body, g_W, {stable + 0.3, 0.7}, 2.5 * T0, 4000, PendulumCase::libration);
  expect_pendulum_matches_ode(body, g_W, {stable - 2.0, -1.0}, 2.5 * T0, 4000, PendulumCase::libration);
  expect_pendulum_matches_ode(body, g_W, {stable + 3.0, 0.0}, 1.3 * T0, 8000, PendulumCase::libration);
  expect_pendulum_matches_ode(body, g_W, {stable + 1.0, 2.5 * omega0}, 2.5 * T0, 8000, PendulumCase::rotation);
  expect_pendulum_matches_ode(body, g_W, {stable - 0.5, -3.0 * omega0}, 2.5 * T0, 8000, PendulumCase::rotation);
  // θ0 = π − 1e-3 at rest: hardly moves at first, then one swing (mc = sin²(5e-4))
  const PivotedPlanarBody hanging = hanging_body();
  const double w0 = CompoundPendulumSolution(hanging, kDown, {}).omega0();
  expect_pendulum_matches_ode(hanging, kDown, {M_PI - 1e-3, 0.0}, 3.0 / w0, 4000, PendulumCase::libration);
  // the separatrix: ϑ0 = 0 with ϑ̇0 = 2 ω0 exactly (k² = 1, mc = 0), then ϑ → π
  expect_pendulum_matches_ode(hanging, kDown, {0.0, 2.0 * w0}, 4.0 / w0, 8000, PendulumCase::separatrix);
  expect_pendulum_matches_ode(hanging, kDown, {0.0, -2.0 * w0}, 4.0 / w0, 8000, PendulumCase::separatrix);
}

TEST(CompoundPendulumSolution, EquilibriaAndNoTorqueAreExact) {
  const PivotedPlanarBody hanging = hanging_body();
  for (double theta : {0.0, M_PI}) {
    const CompoundPendulumSolution rest(hanging, kDown, {theta, 0.0});
    EXPECT_EQ(rest.solution_case(), PendulumCase::rest);
    EXPECT_EQ(rest.at(12.5).theta, theta);
    EXPECT_EQ(rest.at(12.5).omega, 0.0);
    EXPECT_EQ(rest.period(), std::numeric_limits<double>::infinity());
  }
  const CompoundPendulumSolution free_turn(hanging, Eigen::Vector3d(0, 0, -9.81), {0.5, 2.0});  // g along z: no torque
  EXPECT_EQ(free_turn.solution_case(), PendulumCase::uniform);
  EXPECT_NEAR(free_turn.at(3.0).theta, 6.5, 4 * kEps * 6.5);
  EXPECT_NEAR(free_turn.period(), M_PI, 4 * kEps * M_PI);
}

// 4/ω0 ∫₀^{π/2} dφ/√(1 − m sin² φ) (the period integral after sin(ϑ/2) = k sin φ), with 1 − m sin² φ =
// cos² φ + mc sin² φ; written in χ = π/2 − φ as sin² χ + mc cos² χ, whose peak (1/kc at χ = 0, width kc)
// is resolved by splitting [0, π/2] at kc·2^j. On each piece the integrand changes by a factor ≤ 2 and
// its poles (χ = ±i kc, about) lie a piece's length away: the 30-point Gauss rule converges like ρ^−60,
// ρ ≥ 4; its error is bounded by the difference to the same rule on the two halves (far more accurate),
// plus 4 eps of the running sum per piece for the rounding. Independent of the Carlson R_F giving K in the core.
struct Quadrature {
  double value;
  double error;
};
Quadrature period_quadrature(double mc, double omega0) {
  using Gauss = boost::math::quadrature::gauss<double, 30>;
  const double kc = std::sqrt(mc);
  auto integrand = [mc](double chi) {
    const double s = std::sin(chi), c = std::cos(chi);
    return 1.0 / std::sqrt(s * s + mc * c * c);
  };
  double sum = 0.0, error = 0.0, a = 0.0;
  for (double b = kc; a < 0.5 * M_PI; b *= 2.0) {
    b = std::min(b, 0.5 * M_PI);
    const double middle = 0.5 * (a + b), whole = Gauss::integrate(integrand, a, b);
    const double halves = Gauss::integrate(integrand, a, middle) + Gauss::integrate(integrand, middle, b);
    sum += halves;
    error += std::abs(whole - halves) + 4 * kEps * sum;  // the piece's rounding and that of the running sum
    a = b;
  }
  return {4.0 * sum / omega0, 4.0 * error / omega0};
}

TEST(CompoundPendulumSolution, PeriodMatchesTheQuadratureUpToTheSeparatrix) {
  const PivotedPlanarBody hanging = hanging_body();
  const double omega0 = CompoundPendulumSolution(hanging, kDown, {}).omega0();
  std::vector<double> amplitudes{1e-3, 1e-2, 0.1, 0.5, 1.0, 2.0, 3.0, 3.1, M_PI - 1e-3, M_PI - 1e-4, M_PI - 1e-5, M_PI - 1e-6};
  for (double theta0 : amplitudes) {
    const CompoundPendulumSolution solution(hanging, kDown, {theta0, 0.0});
    ASSERT_EQ(solution.solution_case(), PendulumCase::libration);
    // mc = cos²(θ0/2) = sin²((π − θ0)/2): π − θ0 is exact (Sterbenz) for θ0 ≥ π/2
    const double half_gap = 0.5 * (M_PI - theta0), mc = std::sin(half_gap) * std::sin(half_gap);
    EXPECT_NEAR(solution.k_squared_complement(), mc, 4 * kEps * mc) << theta0;
    const Quadrature q = period_quadrature(mc, omega0);
    // the closed form 4K/ω0: K to a few ulps (elliptic.hpp), ω0 and the division 2 more: 16 eps;
    // the quadrature: its error bound (period_quadrature)
    EXPECT_NEAR(solution.period(), q.value, 16 * kEps * q.value + q.error) << theta0;
    // small amplitudes: the period tends to 2π/ω0 (1 + θ0²/16 + 11 θ0⁴/3072 + ...): the next term ≤ 4e-11
    if (theta0 <= 1e-2) {
      EXPECT_NEAR(solution.period() * omega0 / (2 * M_PI), 1 + theta0 * theta0 / 16, 1e-9);
    }
    // one period later the pendulum is back (phase error eps·λT of the reduction, a few ulps of sn, cn, dn)
    const PivotedPlanarBodyState back = solution.at(solution.period());
    EXPECT_NEAR(back.theta, theta0, 64 * kEps * (1 + omega0 * solution.period())) << theta0;
    EXPECT_NEAR(solution.amplitude(), theta0, 8 * kEps * theta0) << theta0;
  }
}

TEST(CompoundPendulumSolution, RotationPeriodIsOneTurn) {
  const PivotedPlanarBody hanging = hanging_body();
  const double omega0 = CompoundPendulumSolution(hanging, kDown, {}).omega0();
  for (double omega : {2.0000001 * omega0, 2.5 * omega0, -7.0 * omega0}) {
    const CompoundPendulumSolution solution(hanging, kDown, {0.2, omega});
    ASSERT_EQ(solution.solution_case(), PendulumCase::rotation);
    const PivotedPlanarBodyState turned = solution.at(solution.period());
    // θ advanced by exactly ±2π, ω back: a few ulps of the functions, the phase eps·λT
    EXPECT_NEAR(turned.theta, 0.2 + std::copysign(2 * M_PI, omega), 64 * kEps * (1 + std::abs(omega) * solution.period()));
    EXPECT_NEAR(turned.omega, omega, 64 * kEps * std::abs(omega) * (1 + std::abs(omega) * solution.period()));
  }
}

TEST(CompoundPendulumSolution, RefusesBadInput) {
  const PivotedPlanarBody hanging = hanging_body();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(CompoundPendulumSolution(hanging, Eigen::Vector3d(0, nan, 0), {}), std::invalid_argument);
  EXPECT_THROW(CompoundPendulumSolution(hanging, kDown, {nan, 0.0}), std::invalid_argument);
  EXPECT_THROW(CompoundPendulumSolution(hanging, kDown, {0.0, INFINITY}), std::invalid_argument);
  const CompoundPendulumSolution solution(hanging, kDown, {0.3, 0.0});
  try {
    solution.at(nan);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("t: expected", 0), 0u) << e.what();
  }
}

// ---------------------------------------------------------------- Lagrange top

// I_C = R diag(A, A, C) Rᵀ with c = l R ẑ: symmetric about the axis O→C, tilted in B
struct TopSetup {
  Eigen::Matrix3d R;
  PivotedBody body;
};
TopSetup top_setup(double A = 0.02, double C = 0.035, double l = 0.15, double mass = 1.3) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Matrix3d I_C = R * Eigen::Vector3d(A, A, C).asDiagonal() * R.transpose();
  return {R, PivotedBody(RigidBody(mass, I_C), l * R.col(2))};
}

// Euler's equations about O and the quaternion kinematics (pivoted_body.hpp): y = (q (x, y, z, w), ω)
Rate top_rate(const PivotedBody& body, const Eigen::Vector3d& g_W) {
  return [&body, g_W](const State& y) {
    const Eigen::Quaterniond q(y[3], y[0], y[1], y[2]);
    const Eigen::Vector3d w = y.segment<3>(4);
    const Eigen::Matrix3d& I = body.inertia_O();
    const Eigen::Vector3d tau = body.p_OC_B().cross(q.conjugate() * (body.mass() * g_W));
    const Eigen::Vector3d w_dot = I.ldlt().solve(tau - w.cross(I * w));
    const Eigen::Quaterniond q_dot = q * Eigen::Quaterniond(0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
    State dy(7);
    dy << q_dot.x(), q_dot.y(), q_dot.z(), q_dot.w(), w_dot;
    return dy;
  };
}

State top_coordinates(const PivotedBodyState& s) {
  State y(7);
  y << s.q_WB.x(), s.q_WB.y(), s.q_WB.z(), s.q_WB.w(), s.w_B;
  return y;
}

// The conserved quantities of the state: energy about O, H_z along −g, H_3 = e3 · I_O ω.
Eigen::Vector3d top_invariants(const PivotedBody& body, const Eigen::Vector3d& g_W, const PivotedBodyState& s) {
  const Eigen::Vector3d H_O_B = body.inertia_O() * s.w_B;
  const double energy = 0.5 * s.w_B.dot(H_O_B) - body.mass() * g_W.dot(s.q_WB * body.p_OC_B());
  return Eigen::Vector3d(energy, (s.q_WB * H_O_B).dot(-g_W.normalized()), H_O_B.dot(body.p_OC_B().normalized()));
}

void expect_top_matches_ode(const TopSetup& setup, const Eigen::Vector3d& g_W, const PivotedBodyState& s0, double periods,
                            int n_per_period) {
  const LagrangeTopSolution solution(setup.body, g_W, s0);
  ASSERT_EQ(solution.solution_case(), LagrangeTopCase::nutation);
  const double T = periods * solution.nutation_period();
  const Reference ref = richardson_rk4(top_rate(setup.body, g_W), top_coordinates(s0), T, static_cast<int>(periods * n_per_period));
  EXPECT_LT(ref.error_bound, 1e-8);  // a meaningful bound
  State y = top_coordinates(solution.at(T));
  if (y.head<4>().dot(ref.value.head<4>()) < 0) y.head<4>() *= -1.0;
  // the closed form: a few ulps of roots, functions and Π at t = 0, growing as eps·λT (lagrange_top.hpp),
  // 256 eps (1 + λ T)(1 + |ω|) counted (the angles are sums of several Π terms and their coefficients)
  const double closed = 256 * kEps * (1 + solution.elliptic_rate() * T) * (1 + s0.w_B.norm());
  EXPECT_LT((y - ref.value).cwiseAbs().maxCoeff(), ref.error_bound + closed);
  // the nutation bounds: θ(t) stays within them and reaches both (u = e3 · up)
  double theta_lo = M_PI, theta_hi = 0.0;
  const Eigen::Vector3d up = -g_W.normalized();
  for (int k = 0; k <= 400; ++k) {
    const double t = k * T / 400;
    const PivotedBodyState s = solution.at(t);
    const double theta = std::acos(std::clamp((s.q_WB * solution.e3_B()).dot(up), -1.0, 1.0));
    theta_lo = std::min(theta_lo, theta);
    theta_hi = std::max(theta_hi, theta);
    // the invariants along at(t): each a function of the state evaluated to a few ulps of its terms
    // (scales: the energy's terms, |H_O|); the closed form keeps them whatever its phase error
    const Eigen::Vector3d inv = top_invariants(setup.body, g_W, s), inv0 = top_invariants(setup.body, g_W, s0);
    const double H = (setup.body.inertia_O() * s0.w_B).norm();
    const double E_scale = 0.5 * s0.w_B.dot(setup.body.inertia_O() * s0.w_B) + setup.body.mass() * g_W.norm() * setup.body.p_OC_B().norm();
    EXPECT_NEAR(inv[0], inv0[0], 256 * kEps * E_scale) << "t = " << t;
    EXPECT_NEAR(inv[1], inv0[1], 256 * kEps * H) << "t = " << t;
    EXPECT_NEAR(inv[2], inv0[2], 64 * kEps * H) << "t = " << t;
  }
  // sampled at T/400 (a fraction of a nutation period): within the bounds, and reaching them to the
  // sampling's resolution (θ's second-order contact at a bound: 1e-3 of the range is generous)
  const double range = solution.theta_max() - solution.theta_min();
  EXPECT_GE(theta_lo, solution.theta_min() - 1e-9);
  EXPECT_LE(theta_hi, solution.theta_max() + 1e-9);
  EXPECT_NEAR(theta_lo, solution.theta_min(), 1e-3 * range + 1e-9);
  EXPECT_NEAR(theta_hi, solution.theta_max(), 1e-3 * range + 1e-9);
  // the invariants given by the solution are those of the state
  const Eigen::Vector3d inv0 = top_invariants(setup.body, g_W, s0);
  EXPECT_NEAR(solution.energy(), inv0[0], 64 * kEps * std::abs(inv0[0]) + 64 * kEps);
  EXPECT_NEAR(solution.H_z(), inv0[1], 64 * kEps * (setup.body.inertia_O() * s0.w_B).norm());
  EXPECT_NEAR(solution.H_3(), inv0[2], 64 * kEps * (setup.body.inertia_O() * s0.w_B).norm());
}

TEST(LagrangeTopSolution, MatchesTheOdeOverSeveralNutationPeriods) {
  const TopSetup setup = top_setup();
  const Eigen::Vector3d e3 = setup.R.col(2), e1 = setup.R.col(0), e2 = setup.R.col(1);
  const Eigen::Vector3d g_W(0.0, 0.0, -9.81);
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.5, Eigen::Vector3d(0.3, 1, 0).normalized()));
  // released tilted with a pure spin: u0 = u2 (the highest point), f(u0) = 0 exactly
  const Eigen::Quaterniond q0 = tilt * Eigen::Quaterniond::FromTwoVectors(e3, Eigen::Vector3d::UnitZ());
  expect_top_matches_ode(setup, g_W, {q0, 60.0 * e3}, 3.0, 400);
  // a general state (u̇0 ≠ 0: Newton on the cubic), and gravity along any direction
  expect_top_matches_ode(setup, g_W, {q0, 40.0 * e3 + 3.0 * e1 - 2.0 * e2}, 3.0, 400);
  expect_top_matches_ode(setup, Eigen::Vector3d(2.0, -1.0, -9.0), {q0, -25.0 * e3 + 1.5 * e1 + 4.0 * e2}, 3.0, 400);
  // a slow top that swings far (below the horizontal: u1 < 0)
  expect_top_matches_ode(setup, g_W, {q0, 8.0 * e3 + 2.0 * e1}, 2.0, 1000);
  // a hanging top (e3 below the pivot)
  const Eigen::Quaterniond hanging = Eigen::Quaterniond(Eigen::AngleAxisd(2.6, Eigen::Vector3d::UnitX())) *
                                     Eigen::Quaterniond::FromTwoVectors(e3, Eigen::Vector3d::UnitZ());
  expect_top_matches_ode(setup, g_W, {hanging, 10.0 * e3 + 1.0 * e2}, 2.0, 1000);
}

TEST(LagrangeTopSolution, FastTopPrecessesAtTheGyroscopicRate) {
  // a fast top released with a pure spin nutates little and precesses on average at ≈ m g l/(I3 ω3)
  // (Goldstein §5.7: the first-order rate; the next correction is O((m g l I1)/(I3 ω3)²) relative)
  const TopSetup setup = top_setup();
  const Eigen::Vector3d e3 = setup.R.col(2);
  const Eigen::Quaterniond q0 = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX())) *
                                Eigen::Quaterniond::FromTwoVectors(e3, Eigen::Vector3d::UnitZ());
  const double spin = 2000.0;
  const LagrangeTopSolution solution(setup.body, Eigen::Vector3d(0, 0, -9.81), {q0, spin * e3});
  const double I3 = solution.I3(), I1 = solution.I1(), mgl = 1.3 * 9.81 * 0.15;
  const double gyroscopic = mgl / (I3 * spin), correction = mgl * I1 / (I3 * spin * I3 * spin);
  EXPECT_NEAR(solution.mean_precession_rate(), gyroscopic, 4 * correction * gyroscopic);
  // released at the top of its nutation: θ_min = θ0
  EXPECT_NEAR(solution.theta_min(), 0.4, 64 * kEps);
  // the nutation period tends to 2π I1/(I3 ω3)
  EXPECT_NEAR(solution.nutation_period(), 2 * M_PI * I1 / (I3 * spin), 4 * correction * solution.nutation_period());
  // the mean precession rate is φ's change over a nutation period divided by it. φ = P+ + P− whose terms
  // c± Π(am τ, n±) ≈ ∓(a/2λ) τ cancel down to φ: their few ulps are eps (I3 ω3)²/(2 I1 m g l) relative to φ
  // (≈ 6e-12 here; the mean rate itself is summed without that cancellation): 16 times that
  const double T = solution.nutation_period();
  const double cancellation = (I3 * spin) * (I3 * spin) / (2 * I1 * mgl);
  EXPECT_NEAR((solution.angles_at(T).phi - solution.angles_at(0.0).phi) / T, solution.mean_precession_rate(),
              16 * kEps * cancellation * solution.mean_precession_rate());
}

TEST(LagrangeTopSolution, SleepingTopSpinsAboutTheVertical) {
  const TopSetup setup = top_setup();
  const Eigen::Vector3d e3 = setup.R.col(2);
  const Eigen::Quaterniond q0 = Eigen::Quaterniond::FromTwoVectors(e3, Eigen::Vector3d::UnitZ());
  const PivotedBodyState s0{q0, 50.0 * e3};
  const LagrangeTopSolution solution(setup.body, Eigen::Vector3d(0, 0, -9.81), s0);
  EXPECT_EQ(solution.solution_case(), LagrangeTopCase::sleeping);
  const Reference ref = richardson_rk4(top_rate(setup.body, Eigen::Vector3d(0, 0, -9.81)), top_coordinates(s0), 0.5, 2000);
  State y = top_coordinates(solution.at(0.5));
  if (y.head<4>().dot(ref.value.head<4>()) < 0) y.head<4>() *= -1.0;
  EXPECT_LT((y - ref.value).cwiseAbs().maxCoeff(), ref.error_bound + 64 * kEps * 50);
}

TEST(LagrangeTopSolution, RefusesWhatItDoesNotSolve) {
  const TopSetup setup = top_setup();
  const Eigen::Vector3d e3 = setup.R.col(2), e1 = setup.R.col(0);
  const Eigen::Vector3d g_W(0, 0, -9.81);
  auto message = [&](const PivotedBody& body, const Eigen::Vector3d& g, const PivotedBodyState& s) {
    try {
      LagrangeTopSolution(body, g, s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const PivotedBodyState s0{Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())), 20.0 * e3};
  // not symmetric about O→C
  const PivotedBody lopsided(RigidBody(1.0, Eigen::Vector3d(0.02, 0.021, 0.035)), Eigen::Vector3d(0, 0, 0.1));
  EXPECT_EQ(message(lopsided, g_W, s0).rfind("body: expected", 0), 0u);
  // symmetric, but C on a transverse axis
  const PivotedBody sideways(RigidBody(1.0, Eigen::Vector3d(0.02, 0.02, 0.035)), Eigen::Vector3d(0.1, 0, 0));
  EXPECT_EQ(message(sideways, g_W, s0).rfind("body: expected", 0), 0u);
  // C at O
  const PivotedBody centred(RigidBody(1.0, Eigen::Vector3d(0.02, 0.02, 0.035)), Eigen::Vector3d::Zero());
  EXPECT_EQ(message(centred, g_W, s0).rfind("body: expected", 0), 0u);
  EXPECT_EQ(message(setup.body, Eigen::Vector3d::Zero(), s0).rfind("g_W: expected", 0), 0u);
  EXPECT_EQ(message(setup.body, Eigen::Vector3d(0, NAN, 0), s0).rfind("g_W: expected", 0), 0u);
  // the axis vertical with a transverse rate: it passes through the vertical
  const Eigen::Quaterniond upright = Eigen::Quaterniond::FromTwoVectors(e3, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(message(setup.body, g_W, {upright, 20.0 * e3 + 1.0 * e1}).rfind("state: expected", 0), 0u);
  EXPECT_EQ(message(setup.body, g_W, {Eigen::Quaterniond(0.5, 0.5, 0.5, 0.6), 20.0 * e3}).rfind("state.q_WB: expected", 0), 0u);
  EXPECT_THROW(LagrangeTopSolution(setup.body, g_W, s0).at(NAN), std::invalid_argument);
}

// ---------------------------------------------------------------- rotating frame

TEST(RotatingFrameFreeParticle, MatchesTheOdeWithCentrifugalAndCoriolis) {
  const Eigen::Vector3d axis(0.2, -0.3, 1.0), p0(1.0, 2.0, -0.5), v0(-0.3, 0.4, 0.8);
  const double rate = 1.7;
  const RotatingFrameFreeParticle solution(axis, rate, p0, v0);
  const Eigen::Vector3d w = solution.w_F();
  // a_F = −ω × (ω × p) − 2 ω × v ("Rigid body kinematics and dynamics" notes, eq. (4.40), no applied force)
  const Rate rate_F = [w](const State& y) {
    const Eigen::Vector3d p = y.head<3>(), v = y.tail<3>();
    State dy(6);
    dy << v, -w.cross(w.cross(p)) - 2.0 * w.cross(v);
    return dy;
  };
  State y0(6);
  y0 << p0, v0;
  const double T = 7.3;
  const Reference ref = richardson_rk4(rate_F, y0, T, 4000);
  EXPECT_LT(ref.error_bound, 1e-8);
  const RotatingFrameParticleState s = solution.at(T);
  State y(6);
  y << s.p_F, s.v_F;
  // the closed form: a rotation by Ω T (its angle to eps·ΩT) of a line: 16 eps (1 + ΩT)(1 + |p| + |v|)
  const double closed = 16 * kEps * (1 + rate * T) * (1 + y.cwiseAbs().maxCoeff());
  EXPECT_LT((y - ref.value).cwiseAbs().maxCoeff(), ref.error_bound + closed);
  // the Jacobi integral along at(t), and the straight line in W
  for (double t : {0.0, 0.3, 2.0, -5.0, 40.0}) {
    const RotatingFrameParticleState st = solution.at(t);
    const double jacobi = 0.5 * st.v_F.squaredNorm() - 0.5 * w.cross(st.p_F).squaredNorm();
    const double scale = st.v_F.squaredNorm() + w.cross(st.p_F).squaredNorm();
    EXPECT_NEAR(jacobi, solution.jacobi_integral(), 32 * kEps * scale) << t;
    const Eigen::AngleAxisd R_WF(rate * t, axis.normalized());
    EXPECT_LT((R_WF * st.p_F - solution.p_W_at(t)).norm(), 16 * kEps * (1 + rate * std::abs(t)) * (1 + solution.p_W_at(t).norm()));
  }
  EXPECT_LT((solution.at(0.0).p_F - p0).norm(), 4 * kEps * p0.norm());
  EXPECT_LT((solution.at(0.0).v_F - v0).norm(), 8 * kEps * (v0.norm() + rate * p0.norm()));
}

TEST(RotatingFrameFreeParticle, TakesTheRateOfAScenesFrame) {
  const Eigen::Vector3d axis(0.2, -0.3, 1.0), p0(1.0, 2.0, -0.5), v0(-0.3, 0.4, 0.8);
  const RotatingFrameFreeParticle direct(axis, 1.7, p0, v0);
  const RotatingFrameFreeParticle framed(SceneFrame::rotating(axis, 1.7), p0, v0);
  // the same ω up to the normalisations of the axis (a few ulps)
  EXPECT_LT((framed.w_F() - direct.w_F()).norm(), 8 * kEps * 1.7);
  EXPECT_LT((framed.at(3.0).p_F - direct.at(3.0).p_F).norm(), 64 * kEps * (1 + 1.7 * 3.0) * 10);
  // the Earth's frame: Ω (0, cos φ, sin φ)
  const double latitude = 0.8;
  const RotatingFrameFreeParticle earth(SceneFrame::earth(latitude), p0, v0);
  EXPECT_LT((earth.w_F() - earth_rotation_rate * Eigen::Vector3d(0, std::cos(latitude), std::sin(latitude))).norm(),
            8 * kEps * earth_rotation_rate);
  // a general moving frame is refused, naming frame
  const FrameMotion wobbling([](double t) {
    FrameKinematics k;
    k.p_PF_P = Eigen::Vector3d(std::sin(t), 0.0, 0.0);
    return k;
  });
  try {
    RotatingFrameFreeParticle(SceneFrame::moving(wobbling), p0, v0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("frame: expected", 0), 0u) << e.what();
  }
}

TEST(RotatingFrameFreeParticle, RefusesBadInput) {
  const Eigen::Vector3d ok(0, 0, 1);
  EXPECT_THROW(RotatingFrameFreeParticle(Eigen::Vector3d::Zero(), 1.0, ok, ok), std::invalid_argument);
  EXPECT_THROW(RotatingFrameFreeParticle(ok, NAN, ok, ok), std::invalid_argument);
  EXPECT_THROW(RotatingFrameFreeParticle(ok, 1.0, Eigen::Vector3d(0, INFINITY, 0), ok), std::invalid_argument);
  EXPECT_THROW(RotatingFrameFreeParticle(ok, 1.0, ok, ok).at(INFINITY), std::invalid_argument);
}

// ---------------------------------------------------------------- constant thrust

TEST(ConstantThrustSolution, MatchesTheOdeAndTsiolkovsky) {
  const double m0 = 120.0, rate = -3.0;
  const Eigen::Vector3d u_rel(0.5, -0.2, -300.0), g(0.0, 0.0, -9.81), p0(1.0, 2.0, 3.0), v0(4.0, -1.0, 2.0);
  const ConstantThrustSolution solution(m0, rate, u_rel, g, p0, v0);
  EXPECT_DOUBLE_EQ(solution.burnout_time(), 40.0);
  // m v̇ = m g + ṁ u_rel, ṁ constant (notes eq. (4.36)); y = (p, v, m)
  const Rate rate_ode = [&](const State& y) {
    State dy(7);
    dy << y.segment<3>(3), g + (rate / y[6]) * u_rel, rate;
    return dy;
  };
  State y0(7);
  y0 << p0, v0, m0;
  for (double T : {1e-3, 5.0, 35.0}) {
    const Reference ref = richardson_rk4(rate_ode, y0, T, 2000);
    const ConstantThrustState s = solution.at(T);
    State y(7);
    y << s.p_W, s.v_W, s.mass;
    // the closed form: log1p and the series or closed form of h(x)/x (≤ 9 ulps), the sums: 32 eps |y|
    EXPECT_LT((y - ref.value).cwiseAbs().maxCoeff(), ref.error_bound + 32 * kEps * (1 + y.cwiseAbs().maxCoeff())) << T;
  }
  // Tsiolkovsky: from rest without gravity the speed reached at mass m1 is |u_rel| ln(m0/m1)
  const ConstantThrustSolution drift_free(m0, rate, u_rel, Eigen::Vector3d::Zero(), p0, Eigen::Vector3d::Zero());
  for (double t : {0.5, 10.0, 39.0}) {
    const double m1 = m0 + rate * t;
    // log1p(x) and log(m0/m1) to an ulp each, |u_rel| to 2: 8 eps relative
    EXPECT_NEAR(drift_free.at(t).v_W.norm(), solution.delta_v(m1), 8 * kEps * solution.delta_v(m1)) << t;
    // against the textbook form: log(m0/m1) of the rounded ratio errs by eps/ln(m0/m1) relative, 4 eps more
    const double textbook = u_rel.norm() * std::log(m0 / m1);
    EXPECT_NEAR(solution.delta_v(m1), textbook, (4 + 1 / std::log(m0 / m1)) * kEps * textbook) << t;
  }
  // 1e-9 relative (the required accuracy): the thrust's velocity change with gravity removed
  EXPECT_NEAR((solution.at(20.0).v_W - v0 - g * 20.0).norm(), solution.delta_v(60.0), 1e-9 * solution.delta_v(60.0));
  // no mass change: a plain ballistic arc, exactly
  const ConstantThrustSolution coasting(m0, 0.0, u_rel, g, p0, v0);
  EXPECT_LT((coasting.at(3.0).p_W - (p0 + 3.0 * v0 + 4.5 * g)).norm(), 4 * kEps * 50);
  EXPECT_EQ(coasting.burnout_time(), std::numeric_limits<double>::infinity());
}

TEST(ConstantThrustSolution, SmallAndLargeBurnFractionsAreAccurate) {
  // h(x)/x switches from its series to the closed form at |x| = 1/4: both sides agree with a
  // long-double evaluation of (1 + x) ln(1 + x) − x, whose own error is below 1e-19 relative for |x| ≥ 1e-4
  const Eigen::Vector3d u(0, 0, -1), zero = Eigen::Vector3d::Zero();
  for (double x : {-0.9, -0.25000001, -0.2499999, -1e-3, 1e-3, 0.2499999, 0.25000001, 3.0}) {
    const ConstantThrustSolution s(1.0, x, u, zero, zero, zero);  // x = ṁ t/m0 at t = 1
    const long double X = x, h_over_x = ((1 + X) * std::log1p(X) - X) / X;
    // p_z = −t h(x)/x: the series (40 terms, Horner) or the closed form (≤ 9 ulps, 1 + 2/|x|): 16 eps
    EXPECT_NEAR(-s.at(1.0).p_W.z(), static_cast<double>(h_over_x), 16 * kEps * std::abs(static_cast<double>(h_over_x))) << x;
  }
  // and near x = 0, h(x)/x = x/2 − x²/6 + x³/12 (the next term, x⁴/20, is below 1e-48 relative here)
  const double x = 1e-12;
  const ConstantThrustSolution tiny(1.0, x, u, zero, zero, zero);
  EXPECT_NEAR(-tiny.at(1.0).p_W.z(), x / 2 - x * x / 6 + x * x * x / 12, 4 * kEps * 0.5e-12);
}

TEST(ConstantThrustSolution, RefusesBadInput) {
  const Eigen::Vector3d z = Eigen::Vector3d::Zero();
  auto message = [&](auto make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(message([&] { ConstantThrustSolution(0.0, -1.0, z, z, z, z); }).rfind("m0: expected", 0), 0u);
  EXPECT_EQ(message([&] { ConstantThrustSolution(-1.0, -1.0, z, z, z, z); }).rfind("m0: expected", 0), 0u);
  EXPECT_EQ(message([&] { ConstantThrustSolution(1.0, NAN, z, z, z, z); }).rfind("rate: expected", 0), 0u);
  EXPECT_EQ(message([&] { ConstantThrustSolution(1.0, -1.0, Eigen::Vector3d(0, 0, INFINITY), z, z, z); }).rfind("u_rel_W: expected", 0), 0u);
  const ConstantThrustSolution s(10.0, -2.0, z, z, z, z);
  EXPECT_EQ(message([&] { s.at(5.0); }).rfind("t: expected", 0), 0u);  // the mass is 0 at burn-out
  EXPECT_EQ(message([&] { s.at(6.0); }).rfind("t: expected", 0), 0u);
  EXPECT_EQ(message([&] { s.delta_v(0.0); }).rfind("m1: expected", 0), 0u);
  EXPECT_NO_THROW(s.at(4.999));
}

// ---------------------------------------------------------------- states across the double range
// (found by fuzzing: underflow and overflow of intermediates; each test failed before the fix)

using test::message_of;

TEST(CompoundPendulumSolution, TinyStatesSwingAsTheLinearPendulum) {
  // θ0, ω0/ω0 ~ 1e-170 and below: k² = s² + v² underflows; the motion is the linear one,
  // θ = θ0 cos ω0 t + (ω/ω0) sin ω0 t, to O(k²) ~ 1e-340 relative. Bound: the elliptic functions to a few
  // ulps of the amplitude at u = u0, plus eps |λ t| from the argument: 16 eps (1 + ω0 t) of the amplitude,
  // and one ulp of the subnormal θ0 itself (5e-324).
  const PivotedPlanarBody hanging = hanging_body();
  const double w0 = CompoundPendulumSolution(hanging, kDown, {}).omega0();
  const PivotedPlanarBodyState states[] = {{1e-170, 0.0}, {1e-170, 1e-170}, {5e-324, 1e-300}, {-3e-200, 2e-310}};
  for (const PivotedPlanarBodyState& s0 : states) {
    const CompoundPendulumSolution solution(hanging, kDown, s0);
    EXPECT_EQ(solution.solution_case(), PendulumCase::libration);
    const double amplitude = std::hypot(s0.theta, s0.omega / w0);
    for (double t : {0.0, 0.3, 2.0}) {
      const PivotedPlanarBodyState s = solution.at(t);
      const double bound = 16 * kEps * (1 + w0 * t) * amplitude + 5e-324;
      EXPECT_NEAR(s.theta, s0.theta * std::cos(w0 * t) + s0.omega / w0 * std::sin(w0 * t), bound) << s0.theta << " " << t;
      EXPECT_NEAR(s.omega, -s0.theta * w0 * std::sin(w0 * t) + s0.omega * std::cos(w0 * t), w0 * bound) << s0.theta << " " << t;
    }
    EXPECT_NEAR(solution.period(), 2 * M_PI / w0, 8 * kEps * 2 * M_PI / w0);  // 4K(0)/ω0, K(0) = π/2
  }
}

TEST(CompoundPendulumSolution, TinySpeedAtTheTopLeavesItExponentially) {
  // at ϑ0 = π with ω = ±1e-300 (c = 0, |v| ~ 1e-301: mc = −v² underflows): a rotation just above the
  // separatrix; the deviation from the top obeys φ̈ = ω0² φ to O(φ²) ~ 1e-590: ω(t) = ω cosh ω0 t. Bound: dn
  // to a few ulps relative plus the argument's absolute error, eps (|u0| + |λ t|) with u0 ≈ K ≈ ln(4/kc)
  // ≈ 695, times |d ln dn/du| = m |sn cn|/dn ≤ 1 (|cn| ≤ dn for m ≤ 1): (8 + 2 K + ω0 t) eps relative.
  const PivotedPlanarBody hanging = hanging_body();
  const double w0 = CompoundPendulumSolution(hanging, kDown, {}).omega0();
  for (double theta0 : {M_PI, -M_PI}) {
    for (double omega : {1e-300, -1e-300}) {
      const CompoundPendulumSolution solution(hanging, kDown, {theta0, omega});
      EXPECT_EQ(solution.solution_case(), PendulumCase::rotation) << theta0 << " " << omega;
      const double K = std::log(4 * 2 * w0 / std::abs(omega));  // kc = |v|/k, k ≈ 1
      for (double t : {0.0, 0.3, 3.0}) {
        const PivotedPlanarBodyState s = solution.at(t);
        const double expected = omega * std::cosh(w0 * t);
        EXPECT_NEAR(s.omega, expected, (8 + 2 * K + w0 * t) * kEps * std::abs(expected) + 5e-324) << omega << " " << t;
        EXPECT_EQ(s.theta, theta0);  // θ0 ± (1e-300 sinh ω0 t) rounds to θ0
      }
    }
  }
}

TEST(CompoundPendulumSolution, FastTurnsAreUniform) {
  // |ω| ≥ 1e160 (v² overflows; with g = 1e-300 even v = ω/2ω0 does, and |g|² underflowed to a torque-free
  // "uniform" case): the gravity's share of ω² is
  // 4 ω0² sin²/ω² < 1e-300, so θ = θ0 + ω t and ω(t) = ω to double precision. Bound: λ = hypot(s ω0, ω/2)
  // and the am reduction, a few ulps of |ω t| plus of θ0: 16 eps (1 + |θ0| + |ω t|); ω to 8 eps.
  const PivotedPlanarBody hanging = hanging_body();
  for (const Eigen::Vector3d& g_W : {kDown, Eigen::Vector3d(0.0, -1e-300, 0.0)}) {
    for (double omega : {1e160, -1e200, 1e300}) {
      const double theta0 = 1.0;
      const CompoundPendulumSolution solution(hanging, g_W, {theta0, omega});
      EXPECT_EQ(solution.solution_case(), PendulumCase::rotation);
      EXPECT_NEAR(solution.period(), 2 * M_PI / std::abs(omega), 8 * kEps * 2 * M_PI / std::abs(omega));
      for (double t : {0.0, 3.0 / std::abs(omega), 1e3 / std::abs(omega)}) {
        const PivotedPlanarBodyState s = solution.at(t);
        EXPECT_NEAR(s.theta, theta0 + omega * t, 16 * kEps * (1 + theta0 + std::abs(omega * t))) << omega << " " << t;
        EXPECT_NEAR(s.omega, omega, 8 * kEps * std::abs(omega)) << omega << " " << t;
      }
    }
  }
  // a phase λ t beyond the double range is refused, naming t (θ(t) would be ~1e310)
  const CompoundPendulumSolution fast(hanging, kDown, {1.0, 1e10});
  EXPECT_EQ(message_of([&] { fast.at(1e300); }).rfind("t: expected", 0), 0u);
}

TEST(LagrangeTopSolution, VeryFastSpinsKeepTheirConstantsInRange) {
  // a pure spin of 1e100 (a² ~ 1e199, |A| = a²/β overflowed p² in the quadratic's discriminant) and
  // spins with a part across e3 (Newton's x³ overflowed for |A| > 1e103): the fast-top limits hold to
  // O((m g l I1)/(I3 ω3)²) ~ 1e-200 relative, i.e. to rounding. Bounds: released at the top of its nutation,
  // θ_min = θ_max = θ0 to the angles' few ulps (8 eps); the nutation period 2π I1/(I3 ω3) to 16 eps (a, a²,
  // the cubic's coefficients and root, √, K: about 10 roundings); w_B at t = 0 back to the state to 8 eps
  // of |w_B| per component across e3 (the rounding of z_S, ω_S and of sin θ's quotients) and ω3 exactly.
  const PivotedBody body(RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 0.5)), Eigen::Vector3d(0.0, 0.0, 0.2));
  const Eigen::Vector3d g_W(0.0, 0.0, -9.81);
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  for (const Eigen::Vector3d& w_B : {Eigen::Vector3d(0, 0, 1e100), Eigen::Vector3d(0, 0, 1e150),
                                     Eigen::Vector3d(1, 0, 1e100), Eigen::Vector3d(1, -2, 1e140)}) {
    const LagrangeTopSolution solution(body, g_W, {q0, w_B});
    const double w_perp = w_B.head<2>().norm();
    EXPECT_NEAR(solution.theta_min(), 0.3, 8 * kEps) << w_B.z();
    EXPECT_NEAR(solution.theta_max(), 0.3, 8 * kEps) << w_B.z();
    const double period = 2 * M_PI * solution.I1() / (solution.I3() * w_B.z());
    EXPECT_NEAR(solution.nutation_period(), period, 16 * kEps * period) << w_B.z();
    const PivotedBodyState s = solution.at(0.0);
    EXPECT_LT((s.w_B.head<2>() - w_B.head<2>()).cwiseAbs().maxCoeff(), 8 * kEps * (1 + w_perp)) << w_B.z();
    EXPECT_EQ(s.w_B.z(), w_B.z());
    EXPECT_LT(s.q_WB.angularDistance(q0), 8 * kEps) << w_B.z();
    // the mean precession rate m g l/(I3 ω3) (its correction, O(m g l I1/(I3 ω3)²) ~ 1e-200 relative, is
    // far below rounding; c+ + c− formed without the ±a/2λ cancellation that gave 0 or a sign flip here):
    // 16 eps for the roots, K, R_J and the quotients. With ω⊥ ≠ 0, φ̇ swings by ~|ω⊥| about this mean, which
    // is then b − a u1 = ρ0 − a x1 over (1 − u1²) λ: the rounding of ρ0 ~ |ω⊥| stays, 16 eps |ω⊥| absolute
    const double gyroscopic = 1.0 * 9.81 * 0.2 / (solution.I3() * w_B.z());
    EXPECT_NEAR(solution.mean_precession_rate(), gyroscopic, 16 * kEps * (gyroscopic + w_perp)) << w_B.z();
  }
  // a² beyond the double range: refused naming state (not an internal parameter)
  EXPECT_EQ(message_of([&] { LagrangeTopSolution(body, g_W, {q0, Eigen::Vector3d(0, 0, 1e160)}); }).rfind("state: expected", 0), 0u);
}

TEST(ConstantThrustSolution, HugeTimesAndMassRatiosStayFinite) {
  // t = −1.4e154: t² overflows, ½ g t² with g = 0 gave 0·inf = NaN. p_z = u_z t h(x)/x, x = ṁ t/m0 = 1.4e152,
  // h(x)/x = (1 + 1/x) ln(1 + x) − 1 (≈ 349: the − 1 loses < 1 bit): log1p, the products and the sums,
  // 16 eps relative against a long-double evaluation (its own error ~1e-19).
  const Eigen::Vector3d z = Eigen::Vector3d::Zero(), u(0, 0, -100);
  const ConstantThrustSolution burn(10.0, -0.1, u, z, z, z);
  const double t = -1.4e154;
  const long double X = -0.1L * t / 10.0L, h = (1 + 1 / X) * std::log1p(X) - 1;
  const double p_z = static_cast<double>(-100.0L * t * h);  // u_z t h(x)/x
  EXPECT_NEAR(burn.at(t).p_W.z(), p_z, 16 * kEps * std::abs(p_z));
  EXPECT_EQ(burn.at(t).p_W.head<2>(), Eigen::Vector2d::Zero());
  // with gravity the true ½ g t² ~ 1e310 is beyond the range: refused naming t
  const ConstantThrustSolution falling(10.0, -0.1, u, Eigen::Vector3d(0, 0, -9.81), z, z);
  EXPECT_EQ(message_of([&] { falling.at(t); }).rfind("t: expected", 0), 0u);
  // Tsiolkovsky far from m0: log(m0/m1) (the ratio's rounding costs eps/2 absolute in the log) or
  // log m0 − log m1 where the ratio overflows (one ulp of each log, no cancellation: ln(m0/m1) > 708);
  // 4 eps relative against long double (log1p of the rounded (m1 − m0)/m0 erred by 2.5e-5 at m1 = 1e-13)
  for (double m1 : {1e-13, 1e-16, 1e-300, 1e-320, 1e300}) {
    const long double exact = 100.0L * (std::log(10.0L) - std::log(static_cast<long double>(m1)));
    EXPECT_NEAR(burn.delta_v(m1), static_cast<double>(exact), 4 * kEps * std::abs(static_cast<double>(exact))) << m1;
  }
  // no thrust: Δv = 0 for any m1 (0 · ln(m0/m1) was 0 · inf = NaN at m1 = 1e-320)
  EXPECT_EQ(ConstantThrustSolution(10.0, -0.1, z, z, z, z).delta_v(1e-320), 0.0);
  // |u_rel| ~ 1e300: stableNorm, not the overflowing sum of squares (√2 e300 ln 2 to 4 eps)
  const ConstantThrustSolution hot(10.0, -0.1, Eigen::Vector3d(1e300, 1e300, 0), z, z, z);
  EXPECT_NEAR(hot.delta_v(5.0), std::sqrt(2.0) * 1e300 * std::log(2.0), 4 * kEps * 1e300);
  // a Δv beyond the double range (√2 e307 · 693) is refused, naming m1
  const ConstantThrustSolution hotter(10.0, -0.1, Eigen::Vector3d(1e307, 1e307, 0), z, z, z);
  EXPECT_EQ(message_of([&] { hotter.delta_v(1e-300); }).rfind("m1: expected", 0), 0u);
}

TEST(RotatingFrameFreeParticle, RatesAndAxesBeyondTheSquaresRange) {
  // |ω_F| = 1e155 (|ω|² overflows): the frame's rate is taken with stableNorm, so ω_F agrees with the
  // direct constructor's to the normalisation's few ulps (8 eps), and an axis_F of length 1e200 is a
  // valid axis (its norm overflowed to inf and was refused).
  const Eigen::Vector3d p0(1.0, 2.0, -0.5), v0(-0.3, 0.4, 0.8);
  const RotatingFrameFreeParticle framed(SceneFrame::rotating(Eigen::Vector3d(0, 0, 1), 1e155), p0, v0);
  EXPECT_LT((framed.w_F() - Eigen::Vector3d(0, 0, 1e155)).norm(), 8 * kEps * 1e155);
  const RotatingFrameFreeParticle long_axis(Eigen::Vector3d(0, 3e200, 4e200), 2.0, p0, v0);
  EXPECT_LT((long_axis.w_F() - Eigen::Vector3d(0, 1.2, 1.6)).norm(), 8 * kEps * 2.0);
}

}  // namespace
}  // namespace rigiddyn
