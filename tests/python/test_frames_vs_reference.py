"""The core's moving-frame kinematics (rigiddyn, C++) against the independent numpy reference
(rigiddyn_ref.kinematics) on hypothesis-randomised frames and points, to ~1e-12: the formula-level
functions (compose/relative kinematics, point velocity/acceleration terms, transport theorem) and
every FrameTree query on a random tree, in every frame of expression."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import rigiddyn as rd
from rigiddyn_ref import kinematics as ref
from rigiddyn_ref import so3

settings.register_profile("reference", max_examples=60, deadline=None)
settings.load_profile("reference")

# one composition on each side: <= ~40 roundings of terms no larger than the centripetal one,
# |w|^2 |r| <= 8.7^2 * 8.7 = 660 (inputs <= 5 per component): 40 eps 660 = 6e-12 absolute, within
# close()'s atol = 100 TOL = 1e-10
EPS = np.finfo(float).eps
TOL = 1e-12
vec = arrays(np.float64, (3,), elements=st.floats(-5.0, 5.0))
rotation = arrays(np.float64, (3,), elements=st.floats(-4.0, 4.0)).map(so3.rotvec_to_matrix)

KEYS = {"R": "R_PF", "w": "w_PF_P", "alpha": "alpha_PF_P", "p": "p_PF_P", "v": "v_PF_P",
        "a": "a_PF_P"}


@st.composite
def states(draw):
    """A reference frame state (dict) with random orientation and derivatives."""
    return ref.frame_state(R=draw(rotation), w=draw(vec), alpha=draw(vec), p=draw(vec),
                           v=draw(vec), a=draw(vec))


def to_core(K):
    return rd.FrameKinematics(R_PF=K["R"], w_PF_P=K["w"], alpha_PF_P=K["alpha"], p_PF_P=K["p"],
                              v_PF_P=K["v"], a_PF_P=K["a"])


def close(a, b, tol=TOL):
    np.testing.assert_allclose(a, b, rtol=tol, atol=tol * 100)  # entries up to ~100 in size


def assert_same_state(core_K, ref_K):
    for key, attr in KEYS.items():
        close(getattr(core_K, attr), ref_K[key])


# ------------------------------------------------------------------ formula level
@given(states(), states())
def test_compose_kinematics(K_AP, K_PF):
    assert_same_state(rd.compose_kinematics(to_core(K_AP), to_core(K_PF)),
                      ref.compose_kinematics(K_AP, K_PF))


@given(states(), states())
def test_relative_kinematics(K_WA, K_WF):
    assert_same_state(rd.relative_kinematics(to_core(K_WA), to_core(K_WF)),
                      ref.relative_kinematics(K_WA, K_WF))


@given(states(), vec, vec, vec)
def test_point_velocity_and_acceleration_terms(K_AF, p_F, v_F, a_F):
    R = K_AF["R"]
    r, v_rel, a_rel = R @ p_F, R @ v_F, R @ a_F  # Q's motion in F, expressed in A
    want_v = ref.point_velocity_terms(K_AF["v"], K_AF["w"], r, v_rel)
    got_v = rd.point_velocity(to_core(K_AF), p_F, v_F)
    for term in ("origin", "rotational", "relative", "total"):
        close(getattr(got_v, term), want_v[term])
    want_a = ref.point_acceleration_terms(K_AF["a"], K_AF["w"], K_AF["alpha"], r, v_rel, a_rel)
    got_a = rd.point_acceleration(to_core(K_AF), p_F, v_F, a_F)
    for term in ("origin", "tangential", "centripetal", "relative", "coriolis", "total"):
        close(getattr(got_a, term), want_a[term])


@given(vec, vec, vec)
def test_transport_derivative(w_AB, u, du):
    close(rd.transport_derivative(w_AB, u, du), ref.transport_derivative(w_AB, u, du))


# ------------------------------------------------------------------ the frame tree
# world <- A <- B <- C, and world <- D: a branch so that queries cross the root.
PARENTS = {"A": "world", "B": "A", "C": "B", "D": "world"}


def build_tree(links):
    """A FrameTree whose frames have the constant kinematics `links[name]` (reference dicts)
    relative to their parents. Constant values are enough: every query is at one instant."""
    tree = rd.FrameTree()
    for name, parent in PARENTS.items():
        K = links[name]
        tree.add_frame(name, parent, rd.FrameMotion(
            lambda t, K=K: (K["R"], K["w"], K["alpha"], K["p"], K["v"], K["a"])))
    return tree


def in_world(links, name):
    """K_W<name> by composing the reference states down the path from the root."""
    if name == "world":
        return ref.frame_state()
    return ref.compose_kinematics(in_world(links, PARENTS[name]), links[name])


NAMES = st.sampled_from(["world", "A", "B", "C", "D"])


@settings(max_examples=40)
@given(st.fixed_dictionaries({name: states() for name in PARENTS}), NAMES, NAMES, NAMES,
       vec, vec, vec, st.floats(-10.0, 10.0))
def test_frame_tree_queries(links, frame, relative_to, expressed_in, p_F, v_F, a_F, t):
    tree = build_tree(links)
    K_AF = ref.relative_kinematics(in_world(links, relative_to), in_world(links, frame))
    R_EA = ref.relative_kinematics(in_world(links, expressed_in), in_world(links, relative_to))["R"]
    # a path of up to 6 links: terms up to M = (1 + W)^2 (1 + P + V + A) (W, P, V, A the sums of the
    # links' |w|, |p|, |v|, |a|: the largest cross product chain), <= 60 roundings of them per side;
    # close() takes atol = 100 tol
    W, P, V, A = (sum(np.abs(links[n][k]).sum() for n in PARENTS) for k in ("w", "p", "v", "a"))
    M = (1 + W) ** 2 * (1 + P + V + A + np.abs([p_F, v_F, a_F]).sum())
    tol = 2 * 60 * EPS * M / 100

    assert_close_state = [(getattr(tree.kinematics(frame, relative_to, t), attr), K_AF[key])
                          for key, attr in KEYS.items()]
    for got, want in assert_close_state:
        close(got, want, tol)
    close(tree.rotation(frame, relative_to, t), K_AF["R"], tol)
    close(tree.angular_velocity(frame, relative_to, expressed_in, t), R_EA @ K_AF["w"], tol)
    close(tree.angular_acceleration(frame, relative_to, expressed_in, t), R_EA @ K_AF["alpha"], tol)
    close(tree.point_position(frame, p_F, relative_to, expressed_in, t),
          R_EA @ (K_AF["p"] + K_AF["R"] @ p_F), tol)

    R = K_AF["R"]
    r, v_rel, a_rel = R @ p_F, R @ v_F, R @ a_F
    want_v = ref.point_velocity_terms(K_AF["v"], K_AF["w"], r, v_rel)
    got_v = tree.point_velocity(frame, p_F, v_F, relative_to, expressed_in, t)
    for term in ("origin", "rotational", "relative", "total"):
        close(getattr(got_v, term), R_EA @ want_v[term], tol)
    want_a = ref.point_acceleration_terms(K_AF["a"], K_AF["w"], K_AF["alpha"], r, v_rel, a_rel)
    got_a = tree.point_acceleration(frame, p_F, v_F, a_F, relative_to, expressed_in, t)
    for term in ("origin", "tangential", "centripetal", "relative", "coriolis", "total"):
        close(getattr(got_a, term), R_EA @ want_a[term], tol)

    # transport theorem between `frame` (B) and `relative_to` (A), vectors expressed in E
    u_E, du_E = v_F, a_F
    w_AB_E = R_EA @ K_AF["w"]
    close(tree.transport_derivative(u_E, du_E, frame, relative_to, expressed_in, t),
          ref.transport_derivative(w_AB_E, u_E, du_E), tol)


def test_seed_001_worked_example_through_the_tree():
    """Shaft R1 at 5 rad/s about i, disk R2 at 4 rad/s about k1; P fixed on the disk at
    r = 0.06 m, θ = 30° at t = 0: a_P = (-16 r cos θ, -41 r sin θ, 40 r cos θ) in R1 (Craig),
    the same from the core's tree and from the reference's two solutions."""
    r, th = 0.06, np.radians(30.0)
    answer = np.array([-16 * r * np.cos(th), -41 * r * np.sin(th), 40 * r * np.cos(th)])
    tree = rd.FrameTree()
    tree.add_frame("R1", "world", rd.FrameMotion.constant_rotation([1.0, 0, 0], 5.0))
    tree.add_frame("R2", "R1", rd.FrameMotion.constant_rotation([0, 0, 1.0], 4.0))
    p = np.array([r * np.cos(th), r * np.sin(th), 0.0])
    got = tree.point_acceleration("R2", p, np.zeros(3), np.zeros(3), "world", "R1", 0.0)
    np.testing.assert_allclose(got.total, answer, atol=1e-14)  # terms <= 2.5: a few eps of them

    K_WR2 = ref.compose_kinematics(ref.frame_state(w=[5.0, 0, 0]), ref.frame_state(w=[0, 0, 4.0]))
    want = ref.point_acceleration_terms(K_WR2["a"], K_WR2["w"], K_WR2["alpha"], p, np.zeros(3),
                                        np.zeros(3))
    for term in ("origin", "tangential", "centripetal", "relative", "coriolis", "total"):
        np.testing.assert_allclose(getattr(got, term), want[term], atol=1e-14)
