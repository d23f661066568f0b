"""A kinematic tree as bodies of a scene (Scene.add_tree): each link a body the force elements act on, the joints
coupling them, the tree's q and v integrated by the articulated-body algorithm.

Checked against the numpy reference: one RK4 step of random trees (revolute, prismatic, spherical, fixed joints,
with and without a free base) under UniformGravity, a SpringDamper from a link point to a world anchor, Drag on
every link, a spring, a damper and a motor in every revolute and prismatic joint and a torsion spring and damper in
every spherical joint equals an RK4 step written from rigiddyn_ref.tree (forward dynamics from the definitions, the
links' wrenches as external forces, the joint springs as joint forces) and rigiddyn_ref.scene (the elements'
forces); one implicit midpoint step equals the variational midpoint step of rigiddyn_ref.tree (on (q, p) for
revolute, prismatic and fixed joints under every force; from the discrete Lagrangian by differences with ball and
free joints); the variational midpoint keeps a symmetry's momentum and a floating tree's momenta to round-off and
bounds the energy error of a chaotic run, and its iterates reach their tolerance at long steps; the work-energy
balance closes on every run; a gravity on all the links (which the tree applies as its base's acceleration) moves
them as the same gravity split across two elements; the double pendulum's small oscillations are its normal modes,
its energy error when chaotic falls at each method's order, a ball-jointed top is the Lagrange top, and a gimballed
gyroscope precesses steadily at m g d / (I₃ ψ̇), each against its closed form; a joint spring's damped oscillation
and a ball joint's twist against their closed forms; a motor's window on a floating tree keeps its momenta; the
links' records and describe(); bad input refused naming the value.

Error bound of the step comparison: both sides evaluate the same four derivatives, each to ~10 n² eps of its scale
(test_tree_vs_reference's bound for forward dynamics, n <= 8 links; the element forces add a few eps), and the step
combines them with weights of order h, so the states agree to ~1e-12 of their scale; asserted at 1e-11.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn_ref import scene as sref
from rigiddyn_ref import so3 as so3_ref
from rigiddyn_ref import tree as ref
from test_tree_vs_reference import VECTOR_JOINT_ODDS, build, random_links, random_state

RTOL = 1e-11  # module docstring
G_W = np.array([0.3, -0.2, -9.81])
ANCHOR = np.array([0.5, -0.3, 2.0])
POINT_B = np.array([0.1, 0.2, -0.1])
SPRING = {"stiffness": 40.0, "rest_length": 0.5, "damping": 1.5}
DRAG = {"linear": 0.3, "quadratic": 0.1, "angular_linear": 0.2, "angular_quadratic": 0.05}
JOINT_SPRING = {"stiffness": 5.0, "rest": 0.2, "damping": 0.3}  # in every revolute and prismatic joint
JOINT_ELEMENTS = {"revolute": (rd.RevoluteSpringDamper, "rest_angle", rd.RevoluteMotor, "torque"),
                  "prismatic": (rd.PrismaticSpringDamper, "rest_position", rd.PrismaticMotor, "force")}
MOTOR = 0.7  # the constant force of a motor in every revolute and prismatic joint [N m or N]
BALL_SPRING = {"stiffness": 3.0, "rest_rotation": np.array([0.4, -0.3, 0.2]), "damping": 0.25}  # in every ball joint


def tree_scene(links, drag=DRAG):
    """The tree of `links` (no gravity of its own) in a scene with gravity, a spring from its last link's point
    POINT_B to ANCHOR, `drag` on every link, JOINT_SPRING and a motor of MOTOR in every revolute and prismatic joint."""
    tree = build(links, np.zeros(3))
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=G_W), rd.Drag(**drag)])
    scene.add_tree(tree, "arm")
    scene.add(rd.SpringDamper(body_a=len(links) - 1, point_a_B=POINT_B, point_b=ANCHOR, **SPRING))
    for i, l in enumerate(links):
        if l["kind"] in JOINT_ELEMENTS:
            spring, rest, motor, value = JOINT_ELEMENTS[l["kind"]]
            scene.add(spring(body=i, stiffness=JOINT_SPRING["stiffness"], damping=JOINT_SPRING["damping"],
                             **{rest: JOINT_SPRING["rest"]}))
            scene.add(motor(body=i, **{value: MOTOR}))
        if l["kind"] == "spherical":
            scene.add(rd.SphericalSpringDamper(body=i, **BALL_SPRING))
    return tree, scene


def joint_forces(links, q, v):
    """τ of the joint springs, dampers and motors: MOTOR − k (q_i − q0) − c v_i in each revolute and prismatic joint,
    −k log(q0⁻¹ q_i) − c w_i (3,) in each spherical one (q0 = exp(rest_rotation)), 0 elsewhere."""
    idx, _, nv = ref.sizes(links)
    tau = np.zeros(nv)
    for l, (iq, iv) in zip(links, idx):
        if l["kind"] in JOINT_ELEMENTS:
            tau[iv] = MOTOR - JOINT_SPRING["stiffness"] * (q[iq] - JOINT_SPRING["rest"]) - JOINT_SPRING["damping"] * v[iv]
        elif l["kind"] == "spherical":
            q0 = so3_ref.rotvec_to_quat(BALL_SPRING["rest_rotation"])
            q_JL = so3_ref.quat_normalize(q[iq:iq + 4])
            phi = so3_ref.quat_to_rotvec(so3_ref.quat_multiply(so3_ref.quat_inverse(q0), q_JL))
            tau[iv:iv + 3] = -BALL_SPRING["stiffness"] * phi - BALL_SPRING["damping"] * v[iv:iv + 3]
    return tau


def link_kinematics(links, q, v):
    """Each link's kinematics as the elements see it (rigiddyn_ref.scene.Kinematics at its centre of mass, B
    parallel to L) and R_WL."""
    T_W, _ = ref.poses(links, q)
    twists = ref.link_twists(links, q, v)  # [w_L; v_L] at L's origin, in L
    out = []
    for l, T, V in zip(links, T_W, twists):
        R = T[:3, :3]
        q_WL = rd.matrix_to_quat(R)
        out.append(sref.Kinematics(T[:3, 3] + R @ l["com"], q_WL, R @ (V[3:] + np.cross(V[:3], l["com"])), V[:3]))
    return out, [T[:3, :3] for T in T_W]


def link_forces(links, q, v):
    """The elements' wrenches on each link (reference force models) as its external force [n; f] at L's origin in
    L, (n, 6)."""
    kin, R_WL = link_kinematics(links, q, v)
    bodies = [sref.rigid(l["mass"], l["inertia_com"]) for l in links]
    effects = [sref.uniform_gravity(bodies, kin, 0.0, G_W), sref.drag(bodies, kin, 0.0, **DRAG),
               sref.spring_damper(bodies, kin, 0.0, len(links) - 1, POINT_B, point_b=ANCHOR, **SPRING)]
    f_ext = np.zeros((len(links), 6))
    for i, l in enumerate(links):
        f_L = R_WL[i].T @ sum(e.f_W[i] for e in effects)
        f_ext[i] = np.concatenate([sum(e.tau_B[i] for e in effects) + np.cross(l["com"], f_L), f_L])
    return f_ext


def reference_rate(links, x):
    """(q̇, v̇) of the tree in the scene, from the definitions: the links' external forces (link_forces), the joint
    springs' forces as joint forces τ (where rigiddyn applies them as wrench pairs on the links), then forward
    dynamics."""
    _, nq, _ = ref.sizes(links)
    q, v = x[:nq], x[nq:]
    a = ref.forward_dynamics(links, q, v, joint_forces(links, q, v), np.zeros(3), link_forces(links, q, v))
    return np.concatenate([ref.configuration_rate(links, q, v), a])


def generalized_force(links, q, v):
    """Q (nv,) of every force in the scene: the joint forces and the links' external forces carried to the joints
    (−rnea at rest without gravity: the principle of virtual power)."""
    zero = np.zeros_like(v)
    return joint_forces(links, q, v) - ref.inverse_dynamics(links, q, zero, zero, np.zeros(3), link_forces(links, q, v))


def normalised(links, x):
    """x with each joint quaternion normalised (rigiddyn projects them after each RK4 step)."""
    idx, _, _ = ref.sizes(links)
    x = x.copy()
    for l, (iq, _) in zip(links, idx):
        at = {"spherical": iq, "free": iq + 3}.get(l["kind"])
        if at is not None:
            x[at:at + 4] /= np.linalg.norm(x[at:at + 4])
    return x


CASES = [(seed, n, free_base) for seed in range(4) for n, free_base in [(1, False), (3, False), (6, False), (4, True)]]


@pytest.mark.parametrize("seed,n,free_base", CASES)
def test_one_rk4_step_is_the_reference(seed, n, free_base):
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, free_base)
    q, v, _ = random_state(rng, links)
    tree, scene = tree_scene(links)
    h = 1e-3
    states = rd.step(scene, tree.joint_states(q, v), dt=h, method="rk4")
    x = np.concatenate([q, v])
    k1 = reference_rate(links, x)
    k2 = reference_rate(links, x + 0.5 * h * k1)
    k3 = reference_rate(links, x + 0.5 * h * k2)
    k4 = reference_rate(links, x + h * k3)
    expected = normalised(links, x + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4))
    actual = np.concatenate(tree.coordinates_of(states))
    assert np.max(np.abs(actual - expected)) <= RTOL * max(1.0, np.max(np.abs(expected)))


MIDPOINT_CASES = [(seed, n) for seed in range(3) for n in (1, 3, 6)]


@pytest.mark.parametrize("seed,n", MIDPOINT_CASES)
def test_one_implicit_midpoint_step_is_the_reference(seed, n):
    """A tree of revolute, prismatic and fixed joints takes the variational midpoint step of rigiddyn_ref.tree's
    variational_midpoint_step (the midpoint rule on (q, p), ∂T/∂q from the definitions) under every force of the
    scene. Both solves stop at round-off (the core's at a change of 1e-14 of the state), so the states agree to the
    module's bound."""
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, False, VECTOR_JOINT_ODDS)
    q, v, _ = random_state(rng, links)
    tree, scene = tree_scene(links)
    h = 1e-2
    actual = np.concatenate(tree.coordinates_of(rd.step(scene, tree.joint_states(q, v), dt=h, method="implicit_midpoint")))
    expected = np.concatenate(ref.variational_midpoint_step(links, q, v, h, lambda q, v: generalized_force(links, q, v)))
    assert np.max(np.abs(actual - expected)) <= RTOL * max(1.0, np.max(np.abs(expected)))


