"""Exact references of the new models: the numpy/scipy reference (rigiddyn_ref.exact_dynamics) checked against
itself (Legendre's Π against quadrature, the pendulum and the heavy top against DOP853, the fast top's precession
against Landau & Lifshitz's m g l/(I3 ω3)), then rigiddyn's CompoundPendulumSolution, LagrangeTopSolution,
RotatingFrameFreeParticle and ConstantThrustSolution against it."""

import mpmath as mp
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy import integrate

import rigiddyn as rd

from rigiddyn_ref import exact_dynamics as ref
from rigiddyn_ref import moving_frame, pivoted, so3

EPS = np.finfo(float).eps
settings.register_profile("exact_dynamics_reference", max_examples=12, deadline=None)
seeds = st.integers(0, 2 ** 32 - 1)


def dop853(rate, y0, t1, rtol=1e-13):
    """solve_ivp DOP853 at rtol (atol 1e-15 × rtol-scale) with dense output."""
    return integrate.solve_ivp(lambda t, y: rate(y), (0.0, t1), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-2,
                               dense_output=True)


def dop853_bound(solution, rtol, scale):
    """DOP853 keeps each accepted step's estimated local error ≤ atol + rtol |y|; on a regular (non-chaotic) motion over
    one period the local errors add up with ‖J‖ ≤ a few: global ≤ N_steps × rtol × scale, N_steps the accepted steps
    (len(solution.t) − 1)."""
    return (len(solution.t) - 1) * rtol * scale


# ---------------------------------------------------------------- the reference against itself
@pytest.mark.parametrize("n, phi, m", [(0.3, 0.7, 0.5), (-0.8, 2.9, 0.2), (0.9, -4.0, 0.95), (-3.0, 7.5, 0.0)])
def test_reference_legendre_pi_matches_quadrature(n, phi, m):
    """Π(n; φ | m) by Carlson's forms and the quasi-period against adaptive quadrature of its integrand (quad at
    epsabs = epsrel = 1e-13 between multiples of π/2, its own error estimate below 1e-12); Carlson's R_F, R_J are
    accurate to a few eps
    (DLMF 19.36): the quadrature's bound dominates."""
    integrand = lambda t: 1.0 / ((1 - n * np.sin(t) ** 2) * np.sqrt(1 - m * np.sin(t) ** 2))  # noqa: E731
    edges = np.append(np.arange(0.0, abs(phi), np.pi / 2), abs(phi)) * np.sign(phi)  # peaks at odd multiples of π/2
    pieces = [integrate.quad(integrand, a, b, epsabs=1e-13, epsrel=1e-13, limit=200) for a, b in zip(edges, edges[1:])]
    value, error = sum(p[0] for p in pieces), sum(p[1] for p in pieces)
    assert error < 1e-12
    assert ref.legendre_pi(n, phi, m) == pytest.approx(value, abs=error + 1e-13 + 64 * EPS * abs(value))


@pytest.mark.parametrize("v0, vdot0", [(2.5, 0.3), (1.0, -1.0), (0.5, 5.0), (-1.0, -4.5), (3.1, 0.0)])
def test_reference_pendulum_motion_matches_dop853(v0, vdot0):
    """v(t), v̇(t) of pendulum_motion (libration and rotation) against DOP853 at rtol 1e-13 over 3 s (ω0 = 2 /s):
    dop853_bound of the run plus the closed form's phase error (eps × ω0 t × 64 operations)."""
    omega0 = 2.0
    run = dop853(lambda y: np.array([y[1], -omega0 ** 2 * np.sin(y[0])]), [v0, vdot0], 3.0)
    v, vdot = ref.pendulum_motion(omega0, v0, vdot0, 3.0)
    scale = max(abs(v0), abs(vdot0), 2 * np.pi, 2 * omega0)
    tol = dop853_bound(run, 1e-13, scale) + 64 * EPS * (1 + omega0 * 3.0) * scale
    assert abs(np.angle(np.exp(1j * (v - run.y[0, -1])))) <= tol
    assert abs(vdot - run.y[1, -1]) <= tol


def heavy_top(seed=None):
    """(mass, I_C, c, g, q, w): a symmetric top (I_C = diag(0.3, 0.3, 0.1) kg m², c = 0.2 m along z_B, 2 kg) tilted
    0.3–0.6 rad, spinning at 20–40 rad/s about its axis with a small transverse rate (its axis stays off the
    vertical)."""
    rng = np.random.default_rng(seed)
    tilt = rng.uniform(0.3, 0.6)
    q = so3.rotvec_to_quat(tilt * np.array([np.cos(rng.uniform(0, 6)), np.sin(rng.uniform(0, 6)), 0.0]))
    w = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(20, 40)])
    return 2.0, np.diag([0.3, 0.3, 0.1]), np.array([0.0, 0.0, 0.2]), np.array([0.0, 0.0, -9.81]), q, w


