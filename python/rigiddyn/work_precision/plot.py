"""A sweep's work-precision plot: error against wall time and against derivative evaluations, per method."""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from .._measures import _check_measure, measure_unit
from .checks import check_name_list, check_path, is_real
from .text import fmt


def _plot_estimates(result: Any, ax: Any, cost: str, measure: str) -> None:
    """Each run's own error estimate (the estimate column) beside its true error: a bar from the true error
    to the estimate at the run's cost, ending in a dash where the estimate is reliable, a cross where not."""
    for i, method in enumerate(result.methods()):
        for r in result.rows:
            estimate, true = r.get("estimate", math.nan), r[measure]
            if (r["method"] != method or r["diverged"] or not is_real(estimate) or not estimate > 0
                    or not math.isfinite(estimate) or not true > 0 or not math.isfinite(true) or not r[cost] > 0):
                continue
            reliable = r.get("estimate_verdict") == "reliable"
            ax.plot([r[cost], r[cost]], [true, estimate], "-", color=f"C{i % 10}", linewidth=0.8, alpha=0.7)
            ax.plot([r[cost]], [estimate], "_" if reliable else "x", markersize=9, color=f"C{i % 10}")
    ax.plot([], [], "_", markersize=9, color="black", label="estimate (result.error), reliable")
    ax.plot([], [], "x", markersize=9, color="black", label="estimate, not reliable")


def _plot_axis(result: Any, ax: Any, cost: str, measure: str) -> None:
    """One work-precision panel: `measure` against `cost` per method (log-log), a closed-form method as
    markers without line, zeros (an exact error, no evaluations), which a log axis cannot show, drawn
    on the axis itself (its floor) with a downward marker, the tolerance and the recommendation."""
    from matplotlib.transforms import blended_transform_factory

    ax.set_xscale("log")
    ax.set_yscale("log")
    rows = [r for r in result.rows if not r["diverged"] and math.isfinite(r[measure])]
    # a zero coordinate goes to the axes' edge (axes fraction 0), the other stays data
    on_floor = {(False, True): blended_transform_factory(ax.transData, ax.transAxes),
                (True, False): blended_transform_factory(ax.transAxes, ax.transData),
                (True, True): ax.transAxes}
    for i, method in enumerate(result.methods()):
        mine = [r for r in rows if r["method"] == method]
        closed = bool(mine) and all(r.get("order") == 0 for r in mine)
        on_scale = [r for r in mine if r[measure] > 0 and r[cost] > 0]
        name = f"{method} (closed form)" if closed else method
        if on_scale:
            ax.plot([r[cost] for r in on_scale], [r[measure] for r in on_scale], "s" if closed else "o-",
                    color=f"C{i % 10}", label=name)
        for zero, transform in on_floor.items():
            at_floor = [r for r in mine if (r[cost] <= 0, r[measure] <= 0) == zero]
            if at_floor:
                ax.plot([0.0 if zero[0] else r[cost] for r in at_floor],
                        [0.0 if zero[1] else r[measure] for r in at_floor], "v", markersize=9,
                        color=f"C{i % 10}", clip_on=False, transform=transform,
                        label=f"{name}: 0, drawn on the axis")
    if measure == result.measure:  # the estimate columns are the sweep's measure's
        _plot_estimates(result, ax, cost, measure)
    if result.tolerance is not None:
        ax.axhline(result.tolerance, color="gray", linestyle="--", linewidth=1, label="tolerance")
    rec = result.recommendation
    if rec is not None and rec.row is not None:
        zero = (rec.row[cost] <= 0, rec.row[measure] <= 0)
        ax.plot([0.0 if zero[0] else rec.row[cost]], [0.0 if zero[1] else rec.row[measure]], "o", markersize=14,
                markerfacecolor="none", markeredgecolor="black", clip_on=False,
                transform=on_floor.get(zero, ax.transData), label="recommended")


def plot(result: Any, path: Any, formats: Sequence[str], measure: str | None) -> list[Path]:
    """TradeoffResult.plot: the two panels of `result`, written as path.<format> for each format."""
    try:
        import matplotlib

        matplotlib.use("Agg") if "matplotlib.pyplot" not in sys.modules else None
        import matplotlib.pyplot as plt
    except ImportError:
        raise ImportError("plot: expected matplotlib (pip install 'rigiddyn[plot]' or pip install matplotlib)") from None
    base = check_path(path, "path", optional=False)
    measure = result.measure if measure is None else measure
    _check_measure(measure)
    from matplotlib.backend_bases import FigureCanvasBase

    formats = check_name_list(formats, "formats", sorted(FigureCanvasBase.get_supported_filetypes()))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
    unit = measure_unit(measure)
    for ax, cost, label in ((axes[0], "total_time", "wall time of the run [s]"),
                            (axes[1], "total_evaluations", "derivative evaluations of the run")):
        _plot_axis(result, ax, cost, measure)
        ax.set_xlabel(label)
        ax.set_ylabel(f"{measure} [{unit}]" if unit != "-" else f"{measure} (dimensionless)")
        ax.grid(True, which="both", alpha=0.3)
    labels: dict[str, Any] = {}
    for ax in axes:
        for handle, text in zip(*ax.get_legend_handles_labels()):
            labels.setdefault(text, handle)
    # outside the axes, right of the second: it never covers data
    axes[1].legend(labels.values(), labels.keys(), loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                   fontsize=8)
    fig.suptitle(f"{result.problem}: work-precision over {fmt(result.horizon)} s")
    written = []
    for fmt_name in formats:
        out = Path(f"{base}.{fmt_name}")
        fig.savefig(out)
        written.append(out)
    plt.close(fig)
    return written
