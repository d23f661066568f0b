"""The accuracy of the error estimate itself: `simulate(..., error=True)`'s `result.error` against the true error
on every shipped problem with an exact reference, for every finite-order method that applies, at three steps.

  python bench/python/accuracy_table.py            # writes docs/accuracy.md
  python bench/python/accuracy_table.py --out FILE # the page to FILE instead
  python bench/python/accuracy_table.py --print    # print the table only

A cell is (problem, method, dt). Its run records at T/4, T/2, 3T/4 and T (every record a common record of the
runs at h, 2h, 4h, so every record is checked); the cell's figures are those of the last record: the true
error against the exact reference, the estimate, their ratio (the effectivity, estimate / true error) and the
verdict. The quantity is the attitude [rad] (geodesic angle) of a body that turns, the position [m] of
particles; of several bodies the largest over the bodies (of the estimate and of the true error alike).
Where the true error is below the round-off of the run (`round_off_floor`), the ratio measures round-off, not
truncation: such a cell counts as "at round-off" (it passes when the estimate is at least half of the true
error, as every cell must).

The summary: the flag rate (share of cells not reliable), the share of the reliable cells above round-off whose
effectivity lies in [0.5, 2], and the worst under-estimate among the reliable cells (smallest effectivity); the same
for the cells judged by their quantity's own verdict (`result.error.reliable_for`).
tests/python/test_effectivity.py asserts the same on a reduced grid and on adversarial cases.

The document records how it was made (command, date, machine, rigiddyn revision) and a digest of its INPUTS;
tests/python/test_generated_docs.py fails once any input differs, naming the command that regenerates it.
"""


import argparse
import math
import sys
import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np
import rigiddyn
from provenance import SIMULATION_INPUTS, markdown_comment, measured_sentence, stamp
from rigiddyn.scene_precision import exact_reference
from rigiddyn.work_precision import reference_states

ROOT = Path(__file__).resolve().parents[2]
# what the figures depend on: this script, what a simulate runs (with its estimate), the scene layer, the exact
# references of scenes and the shipped scenes
INPUTS = ["bench/python/accuracy_table.py", *SIMULATION_INPUTS, "cpp/include/rigiddyn/scene/*",
          "cpp/include/rigiddyn/scene/elements/*", "cpp/include/rigiddyn/scene/fast/*",
          "cpp/include/rigiddyn/scene/kinds/*", "cpp/src/scene/*",
          "cpp/bindings/bind_scene*.cpp", "cpp/bindings/scene_run.hpp", "cpp/bindings/bind_pivoted.cpp",
          "cpp/bindings/bind_exact_dynamics.cpp", "cpp/bindings/bind_orbit.cpp", "python/rigiddyn/scene_file.py",
          "python/rigiddyn/units.py",  # the scene file's number form and units
          "python/rigiddyn/scenes/*.toml", "python/rigiddyn/problems/*.toml"]
REGENERATE = ("cmake --build build/<dir> --target _core && "
              "PYTHONPATH=build/<dir>/python python3 bench/python/accuracy_table.py  (seconds)")

EFFECTIVITY = (0.5, 2.0)  # the window a reliable estimate promises (GlobalError)
FINITE_ORDER = [m["name"] for m in rigiddyn.methods() if m["order"] > 0]


def round_off_floor(size: float, steps: int) -> float:
    """The round-off a run of `steps` steps (and its exact reference) can carry in a quantity of size `size`:
    64 eps per step relative to max(size, 1) (the estimator's own bound is 8 eps per step; the references,
    elliptic functions and Kepler's equation, add a few eps more)."""
    return 64.0 * np.finfo(float).eps * max(size, 1.0) * steps


@dataclass(frozen=True)
class Case:
    """A problem with an exact reference: `simulate(method, dt, steps, record_every)` returns the run (with its
    estimate), `true_error(run)` the true error of `quantity` at each record, (n,) (the largest over the bodies),
    `size` the quantity's scale for the round-off floor; `horizon` [s] and the three steps `dts` [s]."""

    name: str
    quantity: str  # "attitude" [rad] or "position" [m]
    simulate: Callable[[str, float, int, int], Any]
    true_error: Callable[[Any], np.ndarray]
    horizon: float
    dts: tuple[float, ...]
    size: float = 1.0
    methods: tuple[str, ...] = tuple(FINITE_ORDER)


# ----------------------------------------------------------------------------------------------------------------
# the problems


