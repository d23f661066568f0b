r"""
Planar kinetics: a spinning body under a thruster, and a pendulum released high
================================================================================

Plane kinetics (K. Craig, "Rigid Body Dynamics: Kinematics and Kinetics", "Supplement: Rigid Body
Plane Kinetics"): a body moving in a plane obeys ΣF = m a_G and ΣM_G = I_G α, or, pinned at a fixed
point O, ΣM_O = I_O α with :math:`I_O = I_G + m\,|OG|^2`. Two bodies in the vertical xy plane (gravity along −y):

1. a disk (:class:`rigiddyn.PlanarBody`) thrown up while spinning, pushed by a thruster fixed in the
   disk and firing through its centre: no moment about G, so it spins at a constant rate, and its centre
   follows a closed form (the thrust turns with the disk);
2. a 1 m rod pinned at one end (:class:`rigiddyn.PivotedPlanarBody`), released at rest at 150° from
   the bottom: the compound pendulum far from the small-angle regime, whose exact motion is
   :class:`rigiddyn.CompoundPendulumSolution` (Jacobi's elliptic functions).

**What it checks:** the disk's spin stays constant to round-off and its centre of mass follows the
closed form; the pendulum's angle follows the exact solution, returns to its release angle after each
exact period 4 K(k)/ω0, and the pivot's reaction equals m a_G − m g computed from the exact motion;
each within RK4's error, estimated by running again at half the step (Richardson). And the plane
kinetics equations themselves (:func:`rigiddyn.forward_dynamics`, a force off the centre of mass) to
round-off.
"""

# %%
# The equations of plane kinetics
# -------------------------------
# A force F at a point r from G and a couple τ: a_G = F/m + g and α = ((r × F)_z + τ)/I_G.
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
G = np.array([0.0, -9.81])  # [m/s^2], in the plane
disk = rd.PlanarBody(mass=0.5, inertia_zz=0.5 * 0.5 * 0.1**2)  # a 0.1 m disk: I_G = m r^2 / 2 [kg m^2]
state = rd.PlanarBodyState(p_W=[0.0, 0.0], theta=0.3, v_W=[0.5, 4.0], omega=8.0)
F, r, tau = np.array([2.0, -1.0]), np.array([0.05, 0.08]), 0.01  # [N], [m] from G, [N m]; all in W
a_W, alpha = rd.forward_dynamics(disk, state, force=F, point=r, torque=tau, frame="world", gravity=G)
alpha_hand = (r[0] * F[1] - r[1] * F[0] + tau) / disk.inertia_zz
print(f"a_G = {a_W} m/s^2 (F/m + g = {F / disk.mass + G}); alpha = {alpha:.6f} rad/s^2 (hand: {alpha_hand:.6f})")
# a division and a sum, or a cross product, a sum and a division: a few roundings of the largest term
assert np.allclose(a_W, F / disk.mass + G, rtol=0, atol=4 * EPS * np.max(np.abs(F / disk.mass + G)))
assert abs(alpha - alpha_hand) <= 8 * EPS * (np.max(np.abs(np.outer(r, F))) + abs(tau)) / disk.inertia_zz

# %%
# 1. A spinning disk pushed by a thruster fixed in it
# ---------------------------------------------------
# The thrust F_B = (10, 0) N is fixed in the disk (``frame="body"``) and passes through G, so the spin
# ω0 = 8 rad/s is constant and the thrust in W is F (cos θ, sin θ) with θ = θ0 + ω0 t. Integrating
# m dv/dt = F (cos θ, sin θ) + m g twice:
#
# .. math::
#
#    v(t) = v_0 + g t + \frac{F}{m \omega_0} (\sin\theta - \sin\theta_0,\ \cos\theta_0 - \cos\theta)
#
#    p(t) = p_0 + v_0 t + \tfrac12 g t^2 + \frac{F}{m \omega_0}
#           \Big(\frac{\cos\theta_0 - \cos\theta}{\omega_0} - t \sin\theta_0,\
#                \frac{\sin\theta_0 - \sin\theta}{\omega_0} + t \cos\theta_0\Big)
THRUST = 10.0  # [N]
thruster = rd.AppliedLoad(force=[THRUST, 0.0, 0.0], frame="body")
DT, STEPS = 1e-3, 1600
# .body(0): the disk's records (t, p_W, v_W, w_B (n, 3)) in the run of its one-body scene
run = rd.simulate(disk, state, dt=DT, steps=STEPS, method="rk4", loads=thruster, gravity=[*G, 0.0],
                  record_every=10).body(0)
