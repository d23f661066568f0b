"""simulate(..., tolerance=): the method and dt chosen, the result certified and checked against closed forms.

The bound of every "met" assert: the run aims at tolerance / 2 (the safety factor) and is certified by its global
Richardson estimate to be <= tolerance on every record; the estimate is the leading error term, measured within
0.86-1.22 of the true error on reliable records (GlobalError), so the true error is <= tolerance unless the
estimate under-estimates by more than the certificate's margin. A closed form gives the true error to round-off
(TorqueFreeSolution ~1e-13 rad, kepler_propagate ~1e-9 relative, the ballistic particle exact).
"""

import math
import pickle
from pathlib import Path

import numpy as np
import pytest

import rigiddyn as rd

SCENES = Path(rd.__file__).parent / "scenes"  # the shipped scene files


def geodesic(q_a, q_b):
    """Geodesic angle between (n, 4) quaternion rows (x, y, z, w) [rad]: 2 atan2(|v|, |w|) of q_a^-1 q_b, accurate
    near 0 (an arccos of the dot product floors at ~3e-8 rad)."""
    q_a = q_a / np.linalg.norm(q_a, axis=1, keepdims=True)
    q_b = q_b / np.linalg.norm(q_b, axis=1, keepdims=True)
    w = np.sum(q_a * q_b, axis=1)
    v = q_a[:, 3:4] * q_b[:, :3] - q_b[:, 3:4] * q_a[:, :3] - np.cross(q_a[:, :3], q_b[:, :3])
    return 2.0 * np.arctan2(np.linalg.norm(v, axis=1), np.abs(w))


FREE_BODIES = [
    ((1.0, 2.0, 3.0), (0.1, 1.0, 0.1), 20.0),  # near the middle-axis separatrix
    ((1.0, 2.0, 3.0), (3.0, 0.5, 1.0), 10.0),  # a fast tumble
    ((2.0, 2.0, 3.0), (0.5, 0.2, 2.0), 15.0),  # nearly symmetric
]


@pytest.mark.parametrize("inertia, w_B, duration", FREE_BODIES)
@pytest.mark.parametrize("tolerance", [1e-4, 1e-7])
def test_a_free_body_meets_the_tolerance_against_its_closed_form(inertia, w_B, duration, tolerance):
    body = rd.RigidBody(1.0, list(inertia))
    r = rd.simulate(body, rd.RigidBodyState(w_B=list(w_B)), duration=duration, tolerance=tolerance)
    q, _ = rd.TorqueFreeSolution(np.diag(inertia), [0, 0, 0, 1], list(w_B)).state_at(np.asarray(r.t))
    true = geodesic(np.asarray(r.body(0).q_WB), q).max()
    assert true <= tolerance  # certified <= tolerance, aimed at tolerance / 2 (module docstring)
    assert r.choice.met and r.choice.certified_error <= tolerance
    assert r.choice.steps * r.choice.dt == pytest.approx(duration, rel=1e-12)  # duration / steps, round-off
    assert r.t[-1] == pytest.approx(duration, rel=1e-12)


@pytest.mark.parametrize("inertia, w_B, duration", FREE_BODIES)
def test_a_method_exact_on_a_torque_free_body_runs_at_the_fewest_steps(inertia, w_B, duration):
    # exact_flow_kick and the closed form have no truncation error and no stability limit on a torque-free body:
    # the planner's step is then not bounded by its pilot's (duration / 64), only by its fewest steps (16)
    body = rd.RigidBody(1.0, list(inertia))
    r = rd.simulate(body, rd.RigidBodyState(w_B=list(w_B)), duration=duration, tolerance=1e-6)
    assert r.choice.method in ("exact", "exact_flow_kick") and r.choice.steps == 16
    # no other stepping method can take fewer steps: none is piloted
    others = [p for p in r.choice.pilots if p["method"] in ("rk4", "rkmk4", "splitting_dlm_yoshida4")]
    assert others and all(p["verdict"] == "not piloted: exact_flow_kick is exact on this scene" for p in others)
    q, _ = rd.TorqueFreeSolution(np.diag(inertia), [0, 0, 0, 1], list(w_B)).state_at(np.asarray(r.t))
    assert geodesic(np.asarray(r.body(0).q_WB), q).max() <= 1e-6  # certified <= tolerance (module docstring)