def precession_drift(reference_error, rate, t, period, core_error=0.0):
    """The bound [rad] on the angles' drift at t from their Π's relative error: the precession angle φ(t) carries it
    on |φ| ≤ |rate| (t + period) (the secular part and at most a period's worth besides), doubled for the second order
    (reference_error: the reference's mean rate against a 40-digit quadrature; core_error: the core's bound near a
    vertical). The spin ψ, whose rate a I1/I3 − u φ̇ takes φ̇'s Π term times |u| ≤ 1, drifts by at most as much, and
    ω_B's transverse part turns with ψ: |Δω| ≤ |ω| × the drift."""
    return (2 * reference_error + core_error) * abs(rate) * (t + period)


def mean_precession_rate_by_quadrature(top, digits=40):
    """φ's mean rate over a nutation period [rad/s] of the reference top's motion, by mpmath quadrature at `digits`
    digits (independent of Legendre's Π): with u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)² and its roots u1 ≤ u2,
    φ̇ = (b − a u) / (1 − u²) (Goldstein §5.7, in the reference's a, b, α, β), the half period ∫ du / √f and the
    precession over it ∫ φ̇ du / √f, over [u1, u2], where
    u = u1 + (u2 − u1) sin² s removes the square-root singularities at both ends. Near a vertical (u2 → 1) the
    double-precision reference loses digits in 1 − u2 (~eps / (1 − u2) relative, 4e-10 for the axis passing 4e-4
    rad from it), while these integrals do not. 40 digits give the same double as 50 and 70 for that top (30 digits
    are 2e-12 off: f's terms cancel near u2)."""
    with mp.workdps(digits):
        a, b, alpha, beta = (mp.mpf(float(x)) for x in (top.a, top.b, top.alpha, top.beta))
        roots = mp.polyroots([beta, -(alpha + a * a), 2 * a * b - beta, alpha - b * b], maxsteps=200, extraprec=200)
        u1, u2, _ = sorted(mp.re(r) for r in roots)

        def over_half_period(rate):
            def integrand(s):
                u = u1 + (u2 - u1) * mp.sin(s) ** 2
                f = (1 - u * u) * (alpha - beta * u) - (b - a * u) ** 2
                return rate(u) * 2 * (u2 - u1) * mp.sin(s) * mp.cos(s) / mp.sqrt(f)
            # the integrand peaks at the ends (1 − u nearest 0 at u2 near a vertical): the pieces shrink toward both
            ends = [mp.mpf(0), mp.pi / 2]
            return mp.quad(integrand, sorted(ends + [mp.pi / 4 * (1 + side * (1 - mp.mpf(4) ** -k))
                                                     for side in (-1, 1) for k in range(9)]))

        # (the real part: f's rounding at the ends, where the integrand vanishes, may leave it a tiny imaginary one)
        return float(mp.re(over_half_period(lambda u: (b - a * u) / (1 - u * u)) / over_half_period(lambda u: 1)))


def attitude_difference(q1, q2):
    """The angle [rad] between two attitudes."""
    return np.linalg.norm(so3.quat_to_rotvec(so3.quat_multiply(so3.quat_inverse(q1), q2)))


