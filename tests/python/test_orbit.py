"""Orbital elements, anomalies, Kepler's equation and the orbit frames (cpp/include/rigiddyn/orbit/).

References: the worked examples of Curtis, "Orbital Mechanics for Engineering Students" (3rd ed.),
Examples 3.1, 3.2, 3.5, 4.3 and 4.7, and Vallado, "Fundamentals of Astrodynamics and Applications"
(4th ed.), Examples 2-5 (RV2COE) and 2-6 (COE2RV), each checked to the digits the book prints (a value
printed with k decimals is within half a unit of the k-th decimal); Kepler's equation against its residual
evaluated in 50-digit arithmetic (mpmath); properties: round trips, orthonormal frames, the orbit rate,
and SciPy's rotations for the attitude conversions.
"""

from __future__ import annotations

import math
import subprocess
import sys

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import rigiddyn as rd

EPS = np.finfo(float).eps
MU_CURTIS = 398600.0  # km^3/s^2, Curtis's value for the Earth
MU_VALLADO = 398600.4418  # km^3/s^2, Vallado's
DEG = math.pi / 180.0


def printed(value: float, book: float, decimals: int) -> bool:
    """value agrees with a number the book prints with `decimals` decimals (half a unit of the last one)."""
    return abs(value - book) <= 0.5 * 10.0**-decimals * (1 + 1e-9)


# ---------------------------------------------------------------- Curtis, chapter 3: Kepler's equation
def test_curtis_example_3_1_time_since_perigee():
    # r_p = 9600 km, r_a = 21000 km; the time from perigee to nu = 120 deg: E = 1.7281 rad, M_e = 1.3601 rad,
    # T = 18834 s, t = 4077 s
    e = (21000.0 - 9600.0) / (21000.0 + 9600.0)
    a = (21000.0 + 9600.0) / 2
    T = 2 * math.pi * math.sqrt(a**3 / MU_CURTIS)
    E = rd.true_to_eccentric_anomaly(120 * DEG, e)
    M = rd.eccentric_to_mean_anomaly(E, e)
    assert printed(e, 0.37255, 5) and printed(T, 18834, 0)
    assert printed(E, 1.7281, 4) and printed(M, 1.3601, 4)
    assert printed(M / (2 * math.pi) * T, 4077, 0)
    assert rd.true_to_mean_anomaly(120 * DEG, e) == pytest.approx(M, rel=4 * EPS)  # the same path


def test_curtis_example_3_2_true_anomaly_after_3_hours():
    # the orbit of Example 3.1, 3 h after perigee: M_e = 3.6029 rad, E = 3.4794 rad, nu = 193.2 deg
    e = (21000.0 - 9600.0) / (21000.0 + 9600.0)
    T = 2 * math.pi * math.sqrt(((21000.0 + 9600.0) / 2) ** 3 / MU_CURTIS)
    M = 2 * math.pi * 10800.0 / T
    assert printed(M, 3.6029, 4)
    assert printed(rd.mean_to_eccentric_anomaly(M, e), 3.4794, 4)
    assert printed(rd.mean_to_true_anomaly(M, e) / DEG, 193.2, 1)


def test_curtis_example_3_5_hyperbolic_trajectory():
    # perigee speed 15 km/s at 300 km altitude (R_E = 6378 km): h = 100170 km^2/s, e = 2.7696; at nu = 100
    # deg r = 48497 km, F = 2.2927 rad, M_h = 11.279 rad, t = 4141 s; 3 h later: M_h = 40.69 rad,
    # F = 3.4631 rad, nu = 107.78 deg, r = 163180 km, v = 10.51 km/s
    r_p, v_p = 6678.0, 15.0
    h = r_p * v_p
    e = h**2 / (MU_CURTIS * r_p) - 1
    p = h**2 / MU_CURTIS
    assert printed(h, 100170, 0) and printed(e, 2.7696, 4)
    F = rd.true_to_eccentric_anomaly(100 * DEG, e)
    M = rd.eccentric_to_mean_anomaly(F, e)
    rate = MU_CURTIS**2 / h**3 * (e**2 - 1) ** 1.5  # M_h = rate t
    assert printed(p / (1 + e * math.cos(100 * DEG)), 48497, 0)
    assert printed(F, 2.2927, 4) and printed(M, 11.279, 3) and printed(M / rate, 4141, 0)
    M_later = rate * (4141.0 + 3 * 3600.0)  # the book continues from its rounded t = 4141 s
    nu = rd.mean_to_true_anomaly(M_later, e)
    r = p / (1 + e * math.cos(nu))
    assert printed(M_later, 40.69, 2) and printed(rd.mean_to_eccentric_anomaly(M_later, e), 3.4631, 4)
    assert printed(nu / DEG, 107.78, 2)
    assert abs(r - 163180) <= 5  # printed to 5 significant digits
    assert printed(math.sqrt(MU_CURTIS * (2 / r + (e**2 - 1) / p)), 10.51, 2)  # vis-viva, a = -p/(e^2 - 1)


