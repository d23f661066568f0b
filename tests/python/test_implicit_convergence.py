"""implicit_midpoint makes a non-converged Newton solve visible: SimulationResult.unconverged_steps
counts the steps that hit the iteration cap, and simulate warns RuntimeWarning naming dt and the count."""
import re

import numpy as np
import pytest

import rigiddyn as rd

BODY = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
NEAR_SEPARATRIX = rd.RigidBodyState(w_B=[0.01, 2.0, 0.01])  # |w| = 2 rad/s


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # its spatial |L| drifts 0.4 % at this step: this test is about the solve's own warnings
def test_normal_regime_converges_silently():
    result = rd.simulate(BODY, NEAR_SEPARATRIX, 0.1, 200, method="implicit_midpoint")  # dt|w| = 0.2
    assert result.unconverged_steps == 0


def test_explicit_methods_report_zero():
    assert rd.simulate(BODY, NEAR_SEPARATRIX, 0.1, 50, method="rk4").unconverged_steps == 0


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # a step too large on purpose
def test_large_step_counts_and_warns():
    with pytest.warns(RuntimeWarning, match=r"did not converge in \d+ of 200 steps at dt = 4") as record:
        result = rd.simulate(BODY, NEAR_SEPARATRIX, 4.0, 200, method="implicit_midpoint")  # dt|w| = 8
    assert 0 < result.unconverged_steps <= 200
    count = int(re.search(r"in (\d+) of", str(record[0].message)).group(1))
    assert count == result.unconverged_steps


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps on purpose: this test is about the solve
@pytest.mark.parametrize("dt_w", [0.5, 1.0, 2.0, 2.8])
def test_a_body_in_a_scene_converges_as_the_body_alone(dt_w):
    """A rigid body in a scene solves the midpoint equations as the body alone does, up to the documented
    dt|w| = 3: its ω̄ by the Newton step of the gyroscopic term (the plain fixed point left steps unconverged from
    dt|w| = 0.5 and moved the body wrongly at 2). Runs of 50 steps converge in every step; since two runs of a
    tumbling body separate over time by any difference, single steps from the same state are compared: each solve
    stops within ~3 x 1e-14 relative of the midpoint equations' solution (a correction below the tolerance, the
    attitude's fixed point contracting by dt|w|/4 <= 0.7), so the two within 6e-14; 100 x 1e-14 leaves room for
    the roundings of the 3 x 3 solves."""
    w_B = np.array([0.3, 0.2, 1.0])
    dt = dt_w / np.linalg.norm(w_B)
    alone = rd.simulate(BODY, rd.RigidBodyState(w_B=w_B), dt, 50, method="implicit_midpoint", error=False)
    assert alone.unconverged_steps == 0
    alone = alone.body(0)
    scene = rd.simulate(rd.Scene([BODY]), [rd.RigidBodyState(w_B=w_B)], dt, 50, method="implicit_midpoint",
                        error=False)
    assert scene.unconverged_steps == 0
    two = rd.Scene([BODY, rd.Particle(1.0)])  # the generic scene model: the same solve per body
    for k in range(0, 50, 7):
        start = rd.RigidBodyState(q_WB=alone.q_WB[k], w_B=alone.w_B[k])
        want = rd.step(BODY, start, dt, method="implicit_midpoint")
        for model, states in ((rd.Scene([BODY]), [start]), (two, [start, rd.ParticleState()])):
            got = rd.step(model, states, dt, method="implicit_midpoint")[0]
            np.testing.assert_allclose(got.w_B, want.w_B, rtol=0, atol=100 * 1e-14 * np.linalg.norm(want.w_B))
            np.testing.assert_allclose(rd.angular_distance(got.q_WB, want.q_WB), 0.0, atol=100 * 1e-14)


@pytest.mark.filterwarnings("error::RuntimeWarning")  # an unconverged step warns: here it is a failure
@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps on purpose: this test is about the solve
@pytest.mark.parametrize("dt_w", [1.0, 2.0, 2.8])
def test_a_fast_heavy_top_converges_up_to_the_documented_limit(dt_w):
    """A heavy top spinning at 100 rad/s about its axis (a pivoted body: Euler's equations about the pivot in its
    one-body scene): every step's solve converges up to dt|w| = 3, its ω̄ by the Newton step of the gyroscopic
    term of I_O and its q̄ exactly (the plain fixed point missed the tolerance in every step from dt|w| = 1: the
    attitude's iterates contract by dt|w|/4 only)."""
    top = rd.PivotedBody(rd.RigidBody(1.0, [0.004, 0.004, 0.006]), p_OC_B=[0.0, 0.0, 0.1])
    tilted = rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1, 0, 0], np.radians(30)), w_B=[0.0, 0.0, 100.0])
    result = rd.simulate(top, tilted, dt=dt_w / 100.0, steps=200, method="implicit_midpoint", gravity=True,
                         error=False)
    assert result.unconverged_steps == 0 and not result.diverged
