"""
rigiddyn's C++ core (rotations, frames, spatial algebra, inertia, dynamics, orbits).
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['AppliedLoad', 'AtmosphericDrag', 'BatchSceneResult', 'BodyAcceleration', 'BodyRecords', 'ComWrench', 'CompiledScene', 'CompoundPendulumSolution', 'ConstantThrustSolution', 'DensityIntegral', 'Drag', 'ElementField', 'FORCE_ELEMENTS', 'FixedJoint', 'Force', 'FrameKinematics', 'FrameMotion', 'FrameTree', 'FreeJoint', 'GlobalError', 'GravityGradient', 'Gyrostat', 'GyrostatState', 'InertiaCheck', 'InertiaReport', 'JointState', 'KineticEnergy', 'LagrangeTopSolution', 'MagneticDipole', 'MassFlow', 'MeshWeldWarning', 'Motion', 'MutualGravity', 'Particle', 'ParticleState', 'PivotedAcceleration', 'PivotedBody', 'PivotedBodyState', 'PivotedPlanarAcceleration', 'PivotedPlanarBody', 'PivotedPlanarBodyState', 'PivotedPlanarTorque', 'PivotedTorque', 'PlanarAcceleration', 'PlanarBody', 'PlanarBodyState', 'PlanarWrench', 'PointAcceleration', 'PointMassGravity', 'PointVelocity', 'PrincipalAxes', 'PrismaticJoint', 'PrismaticMotor', 'PrismaticSpringDamper', 'PythonForce', 'ReactionWheel', 'RevoluteJoint', 'RevoluteMotor', 'RevoluteSpringDamper', 'RigidBody', 'RigidBodyState', 'RotatingFrameFreeParticle', 'Scene', 'SceneCompatibilityWarning', 'SceneFrame', 'SceneResult', 'ScheduledLoads', 'Screw', 'SolarRadiationPressure', 'SpatialInertia', 'SphericalJoint', 'SphericalSpringDamper', 'SpringDamper', 'Thrust', 'ToleranceChoice', 'ToleranceError', 'TorqueFreeSolution', 'Transform', 'Tree', 'TreeLink', 'UniformGravity', 'WeldedMesh', 'Wheel', 'ZonalGravity', 'aba', 'align_vectors', 'angular_distance', 'angular_momentum', 'angular_velocity_from_quat_rate', 'apply_impulse', 'attitude_from_orbit_frame', 'attitude_to_orbit_frame', 'axis_angle_to_quat', 'bias_forces', 'box_shell', 'compose_kinematics', 'composite', 'crba', 'davenport_to_quat', 'default_thread_count', 'eccentric_to_mean_anomaly', 'eccentric_to_true_anomaly', 'elements_to_state', 'ellipk', 'ellippi', 'ellippi_am', 'elliprf', 'elliprj', 'euler_to_matrix', 'euler_to_quat', 'force_cross_matrix', 'forward_dynamics', 'forward_kinematics', 'from_point_masses', 'generalized_momentum', 'generalized_momentum_rate', 'hat', 'hollow_cylinder', 'hollow_sphere', 'inertia_relative_tolerance', 'inertia_report', 'integrate_density_over_box', 'integrate_density_over_mesh', 'inverse_dynamics', 'jacobi_ellipj', 'kepler_propagate', 'kinetic_energy', 'linear_momentum', 'matrix_to_euler', 'matrix_to_quat', 'matrix_to_rotvec', 'mean_to_eccentric_anomaly', 'mean_to_true_anomaly', 'mesh_shell', 'mesh_symmetry_planes', 'mesh_volume', 'methods', 'motion_cross_matrix', 'mrp_to_quat', 'nearest_rotation', 'nearest_valid_inertia', 'orbit_frame_angular_velocity', 'orbit_frame_rotation', 'point_acceleration', 'point_inertia', 'point_velocity', 'potential_energy', 'power', 'principal_axes', 'quat_canonical', 'quat_integrate', 'quat_inverse', 'quat_multiply', 'quat_normalize', 'quat_rate', 'quat_rotate', 'quat_to_axis_angle', 'quat_to_davenport', 'quat_to_euler', 'quat_to_matrix', 'quat_to_mrp', 'quat_to_rotvec', 'random_rotations', 'relative_kinematics', 'require_closed_oriented_mesh', 'rnea', 'rot_x', 'rot_y', 'rot_z', 'rotvec_to_matrix', 'rotvec_to_quat', 'screw_to_twist', 'semi_latus_rectum', 'simulate', 'simulate_batch', 'slerp', 'slerp_keys', 'solid_box', 'solid_capsule', 'solid_cone', 'solid_cylinder', 'solid_ellipsoid', 'solid_mesh', 'solid_sphere', 'solid_tetrahedron', 'spherical_shell', 'state_to_elements', 'step', 'symmetry_planes', 'thin_disk', 'thin_plate', 'thin_rod', 'transform_compose', 'transform_points', 'transport_derivative', 'true_to_eccentric_anomaly', 'true_to_mean_anomaly', 'twist_to_screw', 'vector_instructions', 'vee', 'weld_vertices']
class _Quantity(typing.Protocol):
    """A pint Quantity of any registry (the core converts it to SI by its magnitude and units)."""
    @property
    def magnitude(self) -> typing.Any: ...
    @property
    def units(self) -> typing.Any: ...
_MethodName: typing.TypeAlias = typing.Literal['explicit_euler', 'semi_implicit_euler', 'semi_implicit_euler_implicit_gyroscopic', 'rk4', 'rkmk4', 'implicit_midpoint', 'splitting_dlm', 'splitting_dlm_yoshida4', 'exact_flow_kick', 'exact']
class FrameKinematics:
    """
    Frame F relative to frame P at one instant: orientation, angular velocity and acceleration, and the
    position, velocity and acceleration of F's origin.
    
    P is the parent of a FrameMotion, or the `relative_to` frame of a FrameTree query. Every vector is
    expressed in P; SI units. The caller keeps the fields consistent (w, alpha the derivatives of R; v, a
    those of p): only R_PF being a rotation and finiteness are checked.
    
    Parameters
    ----------
    R_PF : array_like, shape (3, 3), optional
        Orientation of F in P, F coordinates to P coordinates (None: identity).
    w_PF_P : array_like, shape (3,), optional
        Angular velocity of F relative to P [rad/s], in P (None: zero).
    alpha_PF_P : array_like, shape (3,), optional
        Angular acceleration of F relative to P [rad/s^2], in P (None: zero).
    p_PF_P : array_like, shape (3,), optional
        Position of F's origin relative to P's [m], in P (None: zero).
    v_PF_P : array_like, shape (3,), optional
        Velocity of F's origin seen from P [m/s], in P (None: zero).
    a_PF_P : array_like, shape (3,), optional
        Acceleration of F's origin seen from P [m/s^2], in P (None: zero).
    
    Raises
    ------
    ValueError
        A non-rotation R_PF, NaN/Inf or a bad shape (the message names the argument).
    
    See Also
    --------
    FrameMotion, FrameTree.kinematics, compose_kinematics, point_velocity
    
    Examples
    --------
    F spins at 2 rad/s about its z axis, its origin fixed 1 m along P's x; a point fixed in F 1 m further out
    moves at w x r_FQ = 2 m/s:
    
    >>> K_PF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0], p_PF_P=[1.0, 0.0, 0.0])
    >>> rd.point_velocity(K_PF, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]).total
    array([0., 2., 0.])
    
    Immutable; pickles; == compares every field exactly.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, R_PF: numpy.typing.ArrayLike | None = None, w_PF_P: numpy.typing.ArrayLike | None = None, alpha_PF_P: numpy.typing.ArrayLike | None = None, p_PF_P: numpy.typing.ArrayLike | None = None, v_PF_P: numpy.typing.ArrayLike | None = None, a_PF_P: numpy.typing.ArrayLike | None = None) -> None:
        """
        Arguments as the attributes (None: identity / zero); see the class. ValueError on a non-rotation R_PF or
        NaN/Inf.
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
    Velocity of a point Q moving in a frame F, seen from a frame A, term by term.
    
    v_AQ = v_AF + w_AF x r_FQ + v_FQ ("Rigid body kinematics and dynamics" notes (4.38)): total = origin +
    rotational + relative. Each (3,) [m/s], all expressed in the same frame E (the query's `expressed_in`;
    A for the free function point_velocity).
    
    Parameters
    ----------
    origin : array_like, shape (3,)
        v_AF_E, velocity of F's origin seen from A [m/s].
    rotational : array_like, shape (3,)
        w_AF x r_FQ [m/s].
    relative : array_like, shape (3,)
        v_FQ_E, velocity of Q seen from F [m/s].
    
    See Also
    --------
    point_velocity, FrameTree.point_velocity, PointAcceleration
    
    Examples
    --------
    >>> rd.PointVelocity([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]).total
    array([1., 1., 1.])
    
    Immutable; pickles; == compares every term exactly.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every term.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, origin: numpy.typing.ArrayLike, rotational: numpy.typing.ArrayLike, relative: numpy.typing.ArrayLike) -> None:
        """
        From its terms (3,) [m/s], all in one frame; see the class.
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
    Acceleration of a point Q moving in a frame F, seen from a frame A, term by term.
    
    a_AQ = a_AF + alpha_AF x r_FQ + w_AF x (w_AF x r_FQ) + a_FQ + 2 w_AF x v_FQ ("Rigid body kinematics and
    dynamics" notes (4.39); Craig's "Rigid Body Dynamics" slides): total = origin + tangential +
    centripetal + relative + coriolis. Each (3,) [m/s^2], all expressed in one frame E (the query's
    `expressed_in`; A for the free function point_acceleration).
    
    Parameters
    ----------
    origin : array_like, shape (3,)
        a_AF_E, acceleration of F's origin seen from A [m/s^2].
    tangential : array_like, shape (3,)
        alpha_AF x r_FQ [m/s^2].
    centripetal : array_like, shape (3,)
        w_AF x (w_AF x r_FQ) [m/s^2].
    relative : array_like, shape (3,)
        a_FQ_E, acceleration of Q seen from F [m/s^2].
    coriolis : array_like, shape (3,)
        2 w_AF x v_FQ [m/s^2].
    
    See Also
    --------
    point_acceleration, FrameTree.point_acceleration, PointVelocity
    
    Examples
    --------
    >>> a = rd.PointAcceleration([1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [1.0, 0, 0], [0, 1.0, 0])
    >>> a.total
    array([2., 2., 1.])
    
    Immutable; pickles; == compares every term exactly.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every term.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, origin: numpy.typing.ArrayLike, tangential: numpy.typing.ArrayLike, centripetal: numpy.typing.ArrayLike, relative: numpy.typing.ArrayLike, coriolis: numpy.typing.ArrayLike) -> None:
        """
        From its terms (3,) [m/s^2], all in one frame; see the class.
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
    How a frame F moves relative to its parent P: a function of time t [s] giving its FrameKinematics (all
    vectors expressed in P).
    
    Built from a Python callable (general motion), or by FrameMotion.fixed or FrameMotion.constant_rotation.
    
    Parameters
    ----------
    kinematics_at : callable
        t -> a FrameKinematics or a 6-tuple (R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each
        (3,), expressed in P, SI units). The caller keeps them consistent (w, alpha the derivatives of R; v,
        a those of p); the tree checks each value (finite, R_PF a rotation) and raises ValueError naming the
        frame.
    
    Raises
    ------
    TypeError
        kinematics_at not callable.
    
    See Also
    --------
    FrameTree, FrameKinematics
    
    Examples
    --------
    A frame turning at 2 rad/s about P's z axis is a quarter turn on at t = pi/4 s:
    
    >>> M = rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 2.0)
    >>> bool(np.allclose(M.at(np.pi / 4).R_PF, rd.rot_z(np.pi / 2))), M.at(0.1).w_PF_P
    (True, array([0., 0., 2.]))
    
    Immutable; pickles (a general motion when its callable pickles); == compares how it was built.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def constant_rotation(axis_P: numpy.typing.ArrayLike, rate: float, R_PF0: numpy.typing.ArrayLike | None = None, p_PF_P: numpy.typing.ArrayLike | None = None) -> FrameMotion:
        """
        Simple angular velocity (Craig's "Rigid Body Dynamics" slides): F turns at `rate` [rad/s] about
        axis_P (3,) (expressed in P, any non-zero length) through F's origin, which stays at p_PF_P [m] in P
        (None: 0). R_PF(t) = exp(hat(rate t axis_P/|axis_P|)) R_PF0 (R_PF0: orientation at t = 0, None:
        identity).
        
        Parameters
        ----------
        axis_P : array_like, shape (3,)
            Rotation axis, in P (any non-zero length).
        rate : float
            Angular rate [rad/s].
        R_PF0 : array_like, shape (3, 3), optional
            R_PF at t = 0 (None: identity).
        p_PF_P : array_like, shape (3,), optional
            F's fixed origin relative to P's [m], in P (None: 0).
        
        Returns
        -------
        FrameMotion
        
        Examples
        --------
        >>> M = rd.FrameMotion.constant_rotation([0.0, 0.0, 2.0], 1.0)
        >>> bool(np.allclose(M.at(np.pi / 2).R_PF, rd.rot_z(np.pi / 2))), M.at(0.0).w_PF_P
        (True, array([0., 0., 1.]))
        """
    @staticmethod
    def fixed(R_PF: numpy.typing.ArrayLike | None = None, p_PF_P: numpy.typing.ArrayLike | None = None) -> FrameMotion:
        """
        F fixed in P: orientation R_PF (3,3) (None: identity), origin at p_PF_P (3,) [m] in P (None: 0).
        
        Parameters
        ----------
        R_PF : array_like, shape (3, 3), optional
            F coordinates to P coordinates.
        p_PF_P : array_like, shape (3,), optional
            F's origin relative to P's [m], in P.
        
        Returns
        -------
        FrameMotion
        
        Examples
        --------
        >>> rd.FrameMotion.fixed(p_PF_P=[1.0, 2.0, 3.0]).at(5.0).p_PF_P
        array([1., 2., 3.])
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
    def __init__(self, kinematics_at: collections.abc.Callable[..., typing.Any]) -> None:
        """
        General motion: kinematics_at(t) returns a FrameKinematics or a 6-tuple
        (R_PF (3,3), w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P) (each (3,), expressed in P); see the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: float) -> FrameKinematics:
        """
        FrameKinematics of F relative to P at time t [s], expressed in P (not checked: the tree checks the values
        it uses).
        
        Parameters
        ----------
        t : float
            Time [s].
        
        Returns
        -------
        FrameKinematics
            F relative to P, expressed in P.
        
        Raises
        ------
        TypeError
            A general motion's value neither a FrameKinematics nor a 6-tuple.
        ValueError
            A part of that value of another shape (the message names t and the part).
        
        Examples
        --------
        >>> rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 2.0).at(0.5).w_PF_P
        array([0., 0., 2.])
        """
class FrameTree:
    """
    A tree of reference frames rooted at the inertial frame 'world'.
    
    Each frame is placed relative to its parent by a FrameMotion. Queries relate any frame F (`frame`) to any
    frame A (`relative_to`) at time t [s], with results expressed in `expressed_in` E. Unknown names,
    duplicates and cycles raise ValueError. Trees of any depth (every walk is iterative).
    
    Parameters
    ----------
    frames : list of (str, str, FrameMotion), optional
        (name, parent, motion) triples, as repr shows them (None: 'world' only); a parent may come after its
        child.
    
    Raises
    ------
    ValueError
        An unknown parent, a duplicate name or a cycle (naming it).
    TypeError
        frames not such a list (naming the bad item).
    
    See Also
    --------
    FrameMotion, FrameKinematics, SceneFrame
    
    Examples
    --------
    An arm 2 m out on a table turning at 1 rad/s: its origin moves at 2 m/s, accelerates at 2 m/s^2 inward:
    
    >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
    ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
    >>> tree.frame_names()
    ['world', 'table', 'arm']
    >>> tree.point_velocity("arm", [0, 0, 0], [0, 0, 0], "world", "world", 0.0).total
    array([0., 2., 0.])
    >>> tree.point_acceleration("arm", [0, 0, 0], [0, 0, 0], [0, 0, 0], "world", "world", 0.0).total
    array([-2.,  0.,  0.])
    
    Mutable (add_frame, set_parent); pickles when its motions do; == compares names, parents and motions.
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
        as repr shows them; a parent may come after its child. See the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def add_frame(self, name: str, parent: str, motion: FrameMotion) -> None:
        """
        Adds frame `name` under `parent` (which must exist), placed by `motion`.
        
        Parameters
        ----------
        name : str
            The new frame's name (not in the tree yet).
        parent : str
            An existing frame.
        motion : FrameMotion
            How the new frame moves relative to `parent`.
        
        Raises
        ------
        ValueError
            A duplicate name or an unknown parent (naming it).
        
        Examples
        --------
        >>> tree = rd.FrameTree()
        >>> tree.add_frame("table", "world", rd.FrameMotion.fixed(p_PF_P=[0.0, 0.0, 1.0]))
        >>> tree.frame_names(), tree.parent("table")
        (['world', 'table'], 'world')
        """
    def angular_acceleration(self, frame: str, relative_to: str, expressed_in: str, t: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        alpha_AF_E (3,) [rad/s^2]: d/dt in A of w_AF, expressed in E (includes the w x w terms; no
        addition theorem for angular accelerations, Craig's "Rigid Body Dynamics" slides).
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        relative_to : str
            A, the frame it is seen from.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        ndarray, shape (3,)
            alpha_AF_E [rad/s^2].
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.angular_acceleration("arm", "world", "world", 0.0)
        array([0., 0., 0.])
        """
    def angular_velocity(self, frame: str, relative_to: str, expressed_in: str, t: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        w_AF_E (3,) [rad/s]: angular velocity of F relative to A (addition theorem), expressed in E.
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        relative_to : str
            A, the frame it is seen from.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        ndarray, shape (3,)
            w_AF_E [rad/s].
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.angular_velocity("arm", "world", "arm", 0.0)
        array([0., 0., 1.])
        """
    def frame_names(self) -> list[str]:
        """
        All names: 'world' first, then in the order added.
        """
    def has_frame(self, name: str) -> bool:
        """
        True if a frame of this name is in the tree.
        
        Parameters
        ----------
        name : str
        
        Returns
        -------
        bool
        
        Examples
        --------
        >>> rd.FrameTree().has_frame("world"), rd.FrameTree().has_frame("arm")
        (True, False)
        """
    def kinematics(self, frame: str, relative_to: str, t: float) -> FrameKinematics:
        """
        FrameKinematics of `frame` F relative to `relative_to` A at t, expressed in A.
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        relative_to : str
            A, the frame it is seen from.
        t : float
            Time [s].
        
        Returns
        -------
        FrameKinematics
            F relative to A, every vector expressed in A (SI units).
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.kinematics("arm", "world", 0.0).v_PF_P
        array([0., 2., 0.])
        """
    def motion(self, name: str) -> FrameMotion:
        """
        The FrameMotion placing frame `name` in its parent ('world': fixed at the identity).
        
        Parameters
        ----------
        name : str
            A frame of the tree (ValueError otherwise).
        
        Returns
        -------
        FrameMotion
        
        Examples
        --------
        >>> rd.FrameTree().motion("world").at(0.0).p_PF_P
        array([0., 0., 0.])
        """
    def parent(self, name: str) -> str:
        """
        The parent's name ('' for 'world').
        
        Parameters
        ----------
        name : str
            A frame of the tree (ValueError otherwise).
        
        Returns
        -------
        str
        
        Examples
        --------
        >>> rd.FrameTree().parent("world")
        ''
        """
    def point_acceleration(self, frame: str, p_FQ_F: numpy.typing.ArrayLike, v_FQ_F: numpy.typing.ArrayLike, a_FQ_F: numpy.typing.ArrayLike, relative_to: str, expressed_in: str, t: float) -> PointAcceleration:
        """
        PointAcceleration of Q seen from A (origin, tangential, centripetal, relative, coriolis, total),
        terms expressed in E [m/s^2]; a_FQ_F (3,): Q's acceleration seen from F, expressed in F.
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        p_FQ_F : array_like, shape (3,)
            Q relative to F's origin [m], in F.
        v_FQ_F : array_like, shape (3,)
            Q's velocity seen from F [m/s], in F.
        a_FQ_F : array_like, shape (3,)
            Q's acceleration seen from F [m/s^2], in F.
        relative_to : str
            A, the frame it is seen from.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        PointAcceleration
            origin, tangential, centripetal, relative, coriolis and total [m/s^2], in E.
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.point_acceleration("arm", [0, 0, 0], [0, 0, 0], [0, 0, 0], "world", "world", 0.0).origin
        array([-2.,  0.,  0.])
        """
    def point_position(self, frame: str, p_FQ_F: numpy.typing.ArrayLike, relative_to: str, expressed_in: str, t: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_AQ_E (3,) [m]: position of Q relative to A's origin, expressed in E; p_FQ_F (3,): Q relative
        to F's origin, expressed in F.
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        p_FQ_F : array_like, shape (3,)
            Q relative to F's origin [m], in F.
        relative_to : str
            A, the frame it is seen from.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        ndarray, shape (3,)
            p_AQ_E [m].
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.point_position("arm", [1.0, 0, 0], "world", "world", np.pi / 2).round(12)
        array([0., 3., 0.])
        """
    def point_velocity(self, frame: str, p_FQ_F: numpy.typing.ArrayLike, v_FQ_F: numpy.typing.ArrayLike, relative_to: str, expressed_in: str, t: float) -> PointVelocity:
        """
        PointVelocity of Q seen from A, terms expressed in E. Q at p_FQ_F [m] moving with v_FQ_F [m/s] as
        seen from F (both (3,), expressed in F; zeros for a point fixed in F).
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        p_FQ_F : array_like, shape (3,)
            Q relative to F's origin [m], in F.
        v_FQ_F : array_like, shape (3,)
            Q's velocity seen from F [m/s], in F.
        relative_to : str
            A, the frame it is seen from.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        PointVelocity
            origin, rotational, relative and total [m/s], in E.
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.point_velocity("arm", [0, 0, 0], [0, 0, 0], "world", "world", 0.0).total
        array([0., 2., 0.])
        """
    def rotation(self, frame: str, relative_to: str, t: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        R_AF (3,3): maps `frame` F coordinates to `relative_to` A coordinates at t.
        
        Parameters
        ----------
        frame : str
            F, the frame queried.
        relative_to : str
            A, the frame it is seen from.
        t : float
            Time [s].
        
        Returns
        -------
        ndarray, shape (3, 3)
            R_AF.
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> bool(np.allclose(tree.rotation("arm", "world", np.pi / 2), rd.rot_z(np.pi / 2)))
        True
        """
    def set_parent(self, name: str, parent: str, motion: FrameMotion) -> None:
        """
        Moves frame `name` and its subtree under `parent`, placed by `motion`. ValueError if that would
        make a cycle (parent is `name` or one of its descendants) or `name` is 'world'.
        
        Parameters
        ----------
        name : str
            The frame to move.
        parent : str
            Its new parent.
        motion : FrameMotion
            How it moves relative to the new parent.
        
        Examples
        --------
        >>> tree = rd.FrameTree([("a", "world", rd.FrameMotion.fixed()), ("b", "world", rd.FrameMotion.fixed())])
        >>> tree.set_parent("b", "a", rd.FrameMotion.fixed())
        >>> tree.parent("b")
        'a'
        """
    def transport_derivative(self, u_E: numpy.typing.ArrayLike, du_B_E: numpy.typing.ArrayLike, from_frame: str, to_frame: str, expressed_in: str, t: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        Transport theorem (Craig's "Rigid Body Dynamics" slides): the derivative of u seen from
        A = `to_frame`, from its derivative du_B_E seen from B = `from_frame`: du_B_E + w_AB x u_E. u_E,
        du_B_E and the result (3,) in E.
        
        Parameters
        ----------
        u_E : array_like, shape (3,)
            The vector u (any unit), in E.
        du_B_E : array_like, shape (3,)
            Its derivative seen from B [unit of u / s], in E.
        from_frame : str
            B.
        to_frame : str
            A.
        expressed_in : str
            E, the frame the result is expressed in.
        t : float
            Time [s].
        
        Returns
        -------
        ndarray, shape (3,)
            The derivative of u seen from A [unit of u / s], in E.
        
        Raises
        ------
        ValueError
            An unknown frame name, or a value of a user motion that is not finite or not a rotation (naming
            the frame).
        
        Examples
        --------
        An arm 2 m out on a table turning at 1 rad/s about z:
        
        >>> tree = rd.FrameTree([("table", "world", rd.FrameMotion.constant_rotation([0, 0, 1], 1.0)),
        ...                      ("arm", "table", rd.FrameMotion.fixed(p_PF_P=[2.0, 0, 0]))])
        >>> tree.transport_derivative([1.0, 0, 0], [0, 0, 0], "table", "world", "world", 0.0)
        array([0., 1., 0.])
        """
class Force:
    """
    Spatial force vector (wrench) F = [n; f], angular part first.
    
    n is the moment [N m] about the origin of the frame of expression and f the force [N], both expressed in
    that frame: Featherstone's convention ("Rigid Body Dynamics Algorithms"), moment first as in
    MuJoCo and Drake. The order matters only at to_vector / from_vector.
    
    Parameters
    ----------
    angular : array_like, shape (3,), optional
        n [N m] about the frame's origin (None: zero).
    linear : array_like, shape (3,), optional
        f [N] (None: zero).
    
    Raises
    ------
    ValueError
        A part of another shape or non-finite (the message names it).
    
    See Also
    --------
    Motion, Transform, force_cross_matrix
    
    Examples
    --------
    A force f = (0, 1, 0) [N] through (1, 0, 0) [m], moved to the origin, has the moment p x f:
    
    >>> F = rd.Transform(translation=[1.0, 0.0, 0.0]).act(rd.Force(linear=[0.0, 1.0, 0.0]))
    >>> F.to_vector()
    array([0., 0., 1., 0., 1., 0.])
    
    Immutable; supports +, -, scalar *; pickles; == compares exactly.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_vector(vector: numpy.typing.ArrayLike) -> Force:
        """
        Force from a (6,) array [n; f], moment first ([N m], [N]); ValueError on another shape or NaN/Inf.
        
        Parameters
        ----------
        vector : array_like, shape (6,)
            [n; f] ([N m], [N]).
        
        Returns
        -------
        Force
        
        Examples
        --------
        >>> rd.Force.from_vector([0.0, 0.0, 1.0, 0.0, 2.0, 0.0]).angular
        array([0., 0., 1.])
        """
    def __add__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of the angular and linear parts.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, angular: numpy.typing.ArrayLike | None = None, linear: numpy.typing.ArrayLike | None = None) -> None:
        """
        Force from n (3,) [N m] and f (3,) [N] in one frame (None: zero); see the class.
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
    def dot(self, motion: Motion) -> float:
        """
        Power w . n + v . f [W] of this force on the motion (same frame and reference point).
        
        Parameters
        ----------
        motion : Motion
            [w; v] ([rad/s], [m/s]), in this force's frame.
        
        Returns
        -------
        float
            The power [W], the same in every frame.
        
        Examples
        --------
        >>> rd.Force([0.0, 0.0, 2.0], [3.0, 0.0, 0.0]).dot(rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]))
        5.0
        """
    def is_approx(self, other: Force, prec: float = 1e-12) -> bool:
        """
        True when the 6-vectors agree to `prec` relative to the smaller norm (Eigen's isApprox: |a - b| <=
        prec min(|a|, |b|), so only an exactly zero Force is close to zero). == compares exactly.
        
        Parameters
        ----------
        other : Force
            In the same frame.
        prec : float, default 1e-12
            Relative tolerance, >= 0.
        
        Returns
        -------
        bool
        
        Raises
        ------
        TypeError
            other not a Force.
        ValueError
            prec negative or not finite.
        
        Examples
        --------
        >>> rd.Force([1.0, 0.0, 0.0]).is_approx(rd.Force([1.0 + 1e-14, 0.0, 0.0]))
        True
        """
    def to_vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        [n; f] as a (6,) array, moment first ([N m], [N]), in the force's frame.
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
    Spatial motion vector (twist) V = [w; v], angular part first.
    
    w is the angular velocity [rad/s] and v the velocity [m/s] of the body point at the origin of the frame
    of expression, both expressed in that frame: Plücker coordinates in Featherstone's convention ("Rigid
    Body Dynamics Algorithms"), the order of MuJoCo, Drake and RigidBodyDynamics.jl (Pinocchio puts
    the linear part first). The order matters only at to_vector / from_vector.
    
    Parameters
    ----------
    angular : array_like, shape (3,), optional
        w [rad/s] (None: zero).
    linear : array_like, shape (3,), optional
        v [m/s] of the body point at the frame's origin (None: zero).
    
    Raises
    ------
    ValueError
        A part of another shape or non-finite (the message names it).
    
    See Also
    --------
    Force, Transform, motion_cross_matrix, twist_to_screw
    
    Examples
    --------
    The power w . n + v . f of a force on a motion is the same in every frame:
    
    >>> V = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    >>> V.to_vector()
    array([0., 0., 1., 1., 0., 0.])
    >>> F = rd.Force([0.0, 0.0, 2.0], [0.0, 3.0, 0.0])
    >>> X = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])
    >>> V.dot(F), bool(np.isclose(X.act(V).dot(X.act(F)), V.dot(F)))
    (2.0, True)
    
    Immutable; supports +, -, scalar *; pickles; == compares exactly.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_vector(vector: numpy.typing.ArrayLike) -> Motion:
        """
        Motion from a (6,) array [w; v], angular first ([rad/s], [m/s]); ValueError on another shape or NaN/Inf.
        
        Parameters
        ----------
        vector : array_like, shape (6,)
            [w; v] ([rad/s], [m/s]).
        
        Returns
        -------
        Motion
        
        Examples
        --------
        >>> rd.Motion.from_vector([0.0, 0.0, 1.0, 1.0, 0.0, 0.0]).linear
        array([1., 0., 0.])
        """
    def __add__(self, arg0: typing.Any) -> typing.Any:
        ...
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of the angular and linear parts.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, angular: numpy.typing.ArrayLike | None = None, linear: numpy.typing.ArrayLike | None = None) -> None:
        """
        Motion from w (3,) [rad/s] and v (3,) [m/s] in one frame (None: zero); see the class.
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
    def cross(self, other: Motion) -> Motion:
        """
        Motion cross product (crm): self x other = [w1 x w2; w1 x v2 + v1 x w2], in the common frame
        ([rad/s^2], [m/s^2] for two twists).
        
        Parameters
        ----------
        other : Motion
            In the same frame.
        
        Returns
        -------
        Motion
        
        Examples
        --------
        >>> rd.Motion([0.0, 0.0, 1.0]).cross(rd.Motion(linear=[1.0, 0.0, 0.0])).linear
        array([0., 1., 0.])
        """
    def cross_force(self, force: Force) -> Force:
        """
        Force cross product (crf): self x* force = [w x n + v x f; w x f] ([N m/s], [N/s]), in the common frame.
        
        Parameters
        ----------
        force : Force
            In this motion's frame.
        
        Returns
        -------
        Force
        
        Examples
        --------
        >>> rd.Motion([0.0, 0.0, 1.0]).cross_force(rd.Force(linear=[1.0, 0.0, 0.0])).linear
        array([0., 1., 0.])
        """
    def dot(self, force: Force) -> float:
        """
        Power w . n + v . f [W] of the force on this motion (same frame and reference point).
        
        Parameters
        ----------
        force : Force
            [n; f] ([N m], [N]), in this motion's frame.
        
        Returns
        -------
        float
            The power [W], the same in every frame.
        
        Examples
        --------
        >>> rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).dot(rd.Force([0.0, 0.0, 2.0], [3.0, 0.0, 0.0]))
        5.0
        """
    def is_approx(self, other: Motion, prec: float = 1e-12) -> bool:
        """
        True when the 6-vectors agree to `prec` relative to the smaller norm (Eigen's isApprox: |a - b| <=
        prec min(|a|, |b|), so only an exactly zero Motion is close to zero). == compares exactly.
        
        Parameters
        ----------
        other : Motion
            In the same frame.
        prec : float, default 1e-12
            Relative tolerance, >= 0.
        
        Returns
        -------
        bool
        
        Raises
        ------
        TypeError
            other not a Motion.
        ValueError
            prec negative or not finite.
        
        Examples
        --------
        >>> rd.Motion([1.0, 0.0, 0.0]).is_approx(rd.Motion([1.0 + 1e-14, 0.0, 0.0]))
        True
        """
    def to_vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        [w; v] as a (6,) array, angular first ([rad/s], [m/s]), in the motion's frame.
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
    Rigid transform X_AB: R_AB (B coordinates -> A coordinates) and p_AB (B's origin in A) [m].
    
    Maps points (p_A = R_AB p_B + p_AB), motions and forces expressed in B to A; X_AB * X_BC = X_AC. On
    spatial vectors (angular part first) it is Featherstone's X (motion_matrix) and X* (force_matrix).
    
    Parameters
    ----------
    rotation : array_like, shape (3, 3), optional
        R_AB, orthonormal with det +1 (None: identity).
    translation : array_like, shape (3,), optional
        p_AB [m], B's origin in A (None: zero).
    
    Raises
    ------
    ValueError
        A non-rotation or non-finite input (the message names it).
    
    See Also
    --------
    transform_compose, transform_points, Motion, Force
    
    Examples
    --------
    B turned a quarter turn about z, its origin at (1, 0, 0) in A:
    
    >>> X_AB = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])
    >>> X_AB.act_point([1.0, 0.0, 0.0]).round(12)
    array([1., 1., 0.])
    >>> (X_AB * X_AB.inverse()).is_approx(rd.Transform())
    True
    
    Immutable; pickles; == compares exactly.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_quat(q_AB: numpy.typing.ArrayLike, translation: numpy.typing.ArrayLike | None = None, scalar_first: bool = False) -> Transform:
        """
        X_AB from a unit quaternion and a translation.
        
        Parameters
        ----------
        q_AB : array_like, shape (4,)
            Unit quaternion B -> A, (x, y, z, w), or (w, x, y, z) if `scalar_first`.
        translation : array_like, shape (3,), optional
            p_AB [m], B's origin in A (None: zero).
        scalar_first : bool, default False
            Read q_AB scalar first.
        
        Returns
        -------
        Transform
            X_AB.
        
        Raises
        ------
        ValueError
            A quaternion not of unit norm, or a non-finite or badly shaped argument (naming it).
        
        Examples
        --------
        >>> X = rd.Transform.from_quat([0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)], [1.0, 0.0, 0.0])
        >>> X.is_approx(rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]))
        True
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of rotation and translation.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, rotation: numpy.typing.ArrayLike | None = None, translation: numpy.typing.ArrayLike | None = None) -> None:
        """
        X_AB from rotation R_AB (3,3), orthonormal with det +1 (default identity), and translation
        p_AB (3,) [m] (default zero); see the class. ValueError on a non-rotation or non-finite input.
        """
    def __mul__(self, arg0: typing.Any) -> typing.Any:
        """
        X_AB * X_BC = X_AC.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def act(self, spatial_vector: Motion | Force) -> typing.Any:
        """
        Express a spatial vector given in B in A (Featherstone's X for a Motion, X* for a Force).
        
        A Motion in B -> in A: [R w; R v + p x (R w)]; a Force in B -> in A: [R n + p x (R f); R f]
        (R = R_AB, p = p_AB, angular part first).
        
        Parameters
        ----------
        spatial_vector : Motion or Force
            Expressed in B (a Force's moment about B's origin).
        
        Returns
        -------
        Motion or Force
            The same vector expressed in A (about A's origin).
        
        Raises
        ------
        TypeError
            spatial_vector neither a Motion nor a Force.
        
        Examples
        --------
        >>> rd.Transform(translation=[1.0, 0.0, 0.0]).act(rd.Force(linear=[0.0, 1.0, 0.0])).angular
        array([0., 0., 1.])
        """
    def act_inv(self, spatial_vector: Motion | Force) -> typing.Any:
        """
        Express a spatial vector given in A in B, the inverse of act.
        
        A Motion in A -> in B: [R^T w; R^T (v - p x w)]; a Force in A -> in B: [R^T (n - p x f); R^T f]
        (R = R_AB, p = p_AB, angular part first).
        
        Parameters
        ----------
        spatial_vector : Motion or Force
            Expressed in A.
        
        Returns
        -------
        Motion or Force
            The same vector expressed in B.
        
        Raises
        ------
        TypeError
            spatial_vector neither a Motion nor a Force.
        
        Examples
        --------
        >>> X, V = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]), rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
        >>> X.act_inv(X.act(V)).is_approx(V)
        True
        """
    def act_inv_point(self, p_A: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        Map points from A to B: p_B = R_AB^T (p_A - p_AB), the inverse of act_point.
        
        Parameters
        ----------
        p_A : array_like, shape (3,) or (n, 3)
            Points in A [m].
        
        Returns
        -------
        ndarray, shape (3,) or (n, 3)
            p_B, the points in B [m].
        
        Examples
        --------
        >>> X = rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0])
        >>> X.act_inv_point(X.act_point([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])).round(12)
        array([[1., 2., 3.],
               [4., 5., 6.]])
        """
    def act_point(self, p_B: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        Map points from B to A: p_A = R_AB p_B + p_AB.
        
        Parameters
        ----------
        p_B : array_like, shape (3,) or (n, 3)
            Points in B [m].
        
        Returns
        -------
        ndarray, shape (3,) or (n, 3)
            p_A, the points in A [m].
        
        Examples
        --------
        >>> rd.Transform(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0]).act_point([1.0, 0.0, 0.0]).round(12)
        array([1., 1., 0.])
        """
    def force_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Featherstone's X* (6,6) = X^-T: [[R, hat(p) R], [0, R]].
        """
    def inverse(self) -> Transform:
        """
        X_BA = X_AB^-1: R_BA = R_AB^T, p_BA = -R_AB^T p_AB [m].
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
    def quat(self, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        The rotation R_AB as a unit quaternion q_AB.
        
        Parameters
        ----------
        scalar_first : bool, default False
            Return (w, x, y, z) instead of (x, y, z, w).
        
        Returns
        -------
        ndarray, shape (4,)
            q_AB with w >= 0.
        
        Examples
        --------
        >>> rd.Transform(rd.rot_z(np.pi / 2)).quat(scalar_first=True).round(12)
        array([0.70710678, 0.        , 0.        , 0.70710678])
        """
    @property
    def rotation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        R_AB (3,3): maps B coordinates to A coordinates; read-only copy
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        p_AB (3,) [m]: B's origin relative to A's, expressed in A; read-only copy
        """
class Screw:
    """
    Screw of a twist (instantaneous screw axis), all in the twist's frame.
    
    A unit direction, the point of the axis closest to the origin [m], the pitch [m/rad] (inf for a pure
    translation) and the magnitude (|w| [rad/s], or |v| [m/s] for a pure translation): the twist turns at
    `magnitude` about the axis while it slides along it at pitch times that.
    
    Parameters
    ----------
    direction : array_like, shape (3,)
        Unit axis direction (checked by screw_to_twist).
    point : array_like, shape (3,)
        A point of the axis [m].
    pitch : float
        Translation per turn angle [m/rad]; inf for a pure translation.
    magnitude : float
        |w| [rad/s] (or |v| [m/s] for pitch inf).
    
    See Also
    --------
    twist_to_screw, screw_to_twist, Motion
    
    Examples
    --------
    >>> s = rd.Screw([0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], 0.25, 2.0)
    >>> rd.screw_to_twist(s).to_vector()
    array([0. , 0. , 2. , 0. , 2. , 0.5])
    
    Immutable; pickles; == compares every part exactly.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every part.
        """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], float, float]:
        ...
    def __init__(self, direction: numpy.typing.ArrayLike, point: numpy.typing.ArrayLike, pitch: float, magnitude: float) -> None:
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
        Unit axis direction (3,), expressed in the twist's frame.
        """
    @property
    def magnitude(self) -> float:
        """
        Magnitude |w| [rad/s], or |v| [m/s] for a pure translation.
        """
    @property
    def pitch(self) -> float:
        """
        Pitch [m/rad] along the axis; inf for a pure translation.
        """
    @property
    def point(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) [m], the point of the axis closest to the twist's frame's origin, expressed in that frame
        """
class InertiaCheck:
    """
    What a constructor requires of a rotational inertia.
    
    `physical`: symmetric, positive semi-definite and the triangle inequality I0 + I1 >= I2 on the
    principal moments (every real body). `allow_unrealizable`: symmetric positive semi-definite only; a
    documented opt-in for test problems such as Hairer-Lubich-Wanner's I = diag(2, 1, 2/3), never the
    default.
    
    Parameters
    ----------
    value : int
        0 (physical) or 1 (allow_unrealizable); TypeError otherwise.
    
    See Also
    --------
    SpatialInertia, inertia_report
    
    Examples
    --------
    >>> I = np.diag([2.0, 1.0, 2 / 3])
    >>> rd.SpatialInertia(1.0, [0, 0, 0], I, check=rd.InertiaCheck.allow_unrealizable).mass
    1.0
    >>> rd.InertiaCheck(0)
    <InertiaCheck.physical: 0>
    
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
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
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
    Validity report of a mass and a rotational inertia about the centre of mass.
    
    Made by inertia_report and SpatialInertia.report; == compares every field; it pickles.
    
    Parameters
    ----------
    mass, inertia_com, scale
        As inertia_report (there is no constructor from Python).
    
    See Also
    --------
    inertia_report, nearest_valid_inertia
    
    Examples
    --------
    >>> r = rd.solid_box([1.0, 1.0, 1.0], mass=12.0).report()
    >>> r.valid(), r.principal_moments.round(12), r.condition_number
    (True, array([2., 2., 2.]), 1.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: InertiaReport has no public constructor: inertia_report and SpatialInertia.report return one.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def summary(self) -> str:
        """
        One line with the principal moments and triangle margins [kg m^2], condition number, tolerance
        [kg m^2] and verdict.
        """
    def valid(self, check: InertiaCheck = InertiaCheck.physical) -> bool:
        """
        Whether every check required by `check` passes.
        
        Parameters
        ----------
        check : InertiaCheck, default InertiaCheck.physical
            physical: mass, finite, symmetric, PSD and triangle inequality; allow_unrealizable: all but
            the last.
        
        Returns
        -------
        bool
        """
    @property
    def asymmetry(self) -> float:
        """
        Largest asymmetry max |I - I^T| [kg m^2] of the inertia about the centre of mass.
        """
    @property
    def asymmetry_tolerance(self) -> float:
        """
        Largest asymmetry accepted, 1e-12 max |I_ij| [kg m^2].
        """
    @property
    def condition_number(self) -> float:
        """
        Condition number I2 / I0 of the principal moments, dimensionless (inf when I0 <= 0).
        """
    @property
    def finite(self) -> bool:
        """
        Whether every entry of the inertia is finite.
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
    @property
    def mass_positive(self) -> bool:
        """
        Whether the mass is finite and > 0.
        """
    @property
    def positive_semidefinite(self) -> bool:
        """
        Whether I0 >= -tolerance (the inertia is positive semi-definite).
        """
    @property
    def principal_moments(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Principal moments (3,) ascending I0 <= I1 <= I2 [kg m^2] of the inertia about the
        centre of mass (its symmetric part), read-only.
        """
    @property
    def symmetric(self) -> bool:
        """
        Whether asymmetry <= asymmetry_tolerance.
        """
    @property
    def tolerance(self) -> float:
        """
        Absolute tolerance [kg m^2] of the positive semi-definite and triangle-inequality checks.
        """
    @property
    def triangle_inequality(self) -> bool:
        """
        Whether I0 + I1 - I2 >= -tolerance (the triangle inequality on the principal moments).
        """
    @property
    def triangle_margins(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Triangle margins (3,) (I1+I2-I0, I0+I2-I1, I0+I1-I2) [kg m^2]; the last is binding;
        read-only.
        """
class PrincipalAxes:
    """
    Principal moments and axes of a rotational inertia (Craig, "Principal Axes").
    
    In the frame the inertia is expressed in: moments ascending [kg m^2], axes as columns (column k is
    the unit axis of moments[k]; right-handed, det +1), so that I = axes @ diag(moments) @ axes.T. For a
    stack of n inertias, arrays (n, 3) and (n, 3, 3). Unpacks as ``moments, axes = principal_axes(I)``.
    
    Parameters
    ----------
    moments : array_like, shape (3,) or (n, 3)
        Principal moments [kg m^2]; copied, read-only.
    axes : array_like, shape (3, 3) or (n, 3, 3)
        Unit axes as columns; copied, read-only.
    
    Raises
    ------
    ValueError
        Shapes that do not match (the message names `axes`).
    
    See Also
    --------
    principal_axes, SpatialInertia.principal_axes
    
    Examples
    --------
    >>> p = rd.solid_box([1.0, 2.0, 3.0], mass=12.0).principal_axes()
    >>> moments, axes = p
    >>> moments
    array([ 5., 10., 13.])
    >>> np.allclose(axes @ np.diag(moments) @ axes.T, np.diag([13.0, 10.0, 5.0]))
    True
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
    def __init__(self, moments: numpy.typing.ArrayLike, axes: numpy.typing.ArrayLike) -> None:
        """
        From moments (3,) [kg m^2] and axes (3,3) (or (n,3), (n,3,3)); copied, read-only; see the class.
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
        Principal axes (3,3) or (n,3,3): column k is the unit axis of moments[k], expressed in the
        inertia's frame; det +1. Read-only.
        """
    @property
    def moments(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Principal moments (3,) or (n, 3), ascending [kg m^2], read-only.
        """
class SpatialInertia:
    """
    Mass properties of one rigid body: mass, centre of mass and rotational inertia about it.
    
    Mass m [kg], centre of mass c [m] and rotational inertia I_C [kg m^2] about the centre of mass, all
    expressed in one frame (moments on the diagonal of I_C, negated products off it). Constructors check
    validity. + composes two bodies in one frame, - removes a part (a hole); == compares exactly.
    
    Parameters
    ----------
    mass : float
        Mass m [kg], finite and > 0.
    com : array_like, shape (3,)
        Centre of mass c [m].
    inertia_com : array_like, shape (3, 3)
        Rotational inertia about the centre of mass [kg m^2].
    check : InertiaCheck, default InertiaCheck.physical
        InertiaCheck.physical (triangle inequality required) or InertiaCheck.allow_unrealizable (opt-in:
        symmetric PSD only, e.g. I = diag(2, 1, 2/3)).
    
    Raises
    ------
    ValueError
        A mass not finite and > 0, a non-finite com, or an inertia that fails `check` (the message gives
        its principal moments, triangle margins and condition number).
    
    See Also
    --------
    inertia_report, composite, solid_box, from_point_masses
    
    Examples
    --------
    The parallel-axis theorem: a 2 kg sphere of radius 0.5 m centred 1 m from the origin along x has,
    about the origin, I = 2/5 m r^2 + m d^2 = 0.2 + 2 = 2.2 kg m^2 about the axes across the offset:
    
    >>> body = rd.SpatialInertia(2.0, [1.0, 0.0, 0.0], 0.2 * np.eye(3))
    >>> body.inertia_about_origin().diagonal().round(12)
    array([0.2, 2.2, 2.2])
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def from_inertia_about_origin(mass: float, com: numpy.typing.ArrayLike, inertia_about_origin: numpy.typing.ArrayLike, check: InertiaCheck = InertiaCheck.physical) -> SpatialInertia:
        """
        From the inertia about the frame's origin (parallel-axis theorem, Craig).
        
        Parameters
        ----------
        mass : float
            Mass m [kg], finite and > 0.
        com : array_like, shape (3,)
            Centre of mass c [m].
        inertia_about_origin : array_like, shape (3, 3)
            Rotational inertia I_O about the origin [kg m^2].
        check : InertiaCheck, default InertiaCheck.physical
            What I_C must satisfy, as the constructor.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        >>> body = rd.SpatialInertia.from_inertia_about_origin(3.0, [0, 0, 1.0], np.diag([4.0, 4.0, 0.0]))
        >>> body.inertia_com.diagonal()
        array([1., 1., 0.])
        """
    @staticmethod
    def from_inertia_about_point(mass: float, com: numpy.typing.ArrayLike, inertia_about_point: numpy.typing.ArrayLike, point: numpy.typing.ArrayLike, check: InertiaCheck = InertiaCheck.physical) -> SpatialInertia:
        """
        From the inertia about a point (parallel-axis theorem, Craig).
        
        I_C = I_P - m (|r|^2 1 - r r^T), r = c - p, all in one frame.
        
        Parameters
        ----------
        mass : float
            Mass m [kg], finite and > 0.
        com : array_like, shape (3,)
            Centre of mass c [m].
        inertia_about_point : array_like, shape (3, 3)
            Rotational inertia I_P about `point` [kg m^2].
        point : array_like, shape (3,)
            The point p [m].
        check : InertiaCheck, default InertiaCheck.physical
            What I_C must satisfy, as the constructor.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        A 3 kg rod of length 2 m along z has m L^2/3 = 4 kg m^2 about its end, m L^2/12 = 1 kg m^2 about its
        centre:
        
        >>> rd.SpatialInertia.from_inertia_about_point(3.0, [0, 0, 1.0], np.diag([4.0, 4.0, 0.0]),
        ...                                            [0, 0, 2.0]).inertia_com.diagonal()
        array([1., 1., 0.])
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, check: InertiaCheck = InertiaCheck.physical) -> SpatialInertia:
        """
        From the (6, 6) spatial inertia about the origin.
        
        Angular first: [[I_O, m hat(c)], [m hat(c)^T, m 1]] (I_O [kg m^2], m hat(c) [kg m], m [kg]).
        
        Parameters
        ----------
        matrix : array_like, shape (6, 6)
            The spatial inertia about the frame's origin.
        check : InertiaCheck, default InertiaCheck.physical
            What I_C must satisfy, as the constructor.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        >>> body = rd.solid_box([1.0, 2.0, 3.0], mass=12.0).transformed(rd.Transform(translation=[1.0, 0, 0]))
        >>> rd.SpatialInertia.from_matrix(body.matrix()).is_approx(body)
        True
        """
    @staticmethod
    def point_mass(mass: float, position: numpy.typing.ArrayLike) -> SpatialInertia:
        """
        A point mass (zero inertia about its centre of mass).
        
        Parameters
        ----------
        mass : float
            Mass [kg], finite and > 0.
        position : array_like, shape (3,)
            Its position [m], which becomes the centre of mass.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        >>> rd.SpatialInertia.point_mass(2.0, [1.0, 0, 0]).inertia_about_origin().diagonal()
        array([0., 2., 2.])
        """
    def __add__(self, arg0: SpatialInertia) -> SpatialInertia:
        """
        Composite of two bodies expressed in the same frame (ValueError naming the distance between the centres of mass
        where the sum's inertia would overflow: some 1e150 m or more).
        """
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of mass, com and inertia_com (is_approx: up to a tolerance).
        """
    def __getstate__(self) -> tuple[float, numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, mass: float, com: numpy.typing.ArrayLike, inertia_com: numpy.typing.ArrayLike, check: InertiaCheck = InertiaCheck.physical) -> None:
        """
        From mass [kg] > 0, com (3,) [m] and inertia_com (3,3) [kg m^2] about the centre of mass, checked
        as `check` requires (InertiaCheck.physical by default); see the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def __sub__(self, arg0: SpatialInertia) -> SpatialInertia:
        """
        This body with the part removed (a hole); ValueError if the rest is invalid.
        """
    def admits_symmetry_plane(self, normal: numpy.typing.ArrayLike, tolerance: float = 1e-09) -> bool:
        """
        Whether the plane through the centre of mass with this normal (3,) can be a plane of symmetry
        (Craig: then the products of inertia with the normal vanish). Necessary, not sufficient.
        
        Parameters
        ----------
        normal : array_like, shape (3,)
            The plane's normal, in the frame of expression.
        tolerance : float, default 1e-9
            Relative tolerance, >= 0.
        
        Returns
        -------
        bool
        
        Examples
        --------
        >>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)
        >>> box.admits_symmetry_plane([1.0, 0, 0]), box.admits_symmetry_plane([1.0, 1.0, 0])
        (True, False)
        """
    def angular_momentum_about_com(self, angular_velocity: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular momentum about the centre of mass, H_C = I_C w.
        
        Parameters
        ----------
        angular_velocity : array_like, shape (3,)
            w [rad/s], in the frame of expression.
        
        Returns
        -------
        ndarray, shape (3,)
            H_C [kg m^2/s], in the same frame.
        
        Examples
        --------
        >>> rd.solid_sphere(1.0, mass=5.0).angular_momentum_about_com([0, 0, 2.0])
        array([0., 0., 4.])
        """
    def angular_momentum_about_point(self, angular_velocity: numpy.typing.ArrayLike, com_velocity: numpy.typing.ArrayLike, point: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular momentum about a point, H_P = r_PC x (m v_C) + H_C (Craig).
        
        Parameters
        ----------
        angular_velocity : array_like, shape (3,)
            w [rad/s].
        com_velocity : array_like, shape (3,)
            Velocity of the centre of mass v_C [m/s].
        point : array_like, shape (3,)
            The point P [m]; r_PC = c - p.
        
        Returns
        -------
        ndarray, shape (3,)
            H_P [kg m^2/s]; all vectors in the frame of expression.
        
        Examples
        --------
        >>> rd.solid_sphere(1.0, mass=5.0).angular_momentum_about_point([0, 0, 0], [1.0, 0, 0], [0, -1.0, 0])
        array([ 0.,  0., -5.])
        """
    def inertia_about_origin(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Rotational inertia (3,3) [kg m^2] about the frame's origin, in that frame: I_C + m (|c|^2 1 - c c^T).
        """
    def inertia_about_point(self, point: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        Rotational inertia about a point (parallel-axis theorem, Craig).
        
        I_P = I_C + m (|r|^2 1 - r r^T), r = c - p, in the frame of expression.
        
        Parameters
        ----------
        point : array_like, shape (3,)
            The point p [m].
        
        Returns
        -------
        ndarray, shape (3, 3)
            I_P [kg m^2].
        
        Examples
        --------
        A 5 kg ball of radius 1 m about a point of its surface: 2/5 m r^2 + m r^2 = 7 kg m^2 across:
        
        >>> rd.solid_sphere(1.0, mass=5.0).inertia_about_point([1.0, 0, 0]).diagonal()
        array([2., 7., 7.])
        """
    def is_approx(self, other: SpatialInertia, prec: float = 1e-12) -> bool:
        """
        True when mass, centre of mass and inertia_com agree to `prec` relative to their size (the centre of
        mass relative to the radius of gyration plus |com|). == compares exactly.
        
        Parameters
        ----------
        other : SpatialInertia
            The body to compare, in the same frame.
        prec : float, default 1e-12
            Relative tolerance, >= 0.
        
        Returns
        -------
        bool
        
        Examples
        --------
        >>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)
        >>> other = rd.solid_box([1.0, 2.0, 3.0 + 1e-14], mass=12.0)
        >>> box.is_approx(other), box == other
        (True, False)
        """
    def kinetic_energy(self, twist: Motion) -> float:
        """
        Kinetic energy T = 1/2 V . I V of a twist.
        
        Parameters
        ----------
        twist : Motion
            V = [w; v_O] [rad/s, m/s], as in momentum.
        
        Returns
        -------
        float
            T [J].
        
        Examples
        --------
        >>> ball = rd.solid_sphere(1.0, mass=5.0)  # I = 2 kg m^2
        >>> spin, slide = rd.Motion(angular=[0, 0, 2.0]), rd.Motion(linear=[3.0, 0, 0])
        >>> ball.kinetic_energy(spin), ball.kinetic_energy(slide)  # 1/2 I w^2, 1/2 m v^2
        (4.0, 22.5)
        """
    def matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Spatial inertia (6,6) about the frame's origin, angular first: [[I_O, m hat(c)], [m hat(c)^T, m 1]]
        (I_O [kg m^2], m [kg]).
        """
    def momentum(self, twist: Motion) -> Force:
        """
        Spatial momentum h = I V of a twist, about the frame's origin.
        
        Parameters
        ----------
        twist : Motion
            V = [w; v_O]: angular velocity w [rad/s] and velocity v_O [m/s] of the body point at the origin,
            in the frame of expression.
        
        Returns
        -------
        Force
            h = [moment of momentum about the origin [kg m^2/s]; linear momentum [kg m/s]].
        
        Examples
        --------
        >>> rd.solid_sphere(1.0, mass=5.0).momentum(rd.Motion(linear=[3.0, 0, 0])).linear  # m v
        array([15.,  0.,  0.])
        """
    def principal_axes(self) -> PrincipalAxes:
        """
        PrincipalAxes of I_C (about the centre of mass, in the frame of expression): moments ascending
        [kg m^2], axes as columns, right-handed.
        """
    def remove(self, part: SpatialInertia, check: InertiaCheck = InertiaCheck.physical) -> SpatialInertia:
        """
        This body with `part` removed (a hole), checked as the constructor.
        
        Parameters
        ----------
        part : SpatialInertia
            The removed part, in the same frame.
        check : InertiaCheck, default InertiaCheck.physical
            What the rest's I_C must satisfy.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        >>> ball, core = rd.solid_sphere(2.0, density=1.0), rd.solid_sphere(1.0, density=1.0)
        >>> ball.remove(core).is_approx(rd.hollow_sphere(2.0, 1.0, density=1.0))
        True
        """
    def report(self) -> InertiaReport:
        """
        The validity report (InertiaReport) of the mass [kg] and I_C [kg m^2].
        """
    def rotated(self, R_AB: numpy.typing.ArrayLike) -> SpatialInertia:
        """
        The same body re-expressed in frame A: c_A = R_AB c_B, I_C,A = R_AB I_C,B R_AB^T.
        
        Parameters
        ----------
        R_AB : array_like, shape (3, 3)
            Rotation taking B (this body's frame) coordinates to A coordinates.
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        A quarter turn about z swaps the x and y moments:
        
        >>> box = rd.solid_box([1.0, 2.0, 3.0], mass=12.0)
        >>> box.rotated(rd.rot_z(np.pi / 2)).inertia_com.diagonal().round(12)
        array([10., 13.,  5.])
        """
    def transformed(self, X_AB: Transform) -> SpatialInertia:
        """
        The same body re-expressed in frame A: c_A = R_AB c_B + p_AB, I_C,A = R_AB I_C,B R_AB^T.
        
        Parameters
        ----------
        X_AB : Transform
            Pose of B (this body's frame) in A, p_AB [m].
        
        Returns
        -------
        SpatialInertia
        
        Examples
        --------
        >>> rd.solid_box([1.0, 2.0, 3.0], mass=12.0).transformed(rd.Transform(translation=[1.0, 0, 0])).com
        array([1., 0., 0.])
        """
    @property
    def com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass c (3,) [m] in the frame of expression, a read-only copy.
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Rotational inertia I_C (3,3) [kg m^2] about the centre of mass in the frame of
        expression, a read-only copy.
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
class MeshWeldWarning(UserWarning):
    """
    Warned by solid_mesh and mesh_shell when welding merged vertices or dropped faces (a UserWarning;
    filter it with warnings.filterwarnings, or weld with weld_vertices first).
    """
class WeldedMesh:
    """
    A mesh after weld_vertices, with what the weld changed.
    
    Parameters
    ----------
    vertices, faces, tolerance
        As weld_vertices (there is no constructor from Python; it pickles).
    
    See Also
    --------
    weld_vertices, solid_mesh
    
    Examples
    --------
    >>> w = rd.weld_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
    ...                      [[0, 1, 2], [3, 4, 5]])
    >>> w.vertex_index, w.dropped_faces
    (array([0, 1, 2, 4]), 0)
    """
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64], numpy.typing.NDArray[numpy.int64], int, int, float]:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: WeldedMesh has no public constructor: weld_vertices returns one.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def dropped_faces(self) -> int:
        """
        Number of faces dropped for repeating a vertex after welding.
        """
    @property
    def face_index(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        Input index (f',) int64 of each kept face.
        """
    @property
    def faces(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        Non-degenerate faces (f', 3) int64, in input order, indexing vertices.
        """
    @property
    def tolerance(self) -> float:
        """
        Weld tolerance used [m].
        """
    @property
    def vertex_index(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        Input index (n',) int64 of each kept vertex.
        """
    @property
    def vertices(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Kept vertices (n', 3) [m] (each cluster's lowest-indexed), in input order and frame,
        read-only.
        """
    @property
    def welded_vertices(self) -> int:
        """
        Number of input vertices merged into another.
        """
class DensityIntegral:
    """
    Result of a density quadrature with its error estimate.
    
    All in the frame A of the points rho was evaluated at. == compares every field exactly; it pickles.
    
    Parameters
    ----------
    inertia : SpatialInertia
        Result of the higher-order rule, in A.
    mass_error : float
        |m_high - m_low| [kg].
    com_error : float
        |c_high - c_low| [m].
    inertia_error : float
        ||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass.
    evaluations : int
        Points at which rho was evaluated, both rules together, >= 0.
    
    See Also
    --------
    integrate_density_over_box, integrate_density_over_mesh
    
    Examples
    --------
    >>> d = rd.integrate_density_over_box(lambda p: np.full(len(p), 1000.0), [0, 0, 0], [1, 1, 1])
    >>> f"{d.inertia.mass:.9f}", f"{d.inertia.inertia_com[0, 0]:.9f}", d.evaluations  # m a^2 / 6
    ('1000.000000000', '166.666666667', 15552)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Exact equality of every field.
        """
    def __getstate__(self) -> tuple[SpatialInertia, float, float, float, int]:
        ...
    def __init__(self, inertia: SpatialInertia, mass_error: float, com_error: float, inertia_error: float, evaluations: int) -> None:
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
        Centre-of-mass error estimate |c_high - c_low| [m], in the frame of the points.
        """
    @property
    def evaluations(self) -> int:
        """
        Number of points at which rho was evaluated (both rules).
        """
    @property
    def inertia(self) -> SpatialInertia:
        """
        SpatialInertia from the higher-order rule (mass [kg], centre of mass [m] and inertia about it
        [kg m^2], in the frame of the points).
        """
    @property
    def inertia_error(self) -> float:
        """
        Inertia error estimate ||I_C,high - I_C,low||_F [kg m^2], inertias about the centre of mass.
        """
    @property
    def mass_error(self) -> float:
        """
        Mass error estimate |m_high - m_low| [kg].
        """
class Particle:
    """
    A point mass (3 DOF).
    
    Newton's law for a point, m a_W = f_W + m g_W ("Rigid body kinematics and dynamics" notes, section 4.11); its
    state is a ParticleState (position and velocity in W). Immutable; pickles; == compares the mass.
    
    Parameters
    ----------
    mass : float or pint.Quantity
        Mass m [kg], finite and > 0 (a quantity is converted to kg).
    
    Raises
    ------
    ValueError
        A mass that is not a finite number > 0, or a quantity of another dimension (the message names mass).
    
    See Also
    --------
    ParticleState, PlanarBody, RigidBody, simulate, forward_dynamics
    
    Examples
    --------
    A force of 4 N on 2 kg accelerates it at 2 m/s^2:
    
    >>> p = rd.Particle(2.0)
    >>> rd.forward_dynamics(p, rd.ParticleState(), force=[0.0, 0.0, 4.0])
    array([0., 0., 2.])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float]:
        ...
    def __init__(self, mass: float | _Quantity) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
class PlanarBody:
    """
    A rigid body moving in the xy plane of W (3 DOF: x, y, theta).
    
    Plane kinetics (K. Craig, "Rigid Body Dynamics" slides): m a_W = f_W + m g_W in W's plane and
    I_zz alpha = tau_G about the z axis through the centre of mass G. Its state is a PlanarBodyState.
    Immutable; pickles; == compares mass and inertia_zz.
    
    Parameters
    ----------
    mass : float or pint.Quantity
        Mass m [kg], finite and > 0.
    inertia_zz : float or pint.Quantity
        Moment of inertia I_zz about the z axis through the centre of mass [kg m^2], finite and > 0.
    
    Raises
    ------
    ValueError
        A value that is not a finite number > 0, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    PlanarBodyState, PivotedPlanarBody, RigidBody, simulate
    
    Examples
    --------
    Spinning at 2 rad/s, I_zz = 0.5 kg m^2 holds 1/2 I_zz omega^2 = 1 J:
    
    >>> b = rd.PlanarBody(2.0, 0.5)
    >>> rd.kinetic_energy(b, rd.PlanarBodyState(omega=2.0)).rotational
    1.0
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, mass: float | _Quantity, inertia_zz: float | _Quantity) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def inertia_zz(self) -> float:
        """
        Moment of inertia I_zz about the z axis through the centre of mass G [kg m^2].
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
class RigidBody:
    """
    A spatial rigid body (6 DOF): mass and inertia about its centre of mass.
    
    Newton's law for the centre of mass in W and Euler's equations in the body frame B (origin at the centre
    of mass): m a_W = f_W + m g_W, I alpha_B + w_B x I w_B = tau_B. Its state is a RigidBodyState. Three forms:
    
    - ``RigidBody(mass, [I1, I2, I3])``: principal moments, the axes of B principal (inertia_com = diag(I1, I2, I3));
    - ``RigidBody(mass, inertia_com)``: a full (3, 3) inertia about the centre of mass in B, moments on the
      diagonal and negated products off it (I_xy = -sum x y dm);
    - ``RigidBody(spatial_inertia)``: a SpatialInertia: its mass and inertia about its centre of mass, B placed at
      the centre of mass with the SpatialInertia's axes.
    
    The inertia must be symmetric positive definite and is checked as every inertia of rigiddyn is
    (inertia_report). euler_form tells which form of Euler's equations it uses: 'spherical', 'principal' or
    'full'. Immutable; pickles (an unrealizable test body stays one); == compares mass and inertia_com.
    
    Parameters
    ----------
    mass : float, pint.Quantity or SpatialInertia
        Mass m [kg], finite and > 0; or a SpatialInertia alone (then inertia_com is None).
    inertia_com : array_like, shape (3,) or (3, 3), or pint.Quantity
        Principal moments [kg m^2], or the inertia matrix about the centre of mass in B [kg m^2] (an array
        quantity is converted). Required next to a mass; None next to a SpatialInertia.
    check : InertiaCheck or None, default None
        None or InertiaCheck.physical: the principal moments must also satisfy the triangle inequality
        I_a + I_b >= I_c. InertiaCheck.allow_unrealizable accepts test bodies no real body has, e.g.
        I = diag(2, 1, 2/3).
    
    Raises
    ------
    ValueError
        mass not a finite number > 0; inertia_com of another shape, not symmetric positive definite or (under
        the physical check) violating the triangle inequality; inertia_com next to a SpatialInertia; a quantity
        of another dimension. The message names the argument.
    TypeError
        inertia_com None next to a mass, or check not an InertiaCheck.
    
    See Also
    --------
    RigidBodyState, SpatialInertia, inertia_report, nearest_valid_inertia, PivotedBody, Gyrostat, simulate
    
    Examples
    --------
    >>> b = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> b.inertia_com.diagonal()
    array([1., 2., 3.])
    >>> b.euler_form, rd.RigidBody(1.0, [0.4, 0.4, 0.4]).euler_form
    ('principal', 'spherical')
    
    A product of inertia makes Euler's equations 'full':
    
    >>> rd.RigidBody(1.0, [[2.0, -0.1, 0.0], [-0.1, 2.0, 0.0], [0.0, 0.0, 3.0]]).euler_form
    'full'
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, mass: float | _Quantity | SpatialInertia, inertia_com: numpy.typing.ArrayLike | _Quantity | None = None, check: InertiaCheck | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def euler_form(self) -> str:
        """
        Form of Euler's equations used: 'spherical' (no gyroscopic term), 'principal' (diagonal inertia) or 'full'.
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia I about the centre of mass in B, shape (3, 3) [kg m^2], negated products off the diagonal (read-only).
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
class ParticleState:
    """
    State of a Particle: position and velocity in W.
    
    Fields are assigned whole (``s.v_W = [...]``, converted and checked as the constructor does); the arrays read
    are read-only copies. Pickles; == compares every field.
    
    Parameters
    ----------
    p_W : array_like, shape (3,), or pint.Quantity, optional
        Position in W [m] (None: zero).
    v_W : array_like, shape (3,), or pint.Quantity, optional
        Velocity in W [m/s] (None: zero).
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    Particle, simulate, step
    
    Examples
    --------
    >>> s = rd.ParticleState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 2.0, 0.0])
    >>> rd.linear_momentum(rd.Particle(3.0), s)
    array([0., 6., 0.])
    >>> rd.angular_momentum(rd.Particle(3.0), s)  # about the origin of W: p_W x m v_W
    array([0., 0., 6.])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: numpy.typing.ArrayLike | _Quantity | None = None, v_W: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Position p_W in W, shape (3,) [m].
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Velocity v_W in W, shape (3,) [m/s].
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
class PlanarBodyState:
    """
    State of a PlanarBody in W's xy plane.
    
    Fields are assigned whole (converted and checked as the constructor does); the arrays read are read-only
    copies. Pickles; == compares every field.
    
    Parameters
    ----------
    p_W : array_like, shape (2,), or pint.Quantity, optional
        Centre of mass in W's xy plane [m] (None: zero).
    theta : float or pint.Quantity, default 0
        Angle of B about z [rad] (R_WB = Rz(theta)).
    v_W : array_like, shape (2,), or pint.Quantity, optional
        Centre of mass velocity in W [m/s] (None: zero).
    omega : float or pint.Quantity, default 0
        Angular velocity about z [rad/s].
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    PlanarBody, simulate, step
    
    Examples
    --------
    >>> s = rd.PlanarBodyState(p_W=[1.0, 2.0], theta=np.pi / 2, omega=3.0)
    >>> s.p_W, s.omega
    (array([1., 2.]), 3.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float, numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, p_W: numpy.typing.ArrayLike | _Quantity | None = None, theta: float | _Quantity = 0.0, v_W: numpy.typing.ArrayLike | _Quantity | None = None, omega: float | _Quantity = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def omega(self) -> float:
        """
        Angular velocity omega about z [rad/s].
        """
    @omega.setter
    def omega(self, arg1: typing.Any) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass p_W in W's xy plane, shape (2,) [m].
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def theta(self) -> float:
        """
        Angle theta of B about z [rad], R_WB = Rz(theta).
        """
    @theta.setter
    def theta(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass velocity v_W in W, shape (2,) [m/s].
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
class RigidBodyState:
    """
    State of a RigidBody (docs/conventions.md).
    
    Position and velocity of the centre of mass in W, attitude q_WB (B to W) and the angular velocity of B in W,
    expressed in B. Fields are assigned whole (``s.w_B = [...]``, ``s.q_WB = [x, y, z, w]``, converted and checked
    as the constructor does); the arrays read are read-only copies. Pickles; == compares every field.
    
    Parameters
    ----------
    p_W : array_like, shape (3,), or pint.Quantity, optional
        Centre of mass position in W [m] (None: zero).
    q_WB : array_like, shape (4,), optional
        Unit quaternion B to W, (x, y, z, w), or (w, x, y, z) with `scalar_first` (None: identity); normalised.
    v_W : array_like, shape (3,), or pint.Quantity, optional
        Centre of mass velocity in W [m/s] (None: zero).
    w_B : array_like, shape (3,), or pint.Quantity, optional
        Angular velocity of B in W, expressed in B [rad/s] (None: zero).
    scalar_first : bool, default False
        Read q_WB as (w, x, y, z).
    
    Raises
    ------
    ValueError
        q_WB farther than 1e-6 from unit norm (| |q| - 1 | > 1e-6), a field of another shape or not finite, or
        a quantity of another dimension (the message names it).
    
    See Also
    --------
    RigidBody, simulate, step, quat_normalize
    
    Examples
    --------
    A quarter turn about z, read scalar first:
    
    >>> s = rd.RigidBodyState(q_WB=[0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)], w_B=[0.0, 0.0, 1.0])
    >>> s.quaternion(scalar_first=True).round(12)
    array([0.70710678, 0.        , 0.        , 0.70710678])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: numpy.typing.ArrayLike | _Quantity | None = None, q_WB: numpy.typing.ArrayLike | None = None, v_W: numpy.typing.ArrayLike | _Quantity | None = None, w_B: numpy.typing.ArrayLike | _Quantity | None = None, scalar_first: bool = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def quaternion(self, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        The attitude q_WB (B to W) in the order asked.
        
        Parameters
        ----------
        scalar_first : bool, default False
            Return (w, x, y, z) instead of (x, y, z, w).
        
        Returns
        -------
        ndarray, shape (4,)
            q_WB, read-only.
        
        Examples
        --------
        >>> rd.RigidBodyState().quaternion(scalar_first=True)
        array([1., 0., 0., 0.])
        """
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass position p_W in W, shape (3,) [m].
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm).
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass velocity v_W in W, shape (3,) [m/s].
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular velocity w_B of B in W, expressed in B, shape (3,) [rad/s].
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
class KineticEnergy:
    """
    Kinetic energy T [J], split as T = translational + rotational.
    
    translational = 1/2 m v_W.v_W of the centre of mass, rotational = 1/2 w_B.I w_B about it (1/2 I_zz omega^2 for
    a planar body, 0 for a particle); total = their sum. kinetic_energy's result. Immutable; pickles.
    
    Parameters
    ----------
    translational : float or pint.Quantity, default 0
        1/2 m v_W.v_W [J] (infinities allowed).
    rotational : float or pint.Quantity, default 0
        1/2 w_B.I w_B about the centre of mass [J] (infinities allowed).
    
    Raises
    ------
    ValueError
        A NaN, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    kinetic_energy, potential_energy
    
    Examples
    --------
    >>> T = rd.kinetic_energy(rd.RigidBody(2.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(v_W=[1, 0, 0], w_B=[0, 0, 1]))
    >>> T.translational, T.rotational, T.total
    (1.0, 1.5, 2.5)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, translational: float | _Quantity = 0.0, rotational: float | _Quantity = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def rotational(self) -> float:
        """
        Rotational part 1/2 w_B.I w_B about the centre of mass [J].
        """
    @property
    def total(self) -> float:
        """
        Total kinetic energy, translational + rotational [J].
        """
    @property
    def translational(self) -> float:
        """
        Translational part 1/2 m v_W.v_W of the centre of mass [J].
        """
class ComWrench:
    """
    Loads reduced to the centre of mass G: a force in W and a torque about G in B.
    
    inverse_dynamics' result for a RigidBody; unpacks as ``f_W, tau_B = ...``. Immutable; pickles.
    
    Parameters
    ----------
    f_W : array_like, shape (3,), or pint.Quantity, optional
        Force in W [N] (None: zero).
    tau_B : array_like, shape (3,), or pint.Quantity, optional
        Torque about the centre of mass, in B [N m] (None: zero).
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    inverse_dynamics, BodyAcceleration, power
    
    Examples
    --------
    Holding 2 kg against gravity while lifting it at 1 m/s^2 takes m (a_W - g) = 21.62 N:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> f_W, tau_B = rd.inverse_dynamics(body, rd.RigidBodyState(), a_W=[0, 0, 1], alpha_B=[1, 0, 0], gravity=True)
    >>> f_W, tau_B
    (array([ 0.  ,  0.  , 21.62]), array([1., 0., 0.]))
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, f_W: numpy.typing.ArrayLike | _Quantity | None = None, tau_B: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        Force f_W in W, shape (3,) [N].
        """
    @property
    def tau_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Torque tau_B about the centre of mass, in B, shape (3,) [N m].
        """
class PlanarWrench:
    """
    In-plane loads reduced to the centre of mass G.
    
    A force in W's xy plane and a torque about the z axis through G: inverse_dynamics' result for a PlanarBody;
    unpacks as ``f_W, tau = ...``. Immutable; pickles.
    
    Parameters
    ----------
    f_W : array_like, shape (2,), or pint.Quantity, optional
        Force in W [N] (None: zero).
    tau : float or pint.Quantity, default 0
        Torque about the z axis through the centre of mass [N m].
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    inverse_dynamics, PlanarAcceleration
    
    Examples
    --------
    >>> body = rd.PlanarBody(2.0, 0.5)
    >>> rd.inverse_dynamics(body, rd.PlanarBodyState(), a_W=[1.0, 0.0], alpha_B=2.0)
    PlanarWrench(f_W=[2.0, 0.0], tau=1.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, f_W: numpy.typing.ArrayLike | _Quantity | None = None, tau: float | _Quantity = 0.0) -> None:
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
        Force f_W in W's xy plane, shape (2,) [N].
        """
    @property
    def tau(self) -> float:
        """
        Torque tau about the z axis through the centre of mass [N m].
        """
class BodyAcceleration:
    """
    Accelerations of a rigid body.
    
    The centre of mass's acceleration in W and the angular acceleration in B: forward_dynamics' result for a
    RigidBody; unpacks as ``a_W, alpha_B = ...``. Immutable; pickles.
    
    Parameters
    ----------
    a_W : array_like, shape (3,), or pint.Quantity, optional
        Centre of mass acceleration in W [m/s^2] (None: zero).
    alpha_B : array_like, shape (3,), or pint.Quantity, optional
        Angular acceleration of B in W, expressed in B [rad/s^2] (None: zero).
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    forward_dynamics, ComWrench
    
    Examples
    --------
    1 N along y at 1 m along x: a_W = f/m, alpha_B = I^-1 (p_GP x f):
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> a_W, alpha_B = rd.forward_dynamics(body, rd.RigidBodyState(), force=[0, 1.0, 0], point=[1.0, 0, 0])
    >>> a_W, alpha_B.round(12)
    (array([0. , 0.5, 0. ]), array([0.        , 0.        , 0.33333333]))
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, a_W: numpy.typing.ArrayLike | _Quantity | None = None, alpha_B: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        Centre of mass acceleration a_W in W, shape (3,) [m/s^2].
        """
    @property
    def alpha_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular acceleration alpha_B of B in W, expressed in B, shape (3,) [rad/s^2].
        """
class PlanarAcceleration:
    """
    Accelerations of a planar body.
    
    The centre of mass's acceleration in W's xy plane and the angular acceleration about z: forward_dynamics'
    result for a PlanarBody; unpacks as ``a_W, alpha = ...``. Immutable; pickles.
    
    Parameters
    ----------
    a_W : array_like, shape (2,), or pint.Quantity, optional
        Centre of mass acceleration in W [m/s^2] (None: zero).
    alpha : float or pint.Quantity, default 0
        Angular acceleration about z [rad/s^2].
    
    Raises
    ------
    ValueError
        A field of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    forward_dynamics, PlanarWrench
    
    Examples
    --------
    >>> body = rd.PlanarBody(2.0, 0.5)
    >>> rd.forward_dynamics(body, rd.PlanarBodyState(), force=[0, 1.0], point=[1.0, 0])
    PlanarAcceleration(a_W=[0.0, 0.5], alpha=2.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], float]:
        ...
    def __init__(self, a_W: numpy.typing.ArrayLike | _Quantity | None = None, alpha: float | _Quantity = 0.0) -> None:
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
        Centre of mass acceleration a_W in W's xy plane, shape (2,) [m/s^2].
        """
    @property
    def alpha(self) -> float:
        """
        Angular acceleration alpha about z [rad/s^2].
        """
class PivotedBody:
    """
    A rigid body pinned at a point O fixed in the scene frame W (3 DOF): the heavy top, the gyroscope.
    
    B is the body frame at the centre of mass C, as for RigidBody; C is at p_WO + R_WB p_OC_B. Euler's law is
    written about O (K. Craig, "Rigid Body Dynamics" slides: M_O = dH_O/dt) with
    inertia_O = I_C + m (|c|^2 1 - c c^T), c = p_OC_B, the parallel-axis theorem with the products of inertia.
    digits_lost tells how many decimal digits of I_C the rounding of inertia_O loses (the compile of a scene warns
    above 6). Its state is a PivotedBodyState. Immutable; pickles; == compares body, p_OC_B and p_WO.
    
    Parameters
    ----------
    body : RigidBody
        Mass [kg] and inertia_com [kg m^2] about the centre of mass C, in B.
    p_OC_B : array_like, shape (3,), or pint.Quantity
        C relative to O, in B [m] (zero allowed: the free rotation about C).
    p_WO : array_like, shape (3,), or pint.Quantity, optional
        O in W [m] (None: the origin).
    
    Raises
    ------
    TypeError
        body not a RigidBody.
    ValueError
        p_OC_B beyond 15 digits lost (m |c|^2 > 1e15 times the smallest moment of I_C: inertia_O's moment about the
        axis through O and C, I_C's about it, is then rounding noise), or inertia_O no longer positive definite in
        double precision (the message names p_OC_B); a field of another shape or dimension.
    
    See Also
    --------
    PivotedBodyState, PivotedAcceleration, PivotedTorque, PivotedPlanarBody, forward_dynamics, simulate
    
    Examples
    --------
    A top of 1 kg, its centre of mass 0.5 m up its axis: the parallel-axis theorem adds m |c|^2 = 0.25 kg m^2 to
    the transverse moments:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    >>> top.inertia_O.diagonal()
    array([0.35, 0.35, 0.2 ])
    >>> rd.forward_dynamics(top, rd.PivotedBodyState(), gravity=True).reaction_W  # upright at rest: the pivot holds m g
    array([0.  , 0.  , 9.81])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[RigidBody, typing.Any, typing.Any]:
        ...
    def __init__(self, body: RigidBody, p_OC_B: numpy.typing.ArrayLike | _Quantity, p_WO: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> RigidBody:
        """
        The RigidBody: mass [kg] and inertia about C in B [kg m^2] (a copy).
        """
    @property
    def digits_lost(self) -> float:
        """
        Decimal digits of I_C lost in inertia_O, max(0, log10(m |c|^2 / smallest moment of I_C)), at most 15 (a float).
        """
    @property
    def euler_form(self) -> str:
        """
        Form of Euler's equations of inertia_O: 'spherical', 'principal' or 'full'.
        """
    @property
    def inertia_O(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia about O in B, I_C + m (|c|^2 1 - c c^T), shape (3, 3) [kg m^2].
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia I_C about the centre of mass C, in B, shape (3, 3) [kg m^2].
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
    @property
    def p_OC_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The centre of mass C relative to the pivot O, in B, shape (3,) [m].
        """
    @property
    def p_WO(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The pivot O in the scene frame W, shape (3,) [m].
        """
class PivotedPlanarBody:
    """
    The compound pendulum: a planar body pinned at a point O fixed in the scene frame W (1 DOF).
    
    It turns about W's z axis, R_WB = Rz(theta). Plane kinetics about O (K. Craig, "Rigid Body Dynamics" slides):
    inertia_O_zz alpha = tau_O, inertia_O_zz = inertia_zz + m |c|^2, c = p_OC_B. Its state is a
    PivotedPlanarBodyState; its gravity an in-plane vector. Immutable; pickles; == compares every field.
    
    Parameters
    ----------
    mass : float or pint.Quantity
        Mass m [kg], > 0.
    inertia_zz : float or pint.Quantity
        Moment of inertia about the z axis through the centre of mass C [kg m^2], > 0.
    p_OC_B : array_like, shape (2,), or pint.Quantity
        C relative to O in B's xy plane [m] (zero allowed).
    p_WO : array_like, shape (2,), or pint.Quantity, optional
        O in W's xy plane [m] (None: the origin).
    
    Raises
    ------
    ValueError
        mass or inertia_zz not a finite number > 0; inertia_O_zz beyond the double range (the message names
        p_OC_B); a field of another shape or dimension.
    
    See Also
    --------
    PivotedPlanarBodyState, PivotedPlanarAcceleration, PivotedPlanarTorque, PivotedBody, simulate
    
    Examples
    --------
    A uniform rod of 2 m and 3 kg pinned at one end: inertia_O_zz = m L^2 / 3 = 4 kg m^2.
    
    >>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
    >>> rod.inertia_O_zz
    4.0
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float, typing.Any, typing.Any]:
        ...
    def __init__(self, mass: float | _Quantity, inertia_zz: float | _Quantity, p_OC_B: numpy.typing.ArrayLike | _Quantity, p_WO: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def inertia_O_zz(self) -> float:
        """
        Moment of inertia about the z axis through O, inertia_zz + m |c|^2 [kg m^2].
        """
    @property
    def inertia_zz(self) -> float:
        """
        Moment of inertia about the z axis through C [kg m^2].
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg].
        """
    @property
    def p_OC_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        C relative to O in B's xy plane, shape (2,) [m].
        """
    @property
    def p_WO(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The pivot O in W's xy plane, shape (2,) [m].
        """
class PivotedBodyState:
    """
    State of a PivotedBody: its attitude and angular velocity.
    
    Fields are assigned whole (``s.w_B = [...]``, converted and checked as the constructor does); the arrays read are
    read-only copies. Pickles; == compares every field.
    
    Parameters
    ----------
    q_WB : array_like, shape (4,), optional
        Unit quaternion B to the scene frame W, (x, y, z, w), or (w, x, y, z) with `scalar_first` (None:
        identity); normalised.
    w_B : array_like, shape (3,), or pint.Quantity, optional
        Angular velocity of B relative to W, in B [rad/s] (None: zero).
    scalar_first : bool, default False
        Read q_WB as (w, x, y, z).
    
    Raises
    ------
    ValueError
        q_WB farther than 1e-6 from unit norm (| |q| - 1 | > 1e-6), a field of another shape, or a quantity of
        another dimension (the message names it).
    
    See Also
    --------
    PivotedBody, simulate, step
    
    Examples
    --------
    A top spinning at 10 rad/s about its upright axis stays upright; one step of 0.01 s turns it 0.1 rad:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    >>> s = rd.step(top, rd.PivotedBodyState(w_B=[0.0, 0.0, 10.0]), 0.01, gravity=True)
    >>> rd.quat_to_rotvec(s.q_WB).round(6), s.w_B
    (array([0. , 0. , 0.1]), array([ 0.,  0., 10.]))
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], typing.Any]:
        ...
    def __init__(self, q_WB: numpy.typing.ArrayLike | None = None, w_B: numpy.typing.ArrayLike | _Quantity | None = None, scalar_first: bool = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def quaternion(self, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        The attitude q_WB (B to W) in the order asked.
        
        Parameters
        ----------
        scalar_first : bool, default False
            Return (w, x, y, z) instead of (x, y, z, w).
        
        Returns
        -------
        ndarray, shape (4,)
            q_WB, read-only.
        
        Examples
        --------
        >>> rd.PivotedBodyState().quaternion(scalar_first=True)
        array([1., 0., 0., 0.])
        """
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm).
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular velocity w_B of B relative to W, expressed in B, shape (3,) [rad/s].
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
class PivotedPlanarBodyState:
    """
    State of a PivotedPlanarBody: its angle and angular velocity about z.
    
    Fields are assignable (converted and checked as the constructor does). Pickles; == compares every field.
    
    Parameters
    ----------
    theta : float or pint.Quantity, default 0
        Angle of B about z [rad] (R_WB = Rz(theta)).
    omega : float or pint.Quantity, default 0
        d theta/dt [rad/s].
    
    Raises
    ------
    ValueError
        A value that is not a number, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    PivotedPlanarBody, simulate, step
    
    Examples
    --------
    A pendulum released horizontal keeps its energy (rk4's drift is O(dt^4): below 1e-9 J here at dt = 1 ms):
    
    >>> rod = rd.PivotedPlanarBody(3.0, 1.0, p_OC_B=[1.0, 0.0])
    >>> r = rd.simulate(rod, rd.PivotedPlanarBodyState(theta=0.0), 0.001, steps=1000, gravity=[0.0, -9.81])
    >>> bool(abs(r.total_energy - r.total_energy[0]).max() < 1e-9)
    True
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[float, float]:
        ...
    def __init__(self, theta: float | _Quantity = 0.0, omega: float | _Quantity = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def omega(self) -> float:
        """
        Angular velocity omega = d theta/dt about z [rad/s].
        """
    @omega.setter
    def omega(self, arg1: typing.Any) -> None:
        ...
    @property
    def theta(self) -> float:
        """
        Angle theta of B about z [rad], R_WB = Rz(theta).
        """
    @theta.setter
    def theta(self, arg1: typing.Any) -> None:
        ...
class PivotedAcceleration:
    """
    forward_dynamics' result for a PivotedBody.
    
    The angular acceleration in B and the pivot's force on the body in W; unpacks as
    ``alpha_B, reaction_W = ...``. Immutable; pickles.
    
    Parameters
    ----------
    alpha_B : array_like, shape (3,), or pint.Quantity, optional
        Angular acceleration of B, in B [rad/s^2] (None: zero).
    reaction_W : array_like, shape (3,), or pint.Quantity, optional
        The pivot's force on the body, in W [N] (None: zero).
    
    See Also
    --------
    forward_dynamics, PivotedBody, PivotedTorque
    
    Examples
    --------
    A top of 1 kg held horizontal, its centre of mass 0.5 m from the pivot: alpha = m g |c| / I_O = 14.01 rad/s^2:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    >>> level = rd.PivotedBodyState(q_WB=rd.rotvec_to_quat([0.0, np.pi / 2, 0.0]))
    >>> alpha_B, reaction_W = rd.forward_dynamics(top, level, gravity=True)
    >>> alpha_B.round(6)
    array([ 0.      , 14.014286,  0.      ])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, alpha_B: numpy.typing.ArrayLike | _Quantity | None = None, reaction_W: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        Angular acceleration alpha_B of B, in B, shape (3,) [rad/s^2].
        """
    @property
    def reaction_W(self) -> typing.Any:
        """
        The pivot's force on the body, in W, shape (3,) [N].
        """
class PivotedTorque:
    """
    inverse_dynamics' result for a PivotedBody.
    
    The torque about the pivot O the motion needs besides gravity, in B, and the pivot's force on the body in W;
    unpacks as ``tau_O_B, reaction_W = ...``. Immutable; pickles.
    
    Parameters
    ----------
    tau_O_B : array_like, shape (3,), or pint.Quantity, optional
        Torque about O, in B [N m] (None: zero).
    reaction_W : array_like, shape (3,), or pint.Quantity, optional
        The pivot's force on the body, in W [N] (None: zero).
    
    See Also
    --------
    inverse_dynamics, PivotedBody, PivotedAcceleration
    
    Examples
    --------
    At rest upright, the pivot alone holds the top's weight:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    >>> rd.inverse_dynamics(top, rd.PivotedBodyState(), alpha_B=[0, 0, 0], gravity=True)
    PivotedTorque(tau_O_B=[0.0, 0.0, 0.0], reaction_W=[0.0, 0.0, 9.81])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, tau_O_B: numpy.typing.ArrayLike | _Quantity | None = None, reaction_W: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        The pivot's force on the body, in W, shape (3,) [N].
        """
    @property
    def tau_O_B(self) -> typing.Any:
        """
        Torque tau_O_B about the pivot O, in B, shape (3,) [N m].
        """
class PivotedPlanarAcceleration:
    """
    forward_dynamics' result for a PivotedPlanarBody.
    
    The angular acceleration about z and the pivot's force on the body in W (its z part is what the pin and the
    plane hold); unpacks as ``alpha, reaction_W = ...``. Immutable; pickles.
    
    Parameters
    ----------
    alpha : float or pint.Quantity, default 0
        Angular acceleration about z [rad/s^2].
    reaction_W : array_like, shape (3,), or pint.Quantity, optional
        The pivot's force on the body, in W [N] (None: zero).
    
    See Also
    --------
    forward_dynamics, PivotedPlanarBody, PivotedPlanarTorque
    
    Examples
    --------
    A rod of L = 2 m and 3 kg pinned at one end, released horizontal: alpha = -3 g / (2 L), and the pin carries
    m g / 4 (the centre of mass accelerates down at 3 g / 4):
    
    >>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
    >>> alpha, reaction_W = rd.forward_dynamics(rod, rd.PivotedPlanarBodyState(), gravity=[0.0, -9.81])
    >>> print(f"{alpha:.6f} {reaction_W[1]:.6f} {3.0 * 9.81 / 4:.6f}")
    -7.357500 7.357500 7.357500
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, alpha: float | _Quantity = 0.0, reaction_W: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        Angular acceleration alpha about z [rad/s^2].
        """
    @property
    def reaction_W(self) -> typing.Any:
        """
        The pivot's force on the body, in W, shape (3,) [N].
        """
class PivotedPlanarTorque:
    """
    inverse_dynamics' result for a PivotedPlanarBody.
    
    The torque about the z axis through the pivot O the motion needs besides gravity, and the pivot's force on the
    body in W; unpacks as ``tau_O, reaction_W = ...``. Immutable; pickles.
    
    Parameters
    ----------
    tau_O : float or pint.Quantity, default 0
        Torque about the z axis through O [N m].
    reaction_W : array_like, shape (3,), or pint.Quantity, optional
        The pivot's force on the body, in W [N] (None: zero).
    
    See Also
    --------
    inverse_dynamics, PivotedPlanarBody, PivotedPlanarAcceleration
    
    Examples
    --------
    Holding the rod horizontal takes the torque m g L / 2 about the pin:
    
    >>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
    >>> tau_O, reaction_W = rd.inverse_dynamics(rod, rd.PivotedPlanarBodyState(), alpha_B=0.0, gravity=[0.0, -9.81])
    >>> print(f"{tau_O:.6f} {3.0 * 9.81 * 1.0:.6f}")
    29.430000 29.430000
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getitem__(self, index: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, typing.Any]:
        ...
    def __init__(self, tau_O: float | _Quantity = 0.0, reaction_W: numpy.typing.ArrayLike | _Quantity | None = None) -> None:
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
        The pivot's force on the body, in W, shape (3,) [N].
        """
    @property
    def tau_O(self) -> typing.Any:
        """
        Torque tau_O about the z axis through O [N m].
        """
class Wheel:
    """
    A wheel of a Gyrostat, spun about an axis fixed in the body by a motor.
    
    Its speed relative to the body is a state of the gyrostat (GyrostatState.wheel_speeds). Immutable; pickles; ==
    compares every field.
    
    Parameters
    ----------
    axis_B : array_like, shape (3,)
        The spin axis in the body frame B (any non-zero length; the unit axis is kept).
    inertia : float or pint.Quantity
        The wheel's moment of inertia about its spin axis [kg m^2], > 0.
    motor_torque : float or pint.Quantity, default 0
        The motor's torque on the wheel about its axis [N m] (the body feels its reaction), applied for
        t_start <= t < t_end.
    t_start, t_end : float or pint.Quantity, default 0 and inf
        The motor's time window [s] (a run splits its steps at both).
    
    Raises
    ------
    ValueError
        A zero or non-finite axis, an inertia not > 0, a non-finite torque, t_end not after t_start, or a quantity
        of another dimension (the message names it).
    
    See Also
    --------
    Gyrostat, GyrostatState
    
    Examples
    --------
    >>> rd.Wheel(axis_B=[0, 0, 2], inertia=0.01, motor_torque=0.002, t_end=5.0).axis_B
    array([0., 0., 1.])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, float, float, float, float]:
        ...
    def __init__(self, axis_B: numpy.typing.ArrayLike, inertia: float | _Quantity, motor_torque: float | _Quantity = 0.0, t_start: float | _Quantity = 0.0, t_end: float | _Quantity = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def axis_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The unit spin axis a in B, shape (3,).
        """
    @property
    def inertia(self) -> float:
        """
        Axial moment of inertia J about the spin axis [kg m^2].
        """
    @property
    def motor_torque(self) -> float:
        """
        Motor torque u on the wheel about its axis [N m].
        """
    @property
    def t_end(self) -> float:
        """
        The motor's end [s] (inf: never).
        """
    @property
    def t_start(self) -> float:
        """
        The motor's start [s].
        """
class Gyrostat:
    """
    A rigid body carrying wheels spun by motors about axes fixed in the body: a reaction-wheel spacecraft.
    
    Each wheel's speed relative to the body is a state (Hughes, "Spacecraft Attitude Dynamics", ch. 3). With I the
    whole body's inertia about its centre of mass in B (wheels locked), wheel k's unit axis a_k, axial inertia J_k,
    speed Omega_k relative to the body and motor torque u_k, the transverse inertia A = I - sum J_k a_k a_k^T:
    
        A dw/dt = tau_B - sum u_k a_k - w x (I w + h_w),  dOmega_k/dt = u_k / J_k - a_k . dw/dt,
    
    h_w = sum J_k Omega_k a_k; kinetic energy T = 1/2 m |v|^2 + 1/2 w.A w + 1/2 sum J_k (a_k.w + Omega_k)^2.
    Elements see it as its locked RigidBody. It runs in an inertial scene with explicit_euler, semi_implicit_euler,
    rk4, rkmk4 or implicit_midpoint; simulate and step of a Gyrostat alone run its one-body scene. Immutable;
    pickles; == compares body and wheels.
    
    Parameters
    ----------
    body : RigidBody
        The whole body with its wheels locked: mass [kg] and inertia_com [kg m^2] about its centre of mass in B,
        wheels included.
    wheels : sequence of Wheel
        Its wheels (one Wheel alone is taken as a list of one).
    
    Raises
    ------
    TypeError
        body not a RigidBody, or wheels not a sequence of Wheel (the message names wheels[k]).
    ValueError
        A wheel's axial inertia leaves A not positive definite (the message names wheels[k].inertia).
    
    See Also
    --------
    Wheel, GyrostatState, RigidBody, simulate
    
    Examples
    --------
    >>> sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05)])
    >>> sat.transverse_inertia.diagonal()
    array([10.  , 12.  , 14.95])
    
    Motor torque spins the wheel up and the body the other way; the total angular momentum stays zero:
    
    >>> sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05, motor_torque=0.01)])
    >>> r = rd.simulate(sat, rd.GyrostatState(wheel_speeds=[0.0]), dt=0.1, steps=100)
    >>> bool(r.w_B[-1, 0, 2] < 0 < r.wheel_speed[-1, 0]), bool(np.allclose(r.angular_momentum_W[-1], 0, atol=1e-12))
    (True, True)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[RigidBody, list]:
        ...
    def __init__(self, body: RigidBody, wheels: collections.abc.Sequence[Wheel]) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> RigidBody:
        """
        The RigidBody with the wheels locked: mass [kg] and inertia about C in B [kg m^2] (a copy).
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Inertia I about the centre of mass in B, wheels locked, shape (3, 3) [kg m^2].
        """
    @property
    def mass(self) -> float:
        """
        Mass m [kg], wheels included.
        """
    @property
    def transverse_inertia(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        A = I - sum J_k a_k a_k^T in B, shape (3, 3) [kg m^2]: the body with its wheels free to spin.
        """
    @property
    def wheels(self) -> tuple:
        """
        The wheels, a tuple of Wheel in the order of the state's wheel_speeds.
        """
class GyrostatState:
    """
    State of a Gyrostat: the rigid body's state and its wheels' speeds.
    
    Fields are assigned whole (converted and checked as the constructor does); the arrays read are read-only copies.
    Pickles; == compares every field.
    
    Parameters
    ----------
    p_W : array_like, shape (3,), optional
        Centre of mass position in W [m] (None: zero).
    q_WB : array_like, shape (4,), optional
        Unit quaternion B to W, (x, y, z, w), or (w, x, y, z) with scalar_first=True (None: identity; normalised).
    v_W : array_like, shape (3,), optional
        Centre of mass velocity in W [m/s] (None: zero).
    w_B : array_like, shape (3,), optional
        Angular velocity of B relative to W, in B [rad/s] (None: zero).
    wheel_speeds : array_like, shape (nw,), optional
        Each wheel's speed relative to the body [rad/s], in the order of the gyrostat's wheels (None: none; a run
        checks one per wheel).
    scalar_first : bool, default False
        Read q_WB as (w, x, y, z).
    
    Raises
    ------
    ValueError
        q_WB farther than 1e-6 from unit norm, wheel_speeds not 1-D or not finite, a field of another shape, or a
        quantity of another dimension (the message names it).
    
    See Also
    --------
    Gyrostat, Wheel, simulate
    
    Examples
    --------
    >>> rd.GyrostatState(w_B=[0, 0, 0.1], wheel_speeds=[100.0]).wheel_speeds
    array([100.])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[typing.Any, numpy.typing.NDArray[numpy.float64], typing.Any, typing.Any, numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, p_W: numpy.typing.ArrayLike | None = None, q_WB: numpy.typing.ArrayLike | None = None, v_W: numpy.typing.ArrayLike | None = None, w_B: numpy.typing.ArrayLike | None = None, wheel_speeds: numpy.typing.ArrayLike | None = None, scalar_first: bool = False) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def p_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass position p_W in W, shape (3,) [m].
        """
    @p_W.setter
    def p_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def q_WB(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Attitude q_WB (B to W), shape (4,), (x, y, z, w); set from (x, y, z, w), normalised (ValueError beyond 1e-6 of unit norm).
        """
    @q_WB.setter
    def q_WB(self, arg1: typing.Any) -> None:
        ...
    @property
    def v_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Centre of mass velocity v_W in W, shape (3,) [m/s].
        """
    @v_W.setter
    def v_W(self, arg1: typing.Any) -> None:
        ...
    @property
    def w_B(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Angular velocity w_B of B in W, expressed in B, shape (3,) [rad/s].
        """
    @w_B.setter
    def w_B(self, arg1: typing.Any) -> None:
        ...
    @property
    def wheel_speeds(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Each wheel's speed relative to the body, shape (nw,) [rad/s].
        """
    @wheel_speeds.setter
    def wheel_speeds(self, arg1: typing.Any) -> None:
        ...
class ElementField:
    """
    One field of a force element class: its class attribute `fields`, in constructor order.
    
    Made by the element classes (no public constructor); the scene files, describe() and the stability check read
    them.
    
    Attributes
    ----------
    key : str
        The keyword and attribute.
    kind : str
        'scalar', 'vector' (3,), 'bodies', 'body', 'optional_body', 'loads', 'frame' or 'callable'.
    unit : str
        SI, pint syntax ('' when none).
    required : bool
        The constructor needs it.
    default : object
        None when required; a vector as a tuple.
    doc : str
        What it is, with its unit.
    
    Examples
    --------
    >>> field = rd.SpringDamper.fields[4]
    >>> field.key, field.unit, field.required
    ('stiffness', 'N/m', True)
    >>> [f.key for f in rd.SpringDamper.fields]
    ['body_a', 'point_a_B', 'body_b', 'point_b', 'stiffness', 'rest_length', 'damping']
    """
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: ElementField has no public constructor: each element class lists its fields (e.g. SpringDamper.fields).
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
    
    Examples
    --------
    A particle dropped from rest falls g t²/2 in t seconds:
    
    >>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity(g_W=(0.0, 0.0, -9.81))])
    >>> result = rd.simulate(scene, [rd.ParticleState()], 0.01, duration=2.0, method="rk4")
    >>> result.p_W[-1, 0].round(12)
    array([  0.  ,   0.  , -19.62])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, g_W: numpy.typing.ArrayLike = (0.0, 0.0, -9.81), bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    A particle on a circular orbit of radius 1 about gm = 1 comes back after one period 2π:
    
    >>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.PointMassGravity(gm=1.0)])
    >>> start = rd.ParticleState(p_W=(1.0, 0.0, 0.0), v_W=(0.0, 1.0, 0.0))
    >>> result = rd.simulate(scene, [start], 2 * np.pi / 1000, steps=1000, method="rk4")
    >>> bool(np.allclose(result.p_W[-1, 0], [1.0, 0.0, 0.0], atol=1e-9))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, gm: float, p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), softening: float = 0.0, bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    Two bodies attract each other: their momentum stays zero and their energy is kept to the method's error:
    
    >>> bodies = [rd.Particle(1.0), rd.Particle(1.0)]
    >>> scene = rd.Scene(bodies, elements=[rd.MutualGravity(G=1.0)])
    >>> start = [rd.ParticleState(p_W=(-0.5, 0.0, 0.0), v_W=(0.0, -0.5, 0.0)),
    ...          rd.ParticleState(p_W=(0.5, 0.0, 0.0), v_W=(0.0, 0.5, 0.0))]
    >>> result = rd.simulate(scene, start, 1e-3, duration=5.0, method="rk4")
    >>> E = result.total_energy
    >>> bool(np.allclose(result.linear_momentum_W[-1], 0.0, atol=1e-14)), bool(abs(E[-1] - E[0]) < 1e-9)
    (True, True)
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, G: float = 6.6743e-11, softening: float = 0.0, bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    A body on a circular orbit at rest in W feels the torque 3 gm/|r|³ r̂ × I r̂ (here zero: r̂ along a principal
    axis, an equilibrium):
    
    >>> scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.GravityGradient(gm=1.0)])
    >>> start = rd.RigidBodyState(p_W=(10.0, 0.0, 0.0))
    >>> result = rd.simulate(scene, [start], 0.01, steps=10, method="rk4")
    >>> bool(np.allclose(result.w_B[-1, 0], 0.0, atol=1e-15))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, gm: float, p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    A mass on a spring to a world anchor oscillates at ω = √(k/m): after one period 2π√(m/k) it is back at its
    start:
    
    >>> scene = rd.Scene([rd.Particle(2.0)], elements=[rd.SpringDamper(body_a=0, stiffness=8.0)])
    >>> start = rd.ParticleState(p_W=(0.1, 0.0, 0.0))
    >>> period = 2 * np.pi * np.sqrt(2.0 / 8.0)
    >>> result = rd.simulate(scene, [start], period / 1000, steps=1000, method="rk4")
    >>> result.p_W[-1, 0].round(9)
    array([0.1, 0. , 0. ])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body_a: int, point_a_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), body_b: int | None = None, point_b: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), stiffness: float, rest_length: float = 0.0, damping: float = 0.0) -> None:
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
    
    Examples
    --------
    Linear drag slows a particle exponentially, v(t) = v0 exp(-c t/m):
    
    >>> scene = rd.Scene([rd.Particle(2.0)], elements=[rd.Drag(linear=1.0)])
    >>> result = rd.simulate(scene, [rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 1e-3, duration=2.0, method="rk4")
    >>> bool(np.isclose(result.v_W[-1, 0, 0], np.exp(-1.0), rtol=1e-10))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, linear: float = 0.0, quadratic: float = 0.0, angular_linear: float = 0.0, angular_quadratic: float = 0.0, bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    A torque of 1 N m about z on for the first second of a sphere with I = 0.5 kg m²: ω = 2 rad/s after it:
    
    >>> sphere = rd.RigidBody(1.0, [0.5, 0.5, 0.5])
    >>> torque = rd.AppliedLoad(torque=(0.0, 0.0, 1.0), t_end=1.0)
    >>> scene = rd.Scene([sphere], elements=[rd.ScheduledLoads(body=0, loads=torque)])
    >>> result = rd.simulate(scene, [rd.RigidBodyState()], 0.01, duration=3.0, method="rk4")
    >>> result.w_B[-1, 0].round(12)
    array([0., 0., 2.])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, loads: AppliedLoad | collections.abc.Sequence[AppliedLoad] = (), point_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
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
    
    
    Examples
    --------
    The weight m g of a particle of 1 kg written in Python: it falls g t²/2:
    
    >>> weight = rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: ((0.0, 0.0, -9.81), (0.0, 0.0, 0.0)))
    >>> scene = rd.Scene([rd.Particle(1.0)], elements=[weight])
    >>> result = rd.simulate(scene, [rd.ParticleState()], 0.01, duration=1.0, method="rk4")
    >>> result.p_W[-1, 0].round(12)
    array([ 0.   ,  0.   , -4.905])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, fn: collections.abc.Callable[..., typing.Any], bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    
    Examples
    --------
    A rocket particle that burns half its mass at 10 m/s exhaust speed gains 10 ln 2 m/s (Tsiolkovsky):
    
    >>> rocket = rd.Scene([rd.Particle(2.0)], elements=[rd.Thrust(body=0, u_rel=(-10.0, 0.0, 0.0), frame="world")],
    ...                   mass_flows=[rd.MassFlow(rate=-0.5)])
    >>> result = rd.simulate(rocket, [rd.ParticleState()], 0.01, duration=2.0, method="rk4")
    >>> round(float(result.mass[-1, 0]), 12), bool(np.isclose(result.v_W[-1, 0, 0], 10 * np.log(2.0), rtol=1e-9))
    (1.0, True)
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: int, u_rel: numpy.typing.ArrayLike, frame: typing.Literal['body', 'world'] = 'body', r_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
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
    
    Examples
    --------
    A compass needle (dipole m along its x axis) in a uniform field along x is at rest: no torque:
    
    >>> needle = rd.RigidBody(1.0, [1e-4, 1e-3, 1e-3])
    >>> field = rd.MagneticDipole(m_B=(1.0, 0.0, 0.0), B_W=(1e-4, 0.0, 0.0))
    >>> result = rd.simulate(rd.Scene([needle], elements=[field]), [rd.RigidBodyState()], 0.01, steps=100, method="rk4")
    >>> bool(np.allclose(result.w_B[-1, 0], 0.0, atol=1e-15))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, m_B: numpy.typing.ArrayLike, B_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), source_moment_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), source_p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), bodies: collections.abc.Sequence[int] | None = None) -> None:
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
    A reaction wheel inside a rigid body (a gyrostat): a wheel of moment of inertia J = inertia about the unit axis a = axis_B/|axis_B| (fixed in B) spins relative to the body at the commanded speed Omega(t) = speed + acceleration (clamp(t, t_start, t_end) - t_start), so its relative angular momentum is h_B = J Omega a. The body's inertia is the whole body's, wheel included; the element applies the couple tau_B = -w_B x h_B - dh_B/dt [N m] of Euler's equation of the gyrostat, I dw/dt + w x (I w + h) = tau - dh/dt. A run splits its steps at t_start and t_end. At a constant wheel speed the body's kinetic energy and the total angular momentum R (I w + h) are conserved; spinning the wheel up about a principal axis turns the body by -J/I times the wheel's angle. A rigiddyn.Controller may command its speed (a rate-limited speed loop: from its speed at a sample to the commanded one at the next, at a constant rate). Rigid bodies, free or pinned.
    
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
    
    Examples
    --------
    A wheel (J = 0.1 kg m²) spun up to 1 rad/s about z turns a body (I = 1 kg m², wheel included) the other way at
    J/I × 1 rad/s, so that the total angular momentum stays zero:
    
    >>> body = rd.RigidBody(10.0, [1.0, 1.0, 1.0])
    >>> wheel = rd.ReactionWheel(body=0, axis_B=(0.0, 0.0, 1.0), inertia=0.1, acceleration=1.0, t_end=1.0)
    >>> result = rd.simulate(rd.Scene([body], elements=[wheel]), [rd.RigidBodyState()], 0.01, duration=2.0,
    ...                      method="rk4")
    >>> result.w_B[-1, 0].round(12)
    array([ 0. ,  0. , -0.1])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, axis_B: numpy.typing.ArrayLike, inertia: float, speed: float = 0.0, acceleration: float = 0.0, t_start: float = 0.0, t_end: float = ...) -> None:
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
class ZonalGravity:
    """
    An oblate central body (the Earth) fixed at p_W with its pole along pole_W: on each listed body the force f_W = -m grad U of the zonal field U = -gm/r + sum_{n=2..4} gm j_n radius^n P_n(u)/r^(n+1), r = |p_body - p_W|, u the sine of the latitude (P_n the Legendre polynomials), potential V = m U [J]. j2 alone makes a near-circular orbit's node regress at -(3/2) n j2 (radius/p)^2 cos i. No torque about the centre of mass (the zonal terms' gravity-gradient torque is j_n (radius/r)^n of GravityGradient's).
    
    Parameters
    ----------
    gm : float [m^3/s^2], required
        gravitational parameter GM of the central body [m^3/s^2]
    radius : float [m], required
        reference (equatorial) radius R of the harmonics [m]
    j2 : float, default 0.0
        zonal coefficient J2 (the Earth's: 1.08262668e-3)
    j3 : float, default 0.0
        zonal coefficient J3 (the Earth's: -2.53265649e-6)
    j4 : float, default 0.0
        zonal coefficient J4 (the Earth's: -1.61962159e-6)
    p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) position of the central body's centre in W [m]
    pole_W : array_like, shape (3,), default (0.0, 0.0, 1.0)
        (3,) direction of its pole (symmetry) axis in W, any length
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    At a point of the equator 7000 km from the Earth's centre, J2 pulls harder than gm/r^2 by (3/2) J2 (R/r)^2:
    
    >>> earth = rd.ZonalGravity(gm=3.986004418e14, radius=6378137.0, j2=1.08262668e-3)
    >>> at_rest = rd.ParticleState(p_W=(7e6, 0.0, 0.0))
    >>> result = rd.simulate(rd.Scene([rd.Particle(1.0)], elements=[earth]), [at_rest], 1e-3, steps=1, method="rk4")
    >>> a_x = result.v_W[-1, 0, 0] / 1e-3  # from rest: v = a dt
    >>> expected = -3.986004418e14 / 7e6**2 * (1 + 1.5 * 1.08262668e-3 * (6378137.0 / 7e6) ** 2)
    >>> bool(abs(a_x / expected - 1) < 1e-12)
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, gm: float, radius: float, j2: float = 0.0, j3: float = 0.0, j4: float = 0.0, p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), pole_W: numpy.typing.ArrayLike = (0.0, 0.0, 1.0), bodies: collections.abc.Sequence[int] | None = None) -> None:
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
        gravitational parameter GM of the central body [m^3/s^2]
        """
    @property
    def j2(self) -> typing.Any:
        """
        zonal coefficient J2 (the Earth's: 1.08262668e-3)
        """
    @property
    def j3(self) -> typing.Any:
        """
        zonal coefficient J3 (the Earth's: -2.53265649e-6)
        """
    @property
    def j4(self) -> typing.Any:
        """
        zonal coefficient J4 (the Earth's: -1.61962159e-6)
        """
    @property
    def p_W(self) -> typing.Any:
        """
        (3,) position of the central body's centre in W [m]
        """
    @property
    def pole_W(self) -> typing.Any:
        """
        (3,) direction of its pole (symmetry) axis in W, any length
        """
    @property
    def radius(self) -> typing.Any:
        """
        reference (equatorial) radius R of the harmonics [m]
        """
class AtmosphericDrag:
    """
    Drag of an atmosphere turning with its planet: on each listed body f_W = -(1/2) rho drag_area |v_rel| v_rel [N] at its centre of pressure cp_B, v_rel = v_W - omega_W x r, r = p_body - p_W, h = |r| - radius; torque tau_B = cp_B x f_B [N m]. The density is exponential, rho = density0 exp(-(h - altitude0)/scale_height), or tabulated: given rows (table_altitude[i], table_density[i]) (at least 2, altitudes increasing, densities > 0), rho is log-linear between rows, rho_i exp(-(h - h_i)/H_i) with H_i = (h_{i+1} - h_i)/ln(rho_i/rho_{i+1}) in the band h_i <= h < h_{i+1} (Vallado, Fundamentals of Astrodynamics and Applications, Table 8-4); below the first row the first band's exponential is extended, above the last row the last band's (density0, altitude0 and scale_height are then left at 0). drag_area is C_D A [m^2] (the ballistic coefficient is m/(C_D A)). No potential: it dissipates. A circular orbit decays at da/dt = -rho (drag_area/m) sqrt(gm a).
    
    Parameters
    ----------
    density0 : float [kg/m^3], default 0.0
        air density at altitude0 [kg/m^3] (the exponential model; 0 with a table)
    altitude0 : float [m], default 0.0
        reference altitude of density0 [m] (the exponential model; 0 with a table)
    scale_height : float [m], default 0.0
        scale height H of the density [m] (the exponential model, > 0; 0 with a table)
    radius : float [m], required
        radius of the central body (altitude 0) [m]
    p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) centre of the central body in W [m]
    omega_W : array_like, shape (3,) [rad/s], default (0.0, 0.0, 0.0)
        (3,) angular velocity of the atmosphere in W [rad/s] (the planet's rotation; zero: still air)
    drag_area : float [m^2], required
        drag coefficient times area C_D A of each body [m^2]
    cp_B : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) centre of pressure in each body's B, from its centre of mass [m] (zero on a particle)
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    table_altitude : array_like, shape (n,) [m], default ()
        (n,) the density table's altitudes [m], increasing (empty: the exponential model)
    table_density : array_like, shape (n,) [kg/m^3], default ()
        (n,) the density [kg/m^3] > 0 at each altitude of table_altitude
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A body 400 km up at 7670 m/s in still air of 3e-12 kg/m^3 loses energy at (1/2) rho (C_D A) v^3:
    
    >>> air = rd.AtmosphericDrag(density0=3e-12, altitude0=400e3, scale_height=60e3, radius=6378137.0,
    ...                          drag_area=2.2 * 4.0)
    >>> start = rd.ParticleState(p_W=(6778137.0, 0.0, 0.0), v_W=(0.0, 7670.0, 0.0))
    >>> result = rd.simulate(rd.Scene([rd.Particle(500.0)], elements=[air]), [start], 0.01, steps=1, method="rk4")
    >>> expected = -0.5 * 3e-12 * 8.8 * 7670.0**3 * 0.01  # the work of one step of 0.01 s [J]
    >>> bool(abs(result.work[-1, 0] / expected - 1) < 1e-6)
    True
    
    A table of two rows, 3e-12 kg/m^3 at 400 km and 3e-12/e at 460 km, is the exponential of scale height 60 km in
    that band:
    
    >>> table = rd.AtmosphericDrag(table_altitude=(400e3, 460e3), table_density=(3e-12, 3e-12 / np.e),
    ...                            radius=6378137.0, drag_area=8.8)
    >>> result = rd.simulate(rd.Scene([rd.Particle(500.0)], elements=[table]), [start], 0.01, steps=1, method="rk4")
    >>> bool(abs(result.work[-1, 0] / expected - 1) < 1e-6)
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, density0: float = 0.0, altitude0: float = 0.0, scale_height: float = 0.0, radius: float, p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), omega_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), drag_area: float, cp_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), bodies: collections.abc.Sequence[int] | None = None, table_altitude: numpy.typing.ArrayLike = (), table_density: numpy.typing.ArrayLike = ()) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def altitude0(self) -> typing.Any:
        """
        reference altitude of density0 [m] (the exponential model; 0 with a table)
        """
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def cp_B(self) -> typing.Any:
        """
        (3,) centre of pressure in each body's B, from its centre of mass [m] (zero on a particle)
        """
    @property
    def density0(self) -> typing.Any:
        """
        air density at altitude0 [kg/m^3] (the exponential model; 0 with a table)
        """
    @property
    def drag_area(self) -> typing.Any:
        """
        drag coefficient times area C_D A of each body [m^2]
        """
    @property
    def omega_W(self) -> typing.Any:
        """
        (3,) angular velocity of the atmosphere in W [rad/s] (the planet's rotation; zero: still air)
        """
    @property
    def p_W(self) -> typing.Any:
        """
        (3,) centre of the central body in W [m]
        """
    @property
    def radius(self) -> typing.Any:
        """
        radius of the central body (altitude 0) [m]
        """
    @property
    def scale_height(self) -> typing.Any:
        """
        scale height H of the density [m] (the exponential model, > 0; 0 with a table)
        """
    @property
    def table_altitude(self) -> typing.Any:
        """
        (n,) the density table's altitudes [m], increasing (empty: the exponential model)
        """
    @property
    def table_density(self) -> typing.Any:
        """
        (n,) the density [kg/m^3] > 0 at each altitude of table_altitude
        """
class SolarRadiationPressure:
    """
    Solar radiation pressure on each listed body, at its centre of pressure cp_B: a cannonball (normal_B zero) f_W = -pressure reflectivity area s, or a flat plate of normal n = R_WB normal_B lit on its normal's side, f_W = -pressure area cos(t) [(1 - specular) s + 2 (specular cos(t) + diffuse/3) n], cos(t) = n . s > 0; torque tau_B = cp_B x f_B. s is the unit direction towards the Sun, sun_W at t = 0 turned at sun_rate_W [rad/s]; none inside the cylindrical shadow of a planet of shadow_radius at shadow_p_W. No potential.
    
    Parameters
    ----------
    sun_W : array_like, shape (3,), required
        (3,) direction towards the Sun in W at t = 0, any length
    sun_rate_W : array_like, shape (3,) [rad/s], default (0.0, 0.0, 0.0)
        (3,) angular velocity at which the Sun's direction turns, in W [rad/s] (zero: fixed)
    pressure : float [N/m^2], default 4.56e-06
        radiation pressure P [N/m^2] (4.56e-6: the Sun's at 1 au)
    area : float [m^2], required
        lit area A of each body [m^2]
    reflectivity : float, default 1.0
        cannonball coefficient C_R (1: absorbed, 2: mirrored back)
    normal_B : array_like, shape (3,), default (0.0, 0.0, 0.0)
        (3,) a flat plate's normal in B, any length (zero: a cannonball)
    specular : float, default 0.0
        a flat plate's specular reflectivity
    diffuse : float, default 0.0
        a flat plate's diffuse reflectivity
    cp_B : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) centre of pressure in B, from the centre of mass [m]
    shadow_radius : float [m], default 0.0
        radius of the planet casting a cylindrical shadow [m], 0 for none
    shadow_p_W : array_like, shape (3,) [m], default (0.0, 0.0, 0.0)
        (3,) centre of that planet in W [m]
    bodies : sequence of int or None, default None
        None (every body) or a tuple of the indices of the bodies it acts on
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A 4 m^2 cannonball of reflectivity 1.3 at 1 au is pushed away from the Sun by 4.56e-6 * 1.3 * 4 N:
    
    >>> srp = rd.SolarRadiationPressure(sun_W=(1.0, 0.0, 0.0), area=4.0, reflectivity=1.3)
    >>> result = rd.simulate(rd.Scene([rd.Particle(100.0)], elements=[srp]), [rd.ParticleState()], 1.0, steps=1,
    ...                      method="rk4")
    >>> bool(np.allclose(result.v_W[-1, 0] * 100.0, [-4.56e-6 * 1.3 * 4.0, 0.0, 0.0], rtol=1e-12, atol=0))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, sun_W: numpy.typing.ArrayLike, sun_rate_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), pressure: float = 4.56e-06, area: float, reflectivity: float = 1.0, normal_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), specular: float = 0.0, diffuse: float = 0.0, cp_B: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), shadow_radius: float = 0.0, shadow_p_W: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), bodies: collections.abc.Sequence[int] | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def area(self) -> typing.Any:
        """
        lit area A of each body [m^2]
        """
    @property
    def bodies(self) -> typing.Any:
        """
        None (every body) or a tuple of the indices of the bodies it acts on
        """
    @property
    def cp_B(self) -> typing.Any:
        """
        (3,) centre of pressure in B, from the centre of mass [m]
        """
    @property
    def diffuse(self) -> typing.Any:
        """
        a flat plate's diffuse reflectivity
        """
    @property
    def normal_B(self) -> typing.Any:
        """
        (3,) a flat plate's normal in B, any length (zero: a cannonball)
        """
    @property
    def pressure(self) -> typing.Any:
        """
        radiation pressure P [N/m^2] (4.56e-6: the Sun's at 1 au)
        """
    @property
    def reflectivity(self) -> typing.Any:
        """
        cannonball coefficient C_R (1: absorbed, 2: mirrored back)
        """
    @property
    def shadow_p_W(self) -> typing.Any:
        """
        (3,) centre of that planet in W [m]
        """
    @property
    def shadow_radius(self) -> typing.Any:
        """
        radius of the planet casting a cylindrical shadow [m], 0 for none
        """
    @property
    def specular(self) -> typing.Any:
        """
        a flat plate's specular reflectivity
        """
    @property
    def sun_W(self) -> typing.Any:
        """
        (3,) direction towards the Sun in W at t = 0, any length
        """
    @property
    def sun_rate_W(self) -> typing.Any:
        """
        (3,) angular velocity at which the Sun's direction turns, in W [rad/s] (zero: fixed)
        """
class RevoluteSpringDamper:
    """
    A torsion spring and damper in the revolute joint of the tree link `body` (a body of Scene.add_tree): the joint torque -(stiffness (q - rest_angle) + damping dq/dt) [N m] about the joint's axis, q the joint's angle [rad], on the link and the opposite on its parent (W for a root link), so that a tree's momenta are conserved. Potential V = stiffness (q - rest_angle)^2/2 [J].
    
    Parameters
    ----------
    body : int, required
        index of the tree link whose revolute joint holds it
    stiffness : float [N*m/rad], required
        torsion stiffness k [N m/rad]
    rest_angle : float [rad], default 0.0
        the joint angle q0 at which the spring is relaxed [rad]
    damping : float [N*m*s/rad], default 0.0
        damping coefficient c [N m s/rad]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A wheel of I = 0.5 kg m² on a torsion spring of 2 N m/rad turns back and forth at ω = √(k/I) = 2 rad/s:
    after one period π s it is back at its start:
    
    >>> tree = rd.Tree()
    >>> wheel = tree.add_link("wheel", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "shaft")
    >>> scene.add(rd.RevoluteSpringDamper(body=links[0], stiffness=2.0))
    0
    >>> result = rd.simulate(scene, tree.joint_states([0.1]), np.pi / 1000, steps=1000, method="rk4")
    >>> result.joint_q[-1].round(9)
    array([0.1])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, stiffness: float, rest_angle: float = 0.0, damping: float = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the tree link whose revolute joint holds it
        """
    @property
    def damping(self) -> typing.Any:
        """
        damping coefficient c [N m s/rad]
        """
    @property
    def rest_angle(self) -> typing.Any:
        """
        the joint angle q0 at which the spring is relaxed [rad]
        """
    @property
    def stiffness(self) -> typing.Any:
        """
        torsion stiffness k [N m/rad]
        """
class PrismaticSpringDamper:
    """
    A linear spring and damper in the prismatic joint of the tree link `body` (a body of Scene.add_tree): the joint force -(stiffness (q - rest_position) + damping dq/dt) [N] along the joint's axis, q the joint's offset [m], on the link and the opposite on its parent (W for a root link), both through the joint's origin, so that a tree's momenta are conserved. Potential V = stiffness (q - rest_position)^2/2 [J].
    
    Parameters
    ----------
    body : int, required
        index of the tree link whose prismatic joint holds it
    stiffness : float [N/m], required
        spring stiffness k [N/m]
    rest_position : float [m], default 0.0
        the joint offset q0 at which the spring is relaxed [m]
    damping : float [N*s/m], default 0.0
        damping coefficient c [N s/m]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A 2 kg slider on a spring of 8 N/m oscillates at ω = √(k/m) = 2 rad/s about its rest position: after one
    period π s it is back at its start:
    
    >>> tree = rd.Tree()
    >>> slider = tree.add_link("slider", -1, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.1 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "rail")
    >>> scene.add(rd.PrismaticSpringDamper(body=links[0], stiffness=8.0, rest_position=0.5))
    0
    >>> result = rd.simulate(scene, tree.joint_states([0.6]), np.pi / 1000, steps=1000, method="rk4")
    >>> result.joint_q[-1].round(9)
    array([0.6])
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, stiffness: float, rest_position: float = 0.0, damping: float = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the tree link whose prismatic joint holds it
        """
    @property
    def damping(self) -> typing.Any:
        """
        damping coefficient c [N s/m]
        """
    @property
    def rest_position(self) -> typing.Any:
        """
        the joint offset q0 at which the spring is relaxed [m]
        """
    @property
    def stiffness(self) -> typing.Any:
        """
        spring stiffness k [N/m]
        """
class RevoluteMotor:
    """
    A motor in the revolute joint of the tree link `body` (a body of Scene.add_tree): the joint torque `torque` [N m] about the joint's axis on [t_start, t_end) [s] (by default all of time), none outside, on the link and the opposite on its parent (W for a root link), so that a tree's momenta are conserved; its power is torque dq/dt. A run splits its steps at t_start and t_end. Several windows: one RevoluteMotor each. A rigiddyn.Controller may command its torque (held until its next sample, in place of the window).
    
    Parameters
    ----------
    body : int, required
        index of the tree link whose revolute joint it drives
    torque : float [N*m], required
        the joint torque [N m] about the joint's axis
    t_start : float [s], default -inf
        the time it starts [s] (-inf: on from any time)
    t_end : float [s], default inf
        the time it stops [s] (inf: never)
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A torque of 1 N m for the first second on a wheel of I = 0.5 kg m²: 2 rad/s after it, and 1 + 2 × 2 = 5 rad
    turned at t = 3 s:
    
    >>> tree = rd.Tree()
    >>> wheel = tree.add_link("wheel", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "shaft")
    >>> scene.add(rd.RevoluteMotor(body=links[0], torque=1.0, t_end=1.0))
    0
    >>> result = rd.simulate(scene, tree.joint_states([0.0]), 0.01, duration=3.0, method="rk4")
    >>> result.joint_q[-1].round(12), result.joint_v[-1].round(12)
    (array([5.]), array([2.]))
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, torque: float, t_start: float = ..., t_end: float = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the tree link whose revolute joint it drives
        """
    @property
    def t_end(self) -> typing.Any:
        """
        the time it stops [s] (inf: never)
        """
    @property
    def t_start(self) -> typing.Any:
        """
        the time it starts [s] (-inf: on from any time)
        """
    @property
    def torque(self) -> typing.Any:
        """
        the joint torque [N m] about the joint's axis
        """
class PrismaticMotor:
    """
    A motor in the prismatic joint of the tree link `body` (a body of Scene.add_tree): the joint force `force` [N] along the joint's axis on [t_start, t_end) [s] (by default all of time), none outside, on the link and the opposite on its parent (W for a root link), both through the joint's origin, so that a tree's momenta are conserved; its power is force dq/dt. A run splits its steps at t_start and t_end. Several windows: one PrismaticMotor each. A rigiddyn.Controller may command its force (held until its next sample, in place of the window).
    
    Parameters
    ----------
    body : int, required
        index of the tree link whose prismatic joint it drives
    force : float [N], required
        the joint force [N] along the joint's axis
    t_start : float [s], default -inf
        the time it starts [s] (-inf: on from any time)
    t_end : float [s], default inf
        the time it stops [s] (inf: never)
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A force of 4 N for the first second on a 2 kg slider: 2 m/s after it, and 1 + 2 × 2 = 5 m travelled at t = 3 s:
    
    >>> tree = rd.Tree()
    >>> slider = tree.add_link("slider", -1, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.1 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "rail")
    >>> scene.add(rd.PrismaticMotor(body=links[0], force=4.0, t_end=1.0))
    0
    >>> result = rd.simulate(scene, tree.joint_states([0.0]), 0.01, duration=3.0, method="rk4")
    >>> result.joint_q[-1].round(12), result.joint_v[-1].round(12)
    (array([5.]), array([2.]))
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, force: float, t_start: float = ..., t_end: float = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the tree link whose prismatic joint it drives
        """
    @property
    def force(self) -> typing.Any:
        """
        the joint force [N] along the joint's axis
        """
    @property
    def t_end(self) -> typing.Any:
        """
        the time it stops [s] (inf: never)
        """
    @property
    def t_start(self) -> typing.Any:
        """
        the time it starts [s] (-inf: on from any time)
        """
class SphericalSpringDamper:
    """
    A torsion spring and damper in the spherical (ball) joint of the tree link `body` (a body of Scene.add_tree): with phi = log(q0^-1 q) the rotation [rad] (in the link frame, angle in [0, pi]) from the rest attitude q0 = exp(rest_rotation) to the joint's attitude q, the couple -(stiffness phi + damping w) [N m] in the link frame (w the joint's angular velocity [rad/s]) on the link and the opposite on its parent (W for a root link), so that a tree's momenta are conserved. Potential V = stiffness |phi|^2/2 [J]. The spring pulls along the shorter rotation to rest (its couple flips at half a turn).
    
    Parameters
    ----------
    body : int, required
        index of the tree link whose spherical joint holds it
    stiffness : float [N*m/rad], required
        torsion stiffness k [N m/rad]
    rest_rotation : array_like, shape (3,) [rad], default (0.0, 0.0, 0.0)
        (3,) rotation vector of the rest attitude q0 = exp(rest_rotation), joint frame to link frame [rad]
    damping : float [N*m*s/rad], default 0.0
        damping coefficient c [N m s/rad]
    
    Each argument with a unit takes a float in that unit or a pint quantity (any registry; converted to that unit, ValueError naming the argument for another dimension).
    
    Examples
    --------
    A ball of I = 0.5 kg m² on a torsion spring of 2 N m/rad, twisted 0.1 rad about z, turns back and forth at
    ω = √(k/I) = 2 rad/s: after one period π s it is back at its start:
    
    >>> tree = rd.Tree()
    >>> ball = tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "mount")
    >>> scene.add(rd.SphericalSpringDamper(body=links[0], stiffness=2.0))
    0
    >>> start = [0.0, 0.0, np.sin(0.05), np.cos(0.05)]
    >>> result = rd.simulate(scene, tree.joint_states(start), np.pi / 1000, steps=1000, method="rk4")
    >>> bool(np.allclose(result.joint_q[-1], start, rtol=0, atol=1e-9))
    True
    """
    __hash__: typing.ClassVar[None] = None
    fields: typing.ClassVar[tuple]
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *, body: int, stiffness: float, rest_rotation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), damping: float = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def body(self) -> typing.Any:
        """
        index of the tree link whose spherical joint holds it
        """
    @property
    def damping(self) -> typing.Any:
        """
        damping coefficient c [N m s/rad]
        """
    @property
    def rest_rotation(self) -> typing.Any:
        """
        (3,) rotation vector of the rest attitude q0 = exp(rest_rotation), joint frame to link frame [rad]
        """
    @property
    def stiffness(self) -> typing.Any:
        """
        torsion stiffness k [N m/rad]
        """
class SceneFrame:
    """
    The frame F a scene's states are relative to, moving relative to the inertial frame W.
    
    Scene.frame (None: W itself). Built by its static constructors (no public constructor):
    
    - SceneFrame.rotating(axis, rate): F turns at `rate` [rad/s] about `axis` (3,) (any non-zero length; fixed in F
      and in W) through its origin, fixed at W's origin; F = W at t = 0;
    - SceneFrame.earth(latitude): the local frame (x east, y north, z up) at `latitude` [rad] on the turning Earth:
      Omega = 7.2921159e-5 rad/s about (0, cos(latitude), sin(latitude));
    - SceneFrame.moving(frame_motion, terms=None): any motion of F relative to W, a FrameMotion (a Python
      kinematics_at(t) is called with the GIL taken, at each derivative evaluation); terms: the fictitious terms
      that act, when the motion leaves some identically zero.
    
    Each physical argument: a float [its unit] or a pint quantity. Immutable; pickles (a FrameMotion of a
    module-level function); == compares how it was built.
    
    Notes
    -----
    Newton's and Euler's laws seen from F gain the fictitious terms ("Rigid body kinematics and dynamics" notes,
    eqs. (4.39)-(4.40)): frame origin -m a_O, Euler -m alpha x r, centrifugal -m Omega x (Omega x r), Coriolis
    -2 m Omega x v (and their torques on bodies with an attitude). Compiling a scene adds those that act
    (SceneFrame.terms) as elements "FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce" after the
    scene's own (columns of SceneResult.work and power): the centrifugal and Coriolis ones for rotating and earth
    (none at rate 0), none for a FrameMotion.fixed placement, every term for a general motion unless `terms` names
    those that act (a motion turning at a constant rate has no Euler term, one whose origin does not accelerate no
    origin term; each evaluation of the motion then checks that the values of the terms left out are zero, else
    ValueError naming `frame`). Every element, state and record of the scene is then in F. A motion function
    returning a non-finite value raises ValueError naming `frame`; an exception it raises propagates out of
    simulate.
    
    Examples
    --------
    A particle at rest in W, seen from a frame turning at 1 rad/s about z, circles the other way: after a quarter
    turn it is at (0, -1, 0) in F:
    
    >>> frame = rd.SceneFrame.rotating([0.0, 0.0, 1.0], 1.0)
    >>> frame.terms
    ('centrifugal', 'coriolis')
    >>> scene = rd.Scene([rd.Particle(1.0)], frame=frame)
    >>> at_rest_in_W = rd.ParticleState(p_W=(1.0, 0.0, 0.0), v_W=(0.0, -1.0, 0.0))
    >>> result = rd.simulate(scene, [at_rest_in_W], np.pi / 2000, steps=1000, method="rk4")
    >>> result.p_W[-1, 0].round(9)
    array([ 0., -1.,  0.])
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
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: SceneFrame has no public constructor: its static constructors make one (SceneFrame.rotating, ...).
        """
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
    The mass flow of a body: its mass changes at a given rate, its inertia by a rule.
    
    Given to Scene.add_body(body, mass_flow=...) or Scene(..., mass_flows=[...]). The mass starts at the body's mass
    and is a coordinate of the run (SceneResult.mass). Its force is the Thrust element, f = rate u_rel ("Rigid body
    kinematics and dynamics" notes, eq. (4.36): m dv/dt = f + (dm/dt) u_rel). The mass leaving carries its own
    angular momentum (no jet damping): I(m) dw/dt + w x I(m) w = tau. Immutable; pickles (callables defined at
    module level); == compares rate and inertia_rule.
    
    Parameters
    ----------
    rate : float or callable, default 0.0
        dm/dt [kg/s]: a float (or a pint quantity; negative: the body loses mass) or a callable rate(t) -> float of
        the time t [s].
    inertia_rule : {'scaled'} or callable, default 'scaled'
        How the rotational inertia about the centre of mass follows the mass: 'scaled' (I_C(m) = I_C0 m / m0: the
        body's shape is kept; every method applies) or a callable inertia_rule(m) -> (3, 3) [kg m^2] in B of the
        mass m [kg] (the splitting methods are refused).
    
    Raises
    ------
    ValueError
        A non-finite value of a callable (naming mass_flows[i].rate or inertia_rule); a mass reaching zero (naming
        mass_flows[i] and the step; for a constant rate before the run, naming steps and dt).
    
    Notes
    -----
    Callables are called with the GIL taken, at each derivative evaluation; an exception they raise stops the run
    and propagates. The kinetic energy the flow takes away or brings at the body's own velocity,
    1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w integrated, is SceneResult.mass_flow_energy:
    kinetic_energy - kinetic_energy[0] ~ work + mass-flow energy.
    
    Examples
    --------
    A particle of 2 kg losing 0.5 kg/s has 1 kg left after 2 s:
    
    >>> scene = rd.Scene([rd.Particle(2.0)], mass_flows=[rd.MassFlow(rate=-0.5)])
    >>> result = rd.simulate(scene, [rd.ParticleState()], 0.1, duration=2.0, method="rk4")
    >>> result.mass[[0, 10, 20], 0].round(12)
    array([2. , 1.5, 1. ])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rate: float | collections.abc.Callable[..., typing.Any] = 0.0, inertia_rule: typing.Literal['scaled'] | collections.abc.Callable[..., typing.Any] = 'scaled') -> None:
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
class ToleranceError(ValueError):
    """
    simulate(..., tolerance=) could not meet the tolerance: a ValueError with the figures.
    
    Raised when the cost cap (max_steps) would be exceeded, when the certificate of the refined run still fails, when no
    method reached its asymptotic regime in its pilots, or before any run for a model whose forces the certificate
    cannot check (a PythonForce). The message gives the figures (the steps needed, the measured or predicted error).
    
    Parameters
    ----------
    message : str
        The reason, with its figures (raised by simulate; not made by hand).
    
    Attributes
    ----------
    choice : ToleranceChoice or None
        What was chosen and what happened (None for a refusal before any run).
    error : float
        The certified error of the best run, else the predicted error at max_steps, in the measure's unit (NaN for a
        refusal before any run).
    tolerance : float
        The tolerance asked (NaN for a refusal).
    measure : str or None
        The quantity it bounds.
    result : SceneResult or None
        The best run (None when none ran).
    
    See Also
    --------
    simulate, ToleranceChoice
    
    Examples
    --------
    >>> couple = rd.AppliedLoad(torque=[0.0, 0.0, 0.1], frame="body")
    >>> try:
    ...     rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=20.0,
    ...                 loads=couple, tolerance=1e-10, max_steps=8)
    ... except rd.ToleranceError as e:
    ...     print(e.measure, e.tolerance, e.result, "max_steps = 8" in str(e))
    attitude 1e-10 None True
    """
class ToleranceChoice:
    """
    What simulate(..., tolerance=) chose, and why: result.choice.
    
    The planner pilots each candidate method on a short run (16 steps over a quarter of the horizon, shortened and
    refined until its own global error estimate passes its order check), fits the error model
    eps(t) ~ C dt^p (t - t0) (p the order the model has under the method, linear growth in t), and runs the cheapest
    (method, dt) predicted to meet half the tolerance, cost = steps x the seconds per step its pilot measured (so that
    two calls on machines of different speeds, or on one machine under different loads, may choose differently; a run of
    a given method and dt is the same to the bit whatever the machine's pace). When its
    run has 64 steps or more, the chosen method then runs over the whole horizon at a quarter of those steps and its
    largest error, scaled by dt^p, sets the steps (an error that jumps after the short pilot's span is seen). The run's
    global error estimate (GlobalError) is the certificate: when it is not accepted (see met), or above the tolerance,
    the run is refined, dt' = dt (tolerance / 2 / error)^(1/p) (at most dt / 2 when not accepted), and refined again the
    same way while the certificate fails, at most three times (a step that the short pilots called asymptotic may not
    be over the whole horizon: a cluster's close encounters come later).
    
    Parameters
    ----------
    None
        Made by simulate; it has no public constructor. Pickles; == compares every field.
    
    Attributes
    ----------
    method : str
        The method of the final run.
    order : int
        Its order on this model (0: 'exact', the closed form, whose error is its round-off bound).
    dt : float
        Its step [s]; steps : int, its step count (duration / dt, a multiple of lcm(record_every, 4)).
    measure : str
        The quantity the tolerance bounds ('attitude', 'angular_velocity', 'position', 'velocity', 'energy' or
        'angular_momentum'); tolerance : float, the bound, in the measure's unit.
    predicted_error : float
        The error the pilot's fit predicted for the first final run, in the measure's unit (where the run at the
        fewest steps, tried first, met the tolerance: its own estimate).
    certified_error : float
        The largest global error estimate of the measure over the records (and bodies) of the final run; where the
        largest error's own order is not asymptotic, a record accepted only as negligible (an observed order below the
        window) counts its difference d(y_h, y_2h) unextrapolated, as nothing in the run vouches for the power of h that
        Richardson's division presumes (NaN where a record has none).
    met : bool
        The certificate holds: certified_error <= tolerance, and the measure's own estimate (its observed order
        checked alone: result.error's record-wide verdict also checks the other quantities) is accepted on every
        record: reliable, between two reliable records, an observed order above the window (an over-estimate), or an
        estimate <= tolerance / 16 (a zero crossing of an oscillating error, the round-off of the first records).
    refinements : int
        0 to 3: the runs after the first.
    reason : str
        The choice and its outcome, in words.
    pilots : tuple of dict
        One per candidate: method, order, dt, horizon, steps, error, constant (C), seconds_per_step, planned_steps,
        planned_seconds and verdict ('used', or why not: pruned by order, not piloted because another method is exact
        on the scene, because it takes the same steps as another candidate (rkmk4 as rk4 and exact_flow_kick as
        splitting_dlm where no body turns in 3D) or because the first candidate's run over the whole horizon at the
        fewest steps (16) met the tolerance or set at most 64 steps, not asymptotic, ...); the figures a pilot did not
        reach are NaN (a candidate pruned or not piloted has no error, constant or seconds_per_step). A method the model
        does not take is left out, where the planner asked (a candidate not piloted may be one).
    pilot_seconds, run_seconds : float
        Wall time of the pilots, and of the final run(s) with their estimates [s].
    
    See Also
    --------
    simulate, GlobalError, ToleranceError
    
    Examples
    --------
    >>> body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    >>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-6)
    >>> c = r.choice
    >>> c.met, c.measure, bool(c.certified_error <= 1e-6), c.steps * c.dt
    (True, 'attitude', True, 10.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: ToleranceChoice has no public constructor: simulate(..., tolerance=...) returns one as result.choice.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def certified_error(self) -> float:
        """
        The largest estimate of the measure over the final run's records and bodies; where the largest error's order is not asymptotic, a record accepted only as negligible counts its difference d(y_h, y_2h) (NaN: none).
        """
    @property
    def dt(self) -> float:
        """
        The step of the final run [s].
        """
    @property
    def measure(self) -> str:
        """
        The quantity the tolerance bounds (a str).
        """
    @property
    def met(self) -> bool:
        """
        Every record reliable and certified_error <= tolerance.
        """
    @property
    def method(self) -> str:
        """
        The method of the final run (a str).
        """
    @property
    def order(self) -> int:
        """
        Its order on this model (0: 'exact').
        """
    @property
    def pilot_seconds(self) -> float:
        """
        Wall time of the pilots [s].
        """
    @property
    def pilots(self) -> tuple:
        """
        One dict per candidate method (see the class docstring).
        """
    @property
    def predicted_error(self) -> float:
        """
        The error the pilot's fit predicted for the first final run, in the measure's unit (the run at the fewest steps that met the tolerance: its own estimate).
        """
    @property
    def reason(self) -> str:
        """
        The choice and its outcome, in words.
        """
    @property
    def refinements(self) -> int:
        """
        0 to 3: the runs after the first.
        """
    @property
    def run_seconds(self) -> float:
        """
        Wall time of the final run(s) with their estimates [s].
        """
    @property
    def steps(self) -> int:
        """
        The steps of the final run.
        """
    @property
    def tolerance(self) -> float:
        """
        The tolerance, in the measure's unit.
        """
class SceneCompatibilityWarning(UserWarning):
    """
    Warned when a scene is compiled for a method whose properties its elements break (e.g. velocity-dependent forces with a splitting method: order 1 in the damping, energy behaviour not symplectic). A UserWarning.
    """
class Scene:
    """
    Bodies and the force elements acting on them, as data, in a frame.
    
    The bodies are Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat; the elements
    (UniformGravity, SpringDamper, Drag, ...) refer to bodies by index. The frame is W (inertial; the default) or the
    SceneFrame `frame`: states, elements and records are then relative to it, with its fictitious forces compiled in.
    A body may carry a MassFlow (its mass changes; a Thrust element gives its force). Compile it for a method with
    compile(method) (a CompiledScene, immutable), or give it to rigiddyn.simulate / rigiddyn.step, which compile it.
    Mutable (add_body, add, frame); pickles; == compares bodies, names, elements, frame and mass flows.
    
    Parameters
    ----------
    bodies : sequence of bodies, optional
        The bodies, indexed in order (add_body appends more).
    body_names : sequence of str or None, optional
        One name or None per body (records and DataFrame columns use them).
    elements : sequence of force elements, optional
        Checked against the bodies (add bodies first).
    frame : SceneFrame or None, default None
        The frame the states are relative to; None: W.
    mass_flows : sequence of MassFlow or None, optional
        One per body (None: a constant mass).
    
    Raises
    ------
    TypeError, ValueError
        A body, element or frame that is not valid, or an element naming a body that does not exist (the message
        names it).
    
    See Also
    --------
    simulate : runs the scene.
    load_scene : reads one from a TOML file (with units).
    CompiledScene : the scene compiled for one method.
    
    Examples
    --------
    A satellite in a circular low Earth orbit keeps its orbital energy to RK4's error:
    
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.RigidBody(500.0, [400.0, 300.0, 200.0]), name="sat")
    0
    >>> scene.add(rd.PointMassGravity(gm=3.986004418e14))
    0
    >>> start = rd.RigidBodyState(p_W=[7e6, 0.0, 0.0], v_W=[0.0, 7546.0, 0.0])
    >>> result = rd.simulate(scene, [start], dt=1.0, steps=6000, method="rk4")
    >>> result.body_names, result.elements
    (('sat',), ('PointMassGravity',))
    >>> E = result.total_energy
    >>> bool(abs(E[-1] - E[0]) < 1e-12 * abs(E[0]))
    True
    
    The same kind of scene from lists, as repr prints it:
    
    >>> rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity()])
    Scene(bodies=[Particle(mass=1.0)], body_names=[None], elements=[UniformGravity(g_W=[0.0, 0.0, -9.81], bodies=None)])
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def of_body(body: Particle | PlanarBody | RigidBody | PivotedBody | PivotedPlanarBody | Gyrostat, gravity: bool | numpy.typing.ArrayLike | _Quantity | None = None, loads: AppliedLoad | collections.abc.Sequence[AppliedLoad] | None = None) -> Scene:
        """
        The Scene that simulate(body, ..., gravity=, loads=) and step run for one body.
        
        The body alone in W (index 0), with UniformGravity(gravity) when gravity is not zero and ScheduledLoads(body=0,
        loads) when there are loads: each element declared only where it acts. A run of this scene gives the records of
        simulate(body, ...) bitwise. Use it to add elements to a body's run, or to compile it once for many runs.
        
        Parameters
        ----------
        body : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody or Gyrostat
            The body.
        gravity : None, bool, array_like, shape (3,), or pint.Quantity, optional
            Uniform gravity g_W [m/s^2] in W: None or False none, True standard gravity (0, 0, -9.81); on a planar body
            it must lie in the xy plane.
        loads : None, AppliedLoad or sequence of AppliedLoad, optional
            The piecewise-constant schedule of applied loads (simulate's `loads`).
        
        Returns
        -------
        Scene
            One body; its elements: UniformGravity, then ScheduledLoads, those that act.
        
        Raises
        ------
        TypeError
            `body` of another type, `loads` not AppliedLoads.
        ValueError
            Naming `gravity` (not finite; out of a planar body's plane) or `loads[i]` (not finite; a load the body's kind
            cannot take, e.g. a torque on a particle).
        
        Examples
        --------
        >>> scene = rd.Scene.of_body(rd.RigidBody(2.0, [1.0, 2.0, 3.0]), gravity=True)
        >>> [type(e).__name__ for e in scene.elements]
        ['UniformGravity']
        >>> result = rd.simulate(scene, [rd.RigidBodyState(v_W=(1.0, 0.0, 0.0))], 0.01, steps=100, method="rk4")
        >>> result.p_W[-1, 0].round(6)  # x = v t, z = -g t² / 2
        array([ 1.   ,  0.   , -4.905])
        """
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[list, list, list, typing.Any, typing.Any]:
        ...
    def __init__(self, bodies: typing.Any = None, body_names: collections.abc.Sequence[str] | None = None, elements: typing.Any = None, frame: SceneFrame | None = None, mass_flows: collections.abc.Sequence[MassFlow] | None = None) -> None:
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
        Adds `body` (a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat or TreeLink) named `name` (a str no other body has; None: 'body<index>') with its mass flow `mass_flow` (a MassFlow; None: a constant mass); returns its index, by which elements refer to it.
        """
    def add_tree(self, tree: Tree, name: str | None = None) -> tuple:
        """
        Adds every link of `tree` as a body of the scene, in link order; returns their indices.
        
        Each link is a body (a TreeLink) that force elements act on, by its index or name: gravity at its centre of mass,
        springs and drag at its points (given from its centre of mass, in axes parallel to its link frame), Python forces.
        The tree's joints hold the links together: a run integrates the tree's q and v by the articulated-body algorithm
        with the elements' wrenches as each link's external force. Each link body's state is a JointState (its joint's q
        and v; Tree.joint_states makes them), and its records are the link's motion (centre of mass in W, R_WL, w_L).
        
        Parameters
        ----------
        tree : Tree
            The tree (copied), with no gravity of its own (add a UniformGravity element instead).
        name : str, optional
            Names the bodies "<name>.<link name>" (None: each link's own name). No other body may have those names.
        
        Returns
        -------
        tuple of int
            The bodies' indices, one per link.
        
        Raises
        ------
        ValueError
            A tree with no link or with gravity of its own, or a link name another body has (naming it).
        
        See Also
        --------
        Tree, JointState, Tree.joint_states, Tree.coordinates_of
        
        Notes
        -----
        A tree runs with the methods that integrate the whole motion (explicit_euler, semi_implicit_euler, rk4, rkmk4,
        implicit_midpoint); the splittings need each body's free motion in closed form, which joined links do not have.
        
        Examples
        --------
        A double pendulum of two rods released horizontal under gravity keeps its energy to RK4's error:
        
        >>> rod = rd.SpatialInertia(1.0, [0.5, 0, 0], np.diag([1e-3, 1 / 12, 1 / 12]))
        >>> tree = rd.Tree()
        >>> tree.add_link("upper", -1, rd.RevoluteJoint([0, 1, 0]), rod)
        0
        >>> tree.add_link("lower", 0, rd.RevoluteJoint([0, 1, 0]), rod, rd.Transform(translation=[1, 0, 0]))
        1
        >>> scene = rd.Scene(elements=[rd.UniformGravity()])
        >>> scene.add_tree(tree, "pendulum")
        (0, 1)
        >>> result = rd.simulate(scene, tree.joint_states([0.0, 0.0]), 0.001, duration=1.0, method="rk4")
        >>> bool(abs(result.total_energy[-1] - result.total_energy[0]) < 1e-9)
        True
        >>> result.joint_q.shape  # the joint angles at each record
        (1001, 2)
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
    A scene compiled for one method: immutable; its derivative evaluates only the declared elements.
    
    CompiledScene(scene, method='rk4') is scene.compile(method). Give it to rigiddyn.simulate / rigiddyn.step
    (method None or its own). Pickles (as its scene and method); == compares both.
    
    Parameters
    ----------
    scene : Scene
        The bodies and elements (copied: later changes to the scene do not reach it).
    method : str, default 'rk4'
        A name from methods(); a method the scene cannot take is refused here (ValueError naming it).
    
    Examples
    --------
    Compile once, run many times (here the DLM splitting, whose derivative evaluates the declared elements only):
    
    >>> scene = rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity()])
    >>> compiled = scene.compile("splitting_dlm")
    >>> compiled == rd.CompiledScene(scene, "splitting_dlm")
    True
    >>> result = rd.simulate(compiled, [rd.ParticleState()], 0.1, steps=10)
    >>> result.p_W[-1, 0].round(12)
    array([ 0.   ,  0.   , -4.905])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[Scene, str]:
        ...
    def __init__(self, scene: Scene, method: _MethodName = 'rk4') -> None:
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
        tuple of dict, one per compiled term in the order of SceneResult.work's columns (the scene's elements, then the frame's fictitious terms): reads_attitude, velocity_dependent, time_dependent, has_potential (its forces derive from a potential energy), has_torque, has_force, needs_attitude (it skips particles) and zero_net_wrench (its forces sum to zero and so do their moments: internal forces, which add nothing to the impulses) (bool each)
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
    The records of simulate(scene, ...): one row per record, every array read-only.
    
    n records, nb bodies in the scene's order, ne elements in the scene's order; every array shares the memory the
    C++ run filled. "W" is the scene frame: W itself, or the scene's SceneFrame F (every array is then relative to
    F). Made by simulate (no public constructor).
    
    Attributes
    ----------
    t : ndarray, shape (n,)
        Record times [s].
    p_W, v_W : ndarray, shape (n, nb, 3)
        Centre of mass positions [m] and velocities [m/s] in W (a pinned body: its centre of mass).
    q_WB : ndarray, shape (n, nb, 4)
        Attitudes, (x, y, z, w) unless simulate(..., scalar_first=True).
    w_B : ndarray, shape (n, nb, 3)
        Angular velocities [rad/s] in each body's B. A particle records q_WB = identity and w_B = 0; a planar body
        p_W = (x, y, 0), q_WB = Rz(theta), w_B = (0, 0, omega).
    pivot_reaction_W : ndarray, shape (n, nb, 3)
        The pivot's force on each body in W [N] (0 unpinned).
    angular_momentum_O_W : ndarray, shape (n, nb, 3)
        Each body's angular momentum about its pivot (about its centre of mass unpinned), in W [kg m^2/s].
    mass : ndarray, shape (n, nb)
        Masses [kg].
    kinetic_energy, potential_energy, total_energy : ndarray, shape (n,)
        [J]; the kinetic energy relative to W; the potential energy is the sum of the elements' potentials, and the
        centrifugal one of a frame turning at a constant rate (total_energy is then the Jacobi integral).
    linear_momentum_W : ndarray, shape (n, 3)
        [kg m/s] in W.
    angular_momentum_W : ndarray, shape (n, 3)
        About W's origin [kg m^2/s].
    work, power : ndarray, shape (n, ne)
        Each element's work since t0 [J] and its power at the record [W]; the columns are the scene's elements, then
        the frame's fictitious terms that act (CentrifugalForce, CoriolisForce, ...).
    mass_flow_energy : ndarray, shape (n, nb)
        Each body's mass-flow energy since t0 [J]: the integral of 1/2 (dm/dt) |v|^2 + 1/2 w.(dI/dt) w, the kinetic
        energy its mass flow takes away or brings at its own velocity (0 for a constant mass).
    body_names : tuple of str, shape (nb,)
        Label the body axis.
    elements : tuple of str, shape (ne,)
        Each work and power column's class name.
    diverged : bool
        True if the run stopped on a non-finite state.
    unconverged_steps : int
        Steps whose implicit solve stopped at its iteration cap (0 for explicit methods).
    elapsed_seconds : float
        Wall time of the C++ stepping loop [s].
    
    Notes
    -----
    The work-energy balance, integrated by the run's method (to its error):
    kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1) + mass_flow_energy.sum(axis=1) (without a MassFlow the
    last sum is 0: the work alone).
    
    Examples
    --------
    Two particles under gravity: the change of kinetic energy is the work of gravity.
    
    >>> scene = rd.Scene([rd.Particle(2.0), rd.Particle(1.0)], elements=[rd.UniformGravity()])
    >>> result = rd.simulate(scene, [rd.ParticleState(), rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 0.01, steps=100)
    >>> result.t.shape, result.p_W.shape, result.work.shape
    ((101,), (101, 2, 3), (101, 1))
    >>> T = result.kinetic_energy
    >>> bool(np.allclose(T - T[0], result.work.sum(axis=1), atol=1e-12))
    True
    """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: SceneResult has no public constructor: simulate(scene, ...) returns one.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def body(self, key: int | str) -> BodyRecords:
        """
        The records of one body of the run.
        
        Parameters
        ----------
        key : int or str
            The body's index among the result's bodies, in [-nb, nb) (from the end when negative), or its name (an entry of
            body_names).
        
        Returns
        -------
        BodyRecords
            The body's columns of this result's arrays: t (n,), p_W, v_W, w_B (n, 3), q_WB (n, 4), mass (n,), ...
        
        Raises
        ------
        TypeError
            `key` neither an int nor a str.
        ValueError
            An index out of range or a name not in body_names (the message lists the names).
        
        Examples
        --------
        >>> scene = rd.Scene([rd.Particle(2.0), rd.Particle(1.0)], body_names=["a", "b"])
        >>> result = rd.simulate(scene, [rd.ParticleState(), rd.ParticleState(v_W=(1.0, 0.0, 0.0))], 0.1, steps=10)
        >>> result.body("b").p_W[-1]
        array([1., 0., 0.])
        >>> result.body(-1).name
        'b'
        """
    def to_dataframe(self, scalar_first: typing.Any = None, *, units: typing.Any = None) -> typing.Any:
        """
        A pandas.DataFrame of the records (needs pandas): one row per record, one column per scalar with its unit (wide format; rigiddyn.scene_result documents the columns): 't [s]', then per body '<name>:p_W_x [m]' .. '<name>:q_WB_x' .. '<name>:v_W_x [m/s]' .. '<name>:w_B_x [rad/s]' .. through '<name>:mass [kg]' and '<name>:mass_flow_energy [J]' (and a gyrostat's '<name>:wheel_speed_<k> [rad/s]'), then 'kinetic_energy [J]', 'potential_energy [J]', 'total_energy [J]', 'linear_momentum_W_x [kg m/s]' .., 'angular_momentum_W_x [kg m^2/s]' .., then per element i 'work[i] <Class> [J]' and 'power[i] <Class> [W]'; q_WB's columns in the result's order ('<name>:q_WB_w' first when its scalar_first is True). scalar_first: None (the default) for the order the result records; True or False declares the order of its q_WB rows instead. units: the units of the columns, {dimension: unit} (keys length, angle, time, mass, energy, power, force; rigiddyn.output_units), e.g. {'length': 'km', 'time': 'h'} gives 't [h]', '<name>:p_W_x [km]', '<name>:v_W_x [km/h]'; None (the default): SI. TypeError or ValueError naming a bad units (an unknown dimension, an unknown unit, a unit of another dimension).
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
    def balance(self) -> typing.Any:
        """
        The energy and momentum balance of every record (a Balance), or None (a batch result).
        """
    @property
    def body_names(self) -> tuple:
        """
        (nb,) tuple of the bodies' names
        """
    @property
    def choice(self) -> typing.Any:
        """
        What simulate(..., tolerance=) chose and why (a ToleranceChoice), or None (a run at a given dt).
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
    def error(self) -> typing.Any:
        """
        The global error estimate of every record (a GlobalError: per body (n, nb) for the state, per record (n,) for the energy and |L|), or None (simulate(..., error=False)). A run whose balances close makes it on this first read (simulate's error), a batch's sample with its batch's: the same values.
        """
    @property
    def joint_q(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, k) the trees' configurations q, k the sum of their sizes (Scene.add_tree; the trees in the scene's order, each its Tree's q: angles [rad], offsets [m], quaternions (x, y, z, w) as integrated); (n, 0) without a tree
        """
    @property
    def joint_v(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, k) the trees' velocities v, k the sum of their sizes (each its Tree's v: rates [rad/s], [m/s], w_L [rad/s] in the link frame); (n, 0) without a tree
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
class BodyRecords:
    """
    One body's records of a run: its columns of a SceneResult as (n, ...) arrays.
    
    SceneResult.body(key) gives them (a run of one body: result.body(0)); every array is read-only and shares the
    result's memory (the wheels' columns are copies). "W" is the result's scene frame. BatchSceneResult.body(key) gives
    a batch's: every array with the batch's leading sample axis, t (N, n), p_W (N, n, 3), mass (N, n), ...
    
    Attributes
    ----------
    name : str
        The body's name (an entry of SceneResult.body_names).
    index : int
        Its index among the result's bodies, in [0, nb).
    t : ndarray, shape (n,)
        Record times [s].
    p_W, v_W : ndarray, shape (n, 3)
        Centre of mass position [m] and velocity [m/s] in W.
    q_WB : ndarray, shape (n, 4)
        Attitude, (x, y, z, w) unless scalar_first (a particle: the identity; a planar body: Rz(theta)).
    w_B : ndarray, shape (n, 3)
        Angular velocity in B [rad/s] (a planar body: (0, 0, omega)).
    mass : ndarray, shape (n,)
        Mass [kg].
    pivot_reaction_W : ndarray, shape (n, 3)
        The pivot's force on the body in W [N] (0 unpinned).
    angular_momentum_O_W : ndarray, shape (n, 3)
        Angular momentum about the pivot (about the centre of mass unpinned), in W [kg m^2/s].
    angular_momentum_norm : ndarray, shape (n,)
        |angular_momentum_O_W| [kg m^2/s] (conserved by a free body, a torque-free body about its pivot).
    quaternion_norm_error : ndarray, shape (n,)
        |q_WB| - 1: how far the integrated attitude has drifted off the unit sphere (0 for a method that keeps it).
    mass_flow_energy : ndarray, shape (n,)
        The body's mass-flow energy since t0 [J] (0 for a constant mass).
    wheel_speed, motor_work : ndarray, shape (n, nw)
        Each of the body's gyrostat wheels' speed relative to it [rad/s] and motor work since t0 [J] (nw = 0 for a
        body without wheels).
    scalar_first : bool
        True if q_WB's rows are (w, x, y, z).
    
    See Also
    --------
    SceneResult.body, BatchSceneResult.body, simulate
    
    Examples
    --------
    A free rigid body turning about its first axis:
    
    >>> body = rd.RigidBody(mass=2.0, inertia_com=np.diag([1.0, 2.0, 3.0]))
    >>> result = rd.simulate(rd.Scene([body]), [rd.RigidBodyState(w_B=(0.5, 0.0, 0.0))], 0.01, steps=100)
    >>> records = result.body(0)
    >>> records.name, records.q_WB.shape, records.w_B.shape
    ('body0', (101, 4), (101, 3))
    >>> bool(np.allclose(records.q_WB[-1], rd.rotvec_to_quat([0.5, 0.0, 0.0])))
    True
    """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: BodyRecords has no public constructor: SceneResult.body and BatchSceneResult.body return one.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def angular_momentum_O_W(self) -> typing.Any:
        """
        (n, 3) angular momentum about the pivot (about the centre of mass unpinned), in W [kg m^2/s]
        """
    @property
    def angular_momentum_norm(self) -> typing.Any:
        """
        (n,) |angular_momentum_O_W| [kg m^2/s] (a new read-only array)
        """
    @property
    def index(self) -> int:
        """
        Its index among the result's bodies
        """
    @property
    def mass(self) -> typing.Any:
        """
        (n,) mass [kg]
        """
    @property
    def mass_flow_energy(self) -> typing.Any:
        """
        (n,) mass-flow energy since t0 [J]
        """
    @property
    def motor_work(self) -> typing.Any:
        """
        (n, nw) each of its wheels' motor work since t0 [J]
        """
    @property
    def name(self) -> str:
        """
        The body's name (an entry of SceneResult.body_names)
        """
    @property
    def p_W(self) -> typing.Any:
        """
        (n, 3) centre of mass position in W [m]
        """
    @property
    def pivot_reaction_W(self) -> typing.Any:
        """
        (n, 3) the pivot's force on the body, in W [N] (0 unpinned)
        """
    @property
    def q_WB(self) -> typing.Any:
        """
        (n, 4) attitude, (x, y, z, w) unless scalar_first
        """
    @property
    def quaternion_norm_error(self) -> typing.Any:
        """
        (n,) |q_WB| - 1, the integrated attitude's drift off the unit sphere (a new read-only array)
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z)
        """
    @property
    def t(self) -> typing.Any:
        """
        (n,) time [s]
        """
    @property
    def v_W(self) -> typing.Any:
        """
        (n, 3) centre of mass velocity in W [m/s]
        """
    @property
    def w_B(self) -> typing.Any:
        """
        (n, 3) angular velocity in B [rad/s]
        """
    @property
    def wheel_speed(self) -> typing.Any:
        """
        (n, nw) the speed of each of the body's wheels relative to it [rad/s]
        """
class AppliedLoad:
    """
    An applied load: a force through the centre of mass and a couple, on a time window.
    
    Both are expressed in frame 'world' (W) or 'body' (B) and act for t_start <= t < t_end. simulate and step take a
    sequence of them as a piecewise-constant schedule, splitting a step at each t_start and t_end. Immutable;
    pickles; == compares every field.
    
    Parameters
    ----------
    force : array_like, shape (3,), or pint.Quantity, optional
        Force through the centre of mass [N], in `frame` (None: zero).
    torque : array_like, shape (3,), or pint.Quantity, optional
        Torque, a pure couple [N m], in `frame` (None: zero).
    frame : {'world', 'body'}, default 'world'
        Frame of force and torque: W or B.
    t_start : float or pint.Quantity, default -inf
        Start of the window [s].
    t_end : float or pint.Quantity, default inf
        End of the window [s], excluded.
    
    Raises
    ------
    ValueError
        A field of another shape, a non-finite force or torque, an unknown frame, t_end not after t_start, or a
        quantity of another dimension (the message names it).
    
    See Also
    --------
    simulate, step, simulate_batch
    
    Examples
    --------
    2 N on 1 kg for one second, then coasting: v = 2 m/s, and 1 m + 2 m/s x 1 s = 3 m after 2 s:
    
    >>> push = rd.AppliedLoad(force=[2.0, 0.0, 0.0], t_end=1.0)
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.1, steps=20, loads=push).body(0)
    >>> r.v_W[-1].round(12), r.p_W[-1].round(12)
    (array([2., 0., 0.]), array([3., 0., 0.]))
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], str, float, float]:
        ...
    def __init__(self, force: numpy.typing.ArrayLike | _Quantity | None = None, torque: numpy.typing.ArrayLike | _Quantity | None = None, frame: typing.Literal['world', 'body'] = 'world', t_start: float | _Quantity = ..., t_end: float | _Quantity = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def force(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Force through the centre of mass, in `frame`, shape (3,) [N].
        """
    @property
    def frame(self) -> str:
        """
        Frame of force and torque: 'world' (W) or 'body' (B).
        """
    @property
    def t_end(self) -> float:
        """
        End of the window [s], excluded (inf: never ends).
        """
    @property
    def t_start(self) -> float:
        """
        Start of the window [s] (-inf: always on before t_end).
        """
    @property
    def torque(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Torque (a pure couple), in `frame`, shape (3,) [N m].
        """
class GlobalError:
    """
    The global error estimate of a run: result.error of simulate(..., error=True).
    
    At every record, the error of the run at dt is estimated by global Richardson extrapolation: the method also runs at
    2 dt and 4 dt, and for a method of order p
    
        eps ~ d(y_dt, y_2dt) / (2^p - 1),   r = d(y_2dt, y_4dt) / d(y_dt, y_2dt) ~ 2^p.
    
    The distance d is the geodesic angle between attitudes [rad] (angular_distance) and the norm of the difference for
    the other quantities. The estimate is called reliable only where the observed ratio r of every state quantity
    (attitude, angular velocity, position, velocity: each checked over the bodies together) lies in
    [2^p / 1.5, 2^p * 1.5], and that of the energy and |L| in [2^p / 1.5, 2^(p+1) * 1.5] (the error of an invariant may
    fall one order faster than dt^p, e.g. rk4's energy on a linear problem: above 2^p * 1.5 its estimate takes the
    observed order, d / (r - 1)). Elsewhere the verdict names the reason and the number is only indicative:
    "not asymptotic: observed order 1.3 where 4 is expected (attitude)"; "step beyond the stability limit: ..." (a run
    at 2 dt or 4 dt diverged, or its energy departed by more than |T| + |V|); "past the Lyapunov time of this scene:
    ..." (the estimates grew more than 1000 (t / t_k)^4 from an earlier record: nearby trajectories diverge
    exponentially, and the differences leave the linear regime). A ratio above the window is flagged too: it is what an
    error hidden from all three runs alike looks like. Where d is below the round-off bound of the run (8 eps_machine
    per step, relative to the quantity's size; for |L| the size of its terms) the estimate is that bound, with the
    verdict "reliable"; the method 'exact' reports the round-off bound alone (order 0). Measured against exact
    references (docs/accuracy.md): the reliable estimates lie within a factor 2 of the true error. A verdict covers every
    quantity of its record; reliable_for(quantity) gives the records where one quantity's own check passes (a damped
    chain's positions, where its energy's error mixes two orders).
    
    p is the order the run has, not always the method's: a scene whose velocity-dependent element (drag, a damper, a
    PythonForce) meets a kick-based splitting runs at order 1.
    
    The 2dt and 4dt runs have a state only every m = lcm(record_every, 4) steps: the estimate is computed and checked at
    those records; between them it is interpolated linearly in t, and after the last of them (steps not a multiple of
    m) grown linearly in t from t0. Those records are not checked, so their verdict says "interpolated ..." or
    "extrapolated ..." rather than "reliable": pass a record_every and a steps that are multiples of 4 to have every
    record checked. A run of fewer than m steps has no estimate (NaN, with a verdict saying so). At most 1024 records
    after t0 are checked: a longer run's checked records are every k m steps (k the fewest that leave 1024) and its last
    multiple of m, the records between interpolated (each checked record costs the 2dt and 4dt runs a record each and
    the estimate a comparison, ~3.5 rk4 steps of a free body; the error between varies smoothly).
    
    A scene with a PythonForce is never called reliable (verdict "not verified: ..."): a force that switches inside a
    step (an `if t > t_s`) costs every method its order there, and the runs at dt, 2dt and 4dt can take the switch in
    the same step, so that its error cancels in their differences while the order check passes.
    
    simulate_batch gives one GlobalError for the whole batch (BatchResult.error): every array with a leading sample
    axis, the verdict a tuple per sample; sample i's (result[i].error) is the one simulate gives for that sample alone.
    
    Parameters
    ----------
    None
        Made by simulate and simulate_batch; it has no public constructor.
    
    See Also
    --------
    simulate, simulate_batch, SceneResult, angular_distance
    
    Examples
    --------
    rk4 (order 4) on a tumbling body; halving dt divides the estimate by about 2^4 = 16:
    
    >>> body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    >>> state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    >>> coarse = rd.simulate(body, state, dt=0.02, steps=512).error
    >>> fine = rd.simulate(body, state, dt=0.01, steps=1024).error
    >>> coarse.order, coarse.verdict[-1], fine.verdict[-1]
    (4, 'reliable', 'reliable')
    >>> bool(12 < coarse.attitude[-1] / fine.attitude[-1] < 20)
    True
    
    explicit_euler at a coarse step gains energy at every step (its step is beyond its stability limit), and says so
    (its energy balance is off too, which simulate reports with an AccuracyWarning: switched off here to show the
    estimate's own verdict):
    
    >>> rough = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 3.0, 0.1]), dt=0.1, steps=100, method="explicit_euler",
    ...                     accuracy_level=None)
    >>> bool(rough.error.reliable[-1]), rough.error.verdict[-1].startswith("step beyond the stability limit")
    (False, True)
    >>> rough.balance.verdict["energy"].startswith("open")
    True
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: GlobalError has no public constructor: simulate(..., error=True) returns one as result.error.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def max(self) -> dict:
        """
        The largest estimate of each quantity over the records (and bodies).
        
        Returns
        -------
        dict
            {'attitude': rad, 'angular_velocity': rad/s, 'position': m, 'velocity': m/s, 'energy': J,
            'angular_momentum': kg m^2/s}, floats (NaN for a quantity without an estimate).
        
        Examples
        --------
        >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=400)
        >>> sorted(r.error.max()), bool(r.error.max()["attitude"] < 1e-8)
        (['angular_momentum', 'angular_velocity', 'attitude', 'energy', 'position', 'velocity'], True)
        """
    def reliable_for(self, quantity: str) -> numpy.typing.NDArray[numpy.bool]:
        """
        Where the estimate of one quantity is reliable, whatever the others' order checks say.
        
        A record's verdict is 'reliable' only where every quantity passes its order check; one quantity may pass where
        another does not. A damped spring chain's positions err as dt^4 while its total energy, no invariant there, errs
        as a sum of two orders whose ratios r stray from 2^p: the records fail on the energy, and the positions' estimates
        are still within their promise. reliable_for('position') is True at a record checked (a common record, see above)
        where the position's own ratio r lies in its window (or its differences are at round-off) and nothing disqualifies
        the record as a whole: a run at 2 dt or 4 dt beyond the stability limit, an energy balance that contradicts the
        estimate, a PythonForce. Where it is True, the estimate of that quantity keeps the promise of a reliable record
        (within a factor 2 of the true error, docs/accuracy.md). reliable implies reliable_for(q) for every q.
        
        Parameters
        ----------
        quantity : str
            'attitude', 'angular_velocity', 'position', 'velocity', 'energy' or 'angular_momentum'.
        
        Returns
        -------
        numpy.ndarray
            bool, shape (n,) (a batch's (N, n)), read-only.
        
        Raises
        ------
        ValueError
            quantity is not one of the six names (the message names the nearest).
        
        Examples
        --------
        The shipped spring chain (damped) at 2 ms, every 4th step recorded: most records fail on the energy, none on the
        positions:
        
        >>> scene, initial, _ = rd.load_scene("spring_chain")
        >>> e = rd.simulate(scene, initial, dt=0.002, steps=1000, record_every=4).error
        >>> n = len(e.reliable)
        >>> bool(e.reliable.sum() < 0.1 * n and e.reliable_for("position").sum() > 0.9 * n)
        True
        """
    def summary(self) -> str:
        """
        One line: the order, how many records are reliable, the largest estimates, the first other verdict.
        
        Returns
        -------
        str
        
        Examples
        --------
        >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=400,
        ...                 record_every=4)
        >>> r.error.summary().split(";")[0]
        'order 4: 101 of 101 records reliable'
        """
    @property
    def angular_momentum(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of |L| (angular_momentum_norm of a body, |angular_momentum_W| of a scene) [kg m^2/s], shape (n,) (a batch's (N, n)).
        """
    @property
    def angular_velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of w_B, the norm [rad/s], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).
        """
    @property
    def attitude(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of q_WB as a rotation angle [rad], shape (n,) ((n, nb) for a scene; a batch's with a leading sample axis, (N, n) or (N, n, nb)).
        """
    @property
    def energy(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of total_energy [J], shape (n,) (a batch's (N, n)).
        """
    @property
    def observed_order(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        log2 r of the quantity whose ratio r is furthest from 2^p, shape (n,) (a batch's (N, n)); NaN where every quantity is at round-off level or no estimate was computed.
        """
    @property
    def order(self) -> int:
        """
        The order p the estimate assumed: the run's order (0: the method 'exact', round-off bound only).
        """
    @property
    def position(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of p_W, the norm [m], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).
        """
    @property
    def reliable(self) -> numpy.typing.NDArray[numpy.bool]:
        """
        verdict == 'reliable', shape (n,) (bool; a batch's (N, n)).
        """
    @property
    def velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Error of v_W, the norm [m/s], shape (n,) ((n, nb) for a scene; a batch's (N, n) or (N, n, nb)).
        """
    @property
    def verdict(self) -> tuple:
        """
        'reliable' or the reason the estimate is not, per record (a tuple of n str; a batch's: a tuple of N such tuples, one per sample).
        """
class BatchSceneResult:
    """
    The records of simulate_batch: N samples of n records each.
    
    The arrays of SceneResult with a leading sample axis (nb bodies, ne work columns, nw wheels), read-only: t (N, n)
    [s]; p_W, v_W, w_B, pivot_reaction_W, angular_momentum_O_W (N, n, nb, 3); q_WB (N, n, nb, 4); kinetic_energy,
    potential_energy, total_energy (N, n) [J]; linear_momentum_W, angular_momentum_W (N, n, 3); mass,
    mass_flow_energy (N, n, nb) [kg], [J]; work, power (N, n, ne) [J], [W]; wheel_speed, motor_work (N, n, nw).
    body_names and elements label the axes (the first scene's). Frames and units as SceneResult. A diverged
    sample's rows after filled[i] are NaN. len(result) is N; result[i] is sample i as a SceneResult (its filled
    rows, copies, the same scalar_first); result.body(key) is one body's columns (BodyRecords, arrays (N, n, ...));
    pickles.
    
    Parameters
    ----------
    None
        Made by simulate_batch; it has no public constructor.
    
    See Also
    --------
    simulate_batch, SceneResult, BodyRecords
    
    Examples
    --------
    Three balls thrown up at 0, 1 and 2 m/s, after 1 s: z = v t - g t^2 / 2:
    
    >>> scene = rd.Scene()
    >>> ball = scene.add_body(rd.Particle(1.0), name="ball")
    >>> gravity = scene.add(rd.UniformGravity())
    >>> res = rd.simulate_batch(scene, [[rd.ParticleState(v_W=[0, 0, v])] for v in (0.0, 1.0, 2.0)], dt=0.01,
    ...                         steps=100, record_every=100)
    >>> res.p_W.shape, res.body_names, res.elements
    ((3, 2, 1, 3), ('ball',), ('UniformGravity',))
    >>> res.p_W[:, -1, 0, 2].round(12)
    array([-4.905, -3.905, -2.905])
    """
    def __getitem__(self, i: typing.Any) -> typing.Any:
        """
        sample i's records (negative i counts from the end)
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: BatchSceneResult has no public constructor: simulate_batch returns one.
        """
    def __len__(self) -> int:
        """
        N, the number of samples
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def body(self, key: int | str) -> typing.Any:
        """
        The records of one body of every sample.
        
        Parameters
        ----------
        key : int or str
            The body's index among the result's bodies, in [-nb, nb) (from the end when negative), or its name (an entry of
            body_names).
        
        Returns
        -------
        BodyRecords
            The body's columns of this result's arrays with their sample axis: t (N, n), p_W, v_W, w_B (N, n, 3), q_WB
            (N, n, 4), mass (N, n), ...
        
        Raises
        ------
        TypeError
            `key` neither an int nor a str.
        ValueError
            An index out of range or a name not in body_names (the message lists the names).
        
        Examples
        --------
        Two spheres spun up by 1 and 2 N m for 1 s (I = 0.5 kg m^2) turn at 2 and 4 rad/s:
        
        >>> sphere = rd.RigidBody(1.0, [0.5, 0.5, 0.5])
        >>> torques = [[rd.AppliedLoad(torque=(0.0, 0.0, tau))] for tau in (1.0, 2.0)]
        >>> res = rd.simulate_batch(sphere, [rd.RigidBodyState()] * 2, dt=0.01, duration=1.0, loads=torques)
        >>> spin = res.body(0)
        >>> spin.w_B.shape, spin.w_B[:, -1, 2].round(12)
        ((2, 101, 3), array([2., 4.]))
        """
    @property
    def angular_momentum_O_W(self) -> numpy.ndarray:
        """
        Each body's angular momentum about its pivot (its centre of mass unpinned), in W, shape (N, n, nb, 3) [kg m^2/s].
        """
    @property
    def angular_momentum_W(self) -> numpy.ndarray:
        """
        Angular momentum about W's origin, in W, shape (N, n, 3) [kg m^2/s].
        """
    @property
    def body_names(self) -> tuple:
        """
        The bodies' names, a tuple of nb str.
        """
    @property
    def diverged(self) -> numpy.ndarray:
        """
        Per sample, True if its state became non-finite and its run stopped there, shape (N,) (bool).
        """
    @property
    def elapsed_seconds(self) -> float:
        """
        Wall time of the whole batch [s].
        """
    @property
    def elements(self) -> tuple:
        """
        The work columns' class names, a tuple of ne str.
        """
    @property
    def error(self) -> GlobalError | None:
        """
        The global error estimate of every record of every sample (GlobalError, arrays (N, n, ...)); None with simulate_batch(..., error=False). Made on this first read (or a sample's, or a pickle's): two more batches at 2 dt and 4 dt, +0.75x the batch's cost.
        """
    @property
    def filled(self) -> numpy.ndarray:
        """
        Rows filled per sample, shape (N,) (int64): n unless it diverged (its later rows are NaN).
        """
    @property
    def joint_q(self) -> numpy.ndarray:
        """
        The trees' configurations q (Scene.add_tree), shape (N, n, nq); nq = 0 without a tree.
        """
    @property
    def joint_v(self) -> numpy.ndarray:
        """
        The trees' velocities v, shape (N, n, nv).
        """
    @property
    def kinetic_energy(self) -> numpy.ndarray:
        """
        Kinetic energy, the sum over the bodies, shape (N, n) [J].
        """
    @property
    def linear_momentum_W(self) -> numpy.ndarray:
        """
        Linear momentum, the sum of m v_W, in W, shape (N, n, 3) [kg m/s].
        """
    @property
    def mass(self) -> numpy.ndarray:
        """
        Each body's mass, shape (N, n, nb) [kg].
        """
    @property
    def mass_flow_energy(self) -> numpy.ndarray:
        """
        Each body's mass-flow energy since t0, shape (N, n, nb) [J] (0 for a constant mass).
        """
    @property
    def motor_work(self) -> numpy.ndarray:
        """
        Each wheel's motor work since t0, shape (N, n, nw) [J].
        """
    @property
    def p_W(self) -> numpy.ndarray:
        """
        Each body's centre of mass position in W, shape (N, n, nb, 3) [m].
        """
    @property
    def pivot_reaction_W(self) -> numpy.ndarray:
        """
        The pivot's force on each body, in W, shape (N, n, nb, 3) [N].
        """
    @property
    def potential_energy(self) -> numpy.ndarray:
        """
        Potential energy, the sum of the elements' potentials, shape (N, n) [J].
        """
    @property
    def power(self) -> numpy.ndarray:
        """
        Each element's power at the record, shape (N, n, ne) [W].
        """
    @property
    def q_WB(self) -> numpy.ndarray:
        """
        Each body's attitude q_WB (B to W), shape (N, n, nb, 4), (x, y, z, w) unless scalar_first.
        """
    @property
    def scalar_first(self) -> bool:
        """
        True if q_WB's rows are (w, x, y, z): the result of simulate_batch(..., scalar_first=True).
        """
    @property
    def t(self) -> numpy.ndarray:
        """
        Time of each record, shape (N, n) [s].
        """
    @property
    def total_energy(self) -> numpy.ndarray:
        """
        Kinetic + potential energy, shape (N, n) [J].
        """
    @property
    def unconverged_steps(self) -> numpy.ndarray:
        """
        Per sample, steps whose implicit solve stopped at its iteration cap, shape (N,) (int64; 0 for explicit methods).
        """
    @property
    def v_W(self) -> numpy.ndarray:
        """
        Each body's centre of mass velocity in W, shape (N, n, nb, 3) [m/s].
        """
    @property
    def w_B(self) -> numpy.ndarray:
        """
        Each body's angular velocity, in its body frame B, shape (N, n, nb, 3) [rad/s].
        """
    @property
    def wheel_bodies(self) -> tuple:
        """
        The body index of each wheel, a tuple of nw int.
        """
    @property
    def wheel_speed(self) -> numpy.ndarray:
        """
        Each gyrostat wheel's speed relative to its body, shape (N, n, nw) [rad/s] (nw = 0 without a gyrostat).
        """
    @property
    def work(self) -> numpy.ndarray:
        """
        Each element's work since t0, shape (N, n, ne) [J].
        """
class TorqueFreeSolution:
    """
    Exact motion of a torque-free rigid body (Euler-Poinsot) at any time t [s].
    
    The angular velocity w_B(t) in Jacobi's elliptic functions, the attitude q_WB(t) by Legendre's third
    integral (Landau & Lifshitz, Mechanics §37; Celledoni, Fassò, Säfström, Zanna 2008; docs/references.md):
    the solution of I_B dw_B/dt = -w_B x I_B w_B, dq_WB/dt = 1/2 q_WB ⊗ [w_B; 0], which keeps the angular
    momentum L_W = R_WB I_B w_B and the kinetic energy constant. Any finite magnitudes (the motion is computed
    in scaled units).
    
    Parameters
    ----------
    inertia : array_like, shape (3, 3)
        Rotational inertia I_B about the centre of mass, in B [kg m^2], symmetric positive definite and, under
        check=InertiaCheck.physical, with principal moments satisfying the triangle inequality I1 + I2 >= I3.
    q_WB : array_like, shape (4,)
        Initial attitude, B to W, (x, y, z, w) ((w, x, y, z) if `scalar_first`); normalised.
    w_B : array_like, shape (3,)
        Initial angular velocity of B in W, expressed in B [rad/s].
    scalar_first : bool, default False
        Read q_WB, and return the quaternions of state_at, scalar first.
    check : InertiaCheck, default InertiaCheck.physical
        InertiaCheck.allow_unrealizable opts in to test problems such as diag(2, 1, 2/3).
    
    Raises
    ------
    ValueError
        An inertia not symmetric positive definite or, under InertiaCheck.physical, breaking the triangle
        inequality (naming the moments); w_B when a rate of the motion exceeds the double range; inertia when
        its principal moments span so many orders (~1e150 and more) that the parameters of the elliptic
        functions, up to ~(I_max/I_min)^2 in scaled units, exceed it; a non-finite or badly shaped argument.
    
    See Also
    --------
    jacobi_ellipj, ellippi_am, LagrangeTopSolution, simulate
    
    Examples
    --------
    w_B returns after one period; L_W = R_WB I_B w_B stays constant:
    
    >>> I_B = np.diag([1.0, 2.0, 3.0])
    >>> s = rd.TorqueFreeSolution(I_B, [0, 0, 0, 1], [0.1, 1.0, 0.1])
    >>> s.case, round(s.period, 6)
    ('A', 22.996263)
    >>> q_WB, w_B = s.state_at(s.period)
    >>> bool(np.allclose(w_B, [0.1, 1.0, 0.1]))
    True
    >>> q_WB, w_B = s.state_at(3.7)
    >>> bool(np.allclose(rd.quat_rotate(q_WB, I_B @ w_B), s.angular_momentum_W))
    True
    
    Immutable; pickles; == compares the constructor's arguments.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from exactly equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, inertia: numpy.typing.ArrayLike, q_WB: numpy.typing.ArrayLike, w_B: numpy.typing.ArrayLike, scalar_first: bool = False, check: InertiaCheck = InertiaCheck.physical) -> None:
        """
        The exact motion from I_B (3, 3) [kg m^2] about the centre of mass in B, q_WB (4,) and w_B (3,) [rad/s]
        in B at t = 0 (see the class).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def state_at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        State at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s]; negative allowed.
        
        Returns
        -------
        q_WB : ndarray, shape (4,) or (n, 4)
            Attitude, B to W, in the order chosen at construction.
        w_B : ndarray, shape (3,) or (n, 3)
            Angular velocity of B in W, expressed in B [rad/s].
        
        Raises
        ------
        ValueError
            t when a phase (rate times t) exceeds the double range, or t non-finite.
        
        Examples
        --------
        >>> s = rd.TorqueFreeSolution(np.diag([1.0, 2.0, 3.0]), [0, 0, 0, 1], [0.1, 1.0, 0.1])
        >>> [a.shape for a in s.state_at([0.0, 1.0, 2.0])]
        [(3, 4), (3, 3)]
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
        Parameter m = k^2 of the elliptic functions of w_B(t) (dimensionless, in [0, 1]).
        """
    @property
    def parameter_mc(self) -> float:
        """
        Complement 1 - m, computed without cancellation.
        """
    @property
    def period(self) -> float:
        """
        Period of w_B(t) [s] (w_B in B); inf if w_B is constant or on the separatrix. A flip takes half.
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
    
    Parameters
    ----------
    body : PivotedPlanarBody
        Mass [kg], inertia_zz [kg m^2] about C, p_OC_B [m] in B, pivot p_WO [m] in W.
    g_W : array_like, shape (2,) or (3,)
        Uniform gravity in W [m/s^2] (only its xy part acts); a pint quantity is converted.
    state : PivotedPlanarBodyState
        theta [rad] and omega [rad/s] at t = 0.
    
    Raises
    ------
    ValueError
        g_W, state.theta or state.omega non-finite (the message names it).
    TypeError
        body or state of another type.
    
    See Also
    --------
    PivotedPlanarBody, jacobi_ellipj, ellipk, LagrangeTopSolution
    
    Examples
    --------
    A uniform rod 1 m long pinned at its end (I_O = m L^2/3, d = L/2, so w0^2 = 3 g/(2 L)), let go 0.5 rad
    from the bottom, swings back after one period 4 K(k^2)/w0:
    
    >>> rod = rd.PivotedPlanarBody(1.0, 1.0 / 12, [0.5, 0.0])
    >>> s = rd.CompoundPendulumSolution(rod, [0.0, -9.81], rd.PivotedPlanarBodyState(theta=-np.pi / 2 + 0.5))
    >>> s.case, f"{s.omega0**2:.6f}", bool(np.isclose(s.period, 4 * rd.ellipk(s.k_squared) / s.omega0))
    ('libration', '14.715000', True)
    >>> theta, omega = s.at(s.period)
    >>> bool(np.isclose(theta, -np.pi / 2 + 0.5) and abs(omega) < 1e-12)
    True
    
    Immutable; pickles; == compares the constructor's arguments; unhashable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: PivotedPlanarBody, g_W: numpy.typing.ArrayLike, state: PivotedPlanarBodyState) -> None:
        """
        body: a PivotedPlanarBody; g_W: (2,) or (3,) uniform gravity in W [m/s^2] (only its xy part acts);
        state: the PivotedPlanarBodyState (theta [rad], omega [rad/s]) at t = 0. ValueError naming g_W or
        state.theta / state.omega for non-finite values. See the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        State at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s]; negative allowed.
        
        Returns
        -------
        theta : float or ndarray, shape (n,)
            Angle of B in W about z [rad], continuous from the initial theta (not wrapped; a rotating
            pendulum's theta grows).
        omega : float or ndarray, shape (n,)
            Angular velocity about z [rad/s].
        
        Examples
        --------
        >>> s = rd.CompoundPendulumSolution(rd.PivotedPlanarBody(1.0, 1.0 / 12, [0.5, 0.0]), [0.0, -9.81],
        ...                                 rd.PivotedPlanarBodyState(theta=-np.pi / 2, omega=1.0))
        >>> [x.shape for x in s.at([0.0, 1.0, 2.0])]
        [(3,), (3,)]
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
        k^2 = sin^2(v0/2) + (omega0_state/(2 w0))^2, dimensionless, of the initial state (> 1 for a rotation).
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
        theta of the stable equilibrium [rad] in (-pi, pi] (the angle of B in W about z).
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
    
    Parameters
    ----------
    body : PivotedBody
        Its inertia about O (inertia_O) symmetric about the axis O->C to 1e-12 relative, with C off O.
    g_W : array_like, shape (3,)
        Uniform gravity in W [m/s^2], non-zero; a pint quantity is converted.
    state : PivotedBodyState
        q_WB (B to W) and w_B [rad/s] (of B in W, expressed in B) at t = 0.
    scalar_first : bool, default False
        The order of the quaternions at() and q_WN return ((x, y, z, w) by default).
    
    Raises
    ------
    ValueError
        body not symmetric about O->C or with C at O (naming body); g_W zero or non-finite; a motion whose axis
        passes through a vertical (naming state).
    
    See Also
    --------
    PivotedBody, TorqueFreeSolution, CompoundPendulumSolution, ellippi_am
    
    Examples
    --------
    A fast top (w3 = 50 rad/s) let go 0.3 rad from the vertical nods between 0.3 and 0.303 rad and precesses
    near the gyroscopic rate m g l / (I3 w3) = 0.0981 rad/s:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])
    >>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])
    >>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)
    >>> s.case, f"{s.theta_min:.4f} {s.theta_max:.4f} {s.mean_precession_rate:.4f}"
    ('nutation', '0.3000 0.3030 0.0986')
    
    Immutable; pickles; == compares the constructor's arguments; unhashable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, body: PivotedBody, g_W: numpy.typing.ArrayLike, state: PivotedBodyState, scalar_first: bool = False) -> None:
        """
        body: a PivotedBody whose inertia about O (inertia_O) is symmetric about the axis O->C to 1e-12 relative,
        with C off O (ValueError naming body otherwise); g_W: (3,) uniform gravity in W [m/s^2], non-zero;
        state: the PivotedBodyState (q_WB, w_B [rad/s] in B) at t = 0; scalar_first: the order of the quaternions
        at() returns ((x, y, z, w) by default). See the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def angles_at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        Euler angles Z-X-Z of S in N at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s].
        
        Returns
        -------
        phi, theta, psi : float or ndarray, shape (n,)
            Precession (phi(0) = 0), nutation (the tilt of e3 from the upward vertical), spin [rad]; phi and psi
            continuous.
        
        Examples
        --------
        >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])
        >>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])
        >>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)
        >>> phi, theta, psi = s.angles_at(s.nutation_period)
        >>> bool(np.isclose(theta, s.theta_min))
        True
        """
    def at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        State at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s]; negative allowed.
        
        Returns
        -------
        q_WB : ndarray, shape (4,) or (n, 4)
            B to W, in the order chosen at construction.
        w_B : ndarray, shape (3,) or (n, 3)
            Angular velocity of B in W, expressed in B [rad/s].
        
        Examples
        --------
        The energy about O of the state at t = 2 s is the initial one:
        
        >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), [0.0, 0.0, 0.1])
        >>> state = rd.PivotedBodyState(rd.rotvec_to_quat([0.3, 0.0, 0.0]), [0.0, 0.0, 50.0])
        >>> s = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], state)
        >>> later = rd.LagrangeTopSolution(top, [0.0, 0.0, -9.81], rd.PivotedBodyState(*s.at(2.0)))
        >>> bool(np.isclose(later.energy, s.energy))
        True
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
        Kind of motion: 'nutation' or 'sleeping' (e3 vertical, w_B along it).
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
        m = (u2 - u1)/(u3 - u1), the parameter (m = k^2, dimensionless) of sn.
        """
    @property
    def parameter_mc(self) -> float:
        """
        1 - m (dimensionless), computed without cancellation.
        """
    @property
    def q_WN(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4,) the frame N of the Euler angles, N to W (in the order chosen at construction).
        """
    @property
    def roots(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) roots u1 <= u2 <= u3 of the cubic in u = cos(theta) (dimensionless).
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
    
    Parameters
    ----------
    frame : SceneFrame
        F, turning at a constant rate (SceneFrame.rotating or SceneFrame.earth).
    p0_F : array_like, shape (3,)
        Position relative to F's origin at t = 0, in F [m].
    v0_F : array_like, shape (3,)
        Velocity seen from F at t = 0, in F [m/s].
    
    Raises
    ------
    ValueError
        A general moving frame (naming frame), or a non-finite vector (naming it).
    TypeError
        frame not a SceneFrame.
    
    See Also
    --------
    SceneFrame, point_acceleration, FrameTree
    
    Examples
    --------
    A particle at rest in F, 1 m from the axis of a frame turning at 1 rad/s, flies off along the inertial
    tangent; a quarter turn later F sees it at (pi/2, -1, 0):
    
    >>> s = rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating([0, 0, 1.0], 1.0), [1.0, 0, 0], [0, 0, 0])
    >>> p_F, v_F = s.at(np.pi / 2)
    >>> p_F.round(12), s.jacobi_integral
    (array([ 1.57079633, -1.        ,  0.        ]), -0.5)
    
    Immutable; pickles; == compares the constructor's arguments; unhashable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, frame: SceneFrame, p0_F: numpy.typing.ArrayLike, v0_F: numpy.typing.ArrayLike) -> None:
        """
        frame: a SceneFrame turning at a constant rate (SceneFrame.rotating or SceneFrame.earth; ValueError naming
        frame for a general moving frame); p0_F (3,) [m], v0_F (3,) [m/s]: position and velocity relative to F,
        in F, at t = 0. See the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        State at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s].
        
        Returns
        -------
        p_F : ndarray, shape (3,) or (n, 3)
            Position relative to F's origin, in F [m].
        v_F : ndarray, shape (3,) or (n, 3)
            Velocity seen from F, in F [m/s].
        
        Examples
        --------
        The Jacobi integral 1/2|v_F|^2 - 1/2|w x p_F|^2 stays constant:
        
        >>> s = rd.RotatingFrameFreeParticle(rd.SceneFrame.rotating([0, 0, 1.0], 1.0), [1.0, 0, 0], [0, 0, 0])
        >>> p_F, v_F = s.at(np.linspace(0.0, 3.0, 4))
        >>> J = 0.5 * (v_F**2).sum(axis=1) - 0.5 * (np.cross(s.w_F, p_F) ** 2).sum(axis=1)
        >>> bool(np.allclose(J, s.jacobi_integral))
        True
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
        (3,) F's angular velocity relative to W [rad/s], expressed in F.
        """
class ConstantThrustSolution:
    """
    Exact motion of a particle whose mass changes at a constant rate, m(t) = m0 + rate t, with the thrust
    rate u_rel_W along a fixed direction and uniform gravity ("Rigid body kinematics and dynamics" notes, eq. (4.36):
    m v' = m g + rate u_rel): v(t) = v0 + g t + u_rel ln(m(t)/m0), p(t) = p0 + v0 t + g t^2/2 + u_rel t h(x)/x with
    x = rate t/m0, h(x) = (1 + x) ln(1 + x) - x (series near x = 0). Everything in the inertial frame W.
    
    Parameters
    ----------
    m0 : float
        Mass at t = 0 [kg], > 0.
    rate : float
        dm/dt [kg/s] (negative: losing mass).
    u_rel_W : array_like, shape (3,)
        Velocity of the ejected mass relative to the particle, in W [m/s].
    g_W : array_like, shape (3,), optional
        Uniform gravity in W [m/s^2] (None: zero).
    p0_W : array_like, shape (3,), optional
        Position at t = 0 in W [m] (None: zero).
    v0_W : array_like, shape (3,), optional
        Velocity at t = 0 in W [m/s] (None: zero).
    
    Each may be a pint quantity (converted to SI).
    
    Raises
    ------
    ValueError
        m0 <= 0 or a non-finite value (naming the argument).
    
    See Also
    --------
    MassFlow, Thrust
    
    Examples
    --------
    Burning half of the mass at 2000 m/s exhaust speed gives Tsiolkovsky's 2000 ln 2 m/s:
    
    >>> c = rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0])
    >>> p_W, v_W, mass = c.at(50.0)
    >>> mass, bool(np.isclose(v_W[2], 2000 * np.log(2))), bool(np.isclose(c.delta_v(50.0), v_W[2]))
    (50.0, True, True)
    
    Immutable; pickles; == compares the constructor's arguments; unhashable.
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, arg0: typing.Any) -> typing.Any:
        """
        Built from equal arguments (then every state is bitwise equal).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, m0: float, rate: float, u_rel_W: numpy.typing.ArrayLike, g_W: numpy.typing.ArrayLike | None = None, p0_W: numpy.typing.ArrayLike | None = None, v0_W: numpy.typing.ArrayLike | None = None) -> None:
        """
        m0: mass at t = 0 [kg] > 0; rate: dm/dt [kg/s] (negative: losing mass); u_rel_W (3,): velocity of the
        ejected mass relative to the particle, in W [m/s]; g_W (3,) [m/s^2], p0_W (3,) [m], v0_W (3,) [m/s] (None:
        zero). ValueError naming the argument for m0 <= 0 or a non-finite value. See the class.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def at(self, t: float | numpy.typing.ArrayLike) -> tuple:
        """
        State at time t.
        
        Parameters
        ----------
        t : float or array_like, shape (n,)
            Time [s].
        
        Returns
        -------
        p_W : ndarray, shape (3,) or (n, 3)
            Position in W [m].
        v_W : ndarray, shape (3,) or (n, 3)
            Velocity in W [m/s].
        mass : float or ndarray, shape (n,)
            m0 + rate t [kg].
        
        Raises
        ------
        ValueError
            t where the mass m0 + rate t is not positive (burn-out), naming t.
        
        Examples
        --------
        >>> rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).at([0.0, 50.0])[2]
        array([100.,  50.])
        """
    def delta_v(self, m1: float) -> float:
        """
        Tsiolkovsky: the speed the thrust gives while the mass goes from m0 to m1.
        
        Parameters
        ----------
        m1 : float
            The final mass [kg].
        
        Returns
        -------
        float
            |u_rel| ln(m0/m1) [m/s].
        
        Examples
        --------
        >>> f"{rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).delta_v(50.0):.6f}"
        '1386.294361'
        """
    def mass_at(self, t: float) -> float:
        """
        Mass m0 + rate t [kg] at time t (not checked positive).
        
        Parameters
        ----------
        t : float
            Time [s].
        
        Returns
        -------
        float
            m0 + rate t [kg].
        
        Examples
        --------
        >>> rd.ConstantThrustSolution(100.0, -1.0, [0.0, 0.0, -2000.0]).mass_at(10.0)
        90.0
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
        Mass at t = 0 [kg].
        """
    @property
    def rate(self) -> float:
        """
        Rate of change of the mass dm/dt [kg/s].
        """
    @property
    def u_rel_W(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (3,) velocity of the ejected mass relative to the particle, in W [m/s]
        """
class RevoluteJoint:
    """
    A revolute joint: rotation by the angle q [rad] about a fixed axis.
    
    X_J(q) = (Rot(a, q), 0), S = [a; 0] (Featherstone, Rigid Body Dynamics Algorithms, Table 4.1); nq = nv = 1.
    
    Parameters
    ----------
    axis : array_like, shape (3,), default (0, 0, 1)
        The axis a in the joint frame (and the link frame), any non-zero length (normalised).
    
    Raises
    ------
    ValueError
        A zero or non-finite axis.
    
    See Also
    --------
    PrismaticJoint, SphericalJoint, FreeJoint, FixedJoint, Tree
    
    Examples
    --------
    >>> rd.RevoluteJoint([0.0, 0.0, 2.0]).axis
    array([0., 0., 1.])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, axis: numpy.typing.ArrayLike = (0.0, 0.0, 1.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def motion_subspace(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.
        
        The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).
        
        Returns
        -------
        ndarray, shape (6, nv)
        
        Examples
        --------
        >>> rd.RevoluteJoint().motion_subspace().T
        array([[0., 0., 1., 0., 0., 0.]])
        """
    def transform(self, q: numpy.typing.ArrayLike) -> Transform:
        """
        X_J(q): the pose of the successor frame L in the joint frame J.
        
        Parameters
        ----------
        q : array_like, shape (joint.nq,)
            The joint's configuration.
        
        Returns
        -------
        Transform
            X_JL.
        
        Raises
        ------
        ValueError
            q of another size or not finite.
        
        Examples
        --------
        >>> X = rd.RevoluteJoint().transform([np.pi / 2])
        >>> X.rotation.round(12)
        array([[ 0., -1.,  0.],
               [ 1.,  0.,  0.],
               [ 0.,  0.,  1.]])
        """
    @property
    def axis(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The unit axis a, in the joint frame and the link frame.
        """
    @property
    def nq(self) -> int:
        """
        Number of configuration coordinates q of the joint.
        """
    @property
    def nv(self) -> int:
        """
        Number of velocity coordinates qd of the joint.
        """
class PrismaticJoint:
    """
    A prismatic joint: translation by q [m] along a fixed axis.
    
    X_J(q) = (1, a q), S = [0; a] (Featherstone, Rigid Body Dynamics Algorithms, Table 4.1); nq = nv = 1.
    
    Parameters
    ----------
    axis : array_like, shape (3,), default (0, 0, 1)
        The axis a in the joint frame (and the link frame), any non-zero length (normalised).
    
    Raises
    ------
    ValueError
        A zero or non-finite axis.
    
    See Also
    --------
    RevoluteJoint, Tree
    
    Examples
    --------
    >>> rd.PrismaticJoint([3.0, 0.0, 4.0]).axis
    array([0.6, 0. , 0.8])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, axis: numpy.typing.ArrayLike = (0.0, 0.0, 1.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def motion_subspace(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.
        
        The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).
        
        Returns
        -------
        ndarray, shape (6, nv)
        
        Examples
        --------
        >>> rd.PrismaticJoint([1.0, 0.0, 0.0]).motion_subspace().T
        array([[0., 0., 0., 1., 0., 0.]])
        """
    def transform(self, q: numpy.typing.ArrayLike) -> Transform:
        """
        X_J(q): the pose of the successor frame L in the joint frame J.
        
        Parameters
        ----------
        q : array_like, shape (joint.nq,)
            The joint's configuration.
        
        Returns
        -------
        Transform
            X_JL.
        
        Raises
        ------
        ValueError
            q of another size or not finite.
        
        Examples
        --------
        >>> X = rd.PrismaticJoint([1.0, 0.0, 0.0]).transform([0.5])
        >>> X.translation
        array([0.5, 0. , 0. ])
        """
    @property
    def axis(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The unit axis a, in the joint frame and the link frame.
        """
    @property
    def nq(self) -> int:
        """
        Number of configuration coordinates q of the joint.
        """
    @property
    def nv(self) -> int:
        """
        Number of velocity coordinates qd of the joint.
        """
class SphericalJoint:
    """
    A spherical (ball) joint: any rotation about the common origin of the joint and link frames.
    
    Configuration: the unit quaternion q_JL as (x, y, z, w) (nq = 4); velocity: w_L, the angular velocity
    [rad/s] of the link relative to the joint frame, expressed in the link frame (nv = 3). X_J(q) = (R(q_JL), 0),
    S = [1; 0]; Tree.integrate moves q_JL on SO(3): q_JL ⊗ exp(w_L dt / 2).
    
    See Also
    --------
    FreeJoint, RevoluteJoint, Tree
    
    Examples
    --------
    >>> rd.SphericalJoint().nq, rd.SphericalJoint().nv
    (4, 3)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def motion_subspace(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.
        
        The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).
        
        Returns
        -------
        ndarray, shape (6, nv)
        
        Examples
        --------
        >>> rd.SphericalJoint().motion_subspace()[:3]
        array([[1., 0., 0.],
               [0., 1., 0.],
               [0., 0., 1.]])
        """
    def transform(self, q: numpy.typing.ArrayLike) -> Transform:
        """
        X_J(q): the pose of the successor frame L in the joint frame J.
        
        Parameters
        ----------
        q : array_like, shape (joint.nq,)
            The joint's configuration.
        
        Returns
        -------
        Transform
            X_JL.
        
        Raises
        ------
        ValueError
            q of another size or not finite.
        
        Examples
        --------
        >>> X = rd.SphericalJoint().transform([0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)])
        >>> bool(np.allclose(X.rotation, rd.rot_z(np.pi / 2)))
        True
        """
    @property
    def nq(self) -> int:
        """
        Number of configuration coordinates q of the joint.
        """
    @property
    def nv(self) -> int:
        """
        Number of velocity coordinates qd of the joint.
        """
class FreeJoint:
    """
    A free joint: six degrees of freedom (a floating base).
    
    Configuration (nq = 7): (x, y, z, qx, qy, qz, qw), the link origin's position p_JL [m] in the joint frame
    and the unit quaternion q_JL. Velocity (nv = 6): the twist [w_L; v_L] of the link relative to the joint
    frame, expressed in the link frame (angular first; v_L the velocity [m/s] of the link's origin).
    X_J(q) = (R(q_JL), p_JL), S = 1. Tree.integrate: q_JL ⊗ exp(w_L dt / 2) and p_JL + R(q_JL) v_L dt.
    
    See Also
    --------
    SphericalJoint, Tree
    
    Examples
    --------
    >>> rd.FreeJoint().nq, rd.FreeJoint().nv
    (7, 6)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def motion_subspace(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.
        
        The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).
        
        Returns
        -------
        ndarray, shape (6, nv)
        
        Examples
        --------
        >>> rd.FreeJoint().motion_subspace().shape
        (6, 6)
        """
    def transform(self, q: numpy.typing.ArrayLike) -> Transform:
        """
        X_J(q): the pose of the successor frame L in the joint frame J.
        
        Parameters
        ----------
        q : array_like, shape (joint.nq,)
            The joint's configuration.
        
        Returns
        -------
        Transform
            X_JL.
        
        Raises
        ------
        ValueError
            q of another size or not finite.
        
        Examples
        --------
        >>> X = rd.FreeJoint().transform([1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 1.0])
        >>> X.translation
        array([1., 2., 3.])
        """
    @property
    def nq(self) -> int:
        """
        Number of configuration coordinates q of the joint.
        """
    @property
    def nv(self) -> int:
        """
        Number of velocity coordinates qd of the joint.
        """
class FixedJoint:
    """
    A fixed joint (a weld): the link is rigidly attached to its parent at its placement.
    
    X_J = 1, S has no columns, nq = nv = 0.
    
    See Also
    --------
    RevoluteJoint, Tree
    
    Examples
    --------
    >>> rd.FixedJoint().nq, rd.FixedJoint().nv
    (0, 0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def motion_subspace(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The motion subspace S, shape (6, nv), angular rows first, in the successor frame L.
        
        The joint's velocity qd moves L with the twist S qd relative to J (expressed in L).
        
        Returns
        -------
        ndarray, shape (6, nv)
        
        Examples
        --------
        >>> rd.FixedJoint().motion_subspace().shape
        (6, 0)
        """
    def transform(self, q: numpy.typing.ArrayLike) -> Transform:
        """
        X_J(q): the pose of the successor frame L in the joint frame J.
        
        Parameters
        ----------
        q : array_like, shape (joint.nq,)
            The joint's configuration.
        
        Returns
        -------
        Transform
            X_JL.
        
        Raises
        ------
        ValueError
            q of another size or not finite.
        
        Examples
        --------
        >>> X = rd.FixedJoint().transform(np.zeros(0))
        >>> X.is_approx(rd.Transform())
        True
        """
    @property
    def nq(self) -> int:
        """
        Number of configuration coordinates q of the joint.
        """
    @property
    def nv(self) -> int:
        """
        Number of velocity coordinates qd of the joint.
        """
class Tree:
    """
    A kinematic tree of rigid links joined by joints, rooted at the world frame W.
    
    Links are numbered 0, 1, ... in the order added, each after its parent. Link i sits at
    X_λi = X_T X_J(q_i) in its parent λ(i) (W for parent -1): X_T its placement, X_J(q_i) its joint's
    transform. The configuration q (nq,) stacks the joints' coordinates in link order, the velocity
    v (nv,) their velocities (Featherstone, Rigid Body Dynamics Algorithms, ch. 4).
    
    Parameters
    ----------
    gravity : array_like, shape (3,), optional
        Uniform gravity g [m/s²] in W (None: no gravity).
    
    Raises
    ------
    ValueError
        A non-finite gravity.
    
    See Also
    --------
    rnea, crba, aba, forward_kinematics
    
    Examples
    --------
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> tree.nq, tree.nv, tree.link_names
    (1, 1, ['pendulum'])
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        """
        Whether `other` is a Tree with the same gravity and, link by link, the same names, parents, joints, placements and inertias (exact).
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, gravity: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    def add_link(self, name: str, parent: int, joint: RevoluteJoint | PrismaticJoint | SphericalJoint | FreeJoint | FixedJoint, inertia: SpatialInertia, placement: Transform | None = None) -> int:
        """
        Append a link and return its index.
        
        Parameters
        ----------
        name : str
            A name not yet used.
        parent : int
            The parent link's index, -1 for the world (parents are added first).
        joint : RevoluteJoint, PrismaticJoint, SphericalJoint, FreeJoint or FixedJoint
            The joint from the parent to this link.
        inertia : SpatialInertia
            Mass, centre of mass [m] and inertia about it [kg m²], in the link
            frame; positive definite (every principal moment > 0).
        placement : Transform, optional
            X_T: the joint frame in the parent's frame (None: identity).
        
        Returns
        -------
        int
            The new link's index.
        
        Raises
        ------
        ValueError
            A used or empty name, a parent not in [-1, num_links - 1], or an inertia with a zero
            principal moment (a point mass); the message names the link.
        
        Examples
        --------
        >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
        >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
        >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
        0
        >>> tree.add_link("tip", 0, rd.FixedJoint(), bob, rd.Transform(translation=[0.0, 0.0, -1.0]))
        1
        """
    def coordinates_of(self, states: collections.abc.Sequence[JointState]) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        """
        The tree's configuration q and velocity v stacked from its links' JointStates.
        
        The inverse of joint_states: e.g. of the link bodies' states that a scene's step returns.
        
        Parameters
        ----------
        states : sequence of JointState
            One per link, in link order.
        
        Returns
        -------
        q : ndarray, shape (tree.nq,)
        v : ndarray, shape (tree.nv,)
        
        Raises
        ------
        ValueError
            Not one JointState per link, or one that does not fit its joint (naming it).
        
        Examples
        --------
        >>> tree = rd.Tree()
        >>> tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0, 0, -1], np.eye(3)))
        0
        >>> q, v = tree.coordinates_of([rd.JointState([0, 0, 0, 1], [0.0, 0.0, 2.0])])
        >>> q, v
        (array([0., 0., 0., 1.]), array([0., 0., 2.]))
        """
    def integrate(self, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, dt: float) -> numpy.typing.NDArray[numpy.float64]:
        """
        The configuration q ⊕ v dt reached from q moving with velocity v for a time dt [s].
        
        Joint by joint: q + qd dt for revolute and prismatic joints; q_JL ⊗ exp(w_L dt / 2) on SO(3) for a
        quaternion (spherical and free joints; the result is a unit quaternion); p_JL + R(q_JL) v_L dt for
        a free joint's position.
        
        Parameters
        ----------
        q : array_like, shape (tree.nq,)
            Configuration (unit quaternions within 1e-6).
        v : array_like, shape (tree.nv,)
            Velocity.
        dt : float
            Time step [s].
        
        Returns
        -------
        ndarray, shape (tree.nq,)
        
        Raises
        ------
        ValueError
            A wrong size, a non-finite value or a non-unit quaternion (naming it).
        
        Examples
        --------
        A ball joint turning at pi/2 rad/s about z for 1 s:
        
        >>> tree = rd.Tree()
        >>> tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))
        0
        >>> q = tree.integrate(tree.neutral_configuration(), [0.0, 0.0, np.pi / 2], 1.0)
        >>> bool(np.allclose(q, [0.0, 0.0, np.sin(np.pi / 4), np.cos(np.pi / 4)]))
        True
        """
    def joint_states(self, q: numpy.typing.ArrayLike | None = None, v: numpy.typing.ArrayLike | None = None) -> list:
        """
        The links' JointStates of the tree's configuration q and velocity v: one per link, in link order.
        
        Parameters
        ----------
        q : array_like, shape (tree.nq,), optional
            Configuration (None: the neutral one).
        v : array_like, shape (tree.nv,), optional
            Velocity (None: at rest).
        
        Returns
        -------
        list of JointState
            The states of the bodies Scene.add_tree adds for the tree, in their order.
        
        Raises
        ------
        ValueError
            A wrong size, a non-finite value or a non-unit quaternion (naming it).
        
        Examples
        --------
        >>> tree = rd.Tree()
        >>> rod = rd.SpatialInertia(1.0, [0.5, 0, 0], np.diag([1e-3, 0.1, 0.1]))
        >>> tree.add_link("upper", -1, rd.RevoluteJoint([0, 1, 0]), rod)
        0
        >>> tree.add_link("lower", 0, rd.RevoluteJoint([0, 1, 0]), rod, rd.Transform(translation=[1, 0, 0]))
        1
        >>> tree.joint_states([0.1, 0.2], [0.0, -1.0])
        [JointState(q=[0.1], v=[0.0]), JointState(q=[0.2], v=[-1.0])]
        """
    def kinetic_energy(self, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike) -> float:
        """
        Kinetic energy T = sum_i 1/2 v_i . I_i v_i [J] (= 1/2 v^T H(q) v).
        
        Parameters
        ----------
        q : array_like, shape (tree.nq,)
            Configuration.
        v : array_like, shape (tree.nv,)
            Velocity.
        
        Returns
        -------
        float
        
        Raises
        ------
        ValueError
            A wrong size, a non-finite value or a non-unit quaternion.
        
        Examples
        --------
        >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
        >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
        >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
        0
        >>> round(tree.kinetic_energy([0.0], [2.0]), 12)  # 1/2 (0.1 + 1.0) 2^2
        2.2
        """
    def link_index(self, name: str) -> int:
        """
        The index of the link called `name`.
        
        Parameters
        ----------
        name : str
        
        Returns
        -------
        int
        
        Raises
        ------
        ValueError
            No link has that name.
        
        Examples
        --------
        >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
        >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
        >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
        0
        >>> tree.link_index("pendulum")
        0
        """
    def neutral_configuration(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The neutral configuration (nq,): every angle and offset 0, every quaternion (0, 0, 0, 1).
        
        Returns
        -------
        ndarray, shape (tree.nq,)
        
        Examples
        --------
        >>> tree = rd.Tree()
        >>> tree.add_link("base", -1, rd.FreeJoint(), rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))
        0
        >>> tree.neutral_configuration()
        array([0., 0., 0., 0., 0., 0., 1.])
        """
    def potential_energy(self, q: numpy.typing.ArrayLike) -> float:
        """
        Potential energy V = -sum_i m_i g . p_W,Ci [J] of the uniform gravity (0 at W's origin).
        
        Parameters
        ----------
        q : array_like, shape (tree.nq,)
            Configuration.
        
        Returns
        -------
        float
        
        Raises
        ------
        ValueError
            A wrong size, a non-finite value or a non-unit quaternion.
        
        Examples
        --------
        >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
        >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
        >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
        0
        >>> round(tree.potential_energy([0.0]), 12)  # the bob 1 m below W's origin
        -9.81
        """
    @property
    def gravity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Uniform gravity g [m/s²] in W.
        """
    @property
    def inertias(self) -> list:
        """
        The links' SpatialInertias (each in its link frame), in index order.
        """
    @property
    def joints(self) -> list:
        """
        The links' joints (copies), in index order.
        """
    @property
    def link_names(self) -> list:
        """
        The links' names, in index order.
        """
    @property
    def nq(self) -> int:
        """
        Size of the configuration q.
        """
    @property
    def num_links(self) -> int:
        """
        Number of links n.
        """
    @property
    def nv(self) -> int:
        """
        Size of the velocity v (and of accelerations and joint forces).
        """
    @property
    def parents(self) -> list:
        """
        The links' parent indices λ(i) (-1: the world), in index order.
        """
    @property
    def placements(self) -> list:
        """
        The links' placements X_T (Transforms: each joint frame in its parent's frame), in index order.
        """
class JointState:
    """
    The state of a tree link's body in a scene: its joint's coordinates and velocities.
    
    A scene holds one body per link of a tree (Scene.add_tree), and the state of each is its joint's: q_i and v_i, the
    link's segments of the tree's q and v. Tree.joint_states splits a tree's (q, v) into them, Tree.coordinates_of stacks
    them back. A run checks each against its joint (sizes, finite values, a unit quaternion).
    
    Parameters
    ----------
    q : array_like, shape (nq_i,), optional
        The joint's coordinates: an angle [rad] (revolute), an offset [m] (prismatic), a unit quaternion (x, y, z, w)
        (spherical), (p_JL [m], q_JL) (free); nothing for a fixed joint (None: empty).
    v : array_like, shape (nv_i,), optional
        Its velocities: a rate [rad/s] or [m/s], w_L [rad/s] in the link frame (spherical), [w_L; v_L] (free).
    
    Raises
    ------
    ValueError
        q or v not 1-D, or not finite (naming it).
    
    See Also
    --------
    Tree.joint_states, Tree.coordinates_of, Scene.add_tree
    
    Examples
    --------
    >>> s = rd.JointState([0.3], [-1.0])
    >>> s.q, s.v
    (array([0.3]), array([-1.]))
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
        ...
    def __init__(self, q: numpy.typing.ArrayLike | None = None, v: numpy.typing.ArrayLike | None = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def q(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The joint's coordinates, shape (nq_i,).
        """
    @q.setter
    def q(self, arg1: typing.Any) -> None:
        ...
    @property
    def v(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The joint's velocities, shape (nv_i,).
        """
    @v.setter
    def v(self, arg1: typing.Any) -> None:
        ...
class TreeLink:
    """
    A link of a kinematic tree as a body of a scene (made by Scene.add_tree).
    
    Two are equal when they are the same link of equal trees (link by link: names, parents, joints, placements and
    inertias), so that a scene with a tree equals its copies and the scene its file reads back to. A link pickles as
    (its tree, its index); a scene made of unpickled links shares each tree among its links again.
    
    Force elements act on a link as on any body: at its centre of mass, in axes B parallel to its link frame L
    (points on it given from the centre of mass, in those axes); the tree's joints couple the links' motions. A run
    records each link's centre of mass position and velocity in W, its attitude R_WL and its angular velocity in L.
    
    See Also
    --------
    Scene.add_tree, JointState, Tree
    
    Examples
    --------
    >>> tree = rd.Tree()
    >>> tree.add_link("arm", -1, rd.RevoluteJoint([0, 1, 0]), rd.SpatialInertia(2.0, [0.5, 0, 0], np.diag([1e-3, 0.2, 0.2])))
    0
    >>> scene = rd.Scene()
    >>> scene.add_tree(tree)
    (0,)
    >>> link = scene.bodies[0]
    >>> link.name, link.link, link.mass
    ('arm', 0, 2.0)
    """
    __hash__: typing.ClassVar[None] = None
    def __eq__(self, other: typing.Any) -> typing.Any:
        ...
    def __getstate__(self) -> tuple[Tree, int]:
        ...
    def __init__(self, *args: typing.Never, **kwargs: typing.Never) -> None:
        """
        Raises TypeError: TreeLink has no public constructor: Scene.add_tree makes one per link (read as scene.bodies[i]).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: tuple) -> None:
        ...
    @property
    def com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Its centre of mass in the link frame L, shape (3,) [m].
        """
    @property
    def inertia_com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Its inertia about its centre of mass, in axes parallel to the link frame, shape (3, 3) [kg m^2].
        """
    @property
    def link(self) -> int:
        """
        The link's index in its tree.
        """
    @property
    def mass(self) -> float:
        """
        Its mass [kg].
        """
    @property
    def name(self) -> str:
        """
        The link's name in its tree.
        """
    @property
    def tree(self) -> Tree:
        """
        A copy of the tree the link belongs to.
        """
def _steps_of(steps: typing.Any, duration: typing.Any, dt: typing.Any) -> int:
    """
    The step count of a run of simulate(..., steps=, duration=) at one dt [s] (the package's Python front ends check it before their own work); ValueError as simulate's.
    """
def aba(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, tau: numpy.typing.ArrayLike, f_ext: numpy.typing.ArrayLike | None = None) -> numpy.typing.NDArray[numpy.float64]:
    """
    Forward dynamics by the articulated-body algorithm: a = H(q)^-1 (tau - C(q, v, f_ext)).
    
    Featherstone, Rigid Body Dynamics Algorithms, Table 7.1, in O(n); the inverse of rnea.
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,)
        Velocity.
    tau : array_like, shape (tree.nv,)
        Joint forces.
    f_ext : array_like, shape (n, 6), optional
        External force [n; f] on each link, in its link frame (None: none).
    
    Returns
    -------
    ndarray, shape (tree.nv,)
        The acceleration a.
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    See Also
    --------
    rnea, crba
    
    Examples
    --------
    The horizontal pendulum falls with I a = -m g l:
    
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> a = rd.aba(tree, [np.pi / 2], [0.0], [0.0])
    >>> bool(np.isclose(a[0], -9.81 / 1.1))
    True
    """
def align_vectors(a: numpy.typing.ArrayLike, b: numpy.typing.ArrayLike, weights: numpy.typing.ArrayLike | None = None, return_sensitivity: bool = False, scalar_first: bool = False) -> tuple:
    """
    The rotation that best maps vectors b onto vectors a (Wahba's problem).
    
    R minimises 1/2 sum_i w_i |a_i - R b_i|^2, by the SVD of B = sum_i w_i a_i b_i^T (Markley 1988,
    "Attitude determination using vector observations and the singular value decomposition"). SciPy:
    ``Rotation.align_vectors(a, b, weights)``. One pair (N = 1): the smallest rotation taking the
    direction of b to that of a.
    
    Parameters
    ----------
    a, b : array_like, shape (3,) or (N, 3)
        The same vectors observed in two frames: with a in W and b in B the result is q_WB. Lengths act
        as weights (normalise for equal weighting).
    weights : array_like, shape (N,), optional
        Weights >= 0 (default all 1); one may be inf: that primary pair is aligned exactly and the
        others only by the turn about it.
    return_sensitivity : bool, default False
        Also return the sensitivity matrix (not for one pair or an infinite weight).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    q : ndarray, shape (4,)
        The rotation, canonical (w >= 0), (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    rssd : float
        sqrt(sum_i w_i |a_i - R b_i|^2) over the finite weights [unit of a].
    sensitivity : ndarray, shape (3, 3)
        Only with `return_sensitivity`: SciPy's covariance of the rotation-vector error [rad^2 per unit
        of measurement variance].
    
    Raises
    ------
    ValueError
        `b` not of the shape of `a`, `weights` not of shape (N,), or `return_sensitivity` with one pair
        or an infinite weight (each message names the argument).
    
    Warns
    -----
    UserWarning
        When the optimal rotation is not unique or poorly defined (all pairs parallel, or zero weights).
    
    See Also
    --------
    quat_rotate
    
    Examples
    --------
    Vectors measured in B and known in W give the attitude q_WB:
    
    >>> q_WB = rd.rotvec_to_quat([0.3, -0.5, 1.1])
    >>> b = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    >>> q, rssd = rd.align_vectors(rd.quat_rotate(q_WB, b), b)
    >>> np.allclose(q, rd.quat_canonical(q_WB)), rssd < 1e-12
    (True, True)
    """
def angular_distance(q_a: numpy.typing.ArrayLike, q_b: numpy.typing.ArrayLike, scalar_first: bool = False, degrees: bool = False) -> typing.Any:
    """
    Angle of the rotation taking q_a to q_b.
    
    The magnitude of q_a^-1 ⊗ q_b, 2 atan2(|d_xyz|, |d_w|) for d = q_a^-1 ⊗ q_b: in [0, pi], accurate
    near 0 and near pi; a metric on rotations, independent of the quaternions' signs. SciPy:
    ``(r_a.inv() * r_b).magnitude()``.
    
    Parameters
    ----------
    q_a, q_b : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised). A single one is compared with every item of the other.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False
        Return degrees instead of radians.
    
    Returns
    -------
    float or ndarray, shape (n,)
        Angles [rad] in [0, pi] (degrees if `degrees`).
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it
        and, in a stack, the item), a wrong shape, or stacks of different lengths.
    
    See Also
    --------
    quat_to_axis_angle, slerp
    
    Examples
    --------
    q and -q are the same rotation:
    
    >>> q = rd.rotvec_to_quat([0.2, 0.0, 0.0])
    >>> round(rd.angular_distance(q, -q), 12)
    0.0
    >>> rd.angular_distance([0.0, 0.0, 0.0, 1.0], [[0.0, 0.0, 1.0, 0.0]], degrees=True).round(9)
    array([180.])
    """
def angular_momentum(body: RigidBody | PlanarBody | Particle, state: RigidBodyState | PlanarBodyState | ParticleState, point: numpy.typing.ArrayLike | _Quantity | None = None) -> typing.Any:
    """
    Angular momentum about a point P fixed in W, expressed in W.
    
    About P at p_WP ("Rigid body kinematics and dynamics" notes, eq. (4.42) and (4.65); None: the origin O of W):
    
    - RigidBody: H_P = R_WB I w_B + (p_W - p_WP) x m v_W, shape (3,);
    - PlanarBody: H_z = I_zz omega + (p_W - p_WP) x m v_W about the z axis through P, a float;
    - Particle: (p_W - p_WP) x m v_W, shape (3,).
    
    About the centre of mass: point=state.p_W.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody or Particle
        The body.
    state : RigidBodyState, PlanarBodyState or ParticleState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    point : array_like, shape (3,) or (2,), or pint.Quantity, optional
        p_WP, the point P in W [m] (None: the origin of W); shape (2,) for a PlanarBody.
    
    Returns
    -------
    ndarray, shape (3,), or float
        H_P [kg m^2/s] in W; for a PlanarBody, H_z [kg m^2/s] about z.
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    linear_momentum, kinetic_energy
    
    Examples
    --------
    Spin I w = 6 about the centre of mass plus the orbit p_W x m v_W = 2 about the origin:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> s = rd.RigidBodyState(p_W=[1, 0, 0], v_W=[0, 1, 0], w_B=[0, 0, 2])
    >>> rd.angular_momentum(body, s), rd.angular_momentum(body, s, point=s.p_W)
    (array([0., 0., 8.]), array([0., 0., 6.]))
    """
def angular_velocity_from_quat_rate(q: numpy.typing.ArrayLike, dq_dt: numpy.typing.ArrayLike, frame: typing.Literal['body', 'world'] = 'body', scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Angular velocity of an attitude changing at a quaternion rate (the inverse of `quat_rate`).
    
    frame='body': w_B = 2 vec(q* ⊗ dq/dt); frame='world': w_W = 2 vec(dq/dt ⊗ q*). The part of dq_dt
    along q (which would change |q|, not the rotation) is ignored. SciPy has no equivalent.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within
        1e-6 of 1 (then normalised).
    dq_dt : array_like, shape (4,) or (n, 4)
        Quaternion rates [1/s], any finite values, in the order of q; a single q or dq_dt is used with
        every item of the other.
    frame : {'body', 'world'}, default 'body'
        The frame the result is expressed in.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world').
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    ValueError
        `dq_dt` of a wrong shape or non-finite, stacks of different lengths, or `frame` not 'body' or
        'world'.
    
    See Also
    --------
    quat_rate
    
    Examples
    --------
    >>> q = rd.rotvec_to_quat([0.4, -1.0, 0.3])
    >>> dq = rd.quat_rate(q, [1.0, 2.0, 3.0], frame="world")
    >>> rd.angular_velocity_from_quat_rate(q, dq, frame="world").round(12)
    array([1., 2., 3.])
    """
def apply_impulse(body: RigidBody | PlanarBody | Particle, state: RigidBodyState | PlanarBodyState | ParticleState, impulse: numpy.typing.ArrayLike | _Quantity, point: numpy.typing.ArrayLike | _Quantity | None = None, frame: typing.Literal['world', 'body'] = 'world', angular_impulse: numpy.typing.ArrayLike | float | _Quantity | None = None) -> typing.Any:
    """
    The state just after an impulse at a point and an angular impulse.
    
    Impulse-momentum (K. Craig, "Rigid Body Dynamics" slides): m dv = impulse, I dw = p_GP x impulse +
    angular_impulse, with p_GP the point of application from the centre of mass G; the position and the attitude
    do not change.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody or Particle
        The body.
    state : RigidBodyState, PlanarBodyState or ParticleState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    impulse : array_like, shape (3,) or (2,), or pint.Quantity
        The impulse [N s], in `frame`; shape (2,) for a PlanarBody.
    point : array_like, shape (3,) or (2,), or pint.Quantity, optional
        p_GP [m] from the centre of mass, in `frame` (None: the centre of mass). A Particle takes None.
    frame : {'world', 'body'}, default 'world'
        Frame of impulse, point and angular_impulse: W or B. A Particle takes 'world'.
    angular_impulse : array_like, shape (3,), float or pint.Quantity, optional
        An angular impulse (impulsive torque) [N m s] in `frame` (None: none); a float about z for a PlanarBody.
        A Particle takes None.
    
    Returns
    -------
    RigidBodyState, PlanarBodyState or ParticleState
        The state after the impulse.
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    ValueError
        point or angular_impulse given for a Particle, or frame 'body' for it.
    
    Warns
    -----
    RuntimeWarning
        The new velocities are not finite (an overflow).
    
    See Also
    --------
    linear_momentum, angular_momentum
    
    Examples
    --------
    2 N s along y at 1 m along x: dv = J / m, dw_z = (p_GP x J)_z / I_zz = 2 / 3:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> after = rd.apply_impulse(body, rd.RigidBodyState(), impulse=[0, 2.0, 0], point=[1.0, 0, 0])
    >>> after.v_W, after.w_B.round(12)
    (array([0., 1., 0.]), array([0.        , 0.        , 0.66666667]))
    """
def attitude_from_orbit_frame(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike, q_OB: numpy.typing.ArrayLike, w_OB_B: numpy.typing.ArrayLike, frame: str = 'lvlh', scalar_first: bool = False) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Inertial attitude and rate (q_WB, w_B) of an attitude and rate given relative to an orbit frame O.
    
    q_WB = q_WO (x) q_OB and w_B = w_OB_B + R_WB^T w_WO_W (angular velocities add): the initial state of a
    body whose attitude is given relative to LVLH or RSW (q_OB = identity, w_OB_B = 0: a body that holds
    the orbit frame, as a gravity-gradient-stabilised satellite).
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    q_OB : array_like, shape (4,) or (n, 4)
        Attitude of the body B relative to O, unit quaternions (x, y, z, w) ((w, x, y, z) if
        `scalar_first`); norm within 1e-6 of 1 (then normalised).
    w_OB_B : array_like, shape (3,) or (n, 3)
        Angular velocity of B relative to O, expressed in B [rad/s].
    frame : str, default 'lvlh'
        'lvlh': z_O = -r/|r| (nadir), y_O = -h/|h| (opposite the orbit normal h = r x v), x_O = y_O x z_O
        (along-track; along v on a circular orbit), the attitude texts' LVLH with roll, pitch and yaw axes
        x, y, z (Wie, "Space Vehicle Dynamics and Control"). 'rsw': Hill's frame, x_O = r/|r| (R, radial out),
        z_O = h/|h| (W, the orbit normal), y_O = z_O x x_O (S, along-track) (Vallado, "Fundamentals of
        Astrodynamics and Applications").
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    q_WB : ndarray, shape (4,) or (n, 4)
        Attitude of B in W, in the order of the input.
    w_B : ndarray, shape (3,) or (n, 3)
        Angular velocity of B in W, expressed in B [rad/s] (`RigidBodyState`'s w_B).
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
        A quaternion farther than 1e-6 from unit norm (the message names `q_OB`); `frame` not 'lvlh' or
        'rsw'.
    
    See Also
    --------
    attitude_to_orbit_frame, orbit_frame_rotation
    
    Examples
    --------
    Holding LVLH on the circular orbit of the shipped gravity_gradient scene: q_WB = identity there and
    w_B = (0, -n, 0), n = 1.078007612872506e-3 rad/s:
    
    >>> q, w = rd.attitude_from_orbit_frame([0.0, 0.0, -7e6], [7546.053290107541, 0.0, 0.0], [0, 0, 0, 1.0], np.zeros(3))
    >>> q.round(12), (w / 1.078007612872506e-3).round(12) + 0.0
    (array([0., 0., 0., 1.]), array([ 0., -1.,  0.]))
    """
def attitude_to_orbit_frame(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike, q_WB: numpy.typing.ArrayLike, w_B: numpy.typing.ArrayLike, frame: str = 'lvlh', scalar_first: bool = False) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Attitude and rate relative to an orbit frame O of an inertial attitude and rate (q_WB, w_B).
    
    q_OB = q_WO^-1 (x) q_WB and w_OB_B = w_B - R_WB^T w_WO_W: reads a recorded attitude relative to LVLH or
    RSW (the inverse of `attitude_from_orbit_frame`).
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    q_WB : array_like, shape (4,) or (n, 4)
        Attitude of the body B in W, unit quaternions (x, y, z, w) ((w, x, y, z) if `scalar_first`);
        norm within 1e-6 of 1 (then normalised).
    w_B : array_like, shape (3,) or (n, 3)
        Angular velocity of B in W, expressed in B [rad/s].
    frame : str, default 'lvlh'
        'lvlh': z_O = -r/|r| (nadir), y_O = -h/|h| (opposite the orbit normal h = r x v), x_O = y_O x z_O
        (along-track; along v on a circular orbit), the attitude texts' LVLH with roll, pitch and yaw axes
        x, y, z (Wie, "Space Vehicle Dynamics and Control"). 'rsw': Hill's frame, x_O = r/|r| (R, radial out),
        z_O = h/|h| (W, the orbit normal), y_O = z_O x x_O (S, along-track) (Vallado, "Fundamentals of
        Astrodynamics and Applications").
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    q_OB : ndarray, shape (4,) or (n, 4)
        Attitude of B relative to O, in the order of the input.
    w_OB_B : ndarray, shape (3,) or (n, 3)
        Angular velocity of B relative to O, expressed in B [rad/s].
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
        A quaternion farther than 1e-6 from unit norm (the message names `q_WB`); `frame` not 'lvlh' or
        'rsw'.
    
    See Also
    --------
    attitude_from_orbit_frame, orbit_frame_rotation
    
    Examples
    --------
    A body turning at the orbit rate about -y_W on that orbit holds LVLH: no attitude or rate relative to it:
    
    >>> r, v = [0.0, 0.0, -7e6], [7546.053290107541, 0.0, 0.0]
    >>> q, w = rd.attitude_to_orbit_frame(r, v, [0, 0, 0, 1.0], [0.0, -1.078007612872506e-3, 0.0])
    >>> q.round(12), bool(np.abs(w).max() < 1e-18)
    (array([0., 0., 0., 1.]), True)
    """
def axis_angle_to_quat(axis: numpy.typing.ArrayLike, angle: float | numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of the rotation by an angle about an axis (right-hand rule).
    
    q = (sin(angle/2) u, cos(angle/2)), u = axis / |axis|. SciPy:
    ``Rotation.from_rotvec(angle * u).as_quat()``.
    
    Parameters
    ----------
    axis : array_like, shape (3,) or (n, 3)
        Rotation axes, any non-zero finite length (normalised, also beyond the range where |axis|^2
        would overflow or underflow).
    angle : float or array_like, shape (n,)
        Rotation angles [rad] (degrees if `degrees`); a single axis or angle is used with every item of
        the other.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        A zero or non-finite axis, a non-finite angle, a wrong shape, or stacks of different lengths
        (the message names `axis` or `angle`).
    
    See Also
    --------
    quat_to_axis_angle, rotvec_to_quat
    
    Examples
    --------
    >>> rd.axis_angle_to_quat([0.0, 0.0, 2.0], 180.0, degrees=True).round(12)
    array([0., 0., 1., 0.])
    >>> rd.axis_angle_to_quat([1.0, 0.0, 0.0], [0.0, np.pi], scalar_first=True).round(12)
    array([[1., 0., 0., 0.],
           [0., 1., 0., 0.]])
    """
def bias_forces(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    The bias forces C(q, v) = rnea(tree, q, v, 0): Coriolis, centrifugal and gravity terms.
    
    The equation of motion is H(q) a + C(q, v) = tau.
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,)
        Velocity.
    
    Returns
    -------
    ndarray, shape (tree.nv,)
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    See Also
    --------
    rnea, crba
    
    Examples
    --------
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> rd.bias_forces(tree, [np.pi / 2], [3.0]).round(12)  # gravity only: no Coriolis term
    array([9.81])
    """
def box_shell(size: numpy.typing.ArrayLike, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a closed thin-walled box (its six faces).
    
    Edges (a, b, c) along x, y, z, area density s:
    I_xx = 2 s [b c (b^2 + c^2)/12 + a c (c^2/12 + b^2/4) + a b (b^2/12 + c^2/4)], and cyclically.
    
    Parameters
    ----------
    size : array_like, shape (3,)
        Edge lengths (a, b, c) [m] along x, y, z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Area density [kg/m^2], finite and > 0: m = density * area.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (edges along x, y, z).
    
    Raises
    ------
    ValueError
        A `size` entry not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_box, thin_plate, mesh_shell, SpatialInertia.transformed
    
    Examples
    --------
    A thin-walled cube of edge a has I = 5/18 m a^2 about every axis:
    
    >>> rd.box_shell([1.0, 1.0, 1.0], mass=18.0).inertia_com.diagonal().round(12)
    array([5., 5., 5.])
    """
def compose_kinematics(K_AP: FrameKinematics, K_PF: FrameKinematics) -> FrameKinematics:
    """
    Kinematics of F relative to A from those of P relative to A and of F relative to P.
    
    R_AF = R_AP R_PF; the addition theorem w_AF = w_AP + w_PF; alpha_AF = alpha_AP + alpha_PF + w_AP x w_PF;
    F's origin by the point formulas of the "Rigid body kinematics and dynamics" notes, (4.38), (4.39).
    
    Parameters
    ----------
    K_AP : FrameKinematics
        P relative to A, expressed in A.
    K_PF : FrameKinematics
        F relative to P, expressed in P.
    
    Returns
    -------
    FrameKinematics
        F relative to A, expressed in A.
    
    Raises
    ------
    TypeError
        An argument not a FrameKinematics (naming it).
    
    See Also
    --------
    relative_kinematics, FrameTree.kinematics
    
    Examples
    --------
    P spins at 1 rad/s about z; F, 2 m along P's x, spins at 1 rad/s about P's x:
    
    >>> K_AP = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 1.0])
    >>> K_PF = rd.FrameKinematics(w_PF_P=[1.0, 0.0, 0.0], p_PF_P=[2.0, 0.0, 0.0])
    >>> K_AF = rd.compose_kinematics(K_AP, K_PF)
    >>> K_AF.w_PF_P, K_AF.alpha_PF_P, K_AF.v_PF_P, K_AF.a_PF_P
    (array([1., 0., 1.]), array([0., 1., 0.]), array([0., 2., 0.]), array([-2.,  0.,  0.]))
    """
def composite(parts: typing.Any) -> SpatialInertia:
    """
    Mass properties of a body made of parts (exact).
    
    Masses add, the centre of mass is the mass-weighted mean, and each part's inertia is moved to the
    common centre of mass by the parallel-axis theorem (Craig):
    I_C = sum_k R_k I_Ck R_k^T + m_k (|r_k|^2 1 - r_k r_k^T), r_k the part's centre of mass relative to the
    composite's.
    
    Parameters
    ----------
    parts : sequence of SpatialInertia, or of (Transform, SpatialInertia) pairs
        The parts, all expressed in one frame A; or pairs (X_AB, part) with each part expressed in its own
        frame B and placed in A by the Transform X_AB. The first item sets the form of all. Not empty.
    
    Returns
    -------
    SpatialInertia
        Total mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.
    
    Raises
    ------
    TypeError
        `parts` not a sequence, or an item not of the form of parts[0] (the message names it).
    ValueError
        `parts` empty.
    
    Warns
    -----
    RuntimeWarning
        A result that overflowed to a non-finite value.
    
    See Also
    --------
    SpatialInertia.transformed, SpatialInertia.remove, from_point_masses
    
    Examples
    --------
    Two half cubes side by side make the whole cube:
    
    >>> half = rd.solid_box([0.5, 1.0, 1.0], mass=1.0)
    >>> X_AL = rd.Transform(translation=[-0.25, 0, 0])
    >>> X_AR = rd.Transform(translation=[0.25, 0, 0])
    >>> rd.composite([(X_AL, half), (X_AR, half)]).is_approx(rd.solid_box([1.0, 1.0, 1.0], mass=2.0))
    True
    """
def crba(tree: Tree, q: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    The joint-space inertia matrix H(q) by the composite-rigid-body algorithm.
    
    Featherstone, Rigid Body Dynamics Algorithms, Table 6.2: symmetric positive definite, with
    T = 1/2 v^T H v.
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    
    Returns
    -------
    ndarray, shape (tree.nv, tree.nv)
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    See Also
    --------
    rnea, aba
    
    Examples
    --------
    The pendulum's moment of inertia about its axis, I_C + m l²:
    
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> rd.crba(tree, [0.3]).round(12)
    array([[1.1]])
    """
def davenport_to_quat(axes: numpy.typing.ArrayLike, order: str, angles: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of Davenport angles (rotations about three arbitrary axes).
    
    SciPy: ``Rotation.from_davenport(axes, order, angles).as_quat()``.
    
    Parameters
    ----------
    axes : array_like, shape (3, 3)
        The rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2 orthogonal to n1 and
        to n3 (|cos| <= 1e-7, as SciPy). Coordinate axes give Euler angles.
    order : str
        'e' or 'extrinsic' (fixed axes, R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i' or 'intrinsic' (moving
        axes, R = R_n1(a1) R_n2(a2) R_n3(a3)), as SciPy's `Rotation.from_davenport` / `as_davenport`.
    angles : array_like, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`), in the order of the axes.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        `axes` not of shape (3, 3), with a zero row or with n2 not orthogonal to n1 and n3 (the message
        names `axes`); `order` not one of 'e', 'extrinsic', 'i', 'intrinsic'.
    ValueError
        A non-finite angle or a wrong shape (the message names `angles`).
    
    See Also
    --------
    quat_to_davenport, euler_to_quat
    
    Examples
    --------
    Coordinate axes give Euler angles:
    
    >>> q = rd.davenport_to_quat(np.eye(3), "extrinsic", [0.1, 0.2, 0.3])
    >>> np.allclose(q, rd.euler_to_quat("xyz", [0.1, 0.2, 0.3]))
    True
    """
def default_thread_count() -> int:
    """
    The number of hardware threads, at least 1.
    
    simulate_batch runs on this many threads when threads=None.
    
    Parameters
    ----------
    None
    
    Returns
    -------
    int
        The hardware thread count (1 where it is unknown).
    
    See Also
    --------
    simulate_batch
    
    Examples
    --------
    >>> rd.default_thread_count() >= 1
    True
    """
def eccentric_to_mean_anomaly(E: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    Mean anomaly of the eccentric or hyperbolic anomaly: Kepler's equation.
    
    M = E - e sin E for 0 <= e < 1, M = e sinh H - H for e > 1 (Curtis, "Orbital Mechanics for Engineering
    Students", sec. 3.4 and 3.6), evaluated as (1 - e) E + e (E - sin E) and (e - 1) H + e (sinh H - H)
    with series for E - sin E and sinh H - H near 0: to a few ulps of M also near periapsis as e -> 1.
    M = n t grows linearly in the time t since periapsis (n = sqrt(mu/|a|^3)).
    
    Parameters
    ----------
    E : float or array_like, shape (n,)
        Eccentric anomaly (e < 1) or hyperbolic anomaly (e > 1) [rad].
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0: 0 <= e < 1 an ellipse, e > 1 a hyperbola.
    
    Returns
    -------
    float or ndarray, shape (n,)
        M [rad].
    
    Raises
    ------
    ValueError
        A non-finite value, e < 0 or e = 1 (the message names the argument).
    
    Warns
    -----
    RuntimeWarning
        M overflows (|H| > 710 on a hyperbola).
    
    See Also
    --------
    mean_to_eccentric_anomaly, true_to_mean_anomaly
    
    Examples
    --------
    Curtis's Example 3.1 (e = 0.37255, E = 1.7281 rad):
    
    >>> round(rd.eccentric_to_mean_anomaly(1.7281, 0.37255), 4)
    1.3601
    """
def eccentric_to_true_anomaly(E: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    True anomaly of the eccentric anomaly E (ellipse) or hyperbolic anomaly H (hyperbola).
    
    tan(nu/2) = sqrt((1 + e)/(1 - e)) tan(E/2) for 0 <= e < 1, keeping E's revolutions;
    tan(nu/2) = sqrt((e + 1)/(e - 1)) tanh(H/2) for e > 1, |nu| < acos(-1/e) (Curtis, "Orbital
    Mechanics for Engineering Students", ch. 3).
    
    Parameters
    ----------
    E : float or array_like, shape (n,)
        Eccentric anomaly (e < 1) or hyperbolic anomaly (e > 1) [rad].
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0: 0 <= e < 1 an ellipse, e > 1 a hyperbola.
    
    Returns
    -------
    float or ndarray, shape (n,)
        nu [rad].
    
    Raises
    ------
    ValueError
        A non-finite value, e < 0 or e = 1 (the message names the argument).
    
    See Also
    --------
    true_to_eccentric_anomaly, mean_to_true_anomaly
    
    Examples
    --------
    The round trip through the eccentric anomaly:
    
    >>> E = rd.true_to_eccentric_anomaly(2.0, 0.7)
    >>> round(rd.eccentric_to_true_anomaly(E, 0.7), 12)
    2.0
    """
def elements_to_state(elements: numpy.typing.ArrayLike, mu: float) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Position and velocity of classical orbital elements (Vallado's COE2RV).
    
    r_W = p/(1 + e cos nu) (cos nu P + sin nu Q), v_W = sqrt(mu/p) (-sin nu P + (e + cos nu) Q), with
    [P Q W] = R_z(raan) R_x(i) R_z(argp) (Vallado, "Fundamentals of Astrodynamics and Applications", ch. 2,
    COE2RV; Curtis, "Orbital Mechanics for Engineering Students", algorithm 4.5). Every conic, the
    parabola e = 1 included (through p). The special cases of `state_to_elements` (Omega = 0 when
    equatorial, omega = 0 when circular, the next angle carrying theirs) need nothing special here.
    
    Parameters
    ----------
    elements : array_like, shape (6,) or (n, 6)
        (p, e, i, raan, argp, nu): semi-latus rectum p > 0 [m] (`semi_latus_rectum` of a semi-major axis),
        eccentricity e >= 0, inclination i, right ascension of the ascending node raan, argument of
        periapsis argp and true anomaly nu [rad], each finite; for e >= 1, 1 + e cos(nu) > 0.
    mu : float
        Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).
    
    Returns
    -------
    r_W : ndarray, shape (3,) or (n, 3)
        Position relative to the central body in the inertial frame W [m] (xy the reference plane).
    v_W : ndarray, shape (3,) or (n, 3)
        Velocity in W [m/s].
    
    Raises
    ------
    ValueError
        `mu` not > 0; p <= 0, e < 0, a non-finite element, or nu beyond a hyperbola's asymptotes (the
        message names p, e, i, raan, argp or nu and, in a stack, the item).
    
    See Also
    --------
    state_to_elements, semi_latus_rectum
    
    Examples
    --------
    Curtis's Example 4.7 (km and km/s: h = 80000 km^2/s, e = 1.4, i = 30, raan = 40, argp = 60, nu = 30 deg):
    
    >>> mu = 398600.0
    >>> p = 80000.0**2 / mu
    >>> r, v = rd.elements_to_state([p, 1.4, *np.radians([30.0, 40.0, 60.0, 30.0])], mu)
    >>> r.round(0), v.round(3)
    (array([-4040.,  4815.,  3629.]), array([-10.386,  -4.772,   1.744]))
    """
def ellipk(m: float, mc: float | None = None) -> float:
    """
    Complete elliptic integral of the first kind K(m).
    
    K(m) = int_0^{pi/2} dt / sqrt(1 - m sin^2 t) = R_F(0, mc, 1), the quarter period of the Jacobi elliptic
    functions. The argument is the parameter m = k^2 (k the modulus), as scipy.special.ellipk takes it. K is
    computed from the complement mc, so that K ~ ln(16/mc)/2 keeps full relative precision as m -> 1.
    
    Parameters
    ----------
    m : float
        Parameter m = k^2, 0 <= m <= 1.
    mc : float, optional
        Its complement 1 - m, in [0, 1] and equal to 1 - m to within 4 eps (default: computed as
        1 - m). Pass it near m = 1, where 1 - m loses digits.
    
    Returns
    -------
    float
        K(m); inf at mc = 0.
    
    Raises
    ------
    ValueError
        m or mc outside [0, 1], non-finite, or mc not 1 - m (the message names it).
    
    See Also
    --------
    elliprf, ellippi, jacobi_ellipj
    scipy.special.ellipk : The same function of m; scipy.special.ellipkm1 takes mc.
    
    Examples
    --------
    K(0) = pi/2 and K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi)):
    
    >>> rd.ellipk(0.0) == np.pi / 2
    True
    >>> from math import gamma
    >>> bool(np.isclose(rd.ellipk(0.5), gamma(0.25) ** 2 / (4 * np.sqrt(np.pi))))
    True
    
    Near m = 1, given mc, K follows ln(16/mc)/2 (m = 1 - 1e-20 rounds to 1.0):
    
    >>> f"{rd.ellipk(1.0, mc=1e-20):.9f} {np.log(16 / 1e-20) / 2:.9f}"
    '24.412145291 24.412145291'
    """
def ellippi(n: float, m: float, mc: float | None = None) -> float:
    """
    Complete elliptic integral of the third kind Pi(n|m).
    
    Pi(n|m) = int_0^{pi/2} dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)) for the characteristic n < 1 and the
    parameter m = k^2 (as scipy.special.ellipk takes it). A few ulps for n <= 0.9; relative error
    ~eps/(1 - n) nearer 1.
    
    Parameters
    ----------
    n : float
        Characteristic, n < 1.
    m : float
        Parameter m = k^2, 0 <= m < 1.
    mc : float, optional
        Its complement 1 - m, > 0 and equal to 1 - m to within 4 eps (default: computed as 1 - m).
    
    Returns
    -------
    float
        Pi(n|m), finite.
    
    Raises
    ------
    ValueError
        n >= 1 (naming n); m or mc outside [0, 1] or mc not 1 - m; mc = 0, where Pi(n|1) diverges
        (naming mc).
    
    See Also
    --------
    ellippi_am, ellipk, elliprj
    scipy.special.elliprj : SciPy has no Pi(n|m); it is elliprf(0, 1 - m, 1) + n/3 elliprj(0, 1 - m, 1, 1 - n).
    
    Examples
    --------
    Pi(0|m) = K(m), and Pi(n|0) = pi / (2 sqrt(1 - n)):
    
    >>> bool(np.isclose(rd.ellippi(0.0, 0.5), rd.ellipk(0.5)))
    True
    >>> bool(np.isclose(rd.ellippi(0.5, 0.0), np.pi / (2 * np.sqrt(0.5))))
    True
    """
def ellippi_am(u: float | numpy.typing.ArrayLike, n: float, m: float, mc: float | None = None) -> typing.Any:
    """
    Incomplete elliptic integral of the third kind at the amplitude am u, Pi(am u, n|m).
    
    Pi(am u, n|m) = int_0^u dv / (1 - n sn^2(v|m)) for any finite u (mpmath.ellippi(n, am(u), m)), the
    parameter m = k^2; Pi(am(u + 2K), n|m) = Pi(am u, n|m) + 2 Pi(n|m), K = K(m).
    
    Parameters
    ----------
    u : float or array_like, shape (n,)
        Argument of the Jacobi functions, finite.
    n : float
        Characteristic, n < 1.
    m : float
        Parameter m = k^2, 0 <= m <= 1.
    mc : float, optional
        Its complement 1 - m, equal to 1 - m to within 4 eps (default: computed as 1 - m).
    
    Returns
    -------
    float or ndarray, shape (n,)
        Pi(am u, n|m), of u's shape; +-inf with a RuntimeWarning where it exceeds the double range
        (|u| near it).
    
    Raises
    ------
    ValueError
        n >= 1, m or mc outside [0, 1] or mc not 1 - m, u non-finite or of another shape (the
        message names it).
    
    See Also
    --------
    ellippi, jacobi_ellipj
    
    Notes
    -----
    SciPy has no incomplete integral of the third kind: for |am u| <= pi/2 it is
    s R_F(c^2, d^2, 1) + (n/3) s^3 R_J(c^2, d^2, 1, 1 - n s^2) with (s, c, d) = (sn, cn, dn)(u|m)
    (scipy.special.ellipj, elliprf, elliprj).
    
    Examples
    --------
    At u = K(m) it is the complete integral; for m = 0 (am u = u), atan(sqrt(1 - n) tan u) / sqrt(1 - n):
    
    >>> K = rd.ellipk(0.5)
    >>> bool(np.isclose(rd.ellippi_am(K, 0.3, 0.5), rd.ellippi(0.3, 0.5)))
    True
    >>> bool(np.isclose(rd.ellippi_am(0.7, 0.4, 0.0), np.arctan(np.sqrt(0.6) * np.tan(0.7)) / np.sqrt(0.6)))
    True
    >>> rd.ellippi_am([0.0, 2 * K], 0.3, 0.5) / rd.ellippi(0.3, 0.5)
    array([0., 2.])
    """
def elliprf(x: float, y: float, z: float) -> float:
    """
    Carlson's symmetric elliptic integral of the first kind R_F(x, y, z).
    
    R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t + x)(t + y)(t + z)) (DLMF 19.16.1), symmetric in its arguments,
    to a few ulps for finite arguments of any magnitude (1e-300 to 1e300 together). K(m) = R_F(0, 1 - m, 1).
    
    Parameters
    ----------
    x, y, z : float
        Finite, >= 0, at most one of them zero.
    
    Returns
    -------
    float
        R_F(x, y, z) (it never exceeds the double range).
    
    Raises
    ------
    ValueError
        An argument negative or non-finite, or two of them zero (the message names it).
    
    See Also
    --------
    elliprj, ellipk
    scipy.special.elliprf : The same function (same argument order).
    
    Examples
    --------
    R_F(0, 1, 1) = K(0) = pi/2, and R_F(x, x, x) = 1/sqrt(x):
    
    >>> bool(np.isclose(rd.elliprf(0.0, 1.0, 1.0), np.pi / 2))
    True
    >>> bool(np.isclose(rd.elliprf(2.0, 2.0, 2.0), 1 / np.sqrt(2.0)))
    True
    """
def elliprj(x: float, y: float, z: float, p: float) -> float:
    """
    Carlson's symmetric elliptic integral of the third kind R_J(x, y, z, p).
    
    R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t + p) sqrt((t + x)(t + y)(t + z))) (DLMF 19.16.2), symmetric in
    x, y, z, to a few ulps for finite arguments of any magnitude; Pi(n|m) = R_F(0, 1 - m, 1) +
    (n/3) R_J(0, 1 - m, 1, 1 - n).
    
    Parameters
    ----------
    x, y, z : float
        Finite, >= 0, at most one of them zero.
    p : float
        Finite, > 0.
    
    Returns
    -------
    float
        R_J(x, y, z, p); inf with a RuntimeWarning where it exceeds the double range (R_J ~
        1/sqrt(x y z p) for tiny arguments), 0 or a subnormal below it.
    
    Raises
    ------
    ValueError
        x, y or z negative, two of them zero, p <= 0, or a non-finite argument (the message names
        it).
    
    See Also
    --------
    elliprf, ellippi
    scipy.special.elliprj : The same function (same argument order).
    
    Examples
    --------
    R_J(x, x, x, x) = x^(-3/2):
    
    >>> rd.elliprj(4.0, 4.0, 4.0, 4.0)
    0.125
    """
def euler_to_matrix(seq: str, angles: numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotation matrix of Euler angles.
    
    Extrinsic 'xyz' is R = R_z(a3) R_y(a2) R_x(a1), intrinsic 'XYZ' is R = R_x(a1) R_y(a2) R_z(a3).
    SciPy: ``Rotation.from_euler(seq, angles).as_matrix()``.
    
    Parameters
    ----------
    seq : str
        The axis sequence, 3 letters as SciPy's: lowercase 'xyz' = extrinsic (rotations about the
        fixed axes of W), uppercase 'XYZ' = intrinsic (about the moving axes); the 12 sequences xyz xzy
        yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    angles : array_like, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`), in the order of `seq`.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R, orthonormal with det +1.
    
    Raises
    ------
    ValueError
        `seq` not one of the 24 sequences.
    TypeError
        `seq` not a str.
    ValueError
        A non-finite angle or a wrong shape (the message names `angles`).
    
    See Also
    --------
    matrix_to_euler, euler_to_quat, rot_x
    
    Examples
    --------
    >>> R = rd.euler_to_matrix("xyz", [0.1, 0.2, 0.3])
    >>> np.allclose(R, rd.rot_z(0.3) @ rd.rot_y(0.2) @ rd.rot_x(0.1))
    True
    """
def euler_to_quat(seq: str, angles: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of Euler angles.
    
    SciPy: ``Rotation.from_euler(seq, angles).as_quat()``.
    
    Parameters
    ----------
    seq : str
        The axis sequence, 3 letters as SciPy's: lowercase 'xyz' = extrinsic (rotations about the
        fixed axes of W), uppercase 'XYZ' = intrinsic (about the moving axes); the 12 sequences xyz xzy
        yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    angles : array_like, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`), in the order of `seq`.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        `seq` not one of the 24 sequences.
    TypeError
        `seq` not a str.
    ValueError
        A non-finite angle or a wrong shape (the message names `angles`).
    
    See Also
    --------
    quat_to_euler, euler_to_matrix, davenport_to_quat
    
    Examples
    --------
    Yaw, pitch and roll (intrinsic z-y'-x''); a yaw alone is a turn about z:
    
    >>> rd.euler_to_quat("ZYX", [90.0, 0.0, 0.0], degrees=True)
    array([0.        , 0.        , 0.70710678, 0.70710678])
    >>> q = rd.euler_to_quat("ZYX", [0.1, 0.2, 0.3])
    >>> np.allclose(rd.quat_to_matrix(q), rd.rot_z(0.1) @ rd.rot_y(0.2) @ rd.rot_x(0.3))
    True
    """
def force_cross_matrix(motion: Motion) -> numpy.typing.NDArray[numpy.float64]:
    """
    Force cross-product matrix crf(V) (Featherstone, "Rigid Body Dynamics Algorithms").
    
    crf(V) = [[hat(w), hat(v)], [0, hat(w)]] = -crm(V)^T for V = [w; v] (angular first), so that
    crf(V) F = V x* F (Motion.cross_force), as in the Newton-Euler equation I a + V x* I V.
    
    Parameters
    ----------
    motion : Motion
        V = [w; v] ([rad/s], [m/s]).
    
    Returns
    -------
    ndarray, shape (6, 6)
        crf(V), in V's frame (hat(w) blocks [rad/s], hat(v) block [m/s]).
    
    Raises
    ------
    TypeError
        motion not a Motion.
    
    See Also
    --------
    motion_cross_matrix, Motion.cross_force
    
    Examples
    --------
    >>> V, F = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]), rd.Force([0.0, 0.0, 2.0], [0.0, 3.0, 0.0])
    >>> bool(np.allclose(rd.force_cross_matrix(V), -rd.motion_cross_matrix(V).T))
    True
    >>> bool(np.allclose(rd.force_cross_matrix(V) @ F.to_vector(), V.cross_force(F).to_vector()))
    True
    """
def forward_dynamics(body: RigidBody | PlanarBody | Particle | PivotedBody | PivotedPlanarBody, state: RigidBodyState | PlanarBodyState | ParticleState | PivotedBodyState | PivotedPlanarBodyState, force: numpy.typing.ArrayLike | _Quantity | None = None, torque: numpy.typing.ArrayLike | float | _Quantity | None = None, point: numpy.typing.ArrayLike | _Quantity | None = None, frame: typing.Literal['world', 'body'] = 'world', gravity: bool | numpy.typing.ArrayLike | None = None) -> typing.Any:
    """
    Accelerations of `body` in `state` under an applied force, torque and gravity.
    
    The force f acts at `point` P (p_GP from the centre of mass G) and reduces to G as f and tau_G = tau + p_GP x f.
    Per body kind:
    
    - RigidBody: Newton m a_W = f_W + m g_W, Euler I alpha_B + w_B x I w_B = tau_B (I about G, in B).
    - PlanarBody: m a_W = f_W + m g_W in W's xy plane, I_zz alpha = tau_G about z.
    - Particle: a_W = f_W / m + g_W.
    - PivotedBody: Euler about the pivot O, inertia_O alpha_B + w_B x inertia_O w_B = tau_O (in B), and Newton for
      the centre of mass C, reaction_W = m a_C - f_W - m g_W; `point` is p_CP from C.
    - PivotedPlanarBody: inertia_O_zz alpha = tau_O about the z axis through O, and the reaction as for a
      PivotedBody.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody, Particle, PivotedBody or PivotedPlanarBody
        The body.
    state : RigidBodyState, PlanarBodyState, ParticleState, PivotedBodyState or PivotedPlanarBodyState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    force : array_like, shape (3,) or (2,), or pint.Quantity, optional
        Applied force f [N], expressed in `frame` (None: zero); shape (2,), in the plane, for the planar bodies.
    torque : array_like, shape (3,), float or pint.Quantity, optional
        Applied torque tau [N m], expressed in `frame` (None: zero); a float about z for the planar bodies. A
        Particle takes None.
    point : array_like, shape (3,) or (2,), or pint.Quantity, optional
        Point of application of the force, p_GP [m] from the centre of mass, expressed in `frame` (None: the
        centre of mass). A Particle takes None.
    frame : {'world', 'body'}, default 'world'
        Frame of force, torque and point: W or B. A Particle takes 'world'.
    gravity : None, bool or array_like, default None
        Uniform gravity g_W [m/s^2] in W: None (no gravity, docs/conventions.md), True (0, 0, -9.81) (False:
        none), or a vector, shape (3,). PlanarBody: None or an in-plane vector, shape (2,). PivotedPlanarBody: None
        or an in-plane vector, shape (2,) or (3,).
    
    Returns
    -------
    BodyAcceleration, PlanarAcceleration, ndarray, PivotedAcceleration or PivotedPlanarAcceleration
        RigidBody: BodyAcceleration (a_W, shape (3,) [m/s^2] in W; alpha_B, shape (3,) [rad/s^2] in B).
        PlanarBody: PlanarAcceleration (a_W, shape (2,); alpha [rad/s^2] about z). Particle: a_W, ndarray of
        shape (3,) [m/s^2] in W. PivotedBody: PivotedAcceleration. PivotedPlanarBody: PivotedPlanarAcceleration.
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    ValueError
        torque or point given for a Particle, or frame 'body' for it; gravity True or False for a planar body.
    
    Warns
    -----
    RuntimeWarning
        The result is not finite (an overflow; the message names forward_dynamics).
    
    See Also
    --------
    inverse_dynamics, simulate, step
    
    Examples
    --------
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> rd.forward_dynamics(body, rd.RigidBodyState(), gravity=True)
    BodyAcceleration(a_W=[0.0, 0.0, -9.81], alpha_B=[0.0, 0.0, 0.0])
    
    Torque-free, a spin about two principal axes still accelerates (the gyroscopic term -I^-1 (w_B x I w_B)):
    
    >>> rd.forward_dynamics(body, rd.RigidBodyState(w_B=[1.0, 1.0, 0.0])).alpha_B.round(12)
    array([ 0.        ,  0.        , -0.33333333])
    
    A rod of L = 2 m and 3 kg pinned at one end, held horizontal, starts at alpha = -3 g / (2 L):
    
    >>> rod = rd.PivotedPlanarBody(3.0, 3.0 * 2.0**2 / 12, p_OC_B=[1.0, 0.0])
    >>> print(f"{rd.forward_dynamics(rod, rd.PivotedPlanarBodyState(), gravity=[0.0, -9.81]).alpha:.6f}")
    -7.357500
    """
def forward_kinematics(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike | None = None) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Forward kinematics: every link's pose in W and its twist.
    
    X_λi = X_T X_J(q_i), X_Wi = X_Wλ X_λi, v_i = X_λi^-1 v_λ + S_i qd_i (Featherstone, Rigid Body
    Dynamics Algorithms, Table 5.1).
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,), optional
        Velocity (None: zero).
    
    Returns
    -------
    R_WL : ndarray, shape (n, 3, 3)
        Each link's orientation (link -> W coordinates).
    p_WL : ndarray, shape (n, 3)
        Each link's origin in W [m].
    V_L : ndarray, shape (n, 6)
        Each link's twist in W, expressed in the link frame, [w; v] (v: the velocity of the link's
        origin) [rad/s, m/s].
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    Examples
    --------
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> R, p, V = rd.forward_kinematics(tree, [np.pi / 2], [1.0])
    >>> (R[0] @ bob.com + p[0]).round(12) + 0.0  # the bob swung up to +y
    array([0., 1., 0.])
    >>> V[0]
    array([1., 0., 0., 0., 0., 0.])
    """
def from_point_masses(masses: numpy.typing.ArrayLike, positions: numpy.typing.ArrayLike) -> SpatialInertia:
    """
    Mass properties of a set of point masses.
    
    m = sum m_i, c = sum m_i p_i / m, I_C = sum m_i (|r_i|^2 1 - r_i r_i^T) with r_i = p_i - c
    ("Rigid body kinematics and dynamics" notes, eqs. (4.53)-(4.54)).
    
    Parameters
    ----------
    masses : array_like, shape (n,)
        Masses m_i [kg], finite and >= 0, summing to > 0.
    positions : array_like, shape (n, 3)
        Positions p_i [m], in any frame A; one row per mass.
    
    Returns
    -------
    SpatialInertia
        Total mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.
    
    Raises
    ------
    ValueError
        Shapes that do not match, a mass that is negative or not finite (masses[i] named), masses summing
        to 0, or positions not finite.
    
    See Also
    --------
    point_inertia, symmetry_planes, SpatialInertia.point_mass
    
    Examples
    --------
    A dumbbell of two 1 kg masses 2 m apart: I = 2 m d^2 = 2 kg m^2 about the axes across it:
    
    >>> body = rd.from_point_masses([1.0, 1.0], [[-1.0, 0, 0], [1.0, 0, 0]])
    >>> body.mass, body.com, body.inertia_com.diagonal()
    (2.0, array([0., 0., 0.]), array([0., 2., 2.]))
    """
def generalized_momentum(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    The generalized momentum p = dT/dv = H(q) v, one entry per joint coordinate.
    
    p_i = S_i^T h_i, with h_i the momentum of the subtree at link i (its links' I_k v_k carried to
    link i's frame; Featherstone, Rigid Body Dynamics Algorithms, sec. 6.2): for a revolute joint the
    angular momentum of everything beyond it about its axis, for a prismatic joint their linear
    momentum along it.
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,)
        Velocity.
    
    Returns
    -------
    ndarray, shape (tree.nv,)
        p [N m s for a rotation, N s for a translation; for a ball or free joint the link-frame
        angular momentum about the joint (and linear momentum)].
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    See Also
    --------
    generalized_momentum_rate, crba
    
    Examples
    --------
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> rd.generalized_momentum(tree, [0.3], [2.0]).round(12)  # (I_C + m l^2) v
    array([2.2])
    """
def generalized_momentum_rate(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, f_ext: numpy.typing.ArrayLike | None = None) -> numpy.typing.NDArray[numpy.float64]:
    """
    The rate of the generalized momentum by Lagrange's equations: dp/dt = dT/dq + Q, joint forces
    excluded (with joint forces tau, dp/dt = tau + this).
    
    The momentum equation f = d(m v)/dt of a chain: dT/dq at fixed v (the momentum a joint gains as
    the links beyond it move against their parents' motion) plus Q, the generalized force of gravity
    and f_ext. For trees of revolute, prismatic and fixed joints (a ball or free joint's momentum rate
    has a further term of its rotation group).
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,)
        Velocity.
    f_ext : array_like, shape (n, 6), optional
        External force [n; f] on each link, in its link frame (None: none).
    
    Returns
    -------
    ndarray, shape (tree.nv,)
        dp/dt [N m for a rotation, N for a translation].
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value, or a ball or free joint (naming its link).
    
    See Also
    --------
    generalized_momentum, aba
    
    Examples
    --------
    The horizontal pendulum's gravity torque, whatever its speed (one joint: dT/dq = 0):
    
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> rd.generalized_momentum_rate(tree, [np.pi / 2], [3.0]).round(12)
    array([-9.81])
    """
def hat(v: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Skew-symmetric cross-product matrices.
    
    S = hat(v) = [[0, -v3, v2], [v3, 0, -v1], [-v2, v1, 0]], so that S x = v × x. SciPy has no
    equivalent.
    
    Parameters
    ----------
    v : array_like, shape (3,) or (n, 3)
        Vectors (any unit), finite.
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        hat(v), in the unit of v.
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `v`).
    
    See Also
    --------
    vee
    
    Examples
    --------
    >>> rd.hat([1.0, 2.0, 3.0]) @ [4.0, 5.0, 6.0]
    array([-3.,  6., -3.])
    >>> np.cross([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
    array([-3.,  6., -3.])
    """
def hollow_cylinder(outer_radius: float, inner_radius: float, height: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thick tube (open ends), axis z.
    
    I_zz = m (R^2 + r^2)/2, I_xx = I_yy = m (3 (R^2 + r^2) + h^2)/12 about the centre; r = 0 is the solid
    cylinder.
    
    Parameters
    ----------
    outer_radius : float
        Outer radius R [m], > 0.
    inner_radius : float
        Inner radius r [m], in [0, R).
    height : float
        Height h [m] along z, > 0.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (axis z).
    
    Raises
    ------
    ValueError
        `outer_radius` or `height` not finite and > 0, or `inner_radius` outside [0, outer_radius);
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_cylinder, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.hollow_cylinder(2.0, 1.0, 3.0, mass=4.0).inertia_com.diagonal().round(12)
    array([ 8.,  8., 10.])
    >>> rd.hollow_cylinder(1.0, 0.0, 2.0, mass=1.0).is_approx(rd.solid_cylinder(1.0, 2.0, mass=1.0))
    True
    """
def hollow_sphere(outer_radius: float, inner_radius: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thick spherical shell (a solid sphere with a concentric spherical hole).
    
    I = 2/5 m (R^5 - r^5) / (R^3 - r^3) 1 about the centre; r = 0 is the solid sphere.
    
    Parameters
    ----------
    outer_radius : float
        Outer radius R [m], > 0.
    inner_radius : float
        Inner radius r [m], in [0, R).
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame.
    
    Raises
    ------
    ValueError
        `outer_radius` not finite and > 0, or `inner_radius` outside [0, outer_radius);
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_sphere, spherical_shell, SpatialInertia.transformed
    
    Examples
    --------
    With no hole it is the solid sphere; with R = 2 m, r = 1 m, m = 1 kg, I = 2/5 31/7 kg m^2:
    
    >>> rd.hollow_sphere(1.0, 0.0, mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))
    True
    >>> rd.hollow_sphere(2.0, 1.0, mass=1.0).inertia_com.diagonal().round(12)
    array([1.77142857, 1.77142857, 1.77142857])
    """
def inertia_report(mass: float, inertia_com: numpy.typing.ArrayLike, scale: float = 0.0) -> InertiaReport:
    """
    Validity report of a mass and a rotational inertia about the centre of mass.
    
    Checks the mass (finite, > 0), the inertia (finite, symmetric to 1e-12 max |I_ij|, positive
    semi-definite) and the triangle inequality I0 + I1 >= I2 on its ascending principal moments (from its
    symmetric part), each within tolerance = inertia_relative_tolerance * max(scale, |trace|) [kg m^2].
    Raises nothing on a bad inertia: the report says what fails.
    
    Parameters
    ----------
    mass : float
        Mass [kg].
    inertia_com : array_like, shape (3, 3)
        Rotational inertia about the centre of mass [kg m^2], in any frame (moments on the diagonal,
        negated products off it).
    scale : float, default 0.0
        Size [kg m^2] of the numbers the inertia was computed from, >= 0 (0: the trace only).
    
    Returns
    -------
    InertiaReport
        Principal moments, triangle margins, condition number, tolerance and each check.
    
    Raises
    ------
    ValueError
        `scale` negative or `inertia_com` not of shape (3, 3) (the message names it).
    
    See Also
    --------
    nearest_valid_inertia, SpatialInertia.report, InertiaCheck
    
    Examples
    --------
    Hairer-Lubich-Wanner's test inertia diag(2, 1, 2/3) is symmetric and positive definite, but no real
    body has it (2/3 + 1 < 2):
    
    >>> r = rd.inertia_report(1.0, np.diag([2.0, 1.0, 2 / 3]))
    >>> r.valid(), r.valid(rd.InertiaCheck.allow_unrealizable)
    (False, True)
    >>> r.triangle_margins.round(12)
    array([ 2.33333333,  1.66666667, -0.33333333])
    """
def integrate_density_over_box(rho: collections.abc.Callable[..., typing.Any], lower: numpy.typing.ArrayLike, upper: numpy.typing.ArrayLike, order: int = 6, subdivisions: int = 2) -> DensityIntegral:
    """
    Mass properties of a variable density over a box, by Gauss-Legendre quadrature.
    
    m = int rho dV, c = int rho x dV / m, I_C = int rho (|r|^2 1 - r r^T) dV with r = x - c
    ("Rigid body kinematics and dynamics" notes, eqs. (4.55), (4.56), (4.70)), each by the tensor
    Gauss-Legendre rule of `order` and of 2 * order points per axis of each of subdivisions^3 cells; the
    differences between the two are the error estimates.
    
    Parameters
    ----------
    rho : callable
        ``rho(points)``: points, ndarray, shape (n, 3) [m] -> densities, shape (n,) [kg/m^3], finite and
        >= 0. Called once per rule.
    lower, upper : array_like, shape (3,)
        Opposite corners [m] of the box, upper > lower componentwise, in any frame A.
    order : int, default 6
        Points per cell axis of the lower rule, in [1, 32].
    subdivisions : int, default 2
        Cells per box edge, in [1, 64].
    
    Returns
    -------
    DensityIntegral
        The higher-order SpatialInertia (in A) and the mass, com and inertia error estimates.
    
    Raises
    ------
    ValueError
        A bad box, order or subdivisions; rho returning the wrong number of values, a negative or
        non-finite one, or a zero total mass (the message names it).
    TypeError
        `rho` not callable.
    
    See Also
    --------
    integrate_density_over_mesh, solid_box
    
    Examples
    --------
    Density 1 + x [kg/m^3] over the unit cube: m = 3/2 kg, c_x = (1/2 + 1/3) / m = 5/9 m:
    
    >>> d = rd.integrate_density_over_box(lambda p: 1.0 + p[:, 0], [0, 0, 0], [1, 1, 1])
    >>> f"{d.inertia.mass:.12f}", f"{d.inertia.com[0]:.12f}", d.mass_error < 1e-12
    ('1.500000000000', '0.555555555556', True)
    """
def integrate_density_over_mesh(rho: collections.abc.Callable[..., typing.Any], vertices: numpy.typing.ArrayLike, faces: numpy.typing.ArrayLike, order: int = 4) -> DensityIntegral:
    """
    Mass properties of a variable density over the solid bounded by a closed mesh.
    
    The solid is split into signed tetrahedra (one per face), each integrated by a
    collapsed Gauss-Legendre rule of order^3 and of (2 order)^3 points; the differences between the two
    rules are the error estimates. Integrals as integrate_density_over_box.
    
    Parameters
    ----------
    rho : callable
        ``rho(points)``: points, ndarray, shape (n, 3) [m] -> densities, shape (n,) [kg/m^3], finite and
        >= 0; must be defined on the mesh's convex hull.
    vertices : array_like, shape (n, 3)
        Vertex positions [m], in any frame A.
    faces : array_like of int, shape (f, 3)
        Closed, outward-oriented triangles (counter-clockwise seen from outside).
    order : int, default 4
        Points per axis of the lower rule, in [1, 32].
    
    Returns
    -------
    DensityIntegral
        The higher-order SpatialInertia (in A) and the mass, com and inertia error estimates.
    
    Raises
    ------
    ValueError
        An open, misoriented or inward mesh, a bad order, or rho values as in integrate_density_over_box
        (the message names it).
    TypeError
        `rho` not callable, or `faces` not of an integer dtype.
    
    See Also
    --------
    integrate_density_over_box, solid_mesh
    
    Examples
    --------
    A uniform density gives the exact solid:
    
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> d = rd.integrate_density_over_mesh(lambda p: np.full(len(p), 6.0), v, faces)
    >>> d.inertia.is_approx(rd.solid_tetrahedron(v, density=6.0)), d.evaluations
    (True, 2304)
    """
def inverse_dynamics(body: RigidBody | PlanarBody | Particle | PivotedBody | PivotedPlanarBody, state: RigidBodyState | PlanarBodyState | ParticleState | PivotedBodyState | PivotedPlanarBodyState, a_W: numpy.typing.ArrayLike | _Quantity | None = None, alpha_B: numpy.typing.ArrayLike | float | _Quantity | None = None, gravity: bool | numpy.typing.ArrayLike | None = None) -> typing.Any:
    """
    The applied loads a motion requires, reduced to the centre of mass (undoes forward_dynamics).
    
    Per body kind:
    
    - RigidBody: f_W = m (a_W - g_W) in W, tau_B = I alpha_B + w_B x I w_B about the centre of mass in B.
    - PlanarBody: f_W = m (a_W - g_W) in W's xy plane, tau = I_zz alpha about z.
    - Particle: f_W = m (a_W - g_W).
    - PivotedBody: the torque about O in B the motion needs besides gravity, tau_O_B = inertia_O alpha_B +
      w_B x inertia_O w_B - p_OC_B x m g_B (g_B: gravity in B), and the pivot's reaction_W in W.
    - PivotedPlanarBody: the torque tau_O about the z axis through O besides gravity, and reaction_W.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody, Particle, PivotedBody or PivotedPlanarBody
        The body.
    state : RigidBodyState, PlanarBodyState, ParticleState, PivotedBodyState or PivotedPlanarBodyState
        Its state, of the body's kind and finite.
    a_W : array_like, shape (3,) or (2,), or pint.Quantity
        Centre of mass acceleration in W [m/s^2]; shape (2,) for a PlanarBody. Required, except for the pivoted
        bodies, which take None (the pivot fixes it).
    alpha_B : array_like, shape (3,), float or pint.Quantity
        Angular acceleration in B [rad/s^2]; a float about z for the planar bodies. A Particle takes None.
    gravity : None, bool or array_like, default None
        Uniform gravity g_W [m/s^2] in W, as forward_dynamics takes it.
    
    Returns
    -------
    ComWrench, PlanarWrench, ndarray, PivotedTorque or PivotedPlanarTorque
        RigidBody: ComWrench (f_W, shape (3,) [N] in W; tau_B, shape (3,) [N m] in B). PlanarBody: PlanarWrench
        (f_W, shape (2,); tau [N m] about z). Particle: f_W, ndarray of shape (3,) [N] in W. PivotedBody:
        PivotedTorque. PivotedPlanarBody: PivotedPlanarTorque.
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    TypeError
        a_W or alpha_B None where the body needs it (the message names it).
    ValueError
        alpha_B given for a Particle; a_W given for a pivoted body.
    
    Warns
    -----
    RuntimeWarning
        The result is not finite (an overflow; the message names inverse_dynamics).
    
    See Also
    --------
    forward_dynamics, ComWrench, PivotedTorque
    
    Examples
    --------
    It undoes forward_dynamics, gyroscopic term included:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> s = rd.RigidBodyState(w_B=[1.0, 1.0, 0.0])
    >>> a = rd.forward_dynamics(body, s, force=[1.0, 0, 0], torque=[0, 0.5, 0], gravity=True)
    >>> w = rd.inverse_dynamics(body, s, a_W=a.a_W, alpha_B=a.alpha_B, gravity=True)
    >>> np.allclose(w.f_W, [1, 0, 0]), np.allclose(w.tau_B, [0, 0.5, 0])
    (True, True)
    
    The torque about the pivot that holds a top of 1 kg horizontal, its centre of mass 0.5 m out along x:
    
    >>> top = rd.PivotedBody(rd.RigidBody(1.0, [0.1, 0.1, 0.2]), p_OC_B=[0.0, 0.0, 0.5])
    >>> level = rd.PivotedBodyState(q_WB=rd.rotvec_to_quat([0.0, np.pi / 2, 0.0]))
    >>> rd.inverse_dynamics(top, level, alpha_B=[0, 0, 0], gravity=True).tau_O_B.round(12)
    array([ 0.   , -4.905,  0.   ])
    """
def jacobi_ellipj(u: float | numpy.typing.ArrayLike, m: float, mc: float | None = None) -> typing.Any:
    """
    Jacobi elliptic functions sn(u|m), cn(u|m), dn(u|m).
    
    sn u = sin(am u), cn u = cos(am u), dn u = sqrt(1 - m sn^2 u), where am is the inverse of
    u = int_0^am dt / sqrt(1 - m sin^2 t), for the parameter m = k^2 (as scipy.special.ellipj takes it).
    Absolute error a few ulps for |u| up to K(m), growing as eps |u| beyond; m = 1 gives (tanh u, sech u,
    sech u). Unlike scipy.special.ellipj, accurate near m = 1 at any u when mc is given.
    
    Parameters
    ----------
    u : float or array_like, shape (n,)
        Argument, finite.
    m : float
        Parameter m = k^2, 0 <= m <= 1.
    mc : float, optional
        Its complement 1 - m, equal to 1 - m to within 4 eps (default: computed as 1 - m); pass it
        near m = 1 for full accuracy.
    
    Returns
    -------
    sn, cn, dn : float or ndarray, shape (n,)
        Three floats for a scalar u, three arrays of u's length for an array.
    
    Raises
    ------
    ValueError
        u non-finite or not a scalar or 1-d array, m or mc outside [0, 1], or mc not 1 - m (the
        message names it).
    
    See Also
    --------
    ellipk, ellippi_am
    scipy.special.ellipj : The same functions of (u, m), with am u as a fourth result.
    
    Examples
    --------
    sn K = 1 and cn K = 0 at the quarter period K(m); sn^2 + cn^2 = 1 and dn^2 + m sn^2 = 1:
    
    >>> sn, cn, dn = rd.jacobi_ellipj(rd.ellipk(0.5), 0.5)
    >>> print(f"{sn:.12f} {abs(cn):.12f} {dn:.12f}")
    1.000000000000 0.000000000000 0.707106781187
    >>> sn, cn, dn = rd.jacobi_ellipj(np.linspace(0.0, 5.0, 6), 0.7)
    >>> bool(np.allclose(sn**2 + cn**2, 1.0) and np.allclose(dn**2 + 0.7 * sn**2, 1.0))
    True
    """
def kepler_propagate(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike, mu: float, t: float | numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Position and velocity a time t after a given state on its two-body (Keplerian) orbit.
    
    Through the elements (`state_to_elements`): the mean anomaly advances at the mean motion, M = M0 + n t,
    n = sqrt(mu/a^3) (ellipse), sqrt(mu/(-a)^3) (hyperbola), sqrt(mu/p^3) (parabola, Barker's equation), then
    the true anomaly by Kepler's equation (`mean_to_true_anomaly`); the other elements are constant (Curtis,
    "Orbital Mechanics for Engineering Students", ch. 3). Exact but for round-off: no step size.
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    mu : float
        Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).
    t : float or array_like, shape (n,)
        Time after the given state [s], any sign (or a pint quantity).
    
    Returns
    -------
    r_W : ndarray, shape (3,) or (n, 3)
        Position at t, in W [m].
    v_W : ndarray, shape (3,) or (n, 3)
        Velocity at t, in W [m/s].
    
    Raises
    ------
    ValueError
        `mu` not > 0, r = 0 (the message names `r_W`), `t` not finite, or as below.
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
    
    See Also
    --------
    state_to_elements, mean_to_true_anomaly
    
    Examples
    --------
    One period later the body is back (the kepler scene's orbit: a = 7000 km, e = 0.1, T = 5828.5 s):
    
    >>> mu = 398600.4418e9
    >>> r0, v0 = [6300e3, 0.0, 0.0], [0.0, 8342.475803771201, 0.0]
    >>> r, v = rd.kepler_propagate(r0, v0, mu, 2 * np.pi * np.sqrt(7000e3**3 / mu))
    >>> np.allclose(r, r0, rtol=0, atol=1e-6), np.allclose(v, v0, rtol=0, atol=1e-9)
    (True, True)
    """
def kinetic_energy(body: RigidBody | PlanarBody | Particle, state: RigidBodyState | PlanarBodyState | ParticleState) -> typing.Any:
    """
    Kinetic energy [J], split into its translational and rotational parts.
    
    translational = 1/2 m v_W.v_W, rotational = 1/2 w_B.I w_B about the centre of mass (1/2 I_zz omega^2 for a
    PlanarBody, 0 for a Particle), total = their sum.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody or Particle
        The body.
    state : RigidBodyState, PlanarBodyState or ParticleState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    
    Returns
    -------
    KineticEnergy
        translational, rotational and total [J].
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    
    Warns
    -----
    RuntimeWarning
        A part is not finite (an overflow; the message names kinetic_energy).
    
    See Also
    --------
    KineticEnergy, potential_energy, simulate
    
    Examples
    --------
    A torque-free body keeps its kinetic energy:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> s0 = rd.RigidBodyState(v_W=[1, 0, 0], w_B=[1.0, 0.1, 0.2])
    >>> s1 = rd.step(body, s0, 0.001, method="rkmk4")
    >>> rd.kinetic_energy(body, s0).total, f"{rd.kinetic_energy(body, s1).total:.12f}"
    (1.57, '1.570000000000')
    """
def linear_momentum(body: RigidBody | PlanarBody | Particle, state: RigidBodyState | PlanarBodyState | ParticleState) -> typing.Any:
    """
    Linear momentum m v_W [kg m/s] of the centre of mass, in W.
    
    Parameters
    ----------
    body : RigidBody, PlanarBody or Particle
        The body.
    state : RigidBodyState, PlanarBodyState or ParticleState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    
    Returns
    -------
    ndarray, shape (3,) or (2,)
        m v_W [kg m/s] in W; shape (2,) for a PlanarBody.
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    angular_momentum, kinetic_energy, apply_impulse
    
    Examples
    --------
    >>> rd.linear_momentum(rd.Particle(3.0), rd.ParticleState(v_W=[0.0, 2.0, 0.0]))
    array([0., 6., 0.])
    """
def matrix_to_euler(seq: str, R: numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Euler angles of rotation matrices.
    
    Ranges and method as `quat_to_euler`. SciPy: ``Rotation.from_matrix(R).as_euler(seq)``.
    
    Parameters
    ----------
    seq : str
        The axis sequence, 3 letters as SciPy's: lowercase 'xyz' = extrinsic (rotations about the
        fixed axes of W), uppercase 'XYZ' = intrinsic (about the moving axes); the 12 sequences xyz xzy
        yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    R : array_like, shape (3, 3) or (n, 3, 3)
        Rotation matrices up to rounding: det > 0 and singular values within 0.05 of 1. One not
        orthonormal to SciPy's test is projected onto the nearest rotation (`nearest_rotation`), as
        SciPy's `Rotation.from_matrix` does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`) in the order of `seq`: first and third in [-pi, pi], second
        in [0, pi] (proper Euler sequences) or [-pi/2, pi/2] (Tait-Bryan).
    
    Raises
    ------
    ValueError
        `seq` not one of the 24 sequences.
    TypeError
        `seq` not a str.
    ValueError
        A matrix with det <= 0 (a reflection or a singular matrix), a singular value farther than 0.05
        from 1 or a non-finite entry (the message names `R` and, in a stack, the item), or a shape other
        than (3, 3) or (n, 3, 3).
    
    Warns
    -----
    UserWarning
        'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the middle angle of some item
        within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper sequences, -pi/2 or pi/2
        in Tait-Bryan ones; Davenport angles: the ends of its range). Within round-off of it (1e-13 rad)
        only the sum or difference of the first and third angles is defined: the third is set to 0 and
        the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad the angles are the exact ones
        and the message says so (SciPy sets the third to 0 there too, which moves the rotation by up to
        2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    
    See Also
    --------
    euler_to_matrix, quat_to_euler
    
    Examples
    --------
    >>> R = rd.euler_to_matrix("ZXZ", [0.4, 1.0, -0.7])
    >>> rd.matrix_to_euler("ZXZ", R).round(12)
    array([ 0.4,  1. , -0.7])
    """
def matrix_to_quat(R: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of rotation matrices, canonical sign w >= 0.
    
    Shepperd's method in Markley's form (Markley 2008, "Unit quaternion from rotation matrix") with
    SciPy's choice of branch (the largest of R_00, R_11, R_22 and tr R): accurate at every angle,
    including pi. SciPy: ``Rotation.from_matrix(R).as_quat(canonical=True)``.
    
    Parameters
    ----------
    R : array_like, shape (3, 3) or (n, 3, 3)
        Rotation matrices up to rounding: det > 0 and singular values within 0.05 of 1. One not
        orthonormal to SciPy's test is projected onto the nearest rotation (`nearest_rotation`), as
        SciPy's `Rotation.from_matrix` does.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q with R(q) = R and w >= 0, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        A matrix with det <= 0 (a reflection or a singular matrix), a singular value farther than 0.05
        from 1 or a non-finite entry (the message names `R` and, in a stack, the item), or a shape other
        than (3, 3) or (n, 3, 3).
    
    See Also
    --------
    quat_to_matrix, nearest_rotation, quat_canonical
    
    Examples
    --------
    A half turn about x:
    
    >>> rd.matrix_to_quat(np.diag([1.0, -1.0, -1.0]))
    array([1., 0., 0., 0.])
    >>> rd.matrix_to_quat(np.eye(3), scalar_first=True)
    array([1., 0., 0., 0.])
    """
def matrix_to_rotvec(R: numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Logarithm map of rotation matrices: rotation vectors angle * axis.
    
    The angle is in [0, pi]; accurate near 0 and near pi. SciPy:
    ``Rotation.from_matrix(R).as_rotvec()``.
    
    Parameters
    ----------
    R : array_like, shape (3, 3) or (n, 3, 3)
        Rotation matrices up to rounding: det > 0 and singular values within 0.05 of 1. One not
        orthonormal to SciPy's test is projected onto the nearest rotation (`nearest_rotation`), as
        SciPy's `Rotation.from_matrix` does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Rotation vectors [rad] (degrees if `degrees`).
    
    Raises
    ------
    ValueError
        A matrix with det <= 0 (a reflection or a singular matrix), a singular value farther than 0.05
        from 1 or a non-finite entry (the message names `R` and, in a stack, the item), or a shape other
        than (3, 3) or (n, 3, 3).
    
    See Also
    --------
    rotvec_to_matrix, quat_to_rotvec
    
    Examples
    --------
    >>> rd.matrix_to_rotvec(rd.rot_y(0.5)).round(12)
    array([0. , 0.5, 0. ])
    >>> rd.matrix_to_rotvec(np.diag([-1.0, 1.0, -1.0]), degrees=True).round(9)
    array([  0., 180.,   0.])
    """
def mean_to_eccentric_anomaly(M: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    Eccentric (ellipse) or hyperbolic (hyperbola) anomaly of the mean anomaly: Kepler's equation solved.
    
    Solves M = E - e sin E (0 <= e < 1; M reduced to (-pi, pi], its revolutions kept) or M = e sinh H - H
    (e > 1) to round-off: a starter from the cubic (1 - e) x + e x^3/6 = M near periapsis (exact as e -> 1)
    or Danby's M + 0.85 e, then Halley's iteration kept inside a bracket of the root, bisecting where a step
    would leave it, for at most 200 steps (3 to 5 typically): it always returns.
    
    Parameters
    ----------
    M : float or array_like, shape (n,)
        Mean anomaly [rad], any finite value.
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0: 0 <= e < 1 an ellipse, e > 1 a hyperbola.
    
    Returns
    -------
    float or ndarray, shape (n,)
        E or H [rad] with Kepler's equation satisfied to round-off.
    
    Raises
    ------
    ValueError
        A non-finite value, e < 0 or e = 1 (a parabola: `mean_to_true_anomaly` solves Barker's equation)
        (the message names the argument and, in a stack, the item).
    
    See Also
    --------
    eccentric_to_mean_anomaly, mean_to_true_anomaly
    
    Examples
    --------
    Curtis's Example 3.2 (M = 3.6029 rad, e = 0.37255: E = 3.4794 rad), and the residual:
    
    >>> E = rd.mean_to_eccentric_anomaly(3.6029, 0.37255)
    >>> round(E, 4), bool(abs(E - 0.37255 * np.sin(E) - 3.6029) < 1e-15)
    (3.4794, True)
    """
def mean_to_true_anomaly(M: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    True anomaly of the mean anomaly, for every conic: where the body is a time M/n after periapsis.
    
    Kepler's equation solved (`mean_to_eccentric_anomaly`) for e != 1, then `eccentric_to_true_anomaly`;
    Barker's cubic D^3 + 3 D = 6 M in closed form for the parabola e = 1 (nu = 2 atan D). Keeps the
    revolutions of an ellipse's M.
    
    Parameters
    ----------
    M : float or array_like, shape (n,)
        Mean anomaly [rad].
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0 (1 included).
    
    Returns
    -------
    float or ndarray, shape (n,)
        nu [rad]; for e >= 1 in (-acos(-1/e), acos(-1/e)).
    
    Raises
    ------
    ValueError
        A non-finite value or e < 0 (the message names the argument).
    
    See Also
    --------
    true_to_mean_anomaly, mean_to_eccentric_anomaly
    
    Examples
    --------
    Curtis's Example 3.2: 3 h after perigee on an orbit of e = 0.37255 and period 18834 s, nu = 193.2 deg:
    
    >>> M = 2 * np.pi * 10800 / 18834.0
    >>> round(float(np.degrees(rd.mean_to_true_anomaly(M, 0.37255))), 1)
    193.2
    """
def mesh_shell(vertices: typing.Any, faces: typing.Any, *, mass: typing.Any = None, density: typing.Any = None, weld_tolerance: typing.Any = None) -> SpatialInertia:
    """
    Thin shell made of the faces (any orientation, need not be closed): vertices (n, 3) [m], faces
    (f, 3), welded as in solid_mesh (weld_tolerance). Give exactly one of mass= [kg] or density= [kg/m^2].
    """
def mesh_symmetry_planes(vertices: numpy.typing.ArrayLike, faces: numpy.typing.ArrayLike, tolerance: float = 1e-09, *, weld_tolerance: float | None = None) -> list:
    """
    Planes of symmetry of the uniform solid bounded by a closed, outward-oriented mesh.
    
    The planes of the solid, whatever its triangulation: a plane qualifies when its reflection maps the
    solid's oriented boundary onto itself (each reflected face covered by faces in the same plane and facing
    the same way, up to a strip of width tolerance * L along its edges, L the largest distance from the
    centre of mass to a vertex [m]; normals within tolerance). A faceted cylinder or capsule of s sections
    has the s planes through its axis and the plane normal to it, not the smooth solid's continuum.
    Candidates as in symmetry_planes. The mesh is welded first as in solid_mesh.
    
    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Vertex positions [m], in any frame A.
    faces : array_like of int, shape (f, 3)
        Vertex indices of each triangle, counter-clockwise seen from outside.
    tolerance : float, default 1e-9
        Relative tolerance, >= 0.
    weld_tolerance : float or None, default None
        Weld distance [m] (None: 1e-8 x the bounding-box diagonal; 0: off).
    
    Returns
    -------
    list of tuple (ndarray, ndarray)
        One (normal, point) per plane, in A: normal, shape (3,), unit, its largest-magnitude component
        positive; point, shape (3,) [m], the solid's centre of mass.
    
    Raises
    ------
    ValueError
        A bad mesh or tolerance (the message names the argument).
    
    See Also
    --------
    symmetry_planes, solid_mesh
    
    Examples
    --------
    The corner tetrahedron is symmetric in the three planes x = y, y = z and x = z:
    
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> len(rd.mesh_symmetry_planes(v, faces))
    3
    """
def mesh_volume(vertices: numpy.typing.ArrayLike, faces: numpy.typing.ArrayLike) -> float:
    """
    Signed volume enclosed by a triangle mesh.
    
    V = 1/6 sum_f v0 . (v1 x v2) over the faces (divergence theorem): positive for outward-oriented faces
    (counter-clockwise seen from outside), negative for inward ones. Meaningful for a closed mesh.
    
    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Vertex positions [m].
    faces : array_like of int, shape (f, 3)
        Vertex indices of each triangle.
    
    Returns
    -------
    float
        Signed volume [m^3].
    
    Raises
    ------
    ValueError
        A shape that does not match or an index outside [0, n) (the message names it).
    TypeError
        `faces` not of an integer dtype.
    
    See Also
    --------
    solid_mesh, require_closed_oriented_mesh
    
    Examples
    --------
    The corner tetrahedron has volume 1/6 m^3; turning its faces inside out flips the sign:
    
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> f"{rd.mesh_volume(v, faces):.12f}"
    '0.166666666667'
    >>> f"{rd.mesh_volume(v, [f[::-1] for f in faces]):.12f}"
    '-0.166666666667'
    """
def methods() -> list:
    """
    The fixed-step methods simulate, step and simulate_batch take, with their properties.
    
    Parameters
    ----------
    None
    
    Returns
    -------
    list of dict
        One dict per method, with the keys: name (str, the `method` argument); order (int, global order);
        evaluations (int, derivative evaluations per step); conserves (str, what is kept exactly on a free rigid
        body); notes (str); stability_limit (float, the largest dt*|w| [rad], |w| the largest body rate on the
        torque-free orbit, at which the method is documented stable on a free spin: inf if unconditionally, 0 if
        never); exact_torque_free (bool, True if torque-free motion is reproduced to round-off at any dt: no
        observed order applies); scene_features (str, what of a Scene the method runs: bodies, elements, and its
        compatibility notes).
    
    See Also
    --------
    simulate, step
    
    Examples
    --------
    >>> [m["name"] for m in rd.methods()]  # doctest: +NORMALIZE_WHITESPACE
    ['explicit_euler', 'semi_implicit_euler', 'semi_implicit_euler_implicit_gyroscopic', 'rk4', 'rkmk4',
     'implicit_midpoint', 'splitting_dlm', 'splitting_dlm_yoshida4', 'exact_flow_kick', 'exact']
    >>> rk4 = next(m for m in rd.methods() if m["name"] == "rk4")
    >>> rk4["order"], rk4["evaluations"], f"{rk4['stability_limit']:.6f}"  # 2 sqrt(2)
    (4, 4, '2.828427')
    """
def motion_cross_matrix(motion: Motion) -> numpy.typing.NDArray[numpy.float64]:
    """
    Motion cross-product matrix crm(V) (Featherstone, "Rigid Body Dynamics Algorithms").
    
    crm(V) = [[hat(w), 0], [hat(v), hat(w)]] for V = [w; v] (angular first), so that crm(V) V2 = V x V2
    (Motion.cross).
    
    Parameters
    ----------
    motion : Motion
        V = [w; v] ([rad/s], [m/s]).
    
    Returns
    -------
    ndarray, shape (6, 6)
        crm(V), in V's frame (hat(w) blocks [rad/s], hat(v) block [m/s]).
    
    Raises
    ------
    TypeError
        motion not a Motion.
    
    See Also
    --------
    force_cross_matrix, Motion.cross
    
    Examples
    --------
    >>> V, V2 = rd.Motion([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]), rd.Motion([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
    >>> bool(np.allclose(rd.motion_cross_matrix(V) @ V2.to_vector(), V.cross(V2).to_vector()))
    True
    >>> bool(np.allclose(rd.motion_cross_matrix(V) @ V.to_vector(), 0.0))  # V x V = 0
    True
    """
def mrp_to_quat(mrp: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Unit quaternion of modified Rodrigues parameters.
    
    q = (2 p, 1 - |p|^2) / (1 + |p|^2): either shadow set is accepted (p and -p/|p|^2 are the same
    rotation; w < 0 when |p| > 1). SciPy: ``Rotation.from_mrp(p).as_quat()``.
    
    Parameters
    ----------
    mrp : array_like, shape (3,) or (n, 3)
        Modified Rodrigues parameters p, any finite values (dimensionless).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `mrp`).
    
    See Also
    --------
    quat_to_mrp
    
    Examples
    --------
    A shadow set gives the same rotation:
    
    >>> p = np.array([0.2, -0.4, 0.1])
    >>> rd.angular_distance(rd.mrp_to_quat(p), rd.mrp_to_quat(-p / (p @ p))) < 1e-12
    True
    """
def nearest_rotation(M: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    The rotation matrix nearest to a matrix in the Frobenius norm (orthogonal Procrustes problem).
    
    With the SVD M = U S V^T, R = U diag(1, 1, det(U V^T)) V^T. For det M > 0 this is the orthogonal
    polar factor of M (Higham 1986, "Computing the polar decomposition"), the matrix SciPy's
    ``Rotation.from_matrix(M).as_matrix()`` gives for a non-orthonormal M; for det M < 0 the smallest
    singular direction is flipped (Kabsch). Unique when M has rank >= 2 (and, for det M < 0, distinct
    two smallest singular values). Idempotent: a rotation matrix is returned unchanged to round-off.
    
    Parameters
    ----------
    M : array_like, shape (3, 3) or (n, 3, 3)
        Any finite matrices.
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R, orthonormal with det +1 to round-off.
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `M`).
    
    See Also
    --------
    matrix_to_quat
    
    Examples
    --------
    A rotation matrix with rounding noise is cleaned up:
    
    >>> M = rd.rot_z(0.3) + 1e-4 * np.array([[1.0, 2.0, 0.0], [0.0, -1.0, 3.0], [2.0, 0.0, 1.0]])
    >>> R = rd.nearest_rotation(M)
    >>> np.allclose(R @ R.T, np.eye(3)), f"{np.linalg.det(R):.12f}"
    (True, '1.000000000000')
    >>> rd.nearest_rotation(np.diag([2.0, 3.0, 4.0])).round(12) + 0.0
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
def nearest_valid_inertia(inertia: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Nearest rotational inertia that satisfies the triangle inequality (an explicit repair).
    
    The symmetric part's principal moments are projected onto the cone I_i + I_j >= I_k (nearest in the
    Frobenius norm), keeping its principal axes. A valid inertia is returned unchanged (symmetrised). Never
    applied implicitly.
    
    Parameters
    ----------
    inertia : array_like, shape (3, 3)
        Rotational inertia [kg m^2] about a point, in any frame.
    
    Returns
    -------
    ndarray, shape (3, 3)
        The repaired inertia [kg m^2], about the same point and in the same frame.
    
    Raises
    ------
    ValueError
        `inertia` not of shape (3, 3) or not finite.
    
    See Also
    --------
    inertia_report, InertiaCheck
    
    Examples
    --------
    >>> J = rd.nearest_valid_inertia(np.diag([2.0, 1.0, 2 / 3]))
    >>> J.diagonal().round(12)
    array([1.88888889, 1.11111111, 0.77777778])
    >>> rd.inertia_report(1.0, J).valid()
    True
    """
def orbit_frame_angular_velocity(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Angular velocity w_WO_W = (r x v)/|r|^2 of the orbit frames (LVLH and RSW alike) in W, expressed in W.
    
    The radius vector turns about the orbit normal at h/r^2 (h = r^2 dtheta/dt): on a circular orbit the
    orbit rate n = sqrt(mu/r^3), on an elliptic one faster at periapsis than at apoapsis. Exact for an
    acceleration along r (a Keplerian orbit); an acceleration out of the orbit plane would add a component
    along r, not included. In LVLH coordinates it is (0, -h/r^2, 0), in RSW (0, 0, h/r^2).
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        w_WO_W [rad/s].
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
    
    See Also
    --------
    orbit_frame_rotation
    
    Examples
    --------
    A circular orbit of radius 7000 km about the Earth turns at n = sqrt(mu/r^3):
    
    >>> mu, r = 3.986004418e14, 7.0e6
    >>> w = rd.orbit_frame_angular_velocity([r, 0.0, 0.0], [0.0, np.sqrt(mu / r), 0.0])
    >>> np.allclose(w, [0.0, 0.0, np.sqrt(mu / r**3)], rtol=1e-15, atol=0.0)
    True
    """
def orbit_frame_rotation(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike, frame: str = 'lvlh') -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotation R_WO from an orbit frame O (LVLH or RSW) to the inertial frame W.
    
    The columns of R_WO are O's axes expressed in W, from the body's position and velocity. Use
    `matrix_to_quat` for q_WO.
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    frame : str, default 'lvlh'
        'lvlh': z_O = -r/|r| (nadir), y_O = -h/|h| (opposite the orbit normal h = r x v), x_O = y_O x z_O
        (along-track; along v on a circular orbit), the attitude texts' LVLH with roll, pitch and yaw axes
        x, y, z (Wie, "Space Vehicle Dynamics and Control"). 'rsw': Hill's frame, x_O = r/|r| (R, radial out),
        z_O = h/|h| (W, the orbit normal), y_O = z_O x x_O (S, along-track) (Vallado, "Fundamentals of
        Astrodynamics and Applications").
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R_WO, orthonormal with det +1.
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
        `frame` not 'lvlh' or 'rsw'.
    
    See Also
    --------
    orbit_frame_angular_velocity, attitude_from_orbit_frame
    
    Examples
    --------
    Below the centre on -z_W, moving along +x_W: LVLH's z (third column) points up +z_W, to the centre:
    
    >>> rd.orbit_frame_rotation([0.0, 0.0, -7e6], [7.5e3, 0.0, 0.0]).round(12) + 0.0
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
def point_acceleration(K_AF: FrameKinematics, p_FQ_F: numpy.typing.ArrayLike, v_FQ_F: numpy.typing.ArrayLike, a_FQ_F: numpy.typing.ArrayLike) -> PointAcceleration:
    """
    Acceleration of a point Q moving in frame F, seen from frame A, term by term.
    
    a_AQ = a_AF + alpha_AF x r_FQ + w_AF x (w_AF x r_FQ) + a_FQ + 2 w_AF x v_FQ ("Rigid body kinematics and
    dynamics" notes (4.39)), every term expressed in A.
    
    Parameters
    ----------
    K_AF : FrameKinematics
        F relative to A, expressed in A.
    p_FQ_F : array_like, shape (3,)
        Q's position relative to F's origin [m], expressed in F.
    v_FQ_F : array_like, shape (3,)
        Q's velocity seen from F [m/s], expressed in F.
    a_FQ_F : array_like, shape (3,)
        Q's acceleration seen from F [m/s^2], expressed in F.
    
    Returns
    -------
    PointAcceleration
        origin, tangential, centripetal, relative, coriolis and total [m/s^2], expressed in A.
    
    Raises
    ------
    TypeError
        K_AF not a FrameKinematics.
    ValueError
        A vector of another shape or non-finite (naming it).
    
    See Also
    --------
    point_velocity, FrameTree.point_acceleration
    
    Examples
    --------
    In a frame spinning at 2 rad/s about z: the centripetal term of a point 1 m out, and the Coriolis term of
    a point at the origin moving at 1 m/s along x:
    
    >>> K_AF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0])
    >>> rd.point_acceleration(K_AF, [1.0, 0, 0], [0, 0, 0], [0, 0, 0]).centripetal
    array([-4.,  0.,  0.])
    >>> rd.point_acceleration(K_AF, [0, 0, 0], [1.0, 0, 0], [0, 0, 0]).coriolis
    array([0., 4., 0.])
    """
def point_inertia(mass: float, r: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotational inertia of a point mass about the origin.
    
    I_O = m (|r|^2 1 - r r^T), the parallel-axis term of the theorem (Craig).
    
    Parameters
    ----------
    mass : float
        Mass m [kg], finite and > 0.
    r : array_like, shape (3,)
        Position [m] of the mass relative to the origin, in any frame A.
    
    Returns
    -------
    ndarray, shape (3, 3)
        Inertia about the origin [kg m^2], expressed in A (moments on the diagonal, negated products
        off it).
    
    Raises
    ------
    ValueError
        `mass` not finite and > 0, or `r` not finite (the message names it).
    
    See Also
    --------
    from_point_masses, SpatialInertia.inertia_about_point
    
    Examples
    --------
    2 kg at 3 m on the z axis: m d^2 = 18 kg m^2 about x and y, nothing about z:
    
    >>> rd.point_inertia(2.0, [0.0, 0.0, 3.0])
    array([[18.,  0.,  0.],
           [ 0., 18.,  0.],
           [ 0.,  0.,  0.]])
    """
def point_velocity(K_AF: FrameKinematics, p_FQ_F: numpy.typing.ArrayLike, v_FQ_F: numpy.typing.ArrayLike) -> PointVelocity:
    """
    Velocity of a point Q moving in frame F, seen from frame A, term by term.
    
    v_AQ = v_AF + w_AF x r_FQ + v_FQ ("Rigid body kinematics and dynamics" notes (4.38)), every term
    expressed in A.
    
    Parameters
    ----------
    K_AF : FrameKinematics
        F relative to A, expressed in A.
    p_FQ_F : array_like, shape (3,)
        Q's position relative to F's origin [m], expressed in F.
    v_FQ_F : array_like, shape (3,)
        Q's velocity seen from F [m/s], expressed in F (zero for a point fixed in F).
    
    Returns
    -------
    PointVelocity
        origin, rotational, relative and total [m/s], expressed in A.
    
    Raises
    ------
    TypeError
        K_AF not a FrameKinematics.
    ValueError
        A vector of another shape or non-finite (naming it).
    
    See Also
    --------
    point_acceleration, FrameTree.point_velocity
    
    Examples
    --------
    A point 1 m from the axis of a frame spinning at 2 rad/s moves at 2 m/s:
    
    >>> K_AF = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 2.0])
    >>> rd.point_velocity(K_AF, [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]).total
    array([0., 2., 0.])
    """
def potential_energy(body: RigidBody | PlanarBody | Particle, state: RigidBodyState | PlanarBodyState | ParticleState, gravity: bool | numpy.typing.ArrayLike | None = None) -> typing.Any:
    """
    Potential energy of uniform gravity, V = -m g_W.p_W [J] (zero at the origin of W).
    
    Parameters
    ----------
    body : RigidBody, PlanarBody or Particle
        The body.
    state : RigidBodyState, PlanarBodyState or ParticleState
        Its state, of the body's kind and finite (a state a diverged step returned is refused).
    gravity : None, bool or array_like, default None
        g_W [m/s^2] in W: None (the default, as in simulate: no field, so V = 0 J), True (0, 0, -9.81) or a
        vector, shape (3,); for a PlanarBody None or an in-plane vector, shape (2,).
    
    Returns
    -------
    float
        V [J].
    
    Raises
    ------
    TypeError
        body not one of the kinds listed, or state not of the body's kind (the message names it).
    ValueError
        A state that is not finite or whose quaternion is farther than 1e-6 from unit norm (the message names
        state.<field>); an argument of another shape, or a quantity of another dimension (the message names it).
    
    See Also
    --------
    kinetic_energy, simulate
    
    Examples
    --------
    >>> V = rd.potential_energy(rd.Particle(2.0), rd.ParticleState(p_W=[0, 0, 10.0]), gravity=True)
    >>> print(f"{V:.6f}")  # m g h
    196.200000
    """
def power(state: RigidBodyState | PlanarBodyState | ParticleState, f_W: numpy.typing.ArrayLike | _Quantity, tau_B: numpy.typing.ArrayLike | float | _Quantity | None = None) -> typing.Any:
    """
    Power [W] of a force at the centre of mass and a torque about it: f_W.v_W + tau_B.w_B.
    
    Parameters
    ----------
    state : RigidBodyState, PlanarBodyState or ParticleState
        The state, finite.
    f_W : array_like, shape (3,) or (2,), or pint.Quantity
        Force at the centre of mass, in W [N]; shape (2,) for a PlanarBodyState.
    tau_B : array_like, shape (3,), float or pint.Quantity, optional
        Torque about the centre of mass [N m] (None: none): in B, shape (3,), for a RigidBodyState; a float about
        z for a PlanarBodyState; None for a ParticleState.
    
    Returns
    -------
    float
        The power [W].
    
    Raises
    ------
    TypeError
        state not one of the kinds listed (the message names it).
    ValueError
        A state that is not finite, an argument of another shape or dimension, or tau_B for a ParticleState.
    
    See Also
    --------
    inverse_dynamics, kinetic_energy
    
    Examples
    --------
    >>> rd.power(rd.RigidBodyState(v_W=[1, 0, 0], w_B=[0, 0, 2]), f_W=[3, 0, 0], tau_B=[0, 0, 0.5])
    4.0
    """
def principal_axes(inertia: numpy.typing.ArrayLike) -> PrincipalAxes:
    """
    Principal moments and axes of rotational inertias (Craig, "Principal Axes").
    
    I = axes @ diag(moments) @ axes.T, about the point and in the frame the inertia is given for. Reads the
    lower triangles (the matrices are taken as symmetric). Releases the GIL.
    
    Parameters
    ----------
    inertia : array_like, shape (3, 3) or (n, 3, 3)
        Symmetric rotational inertias [kg m^2].
    
    Returns
    -------
    PrincipalAxes
        moments, shape (3,) or (n, 3), ascending [kg m^2]; axes, shape (3, 3) or (n, 3, 3), column k the
        unit axis of moments[k], right-handed (det +1), canonical when moments coincide. Unpacks as
        ``moments, axes = principal_axes(I)``.
    
    Raises
    ------
    ValueError
        `inertia` of another shape (the message names it).
    
    See Also
    --------
    PrincipalAxes, SpatialInertia.principal_axes
    
    Examples
    --------
    >>> moments, axes = rd.principal_axes(np.diag([3.0, 1.0, 2.0]))
    >>> moments
    array([1., 2., 3.])
    >>> axes
    array([[0., 0., 1.],
           [1., 0., 0.],
           [0., 1., 0.]])
    >>> rd.principal_axes(np.stack([np.eye(3), np.diag([3.0, 1.0, 2.0])])).moments
    array([[1., 1., 1.],
           [1., 2., 3.]])
    """
def quat_canonical(q: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    The canonical quaternion of each rotation (q and -q are the same rotation).
    
    w > 0, or where w = 0 the first non-zero of x, y, z positive, exactly as SciPy's
    ``Rotation.from_quat(q).as_quat(canonical=True)``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q or -q, in the order of the input.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a wrong shape.
    
    See Also
    --------
    quat_normalize, matrix_to_quat
    
    Examples
    --------
    >>> rd.quat_canonical([[0.0, 0.6, 0.0, -0.8], [0.0, -1.0, 0.0, 0.0]]) + 0.0
    array([[ 0. , -0.6,  0. ,  0.8],
           [ 0. ,  1. ,  0. ,  0. ]])
    """
def quat_integrate(q: numpy.typing.ArrayLike, w: numpy.typing.ArrayLike, dt: float, frame: typing.Literal['body', 'world'] = 'body', scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exact attitude update for an angular velocity constant over a step.
    
    frame='body': q(t + dt) = q ⊗ exp(w_B dt/2), w_B expressed in B; frame='world':
    q(t + dt) = exp(w_W dt/2) ⊗ q, w_W expressed in W; exp of a pure vector u is (sin|u| u/|u|, cos|u|)
    (Solà, "Quaternion kinematics for the error-state Kalman filter"). With SciPy, frame='body' is
    ``r * Rotation.from_rotvec(w * dt)``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within
        1e-6 of 1 (then normalised).
    w : array_like, shape (3,) or (n, 3)
        Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world'); a
        single q or w is used with every item of the other.
    dt : float
        Time step [s], finite.
    frame : {'body', 'world'}, default 'body'
        The frame `w` is expressed in.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q(t + dt), normalised, in the order of the input.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    ValueError
        `w` of a wrong shape or non-finite, a non-finite `dt`, stacks of different lengths, or `frame`
        not 'body' or 'world'.
    
    See Also
    --------
    quat_rate, rotvec_to_quat
    
    Examples
    --------
    Turning at pi/2 rad/s about z for 1 s is a quarter turn:
    
    >>> q = rd.quat_integrate([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, np.pi / 2], 1.0)
    >>> rd.quat_to_rotvec(q).round(12)
    array([0.        , 0.        , 1.57079633])
    """
def quat_inverse(q: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Inverse (conjugate) of unit quaternions.
    
    q^-1 = (-x, -y, -z, w): q_BW from q_WB. SciPy: ``Rotation.from_quat(q).inv()``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q^-1, in the order of the input.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    See Also
    --------
    quat_multiply
    
    Examples
    --------
    >>> q = rd.rotvec_to_quat([0.3, -0.2, 0.9])
    >>> rd.quat_multiply(q, rd.quat_inverse(q)).round(12)
    array([0., 0., 0., 1.])
    """
def quat_multiply(q1: numpy.typing.ArrayLike, q2: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Hamilton product q1 ⊗ q2 of unit quaternions.
    
    R(q1 ⊗ q2) = R(q1) R(q2): q2 is applied first, so q_WC = q_WB ⊗ q_BC. SciPy: ``r1 * r2``.
    
    Parameters
    ----------
    q1, q2 : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised). A single one is used with every item of the other.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q1 ⊗ q2, in the order of the input.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it
        and, in a stack, the item), a wrong shape, or stacks of different lengths.
    
    See Also
    --------
    quat_inverse, quat_rotate
    
    Examples
    --------
    A quarter turn about z applied twice is a half turn:
    
    >>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])
    >>> rd.quat_multiply(q, q).round(12)
    array([0., 0., 1., 0.])
    """
def quat_normalize(q: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Quaternions scaled to unit norm, q / |q|.
    
    For finite non-zero quaternions of any norm; the sign is unchanged (no canonical sign). SciPy
    normalises in ``Rotation.from_quat``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Finite non-zero quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q / |q|, in the order of the input.
    
    Raises
    ------
    ValueError
        q = 0, a non-finite entry or a wrong shape (the message names `q` and, in a stack, the item).
    
    See Also
    --------
    quat_canonical
    
    Examples
    --------
    >>> rd.quat_normalize([0.0, 0.0, -3.0, 4.0])
    array([ 0. ,  0. , -0.6,  0.8])
    """
def quat_rate(q: numpy.typing.ArrayLike, w: numpy.typing.ArrayLike, frame: typing.Literal['body', 'world'] = 'body', scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Quaternion rate dq/dt of an attitude turning with an angular velocity.
    
    frame='body': dq/dt = 1/2 q ⊗ (w_B, 0), w_B expressed in B; frame='world': dq/dt = 1/2 (w_W, 0) ⊗ q,
    w_W expressed in W (Solà, "Quaternion kinematics for the error-state Kalman filter"). The result is
    orthogonal to q, with |dq/dt| = |w|/2. SciPy has no equivalent.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Attitudes q_WB, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within
        1e-6 of 1 (then normalised).
    w : array_like, shape (3,) or (n, 3)
        Angular velocity [rad/s] of B in W, expressed in B (frame='body') or in W (frame='world'); a
        single q or w is used with every item of the other.
    frame : {'body', 'world'}, default 'body'
        The frame `w` is expressed in.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        dq/dt [1/s], in the order of q.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    ValueError
        `w` of a wrong shape or non-finite, stacks of different lengths, or `frame` not 'body' or
        'world'.
    
    See Also
    --------
    angular_velocity_from_quat_rate, quat_integrate
    
    Examples
    --------
    >>> q = rd.rotvec_to_quat([0.4, 0.0, 0.0])
    >>> dq = rd.quat_rate(q, [0.0, 2.0, 0.0])
    >>> f"{q @ dq:.12f}", f"{np.linalg.norm(dq):.12f}"
    ('0.000000000000', '1.000000000000')
    """
def quat_rotate(q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Vectors rotated actively by unit quaternions, R(q) v.
    
    With q = q_WB, v_W = R_WB v_B. SciPy: ``Rotation.from_quat(q).apply(v)``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    v : array_like, shape (3,) or (n, 3)
        Vectors (any unit); a single q or v is used with every item of the other.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        R(q) v, in the unit of v.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    ValueError
        `v` of a wrong shape or non-finite, or stacks of different lengths.
    
    See Also
    --------
    quat_to_matrix
    
    Examples
    --------
    >>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])
    >>> rd.quat_rotate(q, [[1.0, 0.0, 0.0], [0.0, 0.0, 2.0]]).round(12)
    array([[0., 1., 0.],
           [0., 0., 2.]])
    """
def quat_to_axis_angle(q: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> tuple[numpy.typing.NDArray[numpy.float64], typing.Any]:
    """
    Unit axis and angle in [0, pi] of unit quaternions.
    
    The identity gives axis (1, 0, 0), angle 0. SciPy has no axis-angle pair: ``as_rotvec`` gives their
    product, and ``magnitude`` the angle.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    axis : ndarray, shape (3,) or (n, 3)
        Unit rotation axes.
    angle : float or ndarray, shape (n,)
        Angles [rad] in [0, pi] (degrees in [0, 180] if `degrees`).
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    See Also
    --------
    axis_angle_to_quat, quat_to_rotvec, angular_distance
    
    Examples
    --------
    >>> axis, angle = rd.quat_to_axis_angle([0.0, 0.0, -np.sin(0.25), np.cos(0.25)])
    >>> axis.round(12), round(angle, 12)
    (array([ 0.,  0., -1.]), 0.5)
    >>> rd.quat_to_axis_angle([0.0, 0.0, 0.0, 1.0])
    (array([1., 0., 0.]), 0.0)
    """
def quat_to_davenport(axes: numpy.typing.ArrayLike, order: str, q: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Davenport angles of unit quaternions (rotations about three arbitrary axes).
    
    By the method of Bernardes & Viollet ("Quaternion to Euler angles conversion: a direct, general and
    computationally efficient method") for arbitrary axes. SciPy:
    ``Rotation.from_quat(q).as_davenport(axes, order)``.
    
    Parameters
    ----------
    axes : array_like, shape (3, 3)
        The rotation axes n1, n2, n3 as rows (any non-zero length, normalised), n2 orthogonal to n1 and
        to n3 (|cos| <= 1e-7, as SciPy). Coordinate axes give Euler angles.
    order : str
        'e' or 'extrinsic' (fixed axes, R = R_n3(a3) R_n2(a2) R_n1(a1)) or 'i' or 'intrinsic' (moving
        axes, R = R_n1(a1) R_n2(a2) R_n3(a3)), as SciPy's `Rotation.from_davenport` / `as_davenport`.
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`) in the order of the axes, as SciPy: first and third in
        [-pi, pi], second in [-l, pi - l] if l >= 0, [-pi - l, -l] if l < 0, where
        l = atan2(m3 . (m1 x n2), m3 . m1) with (m1, m3) = (n1, n3), or (n3, n1) if intrinsic (proper
        Euler: l = 0, second in [0, pi]; Tait-Bryan: l = +-pi/2, second in [-pi/2, pi/2]).
    
    Raises
    ------
    ValueError
        `axes` not of shape (3, 3), with a zero row or with n2 not orthogonal to n1 and n3 (the message
        names `axes`); `order` not one of 'e', 'extrinsic', 'i', 'intrinsic'.
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    Warns
    -----
    UserWarning
        'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the middle angle of some item
        within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper sequences, -pi/2 or pi/2
        in Tait-Bryan ones; Davenport angles: the ends of its range). Within round-off of it (1e-13 rad)
        only the sum or difference of the first and third angles is defined: the third is set to 0 and
        the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad the angles are the exact ones
        and the message says so (SciPy sets the third to 0 there too, which moves the rotation by up to
        2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    
    See Also
    --------
    davenport_to_quat, quat_to_euler
    
    Examples
    --------
    Angles about tilted axes come back:
    
    >>> axes = [[1.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]
    >>> q = rd.davenport_to_quat(axes, "i", [0.5, -0.3, 1.2])
    >>> rd.quat_to_davenport(axes, "i", q).round(12)
    array([ 0.5, -0.3,  1.2])
    """
def quat_to_euler(seq: str, q: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Euler angles of unit quaternions.
    
    By the atan2-only method of Bernardes & Viollet ("Quaternion to Euler angles conversion: a direct,
    general and computationally efficient method"), accurate at all angles. SciPy:
    ``Rotation.from_quat(q).as_euler(seq)``.
    
    Parameters
    ----------
    seq : str
        The axis sequence, 3 letters as SciPy's: lowercase 'xyz' = extrinsic (rotations about the
        fixed axes of W), uppercase 'XYZ' = intrinsic (about the moving axes); the 12 sequences xyz xzy
        yxz yzx zxy zyx xyx xzx yxy yzy zxz zyz in either case.
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Angles [rad] (degrees if `degrees`) in the order of `seq`: first and third in [-pi, pi], second
        in [0, pi] (proper Euler sequences) or [-pi/2, pi/2] (Tait-Bryan).
    
    Raises
    ------
    ValueError
        `seq` not one of the 24 sequences.
    TypeError
        `seq` not a str.
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    Warns
    -----
    UserWarning
        'Gimbal lock detected. ...' (once per call) wherever SciPy warns: the middle angle of some item
        within 1e-7 rad of its singularity (Euler angles: 0 or pi in proper sequences, -pi/2 or pi/2
        in Tait-Bryan ones; Davenport angles: the ends of its range). Within round-off of it (1e-13 rad)
        only the sum or difference of the first and third angles is defined: the third is set to 0 and
        the first carries it, with SciPy's message. Between 1e-13 and 1e-7 rad the angles are the exact ones
        and the message says so (SciPy sets the third to 0 there too, which moves the rotation by up to
        2e-7 rad): the angles reproduce the rotation to round-off everywhere.
    
    See Also
    --------
    euler_to_quat, matrix_to_euler, quat_to_davenport
    
    Examples
    --------
    >>> q = rd.euler_to_quat("ZYX", [0.1, 0.2, 0.3])
    >>> rd.quat_to_euler("ZYX", q).round(12)
    array([0.1, 0.2, 0.3])
    >>> rd.quat_to_euler("zxz", rd.rotvec_to_quat([90.0, 0.0, 0.0], degrees=True), degrees=True)
    array([ 0., 90.,  0.])
    """
def quat_to_matrix(q: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotation matrix of unit quaternions.
    
    R(q) is the active rotation: R v rotates v, and the attitude q_WB gives R_WB (B coordinates to W
    coordinates). SciPy: ``Rotation.from_quat(q).as_matrix()``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R(q), orthonormal with det +1.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    See Also
    --------
    matrix_to_quat, quat_rotate, rot_x
    
    Examples
    --------
    A quarter turn about z takes x to y:
    
    >>> q = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])
    >>> rd.quat_to_matrix(q).round(12)
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
def quat_to_mrp(q: numpy.typing.ArrayLike, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Modified Rodrigues parameters of unit quaternions.
    
    p = axis tan(angle/4) = (x, y, z) / (1 + w) for the representative with w >= 0, the set with
    |p| <= 1 (angle in [0, pi]); dimensionless (Shuster, "A survey of attitude representations"). SciPy:
    ``Rotation.from_quat(q).as_mrp()``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        p, |p| <= 1.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    See Also
    --------
    mrp_to_quat
    
    Examples
    --------
    A half turn about z has |p| = tan(pi/4) = 1, whatever the quaternion's sign:
    
    >>> rd.quat_to_mrp([0.0, 0.0, -1.0, 0.0]).round(12) + 0.0
    array([0., 0., 1.])
    """
def quat_to_rotvec(q: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Logarithm map: rotation vectors of unit quaternions.
    
    rotvec = theta u with theta in [0, pi] (q and -q give the same vector), by the atan2 form: accurate
    near angle 0 and near pi. SciPy: ``Rotation.from_quat(q).as_rotvec()``.
    
    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        Rotation vectors angle * axis [rad], angle in [0, pi] (degrees, angle in [0, 180], if
        `degrees`).
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names `q`
        and, in a stack, the item), or a shape other than (4,) or (n, 4).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    
    See Also
    --------
    rotvec_to_quat, quat_to_axis_angle, matrix_to_rotvec
    
    Examples
    --------
    The logarithm undoes the exponential for angles up to pi:
    
    >>> rotvec = np.array([0.3, -1.2, 2.0])
    >>> np.allclose(rd.quat_to_rotvec(rd.rotvec_to_quat(rotvec)), rotvec)
    True
    >>> rd.quat_to_rotvec([0.0, 0.0, -1.0, 0.0], degrees=True).round(9) + 0.0
    array([  0.,   0., 180.])
    """
def random_rotations(n: int | None = None, rng: numpy.random.Generator | int | None = None, scalar_first: bool = False, canonical: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Rotations drawn uniformly (Haar measure) from SO(3), as unit quaternions.
    
    Normalised standard normal 4-vectors are uniform on the unit sphere of R^4 (Shoemake 1992, "Uniform
    random rotations"). The draws are SciPy's: for the same generator state the result equals
    ``Rotation.random(n, rng=rng).as_quat()``, and the generator advances by 4 n normal draws.
    
    Parameters
    ----------
    n : int or None, default None
        None for one rotation (shape (4,)), or a count >= 0 (shape (n, 4)).
    rng : numpy.random.Generator, int or None, default None
        A generator, or None / a seed (int >= 0) given to ``numpy.random.default_rng``.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    canonical : bool, default False
        Return the representative with w >= 0 (SciPy's ``as_quat(canonical=True)``: at w = 0 the first
        non-zero of x, y, z is positive).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        Unit quaternions, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        `n` negative or too large to allocate.
    TypeError
        `rng` not a Generator, None or an int seed.
    
    See Also
    --------
    quat_canonical
    
    Examples
    --------
    >>> q = rd.random_rotations(1000, rng=0, canonical=True)
    >>> q.shape, np.allclose(np.linalg.norm(q, axis=1), 1.0), bool((q[:, 3] >= 0).all())
    ((1000, 4), True, True)
    """
def relative_kinematics(K_WA: FrameKinematics, K_WF: FrameKinematics) -> FrameKinematics:
    """
    Kinematics of F relative to A from those of A and of F relative to a common frame W.
    
    The inverse of compose_kinematics: compose_kinematics(K_WA, relative_kinematics(K_WA, K_WF)) is K_WF.
    
    Parameters
    ----------
    K_WA : FrameKinematics
        A relative to W, expressed in W.
    K_WF : FrameKinematics
        F relative to W, expressed in W.
    
    Returns
    -------
    FrameKinematics
        F relative to A, expressed in A.
    
    Raises
    ------
    TypeError
        An argument not a FrameKinematics (naming it).
    
    See Also
    --------
    compose_kinematics, FrameTree.kinematics
    
    Examples
    --------
    >>> K_WA = rd.FrameKinematics(w_PF_P=[0.0, 0.0, 1.0])
    >>> K_AF = rd.FrameKinematics(w_PF_P=[1.0, 0.0, 0.0], p_PF_P=[2.0, 0.0, 0.0])
    >>> K = rd.relative_kinematics(K_WA, rd.compose_kinematics(K_WA, K_AF))
    >>> bool(np.allclose(K.w_PF_P, K_AF.w_PF_P) and np.allclose(K.a_PF_P, K_AF.a_PF_P))
    True
    """
def require_closed_oriented_mesh(faces: numpy.typing.ArrayLike, n_vertices: int) -> None:
    """
    Check that triangles form a closed, consistently oriented mesh.
    
    Every edge must be shared by exactly two faces, traversed once in each direction.
    
    Parameters
    ----------
    faces : array_like of int, shape (f, 3)
        Vertex indices of each triangle.
    n_vertices : int
        Number of vertices n, >= 0; indices must lie in [0, n).
    
    Returns
    -------
    None
    
    Raises
    ------
    ValueError
        No faces, an index outside [0, n), a face repeating a vertex, an open edge or a misoriented edge
        (the message names the face and the edge).
    
    See Also
    --------
    solid_mesh, weld_vertices
    
    Examples
    --------
    >>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> rd.require_closed_oriented_mesh(faces, 4)
    >>> rd.require_closed_oriented_mesh(faces[:3], 4)
    Traceback (most recent call last):
        ...
    ValueError: faces: expected a closed mesh (every edge shared by exactly two faces), got edge (2, 1) ...
    """
def rnea(tree: Tree, q: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, a: numpy.typing.ArrayLike, f_ext: numpy.typing.ArrayLike | None = None) -> numpy.typing.NDArray[numpy.float64]:
    """
    Inverse dynamics by the recursive Newton-Euler algorithm: tau = H(q) a + C(q, v, f_ext).
    
    Featherstone, Rigid Body Dynamics Algorithms, Table 5.1, with the tree's gravity as the base
    acceleration -g: the joint forces that give the acceleration a.
    
    Parameters
    ----------
    tree : Tree
    q : array_like, shape (tree.nq,)
        Configuration.
    v : array_like, shape (tree.nv,)
        Velocity.
    a : array_like, shape (tree.nv,)
        Acceleration.
    f_ext : array_like, shape (n, 6), optional
        External force [n; f] on each link, in its link frame (moment about the link's origin)
        [N m, N] (None: none).
    
    Returns
    -------
    ndarray, shape (tree.nv,)
        tau [N m for a rotation, N for a translation].
    
    Raises
    ------
    ValueError
        A wrong size, a non-finite value or a non-unit quaternion (naming it).
    
    See Also
    --------
    bias_forces, crba, aba
    
    Examples
    --------
    The torque that holds the pendulum horizontal is m g l:
    
    >>> tree = rd.Tree(gravity=[0.0, 0.0, -9.81])
    >>> bob = rd.SpatialInertia(1.0, [0.0, 0.0, -1.0], 0.1 * np.eye(3))
    >>> tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), bob)
    0
    >>> rd.rnea(tree, [np.pi / 2], [0.0], [0.0]).round(12)
    array([9.81])
    """
def rot_x(angle: float | numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation matrix about x (active).
    
    R_x(a) = [[1, 0, 0], [0, c, -s], [0, s, c]] with c = cos a, s = sin a. SciPy:
    ``Rotation.from_euler('x', angle).as_matrix()``.
    
    Parameters
    ----------
    angle : float or array_like, shape (n,)
        Angles [rad] (degrees if `degrees`).
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R_x(angle).
    
    Raises
    ------
    ValueError
        A non-finite angle or a shape other than () or (n,) (the message names `angle`).
    
    See Also
    --------
    rot_y, rot_z, euler_to_matrix
    
    Examples
    --------
    A quarter turn about x takes y to z:
    
    >>> rd.rot_x(90.0, degrees=True).round(12) @ [0.0, 1.0, 0.0]
    array([0., 0., 1.])
    """
def rot_y(angle: float | numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation matrix about y (active).
    
    R_y(a) = [[c, 0, s], [0, 1, 0], [-s, 0, c]] with c = cos a, s = sin a. SciPy:
    ``Rotation.from_euler('y', angle).as_matrix()``.
    
    Parameters
    ----------
    angle : float or array_like, shape (n,)
        Angles [rad] (degrees if `degrees`).
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R_y(angle).
    
    Raises
    ------
    ValueError
        A non-finite angle or a shape other than () or (n,) (the message names `angle`).
    
    See Also
    --------
    rot_x, rot_z, euler_to_matrix
    
    Examples
    --------
    A quarter turn about y takes z to x:
    
    >>> rd.rot_y(np.pi / 2).round(12) @ [0.0, 0.0, 1.0]
    array([1., 0., 0.])
    """
def rot_z(angle: float | numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Elementary rotation matrix about z (active).
    
    R_z(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]] with c = cos a, s = sin a. SciPy:
    ``Rotation.from_euler('z', angle).as_matrix()``.
    
    Parameters
    ----------
    angle : float or array_like, shape (n,)
        Angles [rad] (degrees if `degrees`).
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R_z(angle).
    
    Raises
    ------
    ValueError
        A non-finite angle or a shape other than () or (n,) (the message names `angle`).
    
    See Also
    --------
    rot_x, rot_y, euler_to_matrix
    
    Examples
    --------
    A stack of angles gives a stack of matrices:
    
    >>> rd.rot_z([0.0, np.pi / 2]).round(12) @ [1.0, 0.0, 0.0]
    array([[1., 0., 0.],
           [0., 1., 0.]])
    """
def rotvec_to_matrix(rotvec: numpy.typing.ArrayLike, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exponential map into rotation matrices (Rodrigues' formula).
    
    R = I + sin(theta) hat(u) + (1 - cos(theta)) hat(u)^2 for rotvec = theta u [rad]. SciPy:
    ``Rotation.from_rotvec(rotvec).as_matrix()``.
    
    Parameters
    ----------
    rotvec : array_like, shape (3,) or (n, 3)
        Rotation vectors angle * axis [rad] (degrees if `degrees`), finite.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (3, 3) or (n, 3, 3)
        R, orthonormal with det +1.
    
    Raises
    ------
    ValueError
        A non-finite entry, or a shape other than (3,) or (n, 3) (the message names `rotvec`).
    
    See Also
    --------
    matrix_to_rotvec, rotvec_to_quat, hat
    
    Examples
    --------
    >>> rd.rotvec_to_matrix([0.0, 0.0, 90.0], degrees=True).round(12)
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
def rotvec_to_quat(rotvec: numpy.typing.ArrayLike, scalar_first: bool = False, *, degrees: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Exponential map: unit quaternion of rotation vectors.
    
    q = (sin(theta/2) u, cos(theta/2)) for rotvec = theta u [rad], u a unit axis; any angle, exact near
    0. No sign flip: w < 0 when the angle exceeds pi. SciPy: ``Rotation.from_rotvec(rotvec).as_quat()``.
    
    Parameters
    ----------
    rotvec : array_like, shape (3,) or (n, 3)
        Rotation vectors angle * axis [rad] (degrees if `degrees`), finite.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    degrees : bool, default False, keyword-only
        Angles in degrees instead of radians (converted as SciPy does: x * (pi/180) in,
        x * (180/pi) out).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        A non-finite entry, or a shape other than (3,) or (n, 3) (the message names `rotvec`).
    
    See Also
    --------
    quat_to_rotvec, rotvec_to_matrix, axis_angle_to_quat
    
    Examples
    --------
    >>> rd.rotvec_to_quat([0.0, 0.0, np.pi]).round(12)
    array([0., 0., 1., 0.])
    >>> rd.rotvec_to_quat([0.0, 90.0, 0.0], degrees=True)
    array([0.        , 0.70710678, 0.        , 0.70710678])
    """
def screw_to_twist(screw: Screw) -> Motion:
    """
    The twist of a screw, inverse of twist_to_screw.
    
    w = magnitude direction, v = magnitude (point x direction + pitch direction) (v = magnitude direction for
    pitch inf), angular part first.
    
    Parameters
    ----------
    screw : Screw
        Unit direction, point [m], pitch [m/rad], magnitude.
    
    Returns
    -------
    Motion
        [w; v] ([rad/s], [m/s]) in the screw's frame.
    
    Raises
    ------
    ValueError
        A direction that is not a unit vector, or a non-finite part (the message names it).
    TypeError
        screw not a Screw.
    
    See Also
    --------
    twist_to_screw, Screw
    
    Examples
    --------
    >>> V = rd.Motion([0.0, 0.0, 2.0], [0.0, 2.0, 0.5])
    >>> rd.screw_to_twist(rd.twist_to_screw(V)) == V
    True
    """
def semi_latus_rectum(a: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    Semi-latus rectum p = a (1 - e^2) of the semi-major axis: the first element of `elements_to_state`.
    
    Parameters
    ----------
    a : float or array_like, shape (n,)
        Semi-major axis [m]: > 0 for an ellipse, < 0 for a hyperbola (a = -mu/(2 energy)).
    e : float or array_like, shape (n,)
        Eccentricity, finite, >= 0 and != 1 (a parabola's a is infinite: give its p).
    
    Returns
    -------
    float or ndarray, shape (n,)
        p [m], > 0.
    
    Raises
    ------
    ValueError
        `a` not finite, 0 or of the wrong sign for `e`, or `e` not finite, < 0 or 1 (the message names it).
    
    See Also
    --------
    elements_to_state
    
    Examples
    --------
    >>> round(rd.semi_latus_rectum(7000e3, 0.1), 6)
    6930000.0
    >>> rd.semi_latus_rectum(-7000e3, 2.0)
    21000000.0
    """
def simulate(model: Particle | PlanarBody | RigidBody | PivotedBody | PivotedPlanarBody | Gyrostat | Scene | CompiledScene, initial: typing.Any, dt: float | _Quantity | None = None, steps: int | None = None, method: _MethodName | None = None, record_every: int = 1, loads: AppliedLoad | collections.abc.Sequence[AppliedLoad] | None = None, gravity: bool | numpy.typing.ArrayLike | None = None, t0: float | _Quantity = 0.0, scalar_first: bool = False, progress: collections.abc.Callable[..., typing.Any] | None = None, *, duration: float | _Quantity | None = None, error: bool = True, accuracy_level: float | None = 0.001, tolerance: float | _Quantity | None = None, measure: str | None = None, max_steps: int | None = None, controller: typing.Any = None) -> SceneResult:
    """
    Integrate a body or a scene over fixed steps and record its motion.
    
    Runs `steps` fixed steps of `dt` with `method` (see methods()) from `initial` at time t0, in C++ with the GIL
    released (a run of fewer than 512 steps times bodies keeps it, unless a controller drives it: taking it back would
    cost more than such a run, and could wait for another thread), and records every `record_every`-th step plus the
    first and the last (records at t0 + i dt). The loads are a piecewise-constant schedule: a step that crosses a
    switch time (a t_start or t_end) is split there into sub-steps of the same method, so every method keeps its order.
    
    Parameters
    ----------
    model : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat, Scene or CompiledScene
        What to integrate. A body runs as its one-body scene with a UniformGravity (`gravity`) and a
        ScheduledLoads (`loads`).
    initial : ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, ..., or list
        The state of `model`'s kind at t0 (also PivotedPlanarBodyState or GyrostatState); for a Scene or
        CompiledScene, a list of the states of its bodies.
    dt : float or pint.Quantity, optional
        Step [s], finite and > 0 (a quantity is converted to s). Exactly one of dt and tolerance.
    steps : int, optional
        Number of steps, >= 0. Exactly one of steps and duration (with tolerance: duration).
    method : str, optional
        A name of methods(): 'explicit_euler', 'semi_implicit_euler', 'semi_implicit_euler_implicit_gyroscopic',
        'rk4', 'rkmk4', 'implicit_midpoint', 'splitting_dlm', 'splitting_dlm_yoshida4', 'exact_flow_kick' or 'exact'.
        None (the default): 'rk4', or the method a CompiledScene was compiled for.
    record_every : int, default 1
        Record every record_every-th step (>= 1), plus the first and the last.
    loads : AppliedLoad or sequence of AppliedLoad, optional
        The applied loads (None: none). A Scene or CompiledScene takes None (it declares its loads as elements).
    gravity : None, bool or array_like, shape (3,), default None
        Uniform gravity g_W [m/s^2] in W: None or False (none), True ((0, 0, -9.81)) or a vector. A PivotedPlanarBody
        takes None or an in-plane vector, shape (2,) or (3,); a Scene or CompiledScene takes None (declare a
        UniformGravity element).
    t0 : float or pint.Quantity, default 0.0
        Initial time [s].
    scalar_first : bool, default False
        Record quaternions as (w, x, y, z) instead of (x, y, z, w).
    progress : callable, optional
        progress(steps_done), called with the GIL after the first step and then about every 0.05 s of a long run,
        however long a step takes; an exception it raises stops the run and propagates.
    duration : float or pint.Quantity, keyword-only, optional
        Length of the run [s] instead of steps: a whole number of steps of dt (to 1e-9 relative: 10 s at
        dt = 0.01 s is 1000 steps).
    error : bool, keyword-only, default True
        Estimate the global error of every record (result.error, a GlobalError) by two more runs of the method at 2 dt
        and 4 dt (+0.75x the cost; global Richardson extrapolation with an observed-order check, see GlobalError).
        A run without a PythonForce, a control law in Python or a progress callback, whose balances close whatever the
        estimate says, makes it on the first read of result.error, from the records the result keeps (the same values,
        the GIL released meanwhile), so that a run whose state alone is read pays for the run alone.
        False: no estimate (result.error is None), the cost of the run alone. True with tolerance.
    accuracy_level : float or None, keyword-only, default 1e-3
        The relative residual of an energy or momentum balance (result.balance) beyond which a run without a reliable
        global error estimate warns with an AccuracyWarning (where the estimate is reliable, a residual beyond 10 times
        its bound warns instead); finite and > 0. None: no AccuracyWarning (the balance is still made). Runs that are
        coarse on purpose (work-precision studies) pass None.
    tolerance : float or pint.Quantity, keyword-only, optional
        Instead of dt: the largest error of `measure` the run may have, absolute, in the measure's unit (a quantity
        is converted to it), finite and > 0. The method (unless given) and dt are chosen: each candidate method is
        piloted on a short run, its error fitted as C dt^p (t - t0), and the cheapest (method, dt) predicted to meet
        half the tolerance is run with its global error estimate as the certificate, refined while that fails (at
        most three times; see ToleranceChoice). The horizon is `duration` (steps depend on dt: steps is refused);
        record_every counts steps of the chosen dt; steps is a multiple of lcm(record_every, 4), so every record is
        checked (up to 1024 after t0, see GlobalError). Where the loads switch inside the horizon, every run's 4 dt
        ends at the switch times when a grid of at most 256 steps holds them; elsewhere a switch splits a step of the
        estimate's coarse runs, and the certificate takes no record whose order check failed.
        result.choice says what was chosen and why. A scene with a PythonForce is refused (ToleranceError): its
        estimate is never reliable.
    measure : str, keyword-only, optional
        The quantity the tolerance bounds, its largest estimate over the records (and bodies): 'attitude' [rad],
        'angular_velocity' [rad/s], 'position' [m], 'velocity' [m/s], 'energy' [J] or 'angular_momentum'
        [kg m^2/s]. None (the default): 'position' for a Particle and a scene of particles, else 'attitude'
        (which, like 'angular_velocity', a scene of particles refuses: ValueError).
    max_steps : int, keyword-only, optional
        The cost cap of a run to a tolerance: no run (the final run and its refinement) of more steps, >= 4.
        None (the default): 10_000_000.
    controller : Controller, keyword-only, optional
        A digital controller (rigiddyn.Controller) of a body or a scene: its law is
        called with the GIL at t0 + k controller.period, k = 0, 1, ... before the end of the run, with the state of every
        body there, and its actuator commands (gyrostat wheel torques, MagneticDipole dipoles, ScheduledLoads thrusts)
        are held until the next sample; the steps are split at the samples, as at switch times, so every method keeps
        its order. The estimate's runs at 2 dt and 4 dt each go under a copy of the controller as it was before the
        run: a shipped law's, or a law in Python declared Controller(..., repeatable=True) (copy.deepcopy); an
        undeclared law in Python is sampled by the run alone, and result.error has no values, its verdict saying
        why. With tolerance, every run of the choice (pilots, the run, its estimate's runs) goes under a copy of the
        controller as it was before the call, which the law given never sees, and steps on a divisor of period / 4
        (so that no sample splits a step of the runs at 2 dt and 4 dt alone); the duration must then be a whole
        number of period / 4, and a law in Python must be declared repeatable. None (the default): no controller.
    
    Returns
    -------
    SceneResult
        One row per record, n records, of every kind of model: per body (n, nb, ...) arrays (p_W, q_WB, v_W, w_B,
        mass, ...), the scene's (n,) energies and (n, ne) work of each element (a body's one-body scene: its
        UniformGravity first, then its ScheduledLoads); diverged, unconverged_steps, elapsed_seconds; error; balance;
        choice. result.body(0) (a BodyRecords) reads one body's records as (n, ...) arrays: q_WB (n, 4), ... The
        records are those of the run at dt whether or not error is True; elapsed_seconds
        is its loop's. result.balance (a Balance, on every run) holds the residuals of the work-energy and
        impulse-momentum balances per record, zero for the exact dynamics. With tolerance, result.choice is a
        ToleranceChoice (else None).
    
    Raises
    ------
    ValueError
        A bad argument, named: dt not > 0, steps < 0, both or neither of steps and duration, a duration that is not a
        whole number of steps of dt (the message gives the nearest durations that are), an unknown method (with the
        nearest name), record_every < 1, a recording larger than the memory available (record_every, with both
        figures), a quantity of another dimension, loads or gravity for a scene, accuracy_level not finite and > 0;
        with tolerance: tolerance not finite and > 0, dt or steps given too, no duration, error False, an unknown
        measure (with the nearest name), max_steps < 4; with a controller: a body outside a scene, a bad command
        (named by the controller), and with tolerance a law in Python not declared repeatable or a duration that is not
        a whole number of period / 4.
    ToleranceError
        A ValueError: the tolerance cannot be met within max_steps, the last refined run's certificate still fails, or the
        scene has a PythonForce; it carries the measured error, the choice and the best result (see ToleranceError).
    TypeError
        model not one of the kinds listed, or initial not of its kind (the message names it).
    KeyboardInterrupt
        Ctrl-C stops the run within about 0.05 s however long a step takes (a step under way is finished first); no
        result is kept.
    
    Warns
    -----
    RuntimeWarning
        The state became non-finite (the run stops there and diverged is True); a recorded quantity is not finite
        although the state is (an overflow, e.g. the kinetic energy of |v_W| > 1e154 m/s; the message names the
        quantities and their first times); an implicit solve did not converge (naming dt and the count).
    AccuracyWarning
        An energy or momentum balance does not close: its residual exceeds 10 times the reliable global error
        estimate's bound (plus round-off), or, without a reliable estimate, accuracy_level of its scale (see Balance);
        the message gives the figure and suggests a smaller dt or another method.
    
    See Also
    --------
    step, simulate_batch, methods, SceneResult, BodyRecords, AppliedLoad, Scene, GlobalError, Balance,
    AccuracyWarning, ToleranceChoice
    
    Notes
    -----
    A Particle records q = identity and w = 0; a PlanarBody records p = (x, y, 0), q = Rz(theta), w = (0, 0, omega).
    work is integrated by the same method as the motion, so kinetic_energy - kinetic_energy[0] ~ work.sum(axis=1).
    
    Examples
    --------
    A dropped particle follows z = -1/2 g t^2; rk4 integrates a quadratic motion exactly (round-off only):
    
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.01, duration=2.0, gravity=True, record_every=50)
    >>> r.t
    array([0. , 0.5, 1. , 1.5, 2. ])
    >>> np.allclose(r.body(0).p_W[:, 2], -0.5 * 9.81 * r.t**2, rtol=0, atol=1e-12)
    True
    
    A torque-free body keeps its kinetic energy and |H_G|; implicit_midpoint holds both to its Newton tolerance
    (1e-14 per step):
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> r = rd.simulate(body, rd.RigidBodyState(w_B=[1.0, 0.1, 0.2]), dt=0.01, steps=1000, method="implicit_midpoint")
    >>> body_records = r.body(0)
    >>> body_records.q_WB.shape, bool(np.ptp(r.kinetic_energy) < 1e-10), bool(np.ptp(body_records.angular_momentum_norm) < 1e-10)
    ((1001, 4), True, True)
    
    A force of 2 N on 1 kg for the first second (the step across t = 1 s is split there):
    
    >>> push = rd.AppliedLoad(force=[2.0, 0.0, 0.0], t_end=1.0)
    >>> rd.simulate(rd.Particle(1.0), rd.ParticleState(), dt=0.3, steps=5, loads=push).body(0).v_W[-1].round(12)
    array([2., 0., 0.])
    
    How accurate a run is: rk4 on a tumbling body, its attitude's error at the last record [rad]:
    
    >>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.01, steps=1000)
    >>> r.error.verdict[-1], bool(r.error.attitude[-1] < 1e-8)
    ('reliable', True)
    
    Its balances close: the energy residual T - T0 - work and |H_G - H_G0| stay far below their scale:
    
    >>> r.balance.verdict["energy"], r.balance.verdict["angular_momentum"], bool(abs(r.balance.energy[-1]) < 1e-9)
    ('closed', 'closed', True)
    
    Or ask for the accuracy and let the method and dt be chosen: the attitude within 1e-7 rad over 10 s:
    
    >>> r = rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), duration=10.0, tolerance=1e-7)
    >>> r.choice.met, bool(r.error.attitude.max() <= 1e-7), float(r.t[-1])
    (True, True, 10.0)
    """
def simulate_batch(model: Particle | PlanarBody | RigidBody | Scene | CompiledScene | collections.abc.Sequence[Particle] | collections.abc.Sequence[PlanarBody] | collections.abc.Sequence[RigidBody] | collections.abc.Sequence[Scene] | collections.abc.Sequence[CompiledScene], initial: typing.Any, dt: float | numpy.typing.ArrayLike | _Quantity, steps: int | None = None, method: _MethodName | None = None, record_every: int = 1, loads: typing.Any = None, gravity: bool | numpy.typing.ArrayLike | None = None, t0: float | _Quantity = 0.0, threads: int | None = None, simd: bool = False, scalar_first: bool = False, progress: collections.abc.Callable[..., typing.Any] | None = None, *, duration: float | _Quantity | None = None, error: bool = True) -> BatchSceneResult:
    """
    N independent runs of a body or a scene, one per initial state, in parallel.
    
    Integrated in C++ on `threads` threads with the GIL released. Sample i is exactly
    ``rigiddyn.simulate(model_i, initial[i], dt_i, steps, method, record_every, loads_i, gravity_i, t0)``: the
    records equal N serial simulate calls bitwise, whatever the thread count (the SIMD path: up to round-off).
    steps (or duration), record_every, t0, method and scalar_first are shared by every sample, so every sample has
    the same record count n. A body runs as its one-body scene, as simulate runs it; gravity or loads given per
    sample are declared in every sample's scene (a UniformGravity of g = 0, a ScheduledLoads without a load
    included), so that the samples' records have the same columns.
    
    Parameters
    ----------
    model : Particle, PlanarBody, RigidBody, Scene, CompiledScene, sequence of Particle, sequence of PlanarBody, sequence of RigidBody, sequence of Scene or sequence of CompiledScene
        One model shared by every sample, or a list of N of one kind (per-sample mass [kg] and inertia about the
        centre of mass in B [kg m^2]; scenes of the same structure: bodies and elements). A scene with a
        PythonForce runs, slowly: each call takes the GIL, so its samples run one at a time.
    initial : list of states, or dict of arrays
        A list of N states of the body's kind (ParticleState, PlanarBodyState, RigidBodyState), or a dict of
        stacked arrays: RigidBody {'p_W': (N, 3) [m] in W, 'q_WB': (N, 4) (x, y, z, w), or (w, x, y, z) with
        scalar_first, 'v_W': (N, 3) [m/s] in W, 'w_B': (N, 3) [rad/s] in B}; Particle {'p_W', 'v_W'}; PlanarBody
        {'p_W': (N, 2) [m], 'theta': (N,) [rad], 'v_W': (N, 2) [m/s], 'omega': (N,) [rad/s]}. A scene: a list of N
        lists of the states of its bodies.
    dt : float, array_like, shape (N,), or pint.Quantity
        Step [s] of every sample, or of each.
    steps : int, optional
        Number of steps (>= 0) of every sample. Exactly one of steps and duration.
    method : str, optional
        A name of methods(); None (the default): 'rk4', or the method the CompiledScenes were compiled for (the same
        for every sample).
    record_every : int, default 1
        Record every record_every-th step (>= 1), plus the first and the last.
    loads : AppliedLoad, sequence of AppliedLoad, or list of N lists of AppliedLoad, optional
        Bodies: one schedule for every sample, as simulate, or one per sample. A scene takes None (it declares its
        loads as elements).
    gravity : None, bool, array_like, shape (3,) or (N, 3), default None
        Bodies: g_W [m/s^2] in W for every sample (None or False: none; True: (0, 0, -9.81)), or one per sample. A
        scene takes None.
    t0 : float or pint.Quantity, default 0.0
        Initial time [s] of every sample.
    threads : int, optional
        Number of threads, >= 1 (None, the default: every hardware thread, default_thread_count()).
    simd : bool, default False
        Run the SIMD path across samples (RigidBody, method 'rk4', constant loads: a force in W and a torque in B
        without time window), eight samples per 512-bit instruction where the CPU has AVX-512F, else four (AVX2) or
        two (SSE2): equal to the scalar path up to round-off, not bitwise.
    scalar_first : bool, default False
        Quaternions, read from a dict and recorded, as (w, x, y, z).
    progress : callable, optional
        progress(samples_done), called with the GIL from the calling thread once before the samples start and then
        about every 0.05 s; an exception it raises stops every sample and propagates.
    duration : float or pint.Quantity, keyword-only, optional
        Length of the runs [s] instead of steps: it must give the same whole number of steps at every sample's dt.
    error : bool, keyword-only, default True
        Estimate the global error of every record of every sample (result.error, a GlobalError with a leading sample
        axis) from two more batches at 2 dt and 4 dt (+0.75x the cost, on the same threads, with the GIL released),
        made on the first read of result.error, result[i].error or a pickle (at once where a scene has a PythonForce); a
        batch that is never asked for it costs what error=False costs. Sample i's estimate is the one simulate gives
        for it (result[i].error). False: no estimate (result.error is None).
    
    Returns
    -------
    BatchSceneResult
        The arrays of SceneResult with a leading sample axis (N, n, ...), and error; result.body(0) reads one body's
        columns as (N, n, ...) arrays (p_W (N, n, 3), q_WB (N, n, 4), ...). A sample whose state becomes non-finite stops alone: diverged[i]
        is True, filled[i] its rows, the rest of its rows NaN (its error rows too, their verdict saying so).
    
    Raises
    ------
    ValueError
        Input errors, before any sample runs, naming the argument: N = 0, mismatched N between model, initial, dt,
        gravity and loads, a wrong dict key or shape, threads < 1, simd for another kind or method, a duration
        giving different step counts. An error of one sample (a bad state, a body running out of mass), after every
        sample has run: "sample <i>: ..." for the lowest such sample.
    TypeError
        A model or state of the wrong kind (the message names it).
    Exception
        An exception raised by a PythonForce (or its wrong return value) stops every sample within about 0.05 s and
        is raised, its message prefixed "sample <i>: " (the first sample that raised; a KeyboardInterrupt as it is).
    KeyboardInterrupt
        Ctrl-C stops every sample within about 0.05 s however long a step takes (the steps under way are finished
        first); no result is kept.
    
    Warns
    -----
    RuntimeWarning
        One names how many samples diverged and the first few; another the samples whose recorded quantities
        became non-finite although their state stayed finite (an overflow, e.g. a kinetic energy of |v_W| > 1e154
        m/s), each quantity with its first time; another the implicit solves that did not converge.
    
    See Also
    --------
    simulate, BatchSceneResult, default_thread_count
    
    Examples
    --------
    Four spins; each sample equals its serial simulate bitwise:
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> states = [rd.RigidBodyState(w_B=[1.0, 0.0, 0.1 * i]) for i in range(4)]
    >>> res = rd.simulate_batch(body, states, dt=0.01, steps=100, threads=2)
    >>> serial = rd.simulate(body, states[2], dt=0.01, steps=100)
    >>> res.w_B.shape, np.array_equal(res.w_B[2], serial.w_B)
    ((4, 101, 1, 3), True)
    >>> res.body(0).w_B.shape
    (4, 101, 3)
    
    Every record of every sample has its global error estimate (rk4: order 4):
    
    >>> res.error.attitude.shape, res.error.order, np.array_equal(res.error.attitude[2], serial.error.attitude)
    ((4, 101, 1), 4, True)
    
    Three particles dropped for 1 s under their own gravity fall g t^2 / 2:
    
    >>> zeros = np.zeros((3, 3))
    >>> drop = rd.simulate_batch(rd.Particle(1.0), {"p_W": zeros, "v_W": zeros}, dt=0.01, duration=1.0,
    ...                          gravity=[[0, 0, -1.0], [0, 0, -2.0], [0, 0, -3.0]], record_every=100)
    >>> drop.t[0], drop.body(0).p_W[:, -1, 2].round(12)
    (array([0., 1.]), array([-0.5, -1. , -1.5]))
    """
def slerp(q0: numpy.typing.ArrayLike, q1: numpy.typing.ArrayLike, t: float | numpy.typing.ArrayLike, scalar_first: bool = False, canonical: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Spherical linear interpolation from q0 (t = 0) to q1 (t = 1): shortest path, constant rate.
    
    q(t) = q0 ⊗ exp(t log(q0^-1 ⊗ q1)), the log at an angle in [0, pi] (Shoemake, "Animating rotation
    with quaternion curves"). Any finite t extrapolates along the arc. SciPy:
    ``Slerp([0, 1], Rotation.from_quat([q0, q1]))(t)``. To interpolate between key rotations at key
    times use `slerp_keys`.
    
    Parameters
    ----------
    q0, q1 : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1 (then
        normalised).
    t : float or array_like, shape (n,)
        Fraction of the way from q0 to q1 (dimensionless); single items of q0, q1, t are used with every
        item of the stacks.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    canonical : bool, default False
        Return the representative with w >= 0 (SciPy's ``as_quat(canonical=True)``: at w = 0 the first
        non-zero of x, y, z is positive).
    
    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        q(t), (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        A quaternion with a non-finite entry or a norm farther than 1e-6 from 1 (the message names it
        and, in a stack, the item), a non-finite t, a wrong shape, or stacks of different lengths.
    
    See Also
    --------
    slerp_keys, angular_distance
    
    Examples
    --------
    Halfway between the identity and a quarter turn about z is an eighth turn:
    
    >>> q1 = rd.rotvec_to_quat([0.0, 0.0, np.pi / 2])
    >>> q = rd.slerp([0.0, 0.0, 0.0, 1.0], q1, 0.5)
    >>> f"{rd.quat_to_rotvec(q)[2]:.12f}", f"{np.pi / 4:.12f}"
    ('0.785398163397', '0.785398163397')
    """
def slerp_keys(times: numpy.typing.ArrayLike, q: numpy.typing.ArrayLike, t: float | numpy.typing.ArrayLike, scalar_first: bool = False, canonical: bool = False) -> numpy.typing.NDArray[numpy.float64]:
    """
    Slerp through key rotations at key times.
    
    On [times[j], times[j+1]] the result is slerp(q[j], q[j+1], (t - times[j]) / (times[j+1] -
    times[j])). SciPy: ``Slerp(times, Rotation.from_quat(q))(t)``.
    
    Parameters
    ----------
    times : array_like, shape (k,)
        Key times, strictly increasing, k >= 2 (any time unit).
    q : array_like, shape (k, 4)
        Key rotations, unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within
        1e-6 of 1 (then normalised).
    t : float or array_like, shape (m,)
        Times within [times[0], times[-1]], in the unit of `times`.
    scalar_first : bool, default False
        Read and write quaternions scalar first, (w, x, y, z), as MuJoCo does.
    canonical : bool, default False
        Return the representative with w >= 0 (SciPy's ``as_quat(canonical=True)``: at w = 0 the first
        non-zero of x, y, z is positive).
    
    Returns
    -------
    ndarray, shape (4,) or (m, 4)
        The interpolated rotations, (x, y, z, w) or (w, x, y, z) if `scalar_first`.
    
    Raises
    ------
    ValueError
        `times` not strictly increasing, `q` not of shape (k, 4) or not unit quaternions, `t` outside
        the key times or non-finite (each message names the argument).
    TypeError
        `times` not a 1-d array.
    
    See Also
    --------
    slerp
    
    Examples
    --------
    Three keys about z; at t = 1.5 the turn is halfway from the second key to the third:
    
    >>> q = rd.rotvec_to_quat([[0.0, 0.0, 0.0], [0.0, 0.0, 0.5], [0.0, 0.0, 1.5]])
    >>> qt = rd.slerp_keys([0.0, 1.0, 2.0], q, [0.5, 1.5])
    >>> rd.quat_to_rotvec(qt).round(12)
    array([[0.  , 0.  , 0.25],
           [0.  , 0.  , 1.  ]])
    """
def solid_box(size: numpy.typing.ArrayLike, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid rectangular box.
    
    Edges (a, b, c) along x, y, z: I = m/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) about the centre.
    
    Parameters
    ----------
    size : array_like, shape (3,)
        Edge lengths (a, b, c) [m] along x, y, z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (edges along x, y, z).
    
    Raises
    ------
    ValueError
        A `size` entry not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    box_shell, thin_plate, solid_ellipsoid, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.solid_box([1.0, 2.0, 3.0], mass=12.0).inertia_com.diagonal()  # m/12 (b^2+c^2, ...)
    array([13., 10.,  5.])
    """
def solid_capsule(radius: float, length: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid capsule along z: a cylinder capped by two hemispheres.
    
    Cylinder of radius r and length h, total length h + 2r. With m_c = rho pi r^2 h and m_h = rho 2/3 pi r^3
    (each hemisphere): I_zz = m_c r^2/2 + 4/5 m_h r^2,
    I_xx = I_yy = m_c (h^2/12 + r^2/4) + 2 m_h (2/5 r^2 + h^2/4 + 3/8 h r). A given mass is split in the
    same proportions.
    
    Parameters
    ----------
    radius : float
        Radius r [m] of the cylinder and the caps, > 0.
    length : float
        Length h [m] of the cylinder along z, finite and >= 0.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (axis z).
    
    Raises
    ------
    ValueError
        `radius` not finite and > 0, or `length` not finite and >= 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_cylinder, solid_sphere, SpatialInertia.transformed
    
    Examples
    --------
    With a cylinder of length 0 it is a sphere:
    
    >>> rd.solid_capsule(1.0, 0.0, mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))
    True
    """
def solid_cone(radius: float, height: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid right circular cone, axis z.
    
    Apex at z = 3h/4 and base at z = -h/4 (centre of mass at the origin):
    I_zz = 3/10 m r^2, I_xx = I_yy = m (3/20 r^2 + 3/80 h^2).
    
    Parameters
    ----------
    radius : float
        Base radius r [m].
    height : float
        Height h [m] along z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (axis z, apex at z = 3h/4).
    
    Raises
    ------
    ValueError
        `radius` or `height` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_cylinder, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.solid_cone(1.0, 4.0, mass=10.0).inertia_com.diagonal().round(12)
    array([7.5, 7.5, 3. ])
    """
def solid_cylinder(radius: float, height: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid circular cylinder, axis z.
    
    I_zz = m r^2/2, I_xx = I_yy = m (3 r^2 + h^2)/12 about the centre.
    
    Parameters
    ----------
    radius : float
        Radius r [m].
    height : float
        Height h [m] along z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (axis z).
    
    Raises
    ------
    ValueError
        `radius` or `height` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    hollow_cylinder, thin_disk, thin_rod, solid_capsule, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.solid_cylinder(1.0, 2.0, mass=12.0).inertia_com.diagonal()  # m (3r^2+h^2)/12, m r^2/2
    array([7., 7., 6.])
    """
def solid_ellipsoid(semi_axes: numpy.typing.ArrayLike, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid ellipsoid.
    
    Semi-axes (a, b, c) along x, y, z: I = m/5 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) about the centre.
    
    Parameters
    ----------
    semi_axes : array_like, shape (3,)
        Semi-axes (a, b, c) [m] along x, y, z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (semi-axes along x, y, z).
    
    Raises
    ------
    ValueError
        A `semi_axes` entry not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_sphere, solid_box, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.solid_ellipsoid([1.0, 2.0, 3.0], mass=5.0).inertia_com.diagonal()
    array([13., 10.,  5.])
    >>> rd.solid_ellipsoid([1.0, 1.0, 1.0], mass=1.0).is_approx(rd.solid_sphere(1.0, mass=1.0))
    True
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
def solid_sphere(radius: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid sphere.
    
    I = 2/5 m r^2 1 about the centre.
    
    Parameters
    ----------
    radius : float
        Radius r [m].
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame.
    
    Raises
    ------
    ValueError
        `radius` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    hollow_sphere, spherical_shell, solid_ellipsoid, SpatialInertia.transformed
    
    Examples
    --------
    A solid sphere of 2 kg and radius 0.5 m has I = 2/5 m r^2 = 0.2 kg m^2 about every axis:
    
    >>> rd.solid_sphere(0.5, mass=2.0).inertia_com.diagonal()
    array([0.2, 0.2, 0.2])
    >>> f"{rd.solid_sphere(0.1, density=1000.0).mass:.6f}"  # 4/3 pi r^3 rho
    '4.188790'
    """
def solid_tetrahedron(vertices: numpy.typing.ArrayLike, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a solid tetrahedron given by its vertices.
    
    The centre of mass is the mean of the vertices; the inertia comes from the exact second moment
    integral x x^T dV = V/20 (sum v_i v_i^T + s s^T), s = sum v_i. Expressed in the frame of the vertices.
    
    Parameters
    ----------
    vertices : array_like, shape (4, 3)
        The four vertices [m], any order, in any frame A.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0: m = density * volume.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.
    
    Raises
    ------
    ValueError
        `vertices` not of shape (4, 3), not finite or of zero volume; not exactly one of `mass` and
        `density`, or that one not finite and > 0 (the message names the argument).
    
    See Also
    --------
    solid_mesh, from_point_masses
    
    Examples
    --------
    The corner tetrahedron has volume 1/6 m^3 and its centre of mass at (1/4, 1/4, 1/4):
    
    >>> tet = rd.solid_tetrahedron([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], density=6.0)
    >>> f"{tet.mass:.12f}", tet.com
    ('1.000000000000', array([0.25, 0.25, 0.25]))
    """
def spherical_shell(radius: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thin spherical surface.
    
    I = 2/3 m r^2 1 about the centre.
    
    Parameters
    ----------
    radius : float
        Radius r [m].
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Area density [kg/m^2], finite and > 0: m = density * area.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame.
    
    Raises
    ------
    ValueError
        `radius` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    hollow_sphere, solid_sphere, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.spherical_shell(1.0, mass=3.0).inertia_com.diagonal()  # 2/3 m r^2
    array([2., 2., 2.])
    """
def state_to_elements(r_W: numpy.typing.ArrayLike, v_W: numpy.typing.ArrayLike, mu: float) -> numpy.typing.NDArray[numpy.float64]:
    """
    Classical orbital elements of a position and velocity (Vallado's RV2COE).
    
    h = r x v, p = |h|^2/mu, the eccentricity vector e = (v x h)/mu - r/|r|, i from h, the ascending node
    n = z_W x h (Vallado, "Fundamentals of Astrodynamics and Applications", ch. 2, RV2COE; Curtis,
    "Orbital Mechanics for Engineering Students", algorithm 4.2). Angles are measured in the direction
    of motion. Where an angle is undefined it is 0 and the next carries it, so `elements_to_state` gives
    the state back:
    
    - equatorial (sin i < 1e-12, i = 0 or pi): raan = 0, argp = the longitude of periapsis (from x_W);
    - circular (e < 1e-12): argp = 0, nu = the argument of latitude u (from the ascending node);
    - both: raan = argp = 0, nu = the true longitude (from x_W).
    
    Below those tolerances (far above the ~1e-15 round-off of e and sin i from a state) the state given
    back moves by at most 2 e |r| or 2 sin(i) |r|. Semi-major axis: a = p/(1 - e^2).
    
    Parameters
    ----------
    r_W : array_like, shape (3,) or (n, 3)
        Position of the body relative to the central body's centre, in the inertial frame W [m].
    v_W : array_like, shape (3,) or (n, 3)
        Velocity of the body relative to the central body, in W [m/s]; not parallel to `r_W`.
    mu : float
        Gravitational parameter G M of the central body [m^3/s^2], > 0 (or a pint quantity).
    
    Returns
    -------
    ndarray, shape (6,) or (n, 6)
        (p, e, i, raan, argp, nu): p [m]; e; i in [0, pi]; raan, argp in [0, 2 pi); nu in [0, 2 pi) for
        e < 1, in (-pi, pi) for e >= 1 [rad].
    
    Raises
    ------
    ValueError
        `mu` not > 0, r = 0 (the message names `r_W`), or as below.
    ValueError
        A non-finite entry or a wrong shape (the message names `r_W` or `v_W` and, in a stack, the item),
        stacks of different lengths, or r x v = 0 (the message names `r_W, v_W`: a rectilinear orbit has no
        plane).
    
    See Also
    --------
    elements_to_state, mean_to_true_anomaly
    
    Examples
    --------
    Vallado's Example 2-5 (km, km/s; mu = 398600.4418 km^3/s^2): e = 0.832853, i = 87.870, raan = 227.898,
    argp = 53.385, nu = 92.335 deg:
    
    >>> el = rd.state_to_elements([6524.834, 6862.875, 6448.296], [4.901327, 5.533756, -1.976341], 398600.4418)
    >>> float(round(el[1], 6)), np.degrees(el[2:]).round(3)
    (0.832853, array([ 87.869, 227.898,  53.385,  92.335]))
    """
def step(model: Particle | PlanarBody | RigidBody | PivotedBody | PivotedPlanarBody | Gyrostat | Scene | CompiledScene, state: typing.Any, dt: float | _Quantity, method: _MethodName | None = None, loads: AppliedLoad | collections.abc.Sequence[AppliedLoad] | None = None, gravity: bool | numpy.typing.ArrayLike | None = None, t: float | _Quantity | None = None) -> typing.Any:
    """
    One step of `method` from `state` at time t to t + dt.
    
    The step `simulate` takes, for a loop written in Python. A step across a switch time of the loads (a t_start or
    t_end) is split there, as in simulate. Steps from the states they return, at the times t0 + i dt, give the records of
    ``simulate(model, state, dt, steps, t0=t0)`` bit for bit (by every method but 'exact', whose records are its closed
    form from the run's start).
    
    Parameters
    ----------
    model : Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat, Scene or CompiledScene
        What to step. A PivotedBody, PivotedPlanarBody or Gyrostat steps as its one-body scene, as in simulate.
    state : ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, ..., or list
        The state of `model`'s kind; for a Scene or CompiledScene, a list of the states of its bodies.
    dt : float or pint.Quantity
        Step [s], finite and > 0.
    method : str, optional
        A name of methods(); None (the default): 'rk4', or the method a CompiledScene was compiled for.
    loads : AppliedLoad or sequence of AppliedLoad, optional
        The applied loads (None: none), as simulate takes them.
    gravity : None, bool or array_like, shape (3,), default None
        Uniform gravity g_W [m/s^2] in W: None or False (none), True ((0, 0, -9.81)) or a vector; as simulate.
    t : float or pint.Quantity, optional
        The time of `state` [s]. Needed when a load acts on a time window (finite t_start or t_end).
    
    Returns
    -------
    state or (state, float)
        t None: the new state, of the type of `state` (a list of new states for a scene). t given: (new state,
        t + dt), e.g. ``state, t = step(body, state, dt, loads=loads, t=t)`` in a loop.
    
    Raises
    ------
    ValueError
        A bad argument, named; t None while a load acts on a time window (the step then depends on the time); a
        scene with a MassFlow (a state does not carry the mass: use simulate).
    TypeError
        model not one of the kinds listed, or state not of its kind (the message names it).
    
    Warns
    -----
    RuntimeWarning
        The new state is not finite, as simulate warns.
    
    See Also
    --------
    simulate, methods
    
    Examples
    --------
    Ten steps of 0.1 s at 1 rad/s about z turn a body 1 rad (rk4):
    
    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> state, t = rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), 0.0
    >>> for _ in range(10):
    ...     state, t = rd.step(body, state, 0.1, t=t)
    >>> print(f"{t:.12f}", rd.quat_to_rotvec(state.q_WB).round(6))
    1.000000000000 [0. 0. 1.]
    
    One step of a falling particle (rk4 is exact on it):
    
    >>> rd.step(rd.Particle(1.0), rd.ParticleState(), 0.5, gravity=True).v_W.round(12)
    array([ 0.   ,  0.   , -4.905])
    """
def symmetry_planes(masses: numpy.typing.ArrayLike, positions: numpy.typing.ArrayLike, tolerance: float = 1e-09) -> list:
    """
    Planes of symmetry of point masses (Craig, "Plane of Symmetry").
    
    A plane qualifies when its reflection maps every point onto a point of equal mass, within
    tolerance * L [m] (L the largest distance from the centre of mass to a point) and tolerance * mass.
    Candidates: the principal axes, and when principal moments coincide, normals built from the points;
    for such degenerate bodies (cube, regular tetrahedron) the planes found among them, not a proof of
    none else.
    
    Parameters
    ----------
    masses : array_like, shape (n,)
        Masses [kg], > 0.
    positions : array_like, shape (n, 3)
        Positions [m], in any frame A.
    tolerance : float, default 1e-9
        Relative tolerance, >= 0.
    
    Returns
    -------
    list of tuple (ndarray, ndarray)
        One (normal, point) per plane, in A: normal, shape (3,), unit, its largest-magnitude component
        positive; point, shape (3,) [m], the centre of mass.
    
    Raises
    ------
    ValueError
        Shapes that do not match, bad masses or a negative tolerance (the message names it).
    
    See Also
    --------
    mesh_symmetry_planes, SpatialInertia.admits_symmetry_plane
    
    Examples
    --------
    A dumbbell along x is symmetric in the three coordinate planes through its centre:
    
    >>> planes = rd.symmetry_planes([1.0, 1.0], [[-1.0, 0, 0], [1.0, 0, 0]])
    >>> [normal for normal, point in planes]
    [array([1., 0., 0.]), array([0., 1., 0.]), array([0., 0., 1.])]
    """
def thin_disk(radius: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thin circular disk in the xy plane.
    
    I_xx = I_yy = m r^2/4, I_zz = m r^2/2 about the centre.
    
    Parameters
    ----------
    radius : float
        Radius r [m].
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Area density [kg/m^2], finite and > 0: m = density * area.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (disk in the xy plane).
    
    Raises
    ------
    ValueError
        `radius` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_cylinder, thin_plate, SpatialInertia.transformed
    
    Examples
    --------
    Perpendicular-axis theorem, I_zz = I_xx + I_yy:
    
    >>> rd.thin_disk(2.0, mass=1.0).inertia_com.diagonal()
    array([1., 1., 2.])
    """
def thin_plate(size_x: float, size_y: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thin rectangular plate in the xy plane.
    
    Edges (a, b) along x, y: I = m/12 diag(b^2, a^2, a^2 + b^2) about the centre.
    
    Parameters
    ----------
    size_x : float
        Edge a [m] along x.
    size_y : float
        Edge b [m] along y.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Area density [kg/m^2], finite and > 0: m = density * area.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (plate in the xy plane).
    
    Raises
    ------
    ValueError
        `size_x` or `size_y` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_box, thin_disk, SpatialInertia.transformed
    
    Examples
    --------
    Perpendicular-axis theorem, I_zz = I_xx + I_yy:
    
    >>> rd.thin_plate(1.0, 2.0, mass=12.0).inertia_com.diagonal()
    array([4., 1., 5.])
    """
def thin_rod(length: float, *, mass: float | None = None, density: float | None = None) -> SpatialInertia:
    """
    Mass properties of a thin rod along z.
    
    I_xx = I_yy = m L^2/12, I_zz = 0 about the centre.
    
    Parameters
    ----------
    length : float
        Length L [m] along z.
    mass : float, optional
        Total mass m [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Length density [kg/m], finite and > 0: m = density * length.
    
    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass at the origin [m] and inertia_com [kg m^2] about it, expressed in the
        shape's frame (rod along z).
    
    Raises
    ------
    ValueError
        `length` not finite and > 0;
        not exactly one of `mass` and `density`, or that one not finite and > 0 (the message names
        the argument).
    TypeError
        An argument that is not a real number.
    
    See Also
    --------
    solid_cylinder, SpatialInertia.transformed
    
    Examples
    --------
    >>> rd.thin_rod(2.0, mass=3.0).inertia_com.diagonal()  # m L^2/12
    array([1., 1., 0.])
    """
def transform_compose(R_AB: numpy.typing.ArrayLike, p_AB: numpy.typing.ArrayLike, R_BC: numpy.typing.ArrayLike, p_BC: numpy.typing.ArrayLike) -> tuple:
    """
    Compose rigid transforms item by item, X_AC = X_AB * X_BC, on arrays.
    
    R_AC = R_AB R_BC, p_AC = R_AB p_BC + p_AB, as Transform.__mul__, for stacks of n transforms; a single
    item broadcasts against the stacked ones.
    
    Parameters
    ----------
    R_AB : array_like, shape (3, 3) or (n, 3, 3)
        Rotations B -> A (orthonormal, det +1).
    p_AB : array_like, shape (3,) or (n, 3)
        B's origin in A [m].
    R_BC : array_like, shape (3, 3) or (n, 3, 3)
        Rotations C -> B.
    p_BC : array_like, shape (3,) or (n, 3)
        C's origin in B [m].
    
    Returns
    -------
    R_AC : ndarray, shape (3, 3) or (n, 3, 3)
        Rotations C -> A.
    p_AC : ndarray, shape (3,) or (n, 3)
        C's origin in A [m] (stacked if any input is).
    
    Raises
    ------
    ValueError
        A non-rotation (naming it and the item, e.g. R_AB[2]), a non-finite value, a bad shape, or
        stacks of different lengths (naming the argument).
    
    See Also
    --------
    Transform, transform_points
    
    Examples
    --------
    Two quarter turns about z, each with a step of 1 m along its frame's x:
    
    >>> R, p = rd.transform_compose(rd.rot_z(np.pi / 2), [1.0, 0, 0], rd.rot_z(np.pi / 2), [1.0, 0, 0])
    >>> bool(np.allclose(R, rd.rot_z(np.pi))), p.round(12)
    (True, array([1., 1., 0.]))
    """
def transform_points(R_AB: numpy.typing.ArrayLike, p_AB: numpy.typing.ArrayLike, p_B: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Map points from frame B to frame A item by item: p_A = R_AB p_B + p_AB, on arrays.
    
    As Transform.act_point for stacks of n transforms or points; a single item broadcasts against the
    stacked ones.
    
    Parameters
    ----------
    R_AB : array_like, shape (3, 3) or (n, 3, 3)
        Rotations B -> A (orthonormal, det +1).
    p_AB : array_like, shape (3,) or (n, 3)
        B's origin in A [m].
    p_B : array_like, shape (3,) or (n, 3)
        Points in B [m].
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        p_A, the points in A [m] (stacked if any input is).
    
    Raises
    ------
    ValueError
        A non-rotation, a non-finite value, a bad shape, or stacks of different lengths (naming the
        argument).
    
    See Also
    --------
    Transform.act_point, transform_compose
    
    Examples
    --------
    >>> rd.transform_points(rd.rot_z(np.pi / 2), [1.0, 0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).round(12)
    array([[1., 1., 0.],
           [0., 0., 0.]])
    """
def transport_derivative(w_AB: numpy.typing.ArrayLike, u: numpy.typing.ArrayLike, du_dt_in_B: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Transport theorem: the derivative of a vector seen from A, from its derivative seen from B.
    
    d^A u/dt = d^B u/dt + w_AB x u (Craig's "Rigid Body Dynamics" slides).
    
    Parameters
    ----------
    w_AB : array_like, shape (3,)
        Angular velocity of B relative to A [rad/s].
    u : array_like, shape (3,)
        The vector (any unit).
    du_dt_in_B : array_like, shape (3,)
        Its time derivative seen from B [unit of u / s].
    
    Returns
    -------
    ndarray, shape (3,)
        d^A u/dt [unit of u / s]. All vectors are expressed in one (any) frame.
    
    Raises
    ------
    ValueError
        A vector of another shape or non-finite (naming it).
    
    See Also
    --------
    FrameTree.transport_derivative, point_velocity
    
    Examples
    --------
    A vector fixed in B (d^B u/dt = 0) turns with B:
    
    >>> rd.transport_derivative([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    array([0., 1., 0.])
    """
def true_to_eccentric_anomaly(nu: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    Eccentric anomaly E (ellipse) or hyperbolic anomaly H (hyperbola) of the true anomaly.
    
    tan(E/2) = sqrt((1 - e)/(1 + e)) tan(nu/2) for 0 <= e < 1, keeping nu's revolutions (E and nu differ
    by less than pi); tanh(H/2) = sqrt((e - 1)/(e + 1)) tan(nu/2) for e > 1 (Curtis, "Orbital Mechanics
    for Engineering Students", ch. 3).
    
    Parameters
    ----------
    nu : float or array_like, shape (n,)
        True anomaly [rad], the angle from periapsis to the body in the direction of motion; for a
        hyperbola within the asymptotes, 1 + e cos(nu) > 0.
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0: 0 <= e < 1 an ellipse, e > 1 a hyperbola.
    
    Returns
    -------
    float or ndarray, shape (n,)
        E or H [rad] (an array when either argument is one).
    
    Raises
    ------
    ValueError
        A non-finite value, e < 0, e = 1 (a parabola has no eccentric anomaly) or a hyperbola's `nu`
        beyond its asymptotes (the message names the argument and, in a stack, the item).
    
    See Also
    --------
    eccentric_to_true_anomaly, eccentric_to_mean_anomaly, true_to_mean_anomaly
    
    Examples
    --------
    At periapsis and apoapsis the anomalies agree; a circle has E = nu:
    
    >>> rd.true_to_eccentric_anomaly([0.0, np.pi], 0.5).round(12)
    array([0.        , 3.14159265])
    >>> rd.true_to_eccentric_anomaly(1.0, 0.0)
    1.0
    """
def true_to_mean_anomaly(nu: float | numpy.typing.ArrayLike, e: float | numpy.typing.ArrayLike) -> typing.Any:
    """
    Mean anomaly of the true anomaly, for every conic.
    
    Through the eccentric or hyperbolic anomaly for e != 1 (`true_to_eccentric_anomaly`,
    `eccentric_to_mean_anomaly`); Barker's equation M = D/2 + D^3/6, D = tan(nu/2), for the parabola
    e = 1 (Curtis, "Orbital Mechanics for Engineering Students", sec. 3.5), where M = sqrt(mu/p^3) t.
    
    Parameters
    ----------
    nu : float or array_like, shape (n,)
        True anomaly [rad]; for e >= 1 within the asymptotes, 1 + e cos(nu) > 0.
    e : float or array_like, shape (n,)
        Eccentricity, finite and >= 0 (1 included).
    
    Returns
    -------
    float or ndarray, shape (n,)
        M [rad].
    
    Raises
    ------
    ValueError
        A non-finite value, e < 0 or `nu` beyond the asymptotes (the message names the argument).
    
    Warns
    -----
    RuntimeWarning
        M overflows (nu within about 1e-100 rad of a hyperbola's asymptote).
    
    See Also
    --------
    mean_to_true_anomaly
    
    Examples
    --------
    A parabola at nu = 90 deg: D = 1, M = 1/2 + 1/6:
    
    >>> round(rd.true_to_mean_anomaly(np.pi / 2, 1.0), 15)
    0.666666666666667
    """
def twist_to_screw(twist: Motion) -> Screw:
    """
    The screw (instantaneous screw axis) of a twist.
    
    For V = [w; v] (angular first): direction w/|w|, point (w x v)/|w|^2, pitch (w . v)/|w|^2, magnitude
    |w|; for w = 0: pitch inf, direction v/|v|, point 0, magnitude |v|. Chasles' theorem: every rigid
    motion is a rotation about the axis with a slide along it.
    
    Parameters
    ----------
    twist : Motion
        [w; v] ([rad/s], [m/s]) in any frame.
    
    Returns
    -------
    Screw
        Its axis, pitch [m/rad] and magnitude, in the twist's frame.
    
    Raises
    ------
    ValueError
        The zero twist (no axis), or a non-finite one.
    TypeError
        twist not a Motion.
    
    See Also
    --------
    screw_to_twist, Screw
    
    Examples
    --------
    >>> s = rd.twist_to_screw(rd.Motion([0.0, 0.0, 2.0], [0.0, 2.0, 0.5]))
    >>> s.direction, s.point, s.pitch, s.magnitude
    (array([0., 0., 1.]), array([-1.,  0.,  0.]), 0.25, 2.0)
    >>> rd.twist_to_screw(rd.Motion(linear=[0.0, 0.0, 3.0])).pitch
    inf
    """
def vector_instructions() -> str:
    """
    The vector instructions this process's hot kernels run on: 'avx512', 'avx2_fma' or 'portable'.
    
    The N-body pair sum of MutualGravity runs eight pairs per instruction where the CPU and the operating system have
    AVX-512F ('avx512'), four with AVX2 and fused multiply-adds where the CPU has those ('avx2_fma'), and two per
    instruction otherwise ('portable', the x86-64 baseline the library is built for); the rotation array functions run
    their AVX2 blocks on 'avx512' and 'avx2_fma', with the same bits as 'portable'. The paths agree to round-off (the
    pair sum per body and component within (n + 24) 2**-53 times the sum of the pair forces' magnitudes of the exact
    sum, n the body count); only 'portable' gives the same bits on every machine. The choice is made once per process:
    set the environment variable RIGIDDYN_PORTABLE=1 before the first run to force 'portable'. The SIMD batch lanes
    (simulate_batch(..., simd=True)) choose their own instructions when the library is loaded.
    
    Parameters
    ----------
    None
    
    Returns
    -------
    str
        'avx512', 'avx2_fma' or 'portable'.
    
    See Also
    --------
    MutualGravity, simulate_batch
    
    Examples
    --------
    >>> rd.vector_instructions() in ("avx512", "avx2_fma", "portable")
    True
    """
def vee(S: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
    """
    Vectors of skew-symmetric matrices, the inverse of `hat`.
    
    v with hat(v) = (S - S^T)/2: a symmetric part of S is ignored. SciPy has no equivalent.
    
    Parameters
    ----------
    S : array_like, shape (3, 3) or (n, 3, 3)
        Matrices, finite.
    
    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        v, in the unit of S.
    
    Raises
    ------
    ValueError
        A non-finite entry or a wrong shape (the message names `S`).
    
    See Also
    --------
    hat
    
    Examples
    --------
    >>> rd.vee(rd.hat([1.0, 2.0, 3.0]))
    array([1., 2., 3.])
    >>> rd.vee(rd.hat([1.0, 2.0, 3.0]) + np.ones((3, 3)))
    array([1., 2., 3.])
    """
def weld_vertices(vertices: numpy.typing.ArrayLike, faces: numpy.typing.ArrayLike, tolerance: float | None = None) -> WeldedMesh:
    """
    Merge vertices closer than a tolerance, as solid_mesh does before integrating.
    
    Clusters of vertices within `tolerance` of one another (grid hashing, O(n log n)) keep their
    lowest-indexed vertex; faces repeating a vertex afterwards are dropped. Warns nothing.
    
    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Vertex positions [m], finite.
    faces : array_like of int, shape (f, 3)
        Vertex indices of each triangle, three distinct ones per face.
    tolerance : float or None, default None
        Weld distance [m], finite and >= 0 (None: 1e-8 x the bounding-box diagonal).
    
    Returns
    -------
    WeldedMesh
        The kept vertices and faces, their input indices and what the weld changed.
    
    Raises
    ------
    ValueError
        Vertices not finite, a negative tolerance, an index outside [0, n) or a face repeating an index
        (the message names it).
    
    See Also
    --------
    solid_mesh, mesh_shell, WeldedMesh
    
    Examples
    --------
    Two triangles of a square saved as in an STL file, each with its own copy of the shared vertices:
    
    >>> w = rd.weld_vertices([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
    ...                      [[0, 1, 2], [3, 4, 5]])
    >>> w.welded_vertices, w.faces
    (2, array([[0, 1, 2],
           [1, 3, 2]]))
    """
FORCE_ELEMENTS: tuple = (UniformGravity, PointMassGravity, MutualGravity, GravityGradient, SpringDamper, Drag, ScheduledLoads, PythonForce, Thrust, MagneticDipole, ReactionWheel, ZonalGravity, AtmosphericDrag, SolarRadiationPressure, RevoluteSpringDamper, PrismaticSpringDamper, RevoluteMotor, PrismaticMotor, SphericalSpringDamper)
__version__: str = '0.1.0'
_accuracy_rule: tuple = (0.001, 10.0, 0.1)
inertia_relative_tolerance: float = 1e-10
