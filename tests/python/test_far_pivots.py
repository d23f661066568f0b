"""Pivots far from the centre of mass, and bodies whose moments span many orders: refused with a ValueError
naming the input, or run with finite records; never NaN records without a word, a negative count of
digits, or an internal error."""

import math
import warnings

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rigiddyn as rd

I_C = np.diag([0.5, 0.6, 0.9])  # smallest moment 0.5 kg m^2


def compile_warnings(body):
    scene = rd.Scene()
    scene.add_body(body, name="top")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene.compile(method="rk4")
    return [str(w.message) for w in caught]


# ------------------------------------------------------------------ PivotedBody: digits lost
@pytest.mark.parametrize("digits", [7.0, 10.0, 14.0, 14.9])
def test_digits_lost_up_to_the_limit_warn_with_the_digits_kept(digits):
    # m |c|^2 = 10^digits lambda_min(I_C) (m = 2): log10 of it, within a few ulps
    c = 0.5 * 10.0 ** (digits / 2.0)
    body = rd.PivotedBody(rd.RigidBody(2.0, I_C), [0.0, 0.0, c])
    assert body.digits_lost == pytest.approx(digits, abs=1e-12)
    kept = [m for m in compile_warnings(body) if "keeps only" in m]
    assert len(kept) == 1 and f"keeps only ~{16.0 - digits:.1f} of the 16 digits" in kept[0], kept


@pytest.mark.parametrize("digits", [15.1, 16.0, 18.0, 100.0, 200.0, 400.0])
def test_digits_lost_beyond_15_are_refused_naming_p_OC_B(digits):
    # 18.4 digits was accepted and warned "keeps only ~-2.4 of the 16 digits"; 400 overflows m |c|^2
    c = 0.5 * 10.0 ** (digits / 2.0)  # m |c|^2 = 10^digits lambda_min(I_C)
    with pytest.raises(ValueError, match=r"^p_OC_B: expected a pivot .* at most 15 of its 16 digits lost"):
        rd.PivotedBody(rd.RigidBody(2.0, I_C), [0.0, c, 0.0])


def test_no_warning_ever_counts_negative_digits():
    for exponent in np.linspace(0.0, 12.0, 49):  # |c| from 1 m to 1e12 m
        try:
            body = rd.PivotedBody(rd.RigidBody(2.0, I_C), [10.0 ** exponent, 0.0, 0.0])
        except ValueError as refusal:
            assert str(refusal).startswith("p_OC_B: expected")
            continue
        for message in compile_warnings(body):
            assert "keeps only ~-" not in message, message


# ------------------------------------------------------------------ PivotedPlanarBody: overflow
def test_planar_pivot_whose_inertia_overflows_is_refused():
    # I_O = 0.5 + 0.5 (0.25 + 1e600) overflows: accepted before, and every energy and momentum was NaN
    with pytest.raises(ValueError, match=r"^p_OC_B: expected a pivot .* stays within the double range"):
        rd.PivotedPlanarBody(0.5, 0.5, [0.5, 1e300])


def test_planar_pivot_far_but_in_range_records_finite_values():
    body = rd.PivotedPlanarBody(0.5, 0.5, [0.5, 1e150])  # I_O = 5e299 kg m^2
    scene = rd.Scene()
    scene.add_body(body, name="pendulum")
    scene.add(rd.UniformGravity())
    run = rd.simulate(scene, [rd.PivotedPlanarBodyState(theta=0.1, omega=1.0)], 1e-3, 10, "rk4")
    for field in ("kinetic_energy", "potential_energy", "total_energy", "angular_momentum_W", "pivot_reaction_W"):
        assert np.all(np.isfinite(getattr(run, field))), field


# ------------------------------------------------------------------ exact flows: no internal error
def test_exact_flow_kick_on_a_far_pivot_is_refused_at_the_body():
    # a pivot 1e100 m away (200 digits lost) with w = (4.5e-254, 1e300, 0) leaked "Carlson duplication: no
    # convergence after 1200 steps" from the exact free flow; the body itself is refused now
    with pytest.raises(ValueError, match="^p_OC_B: expected"):
        body = rd.PivotedBody(rd.RigidBody(1.0, np.eye(3)), [1e100, 0.0, 0.0])
        rd.simulate(body, rd.PivotedBodyState(w_B=[4.5e-254, 1e300, 0.0]), dt=1e-3, steps=10, method="exact_flow_kick")


