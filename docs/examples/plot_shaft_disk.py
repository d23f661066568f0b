r"""
Shaft and disk: the acceleration of a point, term by term
==========================================================

The worked example of K. Craig's "Rigid Body Dynamics: Kinematics and Kinetics" slides: a shaft
turns at 5 rad/s about the ground's axis i; a disk at the end O of the shaft turns at 4 rad/s about
the shaft's axis k1 relative to the shaft. P is fixed on the disk at r = 0.06 m from O, at disk angle
θ = 30°. The slides find the acceleration of P in the ground R, in the shaft's components:

.. math::

   a_P = (-16\, r \cos\theta)\, i_1 + (-41\, r \sin\theta)\, j_1 + (40\, r \cos\theta)\, k_1

twice: with P fixed in the disk frame R2 (the disk's ω = 5 i + 4 k1, α = −20 j1), and ("Alternate
Solution") with P moving in the shaft frame R1 (ω = 5 i, α = 0; P's motion in R1 from the disk).

This example builds the three frames as a :class:`rigiddyn.FrameTree` and asks it for the
acceleration of P, which it returns term by term (origin, tangential α × r, centripetal
ω × (ω × r), relative, Coriolis 2 ω × v_rel).

**What it checks:** every term of both solutions against the slides' closed form, worked by hand
below; that the two solutions split the same total differently; and the total against the closed
form at every disk angle of a full turn.
"""

# %%
# The frames
# ----------
# R is the tree's root ``"world"``. The shaft R1 has a *simple angular velocity* in R (a constant
# rate about a fixed axis, ``FrameMotion.constant_rotation``), and so has the disk R2 in R1, about
# k1 through O. R2 has no simple angular velocity in R: its ω changes direction as the shaft turns.
import math

import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

W_SHAFT = 5.0  # [rad/s], about i (= i1)
W_DISK = 4.0  # [rad/s], about k1, relative to the shaft
R = 0.06  # [m], |OP|

tree = rd.FrameTree()
tree.add_frame("shaft", "world", rd.FrameMotion.constant_rotation([1.0, 0.0, 0.0], W_SHAFT))
tree.add_frame("disk", "shaft", rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], W_DISK))

theta = math.radians(30.0)  # the disk starts at angle 0, so the instant is t = θ / 4 s
t = theta / W_DISK
p_R2P_R2 = np.array([R, 0.0, 0.0])  # P on the disk's x2 axis, fixed in R2
zero = np.zeros(3)

w_R2 = tree.angular_velocity("disk", "world", "shaft", t)  # ω of R2 in R, R1 components
alpha_R2 = tree.angular_acceleration("disk", "world", "shaft", t)
print("omega (R2 in R) =", w_R2, "rad/s      (slides: 5 i1 + 4 k1)")
print("alpha (R2 in R) =", alpha_R2, "rad/s^2   (slides: -20 j1)")

# %%
# Solution 1: P fixed in the disk frame R2
# -----------------------------------------
# The acceleration of P seen from R, with the moving frame R2 (P at rest in it), components in R1.
TERMS = ("origin", "tangential", "centripetal", "relative", "coriolis")
LABELS = ("origin $a_O$", r"$\alpha \times r$", r"$\omega \times (\omega \times r)$",
          r"relative $a_{rel}$", r"Coriolis $2\omega \times v_{rel}$", "total")


def terms_of(a):
    """The named terms and the total of a PointAcceleration, each (3,) [m/s^2]."""
    return {name: getattr(a, name) for name in (*TERMS, "total")}


first = terms_of(tree.point_acceleration("disk", p_R2P_R2, zero, zero, "world", "shaft", t))

# %%
# Solution 2 ("Alternate Solution"): P moving in the shaft frame R1
# ------------------------------------------------------------------
# Now the moving frame is R1. P's position, velocity and acceleration *seen from R1* come from the
# same tree (the disk turning in the shaft), and feed the point-acceleration query on R1.
r_OP_R1 = tree.point_position("disk", p_R2P_R2, "shaft", "shaft", t)
v_rel = tree.point_velocity("disk", p_R2P_R2, zero, "shaft", "shaft", t).total
a_rel = tree.point_acceleration("disk", p_R2P_R2, zero, zero, "shaft", "shaft", t).total
second = terms_of(tree.point_acceleration("shaft", r_OP_R1, v_rel, a_rel, "world", "shaft", t))

