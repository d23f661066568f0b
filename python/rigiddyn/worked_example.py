"""The worked example of Craig ("Kinematics of a Rigid Body", K. Craig), computed with the
library's FrameTree.

Reference frames: R ground (the inertial "world"), R1 the shaft, R2 the disk. The shaft turns at
5 rad/s about i (i1 = i); the disk turns at 4 rad/s about k1 relative to the shaft, about an axis
through O, the end of the shaft (fixed in R). P is fixed on the disk at r = 0.06 m from O on the
disk's x2 axis, at the instant when the disk angle is θ = 30°, so r_OP = r cos θ i1 + r sin θ j1.
Craig finds the acceleration of P in R, in R1 components:

    a_P = (-16 r cos θ) i1 + (-41 r sin θ) j1 + (40 r cos θ) k1

twice: with P fixed in the moving frame R2 (ω = 5 i + 4 k1, α = 4 (5 i1 × k1) = -20 j1), and
("Alternate Solution") with P moving in R1 (ω = 5 i, α = 0; P's motion in R1 from the disk).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ._core import FrameMotion, FrameTree

TERMS = ("origin", "tangential", "centripetal", "relative", "coriolis")
TERM_LABELS = {
    "origin": "origin       a_O",
    "tangential": "tangential   α × r",
    "centripetal": "centripetal  ω × (ω × r)",
    "relative": "relative     a_rel",
    "coriolis": "Coriolis     2 ω × v_rel",
    "total": "total",
}


def _terms(a: Any) -> dict[str, np.ndarray]:
    """The named terms and total of a PointAcceleration as a dict of (3,) arrays."""
    return {name: getattr(a, name) for name in (*TERMS, "total")}


def textbook_worked_example(r: float = 0.06, theta: float = math.radians(30.0)) -> dict[str, Any]:
    """Build Craig's shaft-and-disk example with a FrameTree and return every quantity.

    r [m]: distance of P from O; theta [rad]: the disk angle at the instant considered. The disk
    starts at angle 0 at t = 0, so the instant is t = theta / 4 s (the shaft has then turned
    5 t rad about i; the answer in R1 components does not depend on it).

    Returns a dict with: "r", "theta", "t"; "r_OP_R1" (3,); "w_R_R2_R1", "alpha_R_R2_R1" (3,) (the
    disk in the ground, R1 components); "terms" (first solution, P fixed in R2) and
    "terms_alternate" (P moving in R1): dicts term -> (3,) array in R1 components [m/s^2] from the
    library; "closed_form" and "closed_form_alternate": the same terms worked by hand from the
    textbook's ω and α; "textbook_answer" (3,): (-16 r cos θ, -41 r sin θ, 40 r cos θ); "max_error": the
    largest |library - closed form| over all terms of both solutions.
    """
    tree = FrameTree()
    # R1: simple angular velocity 5 i in R; R2: simple angular velocity 4 k1 in R1, axis through O
    tree.add_frame("shaft", "world", FrameMotion.constant_rotation([1.0, 0.0, 0.0], 5.0))
    tree.add_frame("disk", "shaft", FrameMotion.constant_rotation([0.0, 0.0, 1.0], 4.0))
    t = theta / 4.0
    p_R2P_R2 = np.array([r, 0.0, 0.0])  # P on the disk's x2 axis
    zero = np.zeros(3)

    # first solution: P fixed in R2, seen from R; components in R1
    terms = _terms(tree.point_acceleration("disk", p_R2P_R2, zero, zero, "world", "shaft", t))
    # alternate solution: P moving in R1 (its position, velocity, acceleration seen from R1)
    r_OP_R1 = tree.point_position("disk", p_R2P_R2, "shaft", "shaft", t)
    v_rel = tree.point_velocity("disk", p_R2P_R2, zero, "shaft", "shaft", t).total
    a_rel = tree.point_acceleration("disk", p_R2P_R2, zero, zero, "shaft", "shaft", t).total
    terms_alt = _terms(tree.point_acceleration("shaft", r_OP_R1, v_rel, a_rel, "world", "shaft", t))

    c, s = math.cos(theta), math.sin(theta)
    textbook_answer = np.array([-16 * r * c, -41 * r * s, 40 * r * c])
    closed_form = {  # ω = (5, 0, 4), α = (0, -20, 0), r_OP = r (c, s, 0); P fixed in R2
        "origin": zero,
        "tangential": np.array([0.0, 0.0, 20 * r * c]),
        "centripetal": np.array([-16 * r * c, -41 * r * s, 20 * r * c]),
        "relative": zero,
        "coriolis": zero,
        "total": textbook_answer,
    }
    closed_form_alt = {  # ω = (5, 0, 0), α = 0; R1 v_P = 4 k1 × r_OP, R1 a_P = -16 r_OP
        "origin": zero,
        "tangential": zero,
        "centripetal": np.array([0.0, -25 * r * s, 0.0]),
        "relative": np.array([-16 * r * c, -16 * r * s, 0.0]),
        "coriolis": np.array([0.0, 0.0, 40 * r * c]),
        "total": textbook_answer,
    }
    max_error = max(
        float(np.max(np.abs(got[k] - want[k])))
        for got, want in ((terms, closed_form), (terms_alt, closed_form_alt))
        for k in want
    )
    return {
        "r": r,
        "theta": theta,
        "t": t,
        "r_OP_R1": r_OP_R1,
        "w_R_R2_R1": tree.angular_velocity("disk", "world", "shaft", t),
        "alpha_R_R2_R1": tree.angular_acceleration("disk", "world", "shaft", t),
        "terms": terms,
        "terms_alternate": terms_alt,
        "closed_form": closed_form,
        "closed_form_alternate": closed_form_alt,
        "textbook_answer": textbook_answer,
        "max_error": max_error,
    }


def _vec(v: np.ndarray) -> str:
    return "[" + ", ".join(f"{x:+.6f}" for x in np.asarray(v, dtype=float) + 0.0) + "]"


def format_worked_example(result: dict[str, Any]) -> str:
    """A printable report of textbook_worked_example(): the set-up, then for both solutions each
    acceleration term and the total from the library beside its closed form."""
    r, theta = result["r"], result["theta"]
    lines = [
        "Worked example of K. Craig, \"Rigid Body Dynamics\" (Kinematics of a Rigid Body): a disk on a rotating shaft",
        "  R  ground, inertial frame ('world')",
        "  R1 shaft: simple angular velocity 5 i rad/s in R (FrameMotion.constant_rotation)",
        "  R2 disk:  simple angular velocity 4 k1 rad/s in R1, about k1 through O (end of the shaft)",
        (f"  P  fixed in the disk, r = {r:g} m from O; disk angle θ = {math.degrees(theta):g}° "
         f"(t = {result['t']:.6f} s)"),
        f"  r_OP     = r cos θ i1 + r sin θ j1 = {_vec(result['r_OP_R1'])} m",
        f"  ω (R2 in R) = 5 i + 4 k1         = {_vec(result['w_R_R2_R1'])} rad/s",
        f"  α (R2 in R) = 4 (5 i1 × k1) = -20 j1 = {_vec(result['alpha_R_R2_R1'])} rad/s²",
        "",
        "Acceleration of P in R, components along (i1, j1, k1) [m/s²]",
    ]
    header = f"  {'term':<26}{'library (FrameTree)':<36}closed form"
    for title, got, want in (
        ("Solution 1: P fixed in the moving frame R2 (ω = 5 i + 4 k1, α = -20 j1)",
         result["terms"], result["closed_form"]),
        ("Alternate solution: P moving in the frame R1 (ω = 5 i, α = 0)",
         result["terms_alternate"], result["closed_form_alternate"]),
    ):
        lines += ["", title, header]
        lines += [f"  {TERM_LABELS[k]:<26}{_vec(got[k]):<36}{_vec(want[k])}" for k in (*TERMS, "total")]
    lines += [
        "",
        "Textbook answer: a_P = (-16 r cos θ) i1 + (-41 r sin θ) j1 + (40 r cos θ) k1",
        f"               = {_vec(result['textbook_answer'])} m/s²",
        f"Largest |library - closed form| over all terms: {result['max_error']:.3g} m/s²",
    ]
    return "\n".join(lines)