def test_a_tolerance_near_the_round_off_of_an_exact_method_is_met_at_its_fewest_steps():
    # exact_flow_kick on a torque-free body: its error is round-off, bounded by 8 eps per step (2.8e-14 rad after 16
    # steps), which more steps would only grow
    r = rd.simulate(BODY, STATE, duration=20.0, tolerance=1e-13, method="exact_flow_kick")
    assert r.choice.met and r.choice.steps == 16 and r.choice.certified_error <= 16 * 8 * np.finfo(float).eps


def test_a_torque_keeps_the_step_of_the_pilot():
    # under a body torque exact_flow_kick has a truncation error: no method is exact on the scene, and every step
    # stays at most its pilot's
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    push = rd.AppliedLoad(torque=[0.0, 0.0, 0.05], frame="body")
    r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=20.0, tolerance=1e-6, loads=[push])
    assert r.choice.met and r.choice.steps > 16
    assert "exact on this scene" not in r.choice.reason
    assert not any(p["verdict"].startswith("not piloted") for p in r.choice.pilots)


def _random_bodies(seed, count):
    """`count` rigid bodies drawn from `seed`: principal moments in [1, 2] kg m^2 (every triple is physical), body
    rates N(0, 1.5^2) rad/s, a duration in [2, 20] s and a tolerance log-uniform in [1e-7, 1e-2] rad."""
    rng = np.random.default_rng(seed)
    return [(np.sort(rng.uniform(1.0, 2.0, 3)), rng.normal(0.0, 1.5, 3), rng.uniform(2.0, 20.0),
             10.0 ** rng.uniform(-7.0, -2.0), rng.normal(0.0, 0.3, 3)) for _ in range(count)]


@pytest.mark.parametrize("inertia, w_B, duration, tolerance, _", _random_bodies(11, 8))
def test_a_random_free_body_meets_the_tolerance(inertia, w_B, duration, tolerance, _):
    # problems the planner was not tuned on, against the closed form
    body = rd.RigidBody(1.0, list(inertia))
    r = rd.simulate(body, rd.RigidBodyState(w_B=list(w_B)), duration=duration, tolerance=tolerance)
    q, _ = rd.TorqueFreeSolution(np.diag(inertia), [0, 0, 0, 1], list(w_B)).state_at(np.asarray(r.t))
    assert geodesic(np.asarray(r.body(0).q_WB), q).max() <= tolerance  # certified <= tolerance (module docstring)


@pytest.mark.parametrize("inertia, w_B, duration, tolerance, torque", _random_bodies(12, 8))
def test_a_random_torqued_body_meets_the_tolerance(inertia, w_B, duration, tolerance, torque):
    # a constant body torque N(0, 0.3^2) N m, against rk4 at a 32nd of the chosen step: every candidate has an order
    # <= 4, so the reference's error is ~32^-4 ~ 1e-6 of an order-4 run's at the chosen step (certified <= tolerance):
    # the difference is the run's error to 1e-6 of the tolerance
    body, state = rd.RigidBody(1.0, list(inertia)), rd.RigidBodyState(w_B=list(w_B))
    load = rd.AppliedLoad(torque=list(torque), frame="body")
    r = rd.simulate(body, state, duration=duration, tolerance=tolerance, loads=[load])
    n = r.choice.steps
    fine = rd.simulate(body, state, duration / (32 * n), steps=32 * n, record_every=32, method="rk4", loads=[load],
                       error=False)
    assert geodesic(np.asarray(r.body(0).q_WB), np.asarray(fine.body(0).q_WB)).max() <= tolerance