fine = rd.simulate(disk, state, dt=DT / 2, steps=2 * STEPS, method="rk4", loads=thruster, gravity=[*G, 0.0],
                   record_every=20).body(0)


def closed_form(t):
    """(p (n, 2) [m], v (n, 2) [m/s]) of the disk's centre at times t [s]."""
    th0, w0, k = state.theta, state.omega, THRUST / (disk.mass * state.omega)
    th = th0 + w0 * t
    v = state.v_W + G * t[:, None] + k * np.stack([np.sin(th) - np.sin(th0), np.cos(th0) - np.cos(th)], axis=1)
    p = (state.p_W + state.v_W * t[:, None] + 0.5 * G * t[:, None] ** 2
         + k * np.stack([(np.cos(th0) - np.cos(th)) / w0 - t * np.sin(th0),
                         (np.sin(th0) - np.sin(th)) / w0 + t * np.cos(th0)], axis=1))
    return p, v


def error_bound(coarse, finer, scale, steps, order=4):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor 2
    covers the next term of the error expansion), plus round-off of about ten roundings a step accumulated over
    the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * steps * EPS * scale


t = run.t
p_exact, v_exact = closed_form(t)
p_run, p_fine = run.p_W[:, :2], fine.p_W[:, :2]
p_bound = error_bound(p_run, p_fine, np.max(np.abs(p_exact)), STEPS)
v_bound = error_bound(run.v_W[:, :2], fine.v_W[:, :2], np.max(np.abs(v_exact)), STEPS)
print(f"disk: max position error {np.max(np.abs(p_run - p_exact)):.2e} m (bound {p_bound:.2e}), "
      f"velocity {np.max(np.abs(run.v_W[:, :2] - v_exact)):.2e} m/s (bound {v_bound:.2e})")
assert np.max(np.abs(p_run - p_exact)) <= p_bound
assert np.max(np.abs(run.v_W[:, :2] - v_exact)) <= v_bound
# no moment about G: the spin is constant; RK4 integrates a constant rate exactly, so only round-off
assert np.max(np.abs(run.w_B[:, 2] - state.omega)) <= 10 * STEPS * EPS * state.omega

# %%
# 2. A compound pendulum released at 150°
# ---------------------------------------
# B turns about z (R_WB = Rz(θ)), the centre of mass 0.5 m from the pin along −y of B: θ = 0 hangs
# straight down. The step is 1/2000 of the exact period, so records fall on whole periods.
rod = rd.PivotedPlanarBody(1.0, 1.0 / 12.0, p_OC_B=[0.0, -0.5])  # 1 kg, 1 m rod: I_G = m L^2/12 [kg m^2]
release = rd.PivotedPlanarBodyState(theta=np.radians(150.0))
exact = rd.CompoundPendulumSolution(rod, G, release)
PERIODS, PER_PERIOD, EVERY = 2, 2000, 20
dt = exact.period / PER_PERIOD
swing = rd.simulate(rod, release, dt=dt, steps=PERIODS * PER_PERIOD, method="rk4", gravity=G, record_every=EVERY)
swing_fine = rd.simulate(rod, release, dt=dt / 2, steps=2 * PERIODS * PER_PERIOD, method="rk4", gravity=G,
                         record_every=2 * EVERY)
