"""Properties of results the API documents, fuzzed beside the calls of fuzz_api.py: the oracle of a wrong
result where a cheap reference or an invariant exists.

Each property is a function of plain parameters (numbers, strings, lists, dicts: printable, so a finding's
reproducer is `properties.<name>(**params)`) that builds its inputs with the public API, runs them, and
raises AssertionError "<what>: <details>" when a documented property fails; STRATEGIES[name] draws its
parameters. fuzz_api.py runs each one in its watched worker like any target (a crash, a hang or an
undocumented exception is a finding too; a TypeError/ValueError naming an argument is an answer).

Every tolerance is the bound stated beside it; exact equalities are those the docstrings promise
("bitwise", "reads back bit for bit").
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import shutil
import sys
import tomllib
import warnings
from pathlib import Path

import numpy as np
from hypothesis import strategies as st

import rigiddyn as rd
from scene_files import UNITS, render, scene_data

EPS = float(np.finfo(float).eps)
SCENE_RECORDS = ("t", "p_W", "q_WB", "v_W", "w_B", "pivot_reaction_W", "angular_momentum_O_W", "kinetic_energy",
                 "potential_energy", "total_energy", "linear_momentum_W", "angular_momentum_W", "mass", "work", "power")


def _same(a, b) -> bool:
    """Bitwise equal arrays (NaN equal to NaN, -0.0 to 0.0 as numpy compares)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and bool(np.array_equal(a, b, equal_nan=True))


def _first_difference(a, b) -> str:
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        return f"shapes {a.shape} and {b.shape}"
    bad = np.argwhere(~((a == b) | (np.isnan(a) & np.isnan(b))))
    i = tuple(bad[0])
    return f"at {i}: {a[i]!r} and {b[i]!r} ({len(bad)} entries differ)"


def _state(kind: str, values: list[float]):
    """A state of a body kind from 12 numbers (what each kind takes of them)."""
    v = np.asarray(values, float)
    if kind == "Particle":
        return rd.ParticleState(p_W=v[0:3], v_W=v[3:6])
    if kind == "PlanarBody":
        return rd.PlanarBodyState(p_W=v[0:2], theta=v[2], v_W=v[3:5], omega=v[5])
    q = v[6:10] / np.linalg.norm(v[6:10]) if np.linalg.norm(v[6:10]) > 1e-3 else np.array([0.0, 0.0, 0.0, 1.0])
    return rd.RigidBodyState(p_W=v[0:3], q_WB=q, v_W=v[3:6], w_B=v[10:12].tolist() + [v[0]])


def _body(kind: str, mass: float, moments: list[float]):
    if kind == "Particle":
        return rd.Particle(mass)
    if kind == "PlanarBody":
        return rd.PlanarBody(mass, moments[2])
    return rd.RigidBody(mass, moments)


MOMENTS = st.tuples(st.floats(0.2, 2.0), st.floats(0.2, 2.0), st.floats(0.2, 2.0)).map(
    lambda s: [s[1] ** 2 + s[2] ** 2, s[0] ** 2 + s[2] ** 2, s[0] ** 2 + s[1] ** 2])  # a box's: a real body's
STATE_VALUES = st.lists(st.floats(-3.0, 3.0), min_size=12, max_size=12)
BODY_METHODS = ["rk4", "splitting_dlm", "implicit_midpoint", "explicit_euler", "semi_implicit_euler", "rkmk4",
                "splitting_dlm_yoshida4", "exact_flow_kick"]


def _scene_text(draw, max_bodies=3) -> str:
    return render(draw(scene_data(max_bodies)))


# ---------------------------------------------------------------------------------------------
# simulate_batch: "the records equal N serial simulate calls bitwise, whatever the thread count"


def batch_equals_serial(kind: str, mass: float, moments: list, states: list, dts: list, steps: int,
                        record_every: int, method: str, threads: int, gravity: bool, scene: str = "") -> None:
    """simulate_batch of a body (kind) or of a scene file's scene (scene: its TOML text; its initial state for
    every sample, each sample with its own dt) equals simulate of each sample, bitwise."""
    if scene:
        model, initial, _ = rd.load_scene(scene)
        model = model.compile(method)
        initial = [list(initial)] * len(dts)
        options = {}
    else:
        model = _body(kind, mass, moments)
        initial = [_state(kind, s) for s in states]
        options = {"gravity": gravity if kind == "RigidBody" or not gravity else [0.0, -9.81, 0.0]}
    dt = np.asarray(dts, float)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # divergence: both sides warn, and both are compared
        batch = rd.simulate_batch(model, initial, dt, steps, method=method, record_every=record_every,
                                  threads=threads, **options)
        for i, state in enumerate(initial):
            one = rd.simulate(model, state, float(dt[i]), steps, method=method, record_every=record_every, **options)
            rows = int(batch.filled[i])
            assert rows == len(one.t), f"batch != serial: sample {i} filled {rows} rows, simulate recorded {len(one.t)}"
            assert bool(batch.diverged[i]) == bool(one.diverged), f"batch != serial: sample {i} diverged flag"
            for name in SCENE_RECORDS:
                a, b = np.asarray(getattr(batch, name))[i, :rows], np.asarray(getattr(one, name))
                assert _same(a, b), f"batch != serial: sample {i} {name} {_first_difference(a, b)}"
            assert np.all(np.isnan(np.asarray(batch.t)[i, rows:])), f"batch rows after filled: sample {i} not NaN"


