"""Stability at the extremes, fast subset (the full matrix: bench/python/bench_extremes.py, table in
docs/extremes.md).

Documented behaviour asserted for every method of methods() on every case:
1. no NaN or Inf returned silently: either every recorded value is finite, or the run says
   `diverged` and simulate warned (RuntimeWarning);
2. a run that rigiddyn.stability does not warn about does not diverge (a method absent from its
   table claims to be stable at any step);
3. methods that keep unit |q| (conserves: "unit |q|" or "SO(3)") keep ||q| - 1| at round-off;
4. methods that conserve energy or |L| keep them bounded with no secular drift within their documented
   stability limit (methods()['stability_limit'], no StabilityWarning); beyond it the splitting methods
   still keep |L| to round-off (exact sub-rotations) while their energy error is O(1);
5. a body rigiddyn cannot integrate (a thin rod, one moment exactly 0) is refused with a ValueError
   naming the inertia.
"""

import math
import warnings
from dataclasses import replace

import numpy as np
import pytest
import rigiddyn
from rigiddyn.problem import Problem, parse_problem
from rigiddyn.stability import STABILITY_POLYNOMIALS, orbit, stability_message
from rigiddyn.work_precision import reference_states

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

METHODS = {m["name"]: m for m in rigiddyn.methods()}


def body_problem(moments, w_B, mass=1.0, horizon=1.0, gravity=(0.0, 0.0, 0.0), v_W=(0.0, 0.0, 0.0)):
    return Problem(name="extreme", mass=mass, inertia_com=np.diag(np.asarray(moments, float)), horizon=horizon,
                   w_B=np.asarray(w_B, float), gravity=np.asarray(gravity, float), v_W=np.asarray(v_W, float))


SEPARATRIX_M = np.array([1.0, 0.5, math.sqrt(3.0) * (1.0 + 1e-9)])  # Delta2 = -m1^2 + m3^2 / 3 ~ 2e-9
# (case id, problem, dt [s], steps)
CASES = [
    ("spin_1e4_dtw_1e-2", body_problem([1.0, 2.0, 2.5], [1.0, 0.5, 1e4]), 1e-6, 300),
    ("spin_1e4_dtw_1", body_problem([1.0, 2.0, 2.5], [1.0, 0.5, 1e4]), 1e-4, 300),
    ("ratio_1e6", body_problem([1e-6, 1.0, 1.0], [10.0, 1.0, 0.5]), 1e-3, 500),
    ("near_spherical_1e-12", body_problem([1.0, 1.0 + 1e-12, 1.0 + 2e-12], [1.0, 2.0, 3.0]), 1e-2, 200),
    ("flat_plate_I3_eq_I1_plus_I2", body_problem(rigiddyn.thin_plate(1.0, 2.0, mass=1.0).principal_axes().moments,
                                                 [0.5, 1.0, 2.0]), 1e-2, 300),
    ("mass_1e-9", body_problem(np.full(3, 0.4e-9 * 1e-4), [3.0, -2.0, 1.0], mass=1e-9, gravity=(0, 0, -9.81),
                               v_W=(1.0, 0.0, 2.0)), 1e-2, 200),
    ("mass_1e9", body_problem(np.full(3, 0.4e9 * 100.0), [3.0, -2.0, 1.0], mass=1e9, gravity=(0, 0, -9.81),
                              v_W=(1.0, 0.0, 2.0)), 1e-2, 200),
    ("dtw_1e-4", body_problem([2.0, 6.5, 8.0], [0.1, 10.0, 0.0]), 1e-5, 200),
    ("dtw_1e-1", body_problem([2.0, 6.5, 8.0], [0.1, 10.0, 0.0]), 1e-2, 200),
    ("dtw_1", body_problem([2.0, 6.5, 8.0], [0.1, 10.0, 0.0]), 0.1, 1000),
    ("dtw_10", body_problem([2.0, 6.5, 8.0], [0.1, 10.0, 0.0]), 1.0, 200),
    ("near_separatrix", body_problem([1.0, 2.0, 3.0], SEPARATRIX_M / [1.0, 2.0, 3.0]), 1e-3, 2000),
]


