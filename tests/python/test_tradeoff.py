"""rigiddyn.tradeoff (in the package rigiddyn.work_precision): references, error measures, observed orders,
the recommendation, outputs, CLI."""

import math
import sys
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import rigiddyn
from rigiddyn import AppliedLoad
from rigiddyn.__main__ import main
from rigiddyn.problem import load_problem
from rigiddyn.work_precision import COLUMNS, MEASURES, TradeoffResult, reference_states, tradeoff
from rigiddyn.work_precision.one_body import ProblemCase
from rigiddyn.work_precision.references import richardson_reference
from rigiddyn.work_precision.runs import run

METHODS = {m["name"]: m for m in rigiddyn.methods()}


def short_t_handle(horizon=1.0):
    return load_problem("t_handle").with_horizon(horizon)


def test_exact_reference_for_torque_free_problems_and_refined_otherwise():
    r = tradeoff(short_t_handle(0.2), methods=["rk4"], dts=[0.01], progress=False)
    assert r.rows[0]["reference"] == "exact" and r.rows[0]["reference_error"] == 0.0
    satellite = load_problem("satellite_torque").with_horizon(60.0)
    r = tradeoff(satellite, methods=["rk4"], dts=[5.0], progress=False)
    assert r.rows[0]["reference"].startswith("richardson(")
    # a body-frame force moves the centre of mass with the attitude: no closed form either
    pushed = replace(short_t_handle(0.2), loads=(AppliedLoad(np.array([1.0, 0, 0]), np.zeros(3), "body"),))
    assert pushed.torque_free and not pushed.has_exact_solution
    with pytest.raises(ValueError, match="^problem: expected torque-free"):
        reference_states(pushed, np.array([0.0]))
    # a world-frame force keeps the closed form
    thrown = replace(short_t_handle(0.2), loads=(AppliedLoad(np.array([1.0, 0, 0]), np.zeros(3), "world", 0.0, 0.1),))
    assert thrown.has_exact_solution


def test_exact_reference_matches_closed_forms():
    p = load_problem("projectile")
    t = np.linspace(0.0, p.horizon, 9)
    ref = reference_states(p, t)
    g = np.array([0.0, 0.0, -9.81])
    # the same closed forms on both sides, <= 4 roundings each: 8 eps relative (atol for zero components)
    np.testing.assert_allclose(ref.p_W, p.p_W + np.outer(t, p.v_W) + 0.5 * np.outer(t**2, g), rtol=1e-14, atol=1e-13)
    np.testing.assert_allclose(ref.v_W, p.v_W + np.outer(t, g), rtol=1e-14, atol=1e-13)
    np.testing.assert_allclose(ref.w_B, np.tile(p.w_B, (9, 1)), rtol=1e-13)  # a sphere spins steadily
    # piecewise-constant world force: against rk4 (exact for piecewise-constant acceleration when the
    # switch falls on a step boundary)
    pushed = replace(p, loads=(AppliedLoad(np.array([0.3, -0.2, 0.1]), np.zeros(3), "world", 1.0, 2.5),))
    r = rigiddyn.simulate(pushed.body(), pushed.initial_state(), 0.01, 400, "rk4", loads=list(pushed.loads),
                          gravity=pushed.gravity, record_every=50).body(0)
    ref = reference_states(pushed, np.asarray(r.t))
    # rk4 is exact here: round-off only, <= 4 roundings of |p|, |v| per step, 400 steps: 3.6e-13 relative
    np.testing.assert_allclose(ref.p_W, r.p_W, rtol=1e-12, atol=1e-11)
    np.testing.assert_allclose(ref.v_W, r.v_W, rtol=1e-12, atol=1e-12)


def test_measures_of_the_reference_itself_are_zero():
    p = short_t_handle(0.5)
    r = tradeoff(p, methods=["rkmk4"], dts=[0.001], progress=False)
    row = r.rows[0]
    for k in MEASURES:
        # 500 steps at dt |w| = 0.01 of a 4th-order method: N times the Taylor remainder of a rotation
        # at |w|, (dt |w|)^5/120: 4e-10
        assert row[k] < 1e-9, k
    assert row["quaternion_norm_error"] < 1e-14  # renormalised every step: ~2 eps


