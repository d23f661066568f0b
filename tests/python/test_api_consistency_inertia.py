"""One way to say each thing in the inertia, spatial, frames and exact layers:
one realizability check (InertiaCheck) also for TorqueFreeSolution, Python spelling in messages, one
return type per concept (PrincipalAxes, KineticEnergy), one name per concept (is_approx, force/motion
arguments), and every value object with a repr that evaluates back to it, pickling, deep copies and a
multiprocessing round trip, all bitwise equal (== compares every member exactly)."""

import concurrent.futures
import copy
import multiprocessing
import pickle

import numpy as np
import pytest

import rigiddyn as rd
from _error_bounds import EPS

HLW = np.diag([2.0, 1.0, 2.0 / 3.0])  # Hairer-Lubich-Wanner's test inertia: 1 + 2/3 < 2, no body has it
Q0 = np.array([0.1, -0.2, 0.3, 0.9])
Q0 = Q0 / np.linalg.norm(Q0)
R_TILT = rd.quat_to_matrix(Q0)


def kinematics_at(t):
    """A general frame motion defined at module level (so that pickle can save it): F slides along x."""
    return rd.FrameKinematics(p_PF_P=[t, 0.0, 0.0], v_PF_P=[1.0, 0.0, 0.0])


# --- one realizability check ------------------------------------------------------------------


def test_torque_free_solution_checks_the_triangle_inequality_by_default():
    with pytest.raises(ValueError, match=r"^inertia: expected principal moments satisfying the triangle inequality") as e:
        rd.TorqueFreeSolution(HLW, [0, 0, 0, 1.0], [1.0, 2.0, 3.0])
    message = str(e.value)
    assert "principal moments (0.66666666666666663, 1, 2)" in message  # the moments, ascending
    assert "InertiaCheck" in message and "::" not in message  # the opt-in, in no language's syntax
    sol = rd.TorqueFreeSolution(HLW, [0, 0, 0, 1.0], [1.0, 2.0, 3.0], check=rd.InertiaCheck.allow_unrealizable)
    assert sol.case == "B" or sol.case == "A"
    # the boundary I0 + I1 = I2 (a flat plate) is realizable, as for SpatialInertia
    rd.TorqueFreeSolution(np.diag([1.0, 2.0, 3.0]), [0, 0, 0, 1.0], [1.0, 2.0, 3.0])
    rd.SpatialInertia(1.0, np.zeros(3), np.diag([1.0, 2.0, 3.0]))
    with pytest.raises(TypeError, match=r"^check: expected InertiaCheck"):
        rd.TorqueFreeSolution(HLW, [0, 0, 0, 1.0], [1.0, 2.0, 3.0], check="allow_unrealizable")


@pytest.mark.parametrize("refuse", [
    lambda: rd.SpatialInertia(1.0, np.zeros(3), HLW),
    lambda: rd.SpatialInertia.from_inertia_about_origin(1.0, np.zeros(3), HLW),
    lambda: rd.TorqueFreeSolution(HLW, [0, 0, 0, 1.0], [1.0, 2.0, 3.0]),
    lambda: rd.SpatialInertia(1.0, np.zeros(3), np.diag([1.0, 1.0, 3.0])).remove(rd.SpatialInertia.point_mass(0.5, [0, 0, 1.0])),
])
def test_messages_use_no_cpp_syntax(refuse):
    with pytest.raises(ValueError) as e:
        refuse()
    assert "::" not in str(e.value) and "triangle inequality" in str(e.value)
    assert "::" not in rd.inertia_report(1.0, HLW).summary()


# --- one return type per concept ----------------------------------------------------------------