def free_body(name: str, inertia: tuple[float, float, float], w_B: tuple[float, float, float], horizon: float,
              dts: tuple[float, ...]) -> Case:
    """A torque-free body against rigiddyn.TorqueFreeSolution (the method 'exact')."""
    body = rigiddyn.RigidBody(1.0, np.diag(inertia))
    start = rigiddyn.RigidBodyState(w_B=w_B)
    exact = rigiddyn.TorqueFreeSolution(np.diag(inertia), start.q_WB, w_B)

    def run(method: str, dt: float, steps: int, every: int) -> Any:
        return rigiddyn.simulate(body, start, dt=dt, steps=steps, method=method, record_every=every,
                                 accuracy_level=None)  # coarse on purpose: the table measures the estimate

    def true_error(r: Any) -> np.ndarray:
        q, _ = exact.state_at(r.t)
        return np.asarray(rigiddyn.angular_distance(r.body(0).q_WB, q))

    return Case(name, "attitude", run, true_error, horizon, dts)


def shipped_problem(name: str, label: str, quantity: str, horizon: float, dts: tuple, size: float = 1.0) -> Case:
    """A shipped problem file with a closed form (torque-free rotation, a ballistic centre of mass) against
    rigiddyn.work_precision.reference_states."""
    problem = rigiddyn.load_problem(name).with_horizon(horizon)

    def run(method: str, dt: float, steps: int, every: int) -> Any:
        return rigiddyn.simulate(problem.body(), problem.initial_state(), dt=dt, steps=steps, method=method,
                                 record_every=every, loads=list(problem.loads), gravity=problem.gravity,
                                 accuracy_level=None)  # coarse on purpose

    def true_error(r: Any) -> np.ndarray:
        exact = reference_states(problem, np.asarray(r.t))
        records = r.body(0)
        if quantity == "attitude":
            return np.asarray(rigiddyn.angular_distance(records.q_WB, exact.q_WB))
        return np.linalg.norm(np.asarray(records.p_W) - exact.p_W, axis=1)

    return Case(f"{label} (shipped {name})", quantity, run, true_error, horizon, dts, size)


def scene_case(name: str, scene: Any, initial: list[Any], quantity: str, horizon: float, dts: tuple[float, ...],
               reference: Callable[[np.ndarray], np.ndarray] | None = None, size: float = 1.0) -> Case:
    """A scene against its closed form (rigiddyn.scene_precision.exact_reference, or `reference(t)`, the exact
    p_W (n, nb, 3) at the times t); the methods: those the scene compiles for (a compatibility warning, e.g. a
    splitting falling to order 1, kept: the estimate must use the order the scene has)."""
    closed = exact_reference(scene, initial) if reference is None else None

    def applies(method: str) -> bool:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", rigiddyn.SceneCompatibilityWarning)
                scene.compile(method=method)
            return True
        except ValueError:
            return False

    def run(method: str, dt: float, steps: int, every: int) -> Any:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", rigiddyn.SceneCompatibilityWarning)
            return rigiddyn.simulate(scene, initial, dt=dt, steps=steps, method=method, record_every=every,
                                     accuracy_level=None)  # coarse on purpose

    def true_error(r: Any) -> np.ndarray:
        t = np.asarray(r.t)
        if quantity == "attitude":
            q = closed.states(t).q_WB
            return np.max([rigiddyn.angular_distance(r.q_WB[:, b], q[:, b]) for b in range(q.shape[1])], axis=0)
        p = closed.states(t).p_W if reference is None else reference(t)
        return np.max(np.linalg.norm(np.asarray(r.p_W) - p, axis=2), axis=1)

    return Case(name, quantity, run, true_error, horizon, dts, size, tuple(m for m in FINITE_ORDER if applies(m)))