def test_richardson_reference_agrees_with_the_exact_solution():
    p = short_t_handle(1.0)
    case = ProblemCase(p)
    steps, every = 50, 5
    runs = [run(case, "rk4", p.horizon / steps, steps, every, timed=False)]
    reference = richardson_reference(case, "rkmk4", 4, p.horizon / steps, steps, every, runs, 10**6)
    ref, estimate = reference.states, reference.estimate
    exact = reference_states(p, ref.t)
    from rigiddyn.work_precision import REFERENCE_TARGET

    true_error = case.measures(ref, exact, np.zeros(1))["max_state_error"]
    # refined until its estimate is below REFERENCE_TARGET x the rk4 run's error (or round-off, 1e-14);
    # the estimate is right to O(dt) relative (x3 covers it), plus round-off
    run_error = case.measures(runs[0].states, exact, np.zeros(1))["max_state_error"]
    assert estimate["max_state_error"] <= max(REFERENCE_TARGET * run_error, 1e-14)
    assert true_error < 3 * estimate["max_state_error"] + 1e-14


@pytest.mark.parametrize("method", sorted(m for m in METHODS if not METHODS[m]["exact_torque_free"]))
def test_observed_order_matches_the_documented_order_on_the_t_handle(method):
    order = METHODS[method]["order"]
    # first-order methods need small steps to reach their asymptotic regime here
    dts = [4e-3, 2e-3, 1e-3] if order >= 2 else [2e-4, 1e-4, 5e-5]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)
        r = tradeoff(short_t_handle(1.0), methods=[method], dts=dts, measure="max_state_error", progress=False)
    observed = [row["observed_order"] for row in r.rows][1:]
    # the next term of the error expansion is O(dt |w|) relative (<= 0.05 here): log2 moves by <= 0.1
    assert observed[-1] == pytest.approx(order, abs=0.25), observed


@pytest.mark.parametrize("method", sorted(m for m in METHODS if METHODS[m]["exact_torque_free"]))
def test_methods_exact_on_torque_free_bodies_have_round_off_error_and_no_observed_order(method):
    """Documented (methods()['exact_torque_free']): `exact` (order 0) and exact_flow_kick (exact without
    couples) reproduce the torque-free T-handle to round-off at every dt, so their error does not fall
    with dt (it grows slowly with the number of steps) and the observed order is not applicable (nan)."""
    r = tradeoff(short_t_handle(1.0), methods=[method], dts=[4e-3, 2e-3, 1e-3], measure="max_state_error",
                 progress=False)
    for row in r.rows:
        # the exact flow to a few ulps per step (free_body.hpp), at worst linear in the steps, times
        # the T-handle's sensitivity over 1 s (e^(lambda t) < 10): 100 eps per step
        assert row["max_state_error"] < 100 * np.finfo(float).eps * row["steps"], row
        assert math.isnan(row["observed_order"])


@pytest.mark.parametrize("method", sorted(m for m in METHODS if METHODS[m]["exact_torque_free"] and
                                          METHODS[m]["order"] > 0))
def test_observed_order_under_a_body_couple(method):
    """Under a couple a flow-kick splitting is no longer exact: its documented order shows (satellite
    with a constant body torque, against the Richardson-refined reference)."""
    satellite = load_problem("satellite_torque").with_horizon(300.0)
    r = tradeoff(satellite, methods=[method], dts=[20.0, 10.0, 5.0], measure="max_state_error", progress=False)
    observed = [row["observed_order"] for row in r.rows][1:]
    # as above: the next term is O(dt |w|) relative, log2 moves by well under 0.25
    assert observed[-1] == pytest.approx(METHODS[method]["order"], abs=0.25), observed