@pytest.mark.parametrize("tolerance", [1e-2, 1.0])
def test_a_kepler_orbit_meets_a_position_tolerance(tolerance):
    scene, initial, _ = rd.load_scene("kepler")
    period = 5828.516637686  # the scene's orbit, 2 pi sqrt(a^3 / GM)
    r = rd.simulate(scene, initial, duration=2 * period, tolerance=tolerance * 1e3)  # metres over 2 orbits
    assert r.choice.measure == "position"  # a scene of particles
    p, _ = rd.kepler_propagate(initial[0].p_W, initial[0].v_W, 398600.4418e9, np.asarray(r.t))
    true = np.linalg.norm(np.asarray(r.p_W)[:, 0, :] - np.asarray(p), axis=1).max()
    # certified <= tolerance (module docstring); kepler_propagate's own error ~1e-9 relative of 7e6 m = 7e-3 m
    assert true <= tolerance * 1e3 + 7e-3


@pytest.mark.parametrize("name", ["kepler", "pendulum"])  # particles; a pivoted planar body
def test_a_lie_group_method_is_not_piloted_where_it_takes_its_plain_forms_steps(name):
    """Where no body turns in 3D, rkmk4 takes rk4's steps and exact_flow_kick splitting_dlm's: the same states up to
    the rounding of operations done in another order (each step adds at most a few roundings of the state's scale,
    bounded by 8 eps per step as the estimate's round-off bound is: 800 eps over 100 steps), so neither is piloted."""
    scene, initial, run = rd.load_scene(name)
    bound = 800 * np.finfo(float).eps
    for lie_group, plain in (("rkmk4", "rk4"), ("exact_flow_kick", "splitting_dlm")):
        a = rd.simulate(scene, initial, run.dt, steps=100, method=lie_group, error=False)
        b = rd.simulate(scene, initial, run.dt, steps=100, method=plain, error=False)
        for field in ("p_W", "v_W"):
            x, y = np.asarray(getattr(a, field)), np.asarray(getattr(b, field))
            assert np.abs(x - y).max() <= bound * np.abs(y).max(), (lie_group, field)
    r = rd.simulate(scene, initial, duration=run.duration / 8, tolerance=1e-3 if name == "pendulum" else 1e4)
    verdicts = {p["method"]: p["verdict"] for p in r.choice.pilots}
    assert verdicts["rkmk4"] == "not piloted: it takes the same steps as rk4 on this scene"
    assert verdicts["exact_flow_kick"] == "not piloted: it takes the same steps as splitting_dlm on this scene"
    assert r.choice.met
    # a rigid body turns in 3D: every method is piloted
    body = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0,
                       tolerance=1e-5)
    assert not any(p["verdict"].startswith("not piloted: it takes") for p in body.choice.pilots)


def test_a_ballistic_particle_takes_the_fewest_steps():
    # rk4 integrates a quadratic motion exactly: the error is round-off at any step
    r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 5.0]), duration=2.0, tolerance=1e-9,
                    gravity=True)
    assert r.choice.measure == "position" and r.choice.met
    t = np.asarray(r.t)
    exact = np.stack([t, 0 * t, 5.0 * t - 0.5 * 9.81 * t**2], axis=1)
    assert np.abs(np.asarray(r.body(0).p_W) - exact).max() <= 1e-9  # certified; round-off of ~|p| 8 eps per step


def test_a_given_method_keeps_it_and_chooses_dt():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-5, method="splitting_dlm")
    assert r.choice.method == "splitting_dlm" and r.choice.order == 2
    assert {p["method"] for p in r.choice.pilots} == {"splitting_dlm"}  # the short pilot and the whole-horizon one


def test_the_choice_is_reported_and_pickles():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-6, record_every=4)
    c = r.choice
    assert c.tolerance == 1e-6 and c.measure == "attitude" and c.steps % 4 == 0
    assert c.method in c.reason and "certified" in c.reason
    assert any(p["verdict"] == "used" and p["method"] == c.method for p in c.pilots)
    assert repr(c).startswith("ToleranceChoice(method=")
    assert pickle.loads(pickle.dumps(c)) == c
    again = pickle.loads(pickle.dumps(r))
    assert again.choice == c and again.error == r.error


