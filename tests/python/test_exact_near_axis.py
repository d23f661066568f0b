"""The exact torque-free solution close to a principal axis, through the Python API:
the transverse body momentum |m_perp| log-spaced from the smallest subnormal to 1e-3 |L| about each
principal axis, either sign of the axial momentum.

References: the steady-spin limit with its first-order correction where it is exact to a fraction of
an ulp (|m_perp|/G <= 1e-12), and the closed form evaluated in mpmath with enough digits to resolve
1 - m (|m_perp|/G >= 1e-30), so that every magnitude has an independent reference; `simulate` with
`exact` and `exact_flow_kick` must inherit the accuracy. tests/cpp/test_exact_near_axis.cpp runs the
steady-spin sweep in C++ (also for nearly symmetric bodies and the one-step flow)."""

import math

import mpmath as mp
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rigiddyn

EPS = np.finfo(float).eps
I_DIAG = np.array([2.0, 3.0, 5.0])
Q0 = Rotation.from_rotvec([0.3, -0.2, 0.5])
G = 1.3  # |L| [kg m^2/s]
SMALLEST_SUBNORMAL = 5e-324


def body_momentum(axis, sign, eps_m, beta=0.9):
    """Body momentum G e_axis (sign) plus a transverse part of relative size eps_m, as the solution
    sees it (m = I w with w = m/I rounded)."""
    i, j = (axis + 1) % 3, (axis + 2) % 3
    w = np.zeros(3)
    w[axis] = sign * G / I_DIAG[axis]
    w[i] = G * eps_m * math.cos(beta) / I_DIAG[i]
    w[j] = G * eps_m * math.sin(beta) / I_DIAG[j]
    return w, I_DIAG * w


def steady_spin_reference(axis, m0, t):
    """The steady-spin limit about `axis` with its first-order correction: R(t) = exp(a(t) L/|L|) R0 B(t),
    a = (2T/G) t, B the rotation carrying the linearised m(t) onto m0 (see test_exact_near_axis.cpp);
    exact to 8 (I_max/I_min) (|m_perp|_max/G)^2 (1 + angle turned) rad."""
    i, j = (axis + 1) % 3, (axis + 2) % 3
    g = m0[axis]
    a = 1.0 / I_DIAG - 1.0 / I_DIAG[axis]
    p = a[i] * a[j] * g * g
    rate = math.sqrt(abs(p))
    c, s = (math.cos(rate * t), math.sin(rate * t) / rate) if p > 0 else (math.cosh(rate * t), math.sinh(rate * t) / rate)
    m = m0.copy()
    m[i] = c * m0[i] - s * g * a[j] * m0[j]
    m[j] = c * m0[j] + s * g * a[i] * m0[i]
    norm = np.linalg.norm(m0)
    L_W = Q0.apply(m0)
    spin = Rotation.from_rotvec(L_W / norm * (np.sum(m0 * m0 / I_DIAG) / norm * t))
    R = spin * Q0 * Rotation.from_rotvec(np.cross(m, m0) / norm**2)
    mu_max = math.hypot(m0[i], m0[j]) * (max(abs(c), 1.0) + abs(s) * abs(g) * max(abs(a[i]), abs(a[j])))
    bound = 8 * I_DIAG.max() / I_DIAG.min() * (mu_max / norm) ** 2 * (1 + abs(g) * abs(t) / I_DIAG[axis])
    return R, bound


