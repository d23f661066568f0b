"""Jacobi elliptic functions and elliptic integrals of rigiddyn.exact against mpmath (40 digits),
including 1 - m down to 1e-15 and large arguments, where scipy.special.ellipj fails."""

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rigiddyn

EPS = np.finfo(float).eps
mp.mp.dps = 40


def mp_sncndn(u, mc):
    m = 1 - mp.mpf(mc)  # the exact parameter whose complement is the double mc
    return [float(mp.ellipfun(f, u, m)) for f in ("sn", "cn", "dn")]


@pytest.mark.parametrize("mc", [0.9, 0.5, 1e-3, 1e-6, 1e-9, 1e-12, 1e-15])
def test_jacobi_ellipj_matches_mpmath(mc):
    rng = np.random.default_rng(int(-np.log10(mc) * 10))
    K = rigiddyn.ellipk(1 - mc, mc)
    us = np.concatenate([rng.uniform(-4 * K, 4 * K, 6), rng.uniform(-1e3, 1e3, 3), [K, 3 * K, -K / 2]])
    sn, cn, dn = rigiddyn.jacobi_ellipj(us, 1 - mc, mc)
    for i, u in enumerate(us):
        ref = mp_sncndn(u, mc)
        # the argument u is known to eps |u| and the functions have slopes <= 1
        tol = 8 * EPS * max(1.0, abs(u))
        assert abs(sn[i] - ref[0]) <= tol and abs(cn[i] - ref[1]) <= tol and abs(dn[i] - ref[2]) <= tol, (u, ref)


def test_dn_relative_accuracy_near_m_one():
    # dn(K + 2jK) = sqrt(mc): tiny, yet to a few ulps relative when mc is passed
    for mc in (1e-9, 1e-15):
        K = rigiddyn.ellipk(1 - mc, mc)
        for u in (K, 3 * K, -5 * K):
            _, _, dn = rigiddyn.jacobi_ellipj(u, 1 - mc, mc)
            ref = float(mp.ellipfun("dn", mp.mpf(u), 1 - mp.mpf(mc)))
            # dn is flat at odd multiples of K (dn' = -m sn cn = 0): the argument's rounding eps |u|
            # enters squared; what is left is the evaluation's few ulps (elliptic.hpp) and K's (<= 100 eps)
            assert abs(dn / ref - 1) < 1e-13


def test_scalar_and_array_forms_agree():
    us = np.array([-3.0, 0.1, 7.5])
    sn, cn, dn = rigiddyn.jacobi_ellipj(us, 0.8)
    for i, u in enumerate(us):
        assert rigiddyn.jacobi_ellipj(u, 0.8) == (sn[i], cn[i], dn[i])
    assert isinstance(rigiddyn.jacobi_ellipj(1.0, 0.8)[0], float)


@pytest.mark.parametrize("mc", [0.49, 1e-8, 1e-15])
def test_ellipk_and_ellippi_match_mpmath(mc):
    m = 1 - mp.mpf(mc)
    # elliptic.hpp: K, Pi and the Carlson forms to a few ulps (against 40 digits: the core's error only)
    assert rigiddyn.ellipk(1 - mc, mc) == pytest.approx(float(mp.ellipk(m)), rel=4 * EPS)
    n = -0.7
    assert rigiddyn.ellippi(n, 1 - mc, mc) == pytest.approx(float(mp.ellippi(n, m)), rel=8 * EPS)
    K = mp.ellipk(m)
    for u in (0.3, 1.7, -4.2, 30.0):
        # am u beyond ±π/2 from the reduction u = v + 2jK, am u = am v + jπ
        j = mp.nint(u / (2 * K))
        v = u - 2 * j * K
        am = mp.asin(mp.ellipfun("sn", v, m)) + j * mp.pi
        ref = float(mp.ellippi(n, am, m))
        # a few ulps, plus the argument u known to eps |u| (slope 1/(1 - n sn^2) <= 1 for n < 0)
        assert rigiddyn.ellippi_am(u, n, 1 - mc, mc) == pytest.approx(ref, rel=16 * EPS, abs=16 * EPS * abs(u))


def test_carlson_integrals_match_mpmath():
    # elliptic.hpp: a few ulps (against 40 digits: the core's error only)
    assert rigiddyn.elliprf(0.5, 1.0, 2.0) == pytest.approx(float(mp.elliprf(0.5, 1, 2)), rel=4 * EPS)
    assert rigiddyn.elliprj(0.5, 1.0, 2.0, 3.0) == pytest.approx(float(mp.elliprj(0.5, 1, 2, 3)), rel=4 * EPS)


def test_detest_b5():
    """DETEST B5: y' = (y2 y3, -y1 y3, -0.51 y1 y2), y0 = (0, 1, 1) is solved by (sn, cn, dn)(t|0.51)
    with period 4K = 7.450563 (Hull, Enright, Fellen, Sedgwick 1972)."""
    assert 4 * rigiddyn.ellipk(0.51) == pytest.approx(7.450563, abs=5e-7)  # published to 7 digits
    t = np.linspace(0, 20, 41)
    rhs = lambda _, y: [y[1] * y[2], -y[0] * y[2], -0.51 * y[0] * y[1]]  # noqa: E731
    sol = solve_ivp(rhs, (0, 20), [0, 1, 1], method="DOP853", rtol=1e-13, atol=1e-13, t_eval=t)
    coarse = solve_ivp(rhs, (0, 20), [0, 1, 1], method="DOP853", rtol=1e-12, atol=1e-12, t_eval=t)
    # DOP853's global error shrinks >= 2x per decade of tolerance (order 8: ~10^(8/9) = 7.7x), so its
    # error at 1e-13 is <= |y(1e-12) - y(1e-13)|; the closed form adds a few ulps of |u| <= 20
    tol = np.abs(coarse.y - sol.y).max() + 8 * EPS * 20
    np.testing.assert_allclose(np.array(rigiddyn.jacobi_ellipj(t, 0.51)), sol.y, rtol=0, atol=tol)


def test_bad_input():
    with pytest.raises(ValueError, match="m"):
        rigiddyn.jacobi_ellipj(1.0, 1.5)
    with pytest.raises(ValueError, match="mc"):
        rigiddyn.jacobi_ellipj(1.0, 0.5, mc=0.4)
    with pytest.raises(ValueError, match="u"):
        rigiddyn.jacobi_ellipj(np.array([1.0, np.nan]), 0.5)
    with pytest.raises(TypeError, match="u"):
        rigiddyn.jacobi_ellipj("a", 0.5)
    with pytest.raises(ValueError, match="n"):
        rigiddyn.ellippi(1.5, 0.5)