def test_recommendation_picks_the_cheapest_run_meeting_the_tolerance():
    def row(method, dt, cost, error, diverged=False):
        return {"method": method, "dt": dt, "steps": int(1 / dt), "total_time": cost, "time_per_step": cost * dt,
                "total_evaluations": int(cost * 1e6), "reference": "exact", "reference_error": 0.0,
                "diverged": diverged, **{m: error for m in MEASURES}}

    rows = [row("a", 0.1, 1.0, 1e-2), row("a", 0.05, 2.0, 1e-4), row("b", 0.1, 1.5, 1e-5),
            row("b", 0.05, 3.0, 1e-7), row("c", 0.2, 0.1, 0.0, diverged=True)]
    result = TradeoffResult("synthetic", 1.0, "final_attitude_error", 1e-3, rows)
    rec = result.recommendation
    assert rec.met and (rec.row["method"], rec.row["dt"]) == ("b", 0.1)  # 1.5 < 2.0; the diverged one excluded
    assert "b with dt = 0.1" in str(rec)
    tight = result.recommend(1e-6)
    assert (tight.row["method"], tight.row["dt"]) == ("b", 0.05)
    none = result.recommend(1e-9)
    assert not none.met and none.best["method"] == "b" and "none meets" in str(none) and "best is b" in str(none)
    with pytest.raises(ValueError, match="^measure: expected one of"):
        result.recommend(1e-3, measure="wobble")


def test_recommendation_on_a_real_sweep_by_evaluations():
    # on the T-handle at tolerance 1e-3: rk4 at dt = 0.02 (800 evaluations) meets it, every first-order
    # run is far off and rk4 at 0.04 is not within it
    r = tradeoff(short_t_handle(1.0), methods=["explicit_euler", "rk4"], dts=[0.04, 0.02, 0.01], tolerance=1e-4,
                 measure="max_attitude_error", cost="evaluations", progress=False)
    meeting = [x for x in r.rows if x["max_attitude_error"] <= 1e-4]
    cheapest = min(meeting, key=lambda x: x["total_evaluations"])
    assert r.recommendation.row is cheapest and cheapest["method"] == "rk4"


def same_row(a, b):
    """Rows equal key by key, nan equal to nan."""
    return a.keys() == b.keys() and all(
        (isinstance(a[k], float) and math.isnan(a[k]) and math.isnan(b[k])) or a[k] == b[k] for k in a)


def test_csv_and_json_round_trip(tmp_path):
    with pytest.warns(rigiddyn.StabilityWarning):
        r = tradeoff(load_problem("fast_top").with_horizon(0.05), methods=["explicit_euler", "rk4"],
                     dts=[0.004, 0.001], tolerance=1e-3, progress=False)
    assert any(row["diverged"] for row in r.rows) or any(row["stability"] for row in r.rows)
    r.to_csv(tmp_path / "t.csv")
    r.to_json(tmp_path / "t.json")
    for back in (TradeoffResult.read_csv(tmp_path / "t.csv"), TradeoffResult.read_json(tmp_path / "t.json")):
        assert len(back.rows) == len(r.rows)
        for a, b in zip(r.rows, back.rows):
            assert a.keys() == b.keys()
            for k in a:
                if isinstance(a[k], float) and math.isnan(a[k]):
                    assert math.isnan(b[k])
                else:
                    assert a[k] == b[k], k
    back = TradeoffResult.read_json(r.to_json())
    assert back.tolerance == 1e-3
    assert same_row(back.recommendation.row, r.recommendation.row)


def test_plot_files_are_written(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    r = tradeoff(short_t_handle(0.5), methods=["rk4", "rkmk4"], dts=[0.02, 0.01], tolerance=1e-5, progress=False)
    written = r.plot(tmp_path / "wp")
    assert [p.name for p in written] == ["wp.png", "wp.svg"]
    assert all(p.stat().st_size > 1000 for p in written)
    assert (tmp_path / "wp.png").read_bytes()[:4] == b"\x89PNG"


def test_table_estimate_and_progress(monkeypatch, capsys):
    """progress=True: the estimated cost first (a timed probe), then a bar on a terminal only."""
    r = tradeoff(short_t_handle(0.2), methods=["rk4"], dts=[0.02, 0.01], tolerance=1.0, progress=True)
    err = capsys.readouterr().err
    # the probe's figures and the run's size: 10 + 20 steps, each run once
    flat = " ".join(err.split())  # wrapped at 100 columns
    assert err.startswith("tradeoff: ") and "about 30 steps, estimated" in flat and "ns/step: rk4" in flat
    assert "%" not in err  # stderr is not a terminal here: no bar
    text = r.to_table()
    assert "rk4" in text and "ns/step" in text
    assert any(line.startswith("recommendation: rk4") for line in text.splitlines())
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    tradeoff(short_t_handle(0.2), methods=["rk4"], dts=[0.02, 0.01], progress=True)
    assert "100%" in capsys.readouterr().err  # tqdm or the plain bar, at the end


def test_plain_progress_bar_without_tqdm(monkeypatch, capsys):
    import builtins

    real_import = builtins.__import__

    def no_tqdm(name, *args, **kwargs):
        if name == "tqdm":
            raise ImportError("no tqdm")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_tqdm)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    tradeoff(short_t_handle(0.2), methods=["rk4"], dts=[0.02, 0.01], progress=True)
    err = capsys.readouterr().err
    # the bar counts steps: 10 + 20 of the runs (timed runs repeat: >= 30 in all)
    assert "tradeoff [########################] 100%" in err and " steps, " in err