# ---------------------------------------------------------------- Curtis, chapter 4; Vallado, chapter 2
def test_curtis_example_4_3_elements_of_a_state():
    # r = (-6045, -3490, 2500) km, v = (-3.457, 6.618, 2.533) km/s: h = 58310 km^2/s, i = 153.2 deg,
    # raan = 255.3 deg, e = 0.1712, argp = 20.07 deg, theta = 28.45 deg, a = 8788 km
    p, e, i, raan, argp, nu = rd.state_to_elements([-6045.0, -3490.0, 2500.0], [-3.457, 6.618, 2.533], MU_CURTIS)
    assert abs(math.sqrt(p * MU_CURTIS) - 58310) <= 5  # printed to 4 significant digits
    assert printed(e, 0.1712, 4) and printed(i / DEG, 153.2, 1) and printed(raan / DEG, 255.3, 1)
    assert printed(argp / DEG, 20.07, 2) and printed(nu / DEG, 28.45, 2)
    assert printed(p / (1 - e**2), 8788, 0)


def test_curtis_example_4_7_state_of_hyperbolic_elements():
    # h = 80000 km^2/s, e = 1.4, i = 30, raan = 40, argp = 60, theta = 30 deg:
    # r = (-4040, 4815, 3629) km, v = (-10.39, -4.772, 1.744) km/s
    r, v = rd.elements_to_state([80000.0**2 / MU_CURTIS, 1.4, 30 * DEG, 40 * DEG, 60 * DEG, 30 * DEG], MU_CURTIS)
    assert all(printed(x, b, 0) for x, b in zip(r, [-4040, 4815, 3629]))
    assert printed(v[0], -10.39, 2) and printed(v[1], -4.772, 3) and printed(v[2], 1.744, 3)


def test_vallado_example_2_5_rv2coe():
    # r = (6524.834, 6862.875, 6448.296) km, v = (4.901327, 5.533756, -1.976341) km/s: e = 0.832853,
    # argp = 53.38, nu = 92.335 deg. The book also prints p = 11067.790 km, a = 36127.343 km, i = 87.870 deg and
    # raan = 227.89 deg; from the printed state, exact arithmetic gives 11067.798 km, 36127.338 km, 87.8691 deg and
    # 227.8983 deg: within 1e-6 relative and a unit of the last printed digit (the state carries 7 digits).
    # Example 2-6 below, the inverse, agrees to every printed digit.
    p, e, i, raan, argp, nu = rd.state_to_elements([6524.834, 6862.875, 6448.296], [4.901327, 5.533756, -1.976341],
                                                   MU_VALLADO)
    assert printed(e, 0.832853, 6) and printed(argp / DEG, 53.38, 2) and printed(nu / DEG, 92.335, 3)
    assert abs(raan / DEG - 227.89) <= 0.01  # 227.898: within a unit of the last printed digit
    assert p == pytest.approx(11067.790, rel=1e-6) and p / (1 - e**2) == pytest.approx(36127.343, rel=1e-6)
    assert abs(i / DEG - 87.870) <= 1e-3


def test_vallado_example_2_6_coe2rv():
    # p = 11067.790 km, e = 0.83285, i = 87.87, raan = 227.89, argp = 53.38, nu = 92.335 deg:
    # r = (6525.368, 6861.532, 6449.119) km, v = (4.902279, 5.533140, -1.975710) km/s
    r, v = rd.elements_to_state([11067.790, 0.83285, *np.radians([87.87, 227.89, 53.38, 92.335])], MU_VALLADO)
    assert all(printed(x, b, 3) for x, b in zip(r, [6525.368, 6861.532, 6449.119]))
    assert all(printed(x, b, 6) for x, b in zip(v, [4.902279, 5.533140, -1.975710]))


