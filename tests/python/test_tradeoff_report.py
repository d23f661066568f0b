"""The tradeoff report: the module/function names, the terminal table, CSV/JSON,
warnings, --help, the Pareto front, the closed-form method, the plot, the stability warning on a
sphere, a recommendation that timing noise does not flip, and --out checked before the sweep."""

import importlib
import importlib.util
import itertools
import json
import math
import warnings
from dataclasses import replace

import numpy as np
import pytest
import rigiddyn
from rigiddyn.__main__ import main
from rigiddyn.problem import load_problem
from rigiddyn.stability import stability_message
from rigiddyn.work_precision import COLUMNS, MEASURES, TradeoffResult, cheapest, pareto_front, timing_noise

METHODS = {m["name"]: m for m in rigiddyn.methods()}


def row(method, dt, **changes):
    """A synthetic row with every column (steps from a 1 s horizon)."""
    info = METHODS.get(method, {"order": 4, "evaluations": 4})
    steps = max(1, round(1.0 / dt))
    out = {c: 0.0 for c in COLUMNS} | {
        "method": method, "dt": dt, "steps": steps, "order": info["order"],
        "evaluations_per_step": info["evaluations"], "total_evaluations": info["evaluations"] * steps,
        "time_per_step": 1e-7, "total_time": 1e-7 * steps, "time_noise": 0.01, "diverged": False,
        "observed_order": math.nan, "order_note": "", "reference": "exact", "reference_check": "", "stability": ""}
    return out | changes


# ------------------------------------------------------------------ names


def test_the_module_is_not_shadowed_by_the_function():
    module = importlib.import_module("rigiddyn.work_precision")
    import rigiddyn.work_precision as m

    assert m is module and m.tradeoff is rigiddyn.tradeoff and callable(rigiddyn.tradeoff)
    assert m.TradeoffResult is rigiddyn.TradeoffResult
    assert importlib.util.find_spec("rigiddyn.tradeoff") is None  # no module left under the function's name


# ------------------------------------------------------------------ the terminal table


def worst_case_result(tolerance):
    """Every core method at three steps, with the widest cells: long notes, a diverged run, a run beyond
    its stability limit, an unreliable reference, six-digit step counts and large times."""
    rows = []
    for method in METHODS:
        for k, dt in enumerate((1e-3, 5e-4, 1.25e-5)):
            rows.append(row(method, dt, time_per_step=123456.0e-9, total_time=12345.6,
                            final_attitude_error=1.23456e-300, observed_order=-12.3456 if k else math.nan,
                            order_note="not asymptotic: slope -12, neighbouring 4.1, 3.9" if k else "coarsest step",
                            stability="x beyond its stability limit for this spin: dt*rho = 3e+05" if k == 1 else "",
                            reference="unreliable: richardson(rkmk4)" if k == 2 else "richardson(rkmk4)",
                            reference_check="dop853(rtol=1e-13) differs by 1e-3 where the Richardson estimate is 1e-9",
                            diverged=k == 2 and method == "explicit_euler"))
    return TradeoffResult("a problem with a rather long name, as users write them", 12345.0,
                          "final_attitude_error", tolerance, rows)


@pytest.mark.parametrize("tolerance", [1e-6, None])
def test_the_table_fits_100_columns_with_the_longest_method_names(tolerance):
    text = worst_case_result(tolerance).to_table()
    longest = max(METHODS, key=len)
    assert longest in text
    assert max(len(line) for line in text.splitlines()) <= 100, max(text.splitlines(), key=len)
    header = text.splitlines()[text.splitlines().index(next(l for l in text.splitlines() if l.startswith("method")))]
    for name in ("method", "dt [s]", "steps", "ns/step", "error [rad]", "order", "note"):
        assert name in header


def test_the_table_at_other_widths_keeps_its_width():
    result = worst_case_result(1e-6)
    assert max(len(line) for line in result.to_table(140).splitlines()) <= 140
    short = TradeoffResult("p", 1.0, "final_attitude_error", 1e-6, [r | {"method": "rk4"} for r in result.rows[:3]])
    assert max(len(line) for line in short.to_table(70).splitlines()) <= 70
    with pytest.raises(ValueError, match="^width: expected an integer >= 60"):
        result.to_table(20)
    with pytest.raises(TypeError, match="^width: expected an integer"):
        result.to_table(100.0)


