"""Every public entry point names the argument it refuses (README: "<argument>: expected <what>, got
<value>").

The sweep introspects rigiddyn.__all__ (functions; classes: constructors, static and instance methods;
tests/fuzz/api_model.py reads the signatures), so a new function is swept without a change here; the
only thing it needs is a valid call, in EXAMPLES below (a test fails, naming it, when one is missing).
Starting from that valid call, each argument in turn is replaced by a value of the wrong type (a str,
None, a list of str, a complex, an object()). The call must raise TypeError or ValueError whose
message says what was expected and whose subject (the text before ": expected") names that argument -
never pybind11's "incompatible function arguments" list, never a crash - or, where the value is valid
after all (None for an optional argument, a str for a frame's name), succeed. Every public property of
those classes (results' classes included) reads and refuses assignment. The cases once
reported as bugs are checked as reported at the end.
"""

from __future__ import annotations

import functools
import inspect
import re
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

import rigiddyn as rd

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "fuzz"))
from api_model import OPERATORS, public_targets  # noqa: E402

WRONG = {  # kind -> a fresh value of that kind
    "str": lambda: "wrong",
    "None": lambda: None,
    "list of str": lambda: ["a", "b"],
    "complex": lambda: 1j,
    "object": lambda: object(),
}

PLOT_DIR = Path(tempfile.mkdtemp(prefix="rigiddyn_argument_errors_"))
Q = np.array([0.0, 0.0, 0.0, 1.0])
V = np.array([0.1, 0.2, 0.3])
I_BOX = np.diag([1.0, 2.0, 2.5])
# a closed, outward-oriented tetrahedron
TET_V = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
TET_F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
# a one-joint URDF (load_urdf)
URDF_ARM = ('<robot name="arm"><link name="base"/><link name="arm"><inertial><mass value="1.0"/><inertia ixx="1" '
            'iyy="2" izz="2.5" ixy="0" ixz="0" iyz="0"/></inertial></link><joint name="hinge" type="revolute">'
            '<parent link="base"/><child link="arm"/><axis xyz="0 0 1"/></joint></robot>')


def _tree():
    tree = rd.FrameTree()
    tree.add_frame("A", "world", rd.FrameMotion.constant_rotation([0, 0, 1.0], 0.5))
    return tree


def _arm(gravity=(0.0, 0.0, -9.81)):
    tree = rd.Tree(gravity=gravity)
    tree.add_link("arm", -1, rd.RevoluteJoint(), rd.SpatialInertia(1.0, V, I_BOX))
    return tree


def _problem():
    return rd.Problem(name="p", mass=1.0, inertia_com=I_BOX, horizon=0.1, w_B=[0.1, 1.0, 0.0])


@functools.lru_cache(maxsize=None)
def _result():
    return rd.tradeoff(_problem(), methods=["rk4"], dts=[0.05, 0.025], progress=False)


def _body_state():
    return {"body": rd.RigidBody(1.0, I_BOX), "state": rd.RigidBodyState(w_B=V)}


def _scene_with_tree():
    """A scene of a one-link tree (a rod on a revolute joint)."""
    scene = rd.Scene()
    scene.add_tree(_arm(gravity=None))
    return scene