@settings(settings.get_profile("exact_dynamics_reference"))
@given(seed=seeds)
@example(seed=7779463)  # its axis 7e-5 rad from the vertical: the reference's angles drift (below)
def test_reference_lagrange_top_matches_dop853_over_one_nutation_period(seed):
    """The reference top's (q_WB, w_B) at 0.37 T and T against DOP853 (rtol 1e-13) of Euler's equations about O
    (rigiddyn_ref.pivoted.rate): dop853_bound (scale max(1, |ω|)) plus the closed form's own error, 1e-12 of the
    phase λ t + the angles φ, ψ (Carlson's Π and ellipj, a few dozen roundings each, on arguments up to ~|ω| T).
    Where the axis passes near the vertical the reference's Π loses digits (seed 7779463, 7e-5 rad from it: 2.6e-9
    of its mean precession rate): the angles then carry its rate's error against a 40-digit quadrature, as in the
    test of the core below."""
    mass, inertia, c, g, q, w = heavy_top(seed)
    top = ref.LagrangeTop(mass, pivoted.inertia_about_pivot(mass, inertia, c), c, g, q, w)
    T = top.nutation_period
    run = dop853(lambda y: pivoted.rate(mass, inertia, c, g, y), np.concatenate([q, w]), T)
    scale = max(1.0, np.linalg.norm(w))
    tol = dop853_bound(run, 1e-13, scale) + 64 * EPS * scale * T * np.linalg.norm(w)
    rate = mean_precession_rate_by_quadrature(top)
    reference_error = abs(top.mean_precession_rate - rate) / abs(rate)
    for t in (0.37 * T, T):
        q_ref, w_ref = top.at(t)
        y = run.sol(t)
        drift = precession_drift(reference_error, rate, t, T)
        assert attitude_difference(q_ref, y[:4] / np.linalg.norm(y[:4])) <= tol / scale * 2 + drift
        np.testing.assert_allclose(w_ref, y[4:], rtol=0, atol=tol + drift * np.linalg.norm(w))


def test_reference_fast_top_precesses_at_mgl_over_i3_omega3():
    """A fast top started with its axis at rest (Landau & Lifshitz §35): the mean precession rate tends to
    m g l/(I3 ω3) with a relative correction of order (I1 m g l)/(I3 ω3)² (the nutation's share); at ω3 = 200 rad/s
    that ratio is 0.3 × 3.92/(0.1 × 200)² ≈ 3e-3: tolerance 1e-2 relative."""
    mass, inertia, c, g = 2.0, np.diag([0.3, 0.3, 0.1]), np.array([0.0, 0.0, 0.2]), np.array([0.0, 0.0, -9.81])
    omega3 = 200.0
    q = so3.rotvec_to_quat([0.5, 0.0, 0.0])
    top = ref.LagrangeTop(mass, pivoted.inertia_about_pivot(mass, inertia, c), c, g, q, [0.0, 0.0, omega3])
    assert top.mean_precession_rate == pytest.approx(mass * 9.81 * 0.2 / (0.1 * omega3), rel=1e-2)
    assert top.theta_min == pytest.approx(0.5, abs=1e-12)  # started at rest in θ: the top of the nutation (u2 = u0)


# ---------------------------------------------------------------- rigiddyn against the reference
@settings(settings.get_profile("exact_dynamics_reference"))
@given(seed=seeds)
def test_core_compound_pendulum_solution_matches_the_reference(seed):
    """CompoundPendulumSolution: ω0, period and (θ, ω) at(t) for t up to 10 s against the reference (any energy).
    Both evaluate Jacobi's functions at the phase u = ω0 t + u0: each side's phase carries eps |u|, each function a few
    dozen roundings (DLMF 22.20's AGM / Carlson): 2 sides × 64 eps (1 + |u|) on (v, v̇/ω0)."""
    rng = np.random.default_rng(seed)
    mass, inertia_zz, c = rng.uniform(0.5, 3), rng.uniform(0.05, 1), rng.uniform(-1, 1, 2)
    g = np.array([0.0, -9.81])
    theta_stable = np.arctan2(-1.0, 0.0) - np.arctan2(c[1], c[0])  # R(θ) c along g
    v0, vdot0 = rng.uniform(-3, 3), rng.uniform(-8, 8)
    body = rd.PivotedPlanarBody(mass, inertia_zz, c)
    solution = rd.CompoundPendulumSolution(body, g, rd.PivotedPlanarBodyState(theta=theta_stable + v0, omega=vdot0))
    omega0 = ref.pendulum_omega0(mass, inertia_zz + mass * c @ c, np.linalg.norm(c), 9.81)
    assert solution.omega0 == pytest.approx(omega0, rel=8 * EPS)
    k2 = np.sin(v0 / 2) ** 2 + (vdot0 / (2 * omega0)) ** 2
    period = (4 * ref.special.ellipk(k2) / omega0 if k2 < 1 else ref.pendulum_rotation_period(omega0, v0, vdot0))
    # K's condition in k² grows as 1/|1 − k²|
    assert solution.period == pytest.approx(period, rel=64 * EPS / max(1e-300, abs(1 - k2)))
    t = np.linspace(0.0, 10.0, 7)
    theta, omega = solution.at(t)
    v, vdot = ref.pendulum_motion(omega0, v0, vdot0, t)
    phase = 1 + omega0 * np.sqrt(max(k2, 1)) * t
    tol = 2 * 64 * EPS * phase / max(1e-300, min(1.0, abs(1 - k2)))
    assert np.all(np.abs(np.angle(np.exp(1j * (theta - theta_stable - v)))) <= tol * 2 * np.pi)
    assert np.all(np.abs(omega - vdot) <= tol * 2 * omega0 * np.sqrt(k2))