def test_principal_axes_is_one_type_that_unpacks():
    body = rd.SpatialInertia(2.0, np.zeros(3), R_TILT @ np.diag([3.0, 1.0, 2.5]) @ R_TILT.T)
    I_B = body.inertia_com  # as stored (symmetrised)
    free = rd.principal_axes(I_B)
    method = body.principal_axes()
    assert type(free) is type(method) is rd.PrincipalAxes
    moments, axes = free  # as the README writes it
    assert len(free) == 2 and free[0] is free.moments and free[1] is free.axes and free[-1] is free.axes
    np.testing.assert_array_equal(moments, method.moments)
    np.testing.assert_array_equal(axes, method.axes)
    assert np.all(np.diff(moments) > 0)
    # axes: columns, right-handed; eigh-accurate to a few eps of |I| (Eigen's symmetric QR, backward stable)
    assert np.linalg.det(axes) == pytest.approx(1.0, abs=16 * EPS)
    np.testing.assert_allclose(axes @ np.diag(moments) @ axes.T, I_B, rtol=0, atol=64 * EPS * 3.0)
    with pytest.raises(ValueError):
        free.moments[0] = 1.0  # a value: read-only arrays
    # a stack (n, 3, 3): arrays (n, 3) and (n, 3, 3) in the same type
    stack = rd.principal_axes(np.stack([I_B, np.diag([1.0, 2.0, 2.5])]))
    assert type(stack) is rd.PrincipalAxes
    moments_n, axes_n = stack
    assert moments_n.shape == (2, 3) and axes_n.shape == (2, 3, 3)
    np.testing.assert_array_equal(moments_n[0], moments)
    np.testing.assert_array_equal(axes_n[0], axes)
    with pytest.raises(ValueError, match=r"^axes: expected shape \(2, 3, 3\)"):
        rd.PrincipalAxes(moments_n, axes)


def test_torque_free_kinetic_energy_is_a_kinetic_energy():
    w_B = np.array([0.3, -1.2, 0.7])
    moments = np.array([1.0, 2.0, 2.5])
    sol = rd.TorqueFreeSolution(np.diag(moments), Q0, w_B)
    T = sol.kinetic_energy
    assert isinstance(T, rd.KineticEnergy)
    assert T.translational == 0.0 and T.total == T.rotational
    # a diagonal inertia: R_BP a signed permutation (exact); 1/2 sum I_i w_i^2 on both sides, each with
    # at most 5 roundings (products, 3-term sum, halving exact): |error| <= 2 * 5 eps T
    expected = 0.5 * np.sum(moments * w_B**2)
    assert T.rotational == pytest.approx(expected, rel=10 * EPS)
    # the free function's rotational part for a body with that inertia: the same concept, the same type
    body_T = rd.kinetic_energy(rd.RigidBody(1.0, np.diag(moments)), rd.RigidBodyState(q_WB=Q0, w_B=w_B))
    assert type(body_T) is type(T)
    assert body_T.rotational == pytest.approx(T.rotational, rel=10 * EPS)


# --- one name per concept -----------------------------------------------------------------------


@pytest.mark.parametrize("make, nudge", [
    (lambda: rd.Motion([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]), lambda x, d: rd.Motion(x.angular + d, x.linear)),
    (lambda: rd.Force([1.0, 2.0, 3.0], [4.0, 5.0, 6.0]), lambda x, d: rd.Force(x.angular, x.linear + d)),
    (lambda: rd.Transform(R_TILT, [1.0, 2.0, 3.0]), lambda x, d: rd.Transform(x.rotation, x.translation + d)),
    (lambda: rd.solid_box([1.0, 2.0, 3.0], mass=2.0), lambda x, d: rd.SpatialInertia(x.mass, x.com + d, x.inertia_com)),
])
def test_is_approx_on_every_value_type(make, nudge):
    x = make()
    # |d| = 1e-14 against norms >= 1: within prec 1e-12 relative, and out of 1e-16
    close = nudge(x, np.array([1e-14, 0.0, 0.0]))
    assert x.is_approx(close) and close.is_approx(x) and x.is_approx(x, prec=0.0)
    assert not x.is_approx(close, prec=1e-16) and not (x == close)
    assert not x.is_approx(nudge(x, np.array([1e-3, 0.0, 0.0])))
    with pytest.raises(TypeError, match=r"^other: expected"):
        x.is_approx(5)
    with pytest.raises(ValueError, match=r"^prec: expected a number >= 0"):
        x.is_approx(x, prec=-1.0)