print(f"pendulum: period {exact.period:.6f} s = {exact.period / (2 * np.pi / exact.omega0):.4f} "
      f"x the small-angle period 2 pi / w0")


def angle(result):
    """theta [rad] from q_WB = Rz(theta)."""
    q = result.q_WB[:, 0]
    return 2.0 * np.arctan2(q[:, 2], q[:, 3])


def reaction(theta, omega):
    """The pivot's force on the rod [N] from Newton's law for G: m a_G - m g, a_G = alpha x r - omega^2 r, with
    alpha = (r x m g)_z / I_O (Euler's law about O)."""
    c, s = np.cos(theta), np.sin(theta)
    r = np.stack([c * rod.p_OC_B[0] - s * rod.p_OC_B[1], s * rod.p_OC_B[0] + c * rod.p_OC_B[1]], axis=1)
    alpha_O = rod.mass * (r[:, 0] * G[1] - r[:, 1] * G[0]) / rod.inertia_O_zz
    a_G = alpha_O[:, None] * np.stack([-r[:, 1], r[:, 0]], axis=1) - omega[:, None] ** 2 * r
    return rod.mass * (a_G - G)


ts = swing.t
theta, theta_fine = angle(swing), angle(swing_fine)
theta_exact, omega_exact = exact.at(ts)
theta_bound = error_bound(theta, theta_fine, np.pi, PERIODS * PER_PERIOD)
force, force_fine = swing.pivot_reaction_W[:, 0, :2], swing_fine.pivot_reaction_W[:, 0, :2]
force_exact = reaction(theta_exact, omega_exact)
force_bound = error_bound(force, force_fine, np.max(np.abs(force_exact)), PERIODS * PER_PERIOD)
print(f"max angle error {np.max(np.abs(theta - theta_exact)):.2e} rad (bound {theta_bound:.2e}); "
      f"max reaction error {np.max(np.abs(force - force_exact)):.2e} N (bound {force_bound:.2e})")
assert np.max(np.abs(theta - theta_exact)) <= theta_bound
assert np.max(np.abs(force - force_exact)) <= force_bound
# the period: back at the release angle after each exact period
whole = np.arange(PERIODS + 1) * (PER_PERIOD // EVERY)
assert np.max(np.abs(theta[whole] - release.theta)) <= theta_bound

# %%
# The two motions
# ---------------
fig, axes = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
axes[0].plot(p_run[:, 0], p_run[:, 1], label="RK4")
axes[0].plot(p_exact[::5, 0], p_exact[::5, 1], "o", markersize=3, markerfacecolor="none", label="closed form")
axes[0].set_xlabel("x [m]")
axes[0].set_ylabel("y (up) [m]")
axes[0].set_aspect("equal", adjustable="datalim")
axes[0].set_title("disk with a thruster fixed in it")
axes[0].legend()
axes[1].plot(ts, np.degrees(theta), label="RK4")
axes[1].plot(ts[::4], np.degrees(theta_exact[::4]), "o", markersize=3, markerfacecolor="none",
             label="CompoundPendulumSolution")
for k in range(PERIODS + 1):
    axes[1].axvline(k * exact.period, color="gray", linewidth=0.6, linestyle=":")
axes[1].set_xlabel("time t [s]")
axes[1].set_ylabel("rod angle θ [deg]")
axes[1].set_title("pendulum released at 150°")
axes[1].legend(fontsize=8)
axes[2].plot(ts, np.hypot(force[:, 0], force[:, 1]), label="RK4 (pivot_reaction_W)")
axes[2].plot(ts[::4], np.hypot(force_exact[::4, 0], force_exact[::4, 1]), "o", markersize=3, markerfacecolor="none",
             label="m a_G − m g (exact motion)")
axes[2].set_xlabel("time t [s]")
axes[2].set_ylabel("pivot reaction |R| [N]")
axes[2].set_title("the pin's force on the rod")
axes[2].legend(fontsize=8)
plt.show()
