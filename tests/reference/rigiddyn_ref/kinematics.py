"""Moving-frame kinematics in plain numpy, term by term (Craig "Kinematics of a Rigid Body",
Rigid-body notes §4.11.1 eqs (4.37)-(4.39)).

Notation: ω_PA is the angular velocity of frame A in frame P, α_PA = ^P d/dt ω_PA its angular
acceleration (the derivative taken in P). Unless a function takes a rotation matrix, all vectors
are expressed in one common frame of the caller's choice. Stacks broadcast over leading axes.
"""

from __future__ import annotations

import numpy as np


def compose_angular_velocity(w_PA, w_AB) -> np.ndarray:
    """Addition theorem: ω_PB = ω_PA + ω_AB (Craig "^Rω^R2 = ^Rω^R1 + ^R1ω^R2")."""
    return np.asarray(w_PA, dtype=float) + np.asarray(w_AB, dtype=float)


def compose_angular_acceleration(w_PA, alpha_PA, w_AB, alpha_AB) -> np.ndarray:
    """α_PB = ^P d/dt (ω_PA + ω_AB) = α_PA + ^A d/dt ω_AB + ω_PA x ω_AB, with α_AB = ^A d/dt ω_AB
    (transport theorem on ω_AB; Craig "There is no addition theorem for angular accelerations";
    Craig's example: 5i x 4k1 = -20 j1)."""
    return (np.asarray(alpha_PA, dtype=float) + np.asarray(alpha_AB, dtype=float)
            + np.cross(w_PA, w_AB))


def chain_angular_velocity(w_rel) -> np.ndarray:
    """ω_0N = Σ_i ω_(i-1)i for w_rel (..., N, 3) = [ω_01, ω_12, ..., ω_(N-1)N] (Craig, the
    addition theorem for N frames)."""
    return np.sum(np.asarray(w_rel, dtype=float), axis=-2)


def chain_angular_acceleration(w_rel, alpha_rel) -> np.ndarray:
    """α_0N = Σ_i [α_(i-1)i + ω_0(i-1) x ω_(i-1)i], α_(i-1)i = ^(i-1) d/dt ω_(i-1)i: the pairwise
    rule compose_angular_acceleration applied down the chain."""
    w_rel = np.asarray(w_rel, dtype=float)
    alpha_rel = np.asarray(alpha_rel, dtype=float)
    w_0i = np.zeros(w_rel.shape[:-2] + (3,))
    alpha_0i = np.zeros_like(w_0i)
    for i in range(w_rel.shape[-2]):
        alpha_0i = compose_angular_acceleration(w_0i, alpha_0i, w_rel[..., i, :],
                                                alpha_rel[..., i, :])
        w_0i = compose_angular_velocity(w_0i, w_rel[..., i, :])
    return alpha_0i


def transport_derivative(w_AB, u, du_dt_in_B) -> np.ndarray:
    """Transport theorem: ^A d/dt u = ^B d/dt u + ω_AB x u (Craig "^R dV/dt = ^R1 dV/dt +
    ^Rω^R1 x V"; Rigid-body notes (4.38)). All three vectors expressed in one frame."""
    return np.asarray(du_dt_in_B, dtype=float) + np.cross(w_AB, u)


def point_velocity_terms(v_O, w, r, v_rel) -> dict:
    """Velocity of a point P moving in a frame M whose origin O moves in the frame W (Craig
    "^R v^P = ^R v^A + ^R ω^R1 x r^AP + ^R1 v^P"; Rigid-body notes (4.38)): terms
      origin   = v_O          velocity of M's origin in W
      rotational = ω x r      r = r_OP, ω = ω_WM
      relative = v_rel        ^M d/dt r_OP
    and their sum `total`."""
    terms = {
        "origin": np.asarray(v_O, dtype=float),
        "rotational": np.cross(w, r),
        "relative": np.asarray(v_rel, dtype=float),
    }
    terms["total"] = terms["origin"] + terms["rotational"] + terms["relative"]
    return terms


def point_acceleration_terms(a_O, w, alpha, r, v_rel, a_rel) -> dict:
    """Acceleration of a point P moving in a moving frame M (Craig "^R a^P = ^R a^A +
    ^Rα^R1 x r + ^Rω^R1 x (^Rω^R1 x r) + ^R1 a^P + 2 ^Rω^R1 x ^R1 v^P"; Rigid-body notes (4.39)):
      origin      = a_O               acceleration of M's origin in W
      tangential  = α x r             α = ^W d/dt ω_WM
      centripetal = ω x (ω x r)
      relative    = a_rel             ^M d²/dt² r_OP
      coriolis    = 2 ω x v_rel       v_rel = ^M d/dt r_OP
    and their sum `total`."""
    terms = {
        "origin": np.asarray(a_O, dtype=float),
        "tangential": np.cross(alpha, r),
        "centripetal": np.cross(w, np.cross(w, r)),
        "relative": np.asarray(a_rel, dtype=float),
        "coriolis": 2.0 * np.cross(w, v_rel),
    }
    terms["total"] = (terms["origin"] + terms["tangential"] + terms["centripetal"]
                      + terms["relative"] + terms["coriolis"])
    return terms