@st.composite
def _batch_params(draw):
    n = draw(st.integers(1, 4))
    kind = draw(st.sampled_from(["RigidBody", "RigidBody", "Particle", "PlanarBody", "scene"]))
    method = draw(st.sampled_from(BODY_METHODS if kind == "RigidBody" else ["rk4", "implicit_midpoint",
                                                                             "explicit_euler", "splitting_dlm"]))
    return {"kind": kind, "mass": draw(st.floats(0.1, 10.0)), "moments": draw(MOMENTS),
            "states": [draw(STATE_VALUES) for _ in range(n)],
            "dts": draw(st.lists(st.sampled_from([1e-3, 5e-3, 1e-2, 2e-2]), min_size=n, max_size=n)),
            "steps": draw(st.integers(0, 30)), "record_every": draw(st.integers(1, 4)), "method": method,
            "threads": draw(st.integers(1, 3)), "gravity": draw(st.booleans()),
            "scene": _scene_text(draw) if kind == "scene" else ""}


# ---------------------------------------------------------------------------------------------
# simulate_batch(simd=True): "equal to the scalar path up to round-off, not bitwise"


def simd_matches_scalar(moments: list, mass: float, states: list, steps: int, dt: float, force: list, torque: list,
                        gravity: bool, record_every: int) -> None:
    """The SIMD path (RigidBody, rk4, constant loads) against the scalar path, to round-off."""
    body = rd.RigidBody(mass, moments)
    initial = [_state("RigidBody", s) for s in states]
    loads = [rd.AppliedLoad(force=force, torque=torque, frame="world")] if any(force) or any(torque) else None
    if loads is not None:  # the SIMD path's loads: a force in W and a torque in B
        loads = [rd.AppliedLoad(force=force, frame="world"), rd.AppliedLoad(torque=torque, frame="body")]
    runs = [rd.simulate_batch(body, initial, dt, steps, method="rk4", record_every=record_every, loads=loads,
                              gravity=gravity, threads=2, simd=simd) for simd in (False, True)]
    scalar, simd = runs
    assert _same(scalar.filled, simd.filled), "simd != scalar: filled rows"
    # the SIMD path may run the full form of Euler's equations where the scalar one runs the principal form: a
    # few ulps per derivative evaluation, <= 16 eps of the state's scale per stage, 4 stages a step (as
    # test_simulate_batch); a difference grows at most as e^(L t) with L <= 2 max|w| + 1 [1/s] (the Jacobian
    # of Euler's equations of a real body: |I_j - I_k| <= I_i; the attitude adds |w|; a constant force adds
    # a linear drift of p)
    w_max = max(float(np.max(np.abs(np.asarray(scalar.w_B)))), 0.0)
    growth = math.exp((2.0 * w_max + 1.0) * steps * dt) * (1.0 + steps * dt)
    for name in ("p_W", "q_WB", "v_W", "w_B"):
        a, b = np.asarray(getattr(simd, name)), np.asarray(getattr(scalar, name))
        scale = max(float(np.max(np.abs(b))), 1.0) if b.size else 1.0
        bound = (steps + 1) * 4 * 16 * EPS * scale * growth
        worst = float(np.max(np.abs(a - b))) if b.size else 0.0
        assert worst <= bound, f"simd != scalar: {name} differs by {worst:.3g} > {bound:.3g}"


@st.composite
def _simd_params(draw):
    n = draw(st.integers(1, 9))  # across SIMD lane counts (2, 4, 8) and their remainders
    return {"moments": draw(MOMENTS), "mass": draw(st.floats(0.1, 10.0)), "states": [draw(STATE_VALUES) for _ in range(n)],
            "steps": draw(st.integers(0, 40)), "dt": draw(st.sampled_from([1e-3, 1e-2])),
            "force": draw(st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3)),
            "torque": draw(st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3)) if draw(st.booleans()) else [0.0] * 3,
            "gravity": draw(st.booleans()), "record_every": draw(st.integers(1, 4))}


# ---------------------------------------------------------------------------------------------
# scene files: "scene_to_toml writes the canonical file ... that loads back to the same scene, states and options"


def scene_file_round_trip(scene: str) -> None:
    """load_scene(text) -> Scene.to_toml -> load_scene gives the same file again (floats by repr: bit for bit), and
    the canonical file keeps each SI number of the text exactly."""
    model, initial, run = rd.load_scene(scene)
    canonical = model.to_toml(initial, run)
    again = rd.load_scene(canonical)
    twice = again.scene.to_toml(again.initial, again.run)
    assert twice == canonical, f"round trip: the canonical file changed on reading it back:\n{_diff(canonical, twice)}"
    assert again.run == run, f"round trip: run options {again.run} != {run}"
    written, read = tomllib.loads(scene), tomllib.loads(canonical)
    for i, table in enumerate(written.get("body", [])):
        for key in ("mass", "p_W", "v_W", "w_B", "p_OC_B", "p_WO", "theta", "omega"):
            if key in table:
                assert _same(read["body"][i][key], table[key]), f"round trip: body[{i}].{key} {read['body'][i][key]} != {table[key]}"


