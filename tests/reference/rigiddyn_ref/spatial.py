"""Spatial vector algebra in plain numpy, as dense Featherstone matrices (angular part first).

A motion vector (twist) is the 6-array m = [w; v]; a force vector (wrench) f = [n; f]. A rigid
transform X_AB is the pair (R_AB, p_AB): R_AB maps B coordinates to A coordinates and p_AB is the
position of B's origin in A. References: Featherstone, "Rigid Body Dynamics Algorithms" (2008),
cited as "RBDA §k"; Rigid-body notes for the screw axis. Stacks (n, 6), (n, 3, 3), (n, 3) broadcast.
"""

from __future__ import annotations

import numpy as np

from .so3 import hat


def _split(m):
    m = np.asarray(m, dtype=float)
    return m[..., :3], m[..., 3:]


def _join(top, bottom) -> np.ndarray:
    return np.concatenate([top, bottom], axis=-1)


def _blocks(A, B, C, D) -> np.ndarray:
    """The 6x6 block matrix [[A, B], [C, D]] from (..., 3, 3) blocks."""
    return np.concatenate([np.concatenate([A, B], -1), np.concatenate([C, D], -1)], -2)


# ---------------------------------------------------------------- cross products
def crm(m) -> np.ndarray:
    """Motion cross-product matrix [[ŵ, 0], [v̂, ŵ]] so crm(m1) m2 = m1 x m2 (RBDA §2.9)."""
    w, v = _split(m)
    W, V = hat(w), hat(v)
    return _blocks(W, np.zeros_like(W), V, W)


def crf(m) -> np.ndarray:
    """Force cross-product matrix crf(m) = -crm(m)^T = [[ŵ, v̂], [0, ŵ]] (RBDA §2.9)."""
    return -np.swapaxes(crm(m), -1, -2)


def cross_motion(m1, m2) -> np.ndarray:
    """m1 x m2 = [w1 x w2; w1 x v2 + v1 x w2] (RBDA §2.9, written out)."""
    w1, v1 = _split(m1)
    w2, v2 = _split(m2)
    return _join(np.cross(w1, w2), np.cross(w1, v2) + np.cross(v1, w2))


def cross_force(m, f) -> np.ndarray:
    """m x* f = [w x n + v x f; w x f] (RBDA §2.9, written out)."""
    w, v = _split(m)
    n, f3 = _split(f)
    return _join(np.cross(w, n) + np.cross(v, f3), np.cross(w, f3))


def power(m, f) -> np.ndarray:
    """Scalar product m · f = w·n + v·f (RBDA §2.6): the power of wrench f on twist m."""
    return np.sum(np.asarray(m, dtype=float) * np.asarray(f, dtype=float), axis=-1)


# ---------------------------------------------------------------- rigid transforms
def motion_matrix(R, p) -> np.ndarray:
    """A_X_B for motion vectors: [[R, 0], [p̂ R, R]]. RBDA §2.8 gives the Plücker transform
    B_X_A = [[E, 0], [-E r̂, E]] (E = R^T: A to B coordinates, r = p); its inverse is this."""
    R = np.asarray(R, dtype=float)
    return _blocks(R, np.zeros_like(R), hat(p) @ R, R)


def force_matrix(R, p) -> np.ndarray:
    """A_X*_B for force vectors: [[R, p̂ R], [0, R]] = motion_matrix(R, p)^-T (RBDA §2.8)."""
    R = np.asarray(R, dtype=float)
    return _blocks(R, hat(p) @ R, np.zeros_like(R), R)


def act_point(R, p, r_B) -> np.ndarray:
    """Point coordinates B -> A: r_A = R r_B + p."""
    return np.einsum("...ij,...j->...i", np.asarray(R, dtype=float), np.asarray(r_B, float)) + p


def act_inv_point(R, p, r_A) -> np.ndarray:
    """Point coordinates A -> B: r_B = R^T (r_A - p)."""
    d = np.asarray(r_A, dtype=float) - np.asarray(p, dtype=float)
    return np.einsum("...ji,...j->...i", np.asarray(R, dtype=float), d)


def act_motion(R, p, m_B) -> np.ndarray:
    """Twist B -> A coordinates: [R w; R v + p x (R w)] (motion_matrix written out)."""
    w, v = _split(m_B)
    Rw = np.einsum("...ij,...j->...i", R, w)
    return _join(Rw, np.einsum("...ij,...j->...i", R, v) + np.cross(p, Rw))


def act_force(R, p, f_B) -> np.ndarray:
    """Wrench B -> A coordinates: [R n + p x (R f); R f] (force_matrix written out)."""
    n, f = _split(f_B)
    Rf = np.einsum("...ij,...j->...i", R, f)
    return _join(np.einsum("...ij,...j->...i", R, n) + np.cross(p, Rf), Rf)


def transform_compose(R_AB, p_AB, R_BC, p_BC):
    """X_AC = X_AB X_BC: R_AC = R_AB R_BC, p_AC = p_AB + R_AB p_BC."""
    R_AB = np.asarray(R_AB, dtype=float)
    return R_AB @ R_BC, act_point(R_AB, p_AB, p_BC)


def transform_inverse(R_AB, p_AB):
    """X_BA = X_AB^-1: R_BA = R_AB^T, p_BA = -R_AB^T p_AB."""
    R_BA = np.swapaxes(np.asarray(R_AB, dtype=float), -1, -2)
    return R_BA, -np.einsum("...ij,...j->...i", R_BA, p_AB)


# ---------------------------------------------------------------- screw of a twist
def _norm_and_unit(u):
    """(|u|, u/|u|) without underflow for tiny u: u is scaled by a power of two near its largest
    entry (exact) before squaring. For u = 0: (0, 0)."""
    biggest = np.max(np.abs(u), axis=-1)
    scale = np.ldexp(1.0, np.frexp(np.where(biggest > 0.0, biggest, 1.0))[1])
    s = u / scale[..., None]
    n = np.sqrt(np.sum(s * s, axis=-1))
    return scale * n, s / np.where(n > 0.0, n, 1.0)[..., None]


def twist_to_screw(m):
    """Instantaneous screw axis of the twist m = [w; v] (v: velocity of the point at the origin of
    the frame of expression; Rigid-body notes §4.10-4.11 "ISA"; Murray-Li-Sastry Prop. 2.9):
      direction = w/|w|, pitch h = w·v/|w|^2, point on the axis nearest the origin
      r = w x v/|w|^2, magnitude |w|.
    Pure translation (w = 0): direction v/|v|, pitch inf, point 0, magnitude |v|.
    Written with the unit axis (pitch = ŵ·v/|w|, point = ŵ x v/|w|) so that tiny |w| does not
    underflow. Returns (direction, point, pitch, magnitude)."""
    w, v = _split(np.asarray(m, dtype=float))
    wn, w_unit = _norm_and_unit(w)
    vn, v_unit = _norm_and_unit(v)
    rotating = wn > 0.0
    safe = np.where(rotating, wn, 1.0)
    direction = np.where(rotating[..., None], w_unit, v_unit)
    point = np.where(rotating[..., None], np.cross(w_unit, v) / safe[..., None], 0.0)
    pitch = np.where(rotating, np.sum(w_unit * v, axis=-1) / safe, np.inf)
    magnitude = np.where(rotating, wn, vn)
    return direction, point, pitch, magnitude