def mp_closed_form(m0, t, dps):
    """R_WB(t) from the Z-X-Z closed form (Landau & Lifshitz §37) in mpmath at
    `dps` digits, for the diagonal inertia I_DIAG (ascending) and body momentum m0, R(0) = Q0. Case A
    (Delta2 > 0) as written; case B through the signed reversal of the axes (e3, e2, -e1), which maps it
    onto case A with the moments in descending order: every formula keeps its sign except Euler's
    equations, which then need the phase rate -lambda."""
    with mp.workdps(dps):
        I = [mp.mpf(v) for v in I_DIAG]
        m = [mp.mpf(v) for v in m0]
        delta2 = m[0] ** 2 * (I[0] - I[1]) / I[0] + m[2] ** 2 * (I[2] - I[1]) / I[2]
        C, direction = mp.eye(3), 1
        if delta2 < 0:
            direction = -1
            C = mp.matrix([[0, 0, -1], [0, 1, 0], [1, 0, 0]])  # columns e3, e2, -e1
            I = [I[2], I[1], I[0]]
            m = [m[2], m[1], -m[0]]
        I1, I2, I3 = I
        d1 = m[1] ** 2 * (I2 - I1) / I2 + m[2] ** 2 * (I3 - I1) / I3
        d3 = m[0] ** 2 * (I1 - I3) / I1 + m[1] ** 2 * (I2 - I3) / I2
        A1, A2, A3 = mp.sqrt(-d3 / (I1 * (I3 - I1))), mp.sqrt(-d3 / (I2 * (I3 - I2))), mp.sqrt(d1 / (I3 * (I3 - I1)))
        lam = direction * mp.sqrt((I3 - I2) * d1 / (I1 * I2 * I3))
        par = (I2 - I1) * -d3 / ((I3 - I2) * d1)
        n = -I3 * (I2 - I1) / (I1 * (I3 - I2))
        s = mp.sign(m[2])
        K, Pi = mp.ellipk(par), mp.ellippi(n, par)
        u0 = mp.ellipf(mp.atan2(s * m[1] / (I2 * A2), m[0] / (I1 * A1)), par)

        def big_pi(u):  # Π(am u, n|m) for any u: Π(φ + jπ) = Π(φ) + 2j Π(n|m)
            j = mp.nint(u / (2 * K))
            phi = mp.asin(mp.ellipfun("sn", u - 2 * j * K, par))
            return (mp.ellippi(n, phi, par) if phi != 0 else 0) + 2 * j * Pi

        def zxz(phi, mq):
            psi = mp.atan2(mq[0], mq[1])
            theta = mp.atan2(mp.sqrt(mq[0] ** 2 + mq[1] ** 2), mq[2])
            rz = lambda x: mp.matrix([[mp.cos(x), -mp.sin(x), 0], [mp.sin(x), mp.cos(x), 0], [0, 0, 1]])
            rx = lambda x: mp.matrix([[1, 0, 0], [0, mp.cos(x), -mp.sin(x)], [0, mp.sin(x), mp.cos(x)]])
            return rz(phi) * rx(theta) * rz(psi)

        G_ = mp.sqrt(sum(v * v for v in m))
        u = lam * mp.mpf(t) + u0
        sn, cn, dn = (mp.ellipfun(f, u, par) for f in ("sn", "cn", "dn"))
        m_t = [I1 * A1 * cn, I2 * s * A2 * sn, I3 * s * A3 * dn]
        phi = G_ * mp.mpf(t) / I3 + G_ * (I3 - I1) / (I1 * I3 * lam) * (big_pi(u) - big_pi(u0))
        R = C * zxz(0, m).T * zxz(phi, m_t) * C.T
        return Q0 * Rotation.from_matrix(np.array(R.tolist(), dtype=float))


def angle(q, R):
    return (Rotation.from_quat(q).inv() * R).magnitude()


def ulps_of_angle(axis, t):
    """An ulp of the angle turned, G |t|/I_axis, counted as eps max(1 rad, angle): the phases are O(1) rad
    even when the angle turned is small."""
    return EPS * max(1.0, G * abs(t) / I_DIAG[axis])


TRANSVERSE = [SMALLEST_SUBNORMAL, 1e-320, 1e-310, 1e-300, 3.5 * math.sqrt(SMALLEST_SUBNORMAL), 1e-100, 1e-30, 1e-20,
              1e-12, 1e-9, 1e-6, 1e-3]