def _diff(a: str, b: str) -> str:
    import difflib

    return "\n".join(list(difflib.unified_diff(a.splitlines(), b.splitlines(), lineterm="", n=1))[:12])


# ---------------------------------------------------------------------------------------------
# units: a value with a unit is the SI value


def units_match_si(scene: dict, picks: list) -> None:
    """A scene file with its numbers written in other units ("3.28 ft") reads as the same scene in SI, to the
    rounding of the conversions: value / size written by repr, pint's factor, its product (<= 3 roundings,
    pint's factors within 2 ulp: 8 eps relative per number); quaternions from angles with units move by the
    angle's error (8 eps of an angle <= 3 rad), cluster positions scale with the radius."""
    data = _from_plain(scene)
    it = iter(picks)
    si = rd.load_scene(render(data))
    other = rd.load_scene(render(data, lambda options: options[next(it) % len(options)]))
    a, b = tomllib.loads(si.scene.to_toml(si.initial, si.run)), tomllib.loads(other.scene.to_toml(other.initial, other.run))
    _close(a, b, "units != SI", ())


# A number written in a larger unit (value / size) may fall below the smallest normal double, where the spacing of
# doubles is 2**-1074 absolute: its rounding then carries up to 2**-1075 x size into SI, for each of the two files
# (UNITS' largest size is 1e9: km^3/s^2).
SUBNORMAL_FLOOR = 2.0**-1074 * max(size for options in UNITS.values() for _, size in options)


def _close(a, b, what, path):
    if isinstance(a, dict):
        assert set(a) == set(b), f"{what}: keys of {path} {sorted(a)} != {sorted(b)}"
        for k in a:
            _close(a[k], b[k], what, path + (k,))
    elif isinstance(a, list) and a and all(isinstance(x, float) for x in a):
        # a vector: its entries to 8 eps of its size (a cluster's positions are centred on their mass centre:
        # a sum of up to 4 positions, 16 eps of the largest), a quaternion from angles to 8 eps of 3 rad
        size = max(map(abs, a)) + max(map(abs, b)) + (3.0 if "q_WB" in path else 0.0)
        worst = max(abs(x - y) for x, y in zip(a, b)) if len(a) == len(b) else math.inf
        assert worst <= 16 * EPS * size + SUBNORMAL_FLOOR, f"{what}: {'.'.join(map(str, path))} {a!r} != {b!r}"
    elif isinstance(a, list):
        assert len(a) == len(b), f"{what}: length of {path}"
        for i, (x, y) in enumerate(zip(a, b)):
            _close(x, y, what, path + (i,))
    elif isinstance(a, float):
        bound = 8 * EPS * (abs(a) + abs(b)) + SUBNORMAL_FLOOR
        assert abs(a - b) <= bound, f"{what}: {'.'.join(map(str, path))} {a!r} != {b!r}"
    else:
        assert a == b, f"{what}: {'.'.join(map(str, path))} {a!r} != {b!r}"


