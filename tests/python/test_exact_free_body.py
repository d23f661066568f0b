"""The exact torque-free rigid body (rigiddyn.TorqueFreeSolution) against SciPy's DOP853, against the
same closed form in mpmath extended precision near the separatrix, and by its invariants."""

import math

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.spatial.transform import Rotation

import rigiddyn
from _error_bounds import closed_form_error, inertia_condition

EPS = np.finfo(float).eps
Q0 = Rotation.from_rotvec([0.3, -0.2, 0.5]).as_quat()
R_TILT = Rotation.from_rotvec([0.4, 0.1, -0.3]).as_matrix()


def euler_quaternion_rhs(inertia):
    """Euler's equations I w' = (I w) x w and q' = q (x) (w, 0)/2 for y = (w_B, q_WB as x, y, z, w)."""
    inv = np.linalg.inv(inertia)
    i = [[float(v) for v in row] for row in inertia]
    k = [[float(v) for v in row] for row in inv]

    def f(_, y):
        w1, w2, w3, x, yy, z, s = y
        m1 = i[0][0] * w1 + i[0][1] * w2 + i[0][2] * w3
        m2 = i[1][0] * w1 + i[1][1] * w2 + i[1][2] * w3
        m3 = i[2][0] * w1 + i[2][1] * w2 + i[2][2] * w3
        c1, c2, c3 = m2 * w3 - m3 * w2, m3 * w1 - m1 * w3, m1 * w2 - m2 * w1
        return [k[0][0] * c1 + k[0][1] * c2 + k[0][2] * c3, k[1][0] * c1 + k[1][1] * c2 + k[1][2] * c3,
                k[2][0] * c1 + k[2][1] * c2 + k[2][2] * c3,
                0.5 * (s * w1 + yy * w3 - z * w2), 0.5 * (s * w2 + z * w1 - x * w3),
                0.5 * (s * w3 + x * w2 - yy * w1), -0.5 * (x * w1 + yy * w2 + z * w3)]

    return f


def angle_between(q1, q2):
    return (Rotation.from_quat(q1).inv() * Rotation.from_quat(q2)).magnitude()


@pytest.mark.parametrize("inertia, w0, case", [
    (np.diag([1.0, 2.0, 3.0]), [0.3, 0.5, 1.0], "A"),
    (np.diag([1.0, 2.0, 3.0]), [1.0, 0.5, -0.3], "B"),
    (R_TILT @ np.diag([3.0, 1.0, 2.0]) @ R_TILT.T, [0.3, -0.5, 1.0], "A"),
])
def test_matches_dop853_over_many_periods(inertia, w0, case):
    w0 = np.array(w0)
    sol = rigiddyn.TorqueFreeSolution(inertia, Q0, w0)
    assert sol.case == case
    t = np.linspace(0, 12 * sol.period, 97)
    ode = solve_ivp(euler_quaternion_rhs(inertia), (0, t[-1]), np.concatenate([w0, Q0]), method="DOP853",
                    rtol=1e-13, atol=1e-13, t_eval=t)
    q, w = sol.state_at(t)
    coarse = solve_ivp(euler_quaternion_rhs(inertia), (0, t[-1]), np.concatenate([w0, Q0]), method="DOP853",
                       rtol=1e-12, atol=1e-12, t_eval=t)
    # DOP853's global error shrinks >= 2x per decade of tolerance (order 8, error ~ tol^(8/9): 7.7x),
    # so its error at 1e-13 is <= |y(1e-12) - y(1e-13)| (pointwise); the closed form adds its own
    # bound (_error_bounds.closed_form_error: 16 eps kappa (1 + |w t|))
    own = closed_form_error(inertia_condition(inertia), w0, t[-1])
    np.testing.assert_allclose(w, ode.y[:3].T, rtol=0,
                               atol=np.abs(coarse.y[:3] - ode.y[:3]).max() + own * np.linalg.norm(w0))
    assert np.all(angle_between(q, ode.y[3:].T) <= angle_between(coarse.y[3:].T, ode.y[3:].T).max() + own)


