"""The numpy reference's scenes (rigiddyn_ref.scene) declared in rigiddyn, and rigiddyn's scene results read
back in the reference's state layout, for the scene tests (imported as `from _scene_core import ...`)."""

import numpy as np

import rigiddyn as rd
from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

EPS = np.finfo(float).eps


def core_body(body: ref.Body):
    """rigiddyn's body of a reference Body (a diagonal inertia as principal moments, else the full matrix)."""
    if body.kind == "particle":
        return rd.Particle(body.mass)
    if body.kind == "planar":
        return rd.PlanarBody(body.mass, body.inertia[2, 2])
    inertia = body.inertia
    if np.count_nonzero(inertia - np.diag(np.diag(inertia))) == 0:
        return rd.RigidBody(body.mass, list(np.diag(inertia)))
    return rd.RigidBody(body.mass, inertia)


def core_element(element: ref.Element):
    """rigiddyn's element of a reference Element: same class name and keywords (a schedule's loads as
    AppliedLoad, a world anchor's body_b as None)."""
    params = dict(element.params)
    if element.kind == "ScheduledLoads":
        params["loads"] = [rd.AppliedLoad(force=load.force, torque=load.torque, frame=load.frame,
                                          t_start=load.t_start, t_end=load.t_end) for load in params["loads"]]
    if element.kind == "SpringDamper" and params.get("body_b", None) is not None and params["body_b"] < 0:
        params["body_b"] = None
    return getattr(rd, element.kind)(**params)


def core_scene(scene: ref.Scene):
    """A rigiddyn.Scene with the reference scene's bodies (named body<i>) and elements, in order."""
    out = rd.Scene()
    for i, body in enumerate(scene.bodies):
        assert out.add_body(core_body(body), name=f"body{i}") == i
    for element in scene.elements:
        out.add(core_element(element))
    return out


def core_states(scene: ref.Scene, y):
    """rigiddyn's initial states (one per body) of the reference state y."""
    states = []
    for body, k in zip(scene.bodies, ref.kinematics(scene.bodies, y)):
        if body.kind == "particle":
            states.append(rd.ParticleState(p_W=k.p_W, v_W=k.v_W))
        elif body.kind == "planar":
            theta = 2.0 * np.arctan2(k.q_WB[2], k.q_WB[3])
            states.append(rd.PlanarBodyState(p_W=k.p_W[:2], theta=theta, v_W=k.v_W[:2], omega=k.w_B[2]))
        else:
            states.append(rd.RigidBodyState(p_W=k.p_W, q_WB=k.q_WB, v_W=k.v_W, w_B=k.w_B))
    return states


def record_state(scene: ref.Scene, result, i, like=None):
    """The reference state y of record i of a SceneResult (t and each element's work included). The
    quaternion's sign and a planar angle's turn are taken closest to `like` (a reference y), so that two
    states of one attitude compare equal."""
    kin = [ref.Kinematics(np.asarray(result.p_W[i, b]), np.asarray(result.q_WB[i, b]), np.asarray(result.v_W[i, b]),
                          np.asarray(result.w_B[i, b])) for b in range(len(scene.bodies))]
    y = ref.state_of(scene.bodies, kin, float(result.t[i]), len(scene.elements))
    y[len(y) - len(scene.elements):] = np.asarray(result.work[i])
    return y if like is None else _closest_attitudes(scene, y, like)


def state_vector(scene: ref.Scene, states, t, like):
    """The reference state y (work zero) of rigiddyn's body states at time t, the attitudes taken closest to
    `like` as in record_state."""
    kin = []
    for body, s in zip(scene.bodies, states):
        if body.kind == "particle":
            kin.append(ref.Kinematics(np.asarray(s.p_W), ref.IDENTITY, np.asarray(s.v_W), np.zeros(3)))
        elif body.kind == "planar":
            kin.append(ref.Kinematics(np.append(s.p_W, 0.0), ref.rz_quat(s.theta), np.append(s.v_W, 0.0),
                                      np.array([0.0, 0.0, s.omega])))
        else:
            kin.append(ref.Kinematics(np.asarray(s.p_W), np.asarray(s.q_WB), np.asarray(s.v_W), np.asarray(s.w_B)))
    return _closest_attitudes(scene, ref.state_of(scene.bodies, kin, t, len(scene.elements)), like)


def _closest_attitudes(scene: ref.Scene, y, like):
    """y with each quaternion's sign and each planar angle's turn taken closest to `like`."""
    for body, o in zip(scene.bodies, ref.body_offsets(scene.bodies)):
        if body.kind == "rigid" and y[o + 3:o + 7] @ like[o + 3:o + 7] < 0:
            y[o + 3:o + 7] *= -1.0
        if body.kind == "planar":
            y[o + 2] += 2.0 * np.pi * np.round((like[o + 2] - y[o + 2]) / (2.0 * np.pi))
    return y


