"""The exact layer at extreme magnitudes: Carlson's R_F and R_J for arguments
spanning 1e-300..1e300 (they used to loop forever or return NaN), and the torque-free solution for any
finite inertia and angular velocity (computed in units scaled by powers of two).

References: mpmath at 400 digits (its R_J is not converged at 50 digits for arguments 1e300 apart:
at (8.5e139, 2.7e158, 1.6e157, 2.4e-274) it gives 6.4e-226 at 50 digits, 1.2e-225 at 100 and
2.3076467995418557e-225 from 300 digits on), and, for the free body, the same motion at moderate
magnitudes (the solution scales exactly: I -> 2^j I leaves the motion unchanged, w -> 2^j w runs it
2^j times faster)."""

import math
import warnings

import mpmath as mp
import numpy as np
import pytest

import rigiddyn

EPS = np.finfo(float).eps
TINY = np.finfo(float).tiny  # smallest normal double
SUBNORMAL_ULP = 5e-324
DPS = 400


def mp_rj(*args):
    with mp.workdps(DPS):
        return float(mp.elliprj(*[mp.mpf(a) for a in args]))


def mp_rf(*args):
    with mp.workdps(DPS):
        return float(mp.elliprf(*[mp.mpf(a) for a in args]))


# Accuracy of the duplication algorithm (elliptic.hpp): the series is truncated where its remainder is
# below 2^-53 relative (Carlson 1995), and each duplication step rounds its arguments relatively (the
# map contracts towards the mean, so these roundings do not accumulate): a few ulps. R_J adds up to ~30
# positive terms, each to a few ulps, so its sum is as accurate; 8 eps for both. A result in the
# subnormal range is rounded to that grid, at most twice (the scaled sum, then the first term): two
# subnormal ulps more.
def close(value, ref):
    return abs(value - ref) <= 8 * EPS * abs(ref) + 2 * SUBNORMAL_ULP


def test_the_reported_cases_that_looped_or_returned_nan():
    # they looped forever (the stopping tolerance overflowed) or returned NaN; SciPy gives 3.53e-151 for R_F
    assert close(rigiddyn.elliprf(1.0, 1e306, 1.0), mp_rf(1.0, 1e306, 1.0))
    assert close(rigiddyn.elliprj(1.0, 1e306, 1.0, 1.0), mp_rj(1.0, 1e306, 1.0, 1.0))
    assert close(rigiddyn.elliprj(1e-300, 1e300, 1e8, 1e16), mp_rj(1e-300, 1e300, 1e8, 1e16))
    # partial sums beyond the double range in the scaled units (two tiny arguments, p tiny): 1.5e150 and
    # 4.7e155, once refused as overflowing
    assert close(rigiddyn.elliprj(1e-300, 1e-300, 1e300, 1e-300), mp_rj(1e-300, 1e-300, 1e300, 1e-300))
    assert close(rigiddyn.elliprj(0.0, 1e-300, 1e300, 1e-310), mp_rj(0.0, 1e-300, 1e300, 1e-310))


def test_arguments_spanning_the_double_range_match_mpmath():
    rng = np.random.default_rng(20261123)
    checked = 0
    for i in range(40):
        args = list(10.0 ** rng.uniform(-300, 300, 4))
        if i % 4 == 0:
            args[i % 3] = 0.0  # at most one of x, y, z zero
        rf, ref_rf = rigiddyn.elliprf(*args[:3]), mp_rf(*args[:3])
        assert close(rf, ref_rf), (args, rf, ref_rf)
        ref_rj = mp_rj(*args)
        if ref_rj > np.finfo(float).max:
            with pytest.warns(RuntimeWarning, match="elliprj"):
                assert rigiddyn.elliprj(*args) == math.inf
        else:
            rj = rigiddyn.elliprj(*args)
            assert close(rj, ref_rj), (args, rj, ref_rj)
            checked += ref_rj >= TINY
    assert checked >= 20  # most draws have a normal result


def test_results_beyond_the_double_range_warn():
    # R_J(x, x, x, x) = x^(-3/2) = 1e450
    with pytest.warns(RuntimeWarning, match="elliprj"):
        assert rigiddyn.elliprj(1e-300, 1e-300, 1e-300, 1e-300) == math.inf
    # below it: rounded to 0 (3/2 ln(x/p)/sqrt(xyz) ~ 2e-447), no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert rigiddyn.elliprj(1e300, 1e300, 1e300, 1e-300) == 0.0


