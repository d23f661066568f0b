"""
rigiddyn's C++ core (rotations, frames, spatial algebra, inertia, dynamics).
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['AppliedLoad', 'BatchResult', 'BatchSceneResult', 'BodyAcceleration', 'ComWrench', 'CompiledScene', 'CompoundPendulumSolution', 'ConstantThrustSolution', 'DensityIntegral', 'Drag', 'ElementField', 'FORCE_ELEMENTS', 'Force', 'FrameKinematics', 'FrameMotion', 'FrameTree', 'GravityGradient', 'Gyrostat', 'GyrostatState', 'InertiaCheck', 'InertiaReport', 'KineticEnergy', 'LagrangeTopSolution', 'MagneticDipole', 'MassFlow', 'MeshWeldWarning', 'Motion', 'MutualGravity', 'Particle', 'ParticleState', 'PivotedAcceleration', 'PivotedBody', 'PivotedBodyState', 'PivotedPlanarAcceleration', 'PivotedPlanarBody', 'PivotedPlanarBodyState', 'PivotedPlanarTorque', 'PivotedTorque', 'PlanarAcceleration', 'PlanarBody', 'PlanarBodyState', 'PlanarWrench', 'PointAcceleration', 'PointMassGravity', 'PointVelocity', 'PrincipalAxes', 'PythonForce', 'ReactionWheel', 'RigidBody', 'RigidBodyState', 'RotatingFrameFreeParticle', 'Scene', 'SceneCompatibilityWarning', 'SceneFrame', 'SceneResult', 'ScheduledLoads', 'Screw', 'SimulationResult', 'SpatialInertia', 'SpringDamper', 'Thrust', 'TorqueFreeSolution', 'Transform', 'UniformGravity', 'WeldedMesh', 'Wheel', 'align_vectors', 'angular_distance', 'angular_momentum', 'angular_velocity_from_quat_rate', 'apply_impulse', 'axis_angle_to_quat', 'box_shell', 'compose_kinematics', 'composite', 'davenport_to_quat', 'default_thread_count', 'ellipk', 'ellippi', 'ellippi_am', 'elliprf', 'elliprj', 'euler_to_matrix', 'euler_to_quat', 'force_cross_matrix', 'forward_dynamics', 'from_point_masses', 'hat', 'hollow_cylinder', 'hollow_sphere', 'inertia_relative_tolerance', 'inertia_report', 'integrate_density_over_box', 'integrate_density_over_mesh', 'inverse_dynamics', 'jacobi_ellipj', 'kinetic_energy', 'linear_momentum', 'matrix_to_euler', 'matrix_to_quat', 'matrix_to_rotvec', 'mesh_shell', 'mesh_symmetry_planes', 'mesh_volume', 'methods', 'motion_cross_matrix', 'mrp_to_quat', 'nearest_rotation', 'nearest_valid_inertia', 'point_acceleration', 'point_inertia', 'point_velocity', 'potential_energy', 'power', 'principal_axes', 'quat_canonical', 'quat_integrate', 'quat_inverse', 'quat_multiply', 'quat_normalize', 'quat_rate', 'quat_rotate', 'quat_to_axis_angle', 'quat_to_davenport', 'quat_to_euler', 'quat_to_matrix', 'quat_to_mrp', 'quat_to_rotvec', 'random_rotations', 'relative_kinematics', 'require_closed_oriented_mesh', 'rot_x', 'rot_y', 'rot_z', 'rotvec_to_matrix', 'rotvec_to_quat', 'screw_to_twist', 'simulate', 'simulate_batch', 'slerp', 'slerp_keys', 'solid_box', 'solid_capsule', 'solid_cone', 'solid_cylinder', 'solid_ellipsoid', 'solid_mesh', 'solid_sphere', 'solid_tetrahedron', 'spherical_shell', 'step', 'symmetry_planes', 'thin_disk', 'thin_plate', 'thin_rod', 'transform_compose', 'transform_points', 'transport_derivative', 'twist_to_screw', 'vee', 'weld_vertices']
class FrameKinematics:
    """
    Frame F relative to frame P at one instant (P = the parent of a FrameMotion, or the
    `relative_to` frame of a FrameTree query). Every vector is expressed in P; SI units.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, R_PF: typing.Any = None, w_PF_P: typing.Any = None, alpha_PF_P: typing.Any = None, p_PF_P: typing.Any = None, v_PF_P: typing.Any = None, a_PF_P: typing.Any = None) -> None:
        """
        Arguments as the attributes (None: identity / zero). ValueError on a non-rotation R_PF or NaN/Inf.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def R_PF(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) orientation of F in P: maps F coordinates to P coordinates.
        """
    @property
    def a_PF_P(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) acceleration of F's origin seen from P [m/s^2], expressed in P.
        """
    @property
    def alpha_PF_P(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular acceleration of F relative to P (d/dt of w_PF) [rad/s^2], expressed in P.
        """
    @property
    def p_PF_P(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) position of F's origin relative to P's origin [m], expressed in P.
        """
    @property
    def v_PF_P(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) velocity of F's origin seen from P [m/s], expressed in P.
        """
    @property
    def w_PF_P(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular velocity of F relative to P [rad/s], expressed in P.
        """
class PointVelocity:
    """
    Velocity of a point Q moving in a frame F, seen from a frame A, term by term
    ("Rigid body kinematics and dynamics" notes (4.38)): total = origin + rotational +
    relative. Each (3,) [m/s], all expressed in the same frame E (the query's `expressed_in`;
    A for the free function point_velocity).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every term.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, origin: typing.Any, rotational: typing.Any, relative: typing.Any) -> None:
        """
        From its terms (3,) [m/s], all in one frame.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def origin(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        v_AF_E: velocity of F's origin seen from A, expressed in E [m/s]
        """
    @property
    def relative(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        v_FQ_E: velocity of Q seen from F, expressed in E [m/s]
        """
    @property
    def rotational(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        w_AF x r_FQ, r_FQ = position of Q relative to F's origin, expressed in E [m/s]
        """
    @property
    def total(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        v_AQ_E: velocity of Q seen from A (sum of the terms), expressed in E [m/s]
        """
class PointAcceleration:
    """
    Acceleration of a point Q moving in a frame F, seen from a frame A, term by term
    ("Rigid body kinematics and dynamics" notes (4.39); Craig's "Rigid Body Dynamics"
    slides): total = origin + tangential + centripetal + relative + coriolis. Each (3,)
    [m/s^2], all expressed in one frame E (the query's `expressed_in`; A for the free
    function point_acceleration).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every term.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, origin: typing.Any, tangential: typing.Any, centripetal: typing.Any, relative: typing.Any, coriolis: typing.Any) -> None:
        """
        From its terms (3,) [m/s^2], all in one frame.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def centripetal(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        w_AF x (w_AF x r_FQ), expressed in E [m/s^2]
        """
    @property
    def coriolis(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        2 w_AF x v_FQ (v_FQ: velocity of Q seen from F), expressed in E [m/s^2]
        """
    @property
    def origin(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        a_AF_E: acceleration of F's origin seen from A, expressed in E [m/s^2]
        """
    @property
    def relative(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        a_FQ_E: acceleration of Q seen from F, expressed in E [m/s^2]
        """
    @property
    def tangential(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        alpha_AF x r_FQ (r_FQ: Q relative to F's origin), expressed in E [m/s^2]
        """
    @property
    def total(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        a_AQ_E: acceleration of Q seen from A (sum of the terms), expressed in E [m/s^2]
        """
class FrameMotion:
    """
    How a frame F moves relative to its parent P: a function of time t [s] giving its
    FrameKinematics (all vectors expressed in P).
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def constant_rotation(axis_P: typing.Any, rate: typing.Any, R_PF0: typing.Any = None, p_PF_P: typing.Any = None) -> FrameMotion:
        """
        Simple angular velocity (Craig's "Rigid Body Dynamics" slides): F turns at `rate` [rad/s] about
        axis_P (3,) (expressed in P, any non-zero length) through F's origin, which stays at p_PF_P [m] in P
        (None: 0). R_PF(t) = exp(hat(rate t axis_P/|axis_P|)) R_PF0 (R_PF0: orientation at t = 0, None:
        identity).
        """
    @staticmethod
    def fixed(R_PF: typing.Any = None, p_PF_P: typing.Any = None) -> FrameMotion:
        """
        F fixed in P: orientation R_PF (3,3) (None: identity), origin at p_PF_P (3,) [m] in P (None: 0).
        """
    def __copy__(self) -> FrameMotion:
        ...
    def __deepcopy__(self, memo: typing.Any) -> FrameMotion:
        """
        A copy; a general motion's callable is shared, as copy.deepcopy shares functions.
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built the same way from exactly equal parameters (or equal callables).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, kinematics_at: typing.Any) -> None:
        """
        General motion: kinematics_at(t) returns a FrameKinematics or a 6-tuple
        (R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each (3,), expressed in P). The caller
        keeps them consistent (w, alpha the derivatives of R; v, a those of p); the tree checks each value
        (finite, R_PF a rotation) and raises ValueError naming the frame.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: typing.Any) -> FrameKinematics:
        """
        F relative to P at time t [s] (not checked: the tree checks the values it uses).
        """
class FrameTree:
    """
    A tree of reference frames rooted at the inertial frame 'world'. Each frame is placed
    relative to its parent by a FrameMotion. Queries relate any frame F (`frame`) to any
    frame A (`relative_to`) at time t [s], with results expressed in `expressed_in` E.
    Unknown names, duplicates and cycles raise ValueError. Trees of any depth (every walk
    is iterative).
    """
    __hash__: typing.ClassVar[None] = None
    world: typing.ClassVar[str] = 'world'
    def __copy__(self) -> FrameTree:
        ...
    def __deepcopy__(self, memo: typing.Any) -> FrameTree:
        """
        A copy; the motions' callables are shared, as copy.deepcopy shares functions.
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Same names in the same order, same parents, equal motions.
        """
    def __getstate__(self) -> tuple[list]:
        ...
    def __init__(self, frames: typing.Any = None) -> None:
        """
        A tree holding 'world' and the frames: a list of (name, parent, FrameMotion) triples (None: none),
        as repr shows them; a parent may come after its child.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def add_frame(self, name: typing.Any, parent: typing.Any, motion: typing.Any) -> None:
        """
        Adds frame `name` under `parent` (which must exist), placed by `motion`.
        """
    def angular_acceleration(self, frame: typing.Any, relative_to: typing.Any, expressed_in: typing.Any, t: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        alpha_AF_E (3,) [rad/s^2]: d/dt in A of w_AF, expressed in E (includes the w x w terms; no
        addition theorem for angular accelerations, Craig's "Rigid Body Dynamics" slides).
        """
    def angular_velocity(self, frame: typing.Any, relative_to: typing.Any, expressed_in: typing.Any, t: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        w_AF_E (3,) [rad/s]: angular velocity of F relative to A (addition theorem), expressed in E.
        """
    def frame_names(self) -> list[str]:
        """
        All names: 'world' first, then in the order added.
        """
    def has_frame(self, name: typing.Any) -> bool:
        """
        True if a frame of this name is in the tree.
        """
    def kinematics(self, frame: typing.Any, relative_to: typing.Any, t: typing.Any) -> FrameKinematics:
        """
        FrameKinematics of `frame` F relative to `relative_to` A at t, expressed in A.
        """
    def motion(self, name: typing.Any) -> FrameMotion:
        """
        The FrameMotion placing frame `name` in its parent ('world': fixed at the identity).
        """
    def parent(self, name: typing.Any) -> str:
        """
        The parent's name ('' for 'world').
        """
    def point_acceleration(self, frame: typing.Any, p_FQ_F: typing.Any, v_FQ_F: typing.Any, a_FQ_F: typing.Any, relative_to: typing.Any, expressed_in: typing.Any, t: typing.Any) -> PointAcceleration:
        """
        PointAcceleration of Q seen from A (origin, tangential, centripetal, relative, coriolis, total),
        terms expressed in E [m/s^2]; a_FQ_F (3,): Q's acceleration seen from F, expressed in F.
        """
    def point_position(self, frame: typing.Any, p_FQ_F: typing.Any, relative_to: typing.Any, expressed_in: typing.Any, t: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_AQ_E (3,) [m]: position of Q relative to A's origin, expressed in E; p_FQ_F (3,): Q relative
        to F's origin, expressed in F.
        """
    def point_velocity(self, frame: typing.Any, p_FQ_F: typing.Any, v_FQ_F: typing.Any, relative_to: typing.Any, expressed_in: typing.Any, t: typing.Any) -> PointVelocity:
        """
        PointVelocity of Q seen from A, terms expressed in E. Q at p_FQ_F [m] moving with v_FQ_F [m/s] as
        seen from F (both (3,), expressed in F; zeros for a point fixed in F).
        """
    def rotation(self, frame: typing.Any, relative_to: typing.Any, t: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        R_AF (3,3): maps `frame` F coordinates to `relative_to` A coordinates at t.
        """
    def set_parent(self, name: typing.Any, parent: typing.Any, motion: typing.Any) -> None:
        """
        Moves frame `name` and its subtree under `parent`, placed by `motion`. ValueError if that would
        make a cycle (parent is `name` or one of its descendants) or `name` is 'world'.
        """
    def transport_derivative(self, u_E: typing.Any, du_B_E: typing.Any, from_frame: typing.Any, to_frame: typing.Any, expressed_in: typing.Any, t: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        Transport theorem (Craig's "Rigid Body Dynamics" slides): the derivative of u seen from
        A = `to_frame`, from its derivative du_B_E seen from B = `from_frame`: du_B_E + w_AB x u_E. u_E,
        du_B_E and the result (3,) in E.
        """
class Force:
    """
    Spatial force vector (wrench) [n; f], angular part first: n moment [N m] about the
    origin of the frame of expression, f force [N].
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_vector(vector: typing.Any) -> Force:
        """
        Force from a (6,) array [n; f].
        """
    def __add__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of the angular and linear parts.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, angular: typing.Any = None, linear: typing.Any = None) -> None:
        """
        Force from n (3,) [N m] and f (3,) [N] (None: zero).
        """
    def __mul__(self, arg0: typing.Any) -> Force:
        ...
    def __neg__(self) -> Force:
        ...
    def __repr__(self) -> str:
        ...
    def __rmul__(self, arg0: typing.Any) -> Force:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def __sub__(self, arg0: typing.Any) -> typing.Any:
        ...
    def dot(self, motion: typing.Any) -> float:
        """
        Power w . n + v . f [W] of this force on the motion (same frame and reference point).
        """
    def is_approx(self, other: typing.Any, prec: typing.Any = 1e-12) -> bool:
        """
        True when the 6-vectors agree to `prec` relative to the smaller norm (Eigen's isApprox: |a - b| <=
        prec min(|a|, |b|), so only an exactly zero Force is close to zero). == compares exactly.
        """
    def to_vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        [n; f] as a (6,) array.
        """
    @property
    def angular(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        n (3,) [N m]: moment about the frame's origin, expressed in that frame; read-only copy
        """
    @property
    def linear(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        f (3,) [N], expressed in the frame of the force; read-only copy
        """
class Motion:
    """
    Spatial motion vector (twist) [w; v], angular part first: w angular velocity [rad/s], v
    velocity [m/s] of the body point at the origin of the frame of expression.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_vector(vector: typing.Any) -> Motion:
        """
        Motion from a (6,) array [w; v].
        """
    def __add__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of the angular and linear parts.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, angular: typing.Any = None, linear: typing.Any = None) -> None:
        """
        Motion from w (3,) [rad/s] and v (3,) [m/s] (None: zero).
        """
    def __mul__(self, arg0: typing.Any) -> Motion:
        ...
    def __neg__(self) -> Motion:
        ...
    def __repr__(self) -> str:
        ...
    def __rmul__(self, arg0: typing.Any) -> Motion:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def __sub__(self, arg0: typing.Any) -> typing.Any:
        ...
    def cross(self, other: typing.Any) -> Motion:
        """
        Motion cross product (crm): self x other = [w1 x w2; w1 x v2 + v1 x w2].
        """
    def cross_force(self, force: typing.Any) -> Force:
        """
        Force cross product (crf): self x* force = [w x n + v x f; w x f].
        """
    def dot(self, force: typing.Any) -> float:
        """
        Power w . n + v . f [W] of the force on this motion (same frame and reference point).
        """
    def is_approx(self, other: typing.Any, prec: typing.Any = 1e-12) -> bool:
        """
        True when the 6-vectors agree to `prec` relative to the smaller norm (Eigen's isApprox: |a - b| <=
        prec min(|a|, |b|), so only an exactly zero Motion is close to zero). == compares exactly.
        """
    def to_vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        [w; v] as a (6,) array.
        """
    @property
    def angular(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        w (3,) [rad/s], expressed in the frame of the motion; read-only copy
        """
    @property
    def linear(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        v (3,) [m/s] of the body point at the frame's origin, expressed in that frame; read-only copy
        """
class Transform:
    """
    Rigid transform X_AB: R_AB (B coordinates -> A coordinates) and p_AB (B's origin in A)
    [m]. Maps points, motions and forces expressed in B to A; X_AB * X_BC = X_AC.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_quat(q_AB: typing.Any, translation: typing.Any = None, scalar_first: typing.Any = False) -> Transform:
        """
        X_AB from the unit quaternion q_AB (4,) ((x, y, z, w), or (w, x, y, z) if scalar_first) and
        p_AB (3,) [m] (default zero).
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of rotation and translation.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, rotation: typing.Any = None, translation: typing.Any = None) -> None:
        """
        X_AB from rotation R_AB (3,3), orthonormal with det +1 (default identity), and translation
        p_AB (3,) [m] (default zero). ValueError on a non-rotation or non-finite input.
        """
    def __mul__(self, arg0: typing.Any) -> typing.Any:
        """
        X_AB * X_BC = X_AC.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def act(self, spatial_vector: typing.Any) -> typing.Any:
        """
        A Motion in B -> in A: [R w; R v + p x (R w)]; a Force in B -> in A: [R n + p x (R f); R f].
        """
    def act_inv(self, spatial_vector: typing.Any) -> typing.Any:
        """
        A Motion in A -> in B: [R^T w; R^T (v - p x w)]; a Force in A -> in B: [R^T (n - p x f); R^T f].
        """
    def act_inv_point(self, p_A: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_B = R_AB^T (p_A - p_AB) for points p_A (3,) or (n, 3) [m].
        """
    def act_point(self, p_B: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_A = R_AB p_B + p_AB for points p_B (3,) or (n, 3) [m].
        """
    def force_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Featherstone's X* (6,6) = X^-T: [[R, hat(p) R], [0, R]].
        """
    def inverse(self) -> Transform:
        """
        X_BA = X_AB^-1.
        """
    def is_approx(self, other: typing.Any, prec: typing.Any = 1e-12) -> bool:
        """
        True when rotations and translations each agree to `prec` relative to the smaller norm (Eigen's
        isApprox; a zero translation compares only with an exactly zero one). == compares exactly.
        """
    def motion_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Featherstone's X (6,6), angular first: [[R, 0], [hat(p) R, R]].
        """
    def quat(self, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        q_AB (4,) with w >= 0, (x, y, z, w) or (w, x, y, z) if scalar_first.
        """
    @property
    def rotation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        R_AB (3,3), read-only copy
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_AB (3,) [m], read-only copy
        """
class Screw:
    """
    Screw of a twist (instantaneous screw axis): unit direction, point of the axis closest to
    the origin [m], pitch [m/rad] (inf for a pure translation) and magnitude (|w| [rad/s], or
    |v| [m/s] for a pure translation), all in the twist's frame.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every part.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], float, float]:
        ...
    def __init__(self, direction: typing.Any, point: typing.Any, pitch: typing.Any, magnitude: typing.Any) -> None:
        """
        Screw from its parts (checked by screw_to_twist): direction (3,) unit, point (3,) [m], pitch [m/rad]
        (inf: pure translation), magnitude [rad/s] (or [m/s]).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def direction(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        unit (3,), expressed in the twist's frame
        """
    @property
    def magnitude(self) -> float:
        """
        |w| [rad/s], or |v| [m/s] for a pure translation
        """
    @property
    def pitch(self) -> float:
        """
        [m/rad]; inf for a pure translation
        """
    @property
    def point(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) [m], the point of the axis closest to the twist's frame's origin, expressed in that frame
        """
class InertiaCheck:
    """
    What a constructor requires of a rotational inertia: `physical` (symmetric, PSD,
    triangle inequality I0 + I1 >= I2 on the principal moments) or `allow_unrealizable`
    (symmetric PSD only; a documented opt-in for test problems such as
    Hairer-Lubich-Wanner's I = diag(2, 1, 2/3), never the default).
    
    Members:
    
      physical
    
      allow_unrealizable
    """
    __members__: typing.ClassVar[dict[str, InertiaCheck]]
    allow_unrealizable: typing.ClassVar[InertiaCheck]
    physical: typing.ClassVar[InertiaCheck]
    @typing.overload
    def __eq__(self, other: InertiaCheck) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    @typing.overload
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, value: typing.Any) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: InertiaCheck) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class InertiaReport:
    """
    Validity report of (mass, inertia about the centre of mass); see inertia_report.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def summary(self) -> str:
        """
        One line with the key numbers.
        """
    def valid(self, check: typing.Any = InertiaCheck.physical) -> bool:
        """
        True when every check required by `check` passes.
        """
    @property
    def asymmetry(self) -> float:
        """
        max |I - I^T| [kg m^2]
        """
    @property
    def asymmetry_tolerance(self) -> float:
        """
        largest asymmetry accepted, 1e-12 max |I_ij| [kg m^2]
        """
    @property
    def condition_number(self) -> float:
        """
        I2 / I0 (inf when I0 <= 0)
        """
    @property
    def finite(self) -> bool:
        ...
    @property
    def mass(self) -> float:
        """
        [kg]
        """
    @property
    def mass_positive(self) -> bool:
        ...
    @property
    def positive_semidefinite(self) -> bool:
        ...
    @property
    def principal_moments(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) ascending I0 <= I1 <= I2 [kg m^2] of the inertia about the centre of mass
        """
    @property
    def symmetric(self) -> bool:
        ...
    @property
    def tolerance(self) -> float:
        """
        absolute tolerance of the positive semi-definite and triangle-inequality checks [kg m^2]
        """
    @property
    def triangle_inequality(self) -> bool:
        ...
    @property
    def triangle_margins(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) (I1+I2-I0, I0+I2-I1, I0+I1-I2) [kg m^2]; the last is binding
        """
class PrincipalAxes:
    """
    Principal moments and axes of a rotational inertia (Craig "Principal Axes"), in the frame the
    inertia is expressed in: moments ascending [kg m^2], axes as columns (column k is the unit axis of
    moments[k]; right-handed, det +1), so that I = axes @ diag(moments) @ axes.T. For a stack of n
    inertias, arrays (n, 3) and (n, 3, 3). Unpacks as `moments, axes = principal_axes(I)`.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        """
        0: moments, 1: axes (as the tuple (moments, axes)).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, moments: typing.Any, axes: typing.Any) -> None:
        """
        From moments (3,) [kg m^2] and axes (3,3) (or (n,3), (n,3,3)); copied, read-only.
        """
    def __iter__(self) -> typing.Any:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def axes(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,3) or (n,3,3): column k is the unit axis of moments[k], expressed in the inertia's frame;
        det +1. Read-only.
        """
    @property
    def moments(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) or (n, 3) ascending [kg m^2], read-only
        """
class SpatialInertia:
    """
    Mass properties of one rigid body: mass m [kg], centre of mass c [m] and rotational inertia about
    the centre of mass I_C [kg m^2], all expressed in one frame. Constructors check validity
    (ValueError with the principal moments, triangle margins and condition number).
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_inertia_about_origin(mass: typing.Any, com: typing.Any, inertia_about_origin: typing.Any, check: typing.Any = InertiaCheck.physical) -> SpatialInertia:
        """
        From the inertia (3,3) [kg m^2] about the frame's origin.
        """
    @staticmethod
    def from_inertia_about_point(mass: typing.Any, com: typing.Any, inertia_about_point: typing.Any, point: typing.Any, check: typing.Any = InertiaCheck.physical) -> SpatialInertia:
        """
        From the inertia (3,3) [kg m^2] about `point` (3,) [m] (parallel axis, Craig).
        """
    @staticmethod
    def from_matrix(matrix: typing.Any, check: typing.Any = InertiaCheck.physical) -> SpatialInertia:
        """
        From the (6,6) spatial inertia about the origin, angular first [[I_O, m hat(c)], [m hat(c)^T, m 1]].
        """
    @staticmethod
    def point_mass(mass: typing.Any, position: typing.Any) -> SpatialInertia:
        """
        A point mass [kg] at position (3,) [m].
        """
    def __add__(self, arg0: SpatialInertia) -> SpatialInertia:
        """
        Composite of two bodies expressed in the same frame.
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of mass, com and inertia_com (is_approx: up to a tolerance).
        """
    def __getstate__(self) -> tuple[float, numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, mass: typing.Any, com: typing.Any, inertia_com: typing.Any, check: typing.Any = InertiaCheck.physical) -> None:
        """
        mass [kg] > 0, com (3,) [m], inertia_com (3,3) [kg m^2] about the centre of mass.
        check: InertiaCheck.physical (default: triangle inequality required) or
        InertiaCheck.allow_unrealizable (opt-in: symmetric PSD only, e.g. I = diag(2, 1, 2/3)).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def __sub__(self, arg0: SpatialInertia) -> SpatialInertia:
        """
        This body with the part removed (a hole); ValueError if the rest is invalid.
        """
    def admits_symmetry_plane(self, normal: typing.Any, tolerance: typing.Any = 1e-09) -> bool:
        """
        Whether the plane through the centre of mass with this normal (3,) can be a plane of symmetry
        (Craig: then the products of inertia with the normal vanish). Necessary, not sufficient.
        """
    def angular_momentum_about_com(self, angular_velocity: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        H_C = I_C w (3,) [kg m^2/s]; w (3,) [rad/s] in the frame.
        """
    def angular_momentum_about_point(self, angular_velocity: typing.Any, com_velocity: typing.Any, point: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        H_P = r_PC x (m v_C) + H_C (3,) [kg m^2/s] (Craig); w [rad/s], v_C [m/s], point [m].
        """
    def inertia_about_origin(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia (3,3) [kg m^2] about the frame's origin.
        """
    def inertia_about_point(self, point: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia (3,3) [kg m^2] about point (3,) [m]: I_C + m (|r|^2 1 - r r^T), r = c - p.
        """
    def is_approx(self, other: typing.Any, prec: typing.Any = 1e-12) -> bool:
        """
        True when mass, centre of mass and inertia_com agree to `prec` relative to their size (the centre of
        mass relative to the radius of gyration plus |com|). == compares exactly.
        """
    def kinetic_energy(self, twist: typing.Any) -> float:
        """
        T = 1/2 V . I V [J] of the twist (Motion).
        """
    def matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (6,6) spatial inertia about the origin, angular first.
        """
    def momentum(self, twist: typing.Any) -> Force:
        """
        Spatial momentum h = I V (Force, moment about the origin) of the twist V = [w; v_O] (Motion).
        """
    def principal_axes(self) -> PrincipalAxes:
        """
        PrincipalAxes of I_C (about the centre of mass, in the frame of expression): moments ascending
        [kg m^2], axes as columns, right-handed.
        """
    def remove(self, part: typing.Any, check: typing.Any = InertiaCheck.physical) -> SpatialInertia:
        """
        This body with `part` removed (a hole), checked as the constructor.
        """
    def report(self) -> InertiaReport:
        """
        The validity report (InertiaReport).
        """
    def rotated(self, R_AB: typing.Any) -> SpatialInertia:
        """
        Re-expressed in A: c_A = R_AB c_B, I_C,A = R_AB I_C,B R_AB^T.
        """
    def transformed(self, X_AB: typing.Any) -> SpatialInertia:
        """
        Re-expressed in A (Transform X_AB): c_A = R_AB c_B + p_AB, I_C,A = R_AB I_C,B R_AB^T.
        """
    @property
    def com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        centre of mass (3,) [m], read-only copy
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        rotational inertia about the centre of mass (3,3) [kg m^2], read-only copy
        """
    @property
    def mass(self) -> float:
        """
        m [kg]
        """
class MeshWeldWarning(UserWarning):
    """
    Warned by solid_mesh and mesh_shell when welding merged vertices or dropped faces (a UserWarning;
    filter it with warnings.filterwarnings, or weld with weld_vertices first).
    """
class WeldedMesh:
    """
    A mesh after weld_vertices, with what the weld changed.
    """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64], int, int, float]:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def dropped_faces(self) -> int:
        """
        faces repeating a vertex after welding, dropped
        """
    @property
    def face_index(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (f',) int64 input index of each kept face
        """
    @property
    def faces(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (f', 3) int64 the non-degenerate faces, in input order, indexing vertices
        """
    @property
    def tolerance(self) -> float:
        """
        weld tolerance used [m]
        """
    @property
    def vertex_index(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (n',) int64 input index of each kept vertex
        """
    @property
    def vertices(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n', 3) [m] the kept vertices (each cluster's lowest-indexed), in input order
        """
    @property
    def welded_vertices(self) -> int:
        """
        input vertices merged into another
        """
class DensityIntegral:
    """
    Result of a density quadrature with its error estimate (all in the frame of the
    points rho was evaluated at).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple[SpatialInertia, float, float, float, int]:
        ...
    def __init__(self, inertia: typing.Any, mass_error: typing.Any, com_error: typing.Any, inertia_error: typing.Any, evaluations: typing.Any) -> None:
        """
        From its fields (as the attributes).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def com_error(self) -> float:
        """
        |c_high - c_low| [m]
        """
    @property
    def evaluations(self) -> int:
        """
        points at which rho was evaluated
        """
    @property
    def inertia(self) -> SpatialInertia:
        """
        SpatialInertia from the higher-order rule (centre of mass and inertia about it, in the frame
        of the points)
        """
    @property
    def inertia_error(self) -> float:
        """
        ||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass
        """
    @property
    def mass_error(self) -> float:
        """
        |m_high - m_low| [kg]
        """
class Particle:
    """
    A point mass (3 DOF; "Rigid body kinematics and dynamics" notes, section 4.11): mass float [kg] > 0 or a pint quantity.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float]:
        ...
    def __init__(self, mass: typing.Any) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
class PlanarBody:
    """
    A rigid body moving in the xy plane of W (x, y, theta; plane kinetics of Craig's "Rigid Body Dynamics" slides): mass [kg] and inertia_zz [kg m^2] about the z axis through the centre of mass, both > 0; each a float [unit] or a pint quantity.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, mass: typing.Any, inertia_zz: typing.Any) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def inertia_zz(self) -> float:
        """
        moment of inertia about z through G [kg m^2]
        """
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
class RigidBody:
    """
    A spatial rigid body (6 DOF), in three forms:
      RigidBody(mass, [I1, I2, I3])  mass [kg] > 0 and principal moments [kg m^2] about the centre of mass
                                     (the body axes B principal: inertia_com = diag(I1, I2, I3));
      RigidBody(mass, inertia_com)   inertia_com (3, 3) [kg m^2] about the centre of mass in B, moments on the
                                     diagonal and negated products off it (I_xy = -sum x y dm);
      RigidBody(spatial_inertia)     a SpatialInertia: its mass and inertia about its centre of mass, B placed
                                     at the centre of mass with the SpatialInertia's axes.
    The inertia must be symmetric positive definite and is checked as every inertia of rigiddyn is
    (inertia_report): under check=InertiaCheck.physical (the default) the principal moments must satisfy the
    triangle inequality I_a + I_b >= I_c; check=InertiaCheck.allow_unrealizable accepts test bodies no real
    body has, e.g. I = diag(2, 1, 2/3). euler_form tells which form of Euler's equations it uses:
    'spherical', 'principal' or 'full'.
    mass and inertia_com: floats [kg], [kg m^2] or pint quantities (an array quantity for the inertia; converted, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, mass: typing.Any, inertia_com: typing.Any = None, check: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def euler_form(self) -> str:
        """
        'spherical' (no gyroscopic term), 'principal' (diagonal inertia) or 'full'
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) inertia about the centre of mass in B [kg m^2] (read-only)
        """
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
class ParticleState:
    """
    Particle state: p_W (3,) [m] and v_W (3,) [m/s] in W (None: zero), each floats [unit] or a pint quantity. Fields are assigned whole (s.v_W = [...]); their arrays are read-only.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: typing.Any = None, v_W: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) position in W [m]
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) velocity in W [m/s]
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
class PlanarBodyState:
    """
    Planar body state: p_W (2,) [m] centre of mass in W, theta [rad] angle of B about z, v_W (2,) [m/s] in W, omega [rad/s] (None: zero), each floats [unit] or a pint quantity. Fields are assigned whole; their arrays are read-only.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float, numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, p_W: typing.Any = None, theta: typing.Any = 0.0, v_W: typing.Any = None, omega: typing.Any = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def omega(self) -> float:
        """
        angular velocity [rad/s]
        """
    @omega.setter
    def omega(self, arg1: typing.Any) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) centre of mass in W [m]
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def theta(self) -> float:
        """
        angle of B about z [rad]
        """
    @theta.setter
    def theta(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) velocity in W [m/s]
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
class RigidBodyState:
    """
    Rigid body state (docs/conventions.md): p_W (3,) centre of mass in W [m], q_WB (4,) unit quaternion (x, y, z, w), or (w, x, y, z) with scalar_first=True, v_W (3,) centre of mass velocity in W [m/s], w_B (3,) angular velocity [rad/s] in B (None: zero, identity); p_W, v_W, w_B: floats [unit] or pint quantities. q_WB is normalised; ValueError if | |q| - 1 | > 1e-6. Fields are assigned whole (s.w_B = [...], s.q_WB = [x, y, z, w], checked as here); their arrays are read-only.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: typing.Any = None, q_WB: typing.Any = None, v_W: typing.Any = None, w_B: typing.Any = None, scalar_first: typing.Any = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def quaternion(self, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        q_WB (4,) as (x, y, z, w), or (w, x, y, z) with scalar_first=True
        """
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) centre of mass position in W [m]
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4,) attitude (x, y, z, w), B to W; set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm)
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) centre of mass velocity in W [m/s]
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular velocity of B in W, expressed in B [rad/s]
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
class KineticEnergy:
    """
    Kinetic energy [J] split as T = translational + rotational: translational 1/2 m v_W.v_W of the centre of mass, rotational 1/2 w_B.I w_B about it (1/2 I_zz omega^2 for a planar body, 0 for a particle); total = their sum. Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, translational: typing.Any = 0.0, rotational: typing.Any = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def rotational(self) -> float:
        """
        1/2 w.I w about the centre of mass [J]
        """
    @property
    def total(self) -> float:
        """
        translational + rotational [J]
        """
    @property
    def translational(self) -> float:
        """
        1/2 m v.v [J]
        """
class ComWrench:
    """
    Loads reduced to the centre of mass G: f_W (3,) force in W [N] and tau_B (3,) torque about G in B [N m] (inverse_dynamics' result; unpacks as f_W, tau_B = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, f_W: typing.Any = None, tau_B: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def f_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) force in W [N]
        """
    @property
    def tau_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) torque about the centre of mass in B [N m]
        """
class PlanarWrench:
    """
    In-plane loads reduced to the centre of mass G: f_W (2,) force in W [N] and tau torque about z through G [N m] (inverse_dynamics' result for a PlanarBody; unpacks as f_W, tau = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, f_W: typing.Any = None, tau: typing.Any = 0.0) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def f_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) force in W [N]
        """
    @property
    def tau(self) -> float:
        """
        torque about z through the centre of mass [N m]
        """
class BodyAcceleration:
    """
    Accelerations of a rigid body: a_W (3,) of the centre of mass in W [m/s^2] and alpha_B (3,) angular, in B [rad/s^2] (forward_dynamics' result; unpacks as a_W, alpha_B = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, a_W: typing.Any = None, alpha_B: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def a_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) centre of mass acceleration in W [m/s^2]
        """
    @property
    def alpha_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular acceleration in B [rad/s^2]
        """
class PlanarAcceleration:
    """
    Accelerations of a planar body: a_W (2,) of the centre of mass in W [m/s^2] and alpha about z [rad/s^2] (forward_dynamics' result; unpacks as a_W, alpha = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, a_W: typing.Any = None, alpha: typing.Any = 0.0) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def a_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) centre of mass acceleration in W [m/s^2]
        """
    @property
    def alpha(self) -> float:
        """
        angular acceleration about z [rad/s^2]
        """
class PivotedBody:
    """
    A rigid body pinned at a point O fixed in the scene frame W (3 rotational DOF): the heavy top, the gyroscope.
      PivotedBody(body, p_OC_B, p_WO=(0, 0, 0))
    body: a RigidBody (mass [kg], inertia_com [kg m^2] about the centre of mass C in B); p_OC_B (3,): C relative to O, in B [m] (zero allowed: the free rotation about C); p_WO (3,): O in W [m]; each a float array or a pint quantity. B is the body frame at C as for RigidBody; C is at p_WO + R_WB p_OC_B. Euler's law is written about O (Craig, "Rigid Body Dynamics" slides: M_O = dH_O/dt) with inertia_O = I_C + m (|c|^2 1 - c c^T), the parallel-axis theorem with the products of inertia. digits_lost tells how many decimal digits of I_C the rounding of inertia_O loses (the compile of a scene warns above 6); ValueError naming p_OC_B beyond 15 digits lost (m |c|^2 > 1e15 times the smallest moment of I_C: inertia_O's moment about the axis through O and C, I_C's about it, is then rounding noise) or when inertia_O is no longer positive definite in double precision. Immutable; pickles; == compares body, p_OC_B and p_WO.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[RigidBody, typing.Any, typing.Any]:
        ...
    def __init__(self, body: typing.Any, p_OC_B: typing.Any, p_WO: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> RigidBody:
        """
        the RigidBody (a copy)
        """
    @property
    def digits_lost(self) -> float:
        """
        decimal digits of I_C lost in inertia_O: max(0, log10(m |c|^2 / smallest moment of I_C)), at most 15
        """
    @property
    def euler_form(self) -> str:
        """
        the form of Euler's equations of inertia_O: 'spherical', 'principal' or 'full'
        """
    @property
    def inertia_O(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) inertia about O in B, I_C + m (|c|^2 1 - c c^T) [kg m^2]
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) inertia about the centre of mass C, in B [kg m^2]
        """
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
    @property
    def p_OC_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) the centre of mass C relative to the pivot O, in B [m]
        """
    @property
    def p_WO(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) the pivot O in the scene frame W [m]
        """
class PivotedPlanarBody:
    """
    The compound pendulum: a planar body pinned at a point O fixed in the scene frame W, turning about W's z axis (1 DOF, R_WB = Rz(theta)).
      PivotedPlanarBody(mass, inertia_zz, p_OC_B, p_WO=(0, 0))
    mass [kg] > 0; inertia_zz [kg m^2] > 0 about the z axis through the centre of mass C; p_OC_B (2,): C relative to O in B's xy plane [m] (zero allowed); p_WO (2,): O in W's xy plane [m]; each a float or a pint quantity. Plane kinetics about O: inertia_O_zz alpha = tau_O, inertia_O_zz = inertia_zz + m |c|^2 (Craig, "Rigid Body Dynamics" slides); ValueError naming p_OC_B when inertia_O_zz exceeds the double range. Immutable; pickles; == compares every field.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float, typing.Any, typing.Any]:
        ...
    def __init__(self, mass: typing.Any, inertia_zz: typing.Any, p_OC_B: typing.Any, p_WO: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def inertia_O_zz(self) -> float:
        """
        moment of inertia about z through O, inertia_zz + m |c|^2 [kg m^2]
        """
    @property
    def inertia_zz(self) -> float:
        """
        moment of inertia about z through C [kg m^2]
        """
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
    @property
    def p_OC_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) C relative to O in B's xy plane [m]
        """
    @property
    def p_WO(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (2,) the pivot O in W's xy plane [m]
        """
class PivotedBodyState:
    """
    State of a PivotedBody: q_WB (4,) unit quaternion B to the scene frame W, (x, y, z, w), or (w, x, y, z) with scalar_first=True (None: identity); w_B (3,) angular velocity of B relative to W, in B [rad/s] (None: zero; floats or a pint quantity). q_WB is normalised; ValueError if | |q| - 1 | > 1e-6. Fields are assigned whole (s.w_B = [...], checked as here); their arrays are read-only.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], typing.Any]:
        ...
    def __init__(self, q_WB: typing.Any = None, w_B: typing.Any = None, scalar_first: typing.Any = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def quaternion(self, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        q_WB (4,) as (x, y, z, w), or (w, x, y, z) with scalar_first=True
        """
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4,) attitude (x, y, z, w), B to W; set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm)
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular velocity of B relative to W, expressed in B [rad/s]
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
class PivotedPlanarBodyState:
    """
    State of a PivotedPlanarBody: theta [rad], the angle of B about z (R_WB = Rz(theta)), and omega = d theta/dt [rad/s]; each a float or a pint quantity. Fields are assignable (checked as here).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, theta: typing.Any = 0.0, omega: typing.Any = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def omega(self) -> float:
        """
        angular velocity about z [rad/s]
        """
    @omega.setter
    def omega(self, arg1: typing.Any) -> None:
        ...
    @property
    def theta(self) -> float:
        """
        angle of B about z [rad]
        """
    @theta.setter
    def theta(self, arg1: typing.Any) -> None:
        ...
class PivotedAcceleration:
    """
    forward_dynamics' result for a PivotedBody: alpha_B (3,) angular acceleration in B [rad/s^2] and reaction_W (3,) the pivot's force on the body in W [N] (unpacks as alpha_B, reaction_W = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, alpha_B: typing.Any = None, reaction_W: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def alpha_B(self) -> typing.Any:
        """
        (3,) angular acceleration in B [rad/s^2]
        """
    @property
    def reaction_W(self) -> typing.Any:
        """
        (3,) the pivot's force on the body, in W [N]
        """
class PivotedTorque:
    """
    inverse_dynamics' result for a PivotedBody: tau_O_B (3,) the torque about O the motion needs besides gravity, in B [N m], and reaction_W (3,) the pivot's force on the body in W [N] (unpacks as tau_O_B, reaction_W = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, tau_O_B: typing.Any = None, reaction_W: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def reaction_W(self) -> typing.Any:
        """
        (3,) the pivot's force on the body, in W [N]
        """
    @property
    def tau_O_B(self) -> typing.Any:
        """
        (3,) torque about the pivot O, in B [N m]
        """
class PivotedPlanarAcceleration:
    """
    forward_dynamics' result for a PivotedPlanarBody: alpha [rad/s^2] about z and reaction_W (3,) the pivot's force on the body in W [N] (its z part is what the pin and the plane hold; unpacks as alpha, reaction_W = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, alpha: typing.Any = 0.0, reaction_W: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def alpha(self) -> typing.Any:
        """
        angular acceleration about z [rad/s^2]
        """
    @property
    def reaction_W(self) -> typing.Any:
        """
        (3,) the pivot's force on the body, in W [N]
        """
class PivotedPlanarTorque:
    """
    inverse_dynamics' result for a PivotedPlanarBody: tau_O [N m] the torque about z the motion needs besides gravity, and reaction_W (3,) the pivot's force on the body in W [N] (unpacks as tau_O, reaction_W = ...). Immutable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, tau_O: typing.Any = 0.0, reaction_W: typing.Any = None) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def reaction_W(self) -> typing.Any:
        """
        (3,) the pivot's force on the body, in W [N]
        """
    @property
    def tau_O(self) -> typing.Any:
        """
        torque about the z axis through O [N m]
        """
class Wheel:
    """
    A wheel of a Gyrostat, spun about an axis fixed in the body by a motor.
    
    Parameters
    ----------
    axis_B : array_like, shape (3,)
        The spin axis in the body frame B (any non-zero length; the unit axis is kept).
    inertia : float or pint.Quantity
        The wheel's moment of inertia about its spin axis [kg m^2], > 0.
    motor_torque : float or pint.Quantity, default 0
        The motor's torque on the wheel about its axis [N m] (the body feels its reaction), applied for t_start <= t < t_end.
    t_start, t_end : float or pint.Quantity, default 0 and inf
        The motor's time window [s] (a run splits its steps at both).
    
    Examples
    --------
    >>> import rigiddyn as rd
    >>> rd.Wheel(axis_B=[0, 0, 2], inertia=0.01, motor_torque=0.002, t_end=5.0).axis_B
    array([0., 0., 1.])
    
    Immutable; pickles; == compares every field.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, float, float, float, float]:
        ...
    def __init__(self, axis_B: typing.Any, inertia: typing.Any, motor_torque: typing.Any = 0.0, t_start: typing.Any = 0.0, t_end: typing.Any = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def axis_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) the unit spin axis in B
        """
    @property
    def inertia(self) -> float:
        """
        axial moment of inertia [kg m^2]
        """
    @property
    def motor_torque(self) -> float:
        """
        motor torque [N m]
        """
    @property
    def t_end(self) -> float:
        """
        the motor's end [s] (inf: never)
        """
    @property
    def t_start(self) -> float:
        """
        the motor's start [s]
        """
class Gyrostat:
    """
    A rigid body carrying wheels, each spun about an axis fixed in the body by a motor, each wheel's speed relative to the body a state (Hughes, "Spacecraft Attitude Dynamics", ch. 3): a reaction-wheel spacecraft.
    
    With I the whole body's inertia (wheels locked), wheel k's unit axis a_k, axial inertia J_k, speed Omega_k relative to the body and motor torque u_k, the transverse inertia A = I - sum J_k a_k a_k^T:
        A dw/dt = tau_B - sum u_k a_k - w x (I w + h_w),  dOmega_k/dt = u_k / J_k - a_k . dw/dt,
    h_w = sum J_k Omega_k a_k; kinetic energy T = 1/2 m |v|^2 + 1/2 w.A w + 1/2 sum J_k (a_k.w + Omega_k)^2.
    
    Parameters
    ----------
    body : RigidBody
        The whole body with its wheels locked: mass [kg] and inertia_com [kg m^2] about its centre of mass in B, wheels included.
    wheels : sequence of Wheel
        Its wheels (ValueError naming wheels[k].inertia when a wheel's axial inertia leaves A not positive definite).
    
    Examples
    --------
    >>> import rigiddyn as rd
    >>> sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05)])
    >>> sat.transverse_inertia.diagonal()
    array([10.  , 12.  , 14.95])
    
    Elements see it as its locked RigidBody. It runs in an inertial scene with explicit_euler, semi_implicit_euler, rk4, rkmk4 or implicit_midpoint. Immutable; pickles; == compares body and wheels.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[RigidBody, list]:
        ...
    def __init__(self, body: typing.Any, wheels: typing.Any) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> RigidBody:
        """
        the RigidBody with the wheels locked (a copy)
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) inertia about the centre of mass in B, wheels locked [kg m^2]
        """
    @property
    def mass(self) -> float:
        """
        mass [kg]
        """
    @property
    def transverse_inertia(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) A = I - sum J_k a_k a_k^T [kg m^2]: the body with its wheels free to spin
        """
    @property
    def wheels(self) -> tuple:
        """
        the wheels (a tuple)
        """
class GyrostatState:
    """
    State of a Gyrostat: the rigid body's and its wheels' speeds.
    
    Parameters
    ----------
    p_W : array_like, shape (3,), optional
        Centre of mass position in W [m] (None: zero).
    q_WB : array_like, shape (4,), optional
        Unit quaternion B to W, (x, y, z, w), or (w, x, y, z) with scalar_first=True (None: identity; normalised, ValueError beyond 1e-6 of unit norm).
    v_W : array_like, shape (3,), optional
        Centre of mass velocity in W [m/s] (None: zero).
    w_B : array_like, shape (3,), optional
        Angular velocity of B relative to W, in B [rad/s] (None: zero).
    wheel_speeds : array_like, shape (nw,), optional
        Each wheel's speed relative to the body [rad/s], in the order of the gyrostat's wheels (None: none; a run checks one per wheel).
    
    Examples
    --------
    >>> import rigiddyn as rd
    >>> rd.GyrostatState(w_B=[0, 0, 0.1], wheel_speeds=[100.0]).wheel_speeds
    array([100.])
    
    Fields are assigned whole (checked as here); their arrays are read-only.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, numpy.typing.NDArray[numpy.float64], typing.Any, typing.Any, numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: typing.Any = None, q_WB: typing.Any = None, v_W: typing.Any = None, w_B: typing.Any = None, wheel_speeds: typing.Any = None, scalar_first: typing.Any = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) centre of mass position in W [m]
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4,) attitude (x, y, z, w), B to W; set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm)
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) centre of mass velocity in W [m/s]
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) angular velocity of B in W, expressed in B [rad/s]
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
    @property
    def wheel_speeds(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (nw,) each wheel's speed relative to the body [rad/s]
        """
    @wheel_speeds.setter
    def wheel_speeds(self, arg1: typing.Any) -> None:
        ...
class ElementField:
    """
    One field of a force element class (its class attribute `fields`, in constructor order): key (the keyword and attribute), kind ('scalar', 'vector' (3,), 'bodies', 'body', 'optional_body', 'loads', 'frame' or 'callable'), unit (SI, pint syntax; '' when none), required, default (None when required; a vector as a tuple) and doc.
    """
    def __repr__(self) -> str:
        ...
    @property
    def default(self) -> typing.Any:
        ...
    @property
    def doc(self) -> str:
        ...
    @property
    def key(self) -> str:
        ...
    @property
    def kind(self) -> str:
        ...
    @property
    def required(self) -> bool:
        ...
    @property
    def unit(self) -> str:
        ...
class UniformGravity:
    """
    Uniform gravity on the listed bodies: f_W = m g_W at each centre of mass, potential V = -m g_W . p_W [J]. A planar body keeps the in-plane part (the plane takes the rest).
    
    Parameters
    ----------
    g_W : array_like, shape (3,) [m/s^2], default (0.0, 0.0, -9.81)
        (3,) gravitational acceleration in W [m/s^2]
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, g_W: typing.Any = (0.0, 0.0, -9.81), bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def g_W(self) -> typing.Any:
        """
        (3,) gravitational acceleration in W [m/s^2]
        """
class PointMassGravity:
    """
    A fixed attractor of gravitational parameter gm at p_W in W: on each listed body f_W = -gm m r/(|r|^2 + softening^2)^(3/2), r = p_body - p_W, potential V = -gm m/sqrt(|r|^2 + softening^2) [J].
    
    Parameters
    ----------
    gm : float [m^3/s^2], required
        gravitational parameter GM of the attractor [m^3/s^2]
    p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) position of the fixed attractor in W [m]
    softening : float [m], default 0.0
        softening length epsilon [m] (0: none)
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, gm: typing.Any, p_W: typing.Any = (0.0, 0.0, 0.0), softening: typing.Any = 0.0, bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def gm(self) -> typing.Any:
        """
        gravitational parameter GM of the attractor [m^3/s^2]
        """
    @property
    def p_W(self) -> typing.Any:
        """
        (3,) position of the fixed attractor in W [m]
        """
    @property
    def softening(self) -> typing.Any:
        """
        softening length epsilon [m] (0: none)
        """
class MutualGravity:
    """
    Newtonian gravity between the listed bodies (direct O(N^2) sum over the pairs): f on i = -G m_i m_j r/(|r|^2 + softening^2)^(3/2), r = p_i - p_j [N], potential V = sum -G m_i m_j/sqrt(|r|^2 + softening^2) [J].
    
    Parameters
    ----------
    G : float [m^3/(kg*s^2)], default 6.6743e-11
        gravitational constant [m^3/(kg s^2)]
    softening : float [m], default 0.0
        softening length epsilon [m] (0: none)
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies that attract each other
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, G: typing.Any = 6.6743e-11, softening: typing.Any = 0.0, bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def G(self) -> typing.Any:
        """
        gravitational constant [m^3/(kg s^2)]
        """
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies that attract each other
        """
    @property
    def softening(self) -> typing.Any:
        """
        softening length epsilon [m] (0: none)
        """
class GravityGradient:
    """
    The gravity-gradient (MacCullagh) term of a central attractor gm at p_W in W on extended bodies: torque tau_B = 3 gm/|r|^5 r_B x (I r_B) [N m] and the matching force, so that the potential V2 = -gm/(2|r|^3) (tr I - 3 r^T I_W r/|r|^2) [J] is conserved with the motion; no effect on particles.
    
    Parameters
    ----------
    gm : float [m^3/s^2], required
        gravitational parameter GM of the central attractor [m^3/s^2]
    p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) position of the attractor in W [m]
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, gm: typing.Any, p_W: typing.Any = (0.0, 0.0, 0.0), bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def gm(self) -> typing.Any:
        """
        gravitational parameter GM of the central attractor [m^3/s^2]
        """
    @property
    def p_W(self) -> typing.Any:
        """
        (3,) position of the attractor in W [m]
        """
class SpringDamper:
    """
    A linear spring and damper between point_a_B of body_a (in its frame B, from its centre of mass) and point_b of body_b (in its B) or, body_b None, the world anchor point_b in W. Force on a: -(stiffness (l - rest_length) + damping dl/dt) u, u = (x_a - x_b)/l, l = |x_a - x_b| [N], along the line (no force at l = 0), so the pair conserves momentum and angular momentum; the opposite on b; torque r x f about each centre of mass. Potential V = stiffness (l - rest_length)^2/2 [J].
    
    Parameters
    ----------
    body_a : int, required
        index of the body at end a
    point_a_B : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) end a in body a's frame B, from its centre of mass [m]
    body_b : int or None, default None
        index of the body at end b, or None: end b is the world anchor point_b
    point_b : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) end b: in body b's frame B from its centre of mass, or in W if body_b is None [m]
    stiffness : float [N/m], required
        spring stiffness k [N/m]
    rest_length : float [m], default 0.0
        rest length l0 [m]
    damping : float [N*s/m], default 0.0
        damping coefficient c [N s/m]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body_a: typing.Any, point_a_B: typing.Any = (0.0, 0.0, 0.0), body_b: typing.Any = None, point_b: typing.Any = (0.0, 0.0, 0.0), stiffness: typing.Any, rest_length: typing.Any = 0.0, damping: typing.Any = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body_a(self) -> typing.Any:
        """
        index of the body at end a
        """
    @property
    def body_b(self) -> typing.Any:
        """
        index of the body at end b, or None: end b is the world anchor point_b
        """
    @property
    def damping(self) -> typing.Any:
        """
        damping coefficient c [N s/m]
        """
    @property
    def point_a_B(self) -> typing.Any:
        """
        (3,) end a in body a's frame B, from its centre of mass [m]
        """
    @property
    def point_b(self) -> typing.Any:
        """
        (3,) end b: in body b's frame B from its centre of mass, or in W if body_b is None [m]
        """
    @property
    def rest_length(self) -> typing.Any:
        """
        rest length l0 [m]
        """
    @property
    def stiffness(self) -> typing.Any:
        """
        spring stiffness k [N/m]
        """
class Drag:
    """
    Linear and quadratic drag on the listed bodies: f_W = -(linear + quadratic |v_W|) v_W [N] at the centre of mass and tau_B = -(angular_linear + angular_quadratic |w_B|) w_B [N m]. Velocity-dependent: the splitting methods warn (SceneCompatibilityWarning).
    
    Parameters
    ----------
    linear : float [N*s/m], default 0.0
        c1 of f_W = -(c1 + c2 |v_W|) v_W [N s/m]
    quadratic : float [N*s^2/m^2], default 0.0
        c2 of f_W = -(c1 + c2 |v_W|) v_W [N s^2/m^2]
    angular_linear : float [N*m*s], default 0.0
        d1 of tau_B = -(d1 + d2 |w_B|) w_B [N m s/rad]
    angular_quadratic : float [N*m*s^2], default 0.0
        d2 of tau_B = -(d1 + d2 |w_B|) w_B [N m s^2/rad^2]
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, linear: typing.Any = 0.0, quadratic: typing.Any = 0.0, angular_linear: typing.Any = 0.0, angular_quadratic: typing.Any = 0.0, bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def angular_linear(self) -> typing.Any:
        """
        d1 of tau_B = -(d1 + d2 |w_B|) w_B [N m s/rad]
        """
    @property
    def angular_quadratic(self) -> typing.Any:
        """
        d2 of tau_B = -(d1 + d2 |w_B|) w_B [N m s^2/rad^2]
        """
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def linear(self) -> typing.Any:
        """
        c1 of f_W = -(c1 + c2 |v_W|) v_W [N s/m]
        """
    @property
    def quadratic(self) -> typing.Any:
        """
        c2 of f_W = -(c1 + c2 |v_W|) v_W [N s^2/m^2]
        """
class ScheduledLoads:
    """
    The piecewise-constant schedule `loads` (AppliedLoad or a sequence: force [N] and torque [N m], each in W or B, active on [t_start, t_end) [s]) on body `body`, the forces applied at point_B (in B, from the centre of mass; adds the torque point_B x f_B). A run splits its steps at the switch times, as simulate does for one body.
    
    Parameters
    ----------
    body : int, required
        index of the body the loads act on
    loads : AppliedLoad or sequence of AppliedLoad, default ()
        tuple of AppliedLoad: the piecewise-constant schedule
    point_B : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) point of application of the forces in B, from the centre of mass [m]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: typing.Any, loads: typing.Any = (), point_B: typing.Any = (0.0, 0.0, 0.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the body the loads act on
        """
    @property
    def loads(self) -> typing.Any:
        """
        tuple of AppliedLoad: the piecewise-constant schedule
        """
    @property
    def point_B(self) -> typing.Any:
        """
        (3,) point of application of the forces in B, from the centre of mass [m]
        """
class PythonForce:
    """
    A force written in Python: fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B) is called for each listed body at every derivative evaluation, with t [s], the body's index, p_W (3,) [m] and v_W (3,) [m/s] in W, q_WB (4,) (x, y, z, w) and w_B (3,) [rad/s] in B (a particle: q_WB identity, w_B 0; a planar body: p_W = (x, y, 0), q_WB = Rz(theta), w_B = (0, 0, omega)); it returns f_W (3,) [N] in W at the centre of mass and tau_B (3,) [N m] in B. It is treated as time- and velocity-dependent. Each call takes the GIL (the run otherwise releases it: other Python threads wait during fn) and costs about 1.2 us per call against about 10 ns for a built-in element (measured 2026-11-24, 10 particles, RK4: python bench/python/bench_scene.py). An exception raised by fn stops the run and propagates; a return value other than two finite 3-vectors raises TypeError/ValueError naming fn.
    
    Parameters
    ----------
    fn : callable, required
        a callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B)
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, fn: typing.Any, bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def fn(self) -> typing.Any:
        """
        a callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B)
        """
class Thrust:
    """
    The thrust of a body whose mass changes (its MassFlow, given to Scene.add_body): f = (dm/dt) u_rel [N] ("Rigid body kinematics and dynamics" notes, eq. (4.36): d(m v)/dt = f + (dm/dt)(v + u_rel), so m dv/dt = f + (dm/dt) u_rel), u_rel the velocity of the mass leaving (dm/dt < 0: u_rel backwards pushes forwards) or joining the body, relative to it, in `frame` ('body': in B, turning with the body; 'world': in the scene frame W), applied at r_B in B from the centre of mass (adds the torque r_B x f_B). Scene.add refuses it (ValueError naming element.body) on a body without a MassFlow. No potential; its power is in SceneResult.power.
    
    Parameters
    ----------
    body : int, required
        index of the body (one with a MassFlow) whose exchanged mass pushes it
    u_rel : array_like, shape (3,) [m/s], required
        (3,) velocity of the exchanged mass relative to the body, in `frame` [m/s]
    frame : {'body', 'world'}, default 'body'
        'body' (u_rel in B, turning with the body) or 'world' (in the scene frame W)
    r_B : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) point of application in B, from the centre of mass [m]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: typing.Any, u_rel: typing.Any, frame: typing.Any = 'body', r_B: typing.Any = (0.0, 0.0, 0.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the body (one with a MassFlow) whose exchanged mass pushes it
        """
    @property
    def frame(self) -> typing.Any:
        """
        'body' (u_rel in B, turning with the body) or 'world' (in the scene frame W)
        """
    @property
    def r_B(self) -> typing.Any:
        """
        (3,) point of application in B, from the centre of mass [m]
        """
    @property
    def u_rel(self) -> typing.Any:
        """
        (3,) velocity of the exchanged mass relative to the body, in `frame` [m/s]
        """
class MagneticDipole:
    """
    A magnetic dipole m_B fixed in each listed body's frame B, in a static field: the uniform B_W plus the field of a fixed source dipole source_moment_W at source_p_W, B(p) = B_W + mu0/(4 pi) (3 r (r . M)/|r|^5 - M/|r|^3), r = p - source_p_W. Torque tau_B = m_B x B_B [N m], force f_W = grad(m_W . B) [N] (zero in a uniform field), potential V = -m_W . B [J]: the motion conserves T + V. A compass needle of moment of inertia I swings at sqrt(|m| |B| / I) [rad/s] for small angles. Particles (no attitude) are skipped; a planar body keeps the in-plane force and tau_z.
    
    Parameters
    ----------
    m_B : array_like, shape (3,) [A*m^2], required
        (3,) magnetic dipole moment of each body, in its B [A m^2]
    B_W : array_like, shape (3,) [T], default (0.0, 0.0, 0.0)
        (3,) uniform magnetic flux density in W [T]
    source_moment_W : array_like, shape (3,) [A*m^2], default (0.0, 0.0, 0.0)
        (3,) moment of the fixed source dipole, in W [A m^2] (zero: no source)
    source_p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) position of the source dipole in W [m]
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, m_B: typing.Any, B_W: typing.Any = (0.0, 0.0, 0.0), source_moment_W: typing.Any = (0.0, 0.0, 0.0), source_p_W: typing.Any = (0.0, 0.0, 0.0), bodies: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def B_W(self) -> typing.Any:
        """
        (3,) uniform magnetic flux density in W [T]
        """
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def m_B(self) -> typing.Any:
        """
        (3,) magnetic dipole moment of each body, in its B [A m^2]
        """
    @property
    def source_moment_W(self) -> typing.Any:
        """
        (3,) moment of the fixed source dipole, in W [A m^2] (zero: no source)
        """
    @property
    def source_p_W(self) -> typing.Any:
        """
        (3,) position of the source dipole in W [m]
        """
class ReactionWheel:
    """
    A reaction wheel inside a rigid body (a gyrostat): a wheel of moment of inertia J = inertia about the unit axis a = axis_B/|axis_B| (fixed in B) spins relative to the body at the commanded speed Omega(t) = speed + acceleration (clamp(t, t_start, t_end) - t_start), so its relative angular momentum is h_B = J Omega a. The body's inertia is the whole body's, wheel included; the element applies the couple tau_B = -w_B x h_B - dh_B/dt [N m] of Euler's equation of the gyrostat, I dw/dt + w x (I w + h) = tau - dh/dt. A run splits its steps at t_start and t_end. At a constant wheel speed the body's kinetic energy and the total angular momentum R (I w + h) are conserved; spinning the wheel up about a principal axis turns the body by -J/I times the wheel's angle. Rigid bodies, free or pinned.
    
    Parameters
    ----------
    body : int, required
        index of the rigid body (free or pinned) that carries the wheel
    axis_B : array_like, shape (3,), required
        (3,) the wheel's spin axis in B (normalised; not zero)
    inertia : float [kg*m^2], required
        the wheel's moment of inertia J about its axis [kg m^2]
    speed : float [rad/s], default 0.0
        the wheel's speed relative to the body at t_start [rad/s]
    acceleration : float [rad/s^2], default 0.0
        the rate of the wheel's speed on [t_start, t_end) [rad/s^2]
    t_start : float [s], default 0.0
        the start of the ramp [s]
    t_end : float [s], default inf
        the end of the ramp [s] (inf: none)
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: typing.Any, axis_B: typing.Any, inertia: typing.Any, speed: typing.Any = 0.0, acceleration: typing.Any = 0.0, t_start: typing.Any = 0.0, t_end: typing.Any = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def acceleration(self) -> typing.Any:
        """
        the rate of the wheel's speed on [t_start, t_end) [rad/s^2]
        """
    @property
    def axis_B(self) -> typing.Any:
        """
        (3,) the wheel's spin axis in B (normalised; not zero)
        """
    @property
    def body(self) -> typing.Any:
        """
        index of the rigid body (free or pinned) that carries the wheel
        """
    @property
    def inertia(self) -> typing.Any:
        """
        the wheel's moment of inertia J about its axis [kg m^2]
        """
    @property
    def speed(self) -> typing.Any:
        """
        the wheel's speed relative to the body at t_start [rad/s]
        """
    @property
    def t_end(self) -> typing.Any:
        """
        the end of the ramp [s] (inf: none)
        """
    @property
    def t_start(self) -> typing.Any:
        """
        the start of the ramp [s]
        """
class SceneFrame:
    """
    The frame F a scene's states are relative to, moving relative to the inertial frame W (Scene.frame; None:
    W itself). Build it with
      SceneFrame.rotating(axis, rate)   F turns at `rate` [rad/s] about `axis` (3,) (any non-zero length; fixed
                                        in F and in W) through its origin, fixed at W's origin; F = W at t = 0;
      SceneFrame.earth(latitude)        the local frame (x east, y north, z up) at `latitude` [rad] on the turning
                                        Earth: Omega = 7.2921159e-5 rad/s about (0, cos(latitude), sin(latitude));
      SceneFrame.moving(frame_motion, terms=None)
                                        any motion of F relative to W, a FrameMotion (a Python kinematics_at(t) is
                                        called with the GIL taken, at each derivative evaluation); terms: the
                                        fictitious terms that act, when the motion leaves some identically zero.
    Each physical argument: a float [its unit] or a pint quantity. Newton's and Euler's laws seen from F gain the
    fictitious terms ("Rigid body kinematics and dynamics" notes, eqs. (4.39)-(4.40)): frame origin -m a_O, Euler
    -m alpha x r, centrifugal -m Omega x (Omega x r), Coriolis -2 m Omega x v (and their torques on bodies with an
    attitude); compiling a scene adds those that act (SceneFrame.terms) as elements "FrameOriginForce", "EulerForce",
    "CentrifugalForce", "CoriolisForce" after the scene's own (columns of SceneResult.work and power): the centrifugal
    and Coriolis ones for rotating and earth (none at rate 0), none for a FrameMotion.fixed placement, every term
    for a general motion unless `terms` names those that act (a motion turning at a constant rate has no Euler term,
    one whose origin does not accelerate no origin term; each evaluation of the motion then checks that the values
    of the terms left out are zero, else ValueError naming `frame`). Every
    element, state and record of the scene is then in F. A motion function returning a non-finite value raises
    ValueError naming `frame`; an exception it raises propagates out of simulate. Immutable; pickles (a
    FrameMotion of a module-level function); == compares how it was built.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def earth(latitude: typing.Any) -> SceneFrame:
        """
        The local frame at `latitude` [rad] in [-pi/2, pi/2] (a pint angle: '48.85 deg') on the turning Earth: x east, y north, z up, Omega = 7.2921159e-5 rad/s about (0, cos(latitude), sin(latitude)); its origin is taken as fixed (the centripetal acceleration of the ground is part of the local gravity, a UniformGravity).
        """
    @staticmethod
    def moving(frame_motion: typing.Any, terms: typing.Any = None) -> SceneFrame:
        """
        F moving relative to W as the FrameMotion `frame_motion` gives (P = W: R_WF, angular velocity and acceleration, origin position, velocity and acceleration, all in W). terms: None (a FrameMotion.fixed placement: none; a FrameMotion.constant_rotation: 'centrifugal' and 'coriolis'; any other motion: every term) or the names of the fictitious terms that act, among 'origin' (a_O not identically 0), 'euler' (alpha), 'centrifugal' and 'coriolis' (Omega: both or neither; 'euler' only with them); compile adds those alone, and each evaluation of the motion checks that the values of the others are zero (ValueError naming `frame` at that t). ValueError naming `terms` for a set that cannot be, or another set than a fixed placement's or a constant rotation's own.
        """
    @staticmethod
    def rotating(axis: typing.Any, rate: typing.Any) -> SceneFrame:
        """
        F turning at `rate` [rad/s] about `axis` (3,) (non-zero) through its origin, fixed at W's origin; F = W at t = 0 (only the centrifugal and Coriolis terms act; the centrifugal one has a potential).
        """
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def constant_rotation(self) -> bool:
        """
        True when F turns at a constant rate about its fixed origin (rotating, earth)
        """
    @property
    def motion(self) -> FrameMotion:
        """
        the FrameMotion of F relative to W
        """
    @property
    def terms(self) -> tuple:
        """
        the fictitious terms that act, a tuple of names among 'origin', 'euler', 'centrifugal', 'coriolis' (in that order): compile adds them as 'frame.<name>' (FrameOriginForce, EulerForce, CentrifugalForce, CoriolisForce)
        """
class MassFlow:
    """
    The mass flow of a body (Scene.add_body(body, mass_flow=...)): its mass changes at the rate
      rate          dm/dt [kg/s]: a float (or a pint quantity; negative: the body loses mass) or a callable
                    rate(t) -> float of the time t [s];
    and its rotational inertia about the centre of mass follows
      inertia_rule  'scaled' (I_C(m) = I_C0 m / m0: the body's shape is kept; every method applies) or a callable
                    inertia_rule(m) -> (3, 3) [kg m^2] in B of the mass m [kg] (the splitting methods are refused).
    The mass starts at the body's mass and is a coordinate of the run (SceneResult.mass). Its force is the
    Thrust element, f = rate u_rel ("Rigid body kinematics and dynamics" notes, eq. (4.36): m dv/dt = f + (dm/dt)
    u_rel). The mass leaving carries its own angular momentum (no jet damping): I(m) dw/dt + w x I(m) w = tau.
    Callables are called with the GIL taken, at each derivative evaluation; an exception they raise stops the run
    and propagates; a non-finite value raises ValueError naming mass_flows[i].rate or inertia_rule. A mass reaching
    zero raises ValueError naming mass_flows[i] and the step (for a constant rate, before the run: naming steps, dt).
    The kinetic energy the flow takes away or brings at the body's own velocity, 1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w
    integrated, is SceneResult.mass_flow_energy: kinetic_energy - kinetic_energy[0] ~ work + mass-flow energy.
    Immutable; pickles (callables defined at module level); == compares rate and inertia_rule.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rate: typing.Any = 0.0, inertia_rule: typing.Any = 'scaled') -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def inertia_rule(self) -> typing.Any:
        """
        'scaled' or the callable inertia_rule(m) -> (3, 3) [kg m^2]
        """
    @property
    def rate(self) -> typing.Any:
        """
        dm/dt [kg/s] (a float) or the callable rate(t)
        """
class SceneCompatibilityWarning(UserWarning):
    """
    Warned when a scene is compiled for a method whose properties its elements break (e.g. velocity-dependent forces with a splitting method: order 1 in the damping, energy behaviour not symplectic). A UserWarning.
    """
class Scene:
    """
    A scene: bodies (Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody) and the force elements
    acting on them, as data, in a frame: W (inertial; the default) or the SceneFrame `frame` (states, elements and
    records are then relative to it, with its fictitious forces compiled in). A body may carry a MassFlow (its mass
    changes; a Thrust element gives its force).
    
        scene = rigiddyn.Scene()
        sat = scene.add_body(rigiddyn.RigidBody(500.0, [400.0, 300.0, 200.0]), name="sat")
        scene.add(rigiddyn.PointMassGravity(gm=3.986004418e14))
        result = rigiddyn.simulate(scene, [rigiddyn.RigidBodyState(p_W=[7e6, 0, 0], v_W=[0, 7546.0, 0])],
                                   dt=1.0, steps=6000, method="rk4")
    
    Scene(bodies=None, body_names=None, elements=None, frame=None, mass_flows=None) builds the same from lists
    (body_names: one str or None per body; mass_flows: one MassFlow or None per body); it is what repr prints. Bodies are indexed in the order added; an element refers to bodies
    by index and is checked against the bodies added so far (add bodies first). Compile it for a method with
    compile(method) (a CompiledScene, immutable), or give it to rigiddyn.simulate / rigiddyn.step, which
    compile it. Mutable (add_body, add, frame); pickles; == compares bodies, names, elements, frame and mass flows.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[list, list, list, typing.Any, typing.Any]:
        ...
    def __init__(self, bodies: typing.Any = None, body_names: typing.Any = None, elements: typing.Any = None, frame: typing.Any = None, mass_flows: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def add(self, element: typing.Any) -> int:
        """
        Adds a force element (an instance of a class of rigiddyn.FORCE_ELEMENTS) after checking it against the bodies added so far (indices in range, loads the body's kind can take: ValueError naming element.<field>); returns its index (the column of SceneResult.work and power).
        """
    def add_body(self, body: typing.Any, name: typing.Any = None, mass_flow: typing.Any = None) -> int:
        """
        Adds `body` (a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat) named `name` (a str no other body has; None: 'body<index>') with its mass flow `mass_flow` (a MassFlow; None: a constant mass); returns its index, by which elements refer to it.
        """
    def compile(self, method: typing.Any = 'rk4') -> CompiledScene:
        """
        The scene compiled for `method` (a name of methods()): an immutable CompiledScene whose derivative evaluates only the declared elements. ValueError with the reason when the method cannot run the scene (e.g. 'exact' with any force element); SceneCompatibilityWarning when it runs it with weaker properties (velocity-dependent elements with a splitting method).
        """
    def describe(self, method: typing.Any = None) -> typing.Any:
        """
        A text table of the scene: bodies (kind, mass [kg], inertia [kg m^2] in B, state), force elements (parameters in SI with their frames, properties, the terms on each body), the frame (W, inertial), the units and, with `method` (a name of methods()), its order and the compile's verdict (rigiddyn.scene_describe.describe).
        """
    def to_toml(self, initial: typing.Any = None, run: typing.Any = None, name: typing.Any = None, description: typing.Any = None) -> typing.Any:
        """
        The canonical scene file (TOML text: SI units, radians, q_WB as (x, y, z, w)) of the scene with `initial` (one state per body, or None), `run` (a rigiddyn.scene_file.RunOptions or None), `name` and `description`; rigiddyn.load_scene reads it back to the same scene (rigiddyn.scene_file.scene_to_toml).
        """
    @property
    def bodies(self) -> tuple:
        """
        tuple of the bodies (copies), in index order
        """
    @property
    def body_names(self) -> tuple:
        """
        tuple of the bodies' names (str), in index order
        """
    @property
    def elements(self) -> tuple:
        """
        tuple of the force elements (copies), in the order added
        """
    @property
    def frame(self) -> typing.Any:
        """
        the SceneFrame F the states, elements and records are relative to, or None (the default: W, inertial); assignable
        """
    @frame.setter
    def frame(self, arg1: typing.Any) -> None:
        ...
    @property
    def mass_flows(self) -> tuple:
        """
        tuple of each body's MassFlow, or None for a constant mass, in index order
        """
class CompiledScene:
    """
    A scene compiled for one method (Scene.compile): immutable; its derivative evaluates only the declared elements. CompiledScene(scene, method='rk4') is scene.compile(method). Give it to rigiddyn.simulate / rigiddyn.step (method None or its own). Pickles (as its scene and method); == compares both.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[Scene, str]:
        ...
    def __init__(self, scene: typing.Any, method: typing.Any = 'rk4') -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def describe(self) -> typing.Any:
        """
        Scene.describe of its scene with its method: bodies, force elements, frame, units, the method's order and the compile's verdict (rigiddyn.scene_describe.describe).
        """
    @property
    def element_traits(self) -> tuple:
        """
        tuple of dict, one per compiled term in the order of SceneResult.work's columns (the scene's elements, then the frame's fictitious terms): reads_attitude, velocity_dependent, time_dependent, has_potential (its forces derive from a potential energy), has_torque, has_force and needs_attitude (it skips particles) (bool each)
        """
    @property
    def method(self) -> str:
        """
        the method's name (see methods())
        """
    @property
    def scene(self) -> Scene:
        """
        the Scene it was compiled from (a copy)
        """
    @property
    def warnings(self) -> tuple:
        """
        tuple of the compatibility warnings (str) compiling gave
        """
class SceneResult:
    """
    The records of simulate(scene, ...), one row per record (n records, nb bodies in the scene's order, ne
    elements in the scene's order); every array is read-only and shares the memory the C++ run filled.
    
    "W" is the scene frame: W itself, or the scene's SceneFrame F (every array is then relative to F).
    t (n,) [s]; p_W (n, nb, 3) centre of mass positions in W [m]; q_WB (n, nb, 4) attitudes, (x, y, z, w)
    unless simulate(..., scalar_first=True); v_W (n, nb, 3) [m/s] in W; w_B (n, nb, 3) [rad/s] in each body's
    B. A particle records q_WB = identity and w_B = 0; a planar body p_W = (x, y, 0), q_WB = Rz(theta),
    w_B = (0, 0, omega); a pinned body its centre of mass. pivot_reaction_W (n, nb, 3) the pivot's force on each
    body in W [N] (0 unpinned); angular_momentum_O_W (n, nb, 3) each body's about its pivot (about its centre of
    mass unpinned), in W [kg m^2/s]; mass (n, nb) [kg]. kinetic_energy (relative to W), potential_energy (the sum
    of the elements' potentials, and the centrifugal one of a frame turning at a constant rate: total_energy is
    then the Jacobi integral), total_energy (n,) [J]; linear_momentum_W (n, 3) [kg m/s]; angular_momentum_W (n, 3) about W's origin [kg m^2/s];
    work (n, ne) each element's work since t0 [J] and power (n, ne) its power at the record [W]; the columns are
    the scene's elements then the frame's fictitious terms that act (CentrifugalForce, CoriolisForce, ...);
    mass_flow_energy (n, nb) each body's mass-flow energy since t0 [J]: the integral of 1/2 (dm/dt) |v|^2 +
    1/2 w.(dI/dt) w, the kinetic energy its mass flow takes away or brings at its own velocity (0 for a constant
    mass). Work-energy balance, integrated by the run's method (to its error):
    kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1)
    (without a MassFlow the last sum is 0: the work alone); body_names (nb,) and
    elements (ne,) (each column's class name) label the axes; diverged, unconverged_steps, elapsed_seconds as in
    SimulationResult.
    """
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def to_dataframe(self, scalar_first: typing.Any = None) -> typing.Any:
        """
        A pandas.DataFrame of the records (needs pandas): one row per record, one column per scalar with its unit (wide format; rigiddyn.scene_result documents the columns): 't [s]', then per body '<name>:p_W_x [m]' .. '<name>:q_WB_x' .. '<name>:v_W_x [m/s]' .. '<name>:w_B_x [rad/s]' .. through '<name>:mass [kg]' and '<name>:mass_flow_energy [J]' (and a gyrostat's '<name>:wheel_speed_<k> [rad/s]'), then 'kinetic_energy [J]', 'potential_energy [J]', 'total_energy [J]', 'linear_momentum_W_x [kg m/s]' .., 'angular_momentum_W_x [kg m^2/s]' .., then per element i 'work[i] <Class> [J]' and 'power[i] <Class> [W]'; q_WB's columns in the result's order ('<name>:q_WB_w' first when its scalar_first is True). scalar_first: None (the default) for the order the result records; True or False declares the order of its q_WB rows instead.
        """
    @property
    def angular_momentum_O_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 3) each body's angular momentum about its pivot O (about its centre of mass when not pinned), in W [kg m^2/s]
        """
    @property
    def angular_momentum_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) about W's origin, in W: sum of p_W x m v_W + R_WB I w_B [kg m^2/s]
        """
    @property
    def body_names(self) -> tuple:
        """
        (nb,) tuple of the bodies' names
        """
    @property
    def diverged(self) -> bool:
        """
        True if the run stopped on a non-finite state
        """
    @property
    def elapsed_seconds(self) -> float:
        """
        wall time of the C++ stepping loop [s]
        """
    @property
    def elements(self) -> tuple:
        """
        (ne,) tuple of the elements' class names, then the frame's fictitious terms' ('CentrifugalForce', ...)
        """
    @property
    def kinetic_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) sum over the bodies [J]
        """
    @property
    def linear_momentum_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) sum of m v_W, in W [kg m/s]
        """
    @property
    def mass(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb) each body's mass [kg] (changing under a MassFlow)
        """
    @property
    def mass_flow_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb) each body's mass-flow energy since t0 [J]: the integral of 1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w (0 for a constant mass); kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1)
        """
    @property
    def motor_work(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nw) each wheel's motor work since t0 [J], the integral of its motor torque times its speed: kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1) + motor_work.sum(axis=1)
        """
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 3) centre of mass positions in W [m]
        """
    @property
    def pivot_reaction_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 3) the pivot's force on each body, in W [N] (0 for a body not pinned)
        """
    @property
    def potential_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) sum of the elements' potentials [J]
        """
    @property
    def power(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, ne) each element's power at the record [W]
        """
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 4) attitudes, (x, y, z, w) unless scalar_first
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z): the result of simulate(..., scalar_first=True)
        """
    @property
    def t(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) time [s]
        """
    @property
    def total_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) kinetic + potential [J]
        """
    @property
    def unconverged_steps(self) -> int:
        """
        number of steps whose implicit solve stopped at its iteration cap (0 for explicit methods)
        """
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 3) centre of mass velocities in W [m/s]
        """
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nb, 3) angular velocities, each in its body's B [rad/s]
        """
    @property
    def wheel_bodies(self) -> tuple:
        """
        (nw,) tuple of the body index of each wheel
        """
    @property
    def wheel_speed(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, nw) each gyrostat wheel's speed relative to its body [rad/s], the wheels of the gyrostats in the scene's order (nw = 0 without a gyrostat)
        """
    @property
    def work(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, ne) each element's work since t0 [J]
        """
class AppliedLoad:
    """
    A load: force (3,) [N] through the centre of mass and torque (3,) [N m] (a pure couple), both expressed in frame 'world' (W) or 'body' (B), active for t_start <= t < t_end [s]. Immutable. Each of force, torque, t_start, t_end: float(s) [unit] or a pint quantity (converted; ValueError naming it for another dimension).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], str, float, float]:
        ...
    def __init__(self, force: typing.Any = None, torque: typing.Any = None, frame: typing.Any = 'world', t_start: typing.Any = ..., t_end: typing.Any = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def force(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) [N] in frame
        """
    @property
    def frame(self) -> str:
        """
        'world' or 'body'
        """
    @property
    def t_end(self) -> float:
        """
        [s]
        """
    @property
    def t_start(self) -> float:
        """
        [s]
        """
    @property
    def torque(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) [N m] in frame
        """
class SimulationResult:
    """
    simulate's records (see simulate), one row per record; the arrays are read-only.
    """
    def __getstate__(self) -> tuple:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def to_dataframe(self, scalar_first: typing.Any = None) -> typing.Any:
        """
        A pandas.DataFrame of the records (needs pandas: pip install 'rigiddyn[dataframe]'): one row per record, one column per scalar with its unit, as the CSV of `python -m rigiddyn simulate`: 't [s]' (a column, not the index), 'p_W_x [m]' .. 'q_WB_x' .. 'q_WB_w', 'v_W_x [m/s]' .., 'w_B_x [rad/s]' .., 'kinetic_energy [J]', 'total_energy [J]', 'angular_momentum_norm [kg m^2/s]', 'quaternion_norm_error', 'work [J]'; q_WB's columns in the result's order ('q_WB_w' first when its scalar_first is True). scalar_first: None (the default) for the order the result records; True or False declares the order of its q_WB rows instead.
        """
    @property
    def angular_momentum_norm(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) |H_G| about the centre of mass [kg m^2/s]
        """
    @property
    def diverged(self) -> bool:
        """
        True if the run stopped on a non-finite state
        """
    @property
    def elapsed_seconds(self) -> float:
        """
        wall time of the C++ stepping loop [s]
        """
    @property
    def kinetic_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) [J]
        """
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) centre of mass position in W [m]
        """
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 4) attitude, (x, y, z, w) unless scalar_first
        """
    @property
    def quaternion_norm_error(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) |q| - 1
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z): the result of simulate(..., scalar_first=True)
        """
    @property
    def t(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) time [s]
        """
    @property
    def total_energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) kinetic + gravity potential [J]
        """
    @property
    def unconverged_steps(self) -> int:
        """
        number of steps whose implicit solve stopped at its iteration cap (implicit_midpoint; 0 for explicit methods); simulate warns RuntimeWarning when > 0
        """
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) centre of mass velocity in W [m/s]
        """
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) angular velocity in B [rad/s]
        """
    @property
    def work(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n,) work of loads and gravity since t0 [J]
        """
class BatchResult:
    """
    The records of simulate_batch over bodies: N samples of n records each (the arrays of SimulationResult with a
    leading sample axis), read-only, sample-major. t (N, n) [s]; p_W (N, n, 3) centre of mass position in W [m];
    q_WB (N, n, 4) attitude, (x, y, z, w) unless scalar_first; v_W (N, n, 3) [m/s] in W; w_B (N, n, 3) [rad/s] in
    B; kinetic_energy, total_energy (N, n) [J]; angular_momentum_norm (N, n) |H_G| [kg m^2/s];
    quaternion_norm_error (N, n) |q| - 1; work (N, n) [J]. diverged (N,) bool; filled (N,) rows filled per sample
    (n unless it diverged: its rows after filled[i] are NaN); unconverged_steps (N,); elapsed_seconds: wall time
    of the whole batch [s]; scalar_first: True if q_WB's rows are (w, x, y, z). len(result) is N; result[i] is sample
    i as a SimulationResult (its filled rows, copies, the same scalar_first); pickles.
    """
    def __getitem__(self, i: typing.Any) -> typing.Any:
        """
        sample i's records (negative i counts from the end)
        """
    def __getstate__(self) -> tuple:
        ...
    def __len__(self) -> int:
        """
        N, the number of samples
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def angular_momentum_norm(self) -> numpy.ndarray:
        """
        (N, n) |H_G| about the centre of mass [kg m^2/s]
        """
    @property
    def diverged(self) -> numpy.ndarray:
        """
        (N,) bool: the sample's state became non-finite; its run stopped
        """
    @property
    def elapsed_seconds(self) -> float:
        """
        wall time of the whole batch [s]
        """
    @property
    def filled(self) -> numpy.ndarray:
        """
        (N,) int64: rows filled per sample (n unless it diverged)
        """
    @property
    def kinetic_energy(self) -> numpy.ndarray:
        """
        (N, n) kinetic energy [J]
        """
    @property
    def p_W(self) -> numpy.ndarray:
        """
        (N, n, 3) centre of mass position in W [m]
        """
    @property
    def q_WB(self) -> numpy.ndarray:
        """
        (N, n, 4) attitude, (x, y, z, w) unless scalar_first
        """
    @property
    def quaternion_norm_error(self) -> numpy.ndarray:
        """
        (N, n) |q| - 1
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z): the result of simulate_batch(..., scalar_first=True)
        """
    @property
    def t(self) -> numpy.ndarray:
        """
        (N, n) time [s]
        """
    @property
    def total_energy(self) -> numpy.ndarray:
        """
        (N, n) kinetic + gravity potential [J]
        """
    @property
    def unconverged_steps(self) -> numpy.ndarray:
        """
        (N,) int64: steps whose implicit solve stopped at its iteration cap (0 for explicit methods)
        """
    @property
    def v_W(self) -> numpy.ndarray:
        """
        (N, n, 3) centre of mass velocity in W [m/s]
        """
    @property
    def w_B(self) -> numpy.ndarray:
        """
        (N, n, 3) angular velocity in B [rad/s]
        """
    @property
    def work(self) -> numpy.ndarray:
        """
        (N, n) work of loads and gravity since t0 [J]
        """
