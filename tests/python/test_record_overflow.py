"""A recorded quantity that overflows while the state stays finite (a kinetic energy of |v| > 1e154 m/s, the
angular momentum of a body spinning near the largest double) warns RuntimeWarning naming the quantity and the
first time it is not finite, in every path that records: simulate of a body and of a scene (a pivoted body, a
moving frame), and simulate_batch (scalar and SIMD, bodies and scenes). A run whose state itself becomes
non-finite keeps its one warning (the diverged one)."""

import re

import numpy as np
import pytest

import rigiddyn as rd

BODY = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
# |v_W| = 1e300 m/s: T = m |v|^2 / 2 = 1e600 J overflows; the state and its motion (no force) stay finite
FAST = rd.RigidBodyState(v_W=[1e300, 0.0, 0.0])
CALM = rd.RigidBodyState(w_B=[0.1, 0.2, 0.3])
OVERFLOW = r"recorded quantities became non-finite while the state stayed finite \(an overflow\)"


def test_one_body_warns_naming_the_quantities_and_their_first_time():
    with pytest.warns(RuntimeWarning, match=rf"^simulate: {OVERFLOW}: kinetic_energy from t = 0, "
                                            r"total_energy from t = 0$"):
        run = rd.simulate(BODY, FAST, 1e-3, 5)
    assert not run.diverged and np.isfinite(run.v_W).all() and np.isinf(run.kinetic_energy).all()


def test_the_time_named_is_the_records_time():
    # from t0 = 2.5 s: the first record (t = t0) is the first that overflows. (A later first overflow cannot come
    # with a finite state here: the work of what raises the kinetic energy is part of the state, and overflows
    # with it.)
    with pytest.warns(RuntimeWarning, match=rf"^simulate: {OVERFLOW}: kinetic_energy from t = 2.5, "
                                            r"total_energy from t = 2.5$"):
        rd.simulate(BODY, FAST, 0.5, 4, t0=2.5)


def test_a_finite_run_gives_no_warning():
    rd.simulate(BODY, CALM, 1e-3, 5)  # warnings are errors


def test_a_pivoted_body_spinning_near_the_largest_double_warns_for_its_momenta():
    # I = 1e10 kg m^2 spinning at 1e300 rad/s about the principal axis z through the pivot (w x I_O w = 0, no
    # gravity): w_B stays finite (dt = 1e-301 s turns it by 0.1 rad a step); T = I w^2 / 2 and H_O = I w overflow
    body = rd.PivotedBody(rd.RigidBody(2.0, [1e10, 1e10, 1e10]), p_OC_B=[0.0, 0.0, 0.2])
    state = rd.PivotedBodyState(w_B=[0.0, 0.0, 1e300])
    with pytest.warns(RuntimeWarning, match=rf"^simulate: {OVERFLOW}: ") as record:
        run = rd.simulate(body, state, 1e-301, 3)
    message = str(record[0].message)
    for quantity in ("kinetic_energy", "angular_momentum_W", "angular_momentum_O_W"):
        assert re.search(rf"\b{quantity} from t = 0\b", message), (quantity, message)
    assert not run.diverged and np.isfinite(run.w_B).all()


def test_a_scene_in_a_moving_frame_warns():
    # a particle at rest 1e160 m from the axis of a frame turning at 1 rad/s: its centrifugal potential
    # -m (Omega |p|)^2 / 2 = -5e319 J overflows; over steps of 1e-80 s the state, its kinetic energy and the work
    # stay finite (~1e160)
    scene = rd.Scene(bodies=[rd.Particle(1.0)], frame=rd.SceneFrame.rotating([0.0, 0.0, 1.0], 1.0))
    with pytest.warns(RuntimeWarning, match=rf"^simulate: {OVERFLOW}: potential_energy from t = 0, "
                                            r"total_energy from t = 0$"):
        run = rd.simulate(scene, [rd.ParticleState(p_W=[1e160, 0.0, 0.0])], 1e-80, 3)
    assert not run.diverged


@pytest.mark.parametrize("simd", [False, True])
def test_a_body_batch_names_the_samples_that_overflow(simd):
    with pytest.warns(RuntimeWarning, match=rf"^simulate_batch: {OVERFLOW} in 1 of 3 samples: sample 1: "
                                            r"kinetic_energy from t = 0, total_energy from t = 0$"):
        batch = rd.simulate_batch(BODY, [CALM, FAST, CALM], 1e-3, 5, simd=simd)
    assert not batch.diverged.any()


def test_a_scene_batch_names_the_samples_that_overflow():
    scene = rd.Scene(bodies=[rd.Particle(1.0)])
    states = [[rd.ParticleState()], [rd.ParticleState()], [rd.ParticleState(v_W=[1e300, 0.0, 0.0])]]
    with pytest.warns(RuntimeWarning, match=rf"^simulate_batch: {OVERFLOW} in 1 of 3 samples: sample 2: "
                                            r"kinetic_energy from t = 0, total_energy from t = 0$"):
        rd.simulate_batch(scene, states, 1e-3, 5)


def test_a_diverged_run_keeps_its_one_warning():
    # explicit Euler on a spin about the intermediate axis blows up (test_simulate_control): the state becomes
    # non-finite, and its energy overflows a record or so before; the run's one warning is the diverged one
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    with pytest.warns(RuntimeWarning) as record:
        run = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 50.0, 0.1]), 0.05, 20, "explicit_euler")
    assert run.diverged
    assert len(record) == 1 and str(record[0].message).startswith("simulate: the state became non-finite by t = ")