def test_elliptic_functions_reject_non_finite_and_name_the_argument():
    for call, name in [(lambda: rigiddyn.elliprf(math.nan, 1.0, 1.0), "x"),
                       (lambda: rigiddyn.elliprj(1.0, 1.0, math.inf, 1.0), "z"),
                       (lambda: rigiddyn.elliprj(1.0, 1.0, 1.0, -1.0), "p"),
                       (lambda: rigiddyn.ellipk(math.nan), "m"),
                       (lambda: rigiddyn.ellipk(0.5, mc=math.inf), "mc"),
                       (lambda: rigiddyn.ellippi(math.nan, 0.5), "n"),
                       (lambda: rigiddyn.ellippi(0.3, 1.0), "mc"),
                       (lambda: rigiddyn.ellippi_am(math.inf, 0.3, 0.5), "u"),
                       (lambda: rigiddyn.jacobi_ellipj(np.array([0.0, math.nan]), 0.5), "u")]:
        with pytest.raises(ValueError, match=f"^{name}: expected"):
            call()


def test_ellippi_am_beyond_the_double_range_warns():
    # Pi(am u, n|m) ~ u Pi(n|m)/K: finite up to |u| ~ 1e308 K/Pi(n|m) and +-inf with a warning past it
    assert math.isfinite(rigiddyn.ellippi_am(1e300, -0.5, 0.5))
    with pytest.warns(RuntimeWarning, match="ellippi_am"):
        assert rigiddyn.ellippi_am(-1.7e308, 0.9, 0.5) == -math.inf


I_DIAG = np.array([2.0, 3.0, 5.0])
Q0 = np.array([0.1, -0.2, 0.3, 0.9273618495495704])  # unit (x, y, z, w)
W0 = np.array([0.3, -0.5, 1.1])


@pytest.mark.parametrize("j", [-1000, -500, 500, 1000])
@pytest.mark.parametrize("w0", [W0, np.array([1e-20, 0.0, 1.0]), np.array([0.0, 1.0, 1e-30])])
def test_free_body_inertia_scale_leaves_the_motion_unchanged(j, w0):
    # I -> 2^j I is exact and leaves the motion unchanged; the momentum I w (2^-1000 or 2^1000 times
    # that of I_DIAG) once underflowed to a few bits or overflowed. The solution scales the inertia
    # by a power of two itself, so both runs make the same operations: equal to the last bit.
    ref = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0, w0)
    scaled = rigiddyn.TorqueFreeSolution(np.diag(np.ldexp(I_DIAG, j)), Q0, w0)
    assert scaled.case == ref.case
    t = np.array([0.0, 0.7, 13.0, -4.0])
    for a, b in zip(scaled.state_at(t), ref.state_at(t)):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("j", [-1000, -300, 300, 1000])
def test_free_body_rate_scale_is_a_time_scale(j):
    # w -> 2^j w runs the same motion 2^j times faster: state_at(2^-j t) of the fast body is state_at(t)
    # with w scaled by 2^j. The phases (rate times time) are the same products up to a rounding each:
    # a few ulps of the phase (<= 5 rad here), 8 eps per radian.
    ref = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0, W0)
    fast = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0, np.ldexp(W0, j))
    t = np.array([0.0, 0.7, 4.0, -2.5])
    q_ref, w_ref = ref.state_at(t)
    q, w = fast.state_at(np.ldexp(t, -j))
    np.testing.assert_allclose(q, q_ref, rtol=0, atol=8 * EPS * 5)
    np.testing.assert_allclose(np.ldexp(w, -j), w_ref, rtol=0, atol=8 * EPS * 5 * np.abs(W0).max())


def test_free_body_invariants_beyond_the_double_range_warn():
    sol = rigiddyn.TorqueFreeSolution(np.diag(np.ldexp(I_DIAG, 1000)), Q0, 1e10 * W0)
    with pytest.warns(RuntimeWarning, match="angular_momentum_W"):
        assert np.isinf(sol.angular_momentum_W).any()
    with pytest.warns(RuntimeWarning, match="kinetic_energy"):
        assert sol.kinetic_energy.rotational == math.inf
    # the motion itself is that of I_DIAG (an exact scale of the inertia does not enter)
    ref = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0, 1e10 * W0)
    for a, b in zip(sol.state_at(0.3), ref.state_at(0.3)):
        np.testing.assert_array_equal(a, b)


def test_free_body_rates_beyond_the_double_range_are_refused():
    # phi turns at G/I1 ~ |w| I3/I1 = 3e600 rad/s: refused naming w_B
    with pytest.raises(ValueError, match="^w_B: expected"):
        rigiddyn.TorqueFreeSolution(np.diag([1e-300, 2.0, 3.0]), Q0, [1e300, 1e300, 1e300],
                                    check=rigiddyn.InertiaCheck.allow_unrealizable)
    # a phase rate times t beyond the double range: refused naming t
    sol = rigiddyn.TorqueFreeSolution(np.diag(I_DIAG), Q0, 1e300 * W0)
    assert np.isfinite(sol.state_at(1.0)[0]).all()
    with pytest.raises(ValueError, match="^t: expected"):
        sol.state_at(1e10)