def run_case(problem, method, dt, steps):
    """simulate through the problem layer, returning (result, warnings raised)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = problem.simulate(method, dt, steps=steps, record_every=max(1, steps // 100))
    return result, caught


def arrays(result):
    body = result.body(0)
    return [np.asarray(getattr(result, k)) for k in ("t", "kinetic_energy")] + [
        np.asarray(getattr(body, k)) for k in ("p_W", "q_WB", "v_W", "w_B", "angular_momentum_norm",
                                               "quaternion_norm_error")]


@pytest.mark.parametrize("method", sorted(METHODS))
@pytest.mark.parametrize("case, problem, dt, steps", CASES, ids=[c[0] for c in CASES])
def test_documented_behaviour(case, problem, dt, steps, method):
    result, caught = run_case(problem, method, dt, steps)
    kinds = {type(w.message) for w in caught}
    finite = all(np.all(np.isfinite(a)) for a in arrays(result))
    # 1. never a silent NaN/Inf
    if not finite or result.diverged:
        assert result.diverged
        assert any(issubclass(w.category, RuntimeWarning) and "non-finite" in str(w.message) for w in caught)
    # 2. no stability warning -> no divergence
    if stability_message(method, dt, steps, problem.inertia_com, problem.w_B, problem.torque_free) is None:
        assert not result.diverged, f"{method} diverged on {case} without a StabilityWarning"
        assert rigiddyn.StabilityWarning not in kinds
    else:
        assert rigiddyn.StabilityWarning in kinds
    if result.diverged:
        return
    conserves = METHODS[method]["conserves"]
    # 3. unit quaternion at round-off
    if "unit |q|" in conserves or "SO(3)" in conserves:
        # renormalised (or an exact unit update) every step: |q| - 1 within ~2 eps at any step
        assert np.max(np.abs(result.body(0).quaternion_norm_error)) < 1e-13
    # 4. structure-preserving methods within their stability limit: energy and |L| bounded without
    # secular drift; beyond it (warned) only what is kept to round-off at any step
    warned = rigiddyn.StabilityWarning in kinds
    for records, key, name in ((result, "kinetic_energy", "energy"), (result.body(0), "angular_momentum_norm", "|L|")):
        if name in conserves and not np.any(problem.gravity):
            values = np.asarray(getattr(records, key))
            drift = np.abs(values - values[0]) / values[0]
            half = drift.size // 2
            if not warned:
                # the method table's stated bound within the stability limit (|dE|/E <= 8e-3, |L| exact),
                # and no secular drift: a bounded error's maximum over the second half of the records
                # does not exceed the first half's beyond sampling (x2) and round-off
                assert np.max(drift) < 1e-2 and np.max(drift[half:]) <= 2 * np.max(drift[:half]) + 1e-13
            elif name == "|L|" and "round-off" in conserves:
                assert np.max(drift) < 4 * steps * np.finfo(float).eps  # <= 4 eps per step, worst case linear


def _momentum_error(problem, method, dt, steps):
    result, _ = run_case(problem, method, dt, steps)
    result = result.body(0)
    ref = reference_states(replace(problem, horizon=dt * steps), np.asarray(result.t))
    g = np.linalg.norm(problem.inertia_com @ problem.w_B)
    momentum_error = np.max(np.linalg.norm((np.asarray(result.w_B) - ref.w_B) @ problem.inertia_com.T, axis=1)) / g
    scale = np.max(np.linalg.norm(ref.p_W, axis=1)) + 1.0
    return momentum_error, np.max(np.linalg.norm(np.asarray(result.p_W) - ref.p_W, axis=1)) / scale


@pytest.mark.parametrize("method", [m for m in sorted(METHODS) if METHODS[m]["order"] >= 2 or METHODS[m]["order"] == 0])
@pytest.mark.parametrize("case", ["near_spherical_1e-12", "flat_plate_I3_eq_I1_plus_I2", "near_separatrix",
                                  "ratio_1e6", "mass_1e-9", "mass_1e9"])
def test_accurate_at_the_extremes(case, method):
    """Where the exact solution is delicate (near sphere, flat plate, moment ratio 1e6, on the
    separatrix, extreme masses), every method of order p >= 2 keeps its documented truncation error:
    at dt |w| <= 0.04 over N steps the body-momentum error is within N (dt |w|)^(p+1) (the local error
    of an order-p method with unit error constant; measured constants are 0.01-0.1), and where it is
    above round-off, halving dt divides it by 2^p (observed order within 0.3 of the documented one): no
    loss of accuracy, no unconverged solver, no badly chosen axes. The exact method (order 0) and the
    methods exact on torque-free bodies stay at round-off. The centre of mass follows the exact
    ballistic motion to 1e-9 of its scale."""
    _, problem, dt, steps = next(c for c in CASES if c[0] == case)
    info = METHODS[method]
    momentum_error, position_error = _momentum_error(problem, method, dt, steps)
    # every method is exact on ballistic motion (constant acceleration): round-off, <= 4 eps of the
    # scale per step over <= 2000 steps = 2e-12, far inside 1e-9
    assert position_error < 1e-9
    if info["order"] == 0 or info["exact_torque_free"]:
        # the exact flow to a few ulps of G per step (free_body.hpp), accumulated at worst linearly
        # and amplified by the flow's sensitivity over these short runs (e^(lambda t) <= 4, lambda t
        # <= 1.2 near the separatrix): 4 x 4 eps per step
        assert momentum_error < 16 * steps * np.finfo(float).eps
        return
    rate = np.max(np.linalg.norm(orbit(problem.inertia_com, problem.w_B, dt * steps), axis=1))
    assert dt * rate <= 0.04
    p = info["order"]
    assert momentum_error < steps * (dt * rate) ** (p + 1)
    if momentum_error > 1e-10:  # 100x above the round-off (<= 16 eps per step, 2000 steps: 7e-12)
        halved, _ = _momentum_error(problem, method, dt / 2, 2 * steps)
        # the next term of the error expansion is O(dt |w|) <= 0.04 relative: log2 moves by <= 0.06
        assert math.log2(momentum_error / halved) == pytest.approx(p, abs=0.3)


def test_near_separatrix_reference_is_the_closed_form():
    _, problem, _, _ = next(c for c in CASES if c[0] == "near_separatrix")
    solution = rigiddyn.TorqueFreeSolution(problem.inertia_com, problem.q_WB, problem.w_B, check=problem.inertia_check)
    assert solution.case == "A" and 0.0 < solution.parameter_mc < 1e-8


@pytest.mark.parametrize("shape", [
    "[body.primitive]\nshape = 'thin_rod'\nlength = 1.0\nmass = 1.0",
    "[body]\nmass = 1.0\ninertia = [0.0, 1.0, 1.0]",
])
def test_a_zero_moment_is_refused(shape):
    with pytest.raises(ValueError, match=r"^body.inertia: "):
        parse_problem(tomllib.loads("horizon = 1.0\n" + shape))


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # runs at the stability limit on purpose
@pytest.mark.parametrize("method", [m for m in sorted(METHODS) if m not in STABILITY_POLYNOMIALS])
def test_stability_limit_is_the_documented_one_from_the_method_table(method):
    """Methods without a stability polynomial are checked against methods()['stability_limit'] (the
    C++ MethodInfo): no warning at dt |w|max = 0.9 x the limit, a StabilityWarning naming the limit at
    1.1 x (|w|max the largest body rate on the orbit); none ever for an unconditionally stable method."""
    limit = METHODS[method]["stability_limit"]
    problem = body_problem([1.0, 2.0, 3.0], [0.3, 0.2, 1.0])
    rate = np.max(np.linalg.norm(orbit(problem.inertia_com, problem.w_B, 100.0), axis=1))
    for factor in (0.9, 1.1):
        dt = factor * (limit if math.isfinite(limit) else 10.0) / rate
        message = stability_message(method, dt, 100, problem.inertia_com, problem.w_B, problem.torque_free)
        if factor < 1 or not math.isfinite(limit):
            assert message is None
        else:
            assert f"> {limit:.3g}, the documented limit" in message
            with pytest.warns(rigiddyn.StabilityWarning, match=method):
                problem.simulate(method, dt, steps=100)


# A run far from t = 0 (an epoch in seconds: 1e9 s is 2001 in Unix time): the implicit midpoint's fixed point stops
# on the motion's coordinates alone, so a scene whose forces do not read t moves bit for bit alike from any t0 (its
# stopping test once read t's size too, and from t0 = 1e9 s a free body kept its energy to 6e-12 instead of 8e-14).
@pytest.mark.parametrize("t0", [1e3, 1e9])
def test_implicit_midpoint_moves_alike_from_any_start_time(t0):
    body = rigiddyn.RigidBody(2.0, [1.0, 2.0, 3.0])
    start = rigiddyn.RigidBodyState(q_WB=rigiddyn.rotvec_to_quat([0.3, -0.2, 0.9]), w_B=[0.1, 1.0, 0.2])
    spring = rigiddyn.SpringDamper(body_a=0, body_b=None, stiffness=5.0, rest_length=0.5, damping=0.2,
                                   point_a_B=[0.2, 0.0, 0.1], point_b=[0.0, 0.0, 1.0])
    second = rigiddyn.RigidBody(1.0, [0.2, 0.3, 0.4])
    scene = rigiddyn.Scene([body, second], elements=[rigiddyn.UniformGravity(), spring])
    runs = [(body, start), (scene, [start, rigiddyn.RigidBodyState(p_W=[1.0, 0.0, 0.0], w_B=[0.0, 2.0, 0.1])])]
    for model, initial in runs:
        options = {"method": "implicit_midpoint", "steps": 400, "error": False, "accuracy_level": None}
        at_zero = rigiddyn.simulate(model, initial, 0.05, **options)
        later = rigiddyn.simulate(model, initial, 0.05, t0=t0, **options)
        for name in ("p_W", "q_WB", "v_W", "w_B"):
            assert np.array_equal(getattr(later, name), getattr(at_zero, name)), (type(model).__name__, name)