def _plain(data):
    """Scene data with its Q leaves as ["Q", value, unit] (printable parameters)."""
    from scene_files import Q

    if isinstance(data, Q):
        return ["Q", data.value, data.unit]
    if isinstance(data, dict):
        return {k: _plain(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_plain(v) for v in data]
    return data


def _from_plain(data):
    from scene_files import Q

    if isinstance(data, list) and len(data) == 3 and data[0] == "Q":
        return Q(data[1], data[2])
    if isinstance(data, dict):
        return {k: _from_plain(v) for k, v in data.items()}
    if isinstance(data, list):
        return [_from_plain(v) for v in data]
    return data


def unit_string_value(x: float, unit: str, pick: int) -> None:
    """units.quantity("<x> <unit>") is x times the unit's size in SI (pint's factors within 2 ulp, one product:
    4 eps relative); the number alone is SI; a Quantity converts the same."""
    name, size = UNITS[unit][pick % len(UNITS[unit])]
    text = f"{x!r} {name}".rstrip()
    got = rd.units.quantity(text if name else x, "x", unit)
    want = x * size
    assert abs(got - want) <= 4 * EPS * abs(want), f"unit string: {text!r} read as {got!r} {unit}, expected {want!r}"
    if name:
        q = rd.units.registry().Quantity(x, name)
        via = rd.units.quantity(q, "x", unit)
        assert abs(via - want) <= 4 * EPS * abs(want), f"unit quantity: {q!r} read as {via!r} {unit}, expected {want!r}"
        vector = rd.units.vector_quantity({"value": [x, 0.0, -x], "unit": name}, "v", unit)
        assert abs(vector[0] - want) <= 4 * EPS * abs(want) and vector[1] == 0.0 and vector[2] == -vector[0], \
            f"unit table: {{value = [{x!r}, 0, {-x!r}], unit = {name!r}}} read as {vector.tolist()}"


def unit_decimal_comma(x: float, unit: str, pick: int) -> None:
    """A number written with a decimal comma ("1,5 m") is refused (ValueError naming the field) or read as the
    decimal number it is; never as another number (4 eps relative, as unit_string_value)."""
    name, size = UNITS[unit][pick % len(UNITS[unit])]
    text = f"{x:.3f} {name}".replace(".", ",")
    try:
        got = rd.units.quantity(text, "x", unit)
    except ValueError as e:
        assert str(e).startswith("x: "), f"decimal comma: {text!r} refused without naming the field: {e}"
        return
    want = float(f"{x:.3f}") * size
    assert abs(got - want) <= 4 * EPS * abs(want), f"decimal comma: {text!r} read as {got!r} {unit}, expected {want!r}"


# ---------------------------------------------------------------------------------------------
# monte_carlo: "sample i's draws depend only on (seed, i): serial and threaded runs agree, and a run of N
# samples is the prefix of a run of N' > N samples with the same seed"


def _dispersions(spec: dict, prefix: str = ""):
    mc = rd.dispersion
    out = {}
    for key, (cls, args) in spec.items():
        if cls == "LoadDispersion":
            out[prefix + key] = mc.LoadDispersion(force=mc.Normal(std=args[0]), torque=mc.Uniform(-args[1], args[1]))
        else:
            out[prefix + key] = getattr(mc, cls)(*args)
    return out


def monte_carlo_reproducible(model: str, n: int, more: int, seed: int, dispersions: dict, steps: int) -> None:
    """monte_carlo of n samples on 1 thread is the prefix of n + more samples on 3 threads, bitwise (inputs and
    records); drawn masses > 0, Uniform draws in [low, high), rotations of unit norm; statistics over the
    samples are numpy's over the values."""
    mc = rd.dispersion
    if model == "scene":
        body = rd.Scene(bodies=[rd.Particle(2.0), rd.RigidBody(1.0, [1.0, 2.0, 2.5])], body_names=["dot", "box"],
                        elements=[rd.UniformGravity()])
        nominal = [rd.ParticleState(v_W=[0.0, 1.0, 0.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])]
        spec = {f"dot.{k}": v for k, v in dispersions.items() if k in ("p_W", "v_W", "mass")}  # a particle's fields
        spec |= {f"box.{k}": v for k, v in dispersions.items() if k not in ("loads", "gravity")}  # a rigid body's
    else:
        body = rd.RigidBody(1.0, [1.0, 2.0, 2.5])
        nominal = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
        spec = dispersions
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # DispersionWarning (redraws) and divergence: both runs the same
        small = mc.monte_carlo(body, nominal, n, seed=seed, dispersions=_dispersions(spec), dt=0.01, steps=steps,
                               threads=1)
        large = mc.monte_carlo(body, nominal, n + more, seed=seed, dispersions=_dispersions(spec), dt=0.01,
                               steps=steps, threads=3)
    assert set(small.inputs) == set(large.inputs), f"monte_carlo: inputs {sorted(small.inputs)} != {sorted(large.inputs)}"
    for key, values in small.inputs.items():
        assert _same(values, np.asarray(large.inputs[key])[:n]), f"monte_carlo prefix: inputs[{key!r}] differ"
    for name in small.fields:
        a, b = small.values(name), large.values(name)[:n]  # the records and the error estimate's
        assert _same(a, b), f"monte_carlo prefix: records {name} {_first_difference(a, b)}"
    for key, values in small.inputs.items():
        field = key.rsplit(".", 1)[-1]
        cls, args = spec[key] if key in spec else (None, None)
        values = np.asarray(values)
        if field == "mass":
            assert np.all(values > 0), f"monte_carlo: a drawn mass <= 0: {values.tolist()}"
        if field == "q_WB":
            assert np.all(np.abs(np.linalg.norm(values, axis=-1) - 1.0) <= 4 * EPS), "monte_carlo: a drawn q_WB not unit"
        if cls == "Uniform":
            low, high = np.broadcast_to(args[0], values.shape[1:]), np.broadcast_to(args[1], values.shape[1:])
            inside = (values >= low) & ((values < high) | (low == high))
            assert np.all(inside), f"monte_carlo: Uniform({args[0]}, {args[1]}) drew {values.tolist()}"
    if "w_B" in small.fields:
        x = small.values("w_B")
        stats = small.statistics("w_B")
        if np.all(np.isfinite(x)):
            assert _same(stats.mean, x.mean(axis=0)) and _same(stats.max, x.max(axis=0)), "monte_carlo statistics: mean/max"
            assert np.all(stats.count == n), f"monte_carlo statistics: count {stats.count} != {n}"


_VECTOR_DISPERSIONS = st.one_of(
    st.tuples(st.just("Normal"), st.tuples(st.none(), st.floats(0.0, 1.0))).map(lambda c: (c[0], list(c[1]))),
    st.tuples(st.floats(-1.0, 0.0), st.floats(0.0, 1.0)).map(lambda lh: ("Uniform", [lh[0], lh[1]])))


@st.composite
def _monte_carlo_params(draw):
    keys = draw(st.lists(st.sampled_from(["p_W", "q_WB", "v_W", "w_B", "mass", "inertia", "gravity", "loads"]),
                         unique=True, max_size=5))
    spec = {}
    for key in keys:
        if key == "q_WB":
            spec[key] = draw(st.sampled_from([("UniformRotation", []), ("RotationNormal", [0.1])]))
        elif key == "inertia":
            spec[key] = ("InertiaDispersion", [draw(st.floats(0.0, 0.3)), draw(st.floats(0.0, 0.2))])
        elif key == "mass":
            spec[key] = draw(st.sampled_from([("Normal", [None, 0.3]), ("Uniform", [0.5, 1.5])]))
        elif key == "loads":
            spec[key] = ("LoadDispersion", [draw(st.floats(0.0, 2.0)), draw(st.floats(0.0, 1.0))])
        else:
            spec[key] = draw(_VECTOR_DISPERSIONS)
    return {"model": draw(st.sampled_from(["body", "scene"])), "n": draw(st.integers(1, 5)),
            "more": draw(st.integers(1, 4)), "seed": draw(st.integers(0, 2**64)), "dispersions": spec,
            "steps": draw(st.integers(0, 10))}


# ---------------------------------------------------------------------------------------------
# the command line on scene files: what it writes is what the API computes


def cli_matches_api(scene: str, options: list) -> None:
    """`python -m rigiddyn simulate scene.toml --out DIR [options]` (in process): exit 0 or 1 with the npz
    columns equal, bitwise, to rigiddyn.scene_result.columns of simulate on load_scene's scene with the same
    method, dt, steps and record_every; exit 2 with one "rigiddyn simulate: ..." or argparse's message on
    stderr and no traceback."""
    from rigiddyn.__main__ import main

    path, out = Path("scene.toml"), Path("cli_out")
    path.write_text(scene)
    shutil.rmtree(out, ignore_errors=True)
    argv = ["simulate", str(path), "--out", str(out), "--no-progress", *options]
    stdout, stderr = io.StringIO(), io.StringIO()
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr), warnings.catch_warnings():
            warnings.simplefilter("always")
            try:
                code = main(argv)
            except SystemExit as e:  # argparse: a usage error
                code = e.code
        err = stderr.getvalue()
        if code == 130:  # the CLI's exit on Ctrl-C: the harness's SIGINT to a slow call reached it, a slow call
            raise KeyboardInterrupt
        assert "Traceback" not in err, f"cli: a traceback on stderr:\n{err[-2000:]}"
        assert code in (0, 1, 2), f"cli: exit status {code!r}; stderr:\n{err[-1000:]}"
        if code == 2:
            lines = [line for line in err.splitlines() if line.strip()]
            assert lines and (lines[-1].startswith("rigiddyn simulate: ") or "error:" in lines[-1]), \
                f"cli: exit 2 without a message naming the problem; stderr:\n{err[-1000:]}"
            if "PROBLEM" in lines[-1]:  # the file refused: load_scene must refuse it too
                try:
                    rd.load_scene(scene)
                except (ValueError, TypeError):
                    return
                raise AssertionError(f"cli refuses a scene file load_scene reads (cluster-only: "
                                     f"{'body' not in tomllib.loads(scene)}): {lines[-1]}")
            return
        record = json.loads((out / "run.json").read_text())
        model, initial, _ = rd.load_scene(scene)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            result = rd.simulate(model, initial, dt=record["dt [s]"], steps=record["steps"], method=record["method"],
                                 record_every=record["record_every"])
        from rigiddyn.scene_result import columns

        want = columns(result)
        with np.load(out / "trajectory.npz") as got:
            assert sorted(got.files) == sorted(want), f"cli: npz columns {sorted(got.files)} != {sorted(want)}"
            for name, values in want.items():
                assert _same(got[name], values), f"cli != api: column {name!r} {_first_difference(got[name], values)}"
        assert (code == 1) == bool(result.diverged), f"cli: exit {code} but diverged={result.diverged}"
    finally:
        shutil.rmtree(out, ignore_errors=True)