def pendulum(theta: float) -> tuple[Any, list[Any]]:
    """The shipped pendulum's rod (1 m, 1 kg, pinned at one end, gravity along -y) released at rest from theta."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedPlanarBody(1.0, 1.0 / 12.0, (0.0, -0.5)), name="rod")
    scene.add(rigiddyn.UniformGravity(g_W=(0.0, -9.81, 0.0)))
    return scene, [rigiddyn.PivotedPlanarBodyState(theta=theta)]


def carousel(rate: float = 1.0) -> tuple[Any, list[Any]]:
    """Two free particles seen from a frame turning at `rate` [rad/s] about (0.3, 0.4, 1)."""
    scene = rigiddyn.Scene()
    for i in range(2):
        scene.add_body(rigiddyn.Particle(1.0 + i), name=f"p{i}")
    scene.frame = rigiddyn.SceneFrame.rotating((0.3, 0.4, 1.0), rate)
    return scene, [rigiddyn.ParticleState(p_W=(1.0, 0.5, 0.0), v_W=(0.1, 0.0, 0.2)),
                   rigiddyn.ParticleState(p_W=(2.0, 0.5, -0.2), v_W=(0.1, -0.3, 0.2))]


def kepler_reference(initial: list[Any], gm: float) -> Callable[[np.ndarray], np.ndarray]:
    """p_W (n, 1, 3) of the Kepler orbit from the initial state: rigiddyn.kepler_propagate."""
    r0, v0 = np.asarray(initial[0].p_W, float), np.asarray(initial[0].v_W, float)
    return lambda t: np.asarray(rigiddyn.kepler_propagate(r0, v0, gm, t), float)[0].reshape(len(t), 1, 3)


def chain_reference(scene: Any, initial: list[Any]) -> Callable[[np.ndarray], np.ndarray]:
    """p_W (n, nb, 3) of a chain of particles along x joined by springs and dampers (each a SpringDamper between
    neighbours or to a wall anchor at the origin), exactly linear along x: y' = A y with y = (x - x_rest, x') and
    A = [[0, I], [-M^-1 K, -M^-1 C]], y(t) = V exp(L t) V^-1 y0 with A = V L V^-1 (its modes; Meirovitch,
    "Fundamentals of Vibrations", ch. 4 and 7)."""
    n = len(scene.bodies)
    mass = np.array([b.mass for b in scene.bodies])
    K, C = np.zeros((n, n)), np.zeros((n, n))
    x_rest = np.zeros(n)
    for e in scene.elements:
        a, b = e.body_a, e.body_b
        pairs = [(a, 1.0)] + ([(b, -1.0)] if b is not None and b >= 0 else [])
        for i, si in pairs:
            for j, sj in pairs:
                K[i, j] += si * sj * e.stiffness
                C[i, j] += si * sj * e.damping
    # the rest positions: the wall at 0, each spring at its rest length from the body before it
    for e in sorted(scene.elements, key=lambda e: e.body_a):
        x_rest[e.body_a] = (x_rest[e.body_b] if e.body_b is not None and e.body_b >= 0 else 0.0) + e.rest_length
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K / mass[:, None], -C / mass[:, None]]])
    eigenvalues, V = np.linalg.eig(A)
    y0 = np.concatenate([[s.p_W[0] for s in initial] - x_rest, [s.v_W[0] for s in initial]])
    c = np.linalg.solve(V, y0)

    def at(t: np.ndarray) -> np.ndarray:
        y = np.real((V[None, :n, :] * (c * np.exp(np.outer(t, eigenvalues)))[:, None, :]).sum(axis=2))
        p = np.zeros((len(t), n, 3))
        p[:, :, 0] = y + x_rest
        return p

    return at


def cases() -> list[Case]:
    """The problems of the table: every shipped problem with an exact reference."""
    out = [
        shipped_problem("t_handle", "free body: T-handle", "attitude", 4.0, (0.004, 0.002, 0.001)),
        shipped_problem("fast_top", "free body: fast symmetric top", "attitude", 1.0, (0.002, 0.001, 0.0005)),
        shipped_problem("projectile", "ballistic spinning ball", "position", 4.0, (0.1, 0.05, 0.025), size=60.0),
        free_body("free body: I = (1, 2, 3), near the middle-axis separatrix", (1.0, 2.0, 3.0), (0.02, 1.0, 0.02),
                  20.0, (0.05, 0.025, 0.0125)),
    ]
    top, top_initial, _ = rigiddyn.load_scene("heavy_top")
    out.append(scene_case("Lagrange top (shipped heavy_top)", top, top_initial, "attitude", 1.0,
                          (0.002, 0.001, 0.0005)))
    rod, rod_initial = pendulum(math.pi - 1e-3)
    out.append(scene_case("compound pendulum, 1 mrad below the separatrix", rod, rod_initial, "attitude", 5.0,
                          (0.01, 0.005, 0.0025)))
    rocket, rocket_initial, _ = rigiddyn.load_scene("rocket")
    out.append(scene_case("constant-thrust burn (shipped rocket)", rocket, rocket_initial, "position", 60.0,
                          (0.5, 0.25, 0.125), size=1e5))
    frame, frame_initial = carousel()
    out.append(scene_case("free particles in a rotating frame", frame, frame_initial, "position", 10.0,
                          (0.05, 0.025, 0.0125), size=3.0))
    kepler, kepler_initial, _ = rigiddyn.load_scene("kepler")
    gm = next(e.gm for e in kepler.elements if type(e).__name__ == "PointMassGravity")
    period = 2.0 * math.pi * math.sqrt(7.0e6**3 / gm)
    out.append(scene_case("Kepler orbit, e = 0.1, one period (shipped kepler)", kepler, kepler_initial, "position",
                          period, tuple(period / n for n in (256, 512, 1024)), kepler_reference(kepler_initial, gm),
                          size=7.0e6))
    chain, chain_initial, _ = rigiddyn.load_scene("spring_chain")
    out.append(scene_case("spring-damper chain, normal modes (shipped spring_chain)", chain, chain_initial,
                          "position", 10.0, (0.02, 0.01, 0.005), chain_reference(chain, chain_initial), size=3.0))
    return out


# ----------------------------------------------------------------------------------------------------------------
# the cells


@dataclass(frozen=True)
class Cell:
    """One (problem, method, dt): the true error and the estimate at the last record, the verdict there, and the
    round-off floor below which the true error measures round-off."""

    problem: str
    method: str
    dt: float
    true: float
    estimate: float
    verdict: str
    floor: float
    quantity_reliable: bool  # result.error.reliable_for(quantity) at the last record

    @property
    def reliable(self) -> bool:
        return self.verdict == "reliable"

    @property
    def at_round_off(self) -> bool:
        return self.true <= self.floor

    @property
    def effectivity(self) -> float:
        return self.estimate / self.true if self.true > 0 else math.inf

    @property
    def under_estimated(self) -> bool:
        """Reliable and the true error beyond twice the estimate (plus the round-off floor)."""
        return self.reliable and not self.true <= 2.0 * self.estimate + self.floor

    def alone(self) -> "Cell":
        """The cell judged by its quantity's verdict alone (reliable where reliable_for(quantity) is)."""
        return Cell(self.problem, self.method, self.dt, self.true, self.estimate,
                    "reliable" if self.quantity_reliable else "not reliable for its quantity", self.floor,
                    self.quantity_reliable)