def test_a_closed_form_method_is_one_row_without_dt():
    rows = [row("rk4", dt, max_attitude_error=dt**4) for dt in (0.1, 0.05)] + \
           [row("exact", dt, max_attitude_error=0.0, total_evaluations=0) for dt in (0.1, 0.05)]
    text = TradeoffResult("p", 1.0, "max_attitude_error", None, rows).to_table()
    exact_lines = [line for line in text.splitlines() if line.startswith("exact ")]
    assert len(exact_lines) == 1 and "closed form" in exact_lines[0]
    assert "0.05" not in exact_lines[0] and " 20 " not in exact_lines[0]  # no dt, no steps


def test_a_real_sweep_marks_its_rows_and_explains_the_marks():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)
        result = rigiddyn.tradeoff(load_problem("fast_top").with_horizon(0.05), methods=["explicit_euler", "rk4"],
                                   dts=[0.004, 0.002, 0.001], tolerance=1e-3, progress=False)
    text = result.to_table()
    assert max(len(line) for line in text.splitlines()) <= 100
    assert "unstable" in text and "unstable = dt beyond the method's stability limit" in text


# ------------------------------------------------------------------ CSV / JSON


def strict_json(text):
    """json.loads refusing NaN / Infinity (what allow_nan=False writes is valid JSON)."""
    def refuse(name):
        raise ValueError(f"not JSON: {name}")

    return json.loads(text, parse_constant=refuse)


def test_json_has_numbers_and_null_never_nan_strings(tmp_path):
    rows = [row("rk4", 0.1, observed_order=math.nan, time_noise=math.nan),
            row("explicit_euler", 0.1, diverged=True, **{m: math.inf for m in MEASURES})]
    result = TradeoffResult("p", math.nan, "final_attitude_error", 1e-3, rows)
    text = result.to_json(tmp_path / "t.json")
    data = strict_json(text)
    json.dumps(data, allow_nan=False)  # round-trips through a strict encoder
    assert '"nan"' not in text and '"inf"' not in text and "NaN" not in text and "Infinity" not in text
    assert data["horizon"] is None and data["rows"][0]["observed_order"] is None
    assert data["rows"][0]["dt"] == 0.1 and data["rows"][1]["final_attitude_error"] is None
    back = TradeoffResult.read_json(tmp_path / "t.json")
    assert math.isnan(back.horizon) and math.isnan(back.rows[0]["observed_order"])
    assert back.rows[1]["final_attitude_error"] == math.inf  # a diverged run's error
    assert back.rows[0]["final_attitude_error"] == 0.0