_CLI_OPTIONS = st.lists(st.sampled_from([
    ["--method", "rk4"], ["--method", "implicit_midpoint"], ["--method", "splitting_dlm"], ["--method", "nope"],
    ["--dt", "0.01"], ["--dt", "0.002"], ["--dt", "0"], ["--dt", "-1"], ["--dt", "nan"], ["--dt", "1e-300"],
    ["--dt", "1e308"], ["--steps", "5"], ["--steps", "0"], ["--steps", "99999999999999999999"], ["--duration", "0.05"],
    ["--duration", "1e-9"], ["--duration", "inf"], ["--record-every", "2"], ["--record-every", "1000"],
    ["--no-plot"], ["--animate"], ["--attitude", "quaternion"], ["--frames", "3"], ["--bogus"]]),
    max_size=3).map(lambda groups: [a for g in groups for a in g])


@st.composite
def _cli_params(draw):
    return {"scene": _scene_text(draw, 2), "options": draw(_CLI_OPTIONS)}


# ---------------------------------------------------------------------------------------------
# exact references: invariants of the closed forms, and the equivalences simulate documents


def lagrange_top_invariants(tilt: float, spin: float, w_x: float, c: float, moments: list, times: list) -> None:
    """LagrangeTopSolution.at(t) keeps the energy, H_z and H_3 (its own constants) at any t: the closed form's
    attitude and w_B are accurate to 1e-12 relative (test_fixed_point_frames_mass_physics' comparison with DOP853); an invariant
    sums products of them with I_O (condition <= 100 here), hence 1e-12 * 100 * 10 of the invariant's scale."""
    I1, I3 = moments
    body = rd.PivotedBody(rd.RigidBody(1.0, [I1, I1, I3]), [0.0, 0.0, c])
    q = [math.sin(tilt / 2), 0.0, 0.0, math.cos(tilt / 2)]
    g = np.array([0.0, 0.0, -9.81])
    sol = rd.LagrangeTopSolution(body, g, rd.PivotedBodyState(q_WB=q, w_B=[w_x, 0.0, spin]))
    q_t, w_t = sol.at(np.asarray(times, float))
    I_O = np.asarray(body.inertia_O)
    p_OC_B = np.array([0.0, 0.0, c])
    scale_E = float(np.max(np.abs(w_t))) ** 2 * float(np.max(np.abs(I_O))) + 9.81 * abs(c) + 1e-300
    scale_H = float(np.max(np.abs(w_t))) * float(np.max(np.abs(I_O))) + 1e-300
    for k, t in enumerate(times):
        R = rd.quat_to_matrix(q_t[k])
        w = w_t[k]
        energy = 0.5 * w @ I_O @ w - g @ (R @ p_OC_B)
        H_z = (R @ (I_O @ w)) @ np.array([0.0, 0.0, 1.0])
        H_3 = (I_O @ w)[2] * math.copysign(1.0, c)
        for name, got, want, scale in (("energy", energy, sol.energy, scale_E), ("H_z", H_z, sol.H_z, scale_H),
                                       ("H_3", H_3, sol.H_3, scale_H)):
            assert abs(got - want) <= 1e-9 * scale, f"lagrange top: {name} at t = {t!r}: {got!r} != constant {want!r}"


