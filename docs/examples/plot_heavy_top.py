r"""
The heavy top: nutation and precession against Lagrange's closed form
=======================================================================

A symmetric top pinned at its tip O (a :class:`rigiddyn.PivotedBody`): 1 kg, its centre of mass C
0.1 m up the axis of symmetry, inertia about C diag(0.004, 0.004, 0.006) kg m², spinning at
100 rad/s about its axis, tilted 30° from the vertical and released without any precession rate.
Euler's law about the fixed point, M_O = dH_O/dt with the inertia about O (K. Craig, "Rigid Body
Dynamics: Kinematics and Kinetics" slides), moves it; gravity's moment about O makes the axis
*precess* about the vertical and *nutate* between two tilts. Lagrange's case (the inertia about O
symmetric about the line OC) has a closed form in Jacobi's elliptic functions (Goldstein, *Classical
Mechanics*, §5.7; Landau & Lifshitz, *Mechanics*, §35): :class:`rigiddyn.LagrangeTopSolution` gives
the nutation bounds θ_min, θ_max, the nutation period and the mean precession rate.

**What it checks:** the integrated axis (RK4) stays between the closed form's bounds, returns to the
release tilt θ_min after every nutation period and reaches θ_max half a period later, and its
precession angle follows the closed form and its mean rate; each within RK4's error, estimated by
running again at half the step (Richardson).
"""

# %%
# The top and its closed form
# ---------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

G_W = np.array([0.0, 0.0, -9.81])  # [m/s^2], W's z up
top = rd.PivotedBody(rd.RigidBody(1.0, [0.004, 0.004, 0.006]),  # mass [kg], I_C [kg m^2] in B
                     p_OC_B=[0.0, 0.0, 0.1])  # C relative to the tip O, in B [m]
start = rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1.0, 0.0, 0.0], 30.0, degrees=True),
                            w_B=[0.0, 0.0, 100.0])  # spin about the axis [rad/s], no precession
exact = rd.LagrangeTopSolution(top, G_W, start)

print(f"inertia about O: {np.diag(top.inertia_O)} kg m^2")
print(f"nutation between {np.degrees(exact.theta_min):.6f} and {np.degrees(exact.theta_max):.6f} deg, "
      f"period {exact.nutation_period:.6f} s; mean precession {exact.mean_precession_rate:.6f} rad/s")
# the fast top's estimates (Landau & Lifshitz §35): precession m g l / (I3 w3), nutation period 2 pi I1 / (I3 w3)
print(f"fast-top estimates: precession {1.0 * 9.81 * 0.1 / (0.006 * 100.0):.4f} rad/s, "
      f"nutation period {2 * np.pi * exact.I1 / (exact.I3 * 100.0):.4f} s")

# %%
# Integrating it
# --------------
# The step is chosen as 1/800 of the nutation period, so that records fall exactly at every quarter
# period (the checks below use the records at whole and half periods). A second run at half the step
# estimates RK4's error: for a method of order p, the error of the coarse run is about
# 2^p/(2^p − 1) times the difference of the two runs (Richardson).
PERIODS, PER_PERIOD, RECORDS_PER_PERIOD = 6, 800, 80
dt = exact.nutation_period / PER_PERIOD
steps = PERIODS * PER_PERIOD
every = PER_PERIOD // RECORDS_PER_PERIOD
run = rd.simulate(top, start, dt=dt, steps=steps, method="rk4", gravity=G_W, record_every=every)
fine = rd.simulate(top, start, dt=dt / 2, steps=2 * steps, method="rk4", gravity=G_W, record_every=2 * every)
t = run.t
assert np.allclose(t, fine.t, rtol=0, atol=1e-12)  # the same record times