def test_a_scene_result_carries_the_choice():
    scene, initial, _ = rd.load_scene("pendulum")
    r = rd.simulate(scene, initial, duration=2.0, tolerance=1e-6)
    assert r.choice.met and r.choice.measure == "attitude"
    assert pickle.loads(pickle.dumps(r)).choice == r.choice


def test_a_tolerance_as_a_quantity_is_converted():
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    r = rd.simulate(body, state, duration=5.0 * u.s, tolerance=1e-3 * u.mrad)
    assert r.choice.tolerance == pytest.approx(1e-6, rel=1e-15)  # one conversion factor


def test_the_cost_cap_raises_with_its_figures():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    couple = rd.AppliedLoad(torque=[0.0, 0.0, 0.1], frame="body")  # no closed form: every method has an order
    with pytest.raises(rd.ToleranceError, match="max_steps = 8") as info:
        rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=20.0, tolerance=1e-10, max_steps=8,
                    loads=couple)
    e = info.value
    assert isinstance(e, ValueError) and e.tolerance == 1e-10 and e.measure == "attitude"
    assert e.result is None and e.error > 1e-10 and not e.choice.met


def test_a_tolerance_below_the_round_off_raises_without_refining():
    # the shipped Kepler orbit (|p_W| ~ 8e6 m) to 1e-5 m: every record's error is at the round-off level of the run
    # (8 eps |p_W| per step, ~1e-3 m at its 86 432 steps), which a smaller step only raises: the call raises at once
    # with the bound, where it refined three times towards 15 million steps before
    kepler = rd.load_scene("kepler")
    with pytest.raises(rd.ToleranceError, match=r"is the round-off bound of \d+ steps") as info:
        rd.simulate(kepler.scene, kepler.initial, duration=kepler.run.duration, tolerance=1e-5)
    e = info.value
    assert e.choice.refinements == 0 and not e.choice.met and e.error > 1e-5
    size = np.max(np.linalg.norm(e.result.p_W, axis=-1))  # the best run's largest |p_W| [m]
    assert e.error <= 8 * np.finfo(float).eps * size * e.choice.steps  # the round-off bound (8 eps |p_W| per step)


def test_a_certificate_is_not_refused_for_the_round_off_of_a_balance_near_zero():
    # the shipped pendulum, released at rest: its energy balance B = T - W is 0 for the exact motion while T and W
    # swing by ~5 J, so B rounds off at the size of T and W (8 eps (|T| + |V| + |W|) per step), not of B; to 1e-12 rad
    # every record's attitude error is at the round-off level (8 eps rad per step): the call raises at once with the
    # bound, where the balance's round-off at record 36 (1.3e-15 J) refused its certificate and it refined twice
    pendulum = rd.load_scene("pendulum")
    with pytest.raises(rd.ToleranceError, match=r"is the round-off bound of \d+ steps") as info:
        rd.simulate(pendulum.scene, pendulum.initial, duration=pendulum.run.duration, tolerance=1e-12,
                    measure="attitude")
    e = info.value
    assert e.choice.refinements == 0 and "energy balance" not in str(e)
    assert e.error <= 8 * np.finfo(float).eps * e.choice.steps  # the round-off bound of an angle (8 eps per step)


def test_a_python_force_is_refused():
    couple = rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: ((0.0, 0.0, 0.0), (0.0, 0.0, 0.01)))
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[couple])
    with pytest.raises(rd.ToleranceError, match="PythonForce") as info:
        rd.simulate(scene, [rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])], duration=1.0, tolerance=1e-6)
    assert info.value.result is None and info.value.choice is None


BODY = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])


