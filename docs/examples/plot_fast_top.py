r"""
A fast top's nutation, and what each integrator does to it
===========================================================

The shipped problem ``fast_top`` (``python/rigiddyn/problems/fast_top.toml``) is a small disk
spinning at 300 rad/s about its symmetry axis with a slight wobble, free of torques. Its symmetry
axis e3 keeps a constant angle θ0 to the (constant) angular momentum L and turns about it: the free
nutation of a symmetric top (Landau & Lifshitz, *Mechanics* §33). In the body, the transverse rate
turns at Ω = (I3 − I1)/I1 w3, and

.. math::

   \tan\theta_0 = \frac{I_1 |w_\perp|}{I_3 |w_3|}.

A fast spin is hard on integrators: every method of :func:`rigiddyn.methods` is run on the same
top with the same step, and the nutation angle, the energy and :math:`|L|` are compared with what each
method promises (the ``conserves`` and ``notes`` fields of :func:`rigiddyn.methods`).

**What it checks:** the exact solution's nutation and body precession against the closed form;
for every Runge-Kutta-type method (explicit Euler widening the nutation, the implicit-gyroscopic
Euler narrowing it, RK4 and RKMK4 letting it decay slowly, the implicit midpoint and the exact flow
keeping it), the nutation angle at every step exactly as the method's stability function predicts;
the DLM splittings keeping :math:`|L|` to round-off and their energy error bounded, without drift, of
order 2 and 4 in the step.
"""

# %%
# The top and its free nutation
# -----------------------------
import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd

problem = rd.load_problem("fast_top")
inertia = problem.inertia_com  # solid cylinder, axis z: diag(I1, I1, I3) about the centre of mass
I1, I2, I3 = np.diag(inertia)
assert I1 == I2 and np.count_nonzero(inertia - np.diag(np.diag(inertia))) == 0
w0 = problem.w_B
Omega = (I3 - I1) / I1 * w0[2]  # [rad/s]: the body-frame precession of w_perp (Euler's equations)
theta0 = np.arctan2(I1 * np.hypot(w0[0], w0[1]), I3 * abs(w0[2]))
print(f"I1 = {I1:.4e}, I3 = {I3:.4e} kg m^2; w_B = {w0} rad/s")
print(f"nutation angle theta0 = {np.degrees(theta0):.5f} deg; body precession Omega = {Omega:.3f} rad/s")


def nutation(w_B):
    """Angle [rad] between the symmetry axis e3 and L, from w_B (n, 3) [rad/s]: L_B = I w_B."""
    m = w_B * np.diag(inertia)
    return np.arctan2(np.hypot(m[:, 0], m[:, 1]), np.abs(m[:, 2]))


exact = rd.TorqueFreeSolution(inertia, problem.q_WB, w0)
print("exact solution case:", exact.case)
t = np.linspace(0.0, 0.25, 501)
_, w_exact = exact.state_at(t)
# Euler's equations of the symmetric top: w3 constant and w1 + i w2 = (w1 + i w2)(0) exp(i Omega t).
turning = (w0[0] + 1j * w0[1]) * np.exp(1j * Omega * t)
w_closed = np.stack([turning.real, turning.imag, np.full_like(t, w0[2])], axis=1)
# The closed form and the library each round the phase Omega t (relative eps) and a few products:
# their difference is at most 100 eps (1 + Omega t) |w|.
eps = np.finfo(float).eps
assert np.all(np.abs(w_exact - w_closed) <= 100 * eps * (1 + Omega * t[:, None]) * np.linalg.norm(w0))
# w_perp is turned, not scaled (cos and sin of one phase): its length is kept to a few eps relative
# at any phase, so theta (~3.5e-3 rad) is kept to far below 100 eps.
assert np.max(np.abs(nutation(w_exact) - theta0)) <= 100 * eps