@pytest.mark.slow
@pytest.mark.parametrize("w0, case", [([0.3, 0.5, 1.0], "A"), ([1.0, 0.5, -0.3], "B")])
def test_dop853_converges_to_it_over_100_periods(w0, case):
    # The requirement: agreement with DOP853 at rtol = atol = 1e-13 over 100 periods. There DOP853's own
    # global error (~5e-11 |w0| in w, ~5e-10 rad in attitude; it grows ~13x per decade of tolerance)
    # dominates, so show the difference is the ODE solver's: as DOP853's tolerance goes 1e-12 -> 1e-13
    # -> 3e-14 its distance to the closed form shrinks with its own error, and at 1e-13 it is a small
    # fraction (measured 0.08) of DOP853's error estimate |y(1e-12) - y(1e-13)|, which a closed form
    # wrong by more than that fraction of the estimate could not achieve.
    I = np.diag([1.0, 2.0, 3.0])
    w0 = np.array(w0)
    sol = rigiddyn.TorqueFreeSolution(I, Q0, w0)
    assert sol.case == case
    t = np.linspace(0, 100 * sol.period, 201)
    q, w = sol.state_at(t)
    tols = (1e-12, 1e-13, 3e-14)
    ode = [solve_ivp(euler_quaternion_rhs(I), (0, t[-1]), np.concatenate([w0, Q0]), method="DOP853",
                     rtol=tol, atol=tol, t_eval=t).y for tol in tols]
    w_diff = [np.linalg.norm(y[:3].T - w, axis=1).max() / np.linalg.norm(w0) for y in ode]
    angle_diff = [angle_between(y[3:].T, q).max() for y in ode]
    w_estimate = np.linalg.norm(ode[0][:3] - ode[1][:3], axis=0).max() / np.linalg.norm(w0)
    angle_estimate = angle_between(ode[0][3:].T, ode[1][3:].T).max()
    # DOP853 (order 8) keeps tolerance proportionality, error ~ tol^(8/9) (>= 5x per decade, >= 2x for
    # 1e-13 -> 3e-14): while its error dominates the closed form's, the distance shrinks by those
    # factors, and its error at 1e-13 is <= estimate/(5 - 1) < 0.25 estimate
    for diff, estimate in ((w_diff, w_estimate), (angle_diff, angle_estimate)):
        assert diff[2] < 0.5 * diff[1] and diff[1] < 0.25 * diff[0]  # converging as DOP853 tightens
        assert diff[1] < 0.25 * estimate
    # the agreement required, within DOP853's own error estimate (not a figure seen once)
    assert w_diff[1] <= w_estimate and angle_diff[1] <= angle_estimate


def test_invariants_to_round_off():
    inertia = R_TILT @ np.diag([1.0, 2.0, 3.0]) @ R_TILT.T
    for w0 in ([0.3, 0.5, 1.0], [1.0, 0.5, 0.3], [0.01, 2.0, 0.01]):
        sol = rigiddyn.TorqueFreeSolution(inertia, Q0, w0, scalar_first=False)
        t = np.linspace(-50 * sol.period, 50 * sol.period, 1001)
        q, w = sol.state_at(t)
        m = w @ inertia  # inertia is symmetric: rows of I w
        energy = 0.5 * np.einsum("ni,ni->n", w, m)
        L_W = Rotation.from_quat(q).apply(m)
        G = np.linalg.norm(sol.angular_momentum_W)
        # the orbit's identities hold to a few ulps at any t (sn^2 + cn^2 = 1 at any phase; only the
        # phase errs with t, free_body.hpp): E and |m| to a few ulps, numpy's evaluation adds <= 8 eps
        assert np.abs(energy / sol.kinetic_energy.rotational - 1).max() < 32 * EPS
        assert np.abs(np.linalg.norm(m, axis=1) / G - 1).max() < 32 * EPS
        # the attitude error grows like eps times the phase (about 1e3 rad here): closed_form_error
        assert np.abs(L_W - sol.angular_momentum_W).max() / G < 2 * closed_form_error(3.0, w0, t[-1])
        assert np.abs(np.linalg.norm(q, axis=1) - 1).max() < 4 * EPS  # normalised: 2 eps, |q| 2 eps


