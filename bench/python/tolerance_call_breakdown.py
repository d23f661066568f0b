"""Where the instructions of a call of simulate(..., tolerance=) go: the call, the plain run at the call's own final
(method, steps) with error=False, and that run with its global error estimate (read), each counted by callgrind as
bench_tolerance.py --instructions counts (counted_instructions: the second of two runs, between os.getppid markers).
Printed per problem: the call and the estimated run over the plain run; the call less the estimated run is the pilots,
the refinements and the rest. Needs valgrind (docs/perf/scenes.md §4.21 has the figures).

    PYTHONPATH=build/<dir>/python:bench/python python3 bench/python/tolerance_call_breakdown.py
"""

import warnings

import numpy as np

import rigiddyn as rd
from bench_tolerance import call_statement, counted_instructions, plain_statement, problems

# (problem, tolerance relative to the measure's size: rad for an attitude, the largest distance of a position)
ROWS = [("kepler", 1e-5), ("spring_chain", 1e-3), ("pendulum", 1e-7), ("j2_orbit", 1e-7), ("three_body", 1e-5),
        ("box_on_springs", 1e-5)]


def tolerance_of(p, relative):
    """The absolute tolerance of bench_tolerance.py's rows: `relative` [rad] for an attitude, else times the largest
    distance from W's origin over a run of 1024 steps [m]."""
    if p.measure == "attitude":
        return relative
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = rd.simulate(p.model, p.initial, p.duration / 1024, steps=1024, error=False, controller=p.controller)
    return relative * float(np.max(np.linalg.norm(np.asarray(r.p_W), axis=-1)))


def main():
    print(f"{'problem':16s} {'tolerance':>10s} {'method':8s} {'steps':>6s} {'call/plain':>10s} {'estimate':>9s} "
          f"{'pilots and the rest':>20s}")
    for name, relative in ROWS:
        p = problems(only=name)[0]
        tolerance = tolerance_of(p, relative)
        choice = rd.simulate(p.model, p.initial, duration=p.duration, tolerance=tolerance, measure=p.measure,
                             controller=p.controller).choice
        call, plain, estimated = counted_instructions(
            p, [call_statement(tolerance), plain_statement(choice.method, choice.steps),
                plain_statement(choice.method, choice.steps, error=True)])
        print(f"{name:16s} {tolerance:10.3g} {choice.method:8s} {choice.steps:6d} {call / plain:10.2f} "
              f"{(estimated - plain) / plain:9.2f} {(call - estimated) / plain:20.2f}", flush=True)


if __name__ == "__main__":
    main()
