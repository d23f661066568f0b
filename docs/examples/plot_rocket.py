r"""
A rocket: variable mass against Tsiolkovsky
============================================

A 200 kg rocket (a :class:`rigiddyn.Particle` with a :class:`rigiddyn.MassFlow`) burns 2 kg/s with
its exhaust leaving at 2500 m/s straight down, under gravity, for 60 s. Newton's law in momentum form
("Rigid body kinematics and dynamics" notes, eq. (4.36)), d(m v)/dt = f + ṁ (v + u_rel), gives
m dv/dt = m g + ṁ u_rel: the :class:`rigiddyn.Thrust` element is the force ṁ u_rel. Without gravity
the speed gained while the mass falls from m0 to m1 is Tsiolkovsky's :math:`\Delta v = |u_{rel}| \ln(m_0/m_1)`; with it,
the constant-rate burn has a closed form, :class:`rigiddyn.ConstantThrustSolution`:
v(t) = v0 + g t + u_rel ln(m(t)/m0), and p(t) in closed form too.

**What it checks:** the mass falls linearly to 80 kg (to round-off); the velocity and position follow
the closed form over the whole burn, within RK4's error (estimated by running again at half the step:
Richardson); the vertical speed at burn-out is Tsiolkovsky's Δv less the gravity loss g t; and the
same burn without gravity gains exactly Tsiolkovsky's Δv at every mass.
"""

# %%
# The rocket as a scene
# ---------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
M0, RATE, U_REL = 200.0, -2.0, np.array([0.0, 0.0, -2500.0])  # [kg], dm/dt [kg/s], exhaust [m/s] in W
G_W = np.array([0.0, 0.0, -9.81])  # [m/s^2]
V0 = np.array([50.0, 0.0, 0.0])  # [m/s]: launched with some horizontal speed


