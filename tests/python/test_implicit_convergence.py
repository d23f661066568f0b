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