@st.composite
def _top_params(draw):
    I1 = draw(st.floats(0.5, 2.0))
    return {"tilt": draw(st.floats(0.05, 3.0)), "spin": draw(st.sampled_from([1.0, -1.0])) * draw(st.floats(0.5, 50.0)),
            "w_x": draw(st.floats(-1.0, 1.0)), "c": draw(st.sampled_from([1.0, -1.0])) * draw(st.floats(0.05, 1.0)),
            "moments": [I1, draw(st.floats(0.1, 2.0 * I1))],
            "times": draw(st.lists(st.floats(-10.0, 100.0), min_size=1, max_size=4))}


def compound_pendulum_invariants(mass: float, inertia_zz: float, p_OC_B: list, theta: float, omega: float,
                                 g: list, times: list) -> None:
    """CompoundPendulumSolution.at(t) keeps its energy 1/2 I_O omega^2 - m g . (R p_OC_B): theta and omega from
    Jacobi's functions to ~1e-15 relative ("accurate up to v0 -> pi"), times the conditioning of the sum
    (its terms over it), 1e-10 of the larger term."""
    body = rd.PivotedPlanarBody(mass, inertia_zz, p_OC_B)
    sol = rd.CompoundPendulumSolution(body, g, rd.PivotedPlanarBodyState(theta=theta, omega=omega))
    th, om = sol.at(np.asarray(times, float))
    I_O = body.inertia_O_zz
    for k, t in enumerate(times):
        c, s = math.cos(th[k]), math.sin(th[k])
        p = np.array([c * p_OC_B[0] - s * p_OC_B[1], s * p_OC_B[0] + c * p_OC_B[1]])
        kinetic, potential = 0.5 * I_O * om[k] ** 2, -mass * (g[0] * p[0] + g[1] * p[1])
        scale = abs(kinetic) + mass * math.hypot(*g[:2]) * math.hypot(*p_OC_B) + 1e-300
        assert abs(kinetic + potential - sol.energy) <= 1e-10 * scale, \
            f"compound pendulum: energy at t = {t!r}: {kinetic + potential!r} != constant {sol.energy!r}"