@pytest.mark.parametrize("argument, value, error", [
    ("methods", ["rk5"], ValueError), ("methods", [], ValueError), ("methods", "rk4", TypeError),
    ("methods", [None], TypeError), ("methods", ["rk4", "rk4"], ValueError), ("methods", 4, TypeError),
    ("dts", [0.0], ValueError), ("dts", [], ValueError), ("dts", ["0.01"], TypeError), ("dts", 0.01, TypeError),
    ("dts", [math.nan], ValueError), ("dts", [True], TypeError),
    ("horizon", -1.0, ValueError), ("horizon", math.inf, ValueError), ("horizon", "1", TypeError),
    ("tolerance", -1.0, ValueError), ("tolerance", math.nan, ValueError), ("tolerance", "1e-6", TypeError),
    ("measure", "speed", ValueError), ("measure", 3, TypeError),
    ("progress", "yes", TypeError), ("progress", 1, TypeError),
    ("cost", "money", ValueError), ("cost", None, TypeError),
    ("samples", 0, ValueError), ("samples", -3, ValueError), ("samples", 2.5, TypeError), ("samples", True, TypeError),
    ("max_reference_steps", 0, ValueError), ("max_reference_steps", 1e6, TypeError),
    ("problem", 5, TypeError), ("problem", None, TypeError),
])
def test_argument_errors_name_the_argument(argument, value, error):
    kwargs = {"problem": short_t_handle(0.2), "methods": ["rk4"], "dts": [0.01], "progress": False, argument: value}
    with pytest.raises(error, match=f"^{argument}: expected"):
        tradeoff(**kwargs)


def test_a_run_too_long_to_count_its_steps_is_refused_naming_its_cause():
    # horizon / dt beyond 2^53 steps (float overflow included): the defaults' steps are due to horizon
    with pytest.raises(ValueError, match=r"^horizon: expected at most 9.01e\+15 steps per run"):
        tradeoff("fast_top", horizon=1e306, progress=False)
    with pytest.raises(ValueError, match=r"^dts: expected at most 9.01e\+15 steps per run"):
        tradeoff("fast_top", horizon=1e3, dts=[1e-300], progress=False)


def test_an_unknown_problem_name_is_refused_naming_problem():
    with pytest.raises(ValueError, match="^problem: expected a .toml path or one of the examples"):
        tradeoff("no_such_problem", progress=False)


def _row(**changes):
    row = {c: 0.0 for c in COLUMNS} | {"method": "rk4", "steps": 10, "diverged": False, "reference": "exact",
                                         "reference_check": "", "order_note": "", "stability": "", "order": 4,
                                         "evaluations_per_step": 4, "total_evaluations": 40}
    return row | changes