@pytest.mark.parametrize("kwargs, match", [
    (dict(duration=1.0, tolerance=0.0), r"tolerance: expected a finite number > 0 \[rad\], got 0"),
    (dict(duration=1.0, tolerance=-1e-6), r"tolerance: expected a finite number > 0 \[rad\], got -9.99"),
    (dict(duration=1.0, tolerance=math.nan), r"tolerance: expected a finite number, got nan"),
    (dict(duration=1.0, tolerance=1e-6, dt=0.01), r"dt: expected None when tolerance is given .* got float 0.01"),
    (dict(steps=10, tolerance=1e-6), r"steps: expected None when tolerance is given"),
    (dict(tolerance=1e-6), r"duration: expected the time span"),
    (dict(duration=1.0, tolerance=1e-6, error=False), r"error: expected True when tolerance is given"),
    (dict(duration=1.0, tolerance=1e-6, measure="attitud"), r"measure: .*did you mean 'attitude'.* got 'attitud'"),
    (dict(duration=1.0, tolerance=1e-6, max_steps=2), r"max_steps: expected an integer in \[4, "),
    (dict(duration=1.0, measure="attitude", dt=0.1), r"measure: expected None without tolerance"),
    (dict(duration=1.0), r"dt: expected a time step \[s\] > 0, or tolerance="),
])
def test_bad_input_is_named(kwargs, match):
    with pytest.raises(ValueError, match=match):
        rd.simulate(BODY, STATE, **kwargs)


@pytest.mark.parametrize("measure", ["attitude", "angular_velocity"])
def test_a_measure_of_attitude_is_refused_for_particles(measure):
    # a particle has no attitude: its estimate would be the round-off bound alone, and the call a certificate of nothing
    expected = rf"measure: expected 'position', .* for a scene of particles \(none has an attitude\), got '{measure}'"
    with pytest.raises(ValueError, match=expected):
        rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), duration=1.0, tolerance=1e-6,
                    measure=measure)
    scene, initial, run = rd.load_scene("rocket")
    with pytest.raises(ValueError, match=expected):
        rd.simulate(scene, initial, duration=run.duration, tolerance=1e-3, measure=measure)


# each shipped scene over its file's duration (under its [controller], where it has one); the cluster (1000 bodies in
# mutual gravity) over its first 1/32: its reference at a sixteenth of the step costs minutes over the whole
SHIPPED_SCENES = [("box_on_springs", 1), ("cluster", 32), ("cubesat_detumbling", 1), ("cubesat_pointing", 1),
                  ("double_pendulum", 1), ("foucault", 1), ("gravity_gradient", 1), ("heavy_top", 1), ("j2_orbit", 1),
                  ("kepler", 1), ("pendulum", 1), ("rocket", 1), ("satellite_boom", 1), ("solar_array", 1),
                  ("spring_chain", 1), ("three_body", 1)]


def test_the_shipped_scenes_checked_are_every_shipped_scene():
    assert sorted(name for name, _ in SHIPPED_SCENES) == sorted(rd.scene_file.example_scenes())


def _largest_difference(result, reference, measure):
    """The largest difference of `measure` between two SceneResults over the same records and bodies."""
    if measure == "attitude":
        q, q_ref = np.asarray(result.q_WB).reshape(-1, 4), np.asarray(reference.q_WB).reshape(-1, 4)
        return float(geodesic(q, q_ref).max())
    return float(np.linalg.norm(np.asarray(result.p_W) - np.asarray(reference.p_W), axis=-1).max())


@pytest.mark.parametrize("name, part", SHIPPED_SCENES)
def test_each_shipped_scene_meets_its_tolerance_against_a_finer_run(name, part):
    _check_shipped_scene(name, part, 1e-5)


def test_a_loose_tolerance_is_met_where_the_coarse_runs_of_a_certificate_would_be_unstable():
    # the Foucault pendulum (period 16.4 s) over an hour to 1e-3 rad: a run of ~1400 rk4 steps has its run at 4h past
    # rk4's stability limit, where the attitude's estimate (1.8e-6 rad) is 1e-4 of its error (0.02 rad); it must not
    # certify, nor set the final steps (it did, and the call raised after one refinement)
    _check_shipped_scene("foucault", 1, 1e-3)


