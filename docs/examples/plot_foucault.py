r"""
Foucault's pendulum: the swing plane turning with the Earth
============================================================

The shipped scene ``foucault`` (``rigiddyn.load_scene("foucault")``) is the Panthéon's pendulum of
1851 (Foucault): a 28 kg bob on a 67 m wire, a :class:`rigiddyn.PivotedBody`, released at rest 3 m
east of its lowest point. The scene is written in the local frame F of Paris (x east, y north, z up)
on the turning Earth, ``SceneFrame.earth(48.85°)``: the states are relative to F, and compiling adds
the centrifugal and Coriolis forces as named elements with their own work and power. The Coriolis
force turns the plane of swing clockwise, seen from above, at Ω sin φ (Landau & Lifshitz,
*Mechanics*, §39), Ω = 7.2921159e-5 rad/s the Earth's rate and φ the latitude: 11.3° in the hour this
example runs (the scene file's own run: 180 000 RK4 steps of 20 ms, a fraction of a second of C++).

**What it checks:** the swing line turns clockwise (north), at Ω sin φ within the spherical pendulum's
own (Airy) precession of its thin ellipse, (3/8)(a/L)² relative for the amplitude a = 3 m and the
length L = 67 m (the leading departure of the real motion from Ω sin φ; allowed twice over for the
higher-order terms and the fit); and the Coriolis force does no work: its power is zero to round-off.
"""

# %%
# The scene
# ---------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

EPS = np.finfo(float).eps
scene, initial, options = rd.load_scene("foucault")
print(scene.describe(options.method))
OMEGA = 7.2921159e-5  # the Earth's rate [rad/s], SceneFrame.earth's
latitude = np.radians(48.85)
bob = scene.bodies[0]
L = np.linalg.norm(bob.p_OC_B)  # [m]
amplitude = np.linalg.norm(rd.quat_rotate(initial[0].q_WB, bob.p_OC_B)[:2])  # the bob from below the pivot [m]
swing = 2 * np.pi * np.sqrt(bob.inertia_O[0, 0] / (bob.mass * 9.81 * L))  # small-amplitude period [s]
print(f"L = {L} m, amplitude {amplitude:.3f} m, swing period {swing:.2f} s; "
      f"Omega sin(latitude) = {OMEGA * np.sin(latitude):.6e} rad/s")

# %%
# One hour on the turning Earth
# -----------------------------
run = rd.simulate(scene, initial, dt=options.dt, steps=options.steps, method=options.method,
                  record_every=options.record_every)
print(f"{options.steps} steps of {options.dt} s in {run.elapsed_seconds:.2f} s; elements {run.elements}")
xy = run.p_W[:, 0, :2] - bob.p_WO[:2]  # the bob seen from above, from below the pivot [m]

# %%
# The swing line's azimuth, one swing at a time: the principal direction of the bob's track over each
# swing period (the line through the point below the pivot), unwrapped modulo π.
per_window = int(round(swing / (options.dt * options.record_every)))
windows = len(xy) // per_window
azimuth, t_mid = np.empty(windows), np.empty(windows)
for i in range(windows):
    x, y = xy[i * per_window:(i + 1) * per_window].T
    azimuth[i] = 0.5 * np.arctan2(2 * np.sum(x * y), np.sum(x * x) - np.sum(y * y))
    t_mid[i] = run.t[i * per_window:(i + 1) * per_window].mean()
azimuth = np.unwrap(2 * azimuth) / 2
rate, offset = np.polyfit(t_mid, azimuth, 1)  # [rad/s], [rad]
expected = -OMEGA * np.sin(latitude)  # clockwise seen from above: the azimuth (from east, towards north) decreases
airy = 3.0 / 8.0 * (amplitude / L) ** 2
print(f"swing line turns at {rate:.6e} rad/s ({np.degrees(rate * run.t[-1]):.3f} deg in the hour); "
      f"-Omega sin(latitude) = {expected:.6e}: relative {rate / expected - 1:+.2e}, Airy (3/8)(a/L)^2 = {airy:.2e}")

# %%
# The checks
# ----------
assert rate < 0  # clockwise in the northern hemisphere
assert abs(rate / expected - 1.0) <= 2.0 * airy
# the Coriolis force -2 m Omega x v is normal to v: its power is a sum of products that cancel exactly in exact
# arithmetic; in floating point, a few roundings of the terms' size, 2 |Omega| (m |v|^2 + w.I w) = 4 |Omega| T
coriolis = run.elements.index("CoriolisForce")
power_bound = 8 * EPS * 4 * OMEGA * np.max(run.kinetic_energy)
print(f"Coriolis power at most {np.max(np.abs(run.power[:, coriolis])):.1e} W (round-off bound {power_bound:.1e} W)")
assert np.max(np.abs(run.power[:, coriolis])) <= power_bound

# %%
# The plane of swing, turning
# ---------------------------
fig, (ax_top, ax_az) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
first, last = slice(0, 2 * per_window), slice(len(xy) - 2 * per_window, len(xy))
ax_top.plot(xy[first, 0], xy[first, 1], label="first two swings")
ax_top.plot(xy[last, 0], xy[last, 1], label="two swings an hour later")
ax_top.set_aspect("equal", adjustable="datalim")
ax_top.set_xlabel("east x [m]")
ax_top.set_ylabel("north y [m]")
ax_top.set_title("the bob seen from above")
ax_top.legend()
ax_az.plot(t_mid / 60, np.degrees(azimuth), "o", markersize=3, label="swing line, one swing period each")
ax_az.plot(t_mid / 60, np.degrees(expected * t_mid + offset), label=r"$-\Omega \sin\varphi\ t$")
ax_az.set_xlabel("time t [min]")
ax_az.set_ylabel("azimuth of the swing line from east [deg]")
ax_az.set_title("clockwise at Ω sin(latitude)")
ax_az.legend()
plt.show()