@settings(settings.get_profile("exact_dynamics_reference"))
@given(seed=seeds)
@example(seed=847414)  # its axis 1.4e-3 rad from the vertical: the reference's precession drifts (below)
@example(seed=7779463)  # 7e-5 rad from it: its spin drifts as much, and ω_B's transverse part with it
def test_core_lagrange_top_solution_matches_the_reference(seed):
    """LagrangeTopSolution: θ_min, θ_max (acos of the cubic's roots: |Δu| ≤ 64 eps × the coefficients' scale
    divided by |f'(u)| at the root, 1e-12 absolute here), the nutation period and the mean precession rate (K and Π of
    the same parameter), and (q_WB, w_B) at(t) over 3 nutation periods (phase λ t ≤ ~20: 2 × 64 eps per unit of
    phase on |ω|; the attitude besides within the reference's own drift of the precession angle)."""
    mass, inertia, c, g, q, w = heavy_top(seed)
    top = ref.LagrangeTop(mass, pivoted.inertia_about_pivot(mass, inertia, c), c, g, q, w)
    core = rd.LagrangeTopSolution(rd.PivotedBody(rd.RigidBody(mass, inertia), c), g, rd.PivotedBodyState(q_WB=q, w_B=w))
    assert core.theta_min == pytest.approx(top.theta_min, abs=1e-12)
    assert core.theta_max == pytest.approx(top.theta_max, abs=1e-12)
    assert core.nutation_period == pytest.approx(top.nutation_period, rel=1e-12)
    # Π(n; m) of the precession loses digits as the axis nears a vertical, where n → 1: about eps / sqrt(1 − |u|)
    # at the bound u = cos θ nearest it (lagrange_top.hpp). The reference's Π, from a double u2 near 1, loses more
    # (eps / (1 − |u|)): the core is held to its own bound against a 40-digit quadrature of the same motion.
    nearest_vertical = min(1 - abs(np.cos(top.theta_min)), 1 - abs(np.cos(top.theta_max)))
    near_vertical_loss = 2 * 64 * EPS / np.sqrt(max(nearest_vertical, EPS))
    rate = mean_precession_rate_by_quadrature(top)
    assert core.mean_precession_rate == pytest.approx(rate, rel=1e-12 + near_vertical_loss)
    # The precession angle ψ(t) carries its Π's relative error: e |ψ|, |ψ| ≤ |rate| (t + one nutation period) (the
    # secular part and at most a period's worth besides); e the reference's (its mean rate's against the quadrature,
    # doubled for the second order) and the core's near a vertical (its bound above; the phase term holds the rest).
    reference_error = abs(top.mean_precession_rate - rate) / abs(rate)
    for t in np.linspace(0, 3 * top.nutation_period, 5):
        q_core, w_core = core.at(t)
        q_ref, w_ref = top.at(t)
        phase = 1 + np.linalg.norm(w) * t
        drift = precession_drift(reference_error, rate, t, top.nutation_period, near_vertical_loss)
        assert attitude_difference(q_core, q_ref) <= 2 * 64 * EPS * phase * 10 + drift
        np.testing.assert_allclose(w_core, w_ref, rtol=0,
                                   atol=(2 * 64 * EPS * phase * 10 + drift) * np.linalg.norm(w))


def test_lagrange_top_passing_near_the_vertical():
    """The heavy top of seed 2509, whose axis passes 4.3e-4 rad from the vertical (1 − u2 = 9.3e-8): the core's mean
    precession rate is within its bound of the test above (1e-12 + 2 × 64 eps / √(1 − u2) = 9.4e-11 relative) of the
    quadrature, where the double-precision reference's Π is 4.4e-10 off (found by the test above)."""
    mass, inertia, c, g, q, w = heavy_top(2509)
    core = rd.LagrangeTopSolution(rd.PivotedBody(rd.RigidBody(mass, inertia), c), g, rd.PivotedBodyState(q_WB=q, w_B=w))
    top = ref.LagrangeTop(mass, pivoted.inertia_about_pivot(mass, inertia, c), c, g, q, w)
    assert 1 - np.cos(top.theta_min) < 1e-7
    bound = 1e-12 + 2 * 64 * EPS / np.sqrt(1 - np.cos(top.theta_min))
    assert core.mean_precession_rate == pytest.approx(mean_precession_rate_by_quadrature(top), rel=bound)