def express(R_AB, v_B) -> np.ndarray:
    """Change of the frame of expression of a free vector: v_A = R_AB v_B."""
    return np.einsum("...ij,...j->...i", np.asarray(R_AB, dtype=float), np.asarray(v_B, float))


# ---------------------------------------------------------------- frames relative to frames
# A frame state K_PF of frame F relative to P is a dict of arrays, every vector expressed in P:
#   R (R_PF, 3x3), w (ω_PF), alpha (α_PF), p (p_PF: F's origin), v (^P d/dt p_PF), a (^P d²/dt² p_PF).
def frame_state(R=None, w=None, alpha=None, p=None, v=None, a=None) -> dict:
    """A frame state with identity/zero defaults for missing entries."""
    def vec(x):
        return np.zeros(3) if x is None else np.asarray(x, dtype=float)
    return {"R": np.eye(3) if R is None else np.asarray(R, dtype=float), "w": vec(w),
            "alpha": vec(alpha), "p": vec(p), "v": vec(v), "a": vec(a)}


def compose_kinematics(K_AP: dict, K_PF: dict) -> dict:
    """K_AF from K_AP and K_PF (result expressed in A): with R = R_AP and r = R p_PF,
      R_AF = R R_PF,  ω_AF = ω_AP + R ω_PF (addition theorem),
      α_AF = α_AP + R α_PF + ω_AP x R ω_PF (compose_angular_acceleration),
      p_AF = p_AP + r,  v_AF = point_velocity_terms(v_AP, ω_AP, r, R v_PF).total,
      a_AF = point_acceleration_terms(a_AP, ω_AP, α_AP, r, R v_PF, R a_PF).total."""
    R = K_AP["R"]
    r = express(R, K_PF["p"])
    v_rel, a_rel, w_rel = express(R, K_PF["v"]), express(R, K_PF["a"]), express(R, K_PF["w"])
    return {
        "R": R @ K_PF["R"],
        "w": compose_angular_velocity(K_AP["w"], w_rel),
        "alpha": compose_angular_acceleration(K_AP["w"], K_AP["alpha"], w_rel,
                                              express(R, K_PF["alpha"])),
        "p": K_AP["p"] + r,
        "v": point_velocity_terms(K_AP["v"], K_AP["w"], r, v_rel)["total"],
        "a": point_acceleration_terms(K_AP["a"], K_AP["w"], K_AP["alpha"], r, v_rel,
                                      a_rel)["total"],
    }


def relative_kinematics(K_WA: dict, K_WF: dict) -> dict:
    """K_AF (expressed in A) from K_WA and K_WF: compose_kinematics solved for K_PF, term by term.
    In W coordinates, with r = p_WF - p_WA:
      ω_AF = ω_WF - ω_WA,  α_AF = α_WF - α_WA - ω_WA x ω_AF,
      v_rel = v_WF - v_WA - ω_WA x r,
      a_rel = a_WF - a_WA - α_WA x r - ω_WA x (ω_WA x r) - 2 ω_WA x v_rel;
    then each is expressed in A by R_AW = R_WA^T."""
    R_AW = np.swapaxes(K_WA["R"], -1, -2)
    w_WA, alpha_WA = K_WA["w"], K_WA["alpha"]
    r = K_WF["p"] - K_WA["p"]
    w_AF = K_WF["w"] - w_WA
    alpha_AF = K_WF["alpha"] - K_WA["alpha"] - np.cross(w_WA, w_AF)
    v_rel = K_WF["v"] - K_WA["v"] - np.cross(w_WA, r)
    a_rel = (K_WF["a"] - K_WA["a"] - np.cross(alpha_WA, r) - np.cross(w_WA, np.cross(w_WA, r))
             - 2.0 * np.cross(w_WA, v_rel))
    return {"R": R_AW @ K_WF["R"], "w": express(R_AW, w_AF), "alpha": express(R_AW, alpha_AF),
            "p": express(R_AW, r), "v": express(R_AW, v_rel), "a": express(R_AW, a_rel)}