# ---------------------------------------------------------------- round trips
angle = st.floats(0.0, 2 * math.pi)
eccentricity = st.one_of(st.just(0.0), st.floats(1e-16, 1e-10), st.floats(0.0, 0.99), st.floats(1.01, 5.0),
                         st.just(1.0))
inclination = st.one_of(st.just(0.0), st.just(math.pi), st.floats(0.0, 1e-13), st.floats(0.0, math.pi))


@settings(max_examples=300, deadline=None)
@given(p=st.floats(1e6, 1e8), e=eccentricity, i=inclination, raan=angle, argp=angle, nu=angle)
def test_state_round_trips_through_the_elements(p, e, i, raan, argp, nu):
    if e >= 1 and 1 + e * math.cos(nu) < 0.2:
        nu = 0.5 * math.acos(-1 / e)  # a point well inside the asymptotes, where the state is well conditioned
    mu = 3.986004418e14
    r, v = rd.elements_to_state([p, e, i, raan, argp, nu], mu)
    r2, v2 = rd.elements_to_state(rd.state_to_elements(r, v, mu), mu)
    # each of the ~40 operations of the two conversions rounds once (an ulp of |r| or |v|): 64 eps leaves a
    # margin; below the tolerances an angle set to 0 moves the state by at most 2 e |r| (circular) and
    # 2 sin(i) |r| (equatorial: the plane tilted about x_W, not the node), |v| likewise (elements.hpp); e read
    # back from the state carries an absolute round-off of ~64 eps, so an e at the 1e-12 tolerance may be read as
    # circular
    degenerate = (2 * e if e < 1e-12 + 64 * EPS else 0.0) + (2 * abs(math.sin(i)) if abs(math.sin(i)) < 2e-12 else 0.0)
    assert np.linalg.norm(r2 - r) <= (64 * EPS + degenerate) * np.linalg.norm(r)
    assert np.linalg.norm(v2 - v) <= (64 * EPS + degenerate) * np.linalg.norm(v)


@settings(max_examples=200, deadline=None)
@given(p=st.floats(1e6, 1e8), e=st.one_of(st.floats(0.01, 0.99), st.floats(1.01, 5.0)), i=st.floats(0.01, 3.13),
       raan=angle, argp=angle, nu=st.floats(-3.0, 3.0))
def test_elements_round_trip_away_from_the_special_cases(p, e, i, raan, argp, nu):
    if e > 1:
        nu = nu / 3.0 * 0.9 * math.acos(-1 / e)  # within the asymptotes
    mu = 3.986004418e14
    el = rd.state_to_elements(*rd.elements_to_state([p, e, i, raan, argp, nu], mu), mu)
    # angles: the direction of the eccentricity vector carries a round-off of ~eps/e (e >= 0.01), the node
    # ~eps/sin(i) (sin i >= 0.01); 1e-12 rad is 100 times that
    assert el[0] == pytest.approx(p, rel=64 * EPS) and el[1] == pytest.approx(e, rel=1e-12, abs=1e-13)
    wrap = lambda x: (x + math.pi) % (2 * math.pi) - math.pi  # noqa: E731
    for got, want in zip(el[2:], [i, raan, argp, nu]):
        assert abs(wrap(got - want)) <= 1e-12


def test_the_special_cases_carry_the_undefined_angles():
    mu = 1.0
    # circular inclined: argp = 0, nu = the argument of latitude u = argp + nu
    el = rd.state_to_elements(*rd.elements_to_state([1.0, 0.0, 0.5, 1.0, 0.3, 0.4], mu), mu)
    np.testing.assert_allclose(el, [1.0, 0.0, 0.5, 1.0, 0.0, 0.7], atol=1e-15)
    # elliptic equatorial (prograde): raan = 0, argp = the longitude of periapsis raan + argp
    el = rd.state_to_elements(*rd.elements_to_state([1.0, 0.3, 0.0, 1.0, 0.3, 0.4], mu), mu)
    np.testing.assert_allclose(el, [1.0, 0.3, 0.0, 0.0, 1.3, 0.4], atol=1e-15)
    # circular equatorial: raan = argp = 0, nu = the true longitude
    el = rd.state_to_elements(*rd.elements_to_state([1.0, 0.0, 0.0, 1.0, 0.3, 0.4], mu), mu)
    np.testing.assert_allclose(el, [1.0, 0.0, 0.0, 0.0, 0.0, 1.7], atol=1e-15)
    # retrograde equatorial: the longitude of periapsis measured in the direction of motion gives the state back
    r, v = rd.elements_to_state([1.0, 0.3, math.pi, 0.0, 1.3, 0.4], mu)
    el = rd.state_to_elements(r, v, mu)
    assert el[2] == pytest.approx(math.pi, abs=1e-15) and el[3] == 0.0 and el[4] == pytest.approx(1.3, abs=16 * EPS)  # atan2 of rounded dot and cross products