def test_lagrange_top_at_a_start_near_a_turning_point():
    """The heavy top of seed 25494 (35.6 rad/s, its transverse rate putting it near a turning point of its nutation at
    t = 0): the core and the reference both give back the initial w_B at t = 0 within the bound of the test above.
    The reference once took the initial phase from an arcsin of sn alone, which loses half the digits there (1.8e-11,
    1.8 x the bound); it now takes sn and cn each where it is well conditioned."""
    mass, inertia, c, g, q, w = heavy_top(25494)
    core = rd.LagrangeTopSolution(rd.PivotedBody(rd.RigidBody(mass, inertia), c), g, rd.PivotedBodyState(q_WB=q, w_B=w))
    top = ref.LagrangeTop(mass, pivoted.inertia_about_pivot(mass, inertia, c), c, g, q, w)
    for _, w_0 in (core.at(0.0), top.at(0.0)):
        np.testing.assert_allclose(w_0, w, rtol=0, atol=2 * 64 * EPS * 10 * np.linalg.norm(w))


@settings(settings.get_profile("exact_dynamics_reference"))
@given(seed=seeds)
def test_core_rotating_frame_free_particle_matches_the_reference(seed):
    """RotatingFrameFreeParticle(SceneFrame.rotating(axis, rate), p0, v0).at(t) against the inertial line turned into F:
    the rotation angle rate t carries eps |rate t| each side, times |p| + |v| t; a dozen roundings on the rest."""
    rng = np.random.default_rng(seed)
    axis, rate = rng.normal(size=3), rng.uniform(-2, 2)
    p0, v0 = rng.uniform(-2, 2, 3), rng.uniform(-2, 2, 3)
    solution = rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating(axis, rate), p0, v0)
    for t in (0.0, 0.7, 5.0):
        p, v = solution.at(t)
        p_ref, v_ref = moving_frame.free_particle_in_frame(axis, rate, t, p0, v0)
        speed = np.linalg.norm(v0) + abs(rate) * np.linalg.norm(p0)
        size = (1 + abs(rate * t)) * (np.linalg.norm(p0) + speed * (1 + t))
        np.testing.assert_allclose(p, p_ref, rtol=0, atol=2 * 32 * EPS * size)
        np.testing.assert_allclose(v, v_ref, rtol=0, atol=2 * 32 * EPS * size * (1 + abs(rate)))


@settings(settings.get_profile("exact_dynamics_reference"))
@given(seed=seeds)
def test_core_constant_thrust_solution_matches_the_reference(seed):
    """ConstantThrustSolution.at(t) and delta_v against constant_thrust and Tsiolkovsky, for burns with |ṁ t/m0| ≥ 0.05
    (the reference's (m/ṁ) ln(m/m0) − t cancels to 2 eps/|x| relative: ≤ 40 eps) up to 90 % of the mass spent:
    ln(m/m0) ≤ 2.3 amplifies nothing; 2 sides × 64 eps on |p0| + |v0| t + |g| t² + |u| t (the terms' magnitudes)."""
    rng = np.random.default_rng(seed)
    m0, rate = rng.uniform(1, 10), -rng.uniform(0.1, 2)
    u, g, p0, v0 = rng.uniform(-300, 300, 3), rng.uniform(-10, 10, 3), rng.uniform(-5, 5, 3), rng.uniform(-5, 5, 3)
    solution = rd.ConstantThrustSolution(m0, rate, u, g, p0, v0)
    t_end = -0.9 * m0 / rate
    for t in np.linspace(0.05 * t_end, t_end, 4):
        p, v, m = solution.at(t)
        p_ref, v_ref, m_ref = ref.constant_thrust(m0, rate, u, g, p0, v0, t)
        assert m == pytest.approx(m_ref, rel=4 * EPS)
        speed = np.linalg.norm(v0) + np.linalg.norm(g) * t + np.linalg.norm(u) * 2.3
        np.testing.assert_allclose(v, v_ref, rtol=0, atol=2 * 64 * EPS * speed)
        np.testing.assert_allclose(p, p_ref, rtol=0, atol=2 * 64 * EPS * (np.linalg.norm(p0) + speed * t))
        assert solution.delta_v(m) == pytest.approx(ref.tsiolkovsky_delta_v(u, m0, m), rel=8 * EPS)