def mp_case_a(inertia_diag, w0, t):
    """The case-A closed form evaluated with mpmath at 50 digits (q0 = identity, diagonal inertia):
    returns w_B(t) and the rotation matrix R_WB(t)."""
    with mp.workdps(50):
        I1, I2, I3 = (mp.mpf(v) for v in inertia_diag)
        m = [mp.mpf(inertia_diag[k]) * mp.mpf(w0[k]) for k in range(3)]
        G = mp.sqrt(sum(v * v for v in m))
        d1 = m[1] ** 2 * (I2 - I1) / I2 + m[2] ** 2 * (I3 - I1) / I3
        d3 = m[0] ** 2 * (I1 - I3) / I1 + m[1] ** 2 * (I2 - I3) / I2
        A1, A2, A3 = mp.sqrt(-d3 / (I1 * (I3 - I1))), mp.sqrt(-d3 / (I2 * (I3 - I2))), mp.sqrt(d1 / (I3 * (I3 - I1)))
        lam = mp.sqrt((I3 - I2) * d1 / (I1 * I2 * I3))
        par = (I2 - I1) * -d3 / ((I3 - I2) * d1)
        n = -I3 * (I2 - I1) / (I1 * (I3 - I2))
        s = mp.sign(m[2])
        K = mp.ellipk(par)
        u0 = mp.ellipf(mp.atan2(s * m[1] / (I2 * A2), m[0] / (I1 * A1)), par)

        def big_pi(u):
            j = mp.nint(u / (2 * K))
            return mp.ellippi(n, mp.asin(mp.ellipfun("sn", u - 2 * j * K, par)), par) + 2 * j * mp.ellippi(n, par)

        def zxz(phi, mq):
            psi = mp.atan2(mq[0], mq[1])
            theta = mp.atan2(mp.sqrt(mq[0] ** 2 + mq[1] ** 2), mq[2])
            rz = lambda a: mp.matrix([[mp.cos(a), -mp.sin(a), 0], [mp.sin(a), mp.cos(a), 0], [0, 0, 1]])
            rx = lambda a: mp.matrix([[1, 0, 0], [0, mp.cos(a), -mp.sin(a)], [0, mp.sin(a), mp.cos(a)]])
            return rz(phi) * rx(theta) * rz(psi)

        u = lam * mp.mpf(t) + u0
        sn, cn, dn = (mp.ellipfun(f, u, par) for f in ("sn", "cn", "dn"))
        w = [A1 * cn, s * A2 * sn, s * A3 * dn]
        phi = G * mp.mpf(t) / I3 + G * (I3 - I1) / (I1 * I3 * lam) * (big_pi(u) - big_pi(u0))
        R = zxz(0, m).T * zxz(phi, [I1 * w[0], I2 * w[1], I3 * w[2]])
        return np.array([float(v) for v in w]), np.array(R.tolist(), dtype=float), 1 - par


