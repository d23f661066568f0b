r"""
Detumbling a CubeSat with B-dot: the shipped ``cubesat_detumbling`` scene
=========================================================================

The shipped scene ``cubesat_detumbling`` is a 1U CubeSat (a 1.33 kg, 10 cm cube: I = m s²/6 = 2.2e-3 kg m²
about every axis) tumbling at 6.4 °/s on a circular polar orbit of radius 7000 km, with a magnetorquer (a
:class:`rigiddyn.MagneticDipole` m_B) in the Earth's tilted dipole field. A flight computer samples its
gyro every second and commands the B-dot law (Stickler & Alfriend, "Elementary magnetic attitude control
system"), m_B = −k dB_B/dt = −k (−ω_B × B_B), held until the next sample
(:class:`rigiddyn.Controller`, :class:`rigiddyn.control.BDot`): the scene file's ``[controller]`` table,
read by :func:`rigiddyn.load_scene` into ``run.controller`` (``python -m rigiddyn simulate cubesat_detumbling``
runs it too).

The torque m_B × B_B = −k (\|B\|² 1 − B Bᵀ) ω damps the rate normal to the field. For an isotropic body,
I ω̇_W = −k (\|B\|² 1 − B Bᵀ) ω_W. The field turns and changes along the orbit (2.25e-5 T at the equator,
4.5e-5 T over the poles); when the decay is slow against the orbit, ε = λ T_orb/(2π) ≪ 1, the rate follows
the orbit average (first-order averaging):

    ω̄_W(t) = exp(−(k/I) M̄ t) ω_W(0),   M̄ = ⟨\|B\|² 1 − B Bᵀ⟩ over the orbit.

**What it checks:** at each whole orbit the simulated rate is the averaged prediction within ε \|ω(0)\| (the
averaging theorem's O(ε) over the decay time); the rate falls below a sixth of its start in four orbits.
"""

# %%
# The scene, the field along the orbit, the gain
# ----------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd
from rigiddyn.control import BDot, dipole_field_W

scene, initial, options = rd.load_scene("cubesat_detumbling")
law = options.controller.law  # the file's [controller]: BDot on element 1, the MagneticDipole
dipole = scene.elements[law.element]
I = scene.bodies[0].inertia_com[0, 0]  # [kg m^2], isotropic
GM = scene.elements[0].gm  # [m^3/s^2]
r = np.linalg.norm(initial[0].p_W)  # [m]
n = np.sqrt(GM / r**3)  # orbit rate [rad/s]
T_orb = 2 * np.pi / n
# the orbit average of |B|^2 1 - B B^T: the field at p_W = r (cos u, 0, sin u), u uniform (a circular orbit)
u = np.linspace(0.0, 2 * np.pi, 4096, endpoint=False)
B_orbit = np.array([dipole_field_W(dipole, r * np.array([np.cos(a), 0.0, np.sin(a)])) for a in u])
M_bar = np.mean([(B @ B) * np.eye(3) - np.outer(B, B) for B in B_orbit], axis=0)
k = law.gain  # [A m^2 s/T], chosen for a mean decay time of two orbits, I / (k tr(M_bar)/3):
print(f"mean decay time {I / (k * np.trace(M_bar) / 3) / T_orb:.4f} orbits")
lam, V = np.linalg.eigh(k * M_bar / I)  # the averaged decay rates [1/s] and their axes in W
eps = lam.max() * T_orb / (2 * np.pi)
print(f"orbit period {T_orb:.1f} s; gain k = {k:.4g} A m^2 s/T; decay rates {lam} 1/s; eps = {eps:.3f}")

# %%
# Four orbits, the law sampled every second
# -----------------------------------------
assert isinstance(law, BDot) and options.controller.period == 1.0
run = rd.simulate(scene, initial, dt=options.dt, steps=options.steps, method=options.method,
                  record_every=options.record_every, controller=options.controller)
w_W = np.einsum("nij,nj->ni", rd.quat_to_matrix(run.q_WB[:, 0]), run.w_B[:, 0])  # rate in W [rad/s]
w_bar = (V @ (np.exp(-np.outer(run.t, lam)) * (V.T @ w_W[0])).T).T  # the averaged prediction

# %%
# The checks
# ----------
# At whole orbits the fluctuation of the field averages out; the averaged solution is then within O(eps) of
# the true one over the decay time (the averaging theorem), eps \|w(0)\| here.
orbits = [int(np.argmin(np.abs(run.t - j * T_orb))) for j in range(1, 5)]
misses = [float(np.linalg.norm(w_W[i] - w_bar[i])) for i in orbits]
print("rate at whole orbits [rad/s]:", [f"{np.linalg.norm(w_W[i]):.5f}" for i in orbits],
      "averaged prediction:", [f"{np.linalg.norm(w_bar[i]):.5f}" for i in orbits])
print(f"largest miss {max(misses):.2e} rad/s, bound eps |w0| = {eps * np.linalg.norm(w_W[0]):.2e} rad/s")
assert max(misses) <= eps * np.linalg.norm(w_W[0])
assert np.linalg.norm(w_W[-1]) < np.linalg.norm(w_W[0]) / 6
# the run's own global error estimate (its law runs in C++, so the runs at 2h and 4h sample it afresh): far below
# the bound the checks use, so they test the physics, not the integration
print(f"run's error estimate: rate {run.error.max()['angular_velocity']:.1e} rad/s, "
      f"attitude {run.error.max()['attitude']:.1e} rad")
assert run.error.max()["angular_velocity"] < 1e-3 * eps * np.linalg.norm(w_W[0])

# %%
# The detumbling
# --------------
fig, ax = plt.subplots(figsize=(9, 4.5), constrained_layout=True)
ax.plot(run.t / T_orb, np.degrees(np.linalg.norm(w_W, axis=1)), label="|ω|, B-dot held every 1 s")
ax.plot(run.t / T_orb, np.degrees(np.linalg.norm(w_bar, axis=1)), "--", label="orbit-averaged prediction")
ax.plot([run.t[i] / T_orb for i in orbits], [np.degrees(np.linalg.norm(w_W[i])) for i in orbits], "o",
        markerfacecolor="none", label="whole orbits")
ax.set_xlabel("orbits")
ax.set_ylabel("rate |ω| [deg/s]")
ax.legend()
fig.suptitle("B-dot detumbling of a 1U CubeSat on a polar orbit")
plt.show()
