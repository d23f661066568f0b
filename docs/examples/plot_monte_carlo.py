r"""
A small Monte Carlo: tumbling boxes from random attitudes
==========================================================

:func:`rigiddyn.monte_carlo` runs N samples of a body with dispersed inputs as one batch
in C++ and gives statistics and percentiles of any recorded quantity. Here: 1000 boxes spinning near
their intermediate axis (the Dzhanibekov flip), each from an attitude drawn uniformly on SO(3)
(``UniformRotation``) with its spin dispersed by 0.01 rad/s (``Normal``), for 4 s.

Two things are known in closed form. The motion in the body frame does not depend on the attitude, so
each sample's attitude is its random start times a rotation independent of it: uniform on SO(3) at
every instant (the uniform measure is invariant under rotations), and the world z-component of any
body axis is then uniform on [−1, 1]. And a torque-free body keeps its kinetic energy.

**What it checks:** at every record, the distribution of the long axis's world z-component over the
1000 samples is uniform on [−1, 1] within the Dvoretzky–Kiefer–Wolfowitz bound with Massart's
constant, :math:`P(\sup |F_N - F| > \varepsilon) \le 2 e^{-2 N \varepsilon^2}`, at a failure probability
of 1e-6 per record; and the percentiles of the kinetic energy stay at their initial values within RK4's
error, estimated by running the same samples again at half the step (Richardson).
"""

# %%
# The dispersed runs
# ------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd
from rigiddyn.dispersion import Normal, UniformRotation, monte_carlo

EPS = np.finfo(float).eps
box = rd.solid_box([0.1, 0.2, 0.4], mass=2.0)  # [m], [kg]
body = rd.RigidBody(box.mass, box.inertia_com)
spin = rd.RigidBodyState(w_B=[0.02, 5.0, 0.01])  # [rad/s] in B: about the intermediate axis y
N, DT, STEPS, EVERY = 1000, 1e-3, 4000, 50
dispersions = {"q_WB": UniformRotation(), "w_B": Normal(std=0.01)}
mc = monte_carlo(body, spin, N, seed=14, dispersions=dispersions, dt=DT, steps=STEPS, record_every=EVERY)
# the same samples (each draws from its own generator, a function of the seed and its index) at half the step
mc_fine = monte_carlo(body, spin, N, seed=14, dispersions=dispersions, dt=DT / 2, steps=2 * STEPS,
                      record_every=2 * EVERY)
print(mc)
t = mc.times


def long_axis_up(batch):
    """(N, n_records): the world z-component of the body's long axis z_B (dimensionless)."""
    q = np.asarray(batch.body(0).q_WB)  # the body's attitudes, (N, n_records, 4)
    return rd.quat_rotate(q.reshape(-1, 4), [0.0, 0.0, 1.0]).reshape(q.shape[:2] + (3,))[..., 2]


# %%
# The checks
# ----------
# Uniform on [−1, 1] at every record: the empirical CDF F_N against F(x) = (x + 1)/2.
ALPHA = 1e-6
eps_dkw = np.sqrt(np.log(2.0 / ALPHA) / (2.0 * N))  # 2 exp(-2 N eps^2) = ALPHA
z = np.sort(mc.values(long_axis_up), axis=0)  # (N, n_records), sorted over the samples
F = (z + 1.0) / 2.0
ranks = np.arange(1, N + 1)[:, None]
ks = np.max(np.maximum(ranks / N - F, F - (ranks - 1) / N), axis=0)  # sup |F_N - F| at each record
print(f"Kolmogorov-Smirnov distance to the uniform law: at most {ks.max():.3f} over {len(t)} records "
      f"(DKW-Massart bound {eps_dkw:.3f})")
assert np.all(ks <= eps_dkw)

# The kinetic energy's percentiles stay at their start, within RK4's error on each sample.
Q = (5, 50, 95)
energy = mc.percentiles("kinetic_energy", q=Q)  # (3, n_records) [J]
drift = mc.values("kinetic_energy") - mc.values("kinetic_energy")[:, :1]  # (N, n_records) [J]: RK4's error
drift_fine = mc_fine.values("kinetic_energy") - mc_fine.values("kinetic_energy")[:, :1]
# twice Richardson's estimate 2^4/(2^4 - 1) |coarse - finer| for the order-4 RK4 (the factor 2 covers the next term
# of the error expansion), plus round-off of about ten roundings a step accumulated over the run; a percentile
# moves by at most the largest change of any sample
bound = 2.0 * 16 / 15 * np.max(np.abs(drift - drift_fine)) + 10 * STEPS * EPS * np.max(energy)
print(f"kinetic energy percentiles {energy[:, 0]} J at t = 0; "
      f"largest change {np.max(np.abs(energy - energy[:, :1])):.1e} J (bound {bound:.1e} J)")
assert np.max(np.abs(energy - energy[:, :1])) <= bound

# %%
# Percentiles over time
# ---------------------
# The long axis's z-component: every percentile band stays where the uniform law puts it, while each
# sample tumbles. The body-frame spin ω_y flips sign once in these 4 s (the Dzhanibekov flip), each sample
# at its own time: the dispersed spins start at different distances from the separatrix.
fig, (ax_z, ax_w) = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
bands = (5, 25, 50, 75, 95)
up = mc.percentiles(long_axis_up, q=bands)
w_y = mc.percentiles(lambda batch: np.asarray(batch.body(0).w_B)[..., 1], q=bands)
for ax, values, label in ((ax_z, up, "long axis z_B, world z-component (dimensionless)"),
                          (ax_w, w_y, "spin ω_y in B [rad/s]")):
    ax.fill_between(t, values[0], values[-1], alpha=0.25, color="C0", label="5–95 %")
    ax.fill_between(t, values[1], values[-2], alpha=0.45, color="C0", label="25–75 %")
    ax.plot(t, values[2], color="C0", label="median")
    ax.set_xlabel("time t [s]")
    ax.set_ylabel(label)
for p in bands:
    ax_z.axhline(2 * p / 100 - 1, color="gray", linestyle="--", linewidth=0.8)
ax_z.set_title("uniform on [−1, 1] (dashed: its percentiles)")
ax_z.legend(loc="lower right", fontsize=8)
ax_w.set_title(f"{N} boxes, flips spreading in phase")
ax_w.legend(loc="lower right", fontsize=8)
plt.show()