GROUP_CASES = [(0, 3, False), (1, 3, False), (2, 3, False), (0, 3, True), (1, 3, True)]


@pytest.mark.parametrize("seed,n,free_base", GROUP_CASES)
def test_one_implicit_midpoint_step_on_rotation_joints_is_the_discrete_euler_lagrange_step(seed, n, free_base):
    """With ball and free joints, one implicit midpoint step is the variational step of rigiddyn_ref.tree's
    group_discrete_lagrangian (the midpoint rule on the curve of constant joint velocity, its discrete Legendre
    transforms by central differences of step 1e-6) under gravity. The differences' error, ~1e-12 of the momenta,
    divided by h and by H's smallest moment, bounds the agreement at ~1e-9 of the state; asserted at 1e-8."""
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, free_base, {"spherical": 0.5, "revolute": 0.3, "prismatic": 0.1, "fixed": 0.1})
    q, v, _ = random_state(rng, links)
    tree = build(links, np.zeros(3))
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=G_W)])
    scene.add_tree(tree, "arm")
    h = 1e-2
    q1, v1 = tree.coordinates_of(rd.step(scene, tree.joint_states(q, v), dt=h, method="implicit_midpoint"))
    q1_ref, v1_ref = ref.group_variational_midpoint_step(links, q, v, h, G_W)
    poses, _ = ref.poses(links, q1)
    poses_ref, _ = ref.poses(links, q1_ref)  # quaternions compared as rotations (q and -q are one)
    assert np.max(np.abs(poses - poses_ref)) <= 1e-8 * max(1.0, np.max(np.abs(poses_ref)))
    assert np.max(np.abs(v1 - v1_ref)) <= 1e-8 * max(1.0, np.max(np.abs(v1_ref)))


def floating_spacecraft():
    """A bus on a free joint, a boom on a ball joint, a panel on a hinge: no element, so the tree's linear momentum
    and its angular momentum about W's origin are conserved."""
    tree = rd.Tree()
    tree.add_link("bus", -1, rd.FreeJoint(), rd.SpatialInertia(40.0, [0.0, 0.0, 0.0], np.diag([6.0, 7.0, 8.0])))
    tree.add_link("boom", 0, rd.SphericalJoint(), rd.SpatialInertia(2.0, [0.8, 0.0, 0.0], np.diag([0.02, 0.4, 0.4])),
                  rd.Transform(translation=[1.0, 0.0, 0.0]))
    tree.add_link("panel", 1, rd.RevoluteJoint([0.0, 0.0, 1.0]),
                  rd.SpatialInertia(3.0, [0.5, 0.0, 0.0], np.diag([0.1, 0.3, 0.4])), rd.Transform(translation=[1.6, 0.0, 0.0]))
    scene = rd.Scene()
    scene.add_tree(tree, "craft")
    v = np.array([0.3, -0.2, 0.5, 0.1, 0.2, -0.1, 1.0, -2.0, 0.5, 2.0])
    return tree, scene, tree.joint_states(tree.neutral_configuration(), v)


def test_the_variational_midpoint_keeps_a_floating_trees_momenta():
    """Discrete Noether theorem: L_d is invariant under rigid motions of the whole tree (its chart moves with them),
    so the linear momentum and the angular momentum about W's origin are kept to round-off: each step solves H v = p
    (error ~ eps κ(H) |p|, κ < 1e4 here) and sums O(n) transforms, so over N = 1000 steps their change stays below
    N eps κ |p| ≈ 2e-9 of |p|. RK4 keeps them only to its error (~1e-6 of |p| here)."""
    tree, scene, start = floating_spacecraft()
    drift = {}
    for method in ("implicit_midpoint", "rk4"):
        result = rd.simulate(scene, start, 1e-2, duration=10.0, method=method)
        assert result.unconverged_steps == 0
        L, H = result.linear_momentum_W, result.angular_momentum_W
        drift[method] = max(np.max(np.abs(L - L[0])) / np.linalg.norm(L[0]), np.max(np.abs(H - H[0])) / np.linalg.norm(H[0]))
    assert drift["implicit_midpoint"] <= 2e-9
    assert drift["rk4"] > 1e-7




@pytest.mark.parametrize("dt", [0.02, 0.05])
def test_the_variational_midpoint_converges_at_long_steps_with_a_light_link(dt):
    """The plain iteration of the variational step contracts at a rate ~ h × (joint rate) × (the links' inertia
    ratio): on the floating spacecraft (a 0.02 kg m² boom on a 40 kg bus, turning at ~2 rad/s) it missed the
    tolerance within the cap in 115 of 3000 steps at 20 ms and in 901 of 1200 at 50 ms. Anderson's mixing of the
    iterates takes every step to the tolerance; the momenta are then kept to round-off, below N eps κ |p| (the test
    above's bound, κ < 1e4) over the N steps."""
    tree, scene, start = floating_spacecraft()
    result = rd.simulate(scene, start, dt, duration=60.0, method="implicit_midpoint",
                         accuracy_level=None)  # 50 ms is coarse for the boom's motion (the energy balance says so)
    assert result.unconverged_steps == 0
    L, H = result.linear_momentum_W, result.angular_momentum_W
    drift = max(np.max(np.abs(L - L[0])) / np.linalg.norm(L[0]), np.max(np.abs(H - H[0])) / np.linalg.norm(H[0]))
    assert drift <= (len(result.t) - 1) * np.finfo(float).eps * 1e4