class BatchSceneResult:
    """
    The records of simulate_batch over scenes: the arrays of SceneResult with a leading sample axis (N samples, n
    records, nb bodies, ne work columns), read-only: t (N, n) [s]; p_W, v_W, w_B, pivot_reaction_W,
    angular_momentum_O_W (N, n, nb, 3); q_WB (N, n, nb, 4); kinetic_energy, potential_energy, total_energy (N, n)
    [J]; linear_momentum_W, angular_momentum_W (N, n, 3); mass, mass_flow_energy (N, n, nb) [kg], [J]; work, power
    (N, n, ne) [J], [W];
    body_names and elements (the first scene's labels of the axes); diverged (N,) bool; filled (N,) rows filled per
    sample (the rest NaN); unconverged_steps (N,); elapsed_seconds: wall time of the batch [s]; scalar_first: True if
    q_WB's rows are (w, x, y, z). Frames and units as SceneResult. len(result) is N; result[i] is sample i as a
    SceneResult (its filled rows, copies, the same scalar_first); pickles.
    """
    def __getitem__(self, i: typing.Any) -> typing.Any:
        """
        sample i's records (negative i counts from the end)
        """
    def __getstate__(self) -> tuple:
        ...
    def __len__(self) -> int:
        """
        N, the number of samples
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def angular_momentum_O_W(self) -> numpy.ndarray:
        """
        (N, n, nb, 3) each body's angular momentum about its pivot (its centre of mass unpinned), in W [kg m^2/s]
        """
    @property
    def angular_momentum_W(self) -> numpy.ndarray:
        """
        (N, n, 3) about W's origin, in W [kg m^2/s]
        """
    @property
    def body_names(self) -> tuple:
        """
        (nb,) tuple of the bodies' names
        """
    @property
    def diverged(self) -> numpy.ndarray:
        """
        (N,) bool: the sample's state became non-finite; its run stopped
        """
    @property
    def elapsed_seconds(self) -> float:
        """
        wall time of the whole batch [s]
        """
    @property
    def elements(self) -> tuple:
        """
        (ne,) tuple of the work columns' class names
        """
    @property
    def filled(self) -> numpy.ndarray:
        """
        (N,) int64: rows filled per sample (n unless it diverged)
        """
    @property
    def kinetic_energy(self) -> numpy.ndarray:
        """
        (N, n) sum over the bodies [J]
        """
    @property
    def linear_momentum_W(self) -> numpy.ndarray:
        """
        (N, n, 3) sum of m v_W, in W [kg m/s]
        """
    @property
    def mass(self) -> numpy.ndarray:
        """
        (N, n, nb) each body's mass [kg]
        """
    @property
    def mass_flow_energy(self) -> numpy.ndarray:
        """
        (N, n, nb) each body's mass-flow energy since t0 [J] (0 for a constant mass)
        """
    @property
    def motor_work(self) -> numpy.ndarray:
        """
        (N, n, nw) each wheel's motor work since t0 [J]
        """
    @property
    def p_W(self) -> numpy.ndarray:
        """
        (N, n, nb, 3) centre of mass positions in W [m]
        """
    @property
    def pivot_reaction_W(self) -> numpy.ndarray:
        """
        (N, n, nb, 3) the pivot's force on each body, in W [N]
        """
    @property
    def potential_energy(self) -> numpy.ndarray:
        """
        (N, n) sum of the elements' potentials [J]
        """
    @property
    def power(self) -> numpy.ndarray:
        """
        (N, n, ne) each element's power at the record [W]
        """
    @property
    def q_WB(self) -> numpy.ndarray:
        """
        (N, n, nb, 4) attitudes, (x, y, z, w) unless scalar_first
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z): the result of simulate_batch(..., scalar_first=True)
        """
    @property
    def t(self) -> numpy.ndarray:
        """
        (N, n) time [s]
        """
    @property
    def total_energy(self) -> numpy.ndarray:
        """
        (N, n) kinetic + potential [J]
        """
    @property
    def unconverged_steps(self) -> numpy.ndarray:
        """
        (N,) int64: steps whose implicit solve stopped at its iteration cap (0 for explicit methods)
        """
    @property
    def v_W(self) -> numpy.ndarray:
        """
        (N, n, nb, 3) centre of mass velocities in W [m/s]
        """
    @property
    def w_B(self) -> numpy.ndarray:
        """
        (N, n, nb, 3) angular velocities, each in its body's B [rad/s]
        """
    @property
    def wheel_bodies(self) -> tuple:
        """
        (nw,) tuple of the body index of each wheel
        """
    @property
    def wheel_speed(self) -> numpy.ndarray:
        """
        (N, n, nw) each gyrostat wheel's speed relative to its body [rad/s] (nw = 0 without a gyrostat)
        """
    @property
    def work(self) -> numpy.ndarray:
        """
        (N, n, ne) each element's work since t0 [J]
        """
class TorqueFreeSolution:
    """
    Exact motion of a torque-free rigid body (Euler-Poinsot): angular velocity in Jacobi's elliptic
    functions, attitude by Legendre's third integral (Landau & Lifshitz, Mechanics §37;
    Celledoni, Fassò, Säfström, Zanna 2008; docs/references.md), at any time t [s].
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from exactly equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, inertia: typing.Any, q_WB: typing.Any, w_B: typing.Any, scalar_first: typing.Any = False, check: typing.Any = InertiaCheck.physical) -> None:
        """
        inertia: (3, 3) rotational inertia about the centre of mass, in B [kg m^2], symmetric positive definite
        and, under check=InertiaCheck.physical (default), with principal moments satisfying the triangle
        inequality I1 + I2 >= I3 (ValueError naming the moments otherwise; check=
        InertiaCheck.allow_unrealizable opts in to test problems such as diag(2, 1, 2/3));
        q_WB: (4,) initial attitude, (x, y, z, w) or (w, x, y, z) if scalar_first; w_B: (3,) initial angular
        velocity of B in W, expressed in B [rad/s]. Any finite magnitudes (the motion is computed in scaled
        units); ValueError naming w_B when a rate of the motion exceeds the double range, and naming inertia
        when its principal moments span so many orders (~1e150 and more) that the parameters of the elliptic
        functions, up to ~(I_max/I_min)^2 in scaled units, exceed it.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def state_at(self, t: typing.Any) -> tuple:
        """
        State at time t [s] (scalar, or (n,) array; negative allowed): (q_WB, w_B) of shapes (4,), (3,) or
        (n, 4), (n, 3); q in the order chosen at construction. ValueError naming t when a phase (rate times t)
        exceeds the double range.
        """
    @property
    def R_BP(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3, 3) rotation from the sorted principal frame P to B (columns: principal axes in B).
        """
    @property
    def angular_momentum_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) constant angular momentum about the centre of mass, expressed in W, L_W [kg m^2/s]; inf with a
        RuntimeWarning beyond the double range.
        """
    @property
    def case(self) -> str:
        """
        'sphere', 'symmetric', 'A' (about axis 3), 'B' (about axis 1) or 'separatrix'.
        """
    @property
    def kinetic_energy(self) -> KineticEnergy:
        """
        Constant KineticEnergy of the rotation [J]: rotational 1/2 w_B . I_B w_B, translational 0 (the
        centre of mass is not part of this solution); inf with a RuntimeWarning beyond the double range.
        """
    @property
    def parameter_m(self) -> float:
        """
        Parameter m of the elliptic functions.
        """
    @property
    def parameter_mc(self) -> float:
        """
        Complement 1 - m, computed without cancellation.
        """
    @property
    def period(self) -> float:
        """
        Period of w_B(t) [s]; inf if w_B is constant or on the separatrix. A flip takes half.
        """
    @property
    def principal_moments(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) principal moments I1 <= I2 <= I3 [kg m^2] about the centre of mass.
        """
