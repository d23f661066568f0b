"""Rotations (SO(3)) in plain numpy: quaternions, matrices, rotation vectors, Euler angles.

Quaternions are (x, y, z, w) arrays unless ``scalar_first=True`` (then (w, x, y, z)); Hamilton
product, active rotation, q maps body coordinates to world coordinates. Every function works on
one item (shape (4,), (3,), (3, 3)) or a stack (n, 4), (n, 3), (n, 3, 3) through numpy's
``...`` indexing. References: Diebel, "Representing Attitude: Euler Angles, Unit Quaternions, and
Rotation Vectors" (2006), cited as "Diebel (k)"; Shepperd, "Quaternion from rotation matrix"
(1978); Shoemake, "Euler angle conversion" (Graphics Gems IV, 1994).
"""

from __future__ import annotations

import numpy as np

_AXIS = {"x": 0, "y": 1, "z": 2}


# ---------------------------------------------------------------- layout helpers
def _to_xyzw(q, scalar_first: bool) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    return q[..., [1, 2, 3, 0]] if scalar_first else q


def _from_xyzw(q: np.ndarray, scalar_first: bool) -> np.ndarray:
    return q[..., [3, 0, 1, 2]] if scalar_first else q


def _quat(v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Assemble (x, y, z, w) from the vector part v (..., 3) and the scalar part w (...)."""
    return np.concatenate([v, np.asarray(w)[..., None]], axis=-1)


def _sinc(x):
    """sin(x)/x, exact at 0 (numpy's sinc is sin(pi x)/(pi x))."""
    return np.sinc(np.asarray(x) / np.pi)


# ---------------------------------------------------------------- skew matrices
def hat(v) -> np.ndarray:
    """Skew matrix S = [v]x with S x = v x x (Rigid-body notes (4.66) uses [r] for this matrix)."""
    v = np.asarray(v, dtype=float)
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    o = np.zeros_like(x)
    return np.stack(
        [np.stack([o, -z, y], -1), np.stack([z, o, -x], -1), np.stack([-y, x, o], -1)], -2
    )


def vee(S) -> np.ndarray:
    """Inverse of hat: v from the skew part of S, v = (S32, S13, S21) (antisymmetrised)."""
    S = np.asarray(S, dtype=float)
    return 0.5 * np.stack(
        [S[..., 2, 1] - S[..., 1, 2], S[..., 0, 2] - S[..., 2, 0], S[..., 1, 0] - S[..., 0, 1]], -1
    )


# ---------------------------------------------------------------- elementary rotations
def axis_rotation(axis: int, angle) -> np.ndarray:
    """Active rotation by angle about coordinate axis `axis` (Diebel (59)-(61), transposed:
    Diebel writes passive rotations, rigiddyn active ones)."""
    a = np.asarray(angle, dtype=float)
    c, s = np.cos(a), np.sin(a)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    R = np.zeros(a.shape + (3, 3))
    R[..., axis, axis] = 1.0
    R[..., i, i] = c
    R[..., j, j] = c
    R[..., i, j] = -s
    R[..., j, i] = s
    return R


def rot_x(angle) -> np.ndarray:
    """R_x(angle) = [[1,0,0],[0,c,-s],[0,s,c]] (active)."""
    return axis_rotation(0, angle)


def rot_y(angle) -> np.ndarray:
    """R_y(angle) = [[c,0,s],[0,1,0],[-s,0,c]] (active)."""
    return axis_rotation(1, angle)


def rot_z(angle) -> np.ndarray:
    """R_z(angle) = [[c,-s,0],[s,c,0],[0,0,1]] (active)."""
    return axis_rotation(2, angle)


# ---------------------------------------------------------------- quaternion algebra
def quat_multiply(q1, q2, scalar_first: bool = False) -> np.ndarray:
    """Hamilton product q1 ⊗ q2 = (w1 v2 + w2 v1 + v1 x v2, w1 w2 - v1·v2) (Diebel (104))."""
    a, b = _to_xyzw(q1, scalar_first), _to_xyzw(q2, scalar_first)
    v1, w1, v2, w2 = a[..., :3], a[..., 3], b[..., :3], b[..., 3]
    v = w1[..., None] * v2 + w2[..., None] * v1 + np.cross(v1, v2)
    w = w1 * w2 - np.sum(v1 * v2, axis=-1)
    return _from_xyzw(_quat(v, w), scalar_first)


def quat_inverse(q, scalar_first: bool = False) -> np.ndarray:
    """q^-1 = conj(q) / |q|^2, conj(q) = (-v, w) (Diebel (108))."""
    a = _to_xyzw(q, scalar_first)
    conj = a * np.array([-1.0, -1.0, -1.0, 1.0])
    return _from_xyzw(conj / np.sum(a * a, axis=-1, keepdims=True), scalar_first)


def quat_normalize(q, scalar_first: bool = False) -> np.ndarray:
    """q / |q| (the layout is unchanged by normalisation)."""
    q = np.asarray(q, dtype=float)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def quat_to_matrix(q, scalar_first: bool = False) -> np.ndarray:
    """R(q) = (w^2 - v·v) I + 2 v v^T + 2 w [v]x for unit q (Diebel (125), active form)."""
    a = _to_xyzw(q, scalar_first)
    v, w = a[..., :3], a[..., 3]
    eye = np.eye(3)
    return (
        (w * w - np.sum(v * v, -1))[..., None, None] * eye
        + 2.0 * v[..., :, None] * v[..., None, :]
        + 2.0 * w[..., None, None] * hat(v)
    )


def matrix_to_quat(R, scalar_first: bool = False) -> np.ndarray:
    """Shepperd's method (1978): from the largest of 4w^2 = 1 + tr R, 4x^2 = 1 + 2 R00 - tr R, ...
    take that component, the others from the off-diagonal sums/differences; canonical sign as SciPy."""
    R = np.asarray(R, dtype=float)
    tr = R[..., 0, 0] + R[..., 1, 1] + R[..., 2, 2]
    # four candidates, each as (x, y, z, w) times 4*(its large component)
    c_w = np.stack([R[..., 2, 1] - R[..., 1, 2], R[..., 0, 2] - R[..., 2, 0],
                    R[..., 1, 0] - R[..., 0, 1], 1.0 + tr], -1)
    c_x = np.stack([1.0 + 2.0 * R[..., 0, 0] - tr, R[..., 0, 1] + R[..., 1, 0],
                    R[..., 0, 2] + R[..., 2, 0], R[..., 2, 1] - R[..., 1, 2]], -1)
    c_y = np.stack([R[..., 0, 1] + R[..., 1, 0], 1.0 + 2.0 * R[..., 1, 1] - tr,
                    R[..., 1, 2] + R[..., 2, 1], R[..., 0, 2] - R[..., 2, 0]], -1)
    c_z = np.stack([R[..., 0, 2] + R[..., 2, 0], R[..., 1, 2] + R[..., 2, 1],
                    1.0 + 2.0 * R[..., 2, 2] - tr, R[..., 1, 0] - R[..., 0, 1]], -1)
    candidates = np.stack([c_x, c_y, c_z, c_w], -2)  # (..., 4, 4)
    best = np.argmax(np.stack([R[..., 0, 0], R[..., 1, 1], R[..., 2, 2], tr], -1), axis=-1)
    c = np.take_along_axis(candidates, best[..., None, None], axis=-2)[..., 0, :]
    q = c / np.linalg.norm(c, axis=-1, keepdims=True)
    # canonical sign: the first non-zero of w, x, y, z positive (SciPy's as_quat(canonical=True))
    first_nonzero = np.take_along_axis(q[..., [3, 0, 1, 2]], np.argmax(q[..., [3, 0, 1, 2]] != 0.0, axis=-1)[..., None], -1)
    q = np.where(first_nonzero < 0.0, -q, q)
    return _from_xyzw(q, scalar_first)


def quat_rotate(q, v, scalar_first: bool = False) -> np.ndarray:
    """R(q) v = v + 2 w (u x v) + 2 u x (u x v), q = (u, w) unit (Diebel (125) expanded)."""
    a = _to_xyzw(q, scalar_first)
    v = np.asarray(v, dtype=float)
    u, w = a[..., :3], a[..., 3:4]
    t = np.cross(u, v)
    return v + 2.0 * w * t + 2.0 * np.cross(u, t)


# ---------------------------------------------------------------- exponential / logarithm
def _exp_pure(u) -> np.ndarray:
    """exp of a pure quaternion (u, 0): (sin|u| u/|u|, cos|u|), as (x, y, z, w)."""
    u = np.asarray(u, dtype=float)
    n = np.linalg.norm(u, axis=-1)
    return _quat(_sinc(n)[..., None] * u, np.cos(n))


def rotvec_to_quat(rotvec, scalar_first: bool = False) -> np.ndarray:
    """Exp map: q = exp(rotvec/2) = (sin(θ/2) rotvec/θ, cos(θ/2)), θ = |rotvec| (Diebel (198))."""
    return _from_xyzw(_exp_pure(0.5 * np.asarray(rotvec, dtype=float)), scalar_first)


def quat_to_rotvec(q, scalar_first: bool = False) -> np.ndarray:
    """Log map: θ = 2 atan2(|v|, w) with w >= 0 (so θ in [0, π]); rotvec = θ v/|v|, whose limit at
    |v| -> 0 is 2 v / w (Diebel (199) in atan2 form, well conditioned near 0 and π)."""
    a = _to_xyzw(q, scalar_first)
    a = a / np.linalg.norm(a, axis=-1, keepdims=True)
    a = np.where(a[..., 3:4] < 0.0, -a, a)
    v, w = a[..., :3], a[..., 3]
    s = np.linalg.norm(v, axis=-1)
    safe_s = np.where(s > 0.0, s, 1.0)
    safe_w = np.where(s > 0.0, 1.0, w)  # s = 0 implies w = 1 after normalisation
    scale = np.where(s > 0.0, 2.0 * np.arctan2(s, w) / safe_s, 2.0 / safe_w)
    return scale[..., None] * v


def rotvec_to_matrix(rotvec) -> np.ndarray:
    """Rodrigues: R = I + (sin θ/θ) K + ((1 - cos θ)/θ^2) K^2, K = [rotvec]x, θ = |rotvec|;
    (1 - cos θ)/θ^2 = sinc(θ/2)^2 / 2 avoids the cancellation near 0."""
    r = np.asarray(rotvec, dtype=float)
    th = np.linalg.norm(r, axis=-1)
    K = hat(r)
    return (np.eye(3) + _sinc(th)[..., None, None] * K
            + (0.5 * _sinc(0.5 * th) ** 2)[..., None, None] * (K @ K))


def matrix_to_rotvec(R) -> np.ndarray:
    """Log of R through its quaternion (Shepperd, then the atan2 log): stable at 0 and at π, where
    the textbook θ = acos((tr R - 1)/2), rotvec = θ/(2 sin θ) vee(R - R^T) loses all precision."""
    return quat_to_rotvec(matrix_to_quat(R))


def axis_angle_to_quat(axis, angle, scalar_first: bool = False) -> np.ndarray:
    """q = (sin(angle/2) n, cos(angle/2)) with n = axis/|axis| (Diebel (175))."""
    axis = np.asarray(axis, dtype=float)
    n = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    half = 0.5 * np.asarray(angle, dtype=float)
    return _from_xyzw(_quat(np.sin(half)[..., None] * n, np.cos(half)), scalar_first)


def quat_to_axis_angle(q, scalar_first: bool = False):
    """(axis, angle) with angle = |log q| in [0, π] and axis = rotvec/angle; at angle 0 the axis is
    undefined and returned as (1, 0, 0)."""
    r = quat_to_rotvec(q, scalar_first)
    angle = np.linalg.norm(r, axis=-1)
    safe = np.where(angle > 0.0, angle, 1.0)
    axis = np.where(angle[..., None] > 0.0, r / safe[..., None], np.array([1.0, 0.0, 0.0]))
    return axis, angle


def quat_integrate(q, w, dt, frame: str = "body", scalar_first: bool = False) -> np.ndarray:
    """Exact update for constant angular velocity w over dt: q ⊗ exp(w dt/2) for w in the body
    frame, exp(w dt/2) ⊗ q for w in the world frame (solution of q' = q ⊗ (w/2, 0) resp.
    q' = (w/2, 0) ⊗ q; Diebel (113)-(114) in Hamilton form)."""
    dq = _exp_pure(0.5 * np.asarray(dt, dtype=float)[..., None] * np.asarray(w, dtype=float))
    a = _to_xyzw(q, scalar_first)
    if frame == "body":
        out = quat_multiply(a, dq)
    elif frame == "world":
        out = quat_multiply(dq, a)
    else:
        raise ValueError(f"frame: expected 'body' or 'world', got {frame!r}")
    return _from_xyzw(out, scalar_first)


# ---------------------------------------------------------------- Euler angles
def _parse_seq(seq: str):
    """Return (axes i, j, k as intrinsic order, extrinsic flag). Extrinsic 'abc' with angles
    (a, b, c) is R = R_c(γ) R_b(β) R_a(α), i.e. the intrinsic sequence 'CBA' with angles reversed."""
    if (not isinstance(seq, str) or len(seq) != 3 or not (seq.islower() or seq.isupper())
            or any(ch not in _AXIS for ch in seq.lower())
            or seq[0].lower() == seq[1].lower() or seq[1].lower() == seq[2].lower()):
        raise ValueError(f"seq: expected one of the 12 Euler sequences such as 'xyz' or 'ZXZ', "
                         f"got {seq!r}")
    axes = [_AXIS[ch] for ch in seq.lower()]
    return axes, seq.islower()


def euler_to_matrix(seq: str, angles) -> np.ndarray:
    """Intrinsic 'IJK': R = R_I(a1) R_J(a2) R_K(a3); extrinsic 'ijk': R = R_k(a3) R_j(a2) R_i(a1)
    (Shoemake 1994; the same product read in the opposite order)."""
    axes, extrinsic = _parse_seq(seq)
    a = np.asarray(angles, dtype=float)
    Rs = [axis_rotation(ax, a[..., n]) for n, ax in enumerate(axes)]
    return Rs[2] @ Rs[1] @ Rs[0] if extrinsic else Rs[0] @ Rs[1] @ Rs[2]


def matrix_to_euler(seq: str, R) -> np.ndarray:
    """Inverse of euler_to_matrix, angle ranges as SciPy: first and third in [-π, π], second in
    [0, π] (proper Euler) or [-π/2, π/2] (Tait-Bryan). Formulas: see _angles_of."""
    axes, extrinsic = _parse_seq(seq)
    R = np.asarray(R, dtype=float)
    if extrinsic:  # R = R_k(c) R_j(b) R_i(a): intrinsic sequence (k, j, i) with (c, b, a)
        i, j, k = axes[2], axes[1], axes[0]
    else:
        i, j, k = axes
    a, b, c = _angles_of(i, j, k, R, zero_first=extrinsic)
    return np.stack([c, b, a], -1) if extrinsic else np.stack([a, b, c], -1)


_GIMBAL_TOL = 1e-7


def _angles_of(i: int, j: int, k: int, R: np.ndarray, zero_first: bool):
    """Angles (a, b, c) of R = R_i(a) R_j(b) R_k(c) (k = i: proper Euler, else Tait-Bryan).
    With k3 the axis other than i, j and ε = +1 if (i, j, k3) is a cyclic permutation, else -1
    (found by multiplying out the elementary matrices):
      Tait-Bryan: R[i,k] = ε sin b, R[j,k] = -ε sin a cos b, R[k,k] = cos a cos b,
                  R[i,j] = -ε cos b sin c, R[i,i] = cos b cos c;
      proper:     R[i,i] = cos b, R[j,i] = sin a sin b, R[k3,i] = -ε cos a sin b,
                  R[i,j] = sin b sin c, R[i,k3] = ε sin b cos c.
    b is taken by atan2 of its sine and cosine, both read off row i, so it is accurate near 0
    and near the ends of its range (arcsin/arccos are not).
    At gimbal lock (cos b = 0, resp. sin b = 0) only a ± c is defined. SciPy sets the angle that
    comes last in the written sequence to 0: c for intrinsic, a for extrinsic (zero_first). Then
      c = 0: R[:, j] = R_i(a) e_j = cos a e_j + ε sin a e_k3   ->  a = atan2(ε R[k3,j], R[j,j]);
      a = 0: R[j, :] = e_j^T R_k(c), i.e. R_k(-c) e_j = cos c e_j - σ sin c e_m (m the axis other
             than k, j; σ = +1 if (k, j, m) is cyclic)        ->  c = atan2(-σ R[j,m], R[j,j])."""
    k3 = 3 - i - j
    eps = 1.0 if (j - i) % 3 == 1 else -1.0
    if k == i:
        b = np.arctan2(np.hypot(R[..., i, j], R[..., i, k3]), R[..., i, i])
        a = np.arctan2(R[..., j, i], -eps * R[..., k3, i])
        c = np.arctan2(R[..., i, j], eps * R[..., i, k3])
        locked = np.abs(np.sin(b)) < _GIMBAL_TOL
    else:
        b = np.arctan2(eps * R[..., i, k], np.hypot(R[..., i, i], R[..., i, j]))
        a = np.arctan2(-eps * R[..., j, k], R[..., k, k])
        c = np.arctan2(-eps * R[..., i, j], R[..., i, i])
        locked = np.abs(np.cos(b)) < _GIMBAL_TOL
    if zero_first:
        m = 3 - k - j
        sigma = 1.0 if (j - k) % 3 == 1 else -1.0
        c = np.where(locked, np.arctan2(-sigma * R[..., j, m], R[..., j, j]), c)
        a = np.where(locked, 0.0, a)
    else:
        a = np.where(locked, np.arctan2(eps * R[..., k3, j], R[..., j, j]), a)
        c = np.where(locked, 0.0, c)
    return a, b, c


def euler_to_quat(seq: str, angles, scalar_first: bool = False) -> np.ndarray:
    """Product of elementary quaternions q_axis(θ) = (sin(θ/2) e_axis, cos(θ/2)) in the order of
    euler_to_matrix (Diebel §5 with (104)); returned with w >= 0."""
    axes, extrinsic = _parse_seq(seq)
    a = np.asarray(angles, dtype=float)
    qs = [axis_angle_to_quat(np.eye(3)[ax], a[..., n]) for n, ax in enumerate(axes)]
    q = (quat_multiply(quat_multiply(qs[2], qs[1]), qs[0]) if extrinsic
         else quat_multiply(quat_multiply(qs[0], qs[1]), qs[2]))
    q = np.where(q[..., 3:4] < 0.0, -q, q)
    return _from_xyzw(q, scalar_first)


def quat_to_euler(seq: str, q, scalar_first: bool = False) -> np.ndarray:
    """matrix_to_euler(seq, quat_to_matrix(q))."""
    return matrix_to_euler(seq, quat_to_matrix(q, scalar_first))