def turntable_pendulum():
    """A turntable about the vertical z (the axis of gravity) carrying a double pendulum hinged about its y: the
    scene is symmetric under turns about z, so the turntable's generalized momentum (the angular momentum about z)
    is conserved (Noether)."""
    rod = rd.SpatialInertia(1.0, [0.5, 0.0, 0.0], np.diag([1e-3, 1.0 / 12.0, 1.0 / 12.0]))
    tree = rd.Tree()
    tree.add_link("turntable", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0],
                                                                                         np.diag([0.1, 0.1, 0.2])))
    tree.add_link("arm", 0, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod, rd.Transform(translation=[0.3, 0.0, 0.0]))
    tree.add_link("tip", 1, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod, rd.Transform(translation=[1.0, 0.0, 0.0]))
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=[0.0, 0.0, -9.81])])
    scene.add_tree(tree, "top")
    return tree, scene, tree.joint_states([0.0, 0.7, -1.2], [3.0, 0.5, -2.0])


def test_the_variational_midpoint_keeps_a_symmetrys_momentum():
    """Discrete Noether theorem (Marsden & West 2001, §1.3.3): the midpoint discrete Lagrangian is invariant under turns
    about z, so p_turntable is kept exactly, up to round-off: each step adds h ṗ_z, whose gravity torque about z is 0
    but for round-off, and solves H v = p (error ~ eps κ(H) |p|, κ < 1e3 here), so over N steps |Δp| <= N eps κ |p|
    = 1e-9 |p| for N = 5000. RK4 is not symplectic: its p drifts by O(h⁴) per unit time (1e-6 of |p| here)."""
    tree, scene, start = turntable_pendulum()
    p_z = {}
    for method in ("implicit_midpoint", "rk4"):
        result = rd.simulate(scene, start, 1e-2, duration=50.0, method=method)
        p_z[method] = np.array([rd.generalized_momentum(tree, q, v)[0] for q, v in zip(result.joint_q, result.joint_v)])
        assert np.allclose(p_z[method], result.angular_momentum_W[:, 2], rtol=1e-12, atol=0.0)
    p0 = abs(p_z["rk4"][0])
    assert np.max(np.abs(p_z["implicit_midpoint"] - p_z["implicit_midpoint"][0])) <= 1e-9 * p0
    assert np.max(np.abs(p_z["rk4"] - p_z["rk4"][0])) > 1e-7 * p0


def test_a_python_force_sees_each_links_attitude():
    """A tree fills its links' quaternions for a user's force (the other elements read the rotation matrices): a
    PythonForce called at the start sees each link's q_WB as the records hold it."""
    tree, scene, start = turntable_pendulum()
    seen = {}

    def record_attitude(t, body, p_W, q_WB, v_W, w_B):
        seen.setdefault(body, np.array(q_WB))
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)

    scene.add(rd.PythonForce(record_attitude))
    result = rd.simulate(scene, start, 1e-2, duration=0.02, method="rk4")
    for body in range(tree.num_links):
        assert np.allclose(seen[body], result.q_WB[0, body], rtol=0.0, atol=1e-15)
    assert np.allclose(result.q_WB[0, 1], [0.0, np.sin(0.35), 0.0, np.cos(0.35)], rtol=0.0, atol=1e-15)  # 0.7 about y


def test_the_variational_midpoint_bounds_the_energy_error_of_a_chaotic_run():
    """Backward error analysis (Hairer, Lubich & Wanner, GNI IX.8): a symplectic method keeps a modified energy
    H + h² H₂ + ... to O(h^N) over exponentially long times, so its energy error stays within the range of h² H₂ over
    the states visited and does not grow: over 200 s (20 000 steps, h = 10 ms) of the chaotic turntable pendulum the
    largest error in the last quarter is within 2× that of the first (the same region of states). RK4's error grows
    with t (here 4× from the first quarter to the last)."""
    tree, scene, start = turntable_pendulum()
    growth = {}
    for method in ("implicit_midpoint", "rk4"):
        result = rd.simulate(scene, start, 1e-2, duration=200.0, method=method)
        error = np.abs(result.total_energy - result.total_energy[0])
        quarter = len(error) // 4
        growth[method] = error[-quarter:].max() / error[:quarter].max()
    assert growth["implicit_midpoint"] <= 2.0
    assert growth["rk4"] > 2.0


@pytest.mark.parametrize("seed", range(4))
def test_work_energy_and_momentum_balances_close(seed):
    """T − T(0) = Σ work (gravity's and the spring's through their potentials' work, drag's) to RK4's error: the
    balance's verdict is 'closed' (its residual within the error estimate's allowance, accuracy_check); the
    momentum balances close for a floating tree (the anchor's spring force's impulse integrated) and do not apply to
    one held by a joint to W; and the estimate's order check passes (the tree runs at RK4's order). Linear drag only: the quadratic drag |v| v is not
    smooth where a link's velocity passes through zero, which takes RK4 below its order there (the estimate then
    says "not asymptotic", rightly)."""
    rng = np.random.default_rng(seed)
    links = random_links(rng, 4, seed % 2 == 0)
    q, v, _ = random_state(rng, links)
    tree, scene = tree_scene(links, {"linear": DRAG["linear"], "angular_linear": DRAG["angular_linear"]})
    result = rd.simulate(scene, tree.joint_states(q, 0.2 * v), 1e-3, duration=0.5, method="rk4")
    assert not result.diverged
    assert result.balance.verdict["energy"] == "closed", result.balance.verdict
    for quantity in ("linear_momentum", "angular_momentum"):  # closed for a floating tree, else its base's reaction
        assert result.balance.verdict[quantity] == "closed" if seed % 2 == 0 else \
            result.balance.verdict[quantity].startswith("not applicable: a tree held by a joint to W")
    # Richardson at h, 2h, 4h on every 4th record (those between interpolated): the observed order is RK4's, 4,
    # within the next term's share (O(h |λ|) ≈ 0.05 here), but where an error component passes through zero (a
    # record or two of a run: there its observed order says nothing, and the verdict rightly withholds "reliable")
    assert 3.8 <= np.nanmedian(result.error.observed_order) <= 4.2
    assert result.error.reliable[::4].mean() >= 0.9


@pytest.mark.parametrize("seed,free_base,method", [(0, True, "rk4"), (1, False, "rk4"), (2, True, "implicit_midpoint"),
                                                   (3, False, "semi_implicit_euler")])
def test_a_tree_applies_gravity_on_all_its_links_as_gravity_on_each_link(seed, free_base, method):
    """A UniformGravity on every link of a tree is applied by the tree's articulated-body algorithm as its base's
    acceleration (a₀ = −g, no wrench per link); split in two elements, each on some links, it loads each link with
    m g instead. Both are the same equations, so the runs agree to round-off: each evaluation differs by a few
    n² eps of its scale (the module docstring's bound), which 300 steps of this smooth map (|λ| t < 3) keep below
    1e-11 of the state's scale; asserted at 1e-10, for the motion, the energies, gravity's work and power (summed
    over the two elements) and the impulses (through a floating tree's momentum balances). A link's load switched on and off (ScheduledLoads) takes the links from
    unloaded to loaded and back."""
    rng = np.random.default_rng(seed)
    links = random_links(rng, 5, free_base)
    q, v, _ = random_state(rng, links)
    tree = build(links, np.zeros(3))
    push = rd.ScheduledLoads(body=2, loads=rd.AppliedLoad(force=(3.0, -1.0, 2.0), t_start=0.1, t_end=0.2),
                             point_B=POINT_B)
    whole = [rd.UniformGravity(g_W=G_W), push]
    split = [rd.UniformGravity(g_W=G_W, bodies=[0, 1]), push, rd.UniformGravity(g_W=G_W, bodies=[2, 3, 4])]
    runs = []
    for elements in (whole, split):
        scene = rd.Scene()
        scene.add_tree(tree, "arm")
        for element in elements:
            scene.add(element)
        runs.append(rd.simulate(scene, tree.joint_states(q, 0.3 * v), 1e-3, duration=0.3, method=method,
                                accuracy_level=None))  # two runs compared, whatever their accuracy
    a, b = runs
    for name in ("joint_q", "joint_v", "kinetic_energy", "potential_energy"):
        x, y = getattr(a, name), getattr(b, name)
        assert np.max(np.abs(x - y)) <= 1e-10 * max(1.0, np.max(np.abs(y))), name
    if free_base:  # the momentum balances L − L0 − J, H − H0 − K: the impulses agree to 1e-10 of the momenta's scale
        for name in ("linear_momentum", "angular_momentum"):
            x, y = getattr(a.balance, name), getattr(b.balance, name)
            assert np.max(np.abs(x - y)) <= 1e-10 * max(1.0, np.max(getattr(b.balance, name + "_scale"))), name
    for name in ("work", "power"):  # gravity's, then the push's
        x, y = getattr(a, name), getattr(b, name)
        gravity = y[:, 0] + y[:, 2]
        assert np.max(np.abs(x[:, 0] - gravity)) <= 1e-10 * max(1.0, np.max(np.abs(gravity))), name
        assert np.max(np.abs(x[:, 1] - y[:, 1])) <= 1e-10 * max(1.0, np.max(np.abs(y[:, 1]))), name
    assert np.any(a.power[:, 1] != 0.0) and np.any(a.power[:, 1] == 0.0)  # the push was on and off