def _scene():
    """A scene of a particle and a rigid body under gravity."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="dot")
    scene.add_body(rd.RigidBody(1.0, I_BOX), name="box")
    scene.add(rd.UniformGravity())
    return scene


def _scene_result():
    return rd.simulate(_scene(), [rd.ParticleState(), rd.RigidBodyState(w_B=V)], 0.01, 2)


def _push(t, body, p_W, q_WB, v_W, w_B):
    return V, V


# one instance of each force element class
ELEMENTS = {
    "UniformGravity": lambda: rd.UniformGravity(), "PointMassGravity": lambda: rd.PointMassGravity(gm=1.0),
    "MutualGravity": lambda: rd.MutualGravity(), "GravityGradient": lambda: rd.GravityGradient(gm=1.0),
    "SpringDamper": lambda: rd.SpringDamper(body_a=0, stiffness=1.0), "Drag": lambda: rd.Drag(linear=0.1),
    "ScheduledLoads": lambda: rd.ScheduledLoads(body=0), "PythonForce": lambda: rd.PythonForce(_push),
    "Thrust": lambda: rd.Thrust(body=0, u_rel=V), "MagneticDipole": lambda: rd.MagneticDipole(m_B=V),
    "ReactionWheel": lambda: rd.ReactionWheel(body=0, axis_B=V, inertia=0.1),
    "ZonalGravity": lambda: rd.ZonalGravity(gm=1.0, radius=0.1, j2=1e-3),
    "AtmosphericDrag": lambda: rd.AtmosphericDrag(density0=1e-11, scale_height=5e4, radius=6.4e6, drag_area=1.0),
    "SolarRadiationPressure": lambda: rd.SolarRadiationPressure(sun_W=V, area=1.0),
    "RevoluteSpringDamper": lambda: rd.RevoluteSpringDamper(body=0, stiffness=1.0),
    "PrismaticSpringDamper": lambda: rd.PrismaticSpringDamper(body=0, stiffness=1.0),
    "RevoluteMotor": lambda: rd.RevoluteMotor(body=0, torque=1.0),
    "PrismaticMotor": lambda: rd.PrismaticMotor(body=0, force=1.0),
    "SphericalSpringDamper": lambda: rd.SphericalSpringDamper(body=0, stiffness=1.0),
}


def _pivoted():
    return rd.PivotedBody(rd.RigidBody(1.0, I_BOX), V)


def _pendulum():
    """A compound pendulum swinging in a vertical plane."""
    return {"body": rd.PivotedPlanarBody(1.0, 0.5, [0.1, 0.2]), "g_W": [0.0, -9.81],
            "state": rd.PivotedPlanarBodyState(theta=0.3, omega=0.1)}


def _top():
    """A spinning symmetric top (inertia about O symmetric about O->C), its axis 0.3 rad from the vertical."""
    return {"body": rd.PivotedBody(rd.RigidBody(1.0, [1.0, 1.0, 0.5]), p_OC_B=[0.0, 0.0, 0.2]), "g_W": [0.0, 0.0, -9.81],
            "state": rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1.0, 0.0, 0.0], 0.3), w_B=[0.1, 0.0, 5.0])}


def _thrust():
    return {"m0": 10.0, "rate": -0.1, "u_rel_W": [0.0, 0.0, -100.0]}


# path -> a function returning the keyword arguments of a valid call (required arguments at least)
EXAMPLES = {
    "Balance": lambda: {"energy": np.zeros(2), "linear_momentum": np.zeros(2), "angular_momentum": np.zeros(2),
                        "energy_round_off": np.zeros(2), "linear_momentum_round_off": np.zeros(2),
                        "angular_momentum_round_off": np.zeros(2), "energy_scale": np.ones(2),
                        "linear_momentum_scale": np.ones(2), "angular_momentum_scale": np.ones(2),
                        "verdict": {"energy": "closed", "linear_momentum": "closed", "angular_momentum": "closed"},
                        "about": "W's origin"},
    "AppliedLoad": lambda: {}, "FrameKinematics": lambda: {}, "FrameTree": lambda: {}, "ParticleState": lambda: {},
    "PlanarBodyState": lambda: {}, "RigidBodyState": lambda: {}, "Transform": lambda: {},
    "Motion": lambda: {"angular": V, "linear": V}, "Force": lambda: {"angular": V, "linear": V},
    "Motion.from_vector": lambda: {"vector": np.ones(6)}, "Force.from_vector": lambda: {"vector": np.ones(6)},
    "Motion.cross": lambda: {"other": rd.Motion(V, V)}, "Motion.cross_force": lambda: {"force": rd.Force(V, V)},
    "Motion.dot": lambda: {"force": rd.Force(V, V)}, "Force.dot": lambda: {"motion": rd.Motion(V, V)},
    "Motion.is_approx": lambda: {"other": rd.Motion(V, V)}, "Force.is_approx": lambda: {"other": rd.Force(V, V)},
    "Transform.is_approx": lambda: {"other": rd.Transform()},
    "FrameMotion": lambda: {"kinematics_at": lambda t: rd.FrameKinematics()},
    "FrameMotion.fixed": lambda: {},
    "FrameMotion.constant_rotation": lambda: {"axis_P": [0, 0, 1.0], "rate": 0.5},
    "FrameMotion.at": lambda: {"t": 0.5},
    "FrameTree.add_frame": lambda: {"name": "B", "parent": "A", "motion": rd.FrameMotion.fixed()},
    "FrameTree.set_parent": lambda: {"name": "A", "parent": "world", "motion": rd.FrameMotion.fixed()},
    "FrameTree.has_frame": lambda: {"name": "A"}, "FrameTree.parent": lambda: {"name": "A"},
    "FrameTree.motion": lambda: {"name": "A"},
    "FrameTree.kinematics": lambda: {"frame": "A", "relative_to": "world", "t": 0.5},
    "FrameTree.rotation": lambda: {"frame": "A", "relative_to": "world", "t": 0.5},
    "FrameTree.angular_velocity": lambda: {"frame": "A", "relative_to": "world", "expressed_in": "A", "t": 0.5},
    "FrameTree.angular_acceleration": lambda: {"frame": "A", "relative_to": "world", "expressed_in": "A", "t": 0.5},
    "FrameTree.transport_derivative": lambda: {"u_E": V, "du_B_E": V, "from_frame": "A", "to_frame": "world",
                                               "expressed_in": "world", "t": 0.5},
    "FrameTree.point_position": lambda: {"frame": "A", "p_FQ_F": V, "relative_to": "world", "expressed_in": "A",
                                         "t": 0.5},
    "FrameTree.point_velocity": lambda: {"frame": "A", "p_FQ_F": V, "v_FQ_F": V, "relative_to": "world",
                                         "expressed_in": "A", "t": 0.5},
    "FrameTree.point_acceleration": lambda: {"frame": "A", "p_FQ_F": V, "v_FQ_F": V, "a_FQ_F": V,
                                             "relative_to": "world", "expressed_in": "A", "t": 0.5},
    "InertiaCheck": lambda: {"value": 0},
    "InertiaReport.valid": lambda: {},
    "Particle": lambda: {"mass": 1.0}, "PlanarBody": lambda: {"mass": 1.0, "inertia_zz": 0.5},
    "RigidBody": lambda: {"mass": 1.0, "inertia_com": I_BOX},
    "RigidBodyState.quaternion": lambda: {},
    "Screw": lambda: {"direction": [0, 0, 1.0], "point": V, "pitch": 0.1, "magnitude": 2.0},
    "SpatialInertia": lambda: {"mass": 1.0, "com": V, "inertia_com": I_BOX},
    "SpatialInertia.from_inertia_about_point": lambda: {"mass": 1.0, "com": V, "inertia_about_point": I_BOX,
                                                        "point": V},
    "SpatialInertia.from_inertia_about_origin": lambda: {"mass": 1.0, "com": [0, 0, 0.0], "inertia_about_origin": I_BOX},
    "SpatialInertia.from_matrix": lambda: {"matrix": rd.SpatialInertia(1.0, V, I_BOX).matrix()},
    "SpatialInertia.point_mass": lambda: {"mass": 1.0, "position": V},
    "SpatialInertia.inertia_about_point": lambda: {"point": V},
    "SpatialInertia.momentum": lambda: {"twist": rd.Motion(V, V)},
    "SpatialInertia.kinetic_energy": lambda: {"twist": rd.Motion(V, V)},
    "SpatialInertia.angular_momentum_about_com": lambda: {"angular_velocity": V},
    "SpatialInertia.angular_momentum_about_point": lambda: {"angular_velocity": V, "com_velocity": V, "point": V},
    "SpatialInertia.rotated": lambda: {"R_AB": np.eye(3)},
    "SpatialInertia.transformed": lambda: {"X_AB": rd.Transform()},
    "SpatialInertia.admits_symmetry_plane": lambda: {"normal": [0, 0, 1.0]},
    "SpatialInertia.remove": lambda: {"part": rd.SpatialInertia(0.1, V, 0.01 * I_BOX)},
    "SpatialInertia.is_approx": lambda: {"other": rd.SpatialInertia(1.0, V, I_BOX)},
    "TorqueFreeSolution": lambda: {"inertia": I_BOX, "q_WB": Q, "w_B": V},
    "PrincipalAxes": lambda: {"moments": [1.0, 2.0, 2.5], "axes": np.eye(3)},
    "DensityIntegral": lambda: {"inertia": rd.SpatialInertia(1.0, V, I_BOX), "mass_error": 0.0, "com_error": 0.0,
                                "inertia_error": 0.0, "evaluations": 8},
    "PointVelocity": lambda: {"origin": V, "rotational": V, "relative": V},
    "PointAcceleration": lambda: {"origin": V, "tangential": V, "centripetal": V, "relative": V, "coriolis": V},
    "TorqueFreeSolution.state_at": lambda: {"t": 0.5},
    "Transform.from_quat": lambda: {"q_AB": Q}, "Transform.quat": lambda: {},
    "Transform.act_point": lambda: {"p_B": V}, "Transform.act_inv_point": lambda: {"p_A": V},
    "Transform.act": lambda: {"spatial_vector": rd.Motion(V, V)},
    "Transform.act_inv": lambda: {"spatial_vector": rd.Force(V, V)},
    "angular_momentum": _body_state, "kinetic_energy": _body_state, "linear_momentum": _body_state,
    "potential_energy": _body_state, "forward_dynamics": _body_state,
    "apply_impulse": lambda: {**_body_state(), "impulse": V},
    "inverse_dynamics": lambda: {**_body_state(), "a_W": V, "alpha_B": V},
    "KineticEnergy": lambda: {"translational": 1.0, "rotational": 2.0},
    "ComWrench": lambda: {"f_W": V, "tau_B": V}, "PlanarWrench": lambda: {"f_W": [0.1, 0.2], "tau": 0.3},
    "BodyAcceleration": lambda: {"a_W": V, "alpha_B": V},
    "PlanarAcceleration": lambda: {"a_W": [0.1, 0.2], "alpha": 0.3},
    "power": lambda: {"state": rd.RigidBodyState(w_B=V), "f_W": V},
    "axis_angle_to_quat": lambda: {"axis": V, "angle": 0.3},
    "box_shell": lambda: {"size": V, "mass": 1.0}, "solid_box": lambda: {"size": V, "mass": 1.0},
    "solid_ellipsoid": lambda: {"semi_axes": V, "mass": 1.0},
    "solid_sphere": lambda: {"radius": 0.1, "mass": 1.0}, "spherical_shell": lambda: {"radius": 0.1, "mass": 1.0},
    "thin_rod": lambda: {"length": 0.1, "mass": 1.0}, "thin_disk": lambda: {"radius": 0.1, "mass": 1.0},
    "thin_plate": lambda: {"size_x": 0.1, "size_y": 0.2, "mass": 1.0},
    "hollow_sphere": lambda: {"outer_radius": 0.2, "inner_radius": 0.1, "mass": 1.0},
    "hollow_cylinder": lambda: {"outer_radius": 0.2, "inner_radius": 0.1, "height": 0.3, "mass": 1.0},
    "solid_capsule": lambda: {"radius": 0.1, "length": 0.3, "mass": 1.0},
    "solid_cone": lambda: {"radius": 0.1, "height": 0.3, "mass": 1.0},
    "solid_cylinder": lambda: {"radius": 0.1, "height": 0.3, "mass": 1.0},
    "solid_tetrahedron": lambda: {"vertices": TET_V, "mass": 1.0},
    "solid_mesh": lambda: {"mesh_or_vertices": TET_V, "faces": TET_F, "mass": 1.0},
    "mesh_shell": lambda: {"mesh_or_vertices": TET_V, "faces": TET_F, "mass": 1.0},
    "mesh_volume": lambda: {"vertices": TET_V, "faces": TET_F},
    "mesh_symmetry_planes": lambda: {"vertices": TET_V, "faces": TET_F},
    "weld_vertices": lambda: {"vertices": TET_V, "faces": TET_F},
    "require_closed_oriented_mesh": lambda: {"faces": TET_F, "n_vertices": 4},
    "from_point_masses": lambda: {"masses": [1.0, 2.0], "positions": [V, -V]},
    "symmetry_planes": lambda: {"masses": [1.0, 1.0], "positions": [V, -V]},
    "integrate_density_over_box": lambda: {"rho": lambda p: np.ones(len(p)), "lower": -V, "upper": V, "order": 2,
                                           "subdivisions": 1},
    "integrate_density_over_mesh": lambda: {"rho": lambda p: np.ones(len(p)), "vertices": TET_V, "faces": TET_F,
                                            "order": 2},
    "composite": lambda: {"parts": [rd.SpatialInertia(1.0, V, I_BOX), rd.SpatialInertia(1.0, -V, I_BOX)]},
    "point_inertia": lambda: {"mass": 1.0, "r": V},
    "inertia_report": lambda: {"mass": 1.0, "inertia_com": I_BOX},
    "nearest_valid_inertia": lambda: {"inertia": I_BOX}, "principal_axes": lambda: {"inertia": I_BOX},
    "compose_kinematics": lambda: {"K_AP": rd.FrameKinematics(), "K_PF": rd.FrameKinematics()},
    "relative_kinematics": lambda: {"K_WA": rd.FrameKinematics(), "K_WF": rd.FrameKinematics()},
    "point_velocity": lambda: {"K_AF": rd.FrameKinematics(), "p_FQ_F": V, "v_FQ_F": V},
    "point_acceleration": lambda: {"K_AF": rd.FrameKinematics(), "p_FQ_F": V, "v_FQ_F": V, "a_FQ_F": V},
    "transport_derivative": lambda: {"w_AB": V, "u": V, "du_dt_in_B": V},
    "twist_to_screw": lambda: {"twist": rd.Motion(V, V)},
    "screw_to_twist": lambda: {"screw": rd.Screw([0, 0, 1.0], V, 0.1, 2.0)},
    "motion_cross_matrix": lambda: {"motion": rd.Motion(V, V)}, "force_cross_matrix": lambda: {"motion": rd.Motion(V, V)},
    "transform_compose": lambda: {"R_AB": np.eye(3), "p_AB": V, "R_BC": np.eye(3), "p_BC": V},
    "transform_points": lambda: {"R_AB": np.eye(3), "p_AB": V, "p_B": V},
    "quat_to_matrix": lambda: {"q": Q}, "quat_to_rotvec": lambda: {"q": Q}, "quat_inverse": lambda: {"q": Q},
    "quat_normalize": lambda: {"q": Q}, "quat_to_axis_angle": lambda: {"q": Q}, "to_scipy": lambda: {"q": Q},
    "quat_multiply": lambda: {"q1": Q, "q2": Q}, "quat_rotate": lambda: {"q": Q, "v": V},
    "quat_integrate": lambda: {"q": Q, "w": V, "dt": 0.1},
    "quat_to_euler": lambda: {"seq": "xyz", "q": Q},
    "davenport_to_quat": lambda: {"axes": np.eye(3), "order": "e", "angles": V},
    "quat_to_davenport": lambda: {"axes": np.eye(3), "order": "e", "q": Q},
    "quat_to_mrp": lambda: {"q": Q}, "mrp_to_quat": lambda: {"mrp": V},
    "quat_rate": lambda: {"q": Q, "w": V}, "angular_velocity_from_quat_rate": lambda: {"q": Q, "dq_dt": Q},
    "matrix_to_quat": lambda: {"R": np.eye(3)}, "matrix_to_rotvec": lambda: {"R": np.eye(3)},
    "matrix_to_euler": lambda: {"seq": "xyz", "R": np.eye(3)},
    "euler_to_quat": lambda: {"seq": "xyz", "angles": V}, "euler_to_matrix": lambda: {"seq": "xyz", "angles": V},
    "rotvec_to_quat": lambda: {"rotvec": V}, "rotvec_to_matrix": lambda: {"rotvec": V},
    "rot_x": lambda: {"angle": 0.3}, "rot_y": lambda: {"angle": 0.3}, "rot_z": lambda: {"angle": 0.3},
    "hat": lambda: {"v": V}, "vee": lambda: {"S": np.eye(3)},
    "from_scipy": lambda: {"rotation": rd.to_scipy(Q)},
    "nearest_rotation": lambda: {"M": np.eye(3)}, "quat_canonical": lambda: {"q": Q},
    "slerp": lambda: {"q0": Q, "q1": Q, "t": 0.5}, "slerp_keys": lambda: {"times": [0.0, 1.0], "q": [Q, Q], "t": 0.5},
    "angular_distance": lambda: {"q_a": Q, "q_b": Q}, "random_rotations": lambda: {"n": 2, "rng": 0},
    "align_vectors": lambda: {"a": [V, V[::-1]], "b": [V, V[::-1]]},
    "elliprf": lambda: {"x": 1.0, "y": 2.0, "z": 3.0}, "elliprj": lambda: {"x": 1.0, "y": 2.0, "z": 3.0, "p": 4.0},
    "ellipk": lambda: {"m": 0.5}, "ellippi": lambda: {"n": 0.3, "m": 0.5},
    # orbits (km and km/s: mu of the Earth in km^3/s^2)
    "state_to_elements": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0], "mu": 398600.0},
    "elements_to_state": lambda: {"elements": [7000.0, 0.1, 0.5, 0.1, 0.2, 0.3], "mu": 398600.0},
    "semi_latus_rectum": lambda: {"a": 7000.0, "e": 0.1},
    "mean_to_eccentric_anomaly": lambda: {"M": 1.0, "e": 0.1}, "eccentric_to_mean_anomaly": lambda: {"E": 1.0, "e": 0.1},
    "true_to_eccentric_anomaly": lambda: {"nu": 1.0, "e": 0.1}, "eccentric_to_true_anomaly": lambda: {"E": 1.0, "e": 0.1},
    "true_to_mean_anomaly": lambda: {"nu": 1.0, "e": 0.1}, "mean_to_true_anomaly": lambda: {"M": 1.0, "e": 0.1},
    "kepler_propagate": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0], "mu": 398600.0, "t": 10.0},
    "orbit_frame_rotation": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0]},
    "orbit_frame_angular_velocity": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0]},
    "attitude_from_orbit_frame": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0], "q_OB": Q, "w_OB_B": V},
    "attitude_to_orbit_frame": lambda: {"r_W": [7000.0, 0, 0], "v_W": [0, 7.5, 0], "q_WB": Q, "w_B": V},
    "ellippi_am": lambda: {"u": 0.4, "n": 0.3, "m": 0.5}, "jacobi_ellipj": lambda: {"u": 0.4, "m": 0.5},
    "simulate": lambda: {"model": rd.RigidBody(1.0, I_BOX), "initial": rd.RigidBodyState(w_B=V), "dt": 0.01,
                         "steps": 2},
    "step": lambda: {"model": rd.RigidBody(1.0, I_BOX), "state": rd.RigidBodyState(w_B=V), "dt": 0.01},
    "simulate_batch": lambda: {"model": rd.RigidBody(1.0, I_BOX), "initial": [rd.RigidBodyState(w_B=V)], "dt": 0.01,
                               "steps": 2},
    "default_thread_count": lambda: {},
    "Problem": lambda: {"name": "p", "mass": 1.0, "inertia_com": I_BOX, "horizon": 0.1},
    "Problem.simulate": lambda: {"method": "rk4", "dt": 0.01},
    "Problem.with_horizon": lambda: {"horizon": 0.2},
    "load_problem": lambda: {"path_or_name": "t_handle"},
    "TradeoffResult": lambda: {"problem": "t_handle", "horizon": 0.1, "measure": "final_attitude_error",
                               "tolerance": 1e-6, "rows": []},
    "TradeoffResult.recommend": lambda: {"tolerance": 1e-6}, "TradeoffResult.pareto": lambda: {},
    "TradeoffResult.to_table": lambda: {}, "TradeoffResult.to_csv": lambda: {}, "TradeoffResult.to_json": lambda: {},
    "TradeoffResult.read_csv": lambda: {"path_or_text": _result().to_csv()},
    "TradeoffResult.read_json": lambda: {"path_or_text": _result().to_json()},
    "TradeoffResult.plot": lambda: {"path": str(PLOT_DIR / "plot")},
    "tradeoff": lambda: {"problem": _problem(), "methods": ["rk4"], "dts": [0.05, 0.025], "progress": False},
    "monte_carlo": lambda: {"model": rd.RigidBody(1.0, I_BOX), "nominal_state": rd.RigidBodyState(w_B=V), "n": 2,
                            "seed": 1, "dt": 0.01, "steps": 2},
    "Scene": lambda: {}, "Scene.add_body": lambda: {"body": rd.Particle(1.0)},
    "Scene.add": lambda: {"element": rd.Drag(linear=0.1)}, "Scene.compile": lambda: {"method": "rk4"},
    "Scene.describe": lambda: {}, "Scene.to_toml": lambda: {},
    "Scene.of_body": lambda: {"body": rd.RigidBody(1.0, I_BOX), "gravity": True, "loads": [rd.AppliedLoad(force=V)]},
    "CompiledScene": lambda: {"scene": _scene()}, "CompiledScene.describe": lambda: {},
    "SceneResult.to_dataframe": lambda: {}, "SceneResult.body": lambda: {"key": 0},
    "GlobalError.reliable_for": lambda: {"quantity": "attitude"},
    "BatchSceneResult.body": lambda: {"key": 0},
    "UniformGravity": lambda: {}, "PointMassGravity": lambda: {"gm": 1.0}, "MutualGravity": lambda: {},
    "GravityGradient": lambda: {"gm": 1.0}, "ZonalGravity": lambda: {"gm": 1.0, "radius": 0.1},
    "AtmosphericDrag": lambda: {"density0": 1e-11, "scale_height": 5e4, "radius": 6.4e6, "drag_area": 1.0},
    "SolarRadiationPressure": lambda: {"sun_W": V, "area": 1.0},
    "SpringDamper": lambda: {"body_a": 0, "stiffness": 1.0},
    "RevoluteSpringDamper": lambda: {"body": 0, "stiffness": 1.0},
    "PrismaticSpringDamper": lambda: {"body": 0, "stiffness": 1.0},
    "RevoluteMotor": lambda: {"body": 0, "torque": 1.0},
    "PrismaticMotor": lambda: {"body": 0, "force": 1.0},
    "SphericalSpringDamper": lambda: {"body": 0, "stiffness": 1.0},
    "Drag": lambda: {}, "ScheduledLoads": lambda: {"body": 0}, "PythonForce": lambda: {"fn": _push},
    "load_scene": lambda: {"path_or_text": "kepler"},
    "load_urdf": lambda: {"source": URDF_ARM},
    "urdf_joint_dampers": lambda: {"source": URDF_ARM, "tree": rd.load_urdf(URDF_ARM), "links": (0,)},
    # bodies about a fixed point, the scene's frame, variable mass
    "PivotedBody": lambda: {"body": rd.RigidBody(1.0, I_BOX), "p_OC_B": V},
    "PivotedPlanarBody": lambda: {"mass": 1.0, "inertia_zz": 0.5, "p_OC_B": [0.1, 0.2]},
    "PivotedBodyState": lambda: {}, "PivotedPlanarBodyState": lambda: {}, "PivotedBodyState.quaternion": lambda: {},
    "PivotedAcceleration": lambda: {"alpha_B": V, "reaction_W": V}, "PivotedTorque": lambda: {"tau_O_B": V, "reaction_W": V},
    "PivotedPlanarAcceleration": lambda: {"alpha": 0.3, "reaction_W": V},
    "PivotedPlanarTorque": lambda: {"tau_O": 0.3, "reaction_W": V},
    "SceneFrame.rotating": lambda: {"axis": [0, 0, 1.0], "rate": 0.5}, "SceneFrame.earth": lambda: {"latitude": 0.8},
    "SceneFrame.moving": lambda: {"frame_motion": rd.FrameMotion.fixed()},
    "MassFlow": lambda: {}, "Thrust": lambda: {"body": 0, "u_rel": V}, "MagneticDipole": lambda: {"m_B": V},
    "ReactionWheel": lambda: {"body": 0, "axis_B": V, "inertia": 0.1},
    "Wheel": lambda: {"axis_B": V, "inertia": 0.1},
    "Gyrostat": lambda: {"body": rd.RigidBody(1.0, I_BOX), "wheels": [rd.Wheel(V, 0.01)]},
    "GyrostatState": lambda: {},
    "Controller": lambda: {"period": 0.5, "law": lambda state: {}},
    "SampledState": lambda: {"t": 0.5, "p_W": np.zeros((1, 3)), "q_WB": np.array([Q]), "v_W": np.zeros((1, 3)),
                             "w_B": np.zeros((1, 3)), "wheel_speed": np.zeros(0)},
    # their exact references
    "CompoundPendulumSolution": _pendulum, "CompoundPendulumSolution.at": lambda: {"t": 0.5},
    "LagrangeTopSolution": _top, "LagrangeTopSolution.at": lambda: {"t": 0.5},
    "LagrangeTopSolution.angles_at": lambda: {"t": 0.5},
    "RotatingFrameFreeParticle": lambda: {"frame": rd.SceneFrame.rotating([0, 0, 1.0], 0.5), "p0_F": V, "v0_F": V},
    "RotatingFrameFreeParticle.at": lambda: {"t": 0.5},
    "ConstantThrustSolution": _thrust, "ConstantThrustSolution.at": lambda: {"t": 0.5},
    "ConstantThrustSolution.delta_v": lambda: {"m1": 5.0}, "ConstantThrustSolution.mass_at": lambda: {"t": 0.5},
    # kinematic trees (_arm: a revolute link, nq = nv = 1)
    "Tree": lambda: {"gravity": V}, "RevoluteJoint": lambda: {"axis": V}, "PrismaticJoint": lambda: {"axis": V},
    "SphericalJoint": lambda: {}, "FreeJoint": lambda: {}, "FixedJoint": lambda: {},
    "Tree.add_link": lambda: {"name": "new", "parent": 0, "joint": rd.RevoluteJoint(), "inertia": rd.SpatialInertia(1.0, V, I_BOX),
                              "placement": rd.Transform()},
    "Tree.link_index": lambda: {"name": "arm"}, "Tree.neutral_configuration": lambda: {},
    "Tree.integrate": lambda: {"q": [0.1], "v": [0.2], "dt": 0.1},
    "Tree.kinetic_energy": lambda: {"q": [0.1], "v": [0.2]}, "Tree.potential_energy": lambda: {"q": [0.1]},
    "Tree.joint_states": lambda: {"q": [0.1], "v": [0.2]}, "Tree.coordinates_of": lambda: {"states": [rd.JointState([0.1], [0.2])]},
    "JointState": lambda: {"q": [0.1], "v": [0.2]},
    "Scene.add_tree": lambda: {"tree": _arm(gravity=None), "name": "tree"},
    "forward_kinematics": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2]},
    "rnea": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2], "a": [0.3], "f_ext": np.ones((1, 6))},
    "bias_forces": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2]}, "crba": lambda: {"tree": _arm(), "q": [0.1]},
    "aba": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2], "tau": [0.3], "f_ext": np.ones((1, 6))},
    "generalized_momentum": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2]},
    "generalized_momentum_rate": lambda: {"tree": _arm(), "q": [0.1], "v": [0.2], "f_ext": np.ones((1, 6))},
    **{f"{joint}.{method}": lambda: {} for joint in ("RevoluteJoint", "PrismaticJoint", "SphericalJoint", "FreeJoint",
                                                     "FixedJoint") for method in ("motion_subspace",)},
    "RevoluteJoint.transform": lambda: {"q": [0.1]}, "PrismaticJoint.transform": lambda: {"q": [0.1]},
    "SphericalJoint.transform": lambda: {"q": Q}, "FreeJoint.transform": lambda: {"q": np.concatenate([V, Q])},
    "FixedJoint.transform": lambda: {"q": np.zeros(0)},
}

# the instance a method is called on, by class
INSTANCES = {
    "Tree": _arm, "RevoluteJoint": rd.RevoluteJoint, "PrismaticJoint": rd.PrismaticJoint, "SphericalJoint": rd.SphericalJoint,
    "FreeJoint": rd.FreeJoint, "FixedJoint": rd.FixedJoint,
    "Force": lambda: rd.Force(V, V), "Motion": lambda: rd.Motion(V, V), "FrameMotion": rd.FrameMotion.fixed,
    "FrameTree": _tree, "InertiaReport": lambda: rd.inertia_report(1.0, I_BOX), "InertiaCheck": lambda: rd.InertiaCheck.physical,
    "RigidBodyState": lambda: rd.RigidBodyState(w_B=V), "SpatialInertia": lambda: rd.SpatialInertia(1.0, V, I_BOX),
    "TorqueFreeSolution": lambda: rd.TorqueFreeSolution(I_BOX, Q, V), "Transform": lambda: rd.Transform(None, V),
    "Problem": _problem, "TradeoffResult": _result,
    "GlobalError": lambda: rd.simulate(rd.RigidBody(1.0, I_BOX), rd.RigidBodyState(w_B=V), 0.01, 8).error,
    "Balance": lambda: rd.simulate(rd.RigidBody(1.0, I_BOX), rd.RigidBodyState(w_B=V), 0.01, 8).balance,
    "Scene": _scene, "CompiledScene": lambda: _scene().compile("rk4"), "SceneResult": _scene_result,
    "BatchSceneResult": lambda: rd.simulate_batch(rd.RigidBody(1.0, I_BOX), [rd.RigidBodyState(w_B=V)], 0.01, 2),
    "PivotedBodyState": lambda: rd.PivotedBodyState(w_B=V),
    "CompoundPendulumSolution": lambda: rd.CompoundPendulumSolution(**_pendulum()),
    "LagrangeTopSolution": lambda: rd.LagrangeTopSolution(**_top()),
    "RotatingFrameFreeParticle": lambda: rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating([0, 0, 1.0], 0.5), V, V),
    "ConstantThrustSolution": lambda: rd.ConstantThrustSolution(**_thrust()),
}

# (path, argument) -> the wrong kinds that are valid values after all (the call may succeed)
VALID_AFTER_ALL = {
    ("Balance", "about"): {"str"},  # any point's name
    ("FrameTree.add_frame", "name"): {"str"},  # any new name
    ("FrameTree.has_frame", "name"): {"str"},  # False
    ("Tree.add_link", "name"): {"str"},  # any new name
    ("Problem", "name"): {"str"}, ("Problem", "description"): {"str"}, ("Problem", "source"): {"str"},
    ("TradeoffResult", "problem"): {"str"}, ("TradeoffResult.read_csv", "problem"): {"str"},  # a problem's name
    ("TradeoffResult", "notes"): {"list of str"},  # the report's notes
    # a file name (written in the test's temporary folder)
    ("TradeoffResult.to_csv", "path"): {"str"}, ("TradeoffResult.to_json", "path"): {"str"},
    ("TradeoffResult.plot", "path"): {"str"},
    ("Scene.add_body", "name"): {"str"},  # any new name
    ("Scene.add_tree", "name"): {"str"},  # any new prefix of the links' names
    ("monte_carlo", "seed"): {"None"},  # fresh entropy, kept as result.seed
    ("Scene.to_toml", "name"): {"str"}, ("Scene.to_toml", "description"): {"str"},  # the file's name and text
}


def _targets():
    targets, _ = public_targets(rd)
    # the callables of the package's own namespace; those of a submodule it lists (none today) are fuzzed with
    # their own examples (tests/fuzz)
    submodules = {name for name in rd.__all__ if inspect.ismodule(getattr(rd, name))}
    # operators (a + b, -a, repr) have no argument name to give; their TypeError is Python's own
    return [t for t in targets if t.path.rsplit(".", 1)[-1] not in OPERATORS and t.path.split(".", 1)[0] not in submodules]


TARGETS = _targets()
CASES = [(t, p.name, p.optional, kind) for t in TARGETS for p in t.overloads[0] for kind in WRONG]


def _call(target, kwargs):
    if target.owner is not None:
        return getattr(INSTANCES[target.owner](), target.path.rsplit(".", 1)[1])(**kwargs)
    obj = rd
    for part in target.path.split("."):
        obj = getattr(obj, part)
    return obj(**kwargs)


def _names_argument(message: str, argument: str) -> bool:
    subject = message.split(": expected", 1)[0] if ": expected" in message else ""
    return re.search(rf"(?<![A-Za-z0-9_]){re.escape(argument)}(?![A-Za-z0-9_])", subject) is not None


def test_every_entry_point_has_a_valid_example(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    missing = sorted({t.path for t in TARGETS if t.overloads[0] and t.path not in EXAMPLES}
                     | {t.owner for t in TARGETS if t.owner and t.owner not in INSTANCES})
    assert not missing, f"add a valid call (EXAMPLES) or an instance (INSTANCES) for: {missing}"
    for target in TARGETS:  # the examples themselves are valid calls
        if target.path in EXAMPLES:
            _call(target, EXAMPLES[target.path]())


@pytest.mark.parametrize("target, argument, optional, kind", CASES,
                         ids=[f"{t.path}-{a}-{k}" for t, a, _, k in CASES])
def test_wrong_type_names_the_argument(target, argument, optional, kind, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a path argument given "wrong" that is accepted writes there
    kwargs = {**EXAMPLES[target.path](), argument: WRONG[kind]()}
    valid_after_all = VALID_AFTER_ALL.get((target.path, argument), set()) | ({"None"} if optional else set())
    try:
        _call(target, kwargs)
    except (TypeError, ValueError) as error:
        message = str(error)
        assert "incompatible function arguments" not in message and "incompatible constructor" not in message, message
        assert _names_argument(message, argument), f"{type(error).__name__} does not name {argument!r}: {message}"
        return
    assert kind in valid_after_all, f"{target.path}({argument}={WRONG[kind]()!r}) was accepted"


def _properties():
    """(class name, property) for every public property of every class of rigiddyn.__all__ that the
    sweep has an instance of (results' classes included: their instances come from INSTANCES_OF_RESULTS)."""
    out = []
    for name in rd.__all__:
        cls = getattr(rd, name)
        if isinstance(cls, type) and not issubclass(cls, BaseException):
            out += [(name, attr) for attr, raw in vars(cls).items() if not attr.startswith("_") and isinstance(raw, property)]
    return out


# instances of the classes that only results have (no constructor)
INSTANCES_OF_RESULTS = {
    "TreeLink": lambda: _scene_with_tree().bodies[0],
    "BodyRecords": lambda: _scene_result().body(0),
    "BatchSceneResult": lambda: rd.simulate_batch(_scene(), [[rd.ParticleState(), rd.RigidBodyState(w_B=V)]], 0.01, 2),
    "DensityIntegral": lambda: rd.integrate_density_over_box(lambda p: np.ones(len(p)), -V, V, order=2),
    "KineticEnergy": lambda: rd.kinetic_energy(**_body_state()),
    "PrincipalAxes": lambda: rd.SpatialInertia(1.0, V, I_BOX).principal_axes(),
    "WeldedMesh": lambda: rd.weld_vertices(TET_V, TET_F),
    "PointVelocity": lambda: rd.point_velocity(rd.FrameKinematics(), V, V),
    "PointAcceleration": lambda: rd.point_acceleration(rd.FrameKinematics(), V, V, V),
    "ElementField": lambda: rd.MagneticDipole.fields[0], "GlobalError": INSTANCES["GlobalError"],
    "Balance": INSTANCES["Balance"],
    "ToleranceChoice": lambda: rd.simulate(rd.RigidBody(1.0, I_BOX), rd.RigidBodyState(w_B=V), duration=1.0,
                                           tolerance=1e-4).choice,
    "InertiaReport": INSTANCES["InertiaReport"], "FrameKinematics": rd.FrameKinematics, "AppliedLoad": rd.AppliedLoad,
    "ParticleState": rd.ParticleState, "PlanarBodyState": rd.PlanarBodyState, "Particle": lambda: rd.Particle(1.0),
    "PlanarBody": lambda: rd.PlanarBody(1.0, 0.5), "RigidBody": lambda: rd.RigidBody(1.0, I_BOX),
    "Screw": lambda: rd.Screw([0, 0, 1.0], V, 0.1, 2.0),
    "ComWrench": lambda: rd.inverse_dynamics(**_body_state(), a_W=V, alpha_B=V),
    "PlanarWrench": lambda: rd.inverse_dynamics(rd.PlanarBody(1.0, 0.5), rd.PlanarBodyState(), [0.1, 0.2], 0.3),
    "BodyAcceleration": lambda: rd.forward_dynamics(**_body_state(), force=V),
    "PlanarAcceleration": lambda: rd.forward_dynamics(rd.PlanarBody(1.0, 0.5), rd.PlanarBodyState(), [0.1, 0.2]),
    "Scene": _scene, "CompiledScene": lambda: _scene().compile("rk4"), "SceneResult": _scene_result, **ELEMENTS,
    "PivotedBody": _pivoted, "PivotedPlanarBody": lambda: rd.PivotedPlanarBody(1.0, 0.5, [0.1, 0.2]),
    "PivotedPlanarBodyState": rd.PivotedPlanarBodyState,
    "PivotedAcceleration": lambda: rd.forward_dynamics(_pivoted(), rd.PivotedBodyState(w_B=V), gravity=True),
    "PivotedTorque": lambda: rd.inverse_dynamics(_pivoted(), rd.PivotedBodyState(w_B=V), alpha_B=V),
    "PivotedPlanarAcceleration": lambda: rd.forward_dynamics(rd.PivotedPlanarBody(1.0, 0.5, [0.1, 0.2]),
                                                             rd.PivotedPlanarBodyState(), gravity=[0.0, -9.81]),
    "PivotedPlanarTorque": lambda: rd.inverse_dynamics(rd.PivotedPlanarBody(1.0, 0.5, [0.1, 0.2]),
                                                       rd.PivotedPlanarBodyState(), alpha_B=0.3),
    "SceneFrame": lambda: rd.SceneFrame.rotating([0, 0, 1.0], 0.5), "MassFlow": lambda: rd.MassFlow(-0.1),
    "Wheel": lambda: rd.Wheel(V, 0.01), "Gyrostat": lambda: rd.Gyrostat(rd.RigidBody(1.0, I_BOX), [rd.Wheel(V, 0.01)]),
    "GyrostatState": lambda: rd.GyrostatState(wheel_speeds=[1.0]), "JointState": lambda: rd.JointState([0.1], [0.2]),
}
PROPERTIES = _properties()
# the states' fields: assigned whole, checked as the constructor checks (their arrays are read-only)
ASSIGNABLE = {("ParticleState", "p_W"), ("ParticleState", "v_W"), ("PlanarBodyState", "p_W"),
              ("PlanarBodyState", "theta"), ("PlanarBodyState", "v_W"), ("PlanarBodyState", "omega"),
              ("RigidBodyState", "p_W"), ("RigidBodyState", "q_WB"), ("RigidBodyState", "v_W"),
              ("RigidBodyState", "w_B"), ("PivotedBodyState", "q_WB"), ("PivotedBodyState", "w_B"),
              ("PivotedPlanarBodyState", "theta"), ("PivotedPlanarBodyState", "omega"),
              ("GyrostatState", "p_W"), ("GyrostatState", "q_WB"), ("GyrostatState", "v_W"), ("GyrostatState", "w_B"),
              ("GyrostatState", "wheel_speeds"), ("JointState", "q"), ("JointState", "v"),
              ("Scene", "frame")}  # a scene's frame: a SceneFrame or None


def test_every_class_with_properties_has_an_instance():
    missing = sorted({c for c, _ in PROPERTIES if c not in INSTANCES and c not in INSTANCES_OF_RESULTS})
    assert not missing, f"add an instance (INSTANCES_OF_RESULTS) for: {missing}"


@pytest.mark.parametrize("cls, attr", PROPERTIES, ids=[f"{c}.{a}" for c, a in PROPERTIES])
def test_properties_read_and_refuse_assignment(cls, attr):
    # a property reads without error and is read-only: assigning a wrong-typed value (or any value)
    # raises AttributeError, never stores it (values are set through the constructors, which check);
    # a state's field is assignable, and a wrong value is refused naming it, the state unchanged
    obj = (INSTANCES.get(cls) or INSTANCES_OF_RESULTS[cls])()
    before = getattr(obj, attr)
    if (cls, attr) in ASSIGNABLE:
        with pytest.raises(TypeError, match=rf"^{attr}: expected"):
            setattr(obj, attr, "wrong")
        np.testing.assert_array_equal(getattr(obj, attr), before)
        return
    with pytest.raises(AttributeError):
        setattr(obj, attr, "wrong")


@pytest.mark.parametrize("call, error, message", [
    (lambda: rd.FrameMotion(5), TypeError, r"^kinematics_at: expected a callable .*, got int 5$"),
    (lambda: rd.composite([1, 2]), TypeError, r"^parts\[0\]: expected a SpatialInertia .*, got int 1$"),
    (lambda: rd.require_closed_oriented_mesh(TET_F, -5), ValueError, r"^n_vertices: expected an integer in \[0, .*got -5$"),
    (lambda: rd.point_inertia(float("nan"), V), ValueError, r"^mass: expected a finite number, got nan$"),
    (lambda: rd.point_inertia(-5, V), ValueError, r"^mass: expected a finite number > 0, got -5$"),
    (lambda: rd.quat_integrate(Q, V, "1"), TypeError, r"^dt: expected .*, got str '1'$"),
])
def test_the_reported_messages(call, error, message):
    # the cases once reported as bugs, each as reported
    with pytest.raises(error, match=message):
        call()


def test_the_symmetry_tolerance_printed_is_the_one_used():
    # max |I - I^T| = 1e-11 was refused with a message printing another tolerance
    asymmetric = I_BOX.copy()
    asymmetric[0, 1] += 1e-11
    with pytest.raises(ValueError, match=r"^inertia_com: expected a symmetric inertia") as refused:
        rd.RigidBody(1.0, asymmetric)
    printed = float(re.search(r"> symmetry tolerance ([0-9.e+-]+)", str(refused.value)).group(1))
    assert printed == rd.inertia_report(1.0, asymmetric).asymmetry_tolerance
    # the printed figure is the threshold: an asymmetry just inside it is accepted, just outside refused
    for factor, accepted in [(0.99, True), (1.01, False)]:
        I = I_BOX.copy()
        I[0, 1] += factor * printed
        assert rd.inertia_report(1.0, I).symmetric == accepted, factor