@pytest.mark.parametrize("eps_w", [1e-5, 3e-8])
def test_near_separatrix_matches_extended_precision(eps_w):
    # I = (1, 2, 3): w0 = (e, 2, e sqrt(3) + 1e-3 e²) is close to the separatrix (1 - m = 2e-10, 2e-15)
    inertia = [1.0, 2.0, 3.0]
    w0 = [eps_w, 2.0, eps_w * math.sqrt(3.0) + eps_w ** 2 * 1e-3]
    sol = rigiddyn.TorqueFreeSolution(np.diag(inertia), [0, 0, 0, 1], w0)
    assert sol.case == "A"
    for t in (0.37 * sol.period, 1.5 * sol.period, 3.2 * sol.period):
        w_ref, R_ref, mc_ref = mp_case_a(inertia, w0, t)
        # 1 - m from double-double Delta_2 (free_body.hpp): a few ulps relative; 1e-13 = 450 eps
        assert sol.parameter_mc == pytest.approx(float(mc_ref), rel=1e-13)
        q, w = sol.state_at(t)
        # the phase λ t is known to eps λ t; slopes of ω and the attitude are O(|ω|)
        tol = 64 * EPS * (1 + 2.0 * t)
        np.testing.assert_allclose(w, w_ref, rtol=0, atol=tol)
        assert angle_between(q, Rotation.from_matrix(R_ref).as_quat()) < tol


@pytest.mark.parametrize("eps_w", [1e-4, 3e-8])
def test_forward_and_back_near_separatrix(eps_w):
    # start near the saddle (the body lingers there), run 1000 periods forward, restart from the
    # computed state and run back
    I = np.diag([1.0, 2.0, 3.0])
    w0 = np.array([eps_w, 2.0, eps_w * math.sqrt(3.0) + eps_w ** 2 * 1e-3])
    sol = rigiddyn.TorqueFreeSolution(I, Q0, w0)
    T = 1000 * sol.period
    q1, w1 = sol.state_at(T)
    back = rigiddyn.TorqueFreeSolution(I, q1, w1)
    q2, w2 = back.state_at(-T)
    assert sol.parameter_mc < 3e-8
    # back at the saddle after 1000 periods, where w moves with the phase u only as
    # |dw/du| ~ |w| sqrt(1 - m) <= 2e-4 |w|: the phase error (<= 16 eps per radian of lambda T ~ 4e4,
    # both ways) moves w by <= 2 x 16 x 4e4 x 2e-4 = 260 eps; the attitude errs by
    # <= 2 x closed_form_error: 2 x 16 kappa (kappa = 3) ulps of the angle turned = 96 ulps
    assert np.abs(w2 - w0).max() < 300 * EPS * np.linalg.norm(w0)
    assert angle_between(q2, Q0) < 300 * np.spacing(np.linalg.norm(w0) * T)


def test_dzhanibekov_flip_takes_half_the_period():
    I = np.diag([1.0, 2.0, 3.0])
    sol = rigiddyn.TorqueFreeSolution(I, Q0, [0.01, 2.0, 0.01])
    w2 = lambda t: sol.state_at(t)[1][1]
    t = np.linspace(0, 3 * sol.period, 3001)
    w = sol.state_at(t)[1][:, 1]
    flips = [brentq(w2, t[i], t[i + 1], xtol=1e-14) for i in np.nonzero(np.sign(w[:-1]) != np.sign(w[1:]))[0]]
    assert len(flips) == 6
    # flip times: brentq's xtol 1e-14 s plus the phase error (16 eps kappa per radian, |w| t <= 140
    # rad over 3 periods) over the rate |dw2/dt| at a flip: <= 2e-14 + 4e-12 s, over half a period (11 s)
    np.testing.assert_allclose(np.diff(flips), sol.period / 2, rtol=1e-12)


