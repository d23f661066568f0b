r"""
The double pendulum as a tree in a scene: normal modes against the closed form, chaos with a closed balance
===========================================================================================================

Two uniform rods, 1 m and 1 kg each, hinged end to end about parallel horizontal axes: a kinematic tree of two
revolute joints (:class:`rigiddyn.Tree`), added link by link to a scene (:meth:`rigiddyn.Scene.add_tree`) whose
:class:`rigiddyn.UniformGravity` loads each link at its centre of mass. The run integrates the joint angles by the
articulated-body algorithm (Featherstone, *Rigid Body Dynamics Algorithms*, Table 7.1) and records them in
``result.joint_q``, and each link's motion as a body's.

Near the hanging equilibrium the motion is linear, M q̈ + K (q − q_eq) = 0, with M the joint-space inertia there
(:func:`rigiddyn.crba`) and K the Hessian of the potential, which for two rods of mass m and length l is

.. math::

   K = m g l \begin{pmatrix} 2 & 1/2 \\ 1/2 & 1/2 \end{pmatrix} :

two normal modes, ω² the roots of det(K − ω² M) = 0 (Goldstein, *Classical Mechanics*, §6.2). Released far from
it, the pendulum is chaotic, yet the work-energy balance of every run still closes to the method's error.

**What it checks:** started along the slow mode at 1 mrad, the joint angles stay on that mode and follow
A cos(ω₁ t) to within the linearisation's error (of relative size A² = 1e-6) and RK4's; released far from rest,
the energy balance closes and the run's own error estimate, reliable on every record at h = 0.5 ms, agrees with
its difference from a run at half the step.
"""

# %%
# The tree, the scene, and the closed-form modes
# ----------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

m, l, g = 1.0, 1.0, 9.81
rod = rd.SpatialInertia(m, [l / 2, 0.0, 0.0], np.diag([1e-4, m * l**2 / 12, m * l**2 / 12]))  # along its x
tree = rd.Tree()
tree.add_link("upper", -1, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod)  # hinged at W's origin about y
tree.add_link("lower", 0, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod, rd.Transform(translation=[l, 0.0, 0.0]))
scene = rd.Scene(elements=[rd.UniformGravity(g_W=[0.0, 0.0, -g])])
scene.add_tree(tree, "pendulum")
print(scene.describe("rk4"))

q_eq = np.array([np.pi / 2, 0.0])  # Ry(pi/2) turns the rods' x axis down, along -z
M = rd.crba(tree, q_eq)
K = m * g * l * np.array([[2.0, 0.5], [0.5, 0.5]])
w2, modes = np.linalg.eig(np.linalg.solve(M, K))
order = np.argsort(w2)
omega, modes = np.sqrt(w2[order]), modes[:, order]
print(f"normal modes: omega = {omega[0]:.6f} and {omega[1]:.6f} rad/s; slow mode shape {modes[:, 0] / modes[0, 0]}")

# %%
# Along the slow mode
# -------------------
A = 1e-3  # [rad] of the upper joint
shape = modes[:, 0] / modes[0, 0]
period = 2 * np.pi / omega[0]
dt = period / 400
small = rd.simulate(scene, tree.joint_states(q_eq + A * shape), dt, steps=1200, method="rk4", record_every=4)
expected = q_eq + A * np.outer(np.cos(omega[0] * small.t), shape)
deviation = np.max(np.abs(small.joint_q - expected))
print(f"largest deviation from A cos(omega_1 t) over 3 periods: {deviation:.3e} rad ({deviation / A:.2e} of A)")
# the potential and M(q) are even about the hanging equilibrium, so the linearisation leaves terms of relative size
# A² (a frequency shift ~A² omega: a phase error ~A² omega t ~ 2e-5 over three periods), and RK4 at 400 steps a
# period (omega dt = 0.016) a phase error of ~(omega dt)^4 omega t / 120 ~ 1e-8: both within 1e-4 A
assert deviation < 1e-4 * A

fig, ax = plt.subplots(figsize=(7, 3))
ax.plot(small.t, (small.joint_q[:, 0] - q_eq[0]) / A, label="upper joint / A")
ax.plot(small.t, small.joint_q[:, 1] / A, label="lower joint / A")
ax.plot(small.t, np.cos(omega[0] * small.t) * shape[1], "k:", label="closed form (lower)")
ax.set_xlabel("t [s]")
ax.legend(loc="upper right")
ax.set_title("The slow normal mode")
fig.tight_layout()

# %%
# Released far from rest: chaos, a balance that closes, an estimate that knows when it holds
# ------------------------------------------------------------------------------------------
# Released at rest with the upper rod 0.5 rad below the horizontal and the lower one in line with it, the pendulum
# tumbles chaotically. The work of gravity is the potential's change, so the kinetic energy's change matches the
# recorded work to RK4's error. Each run carries its own global error estimate (Richardson extrapolation at h, 2h,
# 4h with a check of the observed order): at h = 1 ms the check fails on most records (observed orders between 4 and 5:
# the error's h⁵ term still counts against the h⁴ one, so the extrapolation is not yet trustworthy, and the run
# says so); at h = 0.5 ms every record passes, and the estimate agrees with the difference from a run at half the
# step.
start = tree.joint_states([0.5, 0.0])
coarse = rd.simulate(scene, start, 1e-3, duration=3.0, method="rk4", record_every=10)
big = rd.simulate(scene, start, 5e-4, duration=3.0, method="rk4", record_every=20)
half = rd.simulate(scene, start, 2.5e-4, duration=3.0, method="rk4", record_every=40)
print(f"h = 1 ms: {coarse.error.reliable.mean():.0%} of the records' estimates reliable; "
      f"median observed order {np.nanmedian(coarse.error.observed_order):.2f}")
print(f"h = 0.5 ms: {big.error.reliable.mean():.0%} reliable; median observed order "
      f"{np.nanmedian(big.error.observed_order):.2f}")
print(f"energy balance: {big.balance.verdict['energy']}; largest |T - T0 - work| = {big.balance.max()['energy']:.3e} J")
assert big.balance.verdict["energy"] == "closed"
difference = np.abs(big.p_W[:, 1] - half.p_W[:, 1]).max(axis=1)  # the lower rod's centre of mass [m]
estimate = big.error.position[:, 1]
print(f"at t = 3 s: difference from the half-step run {difference[-1]:.3e} m, estimate {estimate[-1]:.3e} m")
# the half-step run's own error is 1/16 of this one's (order 4), so the difference is 15/16 of this run's error; the
# estimate's contract on reliable records is an effectivity in [0.5, 2] (docs/accuracy.md), so estimate/difference
# lies in [0.5 × 15/16, 2 × 16/15]
assert big.error.reliable.all() and 0.46 <= estimate[-1] / difference[-1] <= 2.14

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.2))
ax1.plot(big.joint_q[:, 0], big.joint_q[:, 1], lw=0.6)
ax1.set_xlabel("upper joint [rad]")
ax1.set_ylabel("lower joint [rad]")
ax1.set_title("Joint angles, 3 s")
ax2.semilogy(big.t[1:], difference[1:], label="|run - half-step run|")
ax2.semilogy(big.t[1:], estimate[1:], "--", label="the run's error estimate")
ax2.set_xlabel("t [s]")
ax2.set_ylabel("lower rod's centre of mass [m]")
ax2.legend()
fig.tight_layout()
plt.show()