def test_the_parabola_through_its_semi_latus_rectum():
    # e = 1: r = p/(1 + cos nu), the speed is the escape speed sqrt(2 mu/r) (zero energy)
    mu, p = 3.986004418e14, 1.4e7
    r, v = rd.elements_to_state([p, 1.0, 0.3, 0.2, 0.1, 1.0], mu)
    assert np.linalg.norm(r) == pytest.approx(p / (1 + math.cos(1.0)), rel=4 * EPS)
    assert np.linalg.norm(v) == pytest.approx(math.sqrt(2 * mu / np.linalg.norm(r)), rel=8 * EPS)
    el = rd.state_to_elements(r, v, mu)
    assert el[1] == pytest.approx(1.0, abs=16 * EPS) and el[5] == pytest.approx(1.0, abs=1e-13)
    # Barker's equation both ways
    D = math.tan(0.5)
    assert rd.true_to_mean_anomaly(1.0, 1.0) == pytest.approx(D / 2 + D**3 / 6, rel=4 * EPS)
    nus = np.linspace(-3.1, 3.1, 41)
    np.testing.assert_allclose(rd.mean_to_true_anomaly(rd.true_to_mean_anomaly(nus, 1.0), 1.0), nus, rtol=0, atol=8 * EPS)


def test_stacks_equal_the_single_items():
    mu = 3.986004418e14
    elements = np.array([[7e6, 0.1, 0.5, 1.0, 2.0, 3.0], [2e7, 1.5, 2.0, 0.1, 0.2, 0.3], [7e6, 0.0, 0.0, 0.0, 0.0, 1.0]])
    r, v = rd.elements_to_state(elements, mu)
    assert r.shape == v.shape == (3, 3)
    for k in range(3):
        rk, vk = rd.elements_to_state(elements[k], mu)
        assert np.array_equal(rk, r[k]) and np.array_equal(vk, v[k])
    assert np.array_equal(rd.state_to_elements(r, v, mu)[1], rd.state_to_elements(r[1], v[1], mu))
    M = rd.true_to_mean_anomaly([0.1, 0.2], [0.5, 1.5])
    assert M.shape == (2,) and M[1] == rd.true_to_mean_anomaly(0.2, 1.5)


# ---------------------------------------------------------------- Kepler's equation
def _residual(x: float, e: float, M: float) -> tuple[float, float]:
    """|M(x) - M| in 50-digit arithmetic, and f'(x) = dM/dx."""
    with mpmath.workdps(50):
        X, E_ = mpmath.mpf(x), mpmath.mpf(e)
        if e < 1:
            return float(abs(X - E_ * mpmath.sin(X) - M)), float(1 - E_ * mpmath.cos(X))
        return float(abs(E_ * mpmath.sinh(X) - X - M)), float(E_ * mpmath.cosh(X) - 1)


TINY = 5e-324  # below the normal range an ulp is absolute: the smallest subnormal
near_one = st.integers(1, 16).map(lambda k: 10.0**-k)


@settings(max_examples=300, deadline=None)
@given(gap=near_one, side=st.sampled_from([-1.0, 1.0]), M=st.one_of(st.floats(1e-300, math.pi), st.floats(1e-12, 1e-3)),
       sign=st.sampled_from([-1.0, 1.0]))
