r"""
The Dzhanibekov flip of a T-handle, against the exact solution
==============================================================

A T-handle spun about its *intermediate* principal axis, with a small perturbation about the
smallest, turns over every half period: the Dzhanibekov effect (the "tennis racket theorem"). The
shipped problem ``t_handle`` (``python/rigiddyn/problems/t_handle.toml``) is such a body, torque-free,
so its motion has a closed form in Jacobi's elliptic functions (Landau & Lifshitz, *Mechanics* §37),
which :class:`rigiddyn.TorqueFreeSolution` evaluates at any time.

This example integrates the handle with the fourth-order Lie-group method ``rkmk4`` and with the
``exact_flow_kick`` method, and sets both beside the exact solution.

**What it checks:** the exact solution's period against the closed form 4 K(m)/λ worked here from the
principal moments and the initial rate; that the intermediate axis reverses every half period;
``rkmk4``'s attitude error against its order (4) and against the Richardson estimate one can make
without an exact solution; ``exact_flow_kick``'s energy and angular momentum to round-off.
"""

# %%
# The problem and its exact solution
# ----------------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

problem = rd.load_problem("t_handle")
print(problem.description.strip())
inertia = problem.inertia_com  # (3, 3) about the centre of mass, in B [kg m^2]
exact = rd.TorqueFreeSolution(inertia, problem.q_WB, problem.w_B)
print("principal moments:", exact.principal_moments, "kg m^2;  case:", exact.case,
      ";  period of w_B:", exact.period, "s")

# %%
# The period from the closed form
# -------------------------------
# With the principal moments I1 < I2 < I3 (the handle's B is already principal and sorted) and the
# body angular momentum m = I w, the integrals :math:`G^2 = |m|^2` and :math:`2E = \sum m_i^2 / I_i` enter through
# :math:`\Delta_j = G^2 - 2 E I_j`, written without cancellation (Landau & Lifshitz §37). Delta_2 < 0: the
# angular momentum circulates about the smallest axis (case B); then
# :math:`w_2 = A_2\, \mathrm{sn}(\lambda t + u_0 \mid m)` with
#
# .. math::
#
#    \lambda = \sqrt{\frac{(I_2 - I_1)(-\Delta_3)}{I_1 I_2 I_3}}, \qquad
#    1 - m = \frac{(I_3 - I_1)(-\Delta_2)}{(I_2 - I_1)(-\Delta_3)}, \qquad
#    T = \frac{4 K(m)}{\lambda}.
#
# The handle is close to the separatrix (1 - m is about 1e-4), where m itself loses digits: the
# complement 1 - m is formed directly and handed to K.
I1, I2, I3 = np.diag(inertia)
m1, m2, m3 = inertia @ problem.w_B
delta1 = m2**2 * (I2 - I1) / I2 + m3**2 * (I3 - I1) / I3
delta2 = m1**2 * (I1 - I2) / I1 + m3**2 * (I3 - I2) / I3
delta3 = m1**2 * (I1 - I3) / I1 + m2**2 * (I2 - I3) / I2
assert delta2 < 0  # case B
lam = np.sqrt((I2 - I1) * -delta3 / (I1 * I2 * I3))
mc = (I3 - I1) * -delta2 / ((I2 - I1) * -delta3)
m = (I3 - I2) * delta1 / ((I2 - I1) * -delta3)
period = 4 * rd.ellipk(m, mc) / lam
print(f"closed form: lambda = {lam:.6f} 1/s, 1 - m = {mc:.4e}, T = {period:.12f} s "
      f"(relative difference from TorqueFreeSolution.period: {abs(period / exact.period - 1):.1e})")

# Each of lambda, 1 - m and K(m) is a few tens of roundings of positive quantities (relative error
# <= 50 eps each), and K is well conditioned in 1 - m (dK/K = -d(1-m) / (2 (1-m) K) with K ~ 6):
# both routes to T agree to 1e-13, i.e. 450 eps, relative.
assert abs(period - exact.period) <= 1e-13 * period