@pytest.mark.parametrize("kwargs, error, match", [
    ({"rows": [{"method": "rk4"}]}, ValueError, "^rows: expected .* got row 0 without dt, steps"),
    ({"rows": [_row(speed=1.0)]}, ValueError, "^rows: expected .* got row 0 with 'speed'"),
    ({"rows": ["rk4"]}, TypeError, "^rows: expected .* got 'rk4' at index 0"),
    ({"rows": {"method": "rk4"}}, TypeError, "^rows: expected"),
    ({"horizon": -1.0}, ValueError, "^horizon: expected"),
    ({"tolerance": 0.0}, ValueError, "^tolerance: expected"),
    ({"cost": "money"}, ValueError, "^cost: expected one of time, evaluations"),
    ({"recommendation": "rk4"}, TypeError, "^recommendation: expected None or a Recommendation"),
])
def test_result_arguments_are_checked(kwargs, error, match):
    with pytest.raises(error, match=match):
        TradeoffResult(**({"problem": "p", "horizon": 1.0, "measure": "final_attitude_error", "rows": [_row()]} | kwargs))


def test_read_csv_and_read_json_refuse_what_is_not_their_output(tmp_path):
    r = TradeoffResult("p", math.nan, "final_attitude_error", 1e-3, [_row()])
    assert TradeoffResult.read_csv(r.to_csv()).rows[0]["method"] == "rk4"  # the unknown horizon (nan) is kept
    with pytest.raises(ValueError, match="^path_or_text: expected a CSV file or text written by to_csv .* got text "
                                         "beginning 'a,b"):
        TradeoffResult.read_csv("a,b\n1,2\n")
    for good, bad in ((",10,", ",ten,"), ("False", "maybe")):  # steps, diverged
        (tmp_path / "t.csv").write_text(r.to_csv().replace(good, bad, 1))
        with pytest.raises(ValueError, match="^path_or_text: expected a CSV file or text written by to_csv, got a "
                                             "value that does not parse"):
            TradeoffResult.read_csv(tmp_path / "t.csv")
    with pytest.raises(ValueError, match="^path_or_text: expected an existing file"):
        TradeoffResult.read_csv(tmp_path / "missing.csv")
    with pytest.raises(ValueError, match="^path_or_text: expected a JSON file or text written by to_json"):
        TradeoffResult.read_json("{not json")
    with pytest.raises(ValueError, match="^path_or_text: expected a JSON file or text written by to_json"):
        TradeoffResult.read_json('{"problem": "p"}')


def test_plot_refuses_an_unknown_format(tmp_path):
    pytest.importorskip("matplotlib")
    r = TradeoffResult("p", 1.0, "final_attitude_error", None, [_row()])
    with pytest.raises(ValueError, match="^formats: expected a list of names from .*png.* got 'doc'"):
        r.plot(tmp_path / "wp", formats=["png", "doc"])
    with pytest.raises(TypeError, match="^path: expected a file path"):
        r.plot(None)


def test_dt_is_adjusted_to_end_on_the_horizon():
    r = tradeoff(short_t_handle(1.0), methods=["rk4"], dts=[0.003], progress=False)
    assert r.rows[0]["steps"] == 333 and r.rows[0]["dt"] == pytest.approx(1.0 / 333)