@pytest.mark.parametrize("axis", [0, 1, 2])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_attitude_to_16_ulps_of_the_angle_turned(axis, sign):
    worst = 0.0
    for eps_m in TRANSVERSE:
        w0, m0 = body_momentum(axis, sign, eps_m)
        sol = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0.as_quat(), w0)
        q, w = sol.state_at(0.0)
        # t = 0 is the initial state: a phase round trip through sn, cn, dn and Pi, a few ulps
        assert angle(q, Q0) <= 8 * EPS, eps_m
        np.testing.assert_allclose(w, w0, rtol=0, atol=8 * EPS * np.linalg.norm(w0))
        for t in (0.5, 7.3, 20.0, -3.0):
            q, _ = sol.state_at(t)
            ulp = ulps_of_angle(axis, t)
            if eps_m <= 1e-12:
                R_ref, bound = steady_spin_reference(axis, m0, t)
                assert bound < 0.1 * ulp  # the reference is exact here
            if eps_m >= 1e-30:
                # enough digits for 1 - m ~ (|m_perp|/G)^2 and 30 more: the reference is exact
                R_ref = mp_closed_form(m0, t, 30 + int(-2 * math.log10(eps_m)))
            error = angle(q, R_ref)
            # the required bound: 16 ulps of the angle turned, which also covers the reference's
            # own rounding to double (~3 ulps for the steady-spin one, 1 for mpmath's)
            assert error <= 16 * ulp, (eps_m, t, error / ulp)
            worst = max(worst, error / ulp)
    print(f"axis {axis + 1}, sign {sign:+.0f}: worst {worst:.2f} ulps of max(1 rad, angle turned)")


def test_references_agree_where_both_hold():
    # |m_perp|/G = 1e-12 about each axis: steady spin + first order (exact to < 0.1 ulp, then formed by
    # three rotation compositions in double, ~1 ulp each) and mpmath's closed form (rounded once to
    # double) agree to that rounding, so neither formula is wrong
    for axis in range(3):
        _, m0 = body_momentum(axis, 1.0, 1e-12)
        for t in (0.5, 20.0):
            R1, _ = steady_spin_reference(axis, m0, t)
            R2 = mp_closed_form(m0, t, 60)
            assert (R1.inv() * R2).magnitude() <= 4 * ulps_of_angle(axis, t)


def test_reported_case_near_the_major_axis():
    # I = diag(2, 3, 5), body momentum (3.5 sqrt(5e-324), 0, 1): 0.010 rad off at t = 0 before
    m0 = np.array([3.5 * math.sqrt(SMALLEST_SUBNORMAL), 0.0, 1.0])
    sol = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), [0, 0, 0, 1.0], m0 / I_DIAG)
    q, _ = sol.state_at(0.0)
    assert Rotation.from_quat(q).magnitude() <= 8 * EPS
    q, _ = sol.state_at(20.0)
    # a spin about axis 3 at G/I3 = 0.2 rad/s, to ~1e-161 rad (the transverse part): 4 rad turned
    assert angle(q, Rotation.from_rotvec([0.0, 0.0, 4.0])) <= 16 * 4.0 * EPS


@pytest.mark.parametrize("method", ["exact", "exact_flow_kick"])
@pytest.mark.parametrize("axis", [0, 1, 2])
def test_simulate_inherits_it(method, axis):
    # transverse parts below 1e-12 |L|, where the steady-spin reference is exact
    body = rigiddyn.RigidBody(1.0, np.diag(I_DIAG))
    dt, steps = 0.02, 1000
    for eps_m in (SMALLEST_SUBNORMAL, 1e-310, 3.5 * math.sqrt(SMALLEST_SUBNORMAL), 1e-100, 1e-13):
        w0, m0 = body_momentum(axis, -1.0, eps_m)
        run = rigiddyn.simulate(body, rigiddyn.RigidBodyState(q_WB=Q0.as_quat(), w_B=w0), dt=dt, steps=steps,
                                method=method, record_every=100)
        for k, t in enumerate(run.t):
            R_ref, _ = steady_spin_reference(axis, m0, t)
            # `exact` evaluates the closed form at t: 16 ulps of the angle turned; `exact_flow_kick`
            # composes t/dt one-step flows, each within 16 ulps of max(1 rad, its angle), errors adding
            n_steps = 1 if method == "exact" else round(t / dt)
            bound = 16 * (ulps_of_angle(axis, t) if method == "exact" else n_steps * ulps_of_angle(axis, dt))
            assert angle(run.q_WB[k], R_ref) <= max(bound, 16 * EPS), (method, eps_m, t)