def test_a_certificate_at_the_rounding_of_its_positions_states_the_difference_of_its_runs():
    # the satellite boom 7 000 km from W's origin: the rounding of its positions turns its attitude by ~1e-9 rad through
    # the boom's stiff spring at any step, so no record's order is asymptotic and the certificate accepts them as
    # negligible (below tolerance / 16). Its figure is then the difference of the runs at h and 2h, not Richardson's
    # extrapolation of it (which said 2.9e-11 rad): runs at 2x, 4x and 8x the steps, each as near the truth as the
    # rounding allows, lie at least that far from the run; the estimator's goal (effectivity at least 0.5) bounds the
    # figure from below by half the nearest of them
    scene, initial, run = rd.load_scene("satellite_boom")
    r = rd.simulate(scene, initial, duration=run.duration, tolerance=1e-7, measure="attitude")
    assert r.choice.met and r.choice.certified_error <= 1e-7
    spreads = []
    for k in (2, 4, 8):
        finer = rd.simulate(scene, initial, r.choice.dt / k, steps=k * r.choice.steps, method=r.choice.method,
                            record_every=k, error=False, accuracy_level=None)
        spreads.append(_largest_difference(r, finer, "attitude"))
    assert r.choice.certified_error >= 0.5 * min(spreads)


def test_no_whole_horizon_pilot_runs_at_a_step_a_pilot_found_beyond_the_stability_limit():
    # the satellite boom's stiff spring: rk4's pilot is used at 256 steps over T/32 after its coarser attempts went
    # beyond the stability limit in their runs at 2 dt or 4 dt (rkmk4's pilot, one attempt coarser than that, as well);
    # the plan, capped at the pilot's step, would have its whole-horizon run at 4 dt, whose runs at 8 dt and 16 dt are
    # coarser still: it is not run (it ran, and failed: "the short pilot's prediction kept"), and the call is the
    # pilots and the certified run. rk4 and rkmk4 plan the same steps here, a tie that the pilots' timing breaks
    # (cheapest_plan): either may run.
    scene, initial, run = rd.load_scene("satellite_boom")
    r = rd.simulate(scene, initial, duration=run.duration, tolerance=1e-3, measure="attitude")
    assert r.choice.met and r.choice.method in ("rk4", "rkmk4")
    chosen = [p for p in r.choice.pilots if p["method"] == r.choice.method]
    assert len(chosen) == 1 and chosen[0]["verdict"] == "used" and chosen[0]["dt"] == r.choice.dt
    assert not any(p["horizon"] == run.duration and p["steps"] > 16 for p in r.choice.pilots)
    assert "no run over the whole horizon at 4x the step: its pilot went beyond the stability limit" in r.choice.reason


def test_a_certificate_that_fails_twice_is_refined_again():
    # the cluster over a quarter of its run to 2.5 mm (1e-4 of its size) with the fourth-order splitting: its close
    # encounters keep the first certificates out of the asymptotic regime (observed orders 2 and 2.7 where 4 is
    # expected, on the machine where this was written) until the steps are small enough; the call refines until a
    # certificate holds (it raised after two unreliable ones). The certificate's truth is the shipped-scene test's.
    scene, initial, run = rd.load_scene("cluster")
    r = rd.simulate(scene, initial, duration=run.duration / 4, tolerance=2.5e-3, measure="position",
                    method="splitting_dlm_yoshida4")
    assert r.choice.met and r.choice.certified_error <= 2.5e-3 and r.choice.refinements >= 1