def axis_angles(q_WB):
    """Nutation theta and precession phi [rad] of the axis e3 (Z-X-Z angles in the closed form's frame N)."""
    e3_W = rd.quat_rotate(q_WB, exact.e3_B)
    e3_N = rd.quat_rotate(rd.quat_inverse(exact.q_WN), e3_W)
    theta = np.arctan2(np.hypot(e3_N[:, 0], e3_N[:, 1]), e3_N[:, 2])
    phi = np.unwrap(np.arctan2(e3_N[:, 0], -e3_N[:, 1]))  # e3_N = (sin phi sin theta, -cos phi sin theta, cos theta)
    return theta, phi


theta, phi = axis_angles(run.q_WB[:, 0])
theta_fine, phi_fine = axis_angles(fine.q_WB[:, 0])
phi_exact, theta_exact, _ = exact.angles_at(t)


def error_bound(coarse, finer, order=4, scale=1.0):
    """Bound on the coarse run's error: twice Richardson's estimate 2^p/(2^p - 1) |coarse - finer| (the factor
    2 covers the next term of the error expansion, O(dt |w|) = 0.016 relative here), plus round-off of about
    ten roundings a step accumulated over the run, 10 steps eps |scale|."""
    richardson = 2**order / (2**order - 1) * np.max(np.abs(coarse - finer))
    return 2.0 * richardson + 10 * steps * np.finfo(float).eps * scale


theta_bound = error_bound(theta, theta_fine)
phi_bound = error_bound(phi, phi_fine, scale=np.max(np.abs(phi)))
print(f"RK4 at dt = {dt:.3e} s: max nutation error {np.max(np.abs(theta - theta_exact)):.2e} rad "
      f"(bound {theta_bound:.2e}); max precession error {np.max(np.abs(phi - phi_exact)):.2e} rad "
      f"(bound {phi_bound:.2e})")

# %%
# The checks
# ----------
# The integrated angles against the closed form at every record, within RK4's estimated error.
assert np.max(np.abs(theta - theta_exact)) <= theta_bound
assert np.max(np.abs(phi - phi_exact)) <= phi_bound
# the nutation bounds: the axis never leaves [theta_min, theta_max] by more than RK4's error
assert theta.min() >= exact.theta_min - theta_bound and theta.max() <= exact.theta_max + theta_bound
# the nutation period: back at the release tilt theta_min after each period, at theta_max half a period later
whole = np.arange(0, PERIODS + 1) * RECORDS_PER_PERIOD
half = whole[:-1] + RECORDS_PER_PERIOD // 2
assert np.max(np.abs(theta[whole] - exact.theta_min)) <= theta_bound
assert np.max(np.abs(theta[half] - exact.theta_max)) <= theta_bound
# the precession: after k periods the axis has turned k T times the mean rate
assert np.max(np.abs(phi[whole] - exact.mean_precession_rate * t[whole])) <= phi_bound

# %%
# The nutation angle over time
# ----------------------------
fig, (ax_theta, ax_phi) = plt.subplots(2, 1, figsize=(8, 6), sharex=True, constrained_layout=True)
ax_theta.plot(t, np.degrees(theta), label="RK4")
ax_theta.plot(t, np.degrees(theta_exact), "--", label="closed form (LagrangeTopSolution)")
for bound, name in ((exact.theta_min, r"$\theta_{min}$"), (exact.theta_max, r"$\theta_{max}$")):
    ax_theta.axhline(np.degrees(bound), color="gray", linewidth=0.8)
    ax_theta.text(t[-1], np.degrees(bound), name, ha="right", va="bottom")
ax_theta.set_ylabel("nutation θ [deg]")
ax_theta.legend(loc="center right")
ax_phi.plot(t, phi, label="RK4")
ax_phi.plot(t, exact.mean_precession_rate * t, "--", label="mean precession rate × t")
ax_phi.set_xlabel("time t [s]")
ax_phi.set_ylabel("precession φ [rad]")
ax_phi.legend()
fig.suptitle("Heavy top, tip pinned: 100 rad/s, released at 30°")
plt.show()