def test_cli_prints_the_table_and_writes_the_files(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    code = main(["tradeoff", "t_handle", "--methods", "rk4,rkmk4", "--dts", "0.02,0.01", "--horizon", "0.5",
                 "--tolerance", "1e-4", "--measure", "max_attitude_error", "--out", str(tmp_path), "--no-progress"])
    out = capsys.readouterr().out
    assert code == 0 and "recommendation:" in out and "rkmk4" in out
    assert {p.name for p in tmp_path.iterdir()} == {"tradeoff.csv", "tradeoff.json", "tradeoff.png", "tradeoff.svg"}
    assert main(["tradeoff", "t_handle", "--measure", "speed", "--no-progress"]) == 2
    assert "measure: expected one of" in capsys.readouterr().err


def test_default_methods_are_those_that_can_run_the_problem():
    """`exact` (order 0) is the closed-form torque-free flow: by default it is swept on torque-free
    problems only; under a couple every other method runs (exact_flow_kick included); asked for
    explicitly, it is refused with the reason."""
    satellite = load_problem("satellite_torque").with_horizon(40.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)
        r = tradeoff(satellite, dts=[10.0], progress=False)
    assert set(r.methods()) == set(METHODS) - {"exact"}
    assert "exact" in tradeoff(short_t_handle(0.1), dts=[0.01], progress=False).methods()
    with pytest.raises(ValueError, match="torque-free"):
        tradeoff(satellite, methods=["exact"], dts=[10.0], progress=False)


# ------------------------------------------------------------------ loads switching inside steps
SWITCHING = Path(__file__).resolve().parent / "problems" / "satellite_switching_torque.toml"
SWITCH_TIMES = (10.0, 200.0)  # [s], the file's t_start and t_end


def switching_dts(ks):
    """300 s / (877 2^k): both switch times fall strictly inside a step (10 / dt = 877 2^k / 30 and
    200 / dt = 877 2^k / 1.5 are never integers: 877 is prime)."""
    dts = [300.0 / (877 * 2**k) for k in ks]
    for dt in dts:
        for s in SWITCH_TIMES:
            assert abs(s / dt - round(s / dt)) > 0.05, (s, dt)
    return dts


@pytest.fixture(scope="module")
def switching_sweeps():
    """Every method on the switching problem: 4th and 2nd order at dt = 0.34 .. 0.043 s, 1st order at
    0.043 .. 0.0053 s (their asymptotic range begins later); method -> rows."""
    problem = load_problem(SWITCHING)
    rows = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)
        for ks, orders in ((range(0, 4), (2, 4)), (range(3, 7), (1,))):
            methods = [m for m in METHODS if METHODS[m]["order"] in orders]
            r = tradeoff(problem, methods=methods, dts=switching_dts(ks), measure="max_state_error", progress=False)
            for method in methods:
                rows[method] = [row for row in r.rows if row["method"] == method]
    return rows


@pytest.mark.parametrize("method", sorted(m for m in METHODS if METHODS[m]["order"] > 0))
def test_every_method_keeps_its_order_with_a_torque_switching_inside_steps(switching_sweeps, method):
    """simulate splits a step at a switch time of the loads, so each method keeps its
    order whatever the step grid (before, the loads held over a step made every method first order,
    erratically); the table: python -m rigiddyn tradeoff tests/python/problems/satellite_switching_torque.toml"""
    rows = switching_sweeps[method]
    assert all(row["reference"] == "richardson(rkmk4)" for row in rows), [row["reference_check"] for row in rows]
    slopes = [row["observed_order"] for row in rows[1:]]
    assert all(math.isfinite(p) for p in slopes), [(row["observed_order"], row["order_note"]) for row in rows]
    # in the asymptotic range the slope's deviation from the order shrinks like dt (the next term of
    # the error expansion is O(dt) relative): the last deviation is about the last change of slope
    # (2x margin); the reference's error moves each slope by at most log2((1 + d0)(1 + d1)), d = ref/error
    contamination = sum(math.log2(1 + row["reference_error"] / row["max_state_error"]) for row in rows[-2:])
    bound = 2 * abs(slopes[-1] - slopes[-2]) + contamination + 0.01
    assert abs(slopes[-1] - METHODS[method]["order"]) <= bound, (slopes, bound)


def late_switching_reference(module):
    """The sweep's richardson_reference with the loads switched on 0.05 s late: consistent with itself (a
    tiny Richardson estimate), wrong by ~1e-3 rad, as a zero-order hold on a grid that misses t_start is."""
    real = module.richardson_reference

    def late(case, *args, **kwargs):
        shifted = tuple(AppliedLoad(load.force, load.torque, load.frame, load.t_start + 0.05, load.t_end)
                        for load in case.problem.loads)
        return real(replace(case, problem=replace(case.problem, loads=shifted)), *args, **kwargs)

    return late