def double_pendulum(gravity=None):
    """Two rods of 1 kg and 1 m hinged about y, the first at W's origin, with the tree's own gravity (None: none)."""
    rod = rd.SpatialInertia(1.0, [0.5, 0.0, 0.0], np.diag([1e-3, 1.0 / 12.0, 1.0 / 12.0]))
    tree = rd.Tree(gravity=gravity)
    tree.add_link("upper", -1, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod)
    tree.add_link("lower", 0, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod, rd.Transform(translation=[1.0, 0.0, 0.0]))
    return tree


def test_links_are_named_bodies_and_their_records_their_motion():
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    assert scene.add_tree(tree, "pendulum") == (0, 1)
    assert scene.body_names == ("pendulum.upper", "pendulum.lower")
    assert [type(b).__name__ for b in scene.bodies] == ["TreeLink", "TreeLink"]
    assert scene.bodies[1].link == 1 and scene.bodies[1].mass == 1.0
    q = np.array([0.4, -0.7])
    result = rd.simulate(scene, tree.joint_states(q), 0.01, steps=1, method="rk4")
    R_WL, p_WL, _ = rd.forward_kinematics(tree, q)
    # the lower link's centre of mass p_WL + R_WL c_L, its attitude R_WL (a forward_kinematics round-off apart)
    assert np.allclose(result.p_W[0, 1], p_WL[1] + R_WL[1] @ [0.5, 0.0, 0.0], rtol=0.0, atol=8 * np.finfo(float).eps)
    assert np.allclose(rd.quat_to_matrix(result.q_WB[0, 1]), R_WL[1], rtol=0.0, atol=8 * np.finfo(float).eps)
    # T + V of the records is the tree's own (its gravity the scene's): a few eps of m g l
    heavy = double_pendulum(gravity=[0.0, 0.0, -9.81])
    E = heavy.kinetic_energy(q, [0.0, 0.0]) + heavy.potential_energy(q)
    assert abs(result.total_energy[0] - E) <= 64 * np.finfo(float).eps * 9.81 * 2.0
    text = scene.describe("rk4")
    assert "tree_link" in text and "Tree links" in text and "pendulum.lower" in text


def test_a_double_pendulums_small_oscillations_are_its_normal_modes():
    """Released from rest near its hanging equilibrium (q = (π/2, 0): the rods along −z) in one normal mode's shape,
    the double pendulum of rods (m = 1 kg, l = 1 m, I_C = m l²/12 about the hinges) swings as ε s cos(ω t) in that
    mode (Goldstein, Classical Mechanics §6.2), ω² and s from det(K − ω² M) = 0 written by hand in the rods' absolute
    angles φ₁ = q₁, φ₂ = q₁ + q₂: M = [[I_C + m l²/4 + m l², m l²/2], [m l²/2, I_C + m l²/4]], K = diag(3/2, 1/2) m g l.
    Error bound relative to the amplitude ε = 1e-5: the nonlinear terms shift the motion by O(ε²) per radian of phase
    (≤ 1e-10 × ω t ≈ 1e-8 over 10 s), RK4 at h = 1 ms by (ω h)⁴ ω t / 120 < 1e-8, round-off by ~1e-9 of ε;
    asserted at 1e-7 ε. Both modes, each alone."""
    m, l, g, I_C = 1.0, 1.0, 9.81, 1.0 / 12.0
    M = np.array([[I_C + m * l**2 / 4 + m * l**2, m * l**2 / 2], [m * l**2 / 2, I_C + m * l**2 / 4]])
    K = np.diag([1.5, 0.5]) * m * g * l
    omega2, shapes = np.linalg.eig(np.linalg.solve(M, K))
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=(0.0, 0.0, -g))])
    scene.add_tree(tree, "pendulum")
    eps, q_eq = 1e-5, np.array([np.pi / 2, 0.0])
    for w2, phi in zip(omega2, shapes.T):
        s = eps * np.array([phi[0], phi[1] - phi[0]]) / np.max(np.abs(phi))  # in the joint angles q
        result = rd.simulate(scene, tree.joint_states(q_eq + s, [0.0, 0.0]), 1e-3, duration=10.0, method="rk4")
        expected = q_eq + np.outer(np.cos(np.sqrt(w2) * result.t), s)
        assert np.max(np.abs(result.joint_q - expected)) <= 1e-7 * eps


@pytest.mark.parametrize("method", ["rk4", "rkmk4", "implicit_midpoint", "semi_implicit_euler", "explicit_euler"])
def test_a_chaotic_double_pendulums_energy_error_falls_at_each_methods_order(method):
    """The double pendulum released from rest with both rods horizontal (chaotic) under gravity, no other element:
    its energy is conserved, so each method's largest energy error over 3 s is its own, O(h^p); halving h divides it
    by 2^p, within the next term's share: [0.75, 1.25] × 2^p (h = 2 ms and 1 ms for the orders above 1, 0.2 ms and
    0.1 ms for the Euler methods)."""
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree, "pendulum")
    p = {"rk4": 4, "rkmk4": 4, "implicit_midpoint": 2, "semi_implicit_euler": 1, "explicit_euler": 1}[method]
    h = 0.002 if p > 1 else 0.0002

    def energy_error(dt):
        r = rd.simulate(scene, tree.joint_states([0.0, 0.0], [0.0, 0.0]), dt, duration=3.0, method=method,
                        error=False, accuracy_level=None)  # the coarse Euler runs are inaccurate on purpose
        return np.max(np.abs(r.total_energy - r.total_energy[0]))

    ratio = energy_error(h) / energy_error(h / 2)
    assert 0.75 * 2**p <= ratio <= 1.25 * 2**p


def test_a_ball_jointed_top_is_the_lagrange_top():
    """A symmetric top as a one-link tree on a ball joint at W's origin, under the scene's gravity, against the
    Lagrange top's closed form (LagrangeTopSolution of the same PivotedBody) at every record over 2 s. Bound: RK4's
    error at h is at most twice its Richardson estimate |y(2h) − y(h)| / 15 (C h⁴ asymptotic, the next term's share
    doubled), plus the closed form's own error 16 eps κ (1 + |ω| t) (κ of I_O ≈ 3)."""
    m, c, I_C = 2.0, np.array([0.0, 0.0, 0.2]), np.diag([0.3, 0.3, 0.1])
    q0, w0 = so3_ref.rotvec_to_quat([0.5, 0.2, 0.0]), np.array([0.4, -0.3, 15.0])
    top = rd.LagrangeTopSolution(rd.PivotedBody(rd.RigidBody(m, I_C), c), [0.0, 0.0, -9.81],
                                 rd.PivotedBodyState(q_WB=q0, w_B=w0))
    tree = rd.Tree()
    tree.add_link("top", -1, rd.SphericalJoint(), rd.SpatialInertia(m, c, I_C))
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=(0.0, 0.0, -9.81))])
    scene.add_tree(tree, "top")
    fine, coarse = (rd.simulate(scene, tree.joint_states(q0, w0), h, duration=2.0, method="rk4",
                                record_every=round(0.1 / h)) for h in (1e-3, 2e-3))
    eps, w = np.finfo(float).eps, np.linalg.norm(w0)
    q_exact, w_exact = top.at(fine.t)
    slack = 16 * eps * 3 * (1 + w * fine.t)

    def angle(a, b):  # between attitudes (n, 4): 2 atan2(|vec(a⁻¹ b)|, |scalar|)
        d = np.array([so3_ref.quat_multiply(so3_ref.quat_inverse(x), y) for x, y in zip(a, b)])
        return 2 * np.arctan2(np.linalg.norm(d[:, :3], axis=1), np.abs(d[:, 3]))

    bound_q = 2 * angle(fine.q_WB[:, 0], coarse.q_WB[:, 0]) / 15 + slack
    bound_w = 2 * np.linalg.norm(fine.w_B[:, 0] - coarse.w_B[:, 0], axis=1) / 15 + w * slack
    assert np.all(angle(fine.q_WB[:, 0], q_exact) <= bound_q)
    assert np.all(np.linalg.norm(fine.w_B[:, 0] - w_exact, axis=1) <= bound_w)