def run(scene: ref.Scene, y0, dt, steps, method="rk4", record_every=1):
    """rigiddyn.simulate of the reference scene from y0 (its t is the start time t0, passed only when
    non-zero)."""
    t0 = ref.time_of(scene, y0)
    start = {"t0": t0} if t0 != 0.0 else {}
    return rd.simulate(core_scene(scene), core_states(scene, y0), dt=dt, steps=steps, method=method,
                       record_every=record_every, **start)


def inertia_condition(scene: ref.Scene) -> float:
    """max κ = I_max/I_min over the rigid bodies (1 without one): the round-off gain of solving I ω̇ = n."""
    kappas = [np.linalg.cond(b.inertia) for b in scene.bodies if b.kind == "rigid"]
    return max(kappas, default=1.0)


def every_model_scene():
    """Two rigid bodies, a particle and a planar body under every force model: uniform gravity, a point-mass
    attractor, mutual gravity, the gravity gradient, three spring–dampers (body–body with rest length,
    body–anchor with rest length 0, particle–planar), drag (all four coefficients) and schedules at a point
    with a switch at t = 0.55 s (inside a step of the 0.02 s run: the core splits the step there; at the end of a
    step of the 0.01 s run)."""
    turn = so3.rotvec_to_matrix([0.3, -0.2, 0.5])
    bodies = [ref.rigid(2.0, [0.4, 0.5, 0.7]), ref.rigid(1.5, turn @ np.diag([0.3, 0.45, 0.6]) @ turn.T),
              ref.particle(0.8), ref.planar(1.2, 0.3)]
    E = ref.Element
    elements = [
        E("UniformGravity", dict(g_W=[0.0, -1.0, -9.81], bodies=None)),
        E("PointMassGravity", dict(gm=30.0, p_W=[0.0, 0.0, -5.0], softening=0.1, bodies=None)),
        E("MutualGravity", dict(G=0.5, softening=0.5, bodies=None)),
        E("GravityGradient", dict(gm=30.0, p_W=[0.0, 0.0, -5.0], bodies=[0, 1, 2])),
        E("SpringDamper", dict(body_a=0, point_a_B=[0.2, 0.1, -0.1], body_b=1, point_b=[-0.1, 0.2, 0.1],
                               stiffness=8.0, rest_length=1.2, damping=0.4)),
        E("SpringDamper", dict(body_a=1, point_a_B=[0.0, 0.3, 0.0], body_b=-1, point_b=[1.0, 1.0, 1.0],
                               stiffness=3.0, rest_length=0.0, damping=0.2)),
        E("SpringDamper", dict(body_a=2, point_a_B=[0.0, 0.0, 0.0], body_b=3, point_b=[0.2, 0.0, 0.0],
                               stiffness=5.0, rest_length=0.8, damping=0.3)),
        E("Drag", dict(linear=0.1, quadratic=0.05, angular_linear=0.02, angular_quadratic=0.01, bodies=None)),
        E("ScheduledLoads", dict(body=0, point_B=[0.1, -0.2, 0.3],
                                 loads=[dyn.Load([1.0, 0.0, 2.0], [0.0, 0.1, 0.0], "body", -np.inf, 0.55),
                                        dyn.Load([0.0, -1.0, 0.5], [0.2, 0.0, 0.0], "world", 0.55, np.inf)])),
        E("ScheduledLoads", dict(body=3, loads=[dyn.Load([0.5, 0.5, 0.0], [0.0, 0.0, 0.2], "world", 0.0, 0.55)])),
    ]
    kin = [ref.Kinematics(np.array([0.0, 0.0, 1.0]), so3.rotvec_to_quat([0.1, 0.2, 0.3]), np.array([0.5, 0.0, 0.2]),
                          np.array([1.0, -0.5, 2.0])),
           ref.Kinematics(np.array([1.2, 0.3, 1.1]), so3.rotvec_to_quat([-0.4, 0.1, 0.0]), np.array([0.0, 0.3, -0.2]),
                          np.array([-0.3, 1.5, 0.4])),
           ref.Kinematics(np.array([-1.0, 0.5, 0.0]), ref.IDENTITY, np.array([0.2, 0.1, 0.0]), np.zeros(3)),
           ref.Kinematics(np.array([-1.5, -0.5, 0.0]), ref.rz_quat(0.4), np.array([0.0, -0.3, 0.0]),
                          np.array([0.0, 0.0, 0.8]))]
    scene = ref.Scene(bodies, elements)
    return scene, ref.initial_state(scene, kin)
