r"""
Work–energy and impulse–momentum on a forced body
==================================================

A 4 kg box tumbling through the air under gravity while a schedule of forces (through its centre of
mass) and couples acts on it: a push for the first second, another until 2.5 s, then nothing. The
kinetics principles of K. Craig's "Rigid Body Dynamics: Kinematics and Kinetics" slides hold over
any interval [t1, t2]:

- **work–energy**: T1 + U12 = T2, U12 the work of every load and of gravity (:func:`rigiddyn.simulate`
  records each element's, ``work`` (n, ne): gravity's, then the loads', integrated with the motion by the
  same method; U12 is their sum);
- **impulse–momentum**: the linear impulse of the forces equals the change of linear momentum,
  ∫ F dt = m v(t2) − m v(t1), and the angular impulse of the moments about the centre of mass G
  equals the change of angular momentum about G, ∫ M_G dt = H_G(t2) − H_G(t1).

**What it checks:** the three balances along the whole run. The linear impulse–momentum balance holds
to round-off (RK4 integrates a piecewise-constant acceleration exactly, and ``simulate`` splits a step
at a load's switch time); the work–energy and angular balances within RK4's error, estimated by
running again at half the step (Richardson). Then an impulsive blow off the centre of mass
(:func:`rigiddyn.apply_impulse`) against the impulse–momentum equations, to round-off.
"""

# %%
# The body and its loads
# ----------------------
# The loads are given in W (``frame="world"``): each force acts through the centre of mass, each torque
# is a couple; gravity is uniform, (0, 0, −9.81) m/s².
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
box = rd.solid_box([0.2, 0.3, 0.5], mass=4.0)  # [m], [kg]
body = rd.RigidBody(box.mass, box.inertia_com)
start = rd.RigidBodyState(v_W=[1.0, 0.0, 2.0], w_B=[0.3, 1.0, -0.5])  # [m/s] in W, [rad/s] in B
G_W = np.array([0.0, 0.0, -9.81])  # [m/s^2]
loads = [rd.AppliedLoad(force=[10.0, 0.0, 30.0], torque=[0.0, 0.5, 0.2], frame="world", t_start=0.0, t_end=1.0),
         rd.AppliedLoad(force=[-5.0, 8.0, 0.0], torque=[0.3, -0.2, 0.0], frame="world", t_start=1.0, t_end=2.5)]
DT, STEPS = 2e-3, 1500  # 3 s
run = rd.simulate(body, start, dt=DT, steps=STEPS, method="rk4", loads=loads, gravity=G_W, record_every=10)
fine = rd.simulate(body, start, dt=DT / 2, steps=2 * STEPS, method="rk4", loads=loads, gravity=G_W, record_every=20)
t = run.t
U12, U12_fine = run.work.sum(axis=1), fine.work.sum(axis=1)  # [J]: gravity's work plus the loads'


def error_bound(coarse, finer, scale, order=4):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor 2
    covers the next term of the error expansion), plus round-off of about ten roundings a step accumulated over
    the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * STEPS * EPS * scale


# %%
# Work–energy: T1 + U12 = T2
# ---------------------------
# The residual T2 − T1 − U12 is zero for the exact motion; for RK4's, it is RK4's error.
residual = run.kinetic_energy - run.kinetic_energy[0] - U12
residual_fine = fine.kinetic_energy - fine.kinetic_energy[0] - U12_fine
energy_bound = error_bound(residual, residual_fine, scale=np.max(np.abs(run.kinetic_energy)))
print(f"T2 - T1 - U12: max {np.max(np.abs(residual)):.2e} J (bound {energy_bound:.2e} J) "
      f"over T up to {run.kinetic_energy.max():.1f} J")
assert np.max(np.abs(residual)) <= energy_bound

# %%
# Impulse–momentum
# ----------------
# The impulses in closed form: each load acts over the part of [0, t] inside its window.


def impulse(vector_of, t):
    """(n, 3): the integral over [0, t] of the piecewise-constant loads' vector_of(load), per time in t."""
    out = np.zeros((len(t), 3))
    for load in loads:
        active = np.clip(t, load.t_start, load.t_end) - load.t_start  # [s] of [0, t] inside the window
        out += active[:, None] * vector_of(load)[None, :]
    return out


linear_impulse = impulse(lambda load: load.force, t) + box.mass * G_W[None, :] * t[:, None]  # [N s]
angular_impulse = impulse(lambda load: load.torque, t)  # [N m s], about G (the forces pass through it)


