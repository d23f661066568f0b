"""What a user reads of a scene's terms: a PythonForce goes by that name everywhere (SceneResult.elements, the
DataFrame's work and power columns, describe(), compile's warnings), and a moving frame adds the fictitious terms
that act, alone (docs/fixed_point_frames_mass.md §2): which columns appear for each kind of frame."""

import pickle
import warnings

import numpy as np
import pytest

import rigiddyn as rd


def push(t, body, p_W, q_WB, v_W, w_B):
    """A small constant push [N] and no torque (module level: the scene pickles)."""
    return (0.0, 0.0, 1.0), (0.0, 0.0, 0.0)


def test_a_python_force_is_named_python_force_everywhere():
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="puck")
    scene.add(rd.PythonForce(push))
    result = rd.simulate(scene, [rd.ParticleState()], dt=0.01, steps=3)
    assert result.elements == ("PythonForce",)
    columns = list(result.to_dataframe().columns)
    assert "work[0] PythonForce [J]" in columns and "power[0] PythonForce [W]" in columns
    assert not any("FunctionForce" in c for c in columns)
    assert "PythonForce" in scene.describe() and "FunctionForce" not in scene.describe()
    # compile's warning for a velocity-dependent element under a kick-based splitting names it the same way
    with pytest.warns(rd.SceneCompatibilityWarning, match=r"elements\[0\] \(PythonForce\)"):
        scene.compile("splitting_dlm")
    assert pickle.loads(pickle.dumps(result)).elements == ("PythonForce",)


# ---------------------------------------------------------------- the fictitious terms of each frame
def translating(t):
    """F sliding along x with a constant acceleration 2 m/s², no rotation (module level: pickles)."""
    return (np.eye(3), np.zeros(3), np.zeros(3), np.array([t * t, 0.0, 0.0]), np.array([2.0 * t, 0.0, 0.0]),
            np.array([2.0, 0.0, 0.0]))


def turning_while_sliding(t):
    """F turning at 0.5 rad/s about z (constant) while its origin slides with a constant acceleration."""
    c, s = np.cos(0.5 * t), np.sin(0.5 * t)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return (R, np.array([0.0, 0.0, 0.5]), np.zeros(3), np.array([t * t, 0.0, 0.0]), np.array([2.0 * t, 0.0, 0.0]),
            np.array([2.0, 0.0, 0.0]))


def spinning_up(t):
    """F about z with Ω = 0.1 t (α = 0.1 rad/s²), origin fixed: centrifugal, Coriolis and Euler terms act."""
    angle = 0.05 * t * t
    c, s = np.cos(angle), np.sin(angle)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return R, np.array([0.0, 0.0, 0.1 * t]), np.array([0.0, 0.0, 0.1]), np.zeros(3), np.zeros(3), np.zeros(3)


FRAMES = [  # (the frame, the fictitious columns it adds)
    (rd.SceneFrame.rotating([0.0, 0.0, 1.0], 0.5), ("CentrifugalForce", "CoriolisForce")),
    (rd.SceneFrame.earth(0.8), ("CentrifugalForce", "CoriolisForce")),
    (rd.SceneFrame.rotating([0.0, 0.0, 1.0], 0.0), ()),
    (rd.SceneFrame.moving(rd.FrameMotion.fixed(p_PF_P=[1.0, 2.0, 3.0])), ()),
    (rd.SceneFrame.moving(rd.FrameMotion.constant_rotation([0.0, 1.0, 0.0], 0.3, p_PF_P=[0.0, 0.0, 5.0])),
     ("CentrifugalForce", "CoriolisForce")),
    (rd.SceneFrame.moving(rd.FrameMotion(spinning_up)),
     ("FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce")),
    (rd.SceneFrame.moving(rd.FrameMotion(translating), terms=["origin"]), ("FrameOriginForce",)),
    (rd.SceneFrame.moving(rd.FrameMotion(turning_while_sliding), terms=("origin", "centrifugal", "coriolis")),
     ("FrameOriginForce", "CentrifugalForce", "CoriolisForce")),
    (rd.SceneFrame.moving(rd.FrameMotion(spinning_up), terms={"euler", "centrifugal", "coriolis"}),
     ("EulerForce", "CentrifugalForce", "CoriolisForce")),
]


