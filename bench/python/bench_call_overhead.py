"""The fixed cost of a call from Python: rigiddyn.step (positional, and with keyword arguments) and
rigiddyn.simulate(steps=10) against a bare pybind11 call (a property getter of a bound class,
RigidBody.mass: the binding layer's own floor) and, where mujoco is importable, MuJoCo's mj_step on a
free body, all in one run, each the best of several rounds of a loop of calls.

simulate's fixed cost is its time less that of its steps: the cost per step is the slope between
simulate(steps=10, error=False) and simulate(steps=10 + k, error=False) (k = 1000), so that "fixed cost" is what
the call costs besides stepping: arguments, the result, the energy and momentum balance and its check. With
error=True, the default, a run whose balances close whatever the estimate says makes its global error estimate (its
two coarse runs compared with its records) on the first read of result.error, so its steps are those of
error=False, short or long. The result's arrays are made on their first read: "... and q_WB[-1]" adds what a control
loop reading the last attitude pays for one, "... and error.attitude[-1]" what reading the estimate costs.

    python bench/python/bench_call_overhead.py           # 20 000 calls a round, 7 rounds
    python bench/python/bench_call_overhead.py --small   # 2 000 calls a round, 3 rounds (what ctest runs)

Prints one line per case with its time per call [us] and its ratio to the bare call, then the
"ratio ..." lines of the other benchmarks (bench/python/_bench_common.py).
"""


import rigiddyn as rd
from _bench_common import parse_small, per_call
from _bench_common import report_ratio as report

BODY = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
DT = 0.01
EXTRA_STEPS = 1000  # the steps added to measure the cost per step


def mujoco_step():
    """mj_step on a free body (a box of 1 kg, no contact, no gravity), or None when mujoco is not importable."""
    try:
        import mujoco
    except ImportError:
        return None
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><option gravity="0 0 0" timestep="0.01"/><worldbody><body><freejoint/>'
        '<geom type="box" size=".1 .2 .3" mass="1" contype="0" conaffinity="0"/></body></worldbody></mujoco>')
    data = mujoco.MjData(model)
    data.qvel[3:6] = [0.1, 1.0, 0.1]
    return lambda: mujoco.mj_step(model, data)


def main():
    args = parse_small(__doc__, "2 000 calls a round, 3 rounds, instead of 20 000 and 7")
    calls, rounds = (2_000, 3) if args.small else (20_000, 7)
    long_calls = max(calls // 100, 20)

    def time_of(fn, n=calls):
        return per_call(fn, n, rounds)

    bare = time_of(lambda: BODY.mass)
    positional, keywords = "step(body, state, dt, 'rk4', None, None, 0.0)", "step(body, state, dt=dt, method='rk4', t=0.0)"
    cases = {
        "step(body, state, dt)": time_of(lambda: rd.step(BODY, STATE, DT)),
        "step(body, state, dt=dt)": time_of(lambda: rd.step(BODY, STATE, dt=DT)),
        positional: time_of(lambda: rd.step(BODY, STATE, DT, "rk4", None, None, 0.0)),
        keywords: time_of(lambda: rd.step(BODY, STATE, dt=DT, method="rk4", t=0.0)),
    }
    plain_step = None  # the cost per step of a run without its estimate
    for error in (False, True):
        short = time_of(lambda: rd.simulate(BODY, STATE, DT, steps=10, error=error), calls // 4)
        long = time_of(lambda: rd.simulate(BODY, STATE, DT, steps=10 + EXTRA_STEPS, error=error), long_calls)
        per_step = (long - short) / EXTRA_STEPS
        plain_step = per_step if plain_step is None else plain_step
        cases[f"simulate(steps=10, error={error})"] = short
        cases[f"simulate(steps=10, error={error}) fixed cost"] = short - 10 * plain_step
        cases[f"simulate(error={error}) per step"] = per_step
        cases[f"simulate(steps=10, error={error}) and q_WB[-1]"] = time_of(
            lambda: rd.simulate(BODY, STATE, DT, steps=10, error=error).q_WB[-1], calls // 4)
    cases["simulate(steps=10) and error.attitude[-1]"] = time_of(
        lambda: rd.simulate(BODY, STATE, DT, steps=10).error.attitude[-1], calls // 4)
    mj = mujoco_step()
    if mj is not None:
        cases["mujoco.mj_step(model, data)"] = time_of(mj)

    print(f"{'bare pybind11 call (RigidBody.mass)':52s} {bare * 1e6:8.3f} us")
    for case, seconds in cases.items():
        print(f"{case:52s} {seconds * 1e6:8.3f} us  {seconds / bare:7.1f} x bare")
    if mj is None:
        print("mujoco is not importable: no mj_step comparison")
    print(f"step with keywords / positional, the same arguments: {cases[keywords] / cases[positional]:.2f} "
          f"(dt alone: {cases['step(body, state, dt=dt)'] / cases['step(body, state, dt)']:.2f})")
    report("step", calls, cases["step(body, state, dt)"] * calls, bare * calls, "bare_pybind11_call")
    report("simulate_steps_10", calls, cases["simulate(steps=10, error=False)"] * calls, bare * calls,
           "bare_pybind11_call")
    if mj is not None:
        report("step", calls, cases["step(body, state, dt)"] * calls, cases["mujoco.mj_step(model, data)"] * calls,
               "mj_step")


if __name__ == "__main__":
    main()
