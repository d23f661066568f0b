r"""
Gravity-gradient libration: the shipped ``gravity_gradient`` scene
===================================================================

The shipped scene ``gravity_gradient`` (``rigiddyn.load_scene("gravity_gradient")``) is a rigid
satellite, I = (300, 400, 100) kg m², on a circular 7000 km orbit about a fixed Earth, under
point-mass gravity and the gravity-gradient torque (:class:`rigiddyn.GravityGradient`, MacCullagh's
second-order term). It starts in the local-vertical local-horizontal (LVLH) attitude, turned 2° in
pitch, turning with the orbit. The gradient torque pulls the long axis back to the vertical: the pitch
θ librates. Linearised (Hughes, *Spacecraft Attitude Dynamics*, ch. 8; Wie, *Space Vehicle Dynamics
and Control*) at ω_p = n √(3 (I_x − I_z)/I_y), n the orbit rate; in full, the pitch equation is a
pendulum in 2θ, φ'' = −ω_p² sin φ, whose exact solution is sin(φ/2) = k cd(ω_p t | k²), k = sin θ0
(Jacobi's elliptic functions, :func:`rigiddyn.jacobi_ellipj`; DLMF §22.19(i)), with the period
4 K(k²)/ω_p (:func:`rigiddyn.ellipk`).

**What it checks:** over the file's 6 hours, the pitch angle follows the pendulum's exact solution, the
total energy (kinetic, point-mass and gradient potentials) and the total angular momentum about the
Earth's centre stay constant; each within RK4's error, estimated by running again at half the step
(Richardson). The linear frequency is shown to be off by the pendulum's amplitude correction.
"""

# %%
# The scene and the pitch equation's constants
# --------------------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
scene, initial, options = rd.load_scene("gravity_gradient")
GM = scene.elements[0].gm  # [m^3/s^2]
Ix, Iy, Iz = np.diag(scene.bodies[0].inertia_com)  # [kg m^2]
radius = np.linalg.norm(initial[0].p_W)  # [m]
n = np.sqrt(GM / radius**3)  # orbit rate [rad/s]
w_p = n * np.sqrt(3.0 * (Ix - Iz) / Iy)  # linear pitch libration [rad/s]
theta0 = np.radians(2.0)  # the file's pitch offset from LVLH, released without pitch rate relative to LVLH
k2 = np.sin(theta0) ** 2  # the pendulum in phi = 2 theta: k = sin(phi0 / 2)
period = 4.0 * rd.ellipk(k2) / w_p
print(f"orbit period {2 * np.pi / n:.2f} s; linear libration {w_p:.10e} rad/s (period {2 * np.pi / w_p:.2f} s); "
      f"pendulum period {period:.2f} s, longer by {period * w_p / (2 * np.pi) - 1:.3e} "
      f"((2 theta0)^2/16 = {(2 * theta0) ** 2 / 16:.3e})")

# %%
# Six hours, and again at half the step
# -------------------------------------
run = rd.simulate(scene, initial, dt=options.dt, steps=options.steps, method=options.method,
                  record_every=options.record_every)
fine = rd.simulate(scene, initial, dt=options.dt / 2, steps=2 * options.steps, method=options.method,
                   record_every=2 * options.record_every)


def pitch(result):
    """The pitch angle [rad] of B relative to LVLH (x along track, z to the Earth, y minus the orbit normal)."""
    p, v = result.p_W[:, 0], result.v_W[:, 0]
    z_L = -p / np.linalg.norm(p, axis=1)[:, None]
    h = np.cross(p, v)
    y_L = -h / np.linalg.norm(h, axis=1)[:, None]
    R_WL = np.stack([np.cross(y_L, z_L), y_L, z_L], axis=2)  # columns: LVLH's axes in W
    R_LB = np.einsum("nji,njk->nik", R_WL, rd.quat_to_matrix(result.q_WB[:, 0]))
    return np.arctan2(R_LB[:, 0, 2], R_LB[:, 2, 2])  # R_LB = R_y(theta)


def pendulum(t):
    """The exact pitch [rad]: sin(phi/2) = k cd(w_p t | k^2), phi = 2 theta (released at rest at theta0)."""
    sn, cn, dn = rd.jacobi_ellipj(w_p * t, k2)
    return np.arcsin(np.sin(theta0) * cn / dn)


def error_bound(coarse, finer, scale, order=4):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor 2
    covers the next term of the error expansion), plus round-off of about ten roundings a step accumulated over
    the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * options.steps * EPS * scale


t = run.t
theta, theta_fine = pitch(run), pitch(fine)
theta_exact = pendulum(t)
theta_linear = theta0 * np.cos(w_p * t)

# %%
# The checks
# ----------
# The pitch against the pendulum's exact solution; the orbit perturbs it only through the body's
# gradient force on the orbit, I/(m r²) ≈ 1e-14 relative, far below RK4's error. An angle's round-off
# is relative to 1 rad (scale 1).
theta_bound = error_bound(theta, theta_fine, 1.0)
E0, H0 = run.total_energy[0], run.angular_momentum_W[0]
E_bound = error_bound(run.total_energy, fine.total_energy, abs(E0))
H_bound = error_bound(run.angular_momentum_W, fine.angular_momentum_W, np.linalg.norm(H0))
print(f"pitch vs pendulum: max error {np.max(np.abs(theta - theta_exact)):.2e} rad (bound {theta_bound:.2e}); "
      f"vs the linear solution: {np.max(np.abs(theta - theta_linear)):.2e} rad")
print(f"energy: max |E - E0| = {np.max(np.abs(run.total_energy - E0)):.2e} J of {abs(E0):.3e} (bound {E_bound:.2e})")
print(f"angular momentum: max |H - H0| = {np.max(np.abs(run.angular_momentum_W - H0)):.2e} kg m^2/s "
      f"(bound {H_bound:.2e})")
assert np.max(np.abs(theta - theta_exact)) <= theta_bound
assert np.max(np.abs(run.total_energy - E0)) <= E_bound
assert np.max(np.abs(run.angular_momentum_W - H0)) <= H_bound
# the pendulum's correction is what separates the run from the linear solution: the phase drifts by
# about 2 pi (t / T) x (2 theta0)^2 / 16, so the linear solution misses by more than the bound
assert np.max(np.abs(theta - theta_linear)) > 100 * theta_bound

# %%
# The libration
# -------------
fig, (ax_theta, ax_err) = plt.subplots(2, 1, figsize=(9, 6), sharex=True, constrained_layout=True)
hours = t / 3600.0
ax_theta.plot(hours, np.degrees(theta), label="RK4")
ax_theta.plot(hours[::6], np.degrees(theta_exact[::6]), "o", markersize=4, markerfacecolor="none",
              label="pendulum, exact")
ax_theta.set_ylabel("pitch θ from LVLH [deg]")
ax_theta.legend(loc="upper right")
ax_err.semilogy(hours[1:], np.abs(theta - theta_linear)[1:], label="RK4 − linear solution θ0 cos(ω_p t)")
ax_err.semilogy(hours[1:], np.abs(theta - theta_exact)[1:], label="RK4 − pendulum's exact solution")
ax_err.axhline(theta_bound, color="gray", linestyle="--", linewidth=1, label="RK4's error bound")
ax_err.set_xlabel("time t [h]")
ax_err.set_ylabel("|Δθ| [rad]")
ax_err.legend(fontsize=8)
fig.suptitle("Gravity-gradient pitch libration, 2° about LVLH")
plt.show()
