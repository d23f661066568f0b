"""The sweep's settings: how many states it compares, how it times runs, how it refines and checks references."""

from __future__ import annotations

import numpy as np

from .._measures import MEASURES

COLUMNS = ("method", "dt", "steps", "order", "evaluations_per_step", "time_per_step", "time_noise", "total_time",
           "total_evaluations") + MEASURES + ("observed_order", "order_note", "reference", "reference_error",
                                              "reference_check", "diverged", "stability", "estimate",
                                              "effectivity", "estimate_verdict")
COSTS = {"time": "total_time", "evaluations": "total_evaluations"}  # the column each cost ranks by
SAMPLES = 200  # states compared per run (every k-th step)
ROUND_OFF_PER_STEP = np.finfo(float).eps  # errors below this x steps (one ulp per step) may be round-off
MIN_TIMED_SECONDS = 2e-2  # time each run at least twice, up to 5 times until this much; keep the fastest
LONG_RUN_SECONDS = 0.5  # a run this long is timed once
REFERENCE_TARGET = 0.01  # the Richardson reference is refined until its error is this x the runs' errors
REFERENCE_MARGIN = 10.0  # an error within this factor of the reference's says nothing about the method
ORDER_AGREEMENT = 0.1  # neighbouring slopes p, p' agree if |p - p'| <= this x max(|p|, |p'|, 1)
CHECK_FACTOR = 10.0  # the second reference may disagree by this x the Richardson estimate (+ its own error)
CHECK_HALVINGS = 4  # the other family's check: its step halved at most this often below the reference's finest
DOP853_RTOL = 1e-13  # the independent reference's relative tolerance (its error: a second run at 10x)
DOP853_MAX_STEPS = 100_000  # per DOP853 run; beyond it the check uses the core's other 4th-order family
MAX_STEPS = 2**53  # steps of one run at most (exact in a float; far beyond any run that ends)
MAX_DTS = 64  # step sizes of one tradeoff at most (one run each; 8 halvings by default)
NOISE_QUANTILE = 0.9  # the sweep's timing noise: this quantile of its runs' time_noise
PROBE_STEPS = 2000  # steps of each method's timed probe for the cost estimate
REFUSED = "not applicable: "  # the order_note of a method a case refuses (its reason follows)