def test_kepler_equation_is_solved_to_round_off_near_e_1(gap, side, M, sign):
    e = 1.0 + side * gap
    if e == 1.0:
        return
    M = sign * M
    x = rd.mean_to_eccentric_anomaly(M, e)
    residual, slope = _residual(x, e, M)
    # the nearest double to the root has a residual of at most f'(x) ulp(x)/2; the solver stops within 2 ulps
    # of the root: 3 f'(x) ulp(x) with ulp(x) <= eps |x| + TINY. Below that it cannot see: M(x) evaluated in double
    # rounds each of its terms (sinh or sin to an ulp, the product, the two differences), an error of up to
    # 2 eps (|e sinh x| + |x| + |M|), which near e = 1 and small f'(x) is larger than the slope's term (the
    # terms cancel: e = 1 + 1e-13, M = -0.213 has |e sinh x| = 1.29 against f'(x) = 0.62)
    terms = abs(e * (math.sin(x) if e < 1 else math.sinh(x))) + abs(x) + abs(M)
    assert residual <= 3 * slope * (EPS * abs(x) + TINY) + 2 * EPS * terms + TINY


@settings(max_examples=300, deadline=None)
@given(e=st.one_of(st.floats(0.0, 0.999), st.floats(1.001, 1e6)), M=st.floats(-1e4, 1e4))
def test_kepler_equation_is_solved_to_round_off(e, M):
    x = rd.mean_to_eccentric_anomaly(M, e)
    residual, slope = _residual(x, e, M)
    # as above; the elliptic M is reduced by the double 2 pi, 2.4e-16 from 2 pi, and the revolutions added back
    # round to an ulp of M: together below 2 eps |M|
    assert residual <= 3 * slope * (EPS * abs(x) + TINY) + 2 * EPS * abs(M) + TINY
    assert rd.eccentric_to_mean_anomaly(rd.mean_to_eccentric_anomaly(M, e), e) == pytest.approx(M, rel=1e-13, abs=1e-300)


def test_the_elliptic_anomalies_keep_their_revolutions():
    e = 0.3
    for k in (-3, 0, 5):
        nu = 1.0 + 2 * math.pi * k
        E = rd.true_to_eccentric_anomaly(nu, e)
        assert abs(E - nu) < math.pi and rd.eccentric_to_true_anomaly(E, e) == pytest.approx(nu, abs=1e-13)
        assert rd.mean_to_true_anomaly(rd.true_to_mean_anomaly(nu, e), e) == pytest.approx(nu, abs=1e-13)