def gyroscope():
    """A gyroscope on a stand: a gimbal turning about the vertical z at the pivot, a tilt frame on a horizontal hinge
    (y), and a symmetric rotor (m = 1 kg, I = diag(I₃, I₁, I₁) = diag(0.01, 0.006, 0.006) kg m²) spinning about
    its axle x, its centre d = 0.1 m out along the axle; the gimbals light (0.01 kg, 1e-4 kg m², centred on the
    pivot)."""
    light = rd.SpatialInertia(0.01, [0.0, 0.0, 0.0], 1e-4 * np.eye(3))
    tree = rd.Tree()
    tree.add_link("gimbal", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), light)
    tree.add_link("tilt", 0, rd.RevoluteJoint([0.0, 1.0, 0.0]), light)
    tree.add_link("rotor", 1, rd.RevoluteJoint([1.0, 0.0, 0.0]),
                  rd.SpatialInertia(1.0, [0.0, 0.0, 0.0], np.diag([0.01, 0.006, 0.006])),
                  rd.Transform(translation=[0.1, 0.0, 0.0]))
    scene = rd.Scene(elements=[rd.UniformGravity(g_W=(0.0, 0.0, -9.81))])
    scene.add_tree(tree, "gyroscope")
    return tree, scene


def test_a_gimballed_gyroscope_precesses_steadily_at_m_g_d_over_its_spin_momentum():
    """With its axle horizontal, the gyroscope's steady precession needs gravity's moment m g d about the tilt
    hinge to turn the spin momentum I₃ ψ̇ at the precession rate Ω: m g d = I₃ ψ̇ Ω exactly (the Lagrange top's
    steady-precession condition at θ = 90°, where the Ω² term vanishes; the gimbals, centred and isotropic, need no
    moment). Then every joint rate is constant, the exact motion is linear in t, and RK4 reproduces it but for
    round-off: N eps × |rates| ≈ 2000 × 2.2e-16 × 100 ≈ 4e-11 over 2 s, asserted at 1e-9. At 0.9 Ω the axle
    nutates (by ~3e-3 rad here): the condition is what keeps it."""
    tree, scene = gyroscope()
    spin = 100.0
    precession = 1.0 * 9.81 * 0.1 / (0.01 * spin)
    for rate, steady in ((precession, True), (0.9 * precession, False)):
        start = tree.joint_states([0.0, 0.0, 0.0], [rate, 0.0, spin])
        result = rd.simulate(scene, start, 1e-3, duration=2.0, method="rk4")
        drift = np.max(np.abs(result.joint_v - [rate, 0.0, spin]))
        tilt = np.max(np.abs(result.joint_q[:, 1]))
        if steady:
            assert drift <= 1e-9 and tilt <= 1e-9
            assert np.max(np.abs(result.joint_q[:, 0] - rate * result.t)) <= 1e-9
        else:
            assert tilt > 1e-4


def test_joint_states_round_trip():
    tree = double_pendulum()
    states = tree.joint_states([0.1, 0.2], [0.3, 0.4])
    q, v = tree.coordinates_of(states)
    assert np.array_equal(q, [0.1, 0.2]) and np.array_equal(v, [0.3, 0.4])
    assert states[0] == rd.JointState([0.1], [0.3])


def test_bad_input_is_refused_naming_the_value():
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree)
    with pytest.raises(ValueError, match=r"name: expected names for the links that no other body of the scene has "
                                         r"\('upper' is body 0's\)"):
        scene.add_tree(tree)
    with pytest.raises(ValueError, match=r"tree.gravity: expected zero in a scene"):
        rd.Scene().add_tree(double_pendulum(gravity=[0.0, 0.0, -9.81]))
    with pytest.raises(ValueError, match=r"initial\[1\].q: expected 1 coordinates \(the revolute joint of link "
                                         r"'lower'\), got 2"):
        rd.simulate(scene, [rd.JointState([0.0], [0.0]), rd.JointState([0.0, 0.0], [0.0])], 0.01, steps=1, method="rk4")
    with pytest.raises(ValueError, match=r"method: expected a method that integrates the whole motion"):
        rd.simulate(scene, tree.joint_states(), 0.01, steps=1, method="splitting_dlm")
    with pytest.raises(ValueError, match=r"^q: expected finite"):
        rd.JointState([np.nan], [0.0])
    with pytest.raises(TypeError, match=r"expected a JointState"):
        rd.simulate(scene, [rd.RigidBodyState(), rd.JointState([0.0], [0.0])], 0.01, steps=1, method="rk4")


def one_joint_tree(joint, mass, inertia):
    """One link on `joint` at W's origin, its centre of mass on the joint's axis."""
    tree = rd.Tree()
    tree.add_link("link", -1, joint, rd.SpatialInertia(mass, [0.0, 0.0, 0.0], inertia * np.eye(3)))
    return tree


def damped_oscillation(x0, v0, omega, zeta, t):
    """x(t) of x'' + 2 zeta omega x' + omega^2 x = 0 from x0, v0 (underdamped, zeta < 1)."""
    omega_d = omega * np.sqrt(1.0 - zeta**2)
    return np.exp(-zeta * omega * t) * (x0 * np.cos(omega_d * t) + (v0 + zeta * omega * x0) / omega_d * np.sin(omega_d * t))


def test_joint_springs_and_dampers_oscillate_as_their_closed_form():
    """A wheel (I = 0.5 kg m²) on a torsion spring and damper (k = 2 N m/rad, c = 0.2 N m s/rad) and a 2 kg slider on
    a spring and damper (k = 8 N/m, c = 0.4 N s/m), two trees of one scene: each joint coordinate is the damped
    oscillator's q0 + e^{−ζωt}(A cos ω_d t + B sin ω_d t), ω = √(k/I) = √(k/m) = 2 rad/s, ζ = c / (2√(k I)).
    Error bound: RK4's error per step on the oscillator's modes λ (|λ| = ω) is |hλ|⁵/120 of the state's size
    √(x² + (ẋ/ω)²) (the first term RK4 drops of e^{hλ}); over N steps at most N times that (the modes decay); asserted
    at twice the bound (the damping makes the modes slightly non-normal in these coordinates, ζ ≤ 0.1)."""
    wheel = one_joint_tree(rd.RevoluteJoint([0.0, 0.0, 1.0]), 2.0, 0.5)
    slider = one_joint_tree(rd.PrismaticJoint([1.0, 0.0, 0.0]), 2.0, 0.1)
    scene = rd.Scene()
    (hinge,), (rail,) = scene.add_tree(wheel, "wheel"), scene.add_tree(slider, "slider")
    scene.add(rd.RevoluteSpringDamper(body=hinge, stiffness=2.0, rest_angle=0.3, damping=0.2))
    scene.add(rd.PrismaticSpringDamper(body=rail, stiffness=8.0, rest_position=-0.5, damping=0.4))
    start = wheel.joint_states([0.5], [1.0]) + slider.joint_states([-0.4], [-0.3])
    h, steps, omega = 0.005, 1000, 2.0
    result = rd.simulate(scene, start, h, steps=steps, method="rk4")
    t = result.t
    for column, (rest, x0, v0, zeta) in enumerate([(0.3, 0.2, 1.0, 0.1), (-0.5, 0.1, -0.3, 0.05)]):
        bound = 2.0 * steps * (h * omega) ** 5 / 120.0 * np.hypot(x0, v0 / omega)
        error = np.abs(result.joint_q[:, column] - rest - damped_oscillation(x0, v0, omega, zeta, t))
        assert np.max(error) <= bound, (column, np.max(error), bound)
    # their potentials ½ k (q − q0)² are the records' potential energy; the dampers' work closes the energy balance
    expected_V = 0.5 * 2.0 * (result.joint_q[:, 0] - 0.3) ** 2 + 0.5 * 8.0 * (result.joint_q[:, 1] + 0.5) ** 2
    assert np.allclose(result.potential_energy, expected_V, rtol=1e-14, atol=1e-15)
    assert result.balance.verdict["energy"] == "closed"