def momenta(records):
    """Linear momentum m v_W [kg m/s] and angular momentum about G in W, H_G = R_WB I w_B [kg m^2/s], from the
    box's records (``result.body(0)``: q_WB (n, 4), v_W and w_B (n, 3))."""
    R_WB = rd.quat_to_matrix(records.q_WB)
    return box.mass * records.v_W, np.einsum("nij,jk,nk->ni", R_WB, box.inertia_com, records.w_B)


P, H = momenta(run.body(0))
P_fine, H_fine = momenta(fine.body(0))
linear_error = np.max(np.abs(P - P[0] - linear_impulse))
# round-off only: about ten roundings a step on the momentum, accumulated over the run
linear_bound = 10 * STEPS * EPS * np.max(np.abs(P))
angular_bound = error_bound(H - H[0] - angular_impulse, H_fine - H_fine[0] - angular_impulse, scale=np.max(np.abs(H)))
angular_error = np.max(np.abs(H - H[0] - angular_impulse))
print(f"m dv - linear impulse: max {linear_error:.2e} N s (round-off bound {linear_bound:.2e})")
print(f"dH_G - angular impulse: max {angular_error:.2e} N m s (bound {angular_bound:.2e})")
assert linear_error <= linear_bound
assert angular_error <= angular_bound

# %%
# The balances over time
# ----------------------
fig, (ax_e, ax_p, ax_h) = plt.subplots(3, 1, figsize=(8, 8), sharex=True, constrained_layout=True)
ax_e.plot(t, run.kinetic_energy - run.kinetic_energy[0], label="$T_2 - T_1$")
ax_e.plot(t[::8], U12[::8], "o", markerfacecolor="none", label="$U_{12}$ (recorded work)")
ax_e.set_ylabel("energy [J]")
ax_e.legend()
for i, axis in enumerate("xyz"):
    ax_p.plot(t, P[:, i] - P[0, i], color=f"C{i}", label=rf"$\Delta (m v)_{axis}$")
    ax_p.plot(t[::8], linear_impulse[::8, i], "o", color=f"C{i}", markerfacecolor="none")
    ax_h.plot(t, H[:, i] - H[0, i], color=f"C{i}", label=rf"$\Delta H_{{G,{axis}}}$")
    ax_h.plot(t[::8], angular_impulse[::8, i], "o", color=f"C{i}", markerfacecolor="none")
ax_p.set_ylabel("linear momentum change [N s]")
ax_p.legend(title="lines: RK4; circles: impulse", fontsize=8, ncol=3)
ax_h.set_ylabel("angular momentum change [N m s]")
ax_h.legend(title="lines: RK4; circles: angular impulse", fontsize=8, ncol=3)
ax_h.set_xlabel("time t [s]")
for ax in (ax_e, ax_p, ax_h):
    for load in loads:
        ax.axvline(load.t_end, color="gray", linewidth=0.6, linestyle=":")
fig.suptitle("Forced box: work–energy and impulse–momentum")
plt.show()

# %%
# An impulsive blow
# -----------------
# A blow J = (0, 2, 0) N s at the point r = (0.1, 0, 0.25) m from G (in W, the box at rest in its start
# attitude): the velocities jump by m Δv = J and I Δω = r × J (impulse–momentum over an instant).
J_W, r_W = np.array([0.0, 2.0, 0.0]), np.array([0.1, 0.0, 0.25])
after = rd.apply_impulse(body, start, J_W, point=r_W, frame="world")
dv = np.asarray(after.v_W) - np.asarray(start.v_W)
dH = box.inertia_com @ (np.asarray(after.w_B) - np.asarray(start.w_B))  # B = W at the start attitude
print(f"m dv = {box.mass * dv} N s; I dw = {dH} N m s; r x J = {np.cross(r_W, J_W)} N m s")
# m dv: a division, a sum, a difference and a product: a few roundings of the largest momentum involved
p_scale = max(np.max(np.abs(J_W)), box.mass * np.max(np.abs(after.v_W)))
assert np.allclose(box.mass * dv, J_W, rtol=0, atol=8 * EPS * p_scale)
# I dw: the solve with I and the product back lose up to cond(I) times a few roundings (Higham, ch. 7)
h_scale = max(np.max(np.abs(np.cross(r_W, J_W))), np.max(np.abs(box.inertia_com @ after.w_B)))
assert np.allclose(dH, np.cross(r_W, J_W), rtol=0, atol=8 * np.linalg.cond(box.inertia_com) * EPS * h_scale)