def test_spatial_arguments_are_named_by_their_type():
    V = rd.Motion([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
    F = rd.Force([0.5, -1.0, 2.0], [1.0, 0.0, -1.0])
    assert V.dot(force=F) == F.dot(motion=V)
    assert V.cross_force(force=F) == V.cross_force(F)
    np.testing.assert_array_equal(rd.force_cross_matrix(motion=V), -rd.motion_cross_matrix(motion=V).T)


# --- repr, pickle, deepcopy, multiprocessing ----------------------------------------------------


def _tree():
    tree = rd.FrameTree()
    tree.add_frame("shaft", "world", rd.FrameMotion.constant_rotation([0.0, 0.0, 2.0], 1.5, R_TILT, [0.1, 0.2, 0.3]))
    tree.add_frame("disk", "world", rd.FrameMotion.fixed(R_TILT.T, [1.0, 0.0, 0.0]))
    tree.add_frame("slider", "disk", rd.FrameMotion(kinematics_at))
    tree.set_parent("disk", "shaft", rd.FrameMotion.fixed(R_TILT.T, [1.0, 0.0, 0.0]))  # a parent added after
    return tree


VALUES = {
    "SpatialInertia": lambda: rd.solid_box([1.0, 2.0, 3.0], mass=2.0).transformed(rd.Transform(R_TILT, [0.1, 0.2, 0.3])),
    "SpatialInertia unrealizable": lambda: rd.SpatialInertia(1.0, [0.1, 0, 0], HLW, check=rd.InertiaCheck.allow_unrealizable),
    "PrincipalAxes": lambda: rd.principal_axes(R_TILT @ np.diag([3.0, 1.0, 2.5]) @ R_TILT.T),
    "PrincipalAxes stack": lambda: rd.principal_axes(np.stack([np.eye(3), np.diag([1.0, 2.0, 2.5])])),
    "InertiaReport": lambda: rd.inertia_report(1.0, HLW),
    "DensityIntegral": lambda: rd.integrate_density_over_box(lambda p: 1.0 + p[:, 0] ** 2, [0, 0, 0], [1.0, 2.0, 3.0],
                                                             order=2),
    "Motion": lambda: rd.Motion([0.1, 0.2, 1 / 3], [4.0, -5.0, 6e-300]),
    "Force": lambda: rd.Force([0.1, 0.2, 1 / 3], [4.0, -5.0, 6e300]),
    "Transform": lambda: rd.Transform(R_TILT, [0.1, 0.2, 1 / 3]),
    "Screw": lambda: rd.twist_to_screw(rd.Motion([0.0, 0.3, 1.0], [1.0, 0.5, 0.2])),
    "Screw translation": lambda: rd.twist_to_screw(rd.Motion(None, [1.0, 0.5, 0.2])),
    "TorqueFreeSolution": lambda: rd.TorqueFreeSolution(R_TILT @ np.diag([1.0, 2.0, 2.5]) @ R_TILT.T, Q0,
                                                        [0.3, -1.2, 0.7]),
    "TorqueFreeSolution scalar_first unrealizable": lambda: rd.TorqueFreeSolution(
        HLW, np.roll(Q0, 1), [0.3, -1.2, 0.7], scalar_first=True, check=rd.InertiaCheck.allow_unrealizable),
    "FrameKinematics": lambda: _tree().kinematics("slider", "world", 0.7),
    "PointVelocity": lambda: _tree().point_velocity("disk", [0.1, 0.2, 0.3], [1.0, 0, 0], "world", "disk", 0.7),
    "PointAcceleration": lambda: _tree().point_acceleration("disk", [0.1, 0.2, 0.3], [1.0, 0, 0], [0, 0.5, 0],
                                                            "world", "disk", 0.7),
    "FrameMotion fixed": lambda: rd.FrameMotion.fixed(R_TILT, [1.0, 2.0, 3.0]),
    "FrameMotion constant_rotation": lambda: rd.FrameMotion.constant_rotation([1e-300, 0, 2e-300], -0.5),
    "FrameMotion function": lambda: rd.FrameMotion(kinematics_at),
    "FrameTree": _tree,
}
NAMES = list(VALUES)


# no constructor from the repr's fields: a report comes from inertia_report; a Python function's repr
# (and so that of a tree holding one) is not code
NOT_EVALUATED = {"InertiaReport", "FrameMotion function", "FrameTree"}


@pytest.mark.parametrize("name", NAMES)
def test_repr_reads_as_the_constructor_call(name):
    x = VALUES[name]()
    text = repr(x)
    assert text.startswith(type(x).__name__) and "(" in text
    assert "\n" not in text and " at 0x" not in text.replace(repr(kinematics_at), "")
    if name in NOT_EVALUATED:
        return
    again = eval(text, vars(rd))
    assert again == x and type(again) is type(x)
    assert repr(again) == text


def test_frame_tree_repr_evaluates_without_general_motions():
    tree = _tree()
    tree.set_parent("slider", "disk", rd.FrameMotion.fixed(None, [0.0, 0.0, 0.5]))
    again = eval(repr(tree), vars(rd))
    assert again == tree and again.frame_names() == tree.frame_names()
    np.testing.assert_array_equal(again.point_position("slider", [1.0, 2.0, 3.0], "world", "world", 0.3),
                                  tree.point_position("slider", [1.0, 2.0, 3.0], "world", "world", 0.3))


@pytest.mark.parametrize("name", NAMES)
def test_pickle_and_deepcopy_are_bitwise(name):
    x = VALUES[name]()
    for again in (pickle.loads(pickle.dumps(x)), copy.deepcopy(x), copy.copy(x)):
        assert type(again) is type(x) and again == x and not (again != x)
    assert x != object() and not (x == 5)


def test_round_trips_keep_the_behaviour_bitwise():
    sol = VALUES["TorqueFreeSolution scalar_first unrealizable"]()
    again = pickle.loads(pickle.dumps(sol))
    for a, b in zip(sol.state_at(np.linspace(-3.0, 40.0, 7)), again.state_at(np.linspace(-3.0, 40.0, 7))):
        np.testing.assert_array_equal(a, b)
    tree, tree_again = _tree(), pickle.loads(pickle.dumps(_tree()))
    for t in (0.0, 0.3, 11.0):
        assert tree.kinematics("slider", "world", t) == tree_again.kinematics("slider", "world", t)
        assert (tree.point_acceleration("slider", [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], "shaft", "world", t)
                == tree_again.point_acceleration("slider", [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], "shaft", "world", t))


def test_a_lambda_motion_copies_but_does_not_pickle():
    motion = rd.FrameMotion(lambda t: rd.FrameKinematics())
    assert copy.deepcopy(motion) == motion  # the callable is shared, as deepcopy shares functions
    tree = rd.FrameTree([("A", "world", motion)])
    assert copy.deepcopy(tree) == tree
    for x in (motion, tree):
        with pytest.raises(TypeError, match=r"^FrameMotion: cannot pickle its kinematics_at .*module level"):
            pickle.dumps(x)


def test_bad_states_and_frames_are_refused():
    with pytest.raises(ValueError, match=r"^Motion state: expected a tuple of 2 items"):
        rd.Motion.__new__(rd.Motion).__setstate__((1.0,))
    with pytest.raises(ValueError, match=r"^FrameMotion state: expected 'fixed', 'constant_rotation' or 'function'"):
        rd.FrameMotion.__new__(rd.FrameMotion).__setstate__(("spin",))
    with pytest.raises(TypeError, match=r"^frames\[0\]: expected a list of \(name, parent, FrameMotion\) triples"):
        rd.FrameTree([("A", "world")])
    with pytest.raises(ValueError, match=r"^parent"):
        rd.FrameTree([("A", "B", rd.FrameMotion.fixed())])


def test_values_cross_process_boundaries():
    values = [VALUES[name]() for name in NAMES]
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
        back = list(pool.map(copy.copy, values))  # pickled to the worker, copied there, pickled back
    for name, x, y in zip(NAMES, values, back):
        assert type(y) is type(x) and y == x, name