@pytest.mark.parametrize("frame, expected", FRAMES)
def test_each_frame_adds_the_fictitious_terms_that_act_and_no_other(frame, expected):
    """The columns after the scene's own element; describe() lists the same terms; the frame pickles with them."""
    scene = rd.Scene(frame=frame)
    scene.add_body(rd.RigidBody(2.0, [0.1, 0.2, 0.3]), name="box")
    scene.add(rd.UniformGravity())
    result = rd.simulate(scene, [rd.RigidBodyState(p_W=[1.0, 0.0, 0.0], w_B=[0.0, 0.0, 1.0])], dt=0.01, steps=5)
    assert result.elements == ("UniformGravity",) + expected
    assert tuple(f"{name}" for name in frame.terms) == tuple(
        {"FrameOriginForce": "origin", "EulerForce": "euler", "CentrifugalForce": "centrifugal",
         "CoriolisForce": "coriolis"}[c] for c in expected)
    text = scene.describe()
    for name in frame.terms:
        assert f"(frame.{name})" in text
    for name in {"origin", "euler", "centrifugal", "coriolis"} - set(frame.terms):
        assert f"(frame.{name})" not in text
    again = pickle.loads(pickle.dumps(frame))
    assert again == frame and again.terms == frame.terms


def test_a_declared_term_set_changes_nothing_but_the_columns():
    """A translating frame with terms=['origin'] runs the same motion as with every term (the others are zero)."""
    initial = [rd.RigidBodyState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 1.0, 0.0], w_B=[0.0, 0.0, 1.0])]
    runs = []
    for frame in (rd.SceneFrame.moving(rd.FrameMotion(translating)),
                  rd.SceneFrame.moving(rd.FrameMotion(translating), terms=["origin"])):
        scene = rd.Scene(frame=frame)
        scene.add_body(rd.RigidBody(2.0, [0.1, 0.2, 0.3]))
        runs.append(rd.simulate(scene, initial, dt=0.01, steps=50))
    assert runs[0].elements == ("FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce")
    assert not np.any(runs[0].work[:, 1:])  # the columns the declaration leaves out were zeros
    np.testing.assert_array_equal(runs[1].p_W, runs[0].p_W)
    np.testing.assert_array_equal(runs[1].v_W, runs[0].v_W)
    np.testing.assert_array_equal(runs[1].work[:, 0], runs[0].work[:, 0])
    assert repr(rd.SceneFrame.moving(rd.FrameMotion(translating), terms=["origin"])).endswith(", terms=('origin',))")
    assert "terms=" not in repr(rd.SceneFrame.moving(rd.FrameMotion(translating)))


@pytest.mark.parametrize("terms, message", [
    (["coriolis"], r"^terms: expected the centrifugal and Coriolis terms together"),
    (["euler"], r"^terms: expected the centrifugal and Coriolis terms together .*got euler$"),
    (["origin", "origin"], r"^terms: expected a collection of the names"),
    (["gravity"], r"^terms: expected a collection of the names"),
])
def test_a_term_set_that_cannot_be_is_refused(terms, message):
    with pytest.raises(ValueError, match=message):
        rd.SceneFrame.moving(rd.FrameMotion(translating), terms=terms)


def test_a_term_set_other_than_a_known_motion_s_own_is_refused():
    with pytest.raises(ValueError, match=r"^terms: expected those of the motion, a constant rotation \(centrifugal, "
                                         r"coriolis\), got origin, euler, centrifugal, coriolis$"):
        rd.SceneFrame.moving(rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 1.0),
                             terms=["origin", "euler", "centrifugal", "coriolis"])
    with pytest.raises(TypeError, match=r"^terms: expected a collection"):
        rd.SceneFrame.moving(rd.FrameMotion(translating), terms="origin")


@pytest.mark.parametrize("motion, terms, message", [
    (spinning_up, ["centrifugal", "coriolis"], r"^frame: expected alpha_W = 0 at t = 0 s \(SceneFrame.moving's terms "
                                               r"leave out the EulerForce\), got"),
    (turning_while_sliding, ["origin"], r"^frame: expected w_W = 0 at t = 0 s \(SceneFrame.moving's terms leave out "
                                        r"the CentrifugalForce and CoriolisForce\), got"),
    (translating, ["centrifugal", "coriolis"], r"^frame: expected a_WO = 0 at t = 0 s \(SceneFrame.moving's terms "
                                               r"leave out the FrameOriginForce\), got"),
])
def test_a_motion_that_contradicts_its_declared_terms_stops_the_run(motion, terms, message):
    """A term left out must be identically zero: the run checks the motion's values at each evaluation."""
    scene = rd.Scene(frame=rd.SceneFrame.moving(rd.FrameMotion(motion), terms=terms))
    scene.add_body(rd.Particle(1.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match=message):
            rd.simulate(scene, [rd.ParticleState(p_W=[1.0, 0.0, 0.0])], dt=0.01, steps=5)