def rocket(gravity):
    """The scene: the particle losing mass at RATE, its thrust, and uniform gravity if asked."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(M0), name="rocket", mass_flow=rd.MassFlow(rate=RATE))
    if gravity:
        scene.add(rd.UniformGravity(g_W=G_W))
    scene.add(rd.Thrust(body=0, u_rel=U_REL, frame="world"))  # the exhaust's velocity relative to the rocket
    return scene


DT, STEPS, EVERY = 0.01, 6000, 20  # 60 s
start = [rd.ParticleState(v_W=V0)]
run = rd.simulate(rocket(True), start, dt=DT, steps=STEPS, method="rk4", record_every=EVERY)
fine = rd.simulate(rocket(True), start, dt=DT / 2, steps=2 * STEPS, method="rk4", record_every=2 * EVERY)
exact = rd.ConstantThrustSolution(M0, RATE, U_REL, g_W=G_W, v0_W=V0)
t = run.t
p_exact, v_exact, m_exact = exact.at(t)
print(run.elements, f"thrust {RATE * U_REL} N; {run.mass[-1, 0]:.1f} kg left after {t[-1]:.0f} s")

# %%
# The checks
# ----------


def error_bound(coarse, finer, scale, order=4):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor 2
    covers the next term of the error expansion), plus round-off of about ten roundings a step accumulated over
    the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * STEPS * EPS * scale


# the mass is linear in t: RK4 integrates it exactly, so only round-off remains
assert np.max(np.abs(run.mass[:, 0] - m_exact)) <= 10 * STEPS * EPS * M0
v_bound = error_bound(run.v_W[:, 0], fine.v_W[:, 0], np.max(np.abs(v_exact)))
p_bound = error_bound(run.p_W[:, 0], fine.p_W[:, 0], np.max(np.abs(p_exact)))
v_error = np.max(np.abs(run.v_W[:, 0] - v_exact))
p_error = np.max(np.abs(run.p_W[:, 0] - p_exact))
print(f"max velocity error {v_error:.2e} m/s (bound {v_bound:.2e}); max position error {p_error:.2e} m "
      f"(bound {p_bound:.2e})")
assert v_error <= v_bound and p_error <= p_bound
# burn-out: Tsiolkovsky's speed gain less the gravity loss
delta_v = exact.delta_v(run.mass[-1, 0])
print(f"v_z at {t[-1]:.0f} s: {run.v_W[-1, 0, 2]:.9f} m/s; Tsiolkovsky {delta_v:.9f} - g t {9.81 * t[-1]:.9f} "
      f"= {delta_v - 9.81 * t[-1]:.9f} m/s")
assert abs(run.v_W[-1, 0, 2] - (delta_v - 9.81 * t[-1])) <= v_bound

# %%
# Without gravity the speed gained is Tsiolkovsky's Δv at every mass along the burn.
free = rd.simulate(rocket(False), start, dt=DT, steps=STEPS, method="rk4", record_every=EVERY)
free_fine = rd.simulate(rocket(False), start, dt=DT / 2, steps=2 * STEPS, method="rk4", record_every=2 * EVERY)
gained = free.v_W[:, 0, 2] - V0[2]
tsiolkovsky = np.linalg.norm(U_REL) * np.log(M0 / free.mass[:, 0])  # |u_rel| ln(m0 / m) [m/s]
free_bound = error_bound(gained, free_fine.v_W[:, 0, 2] - V0[2], np.max(tsiolkovsky))
print(f"no gravity: max |v gained - Tsiolkovsky| {np.max(np.abs(gained - tsiolkovsky)):.2e} m/s "
      f"(bound {free_bound:.2e})")
assert np.max(np.abs(gained - tsiolkovsky)) <= free_bound

# %%
# RK4's error against the step
# ----------------------------
# The largest velocity error over the burn, at steps from 5 s down to the example's 0.01 s: it falls as
# dt⁴ (RK4's order) until it meets round-off, which grows with the number of steps (about
# :math:`\text{steps} \times \epsilon \times \max |v|`, dashed). At 0.01 s the run is already at round-off. The slopes are checked where both errors
# are far (100 times) above that round-off estimate, with the tolerance ``tradeoff`` uses to call two
# slopes equal (``rigiddyn.work_precision.ORDER_AGREEMENT``, relative).
from rigiddyn.work_precision import ORDER_AGREEMENT

counts = np.array([12, 24, 48, 96, 192, 384, 768, 1536, STEPS])
errors = np.empty(len(counts))
for i, count in enumerate(counts):
    result = rd.simulate(rocket(True), start, dt=60.0 / count, steps=int(count), method="rk4",
                         record_every=max(1, int(count) // 60))
    errors[i] = np.max(np.linalg.norm(result.v_W[:, 0] - exact.at(result.t)[1], axis=1))
round_off = counts * EPS * np.max(np.abs(v_exact))
slopes = np.log2(errors[:-1] / errors[1:]) * (counts[1:] == 2 * counts[:-1])  # 0 where the steps do not halve
asymptotic = (errors[1:] > 100 * round_off[1:]) & (counts[1:] == 2 * counts[:-1])
print("observed orders:", ", ".join(f"{p:.3f}" for p in slopes[asymptotic]))
assert asymptotic.sum() >= 3 and np.all(np.abs(slopes[asymptotic] - 4) <= ORDER_AGREEMENT * 4)

# %%
# The burn
# --------
fig, (ax_v, ax_e) = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
ax_v.plot(t, run.v_W[:, 0, 2], label="$v_z$, RK4 (with gravity)")
ax_v.plot(t[::5], v_exact[::5, 2], "o", markerfacecolor="none", label="ConstantThrustSolution")
ax_v.plot(t, gained, label="speed gained without gravity, RK4")
ax_v.plot(t[::5], tsiolkovsky[::5], "s", markerfacecolor="none", label=r"Tsiolkovsky $|u_{rel}| \ln(m_0/m)$")
ax_v.set_xlabel("time t [s]")
ax_v.set_ylabel("vertical speed [m/s]")
ax_v.legend(fontsize=8, loc="upper left")
ax_m = ax_v.twinx()
ax_m.plot(t, run.mass[:, 0], color="gray", linestyle=":", label="mass")
ax_m.set_ylabel("mass [kg] (dotted)")
dts = 60.0 / counts
ax_e.loglog(dts, errors, "o-", label="RK4, max over the burn")
ax_e.loglog(dts, errors[0] * (dts / dts[0]) ** 4, ":", color="gray", label="∝ dt⁴")
ax_e.loglog(dts, round_off, "--", color="gray", label="round-off estimate: steps × eps × max |v|")
ax_e.set_xlabel("step dt [s]")
ax_e.set_ylabel("max |v − v_exact| [m/s]")
ax_e.set_title("RK4's error: order 4 down to round-off")
ax_e.legend(fontsize=8)
fig.suptitle("200 kg rocket burning 2 kg/s at 2500 m/s")
plt.show()