# moments spanning ~1e275 and ~1e283 with a momentum part along the smallest: the amplitudes of the elliptic
# functions, ~(I_max/I_min)^2 in the solution's scaled units, overflowed, and infinities reached Carlson's
# duplication (an internal RuntimeError)
SPREAD_CASES = [
    ([5.194511142106372e-111, 9.969571844746376e+150, 3.2117577726940814e+164],
     [-2.6120584954463155e+139, 1.249331742987632e-97, 2.450745157630913e-296]),
    ([1.2418496538981204e-32, 8.370165563892983e+250, 8.370169767232112e+250],
     [-1.0986963424032568e+239, 3.4148419069774386e+24, 0.0]),
]


@pytest.mark.parametrize("moments, w_B", SPREAD_CASES)
def test_torque_free_solution_refuses_a_spread_beyond_range_naming_the_inertia(moments, w_B):
    with pytest.raises(ValueError, match="^inertia: expected principal moments whose spread"):
        rd.TorqueFreeSolution(np.diag(moments), [0, 0, 0, 1], w_B, check=rd.InertiaCheck.allow_unrealizable)


# moments spanning ~1e100 with the momentum within kc ~ 1e-230..1e-309 of the separatrix, at times |lambda t|
# ~ 1e15..1e50 K where the reduction of the phase leaves it up to 3K/4: the elliptic functions there came back
# cn = dn = 0 (their squares underflowed), which Carlson's duplication cannot take (an internal RuntimeError)
TINY_KC_CASES = [
    ([6.563813539349353e+40, 6.500949554772619e+143, 6.500949554772837e+143],
     [0.0, -1.7914474476248744e+142, 8.671026016895838e-167], 7.943282347242919e-170),
    ([6.036914292023833e-90, 1.2048573978219944e+19, 1.2049320786143422e+19],
     [-4.5971322491551497e-94, -3.630842341389589e+140, -6.260548754405974e-123], 1.584893192461072e-174),
    ([5.416752223597538e-161, 1.028224652647413e-94, 1.0282247788783371e-94],
     [2.674072837919351e-07, 1.9239220306686314e+195, 5.482378836469648e-253], 7.94328234724292e-173),
]


@pytest.mark.parametrize("moments, w_B, t", TINY_KC_CASES)
def test_torque_free_solution_a_hair_from_the_separatrix_gives_a_state(moments, w_B, t):
    solution = rd.TorqueFreeSolution(np.diag(moments), [0, 0, 0, 1], w_B, check=rd.InertiaCheck.allow_unrealizable)
    assert solution.parameter_mc == 0.0  # kc^2 underflows
    q, w = solution.state_at(t)
    assert np.all(np.isfinite(q)) and np.all(np.isfinite(w))
    assert abs(np.linalg.norm(q) - 1.0) <= 4 * np.finfo(float).eps


def test_torque_free_solution_never_raises_an_internal_error():
    # random inertias spanning up to 1e600 (scaled by up to 1e+-300), nearly symmetric ones among them, and
    # rates spanning the double range: a state, or a ValueError naming the input, for every one
    rng = np.random.default_rng(7)
    for _ in range(3000):
        moments = np.sort(10.0 ** rng.uniform(-300, 300, 3))
        if rng.random() < 0.3:
            moments[2] = moments[1] * (1 + 10.0 ** rng.uniform(-16, -1))
        R = Rotation.random(random_state=rng).as_matrix() if rng.random() < 0.3 else np.eye(3)
        inertia = R @ np.diag(moments) @ R.T
        inertia = 0.5 * (inertia + inertia.T)
        w_B = 10.0 ** rng.uniform(-320, 308, 3) * rng.choice([-1.0, 0.0, 1.0], 3, p=[0.45, 0.1, 0.45])
        try:
            solution = rd.TorqueFreeSolution(inertia, [0, 0, 0, 1], w_B, check=rd.InertiaCheck.allow_unrealizable)
            q, w = solution.state_at(10.0 ** rng.uniform(-300, 300))
        except ValueError as refusal:
            assert str(refusal).split(":")[0] in ("inertia", "w_B", "t"), refusal
        else:
            assert np.all(np.isfinite(q)) and np.all(np.isfinite(w))