@st.composite
def _pendulum_params(draw):
    return {"mass": draw(st.floats(0.1, 10.0)), "inertia_zz": draw(st.floats(0.01, 2.0)),
            "p_OC_B": [draw(st.floats(-1.0, 1.0)), draw(st.floats(-1.0, 1.0))],
            "theta": draw(st.one_of(st.floats(-10.0, 10.0), st.sampled_from([math.pi, -math.pi, 0.0]))),
            "omega": draw(st.one_of(st.floats(-30.0, 30.0), st.just(0.0))),
            "g": [draw(st.floats(-10.0, 10.0)), draw(st.floats(-10.0, 10.0))],
            "times": draw(st.lists(st.floats(-10.0, 100.0), min_size=1, max_size=4))}


def pivoted_simulate_is_its_scene(kind: str, mass: float, moments: list, p_OC_B: list, p_WO: list, state: list,
                                  force: list, method: str, steps: int) -> None:
    """simulate(PivotedBody or PivotedPlanarBody, state, gravity=g, loads=L) is "the one-body scene of the body,
    UniformGravity (gravity) and ScheduledLoads (loads)": the same records, bitwise."""
    loads = [rd.AppliedLoad(force=force, t_start=0.01)] if any(force) else []
    if kind == "PivotedBody":
        body = rd.PivotedBody(rd.RigidBody(mass, moments), p_OC_B, p_WO)
        initial = rd.PivotedBodyState(q_WB=np.asarray(state[:4]) / np.linalg.norm(state[:4]), w_B=state[4:7])
        g = [0.0, 0.0, -9.81]
    else:
        body = rd.PivotedPlanarBody(mass, moments[2], p_OC_B[:2], p_WO[:2])
        initial = rd.PivotedPlanarBodyState(theta=state[0], omega=state[1])
        g = [0.0, -9.81, 0.0]
        loads = [rd.AppliedLoad(force=[force[0], force[1], 0.0], t_start=0.01)] if any(force) else []
    elements = [rd.UniformGravity(g_W=g)] + ([rd.ScheduledLoads(body=0, loads=loads)] if loads else [])
    scene = rd.Scene(bodies=[body], elements=elements)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        one = rd.simulate(body, initial, 0.01, steps, method=method, gravity=g, loads=loads or None)
        two = rd.simulate(scene, [initial], 0.01, steps, method=method)
    for name in SCENE_RECORDS:
        a, b = np.asarray(getattr(one, name)), np.asarray(getattr(two, name))
        assert _same(a, b), f"pivoted body != its scene: {name} {_first_difference(a, b)}"


@st.composite
def _pivoted_params(draw):
    return {"kind": draw(st.sampled_from(["PivotedBody", "PivotedPlanarBody"])), "mass": draw(st.floats(0.1, 10.0)),
            "moments": draw(MOMENTS), "p_OC_B": draw(st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3)),
            "p_WO": draw(st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3)),
            "state": draw(st.lists(st.floats(0.1, 3.0), min_size=7, max_size=7)),
            "force": draw(st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3)) if draw(st.booleans()) else [0.0] * 3,
            "method": draw(st.sampled_from(["rk4", "implicit_midpoint", "splitting_dlm", "explicit_euler"])),
            "steps": draw(st.integers(0, 20))}


def rotating_frame_particle(axis: list, rate: float, p0: list, v0: list, dt: float, steps: int) -> None:
    """A free particle simulated in a rotating SceneFrame (rk4) against RotatingFrameFreeParticle: RK4's error
    at dt/2 is at most twice its Richardson estimate |x(dt) - x(dt/2)| / 15 (C h^4 asymptotic, doubled for the
    next term), plus the round-off of the runs (16 eps per step of the state's scale); the solution's Jacobi
    integral constant to 1e-12 of its terms (round-off of a rotation and two squares)."""
    frame = rd.SceneFrame.rotating(axis, rate)
    sol = rd.RotatingFrameFreeParticle(frame, p0, v0)
    scene = rd.Scene(bodies=[rd.Particle(1.0)], frame=frame)
    runs = [rd.simulate(scene, [rd.ParticleState(p_W=p0, v_W=v0)], h, steps * k, method="rk4", record_every=k)
            for h, k in ((dt, 1), (dt / 2, 2))]
    coarse, fine = (np.asarray(r.p_W)[:, 0] for r in runs)
    t = np.asarray(runs[1].t)
    exact = sol.at(t)[0]
    scale = float(np.max(np.abs(exact))) + 1.0
    bound = 2.0 * float(np.max(np.abs(coarse - fine))) / 15.0 + 16 * EPS * scale * (2 * steps + 1)
    worst = float(np.max(np.abs(fine - exact)))
    assert worst <= bound, f"rotating frame: rk4 at dt/2 differs from the exact solution by {worst:.3g} > {bound:.3g}"
    p, v = sol.at(t)
    w = np.asarray(sol.w_F)
    jacobi = 0.5 * np.sum(v * v, axis=1) - 0.5 * np.sum(np.cross(w, p) ** 2, axis=1)
    terms = 0.5 * np.sum(v * v, axis=1) + 0.5 * np.sum(np.cross(w, p) ** 2, axis=1) + 1e-300
    assert np.all(np.abs(jacobi - sol.jacobi_integral) <= 1e-12 * terms), "rotating frame: Jacobi integral not constant"