class CompoundPendulumSolution:
    """
    Exact motion of the compound pendulum (a PivotedPlanarBody under uniform gravity) at any energy, in Jacobi's
    elliptic functions (Landau & Lifshitz, Mechanics §11; DLMF §22.19): libration sin(v/2) = k sn(w0 t + u0|k^2),
    rotation v/2 = am(k w0 t + u0|1/k^2), the separatrix and the equilibria, with v = theta - theta_stable the
    angle from the stable equilibrium (where R_WB p_OC_B points along g) and w0^2 = m g d / I_O. Accurate up
    to v0 -> pi: the complement 1 - k^2 is formed without cancellation.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: typing.Any, g_W: typing.Any, state: typing.Any) -> None:
        """
        body: a PivotedPlanarBody; g_W: (2,) or (3,) uniform gravity in W [m/s^2] (only its xy part acts);
        state: the PivotedPlanarBodyState (theta [rad], omega [rad/s]) at t = 0. ValueError naming g_W or
        state.theta / state.omega for non-finite values.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: typing.Any) -> tuple:
        """
        State at time t [s] (a float, or an (n,) array; negative allowed): (theta [rad], omega [rad/s]), floats
        or (n,) arrays. theta is continuous from the initial theta (not wrapped; a rotating pendulum's theta grows).
        """
    @property
    def amplitude(self) -> float:
        """
        Amplitude 2 asin k of a libration about the stable equilibrium [rad] (pi otherwise).
        """
    @property
    def case(self) -> str:
        """
        'libration', 'rotation', 'separatrix', 'rest' (an equilibrium) or 'uniform' (no torque).
        """
    @property
    def energy(self) -> float:
        """
        Energy about O [J]: 1/2 I_O omega^2 - m g_W . (R_WB p_OC_B) (constant).
        """
    @property
    def k_squared(self) -> float:
        """
        k^2 = sin^2(v0/2) + (omega0_state/(2 w0))^2 (> 1 for a rotation).
        """
    @property
    def k_squared_complement(self) -> float:
        """
        1 - k^2, computed without cancellation (cos^2(v0/2) at rest; negative for a rotation).
        """
    @property
    def omega0(self) -> float:
        """
        w0 = sqrt(m g d / I_O) [rad/s], the small-oscillation angular frequency (0 without torque).
        """
    @property
    def period(self) -> float:
        """
        Period [s]: 4 K(k^2)/w0 for a libration, the time of one turn for a rotation; inf at an
        equilibrium, on the separatrix, and without torque and rate.
        """
    @property
    def theta_stable(self) -> float:
        """
        theta of the stable equilibrium [rad] in (-pi, pi].
        """