def _check_shipped_scene(name, part, relative):
    # the tolerance: `relative` rad of the attitude where a body turns, else `relative` of the largest distance from
    # W's origin
    scene, initial, run = rd.load_scene(name)
    duration = run.duration / part
    turning = any(not isinstance(s, rd.ParticleState) for s in initial)
    measure = "attitude" if turning else "position"
    if turning:
        tolerance = relative
    else:
        coarse = rd.simulate(scene, initial, duration / 256, steps=256, error=False, accuracy_level=None,
                             controller=run.controller)
        tolerance = relative * float(np.linalg.norm(np.asarray(coarse.p_W), axis=-1).max())
    r = rd.simulate(scene, initial, duration=duration, tolerance=tolerance, measure=measure, controller=run.controller)
    assert r.choice.met and r.choice.certified_error <= tolerance
    # the reference: rk4 at a sixteenth of the chosen step, over the same records, with its own estimate; the
    # triangle inequality bounds the run's true error by |run - reference| - |reference's error|, the latter at most
    # 2x its reliable estimate (effectivity within [0.5, 2], docs/accuracy.md)
    reference = rd.simulate(scene, initial, r.choice.dt / 16, steps=16 * r.choice.steps, method="rk4",
                            record_every=16 * r.choice.steps // (len(r.t) - 1), accuracy_level=None,
                            controller=run.controller)
    assert len(reference.t) == len(r.t) and np.allclose(reference.t, r.t, rtol=1e-12, atol=1e-9 * duration)
    reference_error = 2.0 * float(np.nanmax(getattr(reference.error, measure)))
    assert bool(np.all(reference.error.reliable[::4])) or reference_error <= tolerance / 100
    assert _largest_difference(r, reference, measure) <= tolerance + reference_error


def test_a_short_problem_is_its_run_at_the_fewest_steps():
    # the shipped rocket (a particle losing mass) to 0.4 m: rk4 over its whole minute at 16 steps, the fewest a run
    # takes, is certified within half the tolerance (1.5e-2 m), so the call is that run with its estimate and no other
    # method is piloted
    scene, initial, run = rd.load_scene("rocket")
    r = rd.simulate(scene, initial, duration=run.duration, tolerance=0.4, measure="position")
    tried = [p for p in r.choice.pilots if p["steps"] > 0]
    assert r.choice.met and r.choice.steps == 16 and r.choice.refinements == 0
    assert len(tried) == 1 and tried[0]["horizon"] == run.duration and tried[0]["verdict"] == "used"
    assert all(p["verdict"].startswith("not piloted: ") for p in r.choice.pilots if p["steps"] == 0)
    # against rk4 at a sixteenth of the step, whose error is ~16^-4 the run's (dt^4): 2.3e-7 m
    reference = rd.simulate(scene, initial, r.choice.dt / 16, steps=16 * 16, record_every=16, method="rk4",
                            accuracy_level=None)
    assert _largest_difference(r, reference, "position") <= 0.4


def test_every_run_steps_onto_the_loads_switch_times():
    """The shipped solar array's motor torques switch at 10 s and 20 s of its 30 s: every run to a tolerance takes a
    multiple of 12 steps, so that 4 dt divides 10 s and the runs at dt, 2 dt and 4 dt switch on a step's end alike; the
    certificate is then within the estimator's factor 2 of the true error (against rk4 at a 64th of the step, whose
    own error is 64^4 times smaller). Off that grid (16 steps of 1.875 s, the run at 4 dt switching inside its steps)
    the certificate was 4.2x below the true error."""
    scene, initial, _ = rd.load_scene("solar_array")
    r = rd.simulate(scene, initial, duration=30.0, tolerance=1e-5)
    assert r.choice.met and r.choice.steps % 12 == 0
    fine = rd.simulate(scene, initial, r.choice.dt / 64, steps=64 * r.choice.steps, method="rk4", record_every=64,
                       error=False)
    true = _largest_difference(r, fine, "attitude")
    assert 0.5 * true <= r.choice.certified_error <= 2.0 * true