def test_a_ball_joints_spring_twists_a_body_as_its_closed_form():
    """A body on a ball joint (principal moments 0.5, 0.8, 1.1 kg m² about the joint, its centre of mass there) twisted
    2 rad about its principal axis y from a rest attitude q0 about z, on a torsion spring of k = 2.2 N m/rad: its
    rotation from rest stays about y (no torque leaves that axis), so φ(t) = 2 cos(ω t) rad, ω = √(k/I_y) exactly,
    however large the twist (below π). Error bound: RK4 integrates the joint's quaternion, whose components
    sin(φ/2), cos(φ/2) are not linear in φ, so the scalar oscillator's constant |hω|⁵/120 does not apply; the step
    is in RK4's asymptotic range (hω = 0.003), where the error is C h⁴ to a relative O(h): the error at h is at most
    twice its step-doubling estimate 16/15 |φ_h − φ_h/2| (as the estimate is), plus a few roundings a step. A
    law that were not the closed form's (a wrong sign, a couple off the axis) would leave an error that does not
    shrink as h⁴. The spring's potential ½ k |φ|² is the records' potential energy; the energy balance closes."""
    tree = rd.Tree()
    tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(3.0, [0.0, 0.0, 0.0], np.diag([0.5, 0.8, 1.1])))
    scene = rd.Scene()
    (ball,) = scene.add_tree(tree, "mount")
    rest = np.array([0.0, 0.0, 0.7])  # q0: 0.7 rad about z (J to L)
    scene.add(rd.SphericalSpringDamper(body=ball, stiffness=2.2, rest_rotation=rest))
    q0 = so3_ref.rotvec_to_quat(rest)
    start = so3_ref.quat_multiply(q0, so3_ref.rotvec_to_quat([0.0, 2.0, 0.0]))  # q0 exp(φ0), φ0 in L
    h, steps, omega = 0.002, 2000, np.sqrt(2.2 / 0.8)

    def rotation_from_rest(result):
        return np.array([so3_ref.quat_to_rotvec(so3_ref.quat_multiply(so3_ref.quat_inverse(q0), so3_ref.quat_normalize(q)))
                         for q in result.joint_q])

    result = rd.simulate(scene, tree.joint_states(start), h, steps=steps, method="rk4")
    halved = rd.simulate(scene, tree.joint_states(start), h / 2, steps=2 * steps, method="rk4", record_every=2)
    phi, phi_half = rotation_from_rest(result), rotation_from_rest(halved)
    roundoff = steps * 8 * np.finfo(float).eps * 2.0
    error = np.max(np.abs(phi[:, 1] - 2.0 * np.cos(omega * result.t)))
    estimate = 16.0 / 15.0 * np.max(np.abs(phi[:, 1] - phi_half[:, 1]))
    assert error <= 2.0 * estimate + roundoff, (error, estimate)
    assert np.max(np.abs(phi[:, [0, 2]])) <= roundoff  # round-off only
    assert np.allclose(result.potential_energy, 0.5 * 2.2 * np.sum(phi**2, axis=1), rtol=1e-12, atol=1e-14)
    assert result.balance.verdict["energy"] == "closed"


def test_a_ball_joints_damper_keeps_a_floating_trees_momenta():
    """A bus (a free base) carrying a boom on a ball joint with a torsion spring and damper, the boom set swinging: the
    pair is internal, so the tree's linear and angular momenta are conserved, and the damper's work is the energy
    lost: all three balances 'closed'; the swing decays."""
    tree = rd.Tree()
    tree.add_link("bus", -1, rd.FreeJoint(), rd.SpatialInertia(40.0, [0.0, 0.0, 0.0], np.diag([6.0, 7.0, 8.0])))
    tree.add_link("boom", 0, rd.SphericalJoint(), rd.SpatialInertia(2.0, [0.8, 0.0, 0.0], np.diag([0.02, 0.4, 0.4])),
                  rd.Transform(translation=[0.5, 0.0, 0.0]))
    scene = rd.Scene()
    bus, boom = scene.add_tree(tree, "craft")
    scene.add(rd.SphericalSpringDamper(body=boom, stiffness=5.0, damping=2.0))
    v = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.3, -0.5, 1.0])
    result = rd.simulate(scene, tree.joint_states(None, v), 0.005, duration=6.0, method="rk4")
    assert all(result.balance.verdict[q] == "closed" for q in ("energy", "linear_momentum", "angular_momentum")), \
        result.balance.verdict
    # the boom's swing relative to the bus decays (ζ ≈ 0.3 at ω ≈ 1.7 rad/s: e^(−ζ ω t) ≈ 0.03 at t = 6 s)
    assert np.linalg.norm(result.joint_v[-1, 6:]) < 0.2 * np.linalg.norm(v[6:])


def test_a_motor_window_in_a_floating_trees_hinge_keeps_its_momenta():
    """A bus (a free base) and a panel on a hinge about z driven by 2 N m on [0.2, 0.5) s: the panel turns one way,
    the bus the other; the motor's pair is internal, so the tree's linear and angular momenta stay zero, and its work
    is the kinetic energy gained (no potential): all three balances 'closed' (within the run's error allowance). The
    motor's power is τ q̇ inside its window and zero outside (the run splits its steps at t_start and t_end). A motor
    without a window is on at any time (a scene with it needs no time to step: the reference-step test above)."""
    tree = rd.Tree()
    tree.add_link("bus", -1, rd.FreeJoint(), rd.SpatialInertia(50.0, [0.0, 0.0, 0.0], np.diag([8.0, 9.0, 10.0])))
    tree.add_link("panel", 0, rd.RevoluteJoint([0.0, 0.0, 1.0]),
                  rd.SpatialInertia(5.0, [1.0, 0.0, 0.0], np.diag([0.1, 1.5, 1.6])), rd.Transform(translation=[0.6, 0.0, 0.0]))
    scene = rd.Scene()
    bus, panel = scene.add_tree(tree, "craft")
    motor = scene.add(rd.RevoluteMotor(body=panel, torque=2.0, t_start=0.2, t_end=0.5))
    result = rd.simulate(scene, tree.joint_states(), 0.01, duration=1.0, method="rk4")
    assert all(result.balance.verdict[q] == "closed" for q in ("energy", "linear_momentum", "angular_momentum")), \
        result.balance.verdict
    assert result.joint_v[-1, 6] > 0.0 and result.w_B[-1, bus, 2] < 0.0  # the panel and the bus turn apart
    # the records in (0.2, 0.5] hold the motor's piece (a record at a switch time ends the piece before it)
    window = (result.t > 0.2 + 1e-12) & (result.t < 0.5 + 1e-12)
    assert np.all(result.power[window, motor] > 0.0) and np.all(result.power[~window, motor] == 0.0)