# %%
# The flips
# ---------
# The handle's intermediate axis carries w_2 = A_2 sn: it changes sign, and the handle turns over,
# every half period. The zero crossings of the exact w_2, refined by bisection, are spaced T/2.
horizon = 2.0 * period + 0.2  # [s]: two full periods, four flips
t_fine = np.linspace(0.0, horizon, 4001)
_, w_fine = exact.state_at(t_fine)
brackets = np.nonzero(np.sign(w_fine[:-1, 1]) != np.sign(w_fine[1:, 1]))[0]


def w2_exact(t):
    return exact.state_at(t)[1][1]


def bisect(a, b, tol=1e-12):
    """The zero of w2_exact in [a, b] [s], to tol [s]."""
    fa = w2_exact(a)
    while b - a > tol:
        mid = 0.5 * (a + b)
        if np.sign(w2_exact(mid)) == np.sign(fa):
            a, fa = mid, w2_exact(mid)
        else:
            b = mid
    return 0.5 * (a + b)


flips = np.array([bisect(t_fine[k], t_fine[k + 1]) for k in brackets])
print("flip times [s]:", np.round(flips, 6))
assert len(flips) == 4  # a crossing of w_2 = A_2 sn at every half period in (0, 2 T + 0.2)
# each crossing is bisected to 1e-12 s and sn is steep there (|dw_2/dt| = A_2 lambda ~ 65 rad/s^2,
# so w_2's rounding, ~1e-13 rad/s at these phases, moves it by ~1e-15 s): the spacings are T/2 to
# within 2e-12 s plus the rounding of T, below 1e-11 s.
assert np.max(np.abs(np.diff(flips) - period / 2)) <= 1e-11

# %%
# Integrating the handle
# ----------------------
# ``rkmk4`` (Munthe-Kaas' Runge-Kutta on the rotation group, order 4 in the attitude) at three step
# sizes, all recorded on the same 0.01 s grid, and ``exact_flow_kick`` (the closed-form free flow
# between kicks of the loads: exact here, as there are none) at a coarse step. The error of the
# attitude is the angle of the rotation taking the computed attitude to the exact one.
order = {d["name"]: d["order"] for d in rd.methods()}["rkmk4"]
body, initial = problem.body(), problem.initial_state()
dts = (0.01, 0.005, 0.0025)  # [s]; |w| dt <= 0.1
n_records = round(horizon / dts[0])
# a body runs as its one-body scene: .body(0) is the handle's records (t, q_WB (n, 4), w_B (n, 3), ...)
runs = {dt: rd.simulate(body, initial, dt, n_records * round(dts[0] / dt), "rkmk4",
                        record_every=round(dts[0] / dt)).body(0) for dt in dts}
flow = rd.simulate(body, initial, 0.04, round(horizon / 0.04), "exact_flow_kick")


def attitude_error(records):
    """Angle [rad] between the computed and the exact attitude at each record of a body's records."""
    q_exact, _ = exact.state_at(records.t)
    return rd.angular_distance(records.q_WB, q_exact)


errors = {dt: attitude_error(run) for dt, run in runs.items()}
for dt, e in errors.items():
    print(f"rkmk4 dt = {dt:<7} max attitude error {e.max():.3e} rad")
print(f"exact_flow_kick dt = 0.04: max attitude error {attitude_error(flow.body(0)).max():.3e} rad")

# %%
# The attitude error bound
# ------------------------
# A method of order p has a global error e(h) = C h^p (1 + O(h)): halving dt divides it by 2^p. Both
# halvings here give an observed order within 0.5 of 4 (on the largest error over the common record
# grid), which says these steps are in the asymptotic range.
maxima = np.array([errors[dt].max() for dt in dts])
observed = np.log2(maxima[:-1] / maxima[1:])
print("observed orders:", observed)
assert np.all(np.abs(observed - order) < 0.5)