@pytest.mark.parametrize("first, second", [(10.0123457, 20.0123457), (7.31, 17.77)])
def test_a_switch_off_every_grid_is_certified_within_the_estimators_factor(tmp_path, first, second):
    """The solar array's motor switching at times that no grid of at most 256 steps holds (10.0123457 s: no fraction
    a/b of 30 s with b <= 10 000; 7.31 s: 731/3000, a grid of 12 000 steps): the runs at dt, 2 dt and 4 dt split a step
    at different places, and the certificate takes no record that fails. It is then within the estimator's factor 2 of
    the true error (against rk4 at a 64th of the step, whose own error is 64^4 times smaller); before, the first was
    certified 4x below its true error at 16 steps, and the second took 12 000 steps where 64 meet the tolerance."""
    text = (SCENES / "solar_array.toml").read_text()
    text = text.replace("t_end = 10.0", f"t_end = {first}").replace("t_start = 10.0", f"t_start = {first}")
    path = tmp_path / "solar_array_off_grid.toml"
    path.write_text(text.replace("t_end = 20.0", f"t_end = {second}"))
    scene, initial, _ = rd.load_scene(str(path))
    r = rd.simulate(scene, initial, duration=30.0, tolerance=1e-5)
    assert r.choice.met and r.choice.steps <= 1024
    fine = rd.simulate(scene, initial, r.choice.dt / 64, steps=64 * r.choice.steps, method="rk4", record_every=64,
                       error=False)
    true = _largest_difference(r, fine, "attitude")
    assert true <= 1e-5 and 0.5 * true <= r.choice.certified_error <= 2.0 * true


@pytest.mark.parametrize("seed", range(4))
def test_loads_switching_at_random_times_are_certified_within_the_estimators_factor(seed):
    """A body under two torque windows whose ends are drawn at random (1 to 7 decimals: in these four draws no grid of
    at most 256 steps holds them, two needing 400 and 4 000), run to 1e-3, 1e-5 and 1e-7 rad: each certificate within
    the estimator's factor 2 of the true error (against rk4 at a 64th of the step), so the true error is at most
    twice the tolerance. (Measured: within 1.11x.)"""
    rng = np.random.default_rng(seed)
    t1 = float(np.round(rng.uniform(0.5, 9.5), rng.integers(1, 8)))
    t2 = float(np.round(t1 + rng.uniform(0.3, 9.0), rng.integers(1, 8)))
    loads = [rd.AppliedLoad(torque=[0.0, 0.2, 0.05], t_start=0.0, t_end=t1, frame="body"),
             rd.AppliedLoad(torque=[0.1, -0.2, 0.0], t_start=t1, t_end=t2, frame="body")]
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.ScheduledLoads(body=0, loads=loads)])
    initial = [rd.RigidBodyState(w_B=[0.3, 1.0, 0.2])]
    for tolerance in (1e-3, 1e-5, 1e-7):
        r = rd.simulate(scene, initial, duration=10.0, tolerance=tolerance)
        assert r.choice.met and r.choice.certified_error <= tolerance
        fine = rd.simulate(scene, initial, r.choice.dt / 64, steps=64 * r.choice.steps, method="rk4",
                           record_every=64, error=False, accuracy_level=None)
        true = _largest_difference(r, fine, "attitude")
        assert 0.5 * true <= r.choice.certified_error <= 2.0 * true, (t1, t2, tolerance)


def test_a_scene_whose_loads_hold_a_couple_leaves_out_the_exact_method():
    """'exact' compiles for one body with a ScheduledLoads but refuses a couple when its run meets it: the
    planner's one-step probe of each candidate leaves it out (before: the run raised); asked for by name, its
    refusal is the answer."""
    couple = rd.ScheduledLoads(body=0, loads=[rd.AppliedLoad(torque=[0.0, 0.0, 0.1])])
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[couple])
    initial = [rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])]
    r = rd.simulate(scene, initial, duration=20.0, tolerance=1e-6)
    assert r.choice.met and r.choice.method != "exact"
    assert r.error.attitude.max() <= 1e-6  # the certificate: the reliable estimate within the tolerance
    with pytest.raises(ValueError, match=r"loads\[0\]\.torque: expected zero for method 'exact'"):
        rd.simulate(scene, initial, duration=20.0, tolerance=1e-6, method="exact")