def test_the_cli_writes_strict_json_and_the_full_csv(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    code = main(["tradeoff", "t_handle", "--methods", "rk4,exact", "--dts", "0.02,0.01", "--horizon", "0.2",
                 "--out", str(tmp_path), "--no-progress"])
    assert code == 0
    data = strict_json((tmp_path / "tradeoff.json").read_text())
    assert set(data["rows"][0]) == set(COLUMNS)
    assert (tmp_path / "tradeoff.csv").read_text().splitlines()[0].split(",") == list(COLUMNS)


# ------------------------------------------------------------------ warnings


def test_one_stability_warning_line_per_method():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = rigiddyn.tradeoff(load_problem("fast_top").with_horizon(0.05),
                                   methods=["explicit_euler", "semi_implicit_euler", "rk4"],
                                   dts=[0.008, 0.004, 0.002, 0.001], progress=False)
    stability = [w for w in caught if issubclass(w.category, rigiddyn.StabilityWarning)]
    assert len(stability) == 1
    flagged = list(dict.fromkeys(r["method"] for r in result.rows if r["stability"]))
    lines = str(stability[0].message).splitlines()
    assert len(lines) == 1 + len(flagged) and len(flagged) >= 2
    for method in flagged:
        assert sum(line.startswith(f"  {method} at dt = ") for line in lines) == 1


def test_no_stability_warning_on_a_sphere():
    """A sphere has no gyroscopic term ((I w) x w = 0): nothing can destabilise w, and every method's
    attitude update (q (x) P, renormalised) is an isometry, so no step is beyond a limit. Before, the
    projectile (a solid sphere at 151 rad/s) warned for 5 methods: the kinematic modes +-i|w|/2 were
    counted and the documented dt |w| limits of the gyroscopic methods applied."""
    problem = load_problem("projectile")
    with warnings.catch_warnings():
        warnings.simplefilter("error", rigiddyn.StabilityWarning)
        result = rigiddyn.tradeoff(problem, progress=False)
    assert not any(r["stability"] for r in result.rows)
    for method in METHODS:
        for dt in (1e-3, 0.1, 10.0):  # up to dt |w| = 1500
            assert stability_message(method, dt, 100, problem.inertia_com, problem.w_B) is None
            assert stability_message(method, dt, 100, np.eye(3) * 2.5, np.array([0.0, 3.0, 400.0])) is None


def test_a_sphere_keeps_perturbations_of_the_attitude_at_any_step():
    """Why the kinematic modes do not count: rk4 and explicit Euler at dt |w| = 8 (far beyond the old
    limit 2 sqrt(2) on |w|/2) keep the angle between two nearby attitudes of a spinning sphere, as the
    renormalised update q (x) P does (an isometry of unit quaternions)."""
    body = rigiddyn.RigidBody(1.0, np.diag([0.4, 0.4, 0.4]))
    w_B = np.array([3.0, -4.0, 12.0])  # |w| = 13 rad/s
    q_b = np.array([np.sin(5e-4), 0.0, 0.0, np.cos(5e-4)])  # 1e-3 rad about x
    for method in ("rk4", "explicit_euler"):
        a = rigiddyn.simulate(body, rigiddyn.RigidBodyState(w_B=w_B), 8.0 / 13.0, 200, method)
        b = rigiddyn.simulate(body, rigiddyn.RigidBodyState(q_WB=q_b, w_B=w_B), 8.0 / 13.0, 200, method)
        qa, qb = np.asarray(a.body(0).q_WB), np.asarray(b.body(0).q_WB)
        # the angle of qa^-1 qb (rows x, y, z, w) from its vector part: well conditioned at small angles
        vec = qa[:, 3:] * qb[:, :3] - qb[:, 3:] * qa[:, :3] - np.cross(qa[:, :3], qb[:, :3])
        scalar = qa[:, 3] * qb[:, 3] + np.sum(qa[:, :3] * qb[:, :3], axis=1)
        angle = 2 * np.arctan2(np.linalg.norm(vec, axis=1), np.abs(scalar))
        # qa^-1 qb is conjugated by P every step, its angle kept up to round-off: <= 2 eps per step and
        # run (a product, a normalisation), worst case linear, 2 x 200 x 2 eps = 1.8e-13 on the vector
        # part, against its size sin(5e-4): 3.6e-10 relative (a growing mode would change it by O(1))
        np.testing.assert_allclose(angle, 1e-3, rtol=4e-10)


# ------------------------------------------------------------------ the recommendation and timing noise


def test_timing_noise_is_a_quantile_of_the_runs_gaps():
    rows = [row("rk4", 0.1, time_noise=x) for x in (0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09, 0.5)]
    assert timing_noise(rows) == pytest.approx(np.quantile([r["time_noise"] for r in rows], 0.9))
    assert timing_noise([row("rk4", 0.1, time_noise=math.nan)]) == 0.0


def test_the_cheapest_run_does_not_flip_with_timing_noise():
    """Synthetic timings: A and B take the same true time, B with fewer derivative evaluations; each
    measured time is off by a factor in [1 - noise, 1 + noise]. Their ranges t (1 +- noise) then always
    overlap, so B wins every time. C, slower beyond the noise, never does, and a run faster beyond the
    noise wins whatever its evaluations."""
    noise = 0.05
    rng = np.random.default_rng(7)
    true = {"A": (1.0e-5, 800), "B": (1.0e-5, 0), "C": (1.3e-5, 0)}
    picks = set()
    for _ in range(2000):
        rows = [row("rk4", 0.02, total_time=t * rng.uniform(1 - noise, 1 + noise), total_evaluations=e) | {"name": n}
                for n, (t, e) in true.items()]
        picks.add(cheapest(rows, "time", noise)["name"])
    assert picks == {"B"}
    fast = [row("rk4", 0.02, total_time=1.0e-5, total_evaluations=800), row("exact", 0.02, total_time=1.3e-5,
                                                                             total_evaluations=0)]
    assert cheapest(fast, "time", noise)["method"] == "rk4"  # 30 % slower: beyond 2 x 5 %
    assert cheapest(fast, "time", 0.0)["method"] == "rk4" and cheapest(fast, "evaluations")["method"] == "exact"
    with pytest.raises(ValueError, match="^noise: expected"):
        cheapest(fast, "time", -0.1)


def test_the_recommendation_uses_the_measured_noise_and_says_its_rule():
    rows = [row("rk4", 0.02, total_time=1.00e-5, total_evaluations=800, time_noise=0.04),
            row("splitting_dlm", 0.02, total_time=1.05e-5, total_evaluations=200, time_noise=0.04)]
    result = TradeoffResult("p", 1.0, "final_attitude_error", 1e-3, rows)
    assert result.recommendation.row["method"] == "splitting_dlm"  # 5 % apart, noise 4 %: equal, fewer evaluations
    text = str(result.recommendation)
    assert "times equal within the timing noise (4 %" in text and "fewer derivative evaluations" in text
    quiet = TradeoffResult("p", 1.0, "final_attitude_error", 1e-3, [r | {"time_noise": 0.01} for r in rows])
    assert quiet.recommendation.row["method"] == "rk4"  # noise 1 %: 5 % is a real difference


# ------------------------------------------------------------------ Pareto front


def dominated(points, i):
    return any(c <= points[i][0] and e <= points[i][1] and (c, e) != points[i] for c, e in points)


def test_pareto_front_of_a_synthetic_set():
    points = [(1.0, 5.0), (2.0, 3.0), (2.0, 4.0), (3.0, 3.0), (4.0, 1.0), (4.0, 1.0), (5.0, 0.5), (0.5, 9.0)]
    assert pareto_front(points) == [7, 0, 1, 4, 5, 6]  # by cost; (2, 4) and (3, 3) dominated; equal points kept
    rng = np.random.default_rng(3)
    for _ in range(50):  # against the definition, with ties on a coarse grid
        pts = [tuple(map(float, p)) for p in rng.integers(0, 6, size=(rng.integers(1, 15), 2))]
        assert sorted(pareto_front(pts)) == [i for i in range(len(pts)) if not dominated(pts, i)]


def test_without_a_tolerance_the_report_says_so_and_shows_the_pareto_front():
    problem = replace(load_problem("t_handle").with_horizon(0.2), tradeoff={})
    result = rigiddyn.tradeoff(problem, methods=["explicit_euler", "rk4", "exact"], dts=[0.02, 0.01], progress=False)
    assert result.tolerance is None and result.recommendation is None
    text = result.to_table()
    assert "no tolerance given" in text and "Pareto front" in text
    front = result.pareto()
    points = [(r["total_time"], r[result.measure]) for r in result.rows if not r["diverged"]]
    assert len(front) == len(pareto_front(points)) >= 1
    for r in front:
        assert f"  {r['method']}" in text.split("Pareto front", 1)[1]


# ------------------------------------------------------------------ the plot


def test_the_plot_keeps_its_legend_off_the_data_and_draws_the_closed_form(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figures = []
    close = plt.close
    monkeypatch.setattr(plt, "close", lambda fig: figures.append(fig))  # keep the figure to inspect it
    result = rigiddyn.tradeoff(load_problem("t_handle").with_horizon(0.2), methods=["rk4", "exact"],
                               dts=[0.02, 0.01], tolerance=1e-3, progress=False)
    result.plot(tmp_path / "wp", formats=["png"])
    (fig,) = figures
    try:  # closed at the end, so that no later test sees this figure
        renderer = fig.canvas.get_renderer()
        axes = fig.axes
        legends = [ax.get_legend() for ax in axes if ax.get_legend() is not None]
        assert len(legends) == 1
        box = legends[0].get_window_extent(renderer)
        for ax in axes:
            assert not box.overlaps(ax.get_window_extent(renderer))
            assert ax.get_ylabel() == "max_attitude_error [rad]"
            closed = [line for line in ax.get_lines() if line.get_label().startswith("exact (closed form)")]
            assert closed, "the closed form is drawn"
            for line in closed:  # error 0: drawn on the floor of the log axis (its bottom edge), within its width
                xy = line.get_transform().transform(np.column_stack([line.get_xdata(), line.get_ydata()]))
                np.testing.assert_allclose(xy[:, 1], ax.bbox.y0)
                assert np.all((xy[:, 0] >= ax.bbox.x0 - 1e-9) & (xy[:, 0] <= ax.bbox.x1))
    finally:
        close(fig)


# ------------------------------------------------------------------ the command line


def test_help_lists_every_core_method_and_measure(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["tradeoff", "--help"])
    assert exit_.value.code == 0
    text = capsys.readouterr().out
    for method in METHODS:
        assert f"  {method}: order {METHODS[method]['order']}" in text
    for measure in MEASURES:
        assert measure in text
    assert max(len(line) for line in text.splitlines()) <= 100


@pytest.mark.parametrize("make", ["a file", "below a file", "a folder in the way", "not writable"])
def test_a_bad_out_fails_before_the_sweep(tmp_path, monkeypatch, capsys, make):
    import rigiddyn.out_folder as out_folder
    import rigiddyn.work_precision as module

    def no_sweep(*args, **kwargs):
        raise AssertionError("the sweep ran before --out was checked")

    monkeypatch.setattr(module, "tradeoff", no_sweep)
    out = tmp_path / "out"
    if make in ("a file", "below a file"):
        out.write_text("")
        out = out if make == "a file" else out / "sub"
    elif make == "a folder in the way":
        (out / "tradeoff.json").mkdir(parents=True)
    else:
        def refuse(*args, **kwargs):
            raise PermissionError(13, "Permission denied")

        monkeypatch.setattr(out_folder.tempfile, "TemporaryFile", refuse)
    assert main(["tradeoff", "t_handle", "--out", str(out), "--no-progress"]) == 2
    assert "rigiddyn tradeoff: --out: expected a folder where tradeoff.csv" in capsys.readouterr().err


def test_every_pair_of_tags_is_explained():
    """Each short note of the table has its explanation (the legend is built from the same table)."""
    from rigiddyn.work_precision.table import TAGS as _TAGS, tags as _tags

    for diverged, unstable, rec, front in itertools.product((False, True), repeat=4):
        r = row("rk4", 0.1, diverged=diverged, stability="x" if unstable else "", order_note="not asymptotic: 1")
        assert set(_tags(r, False, rec, front)) <= set(_TAGS)


def test_no_observed_order_where_both_errors_are_of_order_one():
    """An attitude error of 1 rad or more (at most pi) says the run has lost all accuracy: the slope
    between two such runs is no order of convergence (the T-handle's explicit Euler showed 'order 0.01')."""
    from rigiddyn.work_precision.orders import observed_orders as _observed_orders

    errors = [3.12, 3.08, 1.48, 0.724, 0.359, 0.18]
    rows = [row("explicit_euler", 0.04 / 2**k, max_attitude_error=e, reference_error=0.0)
            for k, e in enumerate(errors)]
    _observed_orders(rows, "max_attitude_error", set())
    assert [r["order_note"] for r in rows[:3]] == ["coarsest step", "error O(1)", "error O(1)"]
    # from (1.48, 0.724) on the slopes log2(e0 / e1) agree (1.03, 1.01, 1.00): observed order ~1
    assert all(math.isnan(r["observed_order"]) for r in rows[:3])
    assert [round(r["observed_order"], 2) for r in rows[3:]] == [1.03, 1.01, 1.0]


def test_a_sweep_that_fails_leaves_no_empty_out_folder(tmp_path, capsys):
    out = tmp_path / "new"
    assert main(["tradeoff", "t_handle", "--measure", "speed", "--out", str(out), "--no-progress"]) == 2
    assert "measure: expected one of" in capsys.readouterr().err and not out.exists()


# ------------------------------------------------------------------ the closed form's recommendation


def test_a_closed_form_recommendation_has_no_step():
    """The exact method has no step: its recommendation names neither dt nor a time per step."""
    rows = [row("exact", 0.1, order=0, final_attitude_error=0.0, total_evaluations=0, evaluations_per_step=0),
            row("exact", 0.05, order=0, final_attitude_error=0.0, total_evaluations=0, evaluations_per_step=0),
            row("rk4", 0.1, final_attitude_error=1e-3)]
    result = TradeoffResult("p", 1.0, "final_attitude_error", 1e-6, rows)
    text = str(result.recommendation)
    assert text.startswith("recommendation: exact (closed form): final_attitude_error = 0 rad")
    assert "dt" not in text and "/step" not in text and "steps)" not in text
    assert "/step" in str(TradeoffResult("p", 1.0, "final_attitude_error", 1e-2, rows[2:]).recommendation)


# ------------------------------------------------------------------ no raw numpy warnings


TORQUE = """name = "box under a body torque"
horizon = 10.0
[body.primitive]
shape = "solid_box"
size = [1.0, 1.2, 1.6]
mass = 200.0
[initial]
w_B = [0.2, -0.1, 0.5]
[[loads]]
torque = [1.0, 0.0, 2.0]
frame = "body"
"""


def test_the_independent_reference_covers_a_record_an_ulp_past_the_horizon(tmp_path):
    """10 s in 147 steps: the last record is at 147 x (10 / 147) = 10.000000000000002 s. DOP853 stopped at
    10 s left that row unset (np.empty: garbage, and numpy's divide, overflow and invalid warnings)."""
    from rigiddyn.work_precision.dop853 import dop853_states as _dop853_states

    (tmp_path / "torque.toml").write_text(TORQUE)
    problem = load_problem(tmp_path / "torque.toml")
    t = np.array([0.0, 5.0, 147 * (10.0 / 147)])
    assert t[-1] > problem.horizon
    states = _dop853_states(problem, t, 1e-12, 100_000)
    at_horizon = _dop853_states(problem, np.array([0.0, problem.horizon]), 1e-12, 100_000)
    # 2.2e-15 s later: the state moves by |w| 2.2e-15 ~ 1e-15 rad, far below DOP853's rtol 1e-12
    np.testing.assert_allclose(states.q_WB[-1], at_horizon.q_WB[-1], atol=1e-10)
    np.testing.assert_allclose(states.w_B[-1], at_horizon.w_B[-1], rtol=1e-10)


def test_tradeoff_on_a_torque_leaks_no_warning(tmp_path):
    """The sweep of a torqued body whose steps do not divide the horizon exactly, with every warning an
    error (python -W error): exit 0, nothing on stderr but the cost estimate."""
    import subprocess
    import sys

    (tmp_path / "torque.toml").write_text(TORQUE)
    done = subprocess.run([sys.executable, "-W", "error", "-m", "rigiddyn", "tradeoff", "torque.toml", "--methods",
                           "rk4,rkmk4", "--dts", f"{10 / 147},{10 / 294}", "--no-progress"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0 and done.stderr == "", done.stderr


def test_a_run_far_beyond_its_limit_measures_inf_without_a_warning():
    """States of 1e200, still finite, from a run blowing up: their squares overflow, the errors are inf."""
    from rigiddyn.work_precision import States, reference_states
    from rigiddyn.work_precision.one_body import ProblemCase

    problem = load_problem("t_handle")
    t = np.array([0.0, 1.0])
    ref = reference_states(problem, t)
    huge = States(t, ref.p_W, ref.q_WB * 1e200, np.full((2, 3), 1e200), np.full((2, 3), 1e200))
    measures = ProblemCase(problem).measures(huge, ref, np.zeros(2))  # warnings are errors in this suite
    assert measures["energy_drift"] == math.inf and measures["final_momentum_error"] == math.inf
    # q and 1e200 q are the same attitude: angle 0, computed from products rounded at a few eps
    assert measures["final_attitude_error"] < 1e-14


# ------------------------------------------------------------------ the runs' own error estimates


def test_each_run_reports_its_own_estimate_beside_the_true_error(tmp_path):
    """estimate, effectivity and estimate_verdict of the sweep's measure (the T-handle's max_attitude_error)
    against its exact solution: a reliable estimate is within a factor 2 of the true error (GlobalError's window;
    measured 0.95-1.0 here, docs/accuracy.md)."""
    result = rigiddyn.tradeoff("t_handle", methods=["rk4", "splitting_dlm"], dts=[0.01, 0.005], horizon=1.0,
                               progress=False)
    assert result.measure == "max_attitude_error"
    for r in result.rows:
        assert r["effectivity"] == pytest.approx(r["estimate"] / r["max_attitude_error"], rel=1e-12)
        assert r["estimate_verdict"] != "reliable" or 0.5 <= r["effectivity"] <= 2.0, r
    assert any(r["estimate_verdict"] == "reliable" for r in result.rows)
    header = next(line for line in result.to_table().splitlines() if line.startswith("method"))
    assert "estimate" in header
    back = [TradeoffResult.read_csv(result.to_csv(), measure="final_attitude_error"),
            TradeoffResult.read_json(result.to_json())]
    for other in back:
        assert [r["estimate_verdict"] for r in other.rows] == [r["estimate_verdict"] for r in result.rows]
        assert [r["estimate"] for r in other.rows] == [r["estimate"] for r in result.rows]


def test_a_row_is_judged_by_its_own_quantity():
    """The shipped spring chain (damped: its energy is no invariant, and its energy estimate fails the order check
    at many records) by Yoshida's splitting at 10 s / 4896: every record's position estimate passes its own check
    (reliable_for), so the row's max_position_error estimate is reliable, and within a factor 2 of the true error
    (what a reliable estimate promises, docs/accuracy.md), while the records' own verdicts are not all reliable."""
    horizon, steps = 10.0, 4896
    result = rigiddyn.tradeoff("spring_chain", methods=["splitting_dlm_yoshida4"], dts=[horizon / steps],
                               horizon=horizon, measure="max_position_error", progress=False)
    (row,) = result.rows
    assert row["estimate_verdict"] == "reliable" and 0.5 <= row["effectivity"] <= 2.0, row
    scene, states, _ = rigiddyn.load_scene("spring_chain")
    with pytest.warns(rigiddyn.SceneCompatibilityWarning, match="velocity-dependent"):  # the damping: order 1
        error = rigiddyn.simulate(scene, states, horizon / steps, steps=steps, record_every=16,
                                  method="splitting_dlm_yoshida4").error
    assert np.all(error.reliable_for("position"))
    assert not all(v == "reliable" or v.startswith("interpolated between the reliable") for v in error.verdict)


def test_a_measure_without_an_estimate_says_so():
    result = rigiddyn.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=0.5, measure="energy_drift",
                               progress=False)
    (r,) = result.rows
    assert math.isnan(r["estimate"]) and math.isnan(r["effectivity"])
    assert r["estimate_verdict"].startswith("no estimate of energy_drift")


def test_a_scene_sweep_reports_the_estimate_and_flags_a_coarse_step():
    """The shipped pendulum against its closed form: explicit Euler at 20 ms is far from its asymptotic range
    (its error of ~1 rad is not O(dt)), so its estimate is not reliable; rk4's is, within a factor 2."""
    result = rigiddyn.tradeoff("pendulum", methods=["explicit_euler", "splitting_dlm"], dts=[0.02, 0.01], horizon=2.0,
                               measure="final_attitude_error", progress=False)
    rows = {(r["method"], r["steps"]): r for r in result.rows}
    assert rows[("explicit_euler", 100)]["estimate_verdict"] != "reliable"
    for steps in (100, 200):
        r = rows[("splitting_dlm", steps)]
        assert r["estimate_verdict"] == "reliable" and 0.5 <= r["effectivity"] <= 2.0, r


def test_the_plot_draws_the_estimates():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from rigiddyn.work_precision.plot import _plot_axis

    result = rigiddyn.tradeoff("t_handle", methods=["rk4"], dts=[0.01, 0.005], horizon=1.0, progress=False)
    fig, ax = plt.subplots()
    _plot_axis(result, ax, "total_evaluations", result.measure)
    labels = ax.get_legend_handles_labels()[1]
    assert "estimate (result.error), reliable" in labels and "estimate, not reliable" in labels
    # a bar per run from the true error to the estimate, at the run's cost
    bars = [line for line in ax.get_lines() if len(line.get_xdata()) == 2 and line.get_xdata()[0] == line.get_xdata()[1]]
    assert len(bars) == len(result.rows)
    for bar, row in zip(bars, result.rows):
        assert list(bar.get_ydata()) == [row[result.measure], row["estimate"]]
    plt.close(fig)
