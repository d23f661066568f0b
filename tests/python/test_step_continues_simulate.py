"""A loop of `step` calls, each from the state the last returned, at the times t0 + i dt, gives `simulate`'s records
bit for bit; so does a run started from a recorded state, continued by `simulate`. The same steps (a step across a
load's switch time split at the same place) from the same bits: an attitude already of unit norm to round-off is
taken as it is, not normalised again (q / |q| formed twice may move by an ulp, and the runs then drift apart).
"""

import numpy as np
import pytest

import rigiddyn as rd

DT, STEPS, T0 = 0.01, 40, 0.25
# the loads on for 0.0333 s to 0.0777 s after T0: both switch times inside a step
WINDOW = {"t_start": T0 + 0.0333, "t_end": T0 + 0.0777}
# every method that steps (implicit_midpoint's iteration stops on the motion's coordinates alone, not on the run's
# accumulated works, which a step starts anew)
METHODS = ["explicit_euler", "semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic", "rk4", "rkmk4",
           "implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"]
Q0 = rd.rotvec_to_quat([0.3, -0.2, 0.9])
RIGID = rd.RigidBody(2.0, [1.0, 2.0, 3.0])


def planar_case(window):
    load = rd.AppliedLoad(force=[0.3, -0.2, 0.0], torque=[0.0, 0.0, 0.1], frame="body", **window)
    state = rd.PlanarBodyState(p_W=[0.1, 0.2], theta=0.4, v_W=[1.0, 0.5], omega=2.0)
    return rd.PlanarBody(2.0, 0.5), state, {"loads": [load], "gravity": [0.0, -9.81, 0.0]}


def rigid_case(window):
    load = rd.AppliedLoad(force=[0.0, 0.2, 1.0], torque=[0.1, 0.0, -0.05], frame="body", **window)
    return RIGID, rd.RigidBodyState(q_WB=Q0, v_W=[1.0, 0.0, 0.0], w_B=[0.1, 1.0, 0.2]), {"loads": [load]}


def pivoted_case(window):
    top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    load = rd.AppliedLoad(torque=[0.0, 0.02, 0.0], frame="body", **window)
    return top, rd.PivotedBodyState(q_WB=Q0, w_B=[0.2, -0.1, 20.0]), {"loads": [load], "gravity": True}


def gyrostat_case(window):
    sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05, motor_torque=0.01)])
    load = rd.AppliedLoad(torque=[0.3, 0.0, 0.0], frame="body", **window)
    return sat, rd.GyrostatState(q_WB=Q0, w_B=[0.01, 0.02, 0.1], wheel_speeds=[50.0]), {"loads": [load]}


def scene_case(window):
    loads = rd.ScheduledLoads(body=0, loads=[rd.AppliedLoad(force=[0.0, 0.0, 3.0], frame="body", **window)])
    spring = rd.SpringDamper(body_a=0, body_b=1, stiffness=20.0, rest_length=0.5,
                             point_a_B=[0.2, 0.05, 0.0], point_b=[-0.2, 0.0, 0.1])
    scene = rd.Scene([RIGID, rd.RigidBody(1.0, [0.2, 0.3, 0.4])], elements=[rd.UniformGravity(), spring, loads])
    states = [rd.RigidBodyState(q_WB=Q0, w_B=[0.3, 1.0, 0.2]),
              rd.RigidBodyState(p_W=[0.6, 0.0, 0.0], q_WB=rd.rotvec_to_quat([0.0, 1.0, 0.0]), w_B=[2.0, 0.0, 0.1])]
    return scene, states, {}


CASES = {"planar": planar_case, "rigid": rigid_case, "pivoted": pivoted_case, "gyrostat": gyrostat_case,
         "scene": scene_case}
# a gyrostat has no closed-form free rotation: no kick-drift-kick method
RUNS = [(case, method) for case in CASES for method in METHODS
        if case != "gyrostat" or method in ("rk4", "rkmk4", "implicit_midpoint")]


def columns(state, result, i, b):
    """(state's array, record i's array of body b) for each field of the state's kind (a planar body's p_W, v_W in
    the plane and ω about z; its angle θ moves them on the next step)."""
    if hasattr(state, "theta"):
        return [(np.asarray(state.p_W), result.p_W[i, b, :2]), (np.asarray(state.v_W), result.v_W[i, b, :2]),
                (np.asarray(state.omega), result.w_B[i, b, 2])]
    pairs = [(np.asarray(getattr(state, name)), getattr(result, name)[i, b])
             for name in ("p_W", "q_WB", "v_W", "w_B") if hasattr(state, name)]
    if hasattr(state, "wheel_speeds"):
        pairs.append((np.asarray(state.wheel_speeds), result.wheel_speed[i]))
    return pairs


def recorded_state(like, result, i, b):
    """Record i of body b as a state of the kind of `like`."""
    kind = type(like)
    if kind is rd.PivotedBodyState:
        return kind(q_WB=result.q_WB[i, b], w_B=result.w_B[i, b])
    fields = {name: getattr(result, name)[i, b] for name in ("p_W", "q_WB", "v_W", "w_B")}
    if kind is rd.GyrostatState:
        fields["wheel_speeds"] = result.wheel_speed[i]
    return kind(**fields)


def assert_same_bits(states, result, i, what):
    for b, state in enumerate(states if isinstance(states, list) else [states]):
        for value, recorded in columns(state, result, i, b):
            assert np.array_equal(value, recorded), f"{what}: record {i}, body {b}: {value} != {recorded}"


@pytest.mark.parametrize(("case", "method"), RUNS)
def test_steps_from_returned_states_are_the_records(case, method):
    model, state, kwargs = CASES[case](WINDOW)
    result = rd.simulate(model, state, DT, steps=STEPS, method=method, t0=T0, error=False, accuracy_level=None,
                         **kwargs)
    for i in range(STEPS):
        state, _ = rd.step(model, state, DT, method=method, t=T0 + i * DT, **kwargs)
        assert_same_bits(state, result, i + 1, f"{case} by {method}")


# (a planar body's records hold its attitude as a quaternion, not its angle θ: a state rebuilt from them is not its
# state to the bit)
CONTINUED = [(case, method) for case, method in RUNS if case != "planar" and method in ("rk4", "splitting_dlm")]


@pytest.mark.parametrize(("case", "method"), CONTINUED)
def test_a_run_from_a_recorded_state_continues_the_run(case, method):
    # loads on at all times: a later run's grid t0' + i dt may differ from the first run's by an ulp, and a step split
    # at a switch time would then split at another place
    model, state, kwargs = CASES[case]({})
    options = {"method": method, "error": False, "accuracy_level": None, **kwargs}
    whole = rd.simulate(model, state, DT, steps=STEPS, t0=T0, **options)
    for k in (3, 4, 17):
        if isinstance(state, list):
            start = [recorded_state(s, whole, k, b) for b, s in enumerate(state)]
        else:
            start = recorded_state(state, whole, k, 0)
        rest = rd.simulate(model, start, DT, steps=STEPS - k, t0=T0 + k * DT, **options)
        for name in ("p_W", "q_WB", "v_W", "w_B"):
            a, w = getattr(rest, name), getattr(whole, name)[k:]
            assert np.array_equal(a, w), f"{case} by {method} from record {k}: {name} differs"