def measure(case: Case, method: str, dt: float) -> Cell:
    """The cell of `case` at `method` and `dt` (the horizon a whole number of 16 steps: 4 records, each on a
    multiple of 4 steps)."""
    steps = 16 * max(1, round(case.horizon / dt / 16))
    dt = case.horizon / steps
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # a diverging run warns; its cell says so
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)
        r = case.simulate(method, dt, steps, steps // 4)
    estimate = np.asarray(getattr(r.error, case.quantity)).reshape(len(r.t), -1)
    finite = np.all(np.isfinite(np.asarray(r.q_WB).reshape(len(r.t), -1)), axis=1)
    true = case.true_error(r)[-1] if len(r.t) == steps // (steps // 4) + 1 and finite[-1] else math.inf
    return Cell(case.name, method, dt, float(true), float(np.max(estimate[-1])), r.error.verdict[-1],
                round_off_floor(case.size, steps), bool(r.error.reliable_for(case.quantity)[-1]))


def cells(selected: list[Case] | None = None) -> list[Cell]:
    """Every cell of the cases (default: all of `cases()`)."""
    return [measure(c, m, dt) for c in (cases() if selected is None else selected) for m in c.methods for dt in c.dts]


@dataclass(frozen=True)
class Summary:
    cells: int
    reliable: int
    measured: int  # reliable and above round-off
    in_window: int  # of those, effectivity in EFFECTIVITY
    under_estimated: int  # reliable with the true error beyond twice the estimate
    worst: float  # the smallest effectivity of a measured cell

    @property
    def flag_rate(self) -> float:
        return 1.0 - self.reliable / self.cells

    @property
    def in_window_share(self) -> float:
        return self.in_window / self.measured if self.measured else math.nan


def summarize(all_cells: list[Cell]) -> Summary:
    measured = [c for c in all_cells if c.reliable and not c.at_round_off]
    inside = [c for c in measured if EFFECTIVITY[0] <= c.effectivity <= EFFECTIVITY[1]]
    return Summary(len(all_cells), sum(c.reliable for c in all_cells), len(measured), len(inside),
                   sum(c.under_estimated for c in all_cells), min((c.effectivity for c in measured), default=math.nan))


# ----------------------------------------------------------------------------------------------------------------
# the page


def fmt(x: float) -> str:
    return "inf" if math.isinf(x) else ("nan" if math.isnan(x) else f"{x:.2e}")


def table(all_cells: list[Cell]) -> str:
    lines = ["| problem | method | dt [s] | true error | estimate | effectivity | verdict | its quantity alone |",
             "|---|---|---|---|---|---|---|---|"]
    for c in all_cells:
        ratio = "(round-off)" if c.at_round_off else f"{c.effectivity:.2f}"
        verdict = c.verdict.replace("|", "\\|")  # a literal bar inside a table cell
        alone = "reliable" if c.quantity_reliable else "not reliable"
        lines.append(f"| {c.problem} | {c.method} | {c.dt:.4g} | {fmt(c.true)} | {fmt(c.estimate)} | {ratio} "
                     f"| {verdict} | {alone} |")
    return "\n".join(lines)


def summary_text(s: Summary, alone: Summary) -> str:
    return (f"- cells: {s.cells}; reliable: {s.reliable}; **flag rate** (not reliable): {s.flag_rate:.0%}\n"
            f"- reliable cells above round-off: {s.measured}; **effectivity in [0.5, 2]**: {s.in_window} "
            f"({s.in_window_share:.1%})\n"
            f"- **worst reliable under-estimate**: effectivity {s.worst:.2f}; reliable cells whose true error "
            f"exceeds twice the estimate: {s.under_estimated}\n"
            f"- judged by the quantity's own verdict (`result.error.reliable_for(quantity)`): "
            f"reliable {alone.reliable} "
            f"(flag rate {alone.flag_rate:.0%});\n  above round-off {alone.measured}, effectivity in [0.5, 2] "
            f"{alone.in_window} ({alone.in_window_share:.1%});\n  worst under-estimate {alone.worst:.2f}; true error "
            f"beyond twice the estimate: {alone.under_estimated}\n")


HEADER = """# Accuracy of the error estimate

Generated by `python bench/python/accuracy_table.py` (do not edit by hand; regenerate it when
`tests/python/test_generated_docs.py` says its inputs changed). {measured}
The figures are deterministic.

Every run of `rigiddyn.simulate` carries an estimate of its own global error (`result.error`, a
`GlobalError`: global Richardson extrapolation over runs at h, 2h and 4h with an observed-order check, see
[Models and integrators](guide/models_integrators.md)). This page measures that estimate against the true
error, on every shipped problem that has an exact reference, for every finite-order method that applies to
it (a scene's method that falls in order with the scene's elements is kept: the estimate must use the
order the scene has), at three steps.

Each cell runs T with 4 records (at T/4, T/2, 3T/4, T); its figures are those at T. The quantity: the
attitude [rad] (geodesic angle to the exact attitude) of a body that turns, the position [m] of particles;
of several bodies the largest. **Effectivity** = estimate / true error: 1 is a perfect estimate, below 1 an
under-estimate (the dangerous side). A cell whose true error is below the round-off of its run (64 eps per
step of the quantity's scale) is marked "(round-off)": there the estimate is a round-off bound. A cell that is
not reliable names why in its verdict (the estimate is still given, and must not be trusted). A record's verdict
covers every quantity; the last column judges the cell's quantity by its own check alone
(`result.error.reliable_for`), which a cell may pass where another quantity fails (a damped system's energy).

## Summary

{summary}
The contract (`GlobalError`): on reliable records the effectivity lies in [0.5, 2]; `tests/python/test_effectivity.py`
asserts it on a reduced grid of these problems and on adversarial runs (a force switching inside steps, steps
beyond the stability limit, separatrices, a chaotic three-body run, subnormal transverse rates).

## Every cell

"""

FOOTER = "Run time of the whole table: {elapsed:.1f} s on the machine above.\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="markdown file (default: docs/accuracy.md)")
    parser.add_argument("--print", action="store_true", help="print the table only")
    args = parser.parse_args(argv)
    made = stamp(INPUTS)
    start = time.perf_counter()
    all_cells = cells()
    elapsed = time.perf_counter() - start
    s, alone = summarize(all_cells), summarize([c.alone() for c in all_cells])
    text = table(all_cells)
    print(text)
    print(summary_text(s, alone))
    print(f"{len(all_cells)} cells in {elapsed:.1f} s")
    if not args.print:
        out = Path(args.out) if args.out else ROOT / "docs" / "accuracy.md"
        out.write_text(HEADER.format(measured=measured_sentence(made), summary=summary_text(s, alone)) + text + "\n\n"
                       + FOOTER.format(elapsed=elapsed) + "\n" + markdown_comment(made))
        print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