# %%
# Every method on the same top
# ----------------------------
# dt = 2.5e-4 s, so :math:`h |w| = 0.075` and :math:`h \Omega = 0.07`: inside every method's stability limit but the
# two with an explicit gyroscopic term, whose limit is 0.
dt, steps = 2.5e-4, 1000  # 0.25 s: about 11 turns of w_perp in the body
catalogue = {d["name"]: d for d in rd.methods()}
body, initial = problem.body(), problem.initial_state()
# each run is the top's one-body scene: kinetic_energy on the run, the top's w_B (n, 3) and |L| in .body(0)
runs = {name: rd.simulate(body, initial, dt, steps, name) for name in catalogue}
E0 = exact.kinetic_energy.total
L0 = np.linalg.norm(exact.angular_momentum_W)


def energy_error(result):
    return np.abs(result.kinetic_energy - E0) / E0


def momentum_error(result):
    return np.abs(result.body(0).angular_momentum_norm - L0) / L0


print(f"{'method':<42}{'order':>6}{'max |dE|/E':>12}{'max |d|L||/|L|':>16}{'final theta [deg]':>19}")
for name, result in runs.items():
    print(f"{name:<42}{catalogue[name]['order']:>6}{energy_error(result).max():>12.2e}"
          f"{momentum_error(result).max():>16.2e}{np.degrees(nutation(result.body(0).w_B)[-1]):>19.5f}")
print("\nwhat each method promises to conserve (rigiddyn.methods()):")
for name, entry in catalogue.items():
    print(f"  {name}: {entry['conserves']}")

# %%
# What each Runge-Kutta-type method does, in closed form
# -------------------------------------------------------
# For the symmetric top, Euler's equations keep w3 constant and turn the transverse rate:
# :math:`\dot w_\perp = \Omega J w_\perp`, J a quarter turn. That is linear, so a Runge-Kutta-type
# method multiplies :math:`w_\perp` at every step by its *stability function* R(z) at
# :math:`z = i h \Omega` (Hairer, Lubich, Wanner), and
#
# .. math::
#
#    \tan\theta_n = \tan\theta_0\, |R(i h \Omega)|^n .
#
# Explicit Euler, R = 1 + z, has :math:`|R|^2 = 1 + h^2\Omega^2`: the top wobbles wider and wider
# and gains energy at every step (``semi_implicit_euler`` kicks w the same way). The implicit
# gyroscopic term, R = 1/(1 - z), is the mirror image: the wobble dies out (its one Newton step is
# exact here, the equation being linear once w3 is fixed). RK4 and RKMK4 (the same stages on w),
# :math:`|R|^2 = 1 - y^6/72 + y^8/576` with y = h Omega, lose a little at every step: their energy
# drifts, here at h^5 per unit time (methods() promises O(h^4) at most). The implicit midpoint rule
# (R = (1 + z/2)/(1 - z/2)) and the exact flow (R = exp z) have :math:`|R| = 1`: the nutation is kept.
z = 1j * dt * Omega
R_rk4 = 1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24
stability_function = {
    "explicit_euler": 1 + z, "semi_implicit_euler": 1 + z,
    "semi_implicit_euler_implicit_gyroscopic": 1 / (1 - z),
    "rk4": R_rk4, "rkmk4": R_rk4,
    "implicit_midpoint": (1 + z / 2) / (1 - z / 2),
    "exact_flow_kick": np.exp(z), "exact": np.exp(z),
}
n = np.arange(steps + 1)
closed_form_tan = {name: np.tan(theta0) * np.abs(R) ** n for name, R in stability_function.items()}
w_perp0 = np.hypot(w0[0], w0[1])
for name, tan_closed in closed_form_tan.items():
    tan_theta = np.tan(nutation(runs[name].body(0).w_B))
    # one step is at most ~50 roundings on w_perp (4 stages of a few operations each): <= 50 eps
    # relative, accumulating at most linearly; the implicit midpoint adds its Newton tolerance,
    # 1e-14 relative to |w| per step, i.e. 1e-14 |w| / |w_perp| relative on w_perp.
    per_step = 50 * eps + (1e-14 * np.linalg.norm(w0) / w_perp0 if name == "implicit_midpoint" else 0.0)
    assert np.all(np.abs(tan_theta / tan_closed - 1) <= per_step * (n + 1)), name