def test_the_step_recommendation_sees_a_joint_springs_mode():
    """A torsion spring k on a hinged rod (its centre of mass c off the axis) is the mode k / I_a, c_d / I_a of the
    step recommendation, I_a = I_zz + m |c_perp|² about the hinge (the parallel-axis theorem); a slider's is k / m."""
    tree = rd.Tree()
    tree.add_link("rod", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]),
                  rd.SpatialInertia(2.0, [0.5, 0.1, 0.0], np.diag([0.01, 0.2, 0.2])))
    tree.add_link("slider", 0, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(0.5, [0.0, 0.0, 0.0], 0.01 * np.eye(3)))
    scene = rd.Scene()
    rod, slider = scene.add_tree(tree, "arm")
    scene.add(rd.RevoluteSpringDamper(body=rod, stiffness=3.0, damping=0.1))
    scene.add(rd.PrismaticSpringDamper(body=slider, stiffness=8.0, damping=0.4))
    I_a = 0.2 + 2.0 * (0.5**2 + 0.1**2)
    modes = rd.stability.scene_modes(scene, tree.joint_states())
    assert [m[0] for m in modes] == ["the joint spring elements[0]", "the joint spring elements[1]"]
    assert np.allclose([m[1:] for m in modes], [(3.0 / I_a, 0.1 / I_a), (8.0 / 0.5, 0.4 / 0.5)], rtol=1e-14)  # a few ε
    # a ball joint's spring: k / I_min, I_min the least principal moment about the joint, I_C + m (|c|² 1 − c cᵀ) (0.2)
    ball = rd.Tree()
    ball.add_link("boom", -1, rd.SphericalJoint(), rd.SpatialInertia(2.0, [0.0, 0.3, 0.1], np.diag([0.1, 0.2, 0.2])))
    scene = rd.Scene()
    (boom,) = scene.add_tree(ball, "mount")
    scene.add(rd.SphericalSpringDamper(body=boom, stiffness=4.0, damping=0.2))
    I_min = np.linalg.eigvalsh(np.diag([0.1, 0.2, 0.2]) + 2.0 * (0.1 * np.eye(3) - np.outer([0.0, 0.3, 0.1], [0.0, 0.3, 0.1])))[0]
    modes = rd.stability.scene_modes(scene, ball.joint_states())
    assert np.allclose([m[1:] for m in modes], [(4.0 / I_min, 0.2 / I_min)], rtol=1e-13)  # an eigenvalue: a few ε


def test_joint_elements_refuse_bodies_without_their_joint():
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 1.0, 1.0])])
    scene.add_tree(double_pendulum(), "pendulum")
    with pytest.raises(ValueError, match=r"body: expected a link of a tree \(Scene.add_tree\) with a revolute joint, "
                                         r"got 0 \(a rigid body\)"):
        scene.add(rd.RevoluteSpringDamper(body=0, stiffness=1.0))
    with pytest.raises(ValueError, match=r"body: expected a link of a tree \(Scene.add_tree\) with a prismatic joint, "
                                         r"got 2 \('lower', whose joint is revolute\)"):
        scene.add(rd.PrismaticSpringDamper(body=2, stiffness=1.0))
    with pytest.raises(ValueError, match=r"damping: expected a finite number >= 0"):
        scene.add(rd.RevoluteSpringDamper(body=1, stiffness=1.0, damping=-0.1))
    with pytest.raises(ValueError, match=r"body: expected a link of a tree \(Scene.add_tree\) with a prismatic joint, "
                                         r"got 1 \('upper', whose joint is revolute\)"):
        scene.add(rd.PrismaticMotor(body=1, force=1.0))
    with pytest.raises(ValueError, match=r"t_end: expected a time after t_start = 2"):
        rd.RevoluteMotor(body=1, torque=1.0, t_start=2.0, t_end=1.0)
    with pytest.raises(ValueError, match=r"^t_start: expected .*got nan"):
        rd.PrismaticMotor(body=1, force=1.0, t_start=np.nan)


def test_a_scene_file_holds_trees_and_reads_back_the_same_scene():
    """A [[tree]] table with every joint kind, units and placements: read, written canonically, read back equal
    (the scene, its states, its run); the shipped double pendulum runs as its file says."""
    text = """
[[body]]
name = "anchor"
kind = "particle"
mass = 1

[[tree]]
name = "arm"
[[tree.link]]
name = "base"
joint = "free"
mass = "10 kg"
inertia = [1, 2, 2.5]
q = [0, 0, "1 m", 0, 0, 0, 1]
v = ["0.1 rad/s", 0, 0, 0, 0, "0.2 m/s"]
[[tree.link]]
name = "shoulder"
parent = "base"
joint = "spherical"
translation = [0.5, 0, 0]
rotation = [0, 0, 0.7071067811865476, 0.7071067811865476]
mass = 2
com = ["50 cm", 0, 0]
inertia = [[0.01, 0, 0], [0, 0.2, 0], [0, 0, 0.2]]
q = [0, 0, 0, 1]
v = [0, "10 rpm", 0]
[[tree.link]]
name = "slide"
parent = "shoulder"
joint = "prismatic"
axis = [1, 0, 0]
translation = [1, 0, 0]
mass = 1
inertia = [0.01, 0.01, 0.01]
q = ["20 cm"]
[[tree.link]]
name = "flange"
parent = "slide"
joint = "fixed"
mass = 0.1
inertia = [1e-4, 1e-4, 1e-4]

[[force]]
type = "spring_damper"
body_a = "arm.slide"
body_b = "anchor"
stiffness = 10
"""
    scene, initial, run = rd.load_scene(text)
    assert scene.body_names == ("anchor", "arm.base", "arm.shoulder", "arm.slide", "arm.flange")
    tree = scene.bodies[1].tree
    q, v = tree.coordinates_of(initial[1:])
    assert np.allclose(q[:7], [0, 0, 1, 0, 0, 0, 1]) and q[11] == 0.2 and v[7] == 2 * np.pi * 10 / 60
    assert scene.elements[0].body_a == 3
    again, initial_again, run_again = rd.load_scene(scene.to_toml(initial=initial, run=run))
    assert again == scene and initial_again == initial and run_again == run
    result = rd.simulate(scene, initial, 1e-3, steps=10, method="rk4")
    assert not result.diverged and result.joint_q.shape == (11, 12)
    shipped, start, options = rd.load_scene("double_pendulum")
    assert shipped.body_names == ("pendulum.upper", "pendulum.lower") and options.method == "rk4"


def test_a_scene_file_refuses_bad_trees_naming_the_field():
    link = '[[tree.link]]\nname = "rod"\njoint = "revolute"\nmass = 1\ninertia = [1, 1, 1]\n'
    with pytest.raises(ValueError, match=r"tree\[0\]\.link\[0\]\.axis: expected an axis for a revolute joint"):
        rd.load_scene("[[tree]]\n" + link)
    with pytest.raises(ValueError, match=r"tree\[0\]\.link\[0\]\.parent: expected the name of a link above it"):
        rd.load_scene("[[tree]]\n" + link.replace('joint = "revolute"', 'joint = "fixed"\nparent = "nowhere"'))
    with pytest.raises(ValueError, match=r"tree\[0\]\.link\[0\]\.q: expected 1 entries"):
        rd.load_scene("[[tree]]\n" + link + "axis = [0, 1, 0]\nq = [1, 2]\n")
    with pytest.raises(ValueError, match=r"tree\[0\]\.link\[0\]\.joint: expected one of 'revolute'"):
        rd.load_scene("[[tree]]\n" + link.replace("revolute", "hinge"))
    scene = rd.Scene()
    scene.add_tree(double_pendulum(), "pendulum")
    scene.add_body(rd.Particle(1.0), name="after")
    with pytest.raises(ValueError, match=r"expected the trees' links after every other body"):
        scene.to_toml()


def test_joint_columns_record_the_trees_coordinates():
    """joint_q and joint_v hold the tree's q and v at every record: the first the initial state, the last the state
    that as many steps reach (the same map: bitwise); they survive a pickle, and a batch has them per sample."""
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree, "pendulum")
    states = tree.joint_states([0.3, -0.2], [0.5, 0.0])
    result = rd.simulate(scene, states, 0.01, steps=20, method="rk4", record_every=10)
    assert result.joint_q.shape == (3, 2) and result.joint_v.shape == (3, 2)
    assert np.array_equal(result.joint_q[0], [0.3, -0.2]) and np.array_equal(result.joint_v[0], [0.5, 0.0])
    for _ in range(20):
        states = rd.step(scene, states, dt=0.01, method="rk4")
    q, v = tree.coordinates_of(states)
    assert np.array_equal(result.joint_q[-1], q) and np.array_equal(result.joint_v[-1], v)
    again = pickle.loads(pickle.dumps(result))
    assert np.array_equal(again.joint_q, result.joint_q) and np.array_equal(again.joint_v, result.joint_v)
    batch = rd.simulate_batch(scene, [tree.joint_states([a, 0.0]) for a in (0.1, 0.2, 0.3)], 0.01, steps=20,
                              method="rk4", record_every=10)
    assert batch.joint_q.shape == (3, 3, 2)
    assert np.array_equal(batch.joint_q[:, 0, 0], [0.1, 0.2, 0.3])
    assert np.array_equal(batch[2].joint_q, batch.joint_q[2])
    assert np.array_equal(pickle.loads(pickle.dumps(batch)).joint_v, batch.joint_v)
    free = rd.simulate(rd.Scene([rd.Particle(1.0)]), [rd.ParticleState()], 0.01, steps=2)
    assert free.joint_q.shape == (3, 0)


