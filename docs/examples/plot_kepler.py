r"""
A Kepler orbit: the shipped ``kepler`` scene and its invariants
================================================================

The shipped scene ``kepler`` (``rigiddyn.load_scene("kepler")``) is a 1000 kg satellite about a
fixed Earth (:class:`rigiddyn.PointMassGravity`, GM = 398600.4418 km³/s², the file written in km and
km/s), started at perigee of an a = 7000 km, e = 0.1 orbit. The two-body problem's closed form
(Curtis, *Orbital Mechanics for Engineering Students*: vis-viva and Kepler's third law) gives what
the motion must keep: the energy −m GM/(2a), the angular momentum m r × v, the eccentricity vector
((v² − GM/r) r − (r·v) v)/GM, and the period T = 2π √(a³/GM).

**What it checks:** over the file's 10 orbits (RK4 at dt = T/600), the energy, the angular momentum
and the eccentricity vector stay at their initial values, and the satellite is back at perigee after
each period T from Kepler's third law; each within RK4's error, estimated by running again at half
the step (Richardson).
"""

# %%
# The scene and its closed form
# -----------------------------
# a and e follow from the initial state by vis-viva, T from Kepler's third law.
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
scene, initial, options = rd.load_scene("kepler")
print(scene.describe(options.method))
GM = scene.elements[0].gm  # [m^3/s^2]
m = scene.bodies[0].mass  # [kg]
r0, v0 = np.asarray(initial[0].p_W), np.asarray(initial[0].v_W)  # [m], [m/s]
a = 1.0 / (2.0 / np.linalg.norm(r0) - v0 @ v0 / GM)  # vis-viva [m]
T = 2.0 * np.pi * np.sqrt(a**3 / GM)  # Kepler's third law [s]
energy = -m * GM / (2.0 * a)  # [J]
L0 = m * np.cross(r0, v0)  # [kg m^2/s]


def eccentricity(r, v):
    """The eccentricity vector ((v^2 - GM/r) r - (r . v) v) / GM, per row of r [m], v [m/s]."""
    rn = np.linalg.norm(r, axis=1)
    return (((v * v).sum(1) - GM / rn)[:, None] * r - (r * v).sum(1)[:, None] * v) / GM


e0 = eccentricity(r0[None], v0[None])[0]
print(f"a = {a / 1e3:.6f} km, e = {np.linalg.norm(e0):.12f}, T = {T:.9f} s, E = {energy:.10e} J")
print(f"the file's run: {options.method}, dt = {options.dt} s (T/{T / options.dt:.9f}), {options.steps} steps")

# %%
# Ten orbits, and again at half the step
# --------------------------------------
run = rd.simulate(scene, initial, dt=options.dt, steps=options.steps, method=options.method,
                  record_every=options.record_every)
fine = rd.simulate(scene, initial, dt=options.dt / 2, steps=2 * options.steps, method=options.method,
                   record_every=2 * options.record_every)
r, v = run.p_W[:, 0], run.v_W[:, 0]


def error_bound(coarse, finer, scale, order=4):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor 2
    covers the next term of the error expansion), plus round-off of about ten roundings a step accumulated over
    the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * options.steps * EPS * scale


# %%
# The checks
# ----------
E_bound = error_bound(run.total_energy, fine.total_energy, abs(energy))
L_bound = error_bound(run.angular_momentum_W, fine.angular_momentum_W, np.linalg.norm(L0))
e_vec, e_fine = eccentricity(r, v), eccentricity(fine.p_W[:, 0], fine.v_W[:, 0])
e_bound = error_bound(e_vec, e_fine, 1.0)
print(f"energy: max |E - E0| / |E0| = {np.max(np.abs(run.total_energy - energy)) / abs(energy):.2e} "
      f"(bound {E_bound / abs(energy):.2e})")
print(f"angular momentum: max |L - L0| / |L0| = {np.max(np.abs(run.angular_momentum_W - L0)) / np.linalg.norm(L0):.2e}"
      f" (bound {L_bound / np.linalg.norm(L0):.2e})")
print(f"eccentricity vector: max |e - e0| = {np.max(np.abs(e_vec - e0)):.2e} (bound {e_bound:.2e})")
assert np.max(np.abs(run.total_energy - energy)) <= E_bound
assert np.max(np.abs(run.angular_momentum_W - L0)) <= L_bound
assert np.max(np.abs(e_vec - e0)) <= e_bound
# the period: at t = k T (a record, since dt = T/600 to the 16 digits the file prints) back at perigee r0
whole = np.flatnonzero(np.isclose(run.t % T, 0.0, atol=1e-6 * T) | np.isclose(run.t % T, T, atol=1e-6 * T))
assert len(whole) == 11 and np.allclose(run.t[whole] / T, np.arange(11), rtol=0, atol=1e-12)
p_bound = error_bound(r[whole], fine.p_W[whole, 0], np.linalg.norm(r0))
miss = np.max(np.linalg.norm(r[whole] - r0, axis=1))
print(f"back at perigee after each T: miss at most {miss:.2e} m (bound {p_bound:.2e}), i.e. a period error of "
      f"{miss / np.linalg.norm(v0) / T:.1e} relative")
assert np.max(np.abs(r[whole] - r0)) <= p_bound

# %%
# The orbit and its invariants
# ----------------------------
fig, (ax_orbit, ax_inv) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
ax_orbit.plot(r[:, 0] / 1e3, r[:, 1] / 1e3, label="RK4, 10 orbits")
ax_orbit.plot(r[whole, 0] / 1e3, r[whole, 1] / 1e3, "o", markerfacecolor="none", label="at t = k T")
ax_orbit.plot(0.0, 0.0, "*", markersize=12, color="C2", label="Earth (fixed)")
ax_orbit.set_aspect("equal")
ax_orbit.set_xlabel("x [km]")
ax_orbit.set_ylabel("y [km]")
ax_orbit.legend(fontsize=8, loc="upper right")
for result, label in ((run, "dt = T/600"), (fine, "dt = T/1200")):
    ax_inv.semilogy(result.t[1:] / T, np.abs(result.total_energy[1:] / energy - 1.0), label=f"energy, {label}")
    L_error = np.linalg.norm(result.angular_momentum_W[1:] - L0, axis=1) / np.linalg.norm(L0)
    ax_inv.semilogy(result.t[1:] / T, L_error, "--", label=f"angular momentum, {label}")
ax_inv.set_xlabel("time t / T (orbits)")
ax_inv.set_ylabel("relative error (dimensionless)")
ax_inv.set_title("RK4's drift of the invariants, at two steps")
ax_inv.legend(fontsize=8)
plt.show()