# %%
# The splittings: angular momentum exact, energy bounded
# ------------------------------------------------------
# The DLM splitting is not of that form: it composes exact rotations of m about the principal axes
# (5 per step; 15 in its Yoshida composition, 3 DLM steps). Each rotation, with the conversions
# between w and m, keeps :math:`|m|` to 8 eps, so after n steps :math:`|L|` is kept to 8 eps n per rotation
# (the library promises an unbiased walk, ~10 eps sqrt(n); this is the worst case).
for name, rotations in (("splitting_dlm", 5), ("splitting_dlm_yoshida4", 15)):
    assert momentum_error(runs[name]).max() <= 8 * rotations * eps * (steps + 1), name

# Their energy error is bounded, of size C h^p (p = 2 for DLM, 4 for its Yoshida composition): they
# are symplectic and conserve a modified energy (backward error analysis). Halving dt divides the
# largest error over the run by 2^p, up to O(h^2) relative terms (both are symmetric methods):
# we assert an observed order within 0.5 of p.
for name in ("splitting_dlm", "splitting_dlm_yoshida4"):
    halved = rd.simulate(body, initial, dt / 2, 2 * steps, name)
    observed = np.log2(energy_error(runs[name]).max() / energy_error(halved).max())
    print(f"{name}: observed order of the energy error {observed:.2f} (method order {catalogue[name]['order']})")
    assert abs(observed - catalogue[name]["order"]) < 0.5, name

# No drift: over a run four times longer the largest energy error stays that of the first quarter.
# A drift c t on top of a bounded oscillation b would give (4 c T + b) / (c T + b); a ratio below
# 2 means c T < b / 2 over the first quarter (by the theory, c = 0 up to exponentially small terms).
for name in ("splitting_dlm", "splitting_dlm_yoshida4"):
    longer = energy_error(rd.simulate(body, initial, dt, 4 * steps, name))
    assert longer.max() < 2 * energy_error(runs[name]).max(), name

# %%
# The figure
# ----------
# Top: the nutation angle of every method, with the closed forms of explicit Euler, the implicit
# gyroscopic Euler and RK4 dotted (``explicit_euler`` and ``semi_implicit_euler`` coincide, as do
# ``rk4`` and ``rkmk4``: the same update of w). Middle and bottom: the relative energy and
# :math:`|L|` errors; round-off shows near 1e-16, and an error of exactly 0 is drawn at 1e-17.
fig, axes = plt.subplots(3, 1, figsize=(10, 10), sharex=True, layout="constrained")
for k, (name, result) in enumerate(runs.items()):
    style = dict(color="black", linestyle="--", linewidth=2) if name == "exact" else dict(color=f"C{k}")
    axes[0].semilogy(result.t, np.degrees(nutation(result.body(0).w_B)), label=name, **style)
    if name != "exact":  # the closed form at each record: round-off, as exact_flow_kick
        axes[1].semilogy(result.t[1:], np.maximum(energy_error(result)[1:], 1e-17), **style)
        axes[2].semilogy(result.t[1:], np.maximum(momentum_error(result)[1:], 1e-17), **style)
for name in ("explicit_euler", "semi_implicit_euler_implicit_gyroscopic", "rk4"):
    axes[0].semilogy(runs[name].t, np.degrees(np.arctan(closed_form_tan[name])), ":", color="black",
                     linewidth=1.5)
axes[0].set_ylabel(r"nutation angle $\theta$ [deg]")
axes[1].set_ylabel(r"$|E - E_0| / E_0$ [-]")
axes[2].set_ylabel(r"$||L| - |L_0|| / |L_0|$ [-]")
axes[2].set_xlabel("t [s]")
for ax in axes:
    ax.grid(alpha=0.3, which="both")
axes[0].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")
fig.suptitle(f"fast top, every method at dt = {dt} s (dt |w| = {dt * np.linalg.norm(w0):.3f})")
plt.show()