# %%
# The slides' closed form, term by term
# -------------------------------------
# Worked by hand from ω, α and r_OP = r cos θ i1 + r sin θ j1 (R1 components).
c, s = math.cos(theta), math.sin(theta)
answer = np.array([-16 * R * c, -41 * R * s, 40 * R * c])
closed_first = {  # ω = (5, 0, 4), α = (0, -20, 0); P fixed in R2, O fixed in R
    "origin": zero, "relative": zero, "coriolis": zero,
    "tangential": np.array([0.0, 0.0, 20 * R * c]),  # -20 j1 × r (c i1 + s j1)
    "centripetal": np.array([-16 * R * c, -41 * R * s, 20 * R * c]),
    "total": answer,
}
closed_second = {  # ω = (5, 0, 0), α = 0; in R1, P turns at 4 rad/s about k1 on a circle of radius r
    "origin": zero, "tangential": zero,
    "centripetal": np.array([0.0, -25 * R * s, 0.0]),  # 5 i1 × (5 i1 × r)
    "relative": np.array([-16 * R * c, -16 * R * s, 0.0]),  # -4^2 r_OP
    "coriolis": np.array([0.0, 0.0, 40 * R * c]),  # 2 (5 i1) × (4 k1 × r_OP)
    "total": answer,
}

def row(v):
    return "[" + " ".join(f"{x:+.5f}" for x in v) + "]"


for title, got, want in (("Solution 1 (P fixed in R2)", first, closed_first),
                         ("Solution 2 (P moving in R1)", second, closed_second)):
    print(f"{title}, R1 components [m/s^2]\n  {'term':<13}{'FrameTree':<30}closed form")
    for name in (*TERMS, "total"):
        print(f"  {name:<13}{row(got[name]):<30}{row(want[name])}")

# The tree composes rotations exp(hat(rate t axis)) and cross products: each term is a few tens of
# floating-point operations on numbers of size |a| <= 41 r, with the angles 5 t, 4 t < 1 rad,
# so it carries a rounding error below 64 eps |a| (Higham's gamma_n with n = 64).
bound = 64 * np.finfo(float).eps * 41 * R
for got, want in ((first, closed_first), (second, closed_second)):
    for name in want:
        assert np.max(np.abs(got[name] - want[name])) <= bound, (name, got[name], want[name])

# %%
# The terms as bars
# -----------------
# Both solutions reach the same total, but split it differently: with R2 as the moving frame the
# acceleration is all tangential and centripetal; with R1 it takes a relative and a Coriolis term,
# and no tangential term (the shaft turns at a constant rate).
fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharey=True, layout="constrained")
width = 0.25
x = np.arange(len(LABELS))
for ax, terms, title in ((axes[0], first, "Solution 1: P fixed in the disk R2"),
                         (axes[1], second, "Solution 2: P moving in the shaft R1")):
    values = np.array([terms[name] for name in (*TERMS, "total")])  # (6, 3)
    for k, (component, colour) in enumerate(zip(("$i_1$", "$j_1$", "$k_1$"), ("C0", "C1", "C2"))):
        ax.bar(x + (k - 1) * width, values[:, k], width, label=component, color=colour)
    ax.axhline(0.0, color="black", linewidth=0.6)
    ax.set_xticks(x, LABELS, rotation=30, ha="right")
    ax.set_title(title)
    ax.grid(axis="y", alpha=0.3)
axes[0].set_ylabel("acceleration of P in R [m/s$^2$]")
axes[1].legend(title="component along")
fig.suptitle(rf"Craig's shaft and disk: $r$ = {R} m, $\theta$ = 30°")
plt.show()

# %%
# A full turn of the disk
# -----------------------
# The closed form holds at every angle θ = 4 t. Over one turn of the disk (π/2 s), the tree's total
# acceleration of P in R (R1 components) against the slides' formula.
thetas = np.linspace(0.0, 2 * np.pi, 121)
totals = np.array([
    tree.point_acceleration("disk", p_R2P_R2, zero, zero, "world", "shaft", th / W_DISK).total
    for th in thetas
])
closed = np.stack([-16 * R * np.cos(thetas), -41 * R * np.sin(thetas), 40 * R * np.cos(thetas)], axis=1)

# As above, but the angles now reach 5 t = 5π/2 rad (shaft) and 4 t = 2π rad (disk): rounding an
# angle φ costs eps φ, which moves the result by at most |a| eps φ; so the bound grows by a factor
# 1 + 9 t_max < 16.
assert np.max(np.abs(totals - closed)) <= 16 * bound

fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
for k, (name, colour) in enumerate(zip(("$i_1$", "$j_1$", "$k_1$"), ("C0", "C1", "C2"))):
    ax.plot(np.degrees(thetas), closed[:, k], color=colour, label=f"along {name}")
    ax.plot(np.degrees(thetas[::4]), totals[::4, k], "o", color=colour, markersize=4)
ax.set_xlabel(r"disk angle $\theta$ [deg]")
ax.set_ylabel("acceleration of P in R [m/s$^2$]")
ax.set_xticks(np.arange(0, 361, 60))
ax.set_title("acceleration of P over a turn of the disk: closed form (lines), FrameTree (dots)")
ax.legend(ncol=3, fontsize="small", loc="lower right")
ax.grid(alpha=0.3)
plt.show()