# Without an exact solution, the difference of two runs estimates the error of the finer one
# (Richardson): E(h/2) ~ D / (2^p - 1), D = max_t |x(h) - x(h/2)|. The angle between attitudes is a
# metric, so E(h) - E(h/2) <= D <= E(h) + E(h/2) (triangle inequality); with r = E(h) / E(h/2)
# in [2^3.5, 2^4.5] (the order check above), the true error over the estimate,
# (2^p - 1) E(h/2) / D, lies in [15 / (r + 1), 15 / (r - 1)], inside [0.6, 1.5].
D = rd.angular_distance(runs[dts[1]].q_WB, runs[dts[2]].q_WB).max()
richardson = D / (2**order - 1)
print(f"Richardson estimate of the dt = {dts[2]} s error: {richardson:.3e} rad (true {maxima[2]:.3e})")
assert 0.6 <= maxima[2] / richardson <= 1.5

# ``exact_flow_kick`` keeps the energy and |L| of the free body to round-off at any step: each step
# evaluates the closed form with rounding errors of at most ~100 eps relative, accumulating at most
# linearly over the N steps.
eps = np.finfo(float).eps
steps = len(flow.t) - 1
E0, L0 = exact.kinetic_energy.total, np.linalg.norm(exact.angular_momentum_W)
assert np.max(np.abs(flow.kinetic_energy - E0)) <= 100 * eps * steps * E0
assert np.max(np.abs(flow.body(0).angular_momentum_norm - L0)) <= 100 * eps * steps * L0

# %%
# The figure
# ----------
# Top: the body rates, exact (lines) and ``rkmk4`` at dt = 0.01 s (dots); the dotted lines are the
# flips. Middle: the body axes projected on the (constant) direction of the angular momentum: the
# intermediate axis e2 swings from along L to against it and back. Bottom: the attitude errors.
run = runs[dts[0]]
t_exact = np.linspace(0.0, horizon, 1500)
q_exact, w_exact = exact.state_at(t_exact)
L_hat = exact.angular_momentum_W / L0
R_WB = rd.quat_to_matrix(q_exact)  # (n, 3, 3): column k is the body axis e_k in W

fig, axes = plt.subplots(3, 1, figsize=(9.5, 9), sharex=True, layout="constrained")
for k in range(3):
    axes[0].plot(t_exact, w_exact[:, k], color=f"C{k}", label=f"$w_{k + 1}$ exact")
    axes[0].plot(run.t[::8], run.w_B[::8, k], "o", color=f"C{k}", markersize=3,
                 label=f"$w_{k + 1}$ rkmk4, dt = {dts[0]} s")
    axes[1].plot(t_exact, R_WB[:, :, k] @ L_hat, color=f"C{k}", label=rf"$e_{k + 1} \cdot \hat L$")
for ax in axes[:2]:
    for t_flip in flips:
        ax.axvline(t_flip, color="grey", linestyle=":", linewidth=1)
axes[0].set_ylabel(r"$w_B$ [rad/s]")
axes[0].legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
axes[1].set_ylabel("body axis along L [-]")
axes[1].legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
for dt in dts:
    axes[2].semilogy(runs[dt].t[1:], errors[dt][1:], label=f"rkmk4, dt = {dt} s")
axes[2].semilogy(flow.t[1:], np.maximum(attitude_error(flow.body(0))[1:], 1e-17), label="exact_flow_kick, dt = 0.04 s")
axes[2].set_xlabel("t [s]")
axes[2].set_ylabel("attitude error [rad]")
axes[2].legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
axes[2].grid(alpha=0.3, which="both")
moments = ", ".join(f"{x:g}" for x in exact.principal_moments * 1e5)
fig.suptitle(f"T-handle: I = ({moments}) 1e-5 kg m$^2$, a flip every T/2 = {period / 2:.4f} s")
plt.show()
