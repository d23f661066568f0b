r"""
The work-precision plot of your own problem
============================================

Which integrator, at which step, is the cheapest way to reach the accuracy you need? That depends
on the problem, so :func:`rigiddyn.tradeoff` measures it on yours: it runs each method at a range of
steps, measures each run's cost (wall time, derivative evaluations) and error against a reference,
and recommends the cheapest run that meets a tolerance. Here the problem is built in code with
:class:`rigiddyn.Problem`: a box-shaped body thrown into the air, tumbling close to its
intermediate axis (where the Dzhanibekov flips make the attitude sensitive), under gravity. Its
motion has a closed form (the torque-free rotation in Jacobi's elliptic functions, the centre of
mass on a parabola), so the errors are measured against the exact solution.

**What it checks:** the observed order of convergence of each method, which ``tradeoff`` reports only
where two neighbouring slopes of the error against the step agree within its stated tolerance
(``rigiddyn.work_precision.ORDER_AGREEMENT``, relative), matches the method's order (from
:func:`rigiddyn.methods`) within that same tolerance; and the recommended run meets the tolerance.
"""

# %%
# The problem, built in code
# --------------------------
# A 0.3 m × 0.1 m × 0.04 m, 0.5 kg box (inertia of a solid box), thrown up at 5 m/s and spinning at
# 12 rad/s about its intermediate axis (y) with a small perturbation, for 3 s under gravity.
import math
import warnings

import matplotlib.pyplot as plt
import numpy as np

import rigiddyn as rd
from rigiddyn.work_precision import ORDER_AGREEMENT

box = rd.solid_box([0.3, 0.1, 0.04], mass=0.5)
problem = rd.Problem(name="tossed box", mass=box.mass, inertia_com=box.inertia_com, horizon=3.0,
                     v_W=[1.0, 0.0, 5.0],  # [m/s] in W
                     w_B=[0.05, 12.0, 0.05],  # [rad/s] in B
                     gravity=[0.0, 0.0, -9.81])  # [m/s^2] in W
print(f"principal moments {np.diag(box.inertia_com)} kg m^2; exact reference: {problem.has_exact_solution}")

# %%
# The sweep
# ---------
# Six methods of orders 1, 2 and 4, at seven steps halving from :math:`dt\,|\omega_0| = 0.4` rad. In a flip
# the rate grows to :math:`1.26\,|\omega_0|` (from the energy and momentum integrals of this inertia), so every
# run stays inside every method's stability limit. The measure is the attitude error at the end (the geodesic
# angle between the computed and the exact attitude, in rad); the tolerance 1e-6 rad.
METHODS = ["semi_implicit_euler_implicit_gyroscopic", "splitting_dlm", "implicit_midpoint", "rk4", "rkmk4",
           "splitting_dlm_yoshida4"]
rate = float(np.linalg.norm(problem.w_B))
dts = [0.4 / rate / 2**j for j in range(7)]
TOLERANCE = 1e-6  # [rad]
with warnings.catch_warnings():
    warnings.simplefilter("error", rd.StabilityWarning)  # none expected: every dt is inside every limit
    result = rd.tradeoff(problem, methods=METHODS, dts=dts, tolerance=TOLERANCE, measure="final_attitude_error",
                         progress=False)
print(result.to_table(width=110))

# %%
# The plot: how to read it
# ------------------------
# Each line is one method, each point one step size: its error (down is better) against its cost (left
# is cheaper). A method of order p has a line of slope −p on the right panel (derivative evaluations
# are proportional to 1/dt), so the higher-order lines are steeper; where they cross, the cheaper
# method changes. Read the plot from the tolerance (the dashed line): the leftmost point below it is
# the cheapest run that meets it, circled; that is ``result.recommendation``. Times depend on the
# machine (the left panel), derivative evaluations do not (the right panel). The figure is drawn here from
# ``result.rows`` (one dict per run); ``result.plot(path)`` writes the same plot as PNG and SVG files, and
# ``result.to_csv()`` / ``to_json()`` every column of every run.
fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True, constrained_layout=True)
rec = result.recommendation.row
for ax, cost, label in ((axes[0], "total_time", "wall time of the run [s]"),
                        (axes[1], "total_evaluations", "derivative evaluations of the run")):
    for i, method in enumerate(result.methods()):
        rows = [r for r in result.rows if r["method"] == method]
        ax.loglog([r[cost] for r in rows], [r["final_attitude_error"] for r in rows], "o-", color=f"C{i}",
                  label=method)
    ax.axhline(TOLERANCE, color="gray", linestyle="--", linewidth=1, label="tolerance")
    ax.plot(rec[cost], rec["final_attitude_error"], "o", markersize=14, markerfacecolor="none",
            markeredgecolor="black", label="recommended")
    ax.set_xlabel(label)
    ax.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel("attitude error at t = 3 s [rad]")
axes[1].legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8)
fig.suptitle("tossed box: work-precision over 3 s, against the exact solution")
plt.show()


# %%
# The checks
# ----------
orders = {m["name"]: m["order"] for m in rd.methods()}
for method in METHODS:
    rows = [r for r in result.rows if r["method"] == method]
    observed = [r["observed_order"] for r in rows if math.isfinite(r["observed_order"])]
    # at least one step pair in the asymptotic range, or the check below would say nothing
    assert observed, f"{method}: no observed order"
    for p in observed:
        # tradeoff reports a slope only where it agrees with a neighbouring one within ORDER_AGREEMENT x max(p, p', 1);
        # the same tolerance around the method's order
        assert abs(p - orders[method]) <= ORDER_AGREEMENT * max(orders[method], 1), (method, p)
    print(f"{method}: order {orders[method]}, observed {', '.join(f'{p:.2f}' for p in observed)}")
# the recommended run's error, plus its reference's (0: the exact solution), is within the tolerance
assert result.recommendation.met
assert rec["final_attitude_error"] + rec["reference_error"] <= TOLERANCE