def test_table_columns_hold_the_joint_coordinates():
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree, "pendulum")
    result = rd.simulate(scene, tree.joint_states([0.3, -0.2]), 0.01, steps=4, method="rk4")
    from rigiddyn.scene_result import columns

    table = columns(result)
    assert np.array_equal(table["joint_q[1]"], result.joint_q[:, 1])
    assert np.array_equal(table["joint_v[0]"], result.joint_v[:, 0])
    assert "pendulum.lower:p_W_x [m]" in table


def test_a_scene_with_a_tree_equals_its_copies_and_scenes_of_equal_trees():
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(double_pendulum(), "pendulum")
    copy = rd.Scene(bodies=scene.bodies, body_names=scene.body_names, elements=scene.elements)
    assert copy == scene and scene.bodies[0] == copy.bodies[0] and scene.bodies[0] != scene.bodies[1]
    again = rd.Scene(elements=[rd.UniformGravity()])
    again.add_tree(double_pendulum(), "pendulum")  # another copy of an equal tree
    assert again == scene
    heavier = double_pendulum()
    heavier.add_link("tip", 1, rd.FixedJoint(), rd.SpatialInertia(0.1, [0.0, 0.0, 0.0], np.eye(3) * 1e-4))
    other = rd.Scene(elements=[rd.UniformGravity()])
    other.add_tree(heavier, "pendulum")
    assert other.bodies[0] != scene.bodies[0]


JOINTS = [rd.RevoluteJoint([0.0, 3.0, 4.0]), rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SphericalJoint(), rd.FreeJoint(),
          rd.FixedJoint()]


@pytest.mark.parametrize("joint", JOINTS, ids=lambda j: type(j).__name__)
def test_joints_compare_read_back_from_their_repr_and_pickle(joint):
    assert eval(repr(joint), vars(rd)) == joint  # noqa: S307 (the package's own repr)
    assert pickle.loads(pickle.dumps(joint)) == joint
    assert all((joint == other) == (other is joint) for other in JOINTS)


def test_trees_and_scenes_with_trees_pickle_and_run_the_same():
    """A tree, its links and a scene holding it (with a joint spring) survive a pickle (a Dask worker or a process pool
    receives them so): equal objects, and the scene runs bit for bit the same trajectory. Links unpickled one by one
    (each with its own copy of the tree) make a scene again: equal trees are shared by its links."""
    tree = double_pendulum()
    tree.add_link("slider", 1, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(0.2, [0.0, 0.0, 0.0], 1e-3 * np.eye(3)),
                  rd.Transform(translation=[1.0, 0.0, 0.0]))
    assert pickle.loads(pickle.dumps(tree)) == tree
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree, "arm")
    scene.add(rd.PrismaticSpringDamper(body=2, stiffness=50.0, rest_position=0.1, damping=0.5))
    again = pickle.loads(pickle.dumps(scene))
    assert again == scene and [pickle.loads(pickle.dumps(b)) for b in scene.bodies] == list(scene.bodies)
    start = tree.joint_states([0.4, -0.3, 0.05], [0.0, 1.0, 0.2])
    ran, ran_again = (rd.simulate(s, start, 1e-3, steps=200, method="rk4") for s in (scene, again))
    assert np.array_equal(ran.joint_q, ran_again.joint_q) and np.array_equal(ran.joint_v, ran_again.joint_v)
    links = [pickle.loads(pickle.dumps(b)) for b in scene.bodies]  # three copies of the tree
    rebuilt = rd.Scene(bodies=links, body_names=scene.body_names, elements=scene.elements)
    assert np.array_equal(rd.simulate(rebuilt, start, 1e-3, steps=200, method="rk4").joint_q, ran.joint_q)


def test_tradeoff_and_tolerance_run_on_a_tree():
    """tradeoff measures every method a tree takes (the others 'not applicable' with the reason), RK4's observed
    order 4 within the next term's share on its steady rows; simulate(tolerance=) picks a method and step and
    certifies the run."""
    tree = double_pendulum()
    scene = rd.Scene(elements=[rd.UniformGravity()])
    scene.add_tree(tree, "pendulum")
    start = tree.joint_states([0.5, 0.0])
    study = rd.tradeoff(scene, initial=start, horizon=1.0)
    measured = {row["method"] for row in study.rows if np.isfinite(row["final_state_error"])}
    assert measured == {"explicit_euler", "semi_implicit_euler", "rk4", "rkmk4", "implicit_midpoint"}
    orders = [row["observed_order"] for row in study.rows if row["method"] == "rk4" and row["order_note"] == ""]
    assert orders and 3.5 <= np.median(orders) <= 4.5
    result = rd.simulate(scene, start, None, duration=1.0, tolerance=1e-6)
    assert result.choice.met and result.choice.certified_error <= 1e-6


@pytest.mark.parametrize("method", ["rk4", "rkmk4", "implicit_midpoint", "semi_implicit_euler"])
def test_a_floating_tree_with_ball_joints_converges_at_each_methods_order(method):
    """A floating tree (a free joint, a ball joint, a revolute joint) under a spring to an anchor: the state after
    0.5 s at h and h/2 against the same method at h/32 (its error 32^p times smaller); the ratio is 2^p, p the
    method's order, within the next term's share: [0.75, 1.25] × 2^p. The quaternions of the free and ball joints
    move on SO(3) (RKMK4 by its dexp⁻¹ correction)."""
    tree = rd.Tree()
    tree.add_link("base", -1, rd.FreeJoint(), rd.SpatialInertia(10.0, [0.0, 0.0, 0.0], np.diag([1.0, 2.0, 2.5])))
    rod = rd.SpatialInertia(2.0, [0.5, 0.0, 0.0], np.diag([0.01, 0.2, 0.2]))
    tree.add_link("arm", 0, rd.SphericalJoint(), rod, rd.Transform(translation=[0.5, 0.0, 0.0]))
    tree.add_link("hand", 1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rod, rd.Transform(translation=[1.0, 0.0, 0.0]))
    scene = rd.Scene()
    scene.add_tree(tree)
    scene.add(rd.SpringDamper(body_a=2, point_a_B=[1.0, 0.0, 0.0], point_b=[2.0, 1.0, 0.0], stiffness=20.0))
    q = tree.neutral_configuration()
    q[7:11] = [0.0, 0.0, np.sin(0.25), np.cos(0.25)]
    start = tree.joint_states(q, [0.3, -0.2, 0.5, 0.1, 0.2, -0.1, 1.0, -2.0, 0.5, 2.0])
    p = {"rk4": 4, "rkmk4": 4, "implicit_midpoint": 2, "semi_implicit_euler": 1}[method]
    h = 0.01 if p > 1 else 0.002

    def end(dt):
        r = rd.simulate(scene, start, dt, duration=0.5, method=method, record_every=round(0.5 / dt), error=False,
                        accuracy_level=None)  # the coarse runs are inaccurate on purpose
        return np.concatenate([r.p_W[-1].ravel(), r.v_W[-1].ravel(), r.w_B[-1].ravel()])

    reference = end(h / 32)
    ratio = np.max(np.abs(end(h) - reference)) / np.max(np.abs(end(h / 2) - reference))
    assert 0.75 * 2**p <= ratio <= 1.25 * 2**p, ratio