def test_symmetric_and_sphere_are_closed_form_precession():
    # oblate symmetric body about B's z axis: w_perp turns at Ω = (I_a - I_t) w_3 / I_t
    w0 = np.array([0.3, -0.5, 1.0])
    sol = rigiddyn.TorqueFreeSolution(np.diag([2.0, 2.0, 3.0]), Q0, w0)
    assert sol.case == "symmetric"
    omega = (3.0 - 2.0) * w0[2] / 2.0
    assert sol.period == pytest.approx(2 * math.pi / omega, rel=4 * EPS)  # 2 pi/Omega: <= 3 roundings
    t = np.linspace(-10, 10, 21)
    q, w = sol.state_at(t)
    w_ref = np.stack([w0[0] * np.cos(omega * t) - w0[1] * np.sin(omega * t),
                      w0[0] * np.sin(omega * t) + w0[1] * np.cos(omega * t), np.full_like(t, w0[2])], axis=1)
    np.testing.assert_allclose(w, w_ref, atol=closed_form_error(1.5, w0, 10.0) * np.linalg.norm(w0))
    # attitude: R(t) = exp(t L_W/I_t) R0 exp(-t Ω e3)  (Landau & Lifshitz §33)
    L_W = Rotation.from_quat(Q0).apply(np.diag([2.0, 2.0, 3.0]) @ w0)
    R_ref = (Rotation.from_rotvec(np.outer(t, L_W / 2.0)) * Rotation.from_quat(Q0)
             * Rotation.from_rotvec(np.outer(-omega * t, [0, 0, 1])))
    assert np.all(angle_between(q, R_ref.as_quat()) < 2 * closed_form_error(1.5, w0, 10.0))  # both sides
    # sphere: constant w, rotation about the fixed axis
    sphere = rigiddyn.TorqueFreeSolution(2.5 * np.eye(3), Q0, w0)
    assert sphere.case == "sphere" and sphere.period == math.inf
    q, w = sphere.state_at(t)
    np.testing.assert_array_equal(w, np.tile(w0, (len(t), 1)))  # constant: returned as given
    R_ref = Rotation.from_rotvec(np.outer(t, Rotation.from_quat(Q0).apply(w0))) * Rotation.from_quat(Q0)
    assert np.all(angle_between(q, R_ref.as_quat()) < 2 * closed_form_error(1.0, w0, 10.0))  # both sides


def test_nearly_symmetric_body_tends_to_the_symmetric_branch():
    w0 = [0.3, -0.5, 1.0]
    sym = rigiddyn.TorqueFreeSolution(R_TILT @ np.diag([2.0, 2.0, 3.0]) @ R_TILT.T, Q0, w0)
    near = rigiddyn.TorqueFreeSolution(R_TILT @ np.diag([2.0, 2.0 * (1 + 1e-9), 3.0]) @ R_TILT.T, Q0, w0)
    assert sym.case == "symmetric" and near.case == "A"
    q1, w1 = sym.state_at(np.linspace(0, 20, 11))
    q2, w2 = near.state_at(np.linspace(0, 20, 11))
    # the motions of inertias 1e-9 apart differ by ~1e-9 per radian turned (|w| t <= 24 rad): 2.4e-8
    np.testing.assert_allclose(w1, w2, atol=1e-7)
    assert np.all(angle_between(q1, q2) < 1e-7)


def test_hairer_lubich_wanner_problem():
    # GNI IV.1: I = (2, 1, 2/3) (not physically realizable; accepted with the opt-in),
    # L0 = (cos 1.1, 0, sin 1.1): case B about the smallest moment's axis, period 10.7315
    I = np.diag([2.0, 1.0, 2.0 / 3.0])
    L0 = np.array([math.cos(1.1), 0.0, math.sin(1.1)])
    sol = rigiddyn.TorqueFreeSolution(I, [0, 0, 0, 1], L0 / np.diag(I), check=rigiddyn.InertiaCheck.allow_unrealizable)
    assert sol.case == "B"
    assert sol.period == pytest.approx(10.7315, abs=5e-5)  # published to 4 decimals
    np.testing.assert_allclose(sol.principal_moments, [2.0 / 3.0, 1.0, 2.0])