class LagrangeTopSolution:
    """
    Exact motion of the heavy symmetric (Lagrange) top about its fixed point O (Goldstein, Classical Mechanics
    §5.7; Landau & Lifshitz, Mechanics §35): u = cos(theta) = u1 + (u2 - u1) sn^2(lambda t + tau0|m) between the
    roots u1 <= u2 of the cubic u'^2 = (1 - u^2)(alpha - beta u) - (b - a u)^2, the precession phi and spin psi by
    Legendre's integral of the third kind. Euler angles Z-X-Z of the frame S (e1, e2, e3 = p_OC_B/|p_OC_B|, fixed in
    B) in the inertial frame N: z_N = -g_W/|g_W| (up), x_N the line of nodes at t = 0 (phi(0) = 0). Cases:
    'nutation' and 'sleeping' (e3 vertical, w_B along it); a motion whose axis passes through a vertical is refused
    (ValueError naming state).
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: typing.Any, g_W: typing.Any, state: typing.Any, scalar_first: typing.Any = False) -> None:
        """
        body: a PivotedBody whose inertia about O (inertia_O) is symmetric about the axis O->C to 1e-12 relative,
        with C off O (ValueError naming body otherwise); g_W: (3,) uniform gravity in W [m/s^2], non-zero;
        state: the PivotedBodyState (q_WB, w_B [rad/s] in B) at t = 0; scalar_first: the order of the quaternions
        at() returns ((x, y, z, w) by default).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def angles_at(self, t: typing.Any) -> tuple:
        """
        Euler angles Z-X-Z (phi, theta, psi) [rad] of S in N at time t [s] (floats or (n,) arrays): precession
        (phi(0) = 0), nutation (the tilt of e3 from the upward vertical), spin; phi and psi continuous.
        """
    def at(self, t: typing.Any) -> tuple:
        """
        State at time t [s] (a float, or an (n,) array; negative allowed): (q_WB, w_B) of shapes (4,), (3,) or
        (n, 4), (n, 3); q_WB B to W in the order chosen at construction, w_B the angular velocity of B in W,
        expressed in B [rad/s].
        """
    @property
    def H_3(self) -> float:
        """
        Angular momentum about O along e3, I3 omega3 [kg m^2/s] (constant).
        """
    @property
    def H_z(self) -> float:
        """
        Angular momentum about O along the upward vertical -g_W/|g_W| [kg m^2/s] (constant).
        """
    @property
    def I1(self) -> float:
        """
        I1 = I2, the transverse moment about O [kg m^2].
        """
    @property
    def I3(self) -> float:
        """
        I3, the axial moment [kg m^2].
        """
    @property
    def a(self) -> float:
        """
        a = I3 omega3 / I1 [rad/s].
        """
    @property
    def alpha(self) -> float:
        """
        alpha = 2 E'/I1 [1/s^2], E' the energy about O less 1/2 I3 omega3^2.
        """
    @property
    def b(self) -> float:
        """
        b = H_z / I1 [rad/s].
        """
    @property
    def beta(self) -> float:
        """
        beta = 2 m |g| l / I1 [1/s^2].
        """
    @property
    def case(self) -> str:
        """
        'nutation' or 'sleeping'.
        """
    @property
    def e3_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) the symmetry axis p_OC_B/|p_OC_B| in B.
        """
    @property
    def elliptic_rate(self) -> float:
        """
        lambda = sqrt(beta (u3 - u1))/2 [1/s], the rate of the argument of sn.
        """
    @property
    def energy(self) -> float:
        """
        Energy about O [J]: 1/2 w_B . I_O w_B - m g_W . (R_WB p_OC_B) (constant).
        """
    @property
    def mean_precession_rate(self) -> float:
        """
        phi's change over one nutation period divided by it [rad/s] (0 when sleeping).
        """
    @property
    def nutation_period(self) -> float:
        """
        Period of theta(t), 2 K(m)/lambda [s] (inf when sleeping).
        """
    @property
    def parameter_m(self) -> float:
        """
        m = (u2 - u1)/(u3 - u1), the parameter of sn.
        """
    @property
    def parameter_mc(self) -> float:
        """
        1 - m, computed without cancellation.
        """
    @property
    def q_WN(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4,) the frame N of the Euler angles, N to W (in the order chosen at construction).
        """
    @property
    def roots(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) roots u1 <= u2 <= u3 of the cubic in u = cos(theta).
        """
    @property
    def theta_max(self) -> float:
        """
        Largest tilt of e3 from the upward vertical, acos(u1) [rad].
        """
    @property
    def theta_min(self) -> float:
        """
        Smallest tilt of e3 from the upward vertical, acos(u2) [rad].
        """
class RotatingFrameFreeParticle:
    """
    Exact motion of a free particle seen from a frame F turning at a constant rate about a fixed axis through its
    origin: the straight line of the inertial frame turned into F, p_F(t) = R_FW(t) (p0 + v_W t), v_F = R_FW(t)
    (v_W - w x p_W) ("Rigid body kinematics and dynamics" notes §4.11.1); it solves a_F = -w x (w x p_F) -
    2 w x v_F (centrifugal and Coriolis only) and keeps the Jacobi integral 1/2|v_F|^2 - 1/2|w x p_F|^2.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, frame: typing.Any, p0_F: typing.Any, v0_F: typing.Any) -> None:
        """
        frame: a SceneFrame turning at a constant rate (SceneFrame.rotating or SceneFrame.earth; ValueError naming
        frame for a general moving frame); p0_F (3,) [m], v0_F (3,) [m/s]: position and velocity relative to F,
        in F, at t = 0.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: typing.Any) -> tuple:
        """
        State at time t [s] (a float, or an (n,) array): (p_F [m], v_F [m/s]) relative to F, in F, of shapes (3,)
        or (n, 3).
        """
    @property
    def jacobi_integral(self) -> float:
        """
        1/2 |v_F|^2 - 1/2 |w x p_F|^2 [J/kg], constant.
        """
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) the constant inertial velocity [m/s], in F's axes at t = 0.
        """
    @property
    def w_F(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) F's angular velocity [rad/s], in F.
        """
class ConstantThrustSolution:
    """
    Exact motion of a particle whose mass changes at a constant rate, m(t) = m0 + rate t, with the thrust
    rate u_rel_W along a fixed direction and uniform gravity ("Rigid body kinematics and dynamics" notes, eq. (4.36):
    m v' = m g + rate u_rel): v(t) = v0 + g t + u_rel ln(m(t)/m0), p(t) = p0 + v0 t + g t^2/2 + u_rel t h(x)/x with
    x = rate t/m0, h(x) = (1 + x) ln(1 + x) - x (series near x = 0). Everything in the inertial frame W.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, m0: typing.Any, rate: typing.Any, u_rel_W: typing.Any, g_W: typing.Any = None, p0_W: typing.Any = None, v0_W: typing.Any = None) -> None:
        """
        m0: mass at t = 0 [kg] > 0; rate: dm/dt [kg/s] (negative: losing mass); u_rel_W (3,): velocity of the
        ejected mass relative to the particle, in W [m/s]; g_W (3,) [m/s^2], p0_W (3,) [m], v0_W (3,) [m/s] (None:
        zero). ValueError naming the argument for m0 <= 0 or a non-finite value.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: typing.Any) -> tuple:
        """
        State at time t [s] (a float, or an (n,) array): (p_W [m], v_W [m/s], mass [kg]) of shapes (3,), (3,), float
        or (n, 3), (n, 3), (n,). ValueError naming t where the mass m0 + rate t is not positive (burn-out).
        """
    def delta_v(self, m1: typing.Any) -> float:
        """
        Tsiolkovsky: the speed the thrust gives while the mass goes from m0 to m1 [kg], |u_rel| ln(m0/m1) [m/s].
        """
    def mass_at(self, t: typing.Any) -> float:
        """
        m0 + rate t [kg] (not checked positive).
        """
    @property
    def burnout_time(self) -> float:
        """
        -m0/rate [s], when the mass reaches zero; inf when rate >= 0.
        """
    @property
    def g_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) uniform gravity in W [m/s^2]
        """
    @property
    def m0(self) -> float:
        """
        mass at t = 0 [kg]
        """
    @property
    def rate(self) -> float:
        """
        dm/dt [kg/s]
        """
    @property
    def u_rel_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) velocity of the ejected mass relative to the particle, in W [m/s]
        """
def _steps_of(steps: typing.Any, duration: typing.Any, dt: typing.Any) -> int:
    """
    The step count of a run of simulate(..., steps=, duration=) at one dt [s] (the package's Python front ends check it before their own work); ValueError as simulate's.
    """
def align_vectors(a: typing.Any, b: typing.Any, weights: typing.Any = None, return_sensitivity: typing.Any = False, scalar_first: typing.Any = False) -> tuple:
    """
    The rotation R that best maps the vectors b onto the vectors a (Wahba's problem), as SciPy's
    Rotation.align_vectors(a, b, weights): R minimises 1/2 sum_i w_i |a_i - R b_i|^2.
    
    a, b: (3,) or (N, 3), the same vectors observed in two frames: with a in W and b in B the result
    is q_WB. Lengths act as weights (normalise for equal weighting). weights: None (all 1) or (N,)
    of values >= 0; one may be inf: that primary pair is aligned exactly and the others only by the
    turn about it. One pair (N = 1): the smallest rotation taking the direction of b to that of a.
    General case by the SVD of B = sum w_i a_i b_i^T (Markley 1988), UserWarning when the optimum
    is not unique (all pairs parallel).
    Returns (q, rssd) or, with return_sensitivity=True, (q, rssd, sensitivity): q (4,) canonical
    (w >= 0), (x, y, z, w) or (w, x, y, z) if scalar_first; rssd = sqrt(sum_i w_i |a_i - R b_i|^2)
    [units of a] over the finite weights; sensitivity (3, 3), SciPy's covariance of the rotation-vector
    error [rad^2 per unit of measurement variance] (not for one pair or an infinite weight).
    """
def angular_distance(q_a: typing.Any, q_b: typing.Any, scalar_first: typing.Any = False, degrees: typing.Any = False) -> typing.Any:
    """
    Angle [rad, or degrees if degrees=True] in [0, pi] of the rotation taking q_a to q_b: the
    magnitude of q_a^-1 * q_b (SciPy's (r_a.inv() * r_b).magnitude()), a metric on rotations,
    independent of the quaternions' signs. 2 atan2(|d_xyz|, |d_w|): accurate near 0 and near pi.
    
    q_a, q_b: (4,) or (n, 4) unit quaternions, (x, y, z, w) or (w, x, y, z) if scalar_first; a single
    one is compared with every item of the other. Returns a float or (n,).
    """
def angular_momentum(body: typing.Any, state: typing.Any, point: typing.Any = None) -> typing.Any:
    """
    Angular momentum about the point P fixed in W at `point` (p_WP [m] in W; None = the world origin O, as the "Rigid body kinematics and dynamics" notes define it, eq. (4.42) and (4.65)), expressed in W. About the centre of mass: point=state.p_W. body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    RigidBody: (3,) [kg m^2/s], H_P = R_WB I w_B + (p_W - p_WP) x m v_W. PlanarBody: H_z [kg m^2/s] about the z axis through P, I_zz omega + (p_W - p_WP) x m v_W, point (2,). Particle: (3,), (p_W - p_WP) x m v_W.
    """
def angular_velocity_from_quat_rate(q: typing.Any, dq_dt: typing.Any, frame: typing.Any = 'body', scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Angular velocity [rad/s] of the attitude q = q_WB changing at dq_dt [1/s], the inverse of quat_rate:
    frame='body': w_B = 2 vec(q* ⊗ dq/dt); frame='world': w_W = 2 vec(dq/dt ⊗ q*).
    The part of dq_dt along q (which would change |q|, not the rotation) is ignored.
    q: (4,) or (n, 4) unit quaternions; dq_dt: (4,) or (n, 4), any finite values, in q's order.
    Returns (3,) or (n, 3).
    """
def apply_impulse(body: typing.Any, state: typing.Any, impulse: typing.Any, point: typing.Any = None, frame: typing.Any = 'world', angular_impulse: typing.Any = None) -> typing.Any:
    """
    The state just after an impulse [N s] at `point` (p_GP [m] from the centre of mass; None = the centre of mass) and an angular impulse [N m s] (None: none), all in `frame` ('world' or 'body'): m dv = impulse, I dw = p_GP x impulse + angular_impulse (impulse-momentum, Craig's "Rigid Body Dynamics" slides). body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    RigidBody: impulse, point, angular_impulse (3,). PlanarBody: impulse, point (2,), angular_impulse about z. Particle: impulse (3,) in W only.
    """
def axis_angle_to_quat(axis: typing.Any, angle: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of the rotation by angle [rad] about axis (right-hand rule).
    
    axis: (3,) or (n, 3), any non-zero length (normalised); angle: float or (n,), in degrees if degrees=True.
    Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def box_shell(size: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Closed thin-walled box (six faces), edges (3,) [m]. Density [kg/m^2]. Give exactly one of mass= [kg] or density=.
    """
def compose_kinematics(K_AP: typing.Any, K_PF: typing.Any) -> FrameKinematics:
    """
    F relative to A from P relative to A and F relative to P (addition theorem for w; alpha with its
    w_AP x w_PF term; origin by the point formulas of the "Rigid body kinematics and dynamics" notes,
    (4.38), (4.39)). Result expressed in A.
    """
def composite(parts: typing.Any) -> SpatialInertia:
    """
    Composite body: parts is a list of SpatialInertia (one frame) or of (X_AB, SpatialInertia) pairs,
    each part expressed in its B and placed in A by the Transform X_AB. Exact.
    """
def davenport_to_quat(axes: typing.Any, order: typing.Any, angles: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of Davenport angles (rotations about three arbitrary axes).
    
    axes: (3, 3), the rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2
    orthogonal to n1 and to n3 (|cos| <= 1e-7, as SciPy); order: 'e'/'extrinsic' (fixed axes,
    R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i'/'intrinsic' (moving axes, R = R_n1(a1) R_n2(a2) R_n3(a3)),
    as SciPy's Rotation.from_davenport / as_davenport. Coordinate axes give Euler angles.
    angles: (3,) or (n, 3) [rad] (degrees if degrees=True), in the order of the axes.
    Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def default_thread_count() -> int:
    """
    The number of hardware threads (at least 1): simulate_batch's threads=None.
    """
def ellipk(m: typing.Any, mc: typing.Any = None) -> float:
    """
    Complete elliptic integral K(m) = R_F(0, mc, 1) for the parameter m in [0, 1] (as scipy.special.ellipk).
    mc: the complement 1 - m (default 1 - m); pass it near m = 1, where 1 - m loses digits. inf at mc = 0.
    """
def ellippi(n: typing.Any, m: typing.Any, mc: typing.Any = None) -> float:
    """
    Complete elliptic integral of the third kind Pi(n|m) = int_0^{pi/2} dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)),
    n < 1, m in [0, 1), mc = 1 - m (default 1 - m). A few ulps for n <= 0.9; relative error ~eps/(1 - n) nearer 1.
    """
def ellippi_am(u: typing.Any, n: typing.Any, m: typing.Any, mc: typing.Any = None) -> typing.Any:
    """
    Incomplete Pi(am u, n|m) = int_0^u dv / (1 - n sn^2(v|m)) (mpmath.ellippi(n, am(u), m)), for u a scalar
    or a 1-d array (then an array of the same length), n < 1, mc = 1 - m (default 1 - m); +-inf with a
    RuntimeWarning where it exceeds the double range (|u| near it).
    """
def elliprf(x: typing.Any, y: typing.Any, z: typing.Any) -> float:
    """
    Carlson's R_F(x, y, z) (DLMF 19.16.1) for finite x, y, z >= 0, at most one zero, of any magnitude;
    inf with a RuntimeWarning where the result exceeds the double range.
    """
def elliprj(x: typing.Any, y: typing.Any, z: typing.Any, p: typing.Any) -> float:
    """
    Carlson's R_J(x, y, z, p) (DLMF 19.16.2) for finite x, y, z >= 0, at most one zero, and p > 0, of any
    magnitude; inf with a RuntimeWarning where the result exceeds the double range.
    """
def euler_to_matrix(seq: typing.Any, angles: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotation matrix of Euler angles.
    
    seq: 3 letters as SciPy, lowercase 'xyz' = extrinsic (fixed axes), uppercase 'XYZ' = intrinsic
    (moving axes); the 12 sequences xyz xzy yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    angles: (3,) or (n, 3) [rad] (degrees if degrees=True). Returns R: (3, 3) or (n, 3, 3).
    """
def euler_to_quat(seq: typing.Any, angles: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of Euler angles.
    
    seq: 3 letters as SciPy, lowercase 'xyz' = extrinsic (fixed axes), uppercase 'XYZ' = intrinsic
    (moving axes); the 12 sequences xyz xzy yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    angles: (3,) or (n, 3) [rad] (degrees if degrees=True), in the order of seq.
    Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def force_cross_matrix(motion: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    crf(V) (6,6) = [[hat(w), hat(v)], [0, hat(w)]] = -crm(V)^T of the motion V = [w; v], so crf(V) F = V x* F.
    """
def forward_dynamics(body: typing.Any, state: typing.Any, force: typing.Any = None, torque: typing.Any = None, point: typing.Any = None, frame: typing.Any = 'world', gravity: typing.Any = None) -> typing.Any:
    """
    Accelerations of `body` in `state` under a force applied at `point` and a torque `torque`.
    body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    gravity: None (the default: no gravity, docs/conventions.md), True = (0, 0, -9.81) m/s^2, or a vector [m/s^2] in W.
    RigidBody: force (3,) [N] at point (p_GP (3,) [m], from the centre of mass; None = the centre of mass), torque (3,) [N m], all expressed in `frame` ('world' or 'body'), gravity (3,); returns a BodyAcceleration (a_W (3,) [m/s^2] of the centre of mass in W, alpha_B (3,) [rad/s^2] in B; unpacks as a_W, alpha_B). Newton: m a = f + m g; Euler: I alpha + w x I w = tau_G.
    PlanarBody: in-plane force (2,) [N] at point (2,) [m], torque [N m] about z, gravity (2,) [m/s^2]; returns a PlanarAcceleration (a_W (2,), alpha [rad/s^2]); I_zz alpha = tau_G.
    Particle: force (3,) [N] in W (torque and point None, frame 'world'); returns a_W (3,) = force/m + g.
    PivotedBody (state a PivotedBodyState): force (3,) [N] at point (p_CP (3,) [m] from the centre of mass; None = the centre of mass) and torque (3,) [N m], in `frame`, gravity (3,) [m/s^2] in W; returns a PivotedAcceleration (alpha_B (3,) [rad/s^2] in B, reaction_W (3,) [N] the pivot's force in W; unpacks as alpha_B, reaction_W): Euler about O, inertia_O alpha_B + w_B x inertia_O w_B = tau_O, and Newton for C, reaction = m a_C - f.
    PivotedPlanarBody (state a PivotedPlanarBodyState): in-plane force (2,) [N] at point (2,) [m], torque [N m] about z, gravity (2,) or (3,) in W's plane; returns a PivotedPlanarAcceleration (alpha [rad/s^2], reaction_W).
    """
def from_point_masses(masses: typing.Any, positions: typing.Any) -> SpatialInertia:
    """
    Point masses (n,) [kg] >= 0 at positions (n, 3) [m] (Rigid-body notes (4.53)-(4.54)).
    """
def hat(v: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    Skew-symmetric cross-product matrix S = hat(v), S x = v × x. v: (3,) or (n, 3); returns (3, 3) or (n, 3, 3).
    """
def hollow_cylinder(outer_radius: typing.Any, inner_radius: typing.Any, height: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thick tube, axis z: I_zz = m (R^2 + r^2)/2, I_xx = m (3 (R^2 + r^2) + h^2)/12. Density [kg/m^3]. Give
    exactly one of mass= [kg] or density=.
    """
def hollow_sphere(outer_radius: typing.Any, inner_radius: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thick spherical shell [m]: I = 2/5 m (R^5 - r^5)/(R^3 - r^3) 1. Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def inertia_report(mass: typing.Any, inertia_com: typing.Any, scale: typing.Any = 0.0) -> InertiaReport:
    """
    Validity report of mass [kg] and inertia_com (3,3) [kg m^2]: principal moments, triangle margins,
    condition number. Tolerance = inertia_relative_tolerance * max(scale, trace) [kg m^2], where scale is
    the size of the numbers the inertia was computed from (0: trace only).
    """
def integrate_density_over_box(rho: typing.Any, lower: typing.Any, upper: typing.Any, order: typing.Any = 6, subdivisions: typing.Any = 2) -> DensityIntegral:
    """
    Mass properties of density rho over the box [lower, upper] (3,) [m] by Gauss-Legendre quadrature
    (Rigid-body notes (4.55), (4.56), (4.70)) at `order` and 2*order points per cell axis, subdivisions^3 cells.
    rho is called with points (n, 3) [m] and returns (n,) densities [kg/m^3] >= 0. Returns a
    DensityIntegral (high-order result, differences to the low order as error estimate).
    """
def integrate_density_over_mesh(rho: typing.Any, vertices: typing.Any, faces: typing.Any, order: typing.Any = 4) -> DensityIntegral:
    """
    Mass properties of density rho over the solid bounded by a closed mesh (signed tetrahedra, collapsed
    Gauss-Legendre, order^3 and (2 order)^3 points per face). rho: points (n, 3) -> (n,) [kg/m^3], must
    be defined on the mesh's convex hull. Returns a DensityIntegral.
    """
def inverse_dynamics(body: typing.Any, state: typing.Any, a_W: typing.Any = None, alpha_B: typing.Any = None, gravity: typing.Any = None) -> typing.Any:
    """
    The applied loads the motion requires, reduced to the centre of mass (undoes forward_dynamics).
    body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    gravity: None (the default: no gravity), True = (0, 0, -9.81) m/s^2, or a vector [m/s^2] in W.
    RigidBody: a_W (3,) [m/s^2] in W, alpha_B (3,) [rad/s^2] in B; returns a ComWrench: f_W (3,) [N] in W and tau_B (3,) [N m] about the centre of mass in B (unpacks as f_W, tau_B), f_W = m (a_W - g), tau_B = I alpha_B + w_B x I w_B.
    PlanarBody: a_W (2,), alpha_B [rad/s^2] about z, gravity (2,); returns a PlanarWrench: f_W (2,) [N] in W and tau [N m] about z (unpacks as f_W, tau).
    Particle: a_W (3,) (alpha_B None); returns f_W (3,) [N] in W = m (a_W - g).
    PivotedBody: alpha_B (3,) [rad/s^2] in B (a_W None: the pivot fixes it); returns a PivotedTorque: tau_O_B (3,) [N m] the torque about O in B the motion needs besides gravity, and reaction_W (3,) [N] in W (unpacks as tau_O_B, reaction_W). PivotedPlanarBody: alpha_B [rad/s^2] about z; returns a PivotedPlanarTorque (tau_O [N m], reaction_W).
    """
def jacobi_ellipj(u: typing.Any, m: typing.Any, mc: typing.Any = None) -> typing.Any:
    """
    Jacobi elliptic functions (sn, cn, dn)(u|m) for u a scalar (floats) or a 1-d array (three arrays of
    shape (n,)), m in [0, 1]. mc: the complement 1 - m (default 1 - m); pass it near m = 1 for full
    accuracy (unlike scipy.special.ellipj, accurate near m = 1 at any u).
    """
def kinetic_energy(body: typing.Any, state: typing.Any) -> typing.Any:
    """
    Kinetic energy as a KineticEnergy [J]: translational = 1/2 m v_W.v_W, rotational = 1/2 w_B.I w_B about the centre of mass (1/2 I_zz omega^2 for a PlanarBody, 0 for a Particle), total = their sum. body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    """
def linear_momentum(body: typing.Any, state: typing.Any) -> typing.Any:
    """
    Linear momentum m v_W [kg m/s] in W: (3,), or (2,) for a PlanarBody. body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    """
def matrix_to_euler(seq: typing.Any, R: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Euler angles [rad] of rotation matrices (ranges as quat_to_euler; degrees if degrees=True).
    
    seq: 3 letters as SciPy, lowercase 'xyz' = extrinsic (fixed axes), uppercase 'XYZ' = intrinsic
    (moving axes); the 12 sequences xyz xzy yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;
    projected onto the nearest rotation as SciPy's Rotation.from_matrix).
    Returns (3,) or (n, 3).
    Gimbal lock: a UserWarning 'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the
    middle angle of some item within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper
    sequences, -pi/2 or pi/2 in Tait-Bryan ones; Davenport angles: the ends of its range). Within
    round-off of it (1e-13 rad) only the sum or difference of the first and third angles is defined:
    the third is set to 0 and the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad
    the angles are the exact ones and the message says so (SciPy sets the third to 0 there too, which
    moves the rotation by up to 2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    """
def matrix_to_quat(R: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of rotation matrices, canonical sign w >= 0 (Shepperd's method, accurate at all angles).
    
    R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;
    projected onto the nearest rotation as SciPy's Rotation.from_matrix).
    Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def matrix_to_rotvec(R: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Logarithm map of rotation matrices: rotation vector angle * axis [rad], angle in [0, pi].
    
    R: (3, 3) or (n, 3, 3), a rotation matrix up to rounding (det > 0, singular values within 0.05 of 1;
    projected onto the nearest rotation as SciPy's Rotation.from_matrix).
    Returns (3,) or (n, 3), in degrees if degrees=True.
    Accurate near 0 and pi.
    """
def mesh_shell(vertices: typing.Any, faces: typing.Any, *, mass: typing.Any = None, density: typing.Any = None, weld_tolerance: typing.Any = None) -> SpatialInertia:
    """
    Thin shell made of the faces (any orientation, need not be closed): vertices (n, 3) [m], faces
    (f, 3), welded as in solid_mesh (weld_tolerance). Give exactly one of mass= [kg] or density= [kg/m^2].
    """
def mesh_symmetry_planes(vertices: typing.Any, faces: typing.Any, tolerance: typing.Any = 1e-09, *, weld_tolerance: typing.Any = None) -> list:
    """
    Planes of symmetry of the uniform solid bounded by a closed, outward-oriented mesh: vertices (n, 3)
    [m], faces (f, 3), welded as in solid_mesh (weld_tolerance). The planes of the solid, whatever its
    triangulation: a plane qualifies when its reflection maps the solid's oriented boundary onto itself
    (each reflected face covered by faces in the same plane and facing the same way, up to a strip of
    width tolerance * L along its edges, L = largest distance from the centre of mass to a vertex [m];
    normals within tolerance). A faceted cylinder or capsule of s sections has the s planes through its
    axis and the plane normal to it, not the smooth solid's continuum. Returns a list of (normal (3,)
    unit, largest-magnitude component positive; point (3,) [m] = the solid's centre of mass) in the frame
    of the vertices; candidates as in symmetry_planes. ValueError naming the argument on a bad mesh.
    """
def mesh_volume(vertices: typing.Any, faces: typing.Any) -> float:
    """
    Signed volume [m^3] of the mesh vertices (n, 3) [m], faces (f, 3).
    """
def methods() -> list:
    """
    The fixed-step methods: a list of dicts with name, order (global), evaluations (derivative evaluations per step), conserves (what is kept exactly on a free rigid body), notes, stability_limit (largest dt*|w| [rad], |w| the largest body rate on the torque-free orbit, at which the method is documented stable on a free spin: inf if unconditionally, 0 if never), exact_torque_free (True if torque-free motion is reproduced to round-off at any dt: no observed order applies) and scene_features (what of a Scene the method runs: bodies, elements, and its compatibility notes).
    """
def motion_cross_matrix(motion: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    crm(V) (6,6) = [[hat(w), 0], [hat(v), hat(w)]] of the motion V = [w; v], so crm(V) V2 = V x V2.
    """
def mrp_to_quat(mrp: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion ((2 p, 1 - |p|^2) / (1 + |p|^2)) of modified Rodrigues parameters p (either shadow
    set: p and -p/|p|^2 are the same rotation; w < 0 when |p| > 1), as SciPy's Rotation.from_mrp.
    
    mrp: (3,) or (n, 3), any finite values. Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if
    scalar_first.
    """
def nearest_rotation(M: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    The rotation matrix nearest to M in the Frobenius norm (orthogonal Procrustes problem).
    
    M: (3, 3) or (n, 3, 3), any finite matrices. With the SVD M = U S V^T, returns
    R = U diag(1, 1, det(U V^T)) V^T: (3, 3) or (n, 3, 3), orthonormal with det +1 to round-off.
    For det M > 0 this is the orthogonal polar factor of M (Higham 1986), the matrix SciPy's
    Rotation.from_matrix stores for a non-orthonormal M; for det M < 0 the smallest singular
    direction is flipped (Kabsch). Unique when M has rank >= 2 (and, for det M < 0, distinct two
    smallest singular values). Idempotent: a rotation matrix is returned unchanged to round-off.
    """
def nearest_valid_inertia(inertia: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    Explicit repair: the nearest (Frobenius) matrix (3,3) satisfying the triangle inequality, same
    principal axes; a valid inertia is returned unchanged. Never applied implicitly.
    """
def point_acceleration(K_AF: typing.Any, p_FQ_F: typing.Any, v_FQ_F: typing.Any, a_FQ_F: typing.Any) -> PointAcceleration:
    """
    Acceleration terms of Q seen from A, expressed in A; a_FQ_F (3,) [m/s^2]: Q's acceleration seen
    from F, expressed in F; the rest as point_velocity.
    """
def point_inertia(mass: typing.Any, r: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    m (|r|^2 1 - r r^T) (3,3) [kg m^2]: a point mass [kg] > 0 at r (3,) [m] about the origin.
    """
def point_velocity(K_AF: typing.Any, p_FQ_F: typing.Any, v_FQ_F: typing.Any) -> PointVelocity:
    """
    Velocity terms of Q seen from A, expressed in A. K_AF: F relative to A; p_FQ_F (3,) [m] and v_FQ_F
    (3,) [m/s]: Q's position relative to F's origin and its velocity seen from F, expressed in F.
    """
def potential_energy(body: typing.Any, state: typing.Any, gravity: typing.Any = None) -> typing.Any:
    """
    Potential energy of uniform gravity, V = -m g.p_W [J] (zero at the origin of W). gravity: None (the default, as in simulate: no field, so V = 0 J), True = (0, 0, -9.81) m/s^2, or a vector (3,) [m/s^2] in W; for a PlanarBody None or an in-plane (2,) [m/s^2]. body: a RigidBody, PlanarBody or Particle; state: its state (RigidBodyState, PlanarBodyState or ParticleState), finite (ValueError naming it otherwise, e.g. for a state a diverged step returned). 
    """
def power(state: typing.Any, f_W: typing.Any, tau_B: typing.Any = None) -> typing.Any:
    """
    Power [W] of a force f_W [N] in W at the centre of mass and a torque tau_B about it (None: none): f_W.v_W + tau_B.w_B. RigidBodyState: f_W (3,), tau_B (3,) [N m] in B; PlanarBodyState: f_W (2,), tau_B [N m] about z; ParticleState: f_W (3,) only.
    """
def principal_axes(inertia: typing.Any) -> PrincipalAxes:
    """
    Principal moments and axes of symmetric inertias (3,3) or (n,3,3) [kg m^2] (lower triangles read),
    about the point and in the frame the inertia is given for. Returns a PrincipalAxes: moments (3,)
    or (n,3) ascending [kg m^2], axes (3,3) or (n,3,3) with column k the unit axis of moments[k],
    right-handed, canonical when moments coincide; it unpacks as `moments, axes = principal_axes(I)`.
    Releases the GIL.
    """
def quat_canonical(q: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    The canonical quaternion of each rotation (q and -q are the same rotation): w > 0, or where
    w = 0 the first non-zero of x, y, z positive, exactly as SciPy's as_quat(canonical=True).
    
    q: (4,) or (n, 4) unit quaternions, (x, y, z, w) or (w, x, y, z) if scalar_first.
    Returns (4,) or (n, 4) in the same order.
    """
def quat_integrate(q: typing.Any, w: typing.Any, dt: typing.Any, frame: typing.Any = 'body', scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exact attitude update for an angular velocity w [rad/s] constant over dt [s].
    
    frame='body': q ⊗ exp(w dt/2), w = w_B expressed in the body frame;
    frame='world': exp(w dt/2) ⊗ q, w = w_W expressed in the world frame;
    exp of a pure vector u is (sin|u| u/|u|, cos|u|).
    q: (4,) or (n, 4) unit quaternions q_WB; w: (3,) or (n, 3); dt: float.
    Returns (4,) or (n, 4), normalised, (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def quat_inverse(q: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Inverse (conjugate) of unit quaternions: q_BW from q_WB. q: (4,) or (n, 4); returns the same shape.
    """
def quat_multiply(q1: typing.Any, q2: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Hamilton product q1 ⊗ q2 of unit quaternions: R(q1 ⊗ q2) = R(q1) R(q2) (q2 applied first).
    
    q1, q2: (4,) or (n, 4) each (a single one is used with every item of the other).
    Returns (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    """
def quat_normalize(q: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    q / |q| for finite non-zero quaternions of any norm (ValueError for q = 0).
    q: (4,) or (n, 4); returns the same shape, sign unchanged.
    """
def quat_rate(q: typing.Any, w: typing.Any, frame: typing.Any = 'body', scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Quaternion rate dq/dt [1/s] of the attitude q = q_WB turning with angular velocity w [rad/s]:
    frame='body': dq/dt = 1/2 q ⊗ (w, 0), w = w_B expressed in the body frame;
    frame='world': dq/dt = 1/2 (w, 0) ⊗ q, w = w_W expressed in the world frame.
    q: (4,) or (n, 4) unit quaternions; w: (3,) or (n, 3) (a single one is used with every item of the
    other). Returns (4,) or (n, 4) in q's order, orthogonal to q, |dq/dt| = |w|/2.
    """
def quat_rotate(q: typing.Any, v: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    R(q) v: vectors rotated actively by unit quaternions (v_W = R_WB v_B for q = q_WB).
    
    q: (4,) or (n, 4); v: (3,) or (n, 3) (a single one is used with every item of the other).
    Returns (3,) or (n, 3).
    """
def quat_to_axis_angle(q: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> tuple[numpy.typing.NDArray[numpy.float64], typing.Any]:
    """
    Axis (unit) and angle [rad] in [0, pi] (degrees in [0, 180] if degrees=True) of unit quaternions;
    the identity gives axis (1, 0, 0), angle 0.
    
    q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first.
    Returns (axis, angle): ((3,), float) or ((n, 3), (n,)).
    """
def quat_to_davenport(axes: typing.Any, order: typing.Any, q: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Davenport angles [rad] of unit quaternions (Bernardes & Viollet 2022, arbitrary axes).
    
    axes: (3, 3), the rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2
    orthogonal to n1 and to n3 (|cos| <= 1e-7, as SciPy); order: 'e'/'extrinsic' (fixed axes,
    R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i'/'intrinsic' (moving axes, R = R_n1(a1) R_n2(a2) R_n3(a3)),
    as SciPy's Rotation.from_davenport / as_davenport. Coordinate axes give Euler angles.
    q: (4,) or (n, 4). Returns (3,) or (n, 3) [rad] (degrees if degrees=True), as SciPy: first and
    third in [-pi, pi], second in [-l, pi - l] if l >= 0, [-pi - l, -l] if l < 0, where
    l = atan2(m3 . (m1 x n2), m3 . m1) with (m1, m3) = (n1, n3), or (n3, n1) if intrinsic (proper Euler:
    l = 0, second in [0, pi]; Tait-Bryan: l = +-pi/2, second in [-pi/2, pi/2]).
    Gimbal lock: a UserWarning 'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the
    middle angle of some item within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper
    sequences, -pi/2 or pi/2 in Tait-Bryan ones; Davenport angles: the ends of its range). Within
    round-off of it (1e-13 rad) only the sum or difference of the first and third angles is defined:
    the third is set to 0 and the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad
    the angles are the exact ones and the message says so (SciPy sets the third to 0 there too, which
    moves the rotation by up to 2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    """
def quat_to_euler(seq: typing.Any, q: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Euler angles [rad] of unit quaternions (Bernardes & Viollet 2022).
    
    seq: 3 letters as SciPy, lowercase 'xyz' = extrinsic (fixed axes), uppercase 'XYZ' = intrinsic
    (moving axes); the 12 sequences xyz xzy yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    q: (4,) or (n, 4). Returns (3,) or (n, 3) [rad] (degrees if degrees=True): first and third in
    [-pi, pi], second in [0, pi] (proper) or [-pi/2, pi/2] (Tait-Bryan).
    Gimbal lock: a UserWarning 'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the
    middle angle of some item within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper
    sequences, -pi/2 or pi/2 in Tait-Bryan ones; Davenport angles: the ends of its range). Within
    round-off of it (1e-13 rad) only the sum or difference of the first and third angles is defined:
    the third is set to 0 and the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad
    the angles are the exact ones and the message says so (SciPy sets the third to 0 there too, which
    moves the rotation by up to 2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    """
def quat_to_matrix(q: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotation matrix R(q) of unit quaternions.
    
    q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first; unit norm within 1e-6.
    Returns R: (3, 3) or (n, 3, 3), active (R v rotates v; q_WB gives R_WB).
    """
def quat_to_mrp(q: typing.Any, scalar_first: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Modified Rodrigues parameters p = axis tan(angle/4) of unit quaternions, the set with |p| <= 1
    (angle in [0, pi]; as SciPy's Rotation.as_mrp). Dimensionless.
    
    q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first. Returns (3,) or (n, 3).
    """
def quat_to_rotvec(q: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Logarithm map: rotation vector angle * axis [rad] of unit quaternions, angle in [0, pi].
    
    q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first. Returns (3,) or (n, 3),
    in degrees (angle in [0, 180]) if degrees=True.
    Accurate near angle 0 and near pi (atan2 form).
    """
def random_rotations(n: typing.Any = None, rng: typing.Any = None, scalar_first: typing.Any = False, canonical: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotations drawn uniformly (Haar measure) from SO(3), as unit quaternions.
    
    n: None (one rotation, shape (4,)) or a count (shape (n, 4)). rng: a numpy.random.Generator,
    or None / a seed (int >= 0) for numpy.random.default_rng. The draws are SciPy's: for the same
    generator state the result equals Rotation.random(n, rng=rng).as_quat() (normalised
    standard normal 4-vectors), and the generator advances by 4 n normal draws. Returns (x, y, z, w), or (w, x, y, z) if scalar_first; canonical=True gives the representative with w >= 0
    (SciPy's as_quat(canonical=True): at w = 0 the first non-zero of x, y, z is positive).
    """
def relative_kinematics(K_WA: typing.Any, K_WF: typing.Any) -> FrameKinematics:
    """
    F relative to A from A and F relative to a common frame W; expressed in A. Inverse of compose_kinematics.
    """
def require_closed_oriented_mesh(faces: typing.Any, n_vertices: typing.Any) -> None:
    """
    ValueError unless faces (f, 3) index [0, n_vertices) and form a closed, consistently oriented mesh.
    """
def rot_x(angle: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation about x by angle [rad] (active): [[1, 0, 0], [0, c, -s], [0, s, c]].
    angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).
    """
def rot_y(angle: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation about y by angle [rad] (active): [[c, 0, s], [0, 1, 0], [-s, 0, c]].
    angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).
    """
def rot_z(angle: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation about z by angle [rad] (active): [[c, -s, 0], [s, c, 0], [0, 0, 1]].
    angle: float or (n,), in degrees if degrees=True. Returns (3, 3) or (n, 3, 3).
    """
def rotvec_to_matrix(rotvec: typing.Any, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exponential map into rotation matrices (Rodrigues): rotvec = angle * axis [rad], (3,) or (n, 3)
    (in degrees if degrees=True).
    Returns R: (3, 3) or (n, 3, 3).
    """
def rotvec_to_quat(rotvec: typing.Any, scalar_first: typing.Any = False, *, degrees: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exponential map: unit quaternion of rotation vectors rotvec = angle * axis [rad] (any angle; exact near 0).
    
    rotvec: (3,) or (n, 3), in degrees if degrees=True. Returns q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if scalar_first;
    w < 0 when the angle exceeds pi (no sign flip).
    """
def screw_to_twist(screw: typing.Any) -> Motion:
    """
    The twist of a screw: w = magnitude direction, v = magnitude (point x direction + pitch direction)
    (v = magnitude direction for pitch inf).
    """
def simulate(model: typing.Any, initial: typing.Any, dt: typing.Any, steps: typing.Any = None, method: typing.Any = None, record_every: typing.Any = 1, loads: typing.Any = None, gravity: typing.Any = None, t0: typing.Any = 0.0, scalar_first: typing.Any = False, progress: typing.Any = None, *, duration: typing.Any = None) -> SimulationResult | SceneResult:
    """
    Integrate `model` from `initial` over `steps` fixed steps of `dt` [s] with `method` (see methods()),
    in C++ with the GIL released, and record every `record_every`-th step (plus the first and the last).
    The run's length: steps= (an int >= 0) or, by keyword, duration= [s] (a float or a pint quantity), exactly one;
    a duration must be a whole number of steps of dt (to 1e-9 relative: 10 s at dt = 0.01 s is 1000 steps),
    else ValueError naming duration and dt with the nearest durations that are.
    dt, t0 and duration: each a float [s] or a pint quantity (converted to s; ValueError naming it for another
    dimension).
    
    model/initial: Particle/ParticleState, PlanarBody/PlanarBodyState or RigidBody/RigidBodyState; or a Scene
      or CompiledScene and a list of the states of its bodies (returns a SceneResult: see Scene); or a PivotedBody/
      PivotedBodyState, PivotedPlanarBody/PivotedPlanarBodyState or Gyrostat/GyrostatState: the one-body scene of
      the body, UniformGravity (gravity) and ScheduledLoads (loads) (returns a SceneResult; a PivotedPlanarBody takes
      an in-plane gravity (2,) or (3,)).
    method: a name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
    loads: an AppliedLoad or a sequence of them, a piecewise-constant schedule: a step that crosses a
      switch time (a t_start or t_end) is split there into sub-steps of the same method, so every method
      keeps its order; records stay at t0 + i dt. gravity: None/False (the default: none), True
      ((0, 0, -9.81) m/s^2 in W) or a 3-vector [m/s^2] in W. t0: initial time [s]. scalar_first: quaternions
      as (w, x, y, z).
    progress: None or a callable(steps_done), called with the GIL after the first step and then about every
      0.05 s of a long run, however long a step takes; an exception it raises stops the run and propagates.
    
    Returns a SimulationResult, arrays with one row per record (n records): t (n,) [s]; p_W (n, 3) [m];
    q_WB (n, 4) (x, y, z, w); v_W (n, 3) [m/s]; w_B (n, 3) [rad/s]; kinetic_energy (n,) [J];
    total_energy (n,) kinetic + gravity potential [J]; angular_momentum_norm (n,) |H_G| [kg m^2/s];
    quaternion_norm_error (n,) |q| - 1; work (n,) work of loads and gravity since t0 [J], integrated by the
    same method (kinetic_energy - kinetic_energy[0] ~ work); diverged; unconverged_steps (implicit solves that
    hit their iteration cap); elapsed_seconds (C++ loop wall time).
    A particle records q = identity, w = 0; a planar body p = (x, y, 0), q = Rz(theta), w = (0, 0, omega).
    Warns RuntimeWarning and stops if the state becomes non-finite; warns RuntimeWarning naming the quantities
    and their first times if a recorded quantity is not finite although the state is (an overflow, e.g. the
    kinetic energy of |v_W| > 1e154 m/s); warns RuntimeWarning (naming dt and the count) if an implicit solve
    did not converge. Ctrl-C stops the run within about 0.05 s however long a step takes (a step under way is
    finished first) with KeyboardInterrupt (no result is kept). ValueError names a bad argument, also a
    recording larger than the memory available (record_every, with both figures).
    """
def simulate_batch(model: typing.Any, initial: typing.Any, dt: typing.Any, steps: typing.Any = None, method: typing.Any = None, record_every: typing.Any = 1, loads: typing.Any = None, gravity: typing.Any = None, t0: typing.Any = 0.0, threads: typing.Any = None, simd: typing.Any = False, scalar_first: typing.Any = False, progress: typing.Any = None, *, duration: typing.Any = None) -> BatchResult | BatchSceneResult:
    """
    N independent runs of `model`, one per initial state, with per-sample parameters, integrated in C++ on
    `threads` threads with the GIL released. Sample i is exactly rigiddyn.simulate(model_i, initial[i], dt_i, steps,
    method, record_every, loads_i, gravity_i, t0): the records equal N serial simulate calls bitwise, whatever the
    thread count.
    
    model: a Particle, PlanarBody or RigidBody shared by every sample, or a list of N of one kind (per-sample
      mass [kg] and inertia about the centre of mass in B [kg m^2]); or a Scene or CompiledScene, or a list of N of
      them (of the same structure: bodies and elements). A scene with a PythonForce runs, slowly: each call takes
      the GIL, so its samples run one at a time.
    initial: a list of N states of the body's kind (ParticleState, PlanarBodyState, RigidBodyState), or a dict of
      stacked arrays: RigidBody {'p_W': (N, 3) [m], 'q_WB': (N, 4) (x, y, z, w), or (w, x, y, z) with scalar_first,
      'v_W': (N, 3) [m/s] in W, 'w_B': (N, 3) [rad/s] in B}; Particle {'p_W', 'v_W'}; PlanarBody {'p_W': (N, 2) [m],
      'theta': (N,) [rad], 'v_W': (N, 2) [m/s], 'omega': (N,) [rad/s]}. A scene: a list of N lists of the states of
      its bodies.
    dt: a float [s] for every sample or an (N,) array [s] (pint quantities converted). steps (or duration= by
      keyword), record_every, t0, method, scalar_first: as simulate, shared by every sample (so every sample has the
      same record count n; a duration must give the same number of steps at every sample's dt).
    loads (bodies): as simulate (one schedule for every sample), or a list of N schedules (lists of AppliedLoad).
    gravity (bodies): as simulate (None/False, True, a 3-vector [m/s^2] in W), or an (N, 3) array [m/s^2] in W.
      A scene declares its loads and gravity as elements (loads and gravity must be None).
    threads: None (the default: every hardware thread) or an int >= 1.
    simd: True runs the SIMD path across samples (RigidBody, method 'rk4', constant loads: a force in W and a
      torque in B without time window): equal to the scalar path up to round-off, not bitwise.
    progress: None or a callable(samples_done), called with the GIL from the calling thread once before the samples
      start and then about every 0.05 s; an exception it raises stops every sample and propagates. Ctrl-C stops every sample within about 0.05 s however
      long a step takes (the steps under way are finished first) and raises KeyboardInterrupt (no result is kept).
    
    Returns a BatchResult (bodies) or a BatchSceneResult (scenes): the arrays of SimulationResult / SceneResult
    with a leading sample axis (N, n, ...). A sample whose state becomes non-finite stops alone: diverged[i] is
    True, filled[i] its rows, the rest of its rows NaN; one RuntimeWarning names how many samples diverged and
    the first few; another names the samples whose recorded quantities became non-finite although their state
    stayed finite (an overflow, e.g. a kinetic energy of |v_W| > 1e154 m/s), each quantity with its first time.
    Input errors (N = 0, mismatched N between model, initial, dt, gravity and loads, a wrong dict key or shape,
    threads < 1) raise ValueError/TypeError naming the argument before any sample runs; an error of one sample (a
    bad state, a body running out of mass) raises ValueError "sample <i>: ..." for the lowest such sample, after
    every sample has run. An exception raised by a PythonForce (or its wrong return value) stops every sample
    within about 0.05 s and is raised, its message prefixed "sample <i>: " (the first sample that raised; a
    KeyboardInterrupt as it is).
    """
def slerp(q0: typing.Any, q1: typing.Any, t: typing.Any, scalar_first: typing.Any = False, canonical: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Spherical linear interpolation from q0 (t = 0) to q1 (t = 1), shortest path, constant rate.
    
    q(t) = q0 * exp(t log(q0^-1 * q1)), the log at angle in [0, pi]: SciPy's
    Slerp([0, 1], Rotation.from_quat([q0, q1]))(t). Any finite t extrapolates along the arc.
    q0, q1: (4,) or (n, 4) unit quaternions; t: float or (n,) (dimensionless fraction);
    single items are used with every item of the stacks. Returns (4,) or (n, 4),
    (x, y, z, w), or (w, x, y, z) if scalar_first; canonical=True gives the representative with w >= 0
    (SciPy's as_quat(canonical=True): at w = 0 the first non-zero of x, y, z is positive).
    To interpolate between key rotations at key times use slerp_keys.
    """
def slerp_keys(times: typing.Any, q: typing.Any, t: typing.Any, scalar_first: typing.Any = False, canonical: typing.Any = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Slerp through key rotations q[k] at key times times[k]: SciPy's Slerp(times, rotations)(t).
    
    times: (k,) strictly increasing, k >= 2 [any time unit]; q: (k, 4) unit quaternions;
    t: float or (m,) within [times[0], times[-1]] (ValueError outside). On [times[j], times[j+1]]
    the result is slerp(q[j], q[j+1], (t - times[j]) / (times[j+1] - times[j])).
    Returns (4,) or (m, 4), (x, y, z, w), or (w, x, y, z) if scalar_first; canonical=True gives the representative with w >= 0
    (SciPy's as_quat(canonical=True): at w = 0 the first non-zero of x, y, z is positive).
    """
def solid_box(size: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid box, edges size (3,) [m] along x, y, z. Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_capsule(radius: typing.Any, length: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid capsule along z: cylinder of the given length [m] plus two hemispherical caps of radius [m].
    Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_cone(radius: typing.Any, height: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid cone, axis z, apex at z = 3h/4, base at z = -h/4 (com at origin): I_zz = 3/10 m r^2,
    I_xx = m (3/20 r^2 + 3/80 h^2). Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_cylinder(radius: typing.Any, height: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid cylinder, axis z: I_zz = m r^2/2, I_xx = m (3 r^2 + h^2)/12. Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_ellipsoid(semi_axes: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid ellipsoid, semi-axes (3,) [m]: I = m/5 diag(b^2+c^2, a^2+c^2, a^2+b^2). Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_mesh(vertices: typing.Any, faces: typing.Any, *, mass: typing.Any = None, density: typing.Any = None, weld_tolerance: typing.Any = None) -> SpatialInertia:
    """
    Solid bounded by a closed, outward-oriented triangle mesh: vertices (n, 3) [m], faces (f, 3),
    exact (divergence theorem). Vertices closer than weld_tolerance [m] are first welded into one, as
    trimesh does on load (None: 1e-8 x the bounding-box diagonal; 0: off), faces left degenerate dropped,
    and a MeshWeldWarning says how many. ValueError naming the first open or misoriented edge (input
    indices), or an inward orientation. Give exactly one of mass= [kg] or density= [kg/m^3].
    (rigiddyn.solid_mesh also accepts a trimesh object.)
    """
def solid_sphere(radius: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid sphere, radius [m]: I = 2/5 m r^2 1. Density [kg/m^3]. Give exactly one of mass= [kg] or density=.
    """
def solid_tetrahedron(vertices: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Solid tetrahedron with vertices (4, 3) [m], expressed in their frame. Density [kg/m^3]. Give exactly
    one of mass= [kg] or density=.
    """
def spherical_shell(radius: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thin spherical surface [m]: I = 2/3 m r^2 1. Density [kg/m^2]. Give exactly one of mass= [kg] or density=.
    """
def step(model: typing.Any, state: typing.Any, dt: typing.Any, method: typing.Any = None, loads: typing.Any = None, gravity: typing.Any = None, t: typing.Any = None) -> typing.Any:
    """
    One step of `method` (see methods()) of length dt [s] from `state` at time t [s] to t + dt under `loads`
    (AppliedLoad or sequence) and `gravity` (None/False, the default: none; True for (0, 0, -9.81) m/s^2, or a
    3-vector [m/s^2] in W). A step across a switch time of the loads is split there, as in simulate.
    dt and t: each a float [s] or a pint quantity (converted to s; ValueError naming it for another dimension).
    
    t=None (default): returns the new state (same type as `state`); ValueError (naming t) if a load acts on a
      time window (finite t_start or t_end), since the step then depends on the time.
    t given: returns (new state, t + dt), e.g. `state, t = step(body, state, dt, loads=loads, t=t)` in a loop.
    Warns RuntimeWarning if the new state is not finite, as simulate does. ValueError names a bad argument.
    method: a name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
    model may also be a Scene or CompiledScene with `state` a list of the states of its bodies: returns the
    list of new states (or (list, t + dt)); ValueError naming model for a scene with a MassFlow (a state does
    not carry the mass: use simulate); or a PivotedBody / PivotedPlanarBody / Gyrostat with its state (the step of its
    one-body scene, as simulate): returns the new state (or (state, t + dt)).
    """
def symmetry_planes(masses: typing.Any, positions: typing.Any, tolerance: typing.Any = 1e-09) -> list:
    """
    Planes of symmetry (Craig "Plane of Symmetry") of point masses (n,) [kg] > 0 at positions
    (n, 3) [m]: the planes whose reflection maps every point onto a point of equal mass, within
    tolerance * (largest distance from the centre of mass to a point) [m] and tolerance * mass.
    Returns a list of (normal (3,) unit, largest-magnitude component positive; point (3,) [m] = the
    centre of mass), in the frame of the positions. Candidates: the principal axes, and when principal
    moments coincide, normals built from the points; for such
    degenerate bodies (cube, regular tetrahedron) the planes found among them, not a proof of none else.
    """
def thin_disk(radius: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thin disk in the xy plane: I = m r^2 diag(1/4, 1/4, 1/2). Density [kg/m^2]. Give exactly one of mass= [kg] or density=.
    """
def thin_plate(size_x: typing.Any, size_y: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thin plate in the xy plane: I = m/12 diag(b^2, a^2, a^2 + b^2). Density [kg/m^2]. Give exactly one of mass= [kg] or density=.
    """
def thin_rod(length: typing.Any, *, mass: typing.Any = None, density: typing.Any = None) -> SpatialInertia:
    """
    Thin rod along z: I_xx = I_yy = m L^2/12. Density [kg/m]. Give exactly one of mass= [kg] or density=.
    """
def transform_compose(R_AB: typing.Any, p_AB: typing.Any, R_BC: typing.Any, p_BC: typing.Any) -> tuple:
    """
    X_AC = X_AB * X_BC item by item: R_AC = R_AB R_BC, p_AC = R_AB p_BC + p_AB. Rotations (3,3) or
    (n,3,3), translations (3,) or (n,3) [m]; single items broadcast. Returns (R_AC, p_AC).
    """
def transform_points(R_AB: typing.Any, p_AB: typing.Any, p_B: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    p_A = R_AB p_B + p_AB item by item: R_AB (3,3)|(n,3,3), p_AB (3,)|(n,3), p_B (3,)|(n,3) [m];
    single items broadcast.
    """
def transport_derivative(w_AB: typing.Any, u: typing.Any, du_dt_in_B: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    Transport theorem (Craig's "Rigid Body Dynamics" slides): d^A u/dt = d^B u/dt + w_AB x u. All (3,),
    expressed in one frame.
    """
def twist_to_screw(twist: typing.Any) -> Screw:
    """
    The screw (instantaneous screw axis) of a twist [w; v]: direction w/|w|, point (w x v)/|w|^2,
    pitch (w . v)/|w|^2, magnitude |w|; for w = 0: pitch inf, direction v/|v|, point 0, magnitude |v|.
    ValueError for the zero twist (no axis).
    """
def vee(S: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
    """
    Inverse of hat: v with hat(v) = (S - S^T)/2 (a symmetric part of S is ignored).
    S: (3, 3) or (n, 3, 3); returns (3,) or (n, 3).
    """
def weld_vertices(vertices: typing.Any, faces: typing.Any, tolerance: typing.Any = None) -> WeldedMesh:
    """
    Welds vertices (n, 3) [m] closer than tolerance [m] (None: 1e-8 x the bounding-box diagonal), as
    solid_mesh does: clusters of vertices within tolerance of one another (grid hashing, O(n log n)) keep
    their lowest-indexed vertex; faces (f, 3) repeating a vertex afterwards are dropped. Returns a
    WeldedMesh (vertices, faces, welded_vertices, dropped_faces, ...); warns nothing.
    """
FORCE_ELEMENTS: tuple = (UniformGravity, PointMassGravity, MutualGravity, GravityGradient, SpringDamper, Drag, ScheduledLoads, PythonForce, Thrust, MagneticDipole, ReactionWheel)
__version__: str = '0.1.0'
inertia_relative_tolerance: float = 1e-10