def test_extreme_inputs_return_in_bounded_time():
    # the solver's iteration count is bounded: a sweep of the extremes must finish (the timeout only catches
    # a hang: the sweep takes milliseconds)
    code = (
        "import numpy as np, rigiddyn as rd\n"
        "for e in [0.0, 1e-300, 0.5, 1 - 2**-53, 1 + 2**-52, 2.0, 1e300]:\n"
        "    for M in [0.0, 5e-324, 1e-300, 1e-8, 1.0, np.pi, 1e6, 1e300, -1e300]:\n"
        "        x = rd.mean_to_eccentric_anomaly(M, e)\n"
        "        assert np.isfinite(x), (M, e, x)\n"
        "print('ok')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert out.stdout.strip() == "ok", out.stderr


# ---------------------------------------------------------------- Kepler propagation
def test_kepler_propagate_reproduces_curtis_examples_3_2_and_3_5():
    # Example 3.2 from perigee (r_p = 9600 km, r_a = 21000 km): 3 h later nu = 193.2 deg
    r_p, r_a = 9600.0, 21000.0
    v_p = math.sqrt(2 * MU_CURTIS * r_a / (r_p * (r_a + r_p)))  # vis-viva at perigee
    r, v = rd.kepler_propagate([r_p, 0.0, 0.0], [0.0, v_p, 0.0], MU_CURTIS, 10800.0)
    assert printed(math.degrees(math.atan2(r[1], r[0])) % 360, 193.2, 1)
    # Example 3.5 from perigee (6678 km, 15 km/s), t = 4141 s + 3 h: r = 163180 km, v = 10.51 km/s
    r, v = rd.kepler_propagate([6678.0, 0.0, 0.0], [0.0, 15.0, 0.0], MU_CURTIS, 4141.0 + 10800.0)
    assert abs(np.linalg.norm(r) - 163180) <= 5 and printed(np.linalg.norm(v), 10.51, 2)


@settings(max_examples=100, deadline=None)
@given(e=st.one_of(st.floats(0.0, 0.95), st.floats(1.05, 4.0), st.just(1.0)), i=st.floats(0.0, math.pi), nu=angle,
       t1=st.floats(-3000.0, 3000.0), t2=st.floats(-3000.0, 3000.0))
def test_kepler_propagate_composes(e, i, nu, t1, t2):
    mu, p = 3.986004418e14, 8e6
    if e >= 1 and 1 + e * math.cos(nu) < 0.5:
        nu = 0.5 * math.acos(-1 / e)
    r0, v0 = rd.elements_to_state([p, e, i, 0.3, 0.4, nu], mu)
    r1, v1 = rd.kepler_propagate(*rd.kepler_propagate(r0, v0, mu, t1), mu, t2)
    r2, v2 = rd.kepler_propagate(r0, v0, mu, t1 + t2)
    # round-off of each state (~64 eps, as the round trip above) grows along the orbit by the shear of the
    # flow, at most ~3 n |t| + 1 (~10 over these times): 1e-11 of |r|, |v| is far above it
    assert np.linalg.norm(r1 - r2) <= 1e-11 * np.linalg.norm(r2)
    assert np.linalg.norm(v1 - v2) <= 1e-11 * np.linalg.norm(v2)
    # the invariants: angular momentum and energy
    energy = lambda r, v: v @ v / 2 - mu / np.linalg.norm(r)  # noqa: E731
    np.testing.assert_allclose(np.cross(r2, v2), np.cross(r0, v0), rtol=0, atol=1e-12 * np.linalg.norm(np.cross(r0, v0)))
    assert abs(energy(r2, v2) - energy(r0, v0)) <= 1e-12 * mu / p


def test_kepler_propagate_closes_one_period_and_stacks_times():
    mu, a, e = 398600.4418e9, 7000e3, 0.1
    r0, v0 = [6300e3, 0.0, 0.0], [0.0, 8342.475803771201, 0.0]
    T = 2 * math.pi * math.sqrt(a**3 / mu)
    r, v = rd.kepler_propagate(r0, v0, mu, [0.0, T / 2, T, 10 * T])
    assert r.shape == v.shape == (4, 3)
    # perigee, apogee a (1 + e), perigee again: to round-off of |r| (the 10 periods add the round-off of 10 T)
    np.testing.assert_allclose(np.linalg.norm(r, axis=1), [6300e3, 7700e3, 6300e3, 6300e3], rtol=64 * EPS)
    np.testing.assert_allclose(r[[0, 2, 3]], np.tile(r0, (3, 1)), rtol=0, atol=1e-6)


# ---------------------------------------------------------------- bad input
@pytest.mark.parametrize("call, names", [
    (lambda: rd.state_to_elements([7e6, 0, 0], [0, 7e3, 0], -1.0), "mu"),
    (lambda: rd.state_to_elements([7e6, 0, 0], [7e3, 0, 0], 1.0), "r_W, v_W"),
    (lambda: rd.state_to_elements([0.0, 0, 0], [7e3, 0, 0], 1.0), "r_W"),
    (lambda: rd.state_to_elements([np.nan, 0, 0], [0, 7e3, 0], 1.0), "r_W"),
    (lambda: rd.elements_to_state([7e6, -0.1, 0, 0, 0, 0], 1.0), "e"),
    (lambda: rd.elements_to_state([-7e6, 0.1, 0, 0, 0, 0], 1.0), "p"),
    (lambda: rd.elements_to_state([7e6, 2.0, 0, 0, 0, 2.5], 1.0), "nu"),
    (lambda: rd.elements_to_state([7e6, 0.1, np.nan, 0, 0, 0], 1.0), "elements"),
    (lambda: rd.elements_to_state([7e6, 0.1, 0, 0, 0, 0], 0.0), "mu"),
    (lambda: rd.semi_latus_rectum(-7e6, 0.1), "a"),
    (lambda: rd.semi_latus_rectum(7e6, 1.5), "a"),
    (lambda: rd.semi_latus_rectum(7e6, 1.0), "e"),
    (lambda: rd.mean_to_eccentric_anomaly(1.0, -0.5), "e"),
    (lambda: rd.mean_to_eccentric_anomaly(np.nan, 0.5), "M"),
    (lambda: rd.mean_to_eccentric_anomaly(1.0, 1.0), "e"),
    (lambda: rd.true_to_eccentric_anomaly(2.5, 2.0), "nu"),
    (lambda: rd.true_to_mean_anomaly(math.pi, 1.0), "nu"),
    (lambda: rd.mean_to_true_anomaly(1.0, np.inf), "e"),
    (lambda: rd.orbit_frame_rotation([1.0, 0, 0], [2.0, 0, 0]), "r_W, v_W"),
    (lambda: rd.kepler_propagate([7e6, 0, 0], [0, 7e3, 0], 3.986e14, np.inf), "t"),
    (lambda: rd.orbit_frame_rotation([1.0, 0, 0], [0, 1.0, 0], "ntw"), "frame"),
    (lambda: rd.attitude_from_orbit_frame([1.0, 0, 0], [0, 1.0, 0], [0, 0, 0, 2.0], [0, 0, 0]), "q_OB"),
])
def test_bad_input_names_the_value(call, names):
    with pytest.raises(ValueError) as info:
        call()
    assert str(info.value).startswith(names + ": expected"), str(info.value)


# ---------------------------------------------------------------- orbit frames
@settings(max_examples=100, deadline=None)
@given(p=st.floats(1e6, 1e8), e=st.floats(0.0, 0.9), i=st.floats(0.0, math.pi), raan=angle, argp=angle, nu=angle,
       frame=st.sampled_from(["lvlh", "rsw"]))
def test_the_orbit_frames_are_orthonormal_and_point_as_stated(p, e, i, raan, argp, nu, frame):
    r, v = rd.elements_to_state([p, e, i, raan, argp, nu], 3.986004418e14)
    R = rd.orbit_frame_rotation(r, v, frame)
    # orthonormal to a few ulps (unit vectors and their cross products, each rounded once)
    assert np.abs(R.T @ R - np.eye(3)).max() <= 8 * EPS and np.linalg.det(R) == pytest.approx(1.0, abs=8 * EPS)
    h = np.cross(r, v)
    r_hat, h_hat = r / np.linalg.norm(r), h / np.linalg.norm(h)
    if frame == "lvlh":  # z to nadir, y opposite the orbit normal, x along-track (v . x > 0)
        np.testing.assert_allclose(R[:, 2], -r_hat, atol=8 * EPS)
        np.testing.assert_allclose(R[:, 1], -h_hat, atol=8 * EPS)
        assert R[:, 0] @ v > 0
    else:  # radial out, along-track, orbit normal
        np.testing.assert_allclose(R[:, 0], r_hat, atol=8 * EPS)
        np.testing.assert_allclose(R[:, 2], h_hat, atol=8 * EPS)
        assert R[:, 1] @ v > 0


def test_the_frame_rate_is_the_orbit_rate_on_a_circle_and_h_over_r2_on_an_ellipse():
    mu, r0 = 3.986004418e14, 7.0e6
    n = math.sqrt(mu / r0**3)
    r, v = rd.elements_to_state([r0, 0.0, 0.7, 0.2, 0.0, 1.1], mu)
    w = rd.orbit_frame_angular_velocity(r, v)
    R = rd.orbit_frame_rotation(r, v)
    np.testing.assert_allclose(R.T @ w, [0.0, -n, 0.0], rtol=0, atol=8 * EPS * n)  # about -y_LVLH at n
    # an ellipse: h/r^2, faster at perigee than at apogee by ((1 + e)/(1 - e))^2
    p, e = 7.0e6, 0.3
    h = math.sqrt(mu * p)
    for nu in (0.0, 1.0, math.pi):
        r, v = rd.elements_to_state([p, e, 0.7, 0.2, 0.4, nu], mu)
        rate = np.linalg.norm(rd.orbit_frame_angular_velocity(r, v))
        assert rate == pytest.approx(h / np.linalg.norm(r) ** 2, rel=8 * EPS)


def test_the_frame_rate_is_the_derivative_of_the_frame_along_the_orbit():
    # R_WO(t) along a Keplerian ellipse (mean anomaly M = n t): R^T dR/dt = [w_WO_O x], by central differences
    mu, p, e = 3.986004418e14, 7.0e6, 0.3
    a = p / (1 - e**2)
    n = math.sqrt(mu / a**3)
    el = lambda t: [p, e, 0.7, 0.2, 0.4, rd.mean_to_true_anomaly(0.8 + n * t, e)]  # noqa: E731
    dt = 0.01
    R = {s: rd.orbit_frame_rotation(*rd.elements_to_state(el(s * dt), mu)) for s in (-1, 0, 1)}
    skew = R[0].T @ (R[1] - R[-1]) / (2 * dt)
    w_O = np.array([skew[2, 1], skew[0, 2], skew[1, 0]])
    w_W = rd.orbit_frame_angular_velocity(*rd.elements_to_state(el(0.0), mu))
    # central differences: truncation ~ (|w| dt)^2 ~ 2e-10 of |w| (|w| ~ 1.2e-3 rad/s), round-off ~ eps/(|w| dt)
    # ~ 2e-11 of it: 1e-8 relative is far above both
    np.testing.assert_allclose(R[0] @ w_O, w_W, rtol=0, atol=1e-8 * np.linalg.norm(w_W))


def test_an_attitude_holding_lvlh_comes_back_unchanged():
    # the shipped gravity_gradient scene: at p_W = (0, 0, -r), v_W along +x, LVLH is W itself and holding it
    # needs w_B = (0, -n, 0), n = 1.078007612872506e-3 rad/s (the scene file's figures)
    r, v = [0.0, 0.0, -7.0e6], [7546.053290107541, 0.0, 0.0]
    q_WB, w_B = rd.attitude_from_orbit_frame(r, v, [0.0, 0.0, 0.0, 1.0], np.zeros(3))
    np.testing.assert_allclose(q_WB, [0, 0, 0, 1.0], atol=4 * EPS)
    np.testing.assert_allclose(w_B, [0.0, -1.078007612872506e-3, 0.0], rtol=0, atol=4 * EPS * 1.1e-3)
    # on an inclined elliptic orbit: an attitude given in LVLH comes back to round-off
    mu = 3.986004418e14
    rs, vs = rd.elements_to_state(np.array([[7e6, 0.1, 0.9, 0.3, 0.4, nu] for nu in np.linspace(0, 6, 7)]), mu)
    q_OB = Rotation.from_rotvec([0.02, -0.01, 0.03]).as_quat()
    w_OB_B = np.array([1e-5, -2e-5, 3e-6])
    for frame in ("lvlh", "rsw"):
        q, w = rd.attitude_to_orbit_frame(rs, vs, *rd.attitude_from_orbit_frame(rs, vs, q_OB, w_OB_B, frame), frame)
        assert np.abs(np.abs(np.sum(q * q_OB, axis=1)) - 1).max() <= 8 * EPS  # the same rotation (q or -q)
        # w_B is of the size of the orbit rate n ~ 1e-3 rad/s: its round-off is ~eps n
        np.testing.assert_allclose(w, np.broadcast_to(w_OB_B, w.shape), rtol=0, atol=16 * EPS * 1.2e-3)


@settings(max_examples=60, deadline=None)
@given(rotvec=st.tuples(*[st.floats(-3, 3)] * 3), w=st.tuples(*[st.floats(-1, 1)] * 3),
       nu=angle, scalar_first=st.booleans(), frame=st.sampled_from(["lvlh", "rsw"]))
def test_attitude_conversions_against_scipy(rotvec, w, nu, scalar_first, frame):
    mu = 3.986004418e14
    r, v = rd.elements_to_state([7e6, 0.2, 1.0, 0.5, 0.6, nu], mu)
    R_WO = Rotation.from_matrix(rd.orbit_frame_rotation(r, v, frame))
    R_OB = Rotation.from_rotvec(rotvec)
    q_WB, w_B = rd.attitude_from_orbit_frame(r, v, R_OB.as_quat(scalar_first=scalar_first), w, frame,
                                             scalar_first=scalar_first)
    want = (R_WO * R_OB).as_quat(scalar_first=scalar_first)
    assert abs(abs(q_WB @ want) - 1) <= 8 * EPS
    w_WO_B = (R_WO * R_OB).inv().apply(rd.orbit_frame_angular_velocity(r, v))
    np.testing.assert_allclose(w_B, np.add(w, w_WO_B), rtol=0, atol=8 * EPS)  # |w| <= 1.8 rad/s