def test_separatrix_and_steady_spins():
    # I = (2, 3, 6) (unrealizable: the opt-in), L = (6, ., 6): L1²(I2 - I1)/I1 = L3²(I3 - I2)/I3 exactly,
    # so Δ2 = 0
    I = np.diag([2.0, 3.0, 6.0])
    sol = rigiddyn.TorqueFreeSolution(I, Q0, [3.0, 0.4, 1.0], check=rigiddyn.InertiaCheck.allow_unrealizable)
    assert sol.case == "separatrix" and sol.period == math.inf
    t = np.linspace(0, 6, 31)  # the separatrix is unstable: DOP853 leaves it once close to the saddle
    ode = solve_ivp(euler_quaternion_rhs(I), (0, 6), np.concatenate([[3.0, 0.4, 1.0], Q0]), method="DOP853",
                    rtol=1e-13, atol=1e-13, t_eval=t)
    q, w = sol.state_at(t)
    coarse = solve_ivp(euler_quaternion_rhs(I), (0, 6), np.concatenate([[3.0, 0.4, 1.0], Q0]), method="DOP853",
                       rtol=1e-12, atol=1e-12, t_eval=t)
    # DOP853's error at 1e-13 <= |y(1e-12) - y(1e-13)| (>= 2x per decade, as above), plus the
    # closed form's own bound
    own = closed_form_error(3.0, [3.0, 0.4, 1.0], 6.0)
    np.testing.assert_allclose(w, ode.y[:3].T, rtol=0, atol=np.abs(coarse.y[:3] - ode.y[:3]).max() + own * 3.2)
    assert np.all(angle_between(q, ode.y[3:].T) < angle_between(coarse.y[3:].T, ode.y[3:].T).max() + own)
    for w0, case in (([0, 2.0, 0], "separatrix"), ([0, 0, 2.0], "A"), ([2.0, 0, 0], "B"), ([0, 0, 0], "separatrix")):
        steady = rigiddyn.TorqueFreeSolution(I, Q0, w0, check=rigiddyn.InertiaCheck.allow_unrealizable)
        q, w = steady.state_at(t)
        assert steady.case == case
        np.testing.assert_array_equal(w, np.tile(w0, (len(t), 1)))  # steady: returned as given
        R_ref = Rotation.from_rotvec(np.outer(t, Rotation.from_quat(Q0).apply(w0))) * Rotation.from_quat(Q0)
        # exp(t w) on both sides: 2 x closed_form_error at |w t| <= 12 rad (kappa = 1: no m <-> w)
        assert np.all(angle_between(q, R_ref.as_quat()) < 2 * closed_form_error(1.0, w0, 6.0))


def test_shapes_and_scalar_first():
    I = np.diag([1.0, 2.0, 3.0])
    a = rigiddyn.TorqueFreeSolution(I, Q0, [0.3, 0.5, 1.0])
    b = rigiddyn.TorqueFreeSolution(I, np.roll(Q0, 1), [0.3, 0.5, 1.0], scalar_first=True)
    q, w = a.state_at(1.5)
    assert q.shape == (4,) and w.shape == (3,)
    qb, wb = b.state_at(np.array([1.5]))
    assert qb.shape == (1, 4) and wb.shape == (1, 3)
    np.testing.assert_array_equal(np.roll(q, 1), qb[0])
    np.testing.assert_allclose(a.state_at(0.0)[0], Q0, rtol=0, atol=4 * EPS)  # t = 0: a few ulps (free_body.hpp)


def test_bad_input():
    I = np.diag([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="inertia"):
        rigiddyn.TorqueFreeSolution(np.diag([1.0, -2.0, 3.0]), Q0, [1, 2, 3])
    with pytest.raises(ValueError, match="inertia"):
        rigiddyn.TorqueFreeSolution(I + np.triu(np.ones((3, 3)), 1), Q0, [1, 2, 3])
    with pytest.raises(ValueError, match="q_WB"):
        rigiddyn.TorqueFreeSolution(I, [0, 0, 0, 2.0], [1, 2, 3])
    with pytest.raises(ValueError, match="w_B"):
        rigiddyn.TorqueFreeSolution(I, Q0, [1, np.nan, 3])
    with pytest.raises(ValueError, match="t"):
        rigiddyn.TorqueFreeSolution(I, Q0, [1, 2, 3]).state_at(np.inf)