@pytest.mark.parametrize("checker", ["dop853", "other family"])
def test_reference_check_catches_a_broken_reference(monkeypatch, checker):
    module = sys.modules["rigiddyn.work_precision.sweep"]
    problem, dts = load_problem(SWITCHING), switching_dts(range(0, 3))
    if checker == "other family":  # no SciPy (or a horizon too long for DOP853)
        monkeypatch.setattr(ProblemCase, "independent", lambda self, times: None)
    good = tradeoff(problem, methods=["rkmk4"], dts=dts, measure="max_state_error", tolerance=1e-6, progress=False)
    name = "dop853" if checker == "dop853" else "splitting_dlm_yoshida4"
    assert all(row["reference"] == "richardson(rkmk4)" and row["reference_check"].startswith(name)
               for row in good.rows), [row["reference_check"] for row in good.rows]
    assert good.recommendation.met
    monkeypatch.setattr(module, "richardson_reference", late_switching_reference(module))
    broken = tradeoff(problem, methods=["rkmk4"], dts=dts, measure="max_state_error", tolerance=1e-6, progress=False)
    for g, b in zip(good.rows, broken.rows):
        assert b["reference"] == "unreliable: richardson(rkmk4)" and "differs by" in b["reference_check"]
        # what the broken reference is really off by: the good run's error against it, less the run's own
        # error and the good reference's (both < 1e-6 here, against a disagreement of ~1e-3)
        real = b["max_state_error"] - g["max_state_error"] - g["reference_error"]
        assert real > 1e-4 and b["reference_error"] >= 0.5 * real, (b["reference_error"], real)
        assert math.isnan(b["observed_order"]) and b["order_note"] in ("coarsest step", "error within 10x the reference's")
    assert not broken.recommendation.met  # nothing can be certified below the reference's error
    assert "its reference is unreliable" in str(broken.recommendation)


def test_dop853_reference_agrees_with_closed_forms_within_its_error_estimate():
    """The independent reference against the exact solution: a tumbling T-handle pushed by a world-fixed
    force from 0.3 s to 0.7 s (DOP853 restarted at both switch times). Its error estimate is the
    difference from a run at 10x rtol, whose error is ~10x larger (DOP853's error is proportional to
    its tolerance), so it bounds the error of the run at rtol."""
    p = replace(short_t_handle(2.0), loads=(AppliedLoad(np.array([0.3, -0.1, 0.2]), np.zeros(3), "world", 0.3, 0.7),))
    case = ProblemCase(p)
    times = np.linspace(0.0, p.horizon, 401)
    independent = case.independent(times)(times)
    true = case.measures(independent.states, reference_states(p, times), np.zeros(1))
    for k in ("max_attitude_error", "max_momentum_error", "max_position_error", "max_velocity_error"):
        assert true[k] <= independent.error[k] + 1e-15, (k, true[k], independent.error[k])
    assert true["max_state_error"] < 1e-10  # rtol 1e-13 over ~20 rad of tumbling


def test_a_body_frame_force_costs_the_torque_free_methods_their_exactness():
    """A torque-free body pushed by a force fixed in B: the exact free flow keeps the rotation exact, but the
    kick of the turning force is a second-order step, so exact_flow_kick gets an observed order (not "exact
    on this problem"), and the closed form 'exact', which the core refuses such a force, is no default."""
    pushed = replace(short_t_handle(1.0), loads=(AppliedLoad(np.array([1.0, 0, 0]), np.zeros(3), "body"),))
    r = tradeoff(pushed, methods=["exact_flow_kick"], dts=[0.01, 0.005, 0.0025], measure="max_position_error",
                 progress=False)
    assert all(row["order_note"] != "exact on this problem" for row in r.rows)
    # a second-order method in its asymptotic range: slope 2 + O(dt) (0.01 here), and the reference's error
    # (REFERENCE_TARGET = 1 % of the smallest error) moves a slope by at most 2 log2(1.01) = 0.03
    assert abs(r.rows[-1]["observed_order"] - 2) < 0.1, [row["observed_order"] for row in r.rows]
    default = tradeoff(pushed, dts=[0.05], horizon=0.1, progress=False)
    assert "exact" not in default.methods() and "exact_flow_kick" in default.methods()


def test_order_notes_say_why_an_order_is_blank():
    r = tradeoff(short_t_handle(1.0), methods=["rk4", "exact"], dts=[4e-3, 2e-3], measure="max_state_error",
                 progress=False)
    notes = {(row["method"], row["steps"]): row["order_note"] for row in r.rows}
    assert notes[("rk4", 250)] == "coarsest step" and notes[("rk4", 500)].startswith("unconfirmed: slope 4")
    assert notes[("exact", 500)] == "exact on this problem"
    assert all(math.isnan(row["observed_order"]) for row in r.rows)
    header = r.to_table().splitlines()[1].split()
    assert "order" in header and "note" in header