@st.composite
def _rotating_params(draw):
    rate = draw(st.floats(-2.0, 2.0))
    return {"axis": draw(st.sampled_from([[0.0, 0.0, 1.0], [1.0, 1.0, 0.0], [0.3, -0.2, 2.0]])), "rate": rate,
            "p0": draw(st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3)),
            "v0": draw(st.lists(st.floats(-3.0, 3.0), min_size=3, max_size=3)),
            "dt": draw(st.sampled_from([0.01, 0.02])), "steps": draw(st.integers(1, 30))}


def constant_thrust(m0: float, burn: float, u_rel: list, g: list, v0: list, frame: str, dt: float, steps: int) -> None:
    """A particle with MassFlow(rate) and Thrust(u_rel) under UniformGravity, simulated with rk4, against
    ConstantThrustSolution (the rate a fraction `burn` of m0 per run): RK4's error at dt/2 within twice its
    Richardson estimate plus the runs' round-off; the mass exactly m0 + rate t up to 4 ulp."""
    duration = dt * steps
    rate = -burn * m0 / max(duration, dt)
    sol = rd.ConstantThrustSolution(m0, rate, u_rel, g_W=g, v0_W=v0)
    scene = rd.Scene(bodies=[rd.Particle(m0)], elements=[rd.UniformGravity(g_W=g), rd.Thrust(0, u_rel, frame=frame)],
                     mass_flows=[rd.MassFlow(rate)])
    runs = [rd.simulate(scene, [rd.ParticleState(v_W=v0)], h, steps * k, method="rk4", record_every=k)
            for h, k in ((dt, 1), (dt / 2, 2))]
    t = np.asarray(runs[1].t)
    p, v, m = sol.at(t)
    for name, exact in (("p_W", p), ("v_W", v)):
        coarse, fine = (np.asarray(getattr(r, name))[:, 0] for r in runs)
        scale = float(np.max(np.abs(exact))) + 1.0
        bound = 2.0 * float(np.max(np.abs(coarse - fine))) / 15.0 + 16 * EPS * scale * (2 * steps + 1)
        worst = float(np.max(np.abs(fine - exact)))
        assert worst <= bound, f"constant thrust: {name} of rk4 at dt/2 differs from the exact solution by {worst:.3g} > {bound:.3g}"
    mass = np.asarray(runs[1].mass)[:, 0]
    assert np.all(np.abs(mass - m) <= 4 * EPS * m0 * (2 * steps + 1)), f"constant thrust: mass {mass[-1]!r} != {m[-1]!r}"


@st.composite
def _thrust_params(draw):
    steps = draw(st.integers(1, 30))
    # at most 2 % of the mass burnt per step: RK4 in its asymptotic regime (h |rate| / m small), where the
    # Richardson estimate bounds its error
    return {"m0": draw(st.floats(0.1, 100.0)), "burn": draw(st.floats(0.0, min(0.9, 0.02 * steps))),
            "u_rel": draw(st.lists(st.floats(-100.0, 100.0), min_size=3, max_size=3)),
            "g": draw(st.lists(st.floats(-10.0, 10.0), min_size=3, max_size=3)),
            "v0": draw(st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3)),
            "frame": "world", "dt": draw(st.sampled_from([0.01, 0.05])), "steps": steps}


@st.composite
def _units_params(draw):
    from scene_files import scene_data as data

    return {"scene": _plain(draw(data())), "picks": draw(st.lists(st.integers(0, 5), min_size=200, max_size=200))}


@st.composite
def _unit_string_params(draw):
    unit = draw(st.sampled_from(sorted(u for u in UNITS if u != "1")))
    x = draw(st.one_of(st.floats(-1e6, 1e6), st.builds(lambda m, e: m * 10.0**e, st.floats(1.0, 10.0), st.integers(-300, 290))))
    return {"x": x, "unit": unit, "pick": draw(st.integers(0, 5))}


@st.composite
def _round_trip_params(draw):
    return {"scene": _scene_text(draw)}


STRATEGIES = {
    "batch_equals_serial": _batch_params(),
    "simd_matches_scalar": _simd_params(),
    "scene_file_round_trip": _round_trip_params(),
    "units_match_si": _units_params(),
    "unit_string_value": _unit_string_params(),
    "unit_decimal_comma": st.fixed_dictionaries({"x": st.floats(0.001, 1000.0), "unit": st.sampled_from(["m", "kg", "s"]),
                                                 "pick": st.integers(0, 5)}),
    "monte_carlo_reproducible": _monte_carlo_params(),
    "cli_matches_api": _cli_params(),
    "lagrange_top_invariants": _top_params(),
    "compound_pendulum_invariants": _pendulum_params(),
    "pivoted_simulate_is_its_scene": _pivoted_params(),
    "rotating_frame_particle": _rotating_params(),
    "constant_thrust": _thrust_params(),
}

if sys.version_info < (3, 11):  # pragma: no cover
    raise ImportError("the fuzz's properties need Python 3.11 (tomllib)")
