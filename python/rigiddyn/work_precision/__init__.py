"""Speed against accuracy on the user's own problem: a work-precision sweep over methods and steps.

The sweep is the function `rigiddyn.tradeoff` (this package, rigiddyn.work_precision, holds it and its
result, TradeoffResult). For each method x dt, `tradeoff` runs the C++ `simulate` over the problem's
horizon, measures the cost (wall time of the C++ loop per step; derivative evaluations per step from
`methods()`), and compares every recorded state with a reference at the same times:

- ``"exact"`` when the problem has a closed form: torque-free rotation (`TorqueFreeSolution`,
  Euler-Poinsot) and a centre of mass under gravity and world-fixed piecewise-constant forces
  (p = p0 + v0 t + a t^2/2 on each piece);
- ``"richardson(<method>)"`` otherwise: the highest-order method at dt/2^j, refined (j = 1, 2, ...)
  until its Richardson estimate |y_{h/2} - y_h| / (2^p - 1) is below REFERENCE_TARGET x the errors
  it referees. That estimate only holds in the method's asymptotic range, so the reference is checked
  against a second, independent one: SciPy's DOP853 (another method family, adaptive, run in pieces
  between the switch times of the loads) at rtol DOP853_RTOL, its own error estimated by a second
  run at 10 x rtol; without SciPy, or beyond DOP853_MAX_STEPS, the best method of the core's other
  family (splitting or Runge-Kutta-Munthe-Kaas) from the reference's finest step, with its own
  Richardson estimate (the step halved while that estimate exceeds CHECK_FACTOR x the reference's,
  CHECK_HALVINGS times at most). If the two disagree by more than CHECK_FACTOR x the Richardson estimate
  (plus the second reference's own error), the reference is reported ``"unreliable: ..."``.
  reference_error is the larger of the Richardson estimate and the disagreement less the second
  reference's error (what the reference's error must at least be); reference_check says what was
  compared. Loads switching inside a step cost no accuracy: `simulate` splits such a step at the
  switch time, so every method keeps its order.

Error measures (the SciML work-precision convention), "final_"
at the horizon and "max_" over the recorded states:
  attitude_error  geodesic angle |log(q_ref^-1 q)| [rad]
  momentum_error  |I (w_B - w_ref)| / |I w_ref| (body angular momentum relative to G)
  position_error  |p_W - p_ref| [m];  velocity_error |v_W - v_ref| [m/s]
  state_error     max of attitude, momentum, position / L_p and velocity / L_v (dimensionless;
                  L_p = max(radius of gyration, distance travelled), L_v = max(speed, L_p / horizon))
  energy_drift    max_t |T - T_ref| / max_t T_ref (kinetic energy)
  momentum_drift  max_t ||I w| - |I w_ref|| / max_t |I w_ref| (|L| drift)
  quaternion_norm_error  max_t ||q| - 1|
observed_order: slope of log(measure) against log(dt) between a run and the next larger dt of the
  same method, reported only in the asymptotic range: both errors above the floor (round-off,
  ROUND_OFF_PER_STEP x steps, and REFERENCE_MARGIN x reference_error) and the slope agreeing
  with a neighbouring pair's (within ORDER_AGREEMENT, relative), and not both errors 1 or more (in rad
  or relative: nothing left to converge). Otherwise nan, with the reason in
  order_note; also nan for a method that is exact on the problem (order 0, or exact_torque_free
  on a torque-free problem whose forces are fixed in W: its error is round-off at every dt).

estimate, effectivity, estimate_verdict: the run's own estimate of its error in the sweep's measure
  (`simulate(..., error=True)`'s `result.error`, global Richardson over runs at h, 2h and 4h; see
  GlobalError), from a separate untimed run of the same method, dt and records (the same states), beside
  the true error the reference gives: effectivity = estimate / measure (1: exact, below 1: an
  under-estimate) and the estimate's verdict ("reliable" or why not), judged by the measure's quantity
  alone (`GlobalError.reliable_for`: a record that fails its check on another quantity, such as the
  energy of a damped scene, may still hold a reliable attitude estimate). The estimate covers the attitude,
  position and velocity errors (final_ at the horizon, max_ the largest over the records, of the bodies);
  for the other measures the columns are nan and the verdict says so. A reliable estimate promises an
  effectivity in [0.5, 2] (measured: docs/accuracy.md).
time_noise: how well a run's time repeats: (second fastest - fastest) / fastest of its repeated
  timings (nan for a run timed once; the time reported is the fastest). The sweep's timing noise is the
  NOISE_QUANTILE quantile over its runs (a minimum repeats better within a process than across runs).
  The recommendation by time counts two total times as equal when their ranges t (1 +- noise) overlap
  and breaks such ties by fewer derivative evaluations, then fewer steps (`cheapest`): timing noise
  does not flip it.
Without a tolerance there is no recommendation: the report gives the Pareto front of (cost, error)
instead, the runs that no other run beats in both (`pareto_front`).

A scene (many bodies, force elements; rigiddyn.Scene or a scene TOML file) is swept by the same loop:
the sweep runs one case type (case.Case), a problem's (one_body.ProblemCase) or a scene's
(rigiddyn.scene_precision.SceneCase), each saying how it runs, what its states are, how they are
measured, what its closed form and its independent reference are. On a scene: the Richardson reference
is checked against another method family, the errors are taken over the bodies, and a method the scene
refuses at compile is reported "not applicable: <reason>".

Before the sweep, a short timed probe of every method estimates the sweep's cost, printed on stderr
(progress=True), and a progress bar in steps follows the runs while stderr is a terminal (tqdm if
installed, else a plain one); progress=callable is called with the steps done instead, as simulate's.

The modules, one concept each (none imports this package's __init__): constants (the settings above),
checks (arguments), states (what is compared), case (the case interface and the entrance), one_body and
dop853 (a problem's case and its independent reference), runs (one timed run, its own error estimate),
references (Richardson reference and its check), progress (cost estimate, progress bar), orders
(observed orders), ranking (timing noise, cheapest, Pareto front), recommendation, result
(TradeoffResult) with table, plot and files (its reports), text (number and paragraph formats), and
sweep (the loop and `tradeoff`).
"""

from __future__ import annotations

from .._measures import MEASURES, measure_unit
from .constants import COLUMNS
from .one_body import reference_states
from .ranking import cheapest, pareto_front, timing_noise
from .recommendation import Recommendation
from .result import TradeoffResult
from .sweep import tradeoff

# the settings the docstring above names, read as rigiddyn.work_precision.<NAME> (explicit re-exports)
from .constants import CHECK_FACTOR as CHECK_FACTOR, CHECK_HALVINGS as CHECK_HALVINGS
from .constants import DOP853_MAX_STEPS as DOP853_MAX_STEPS, DOP853_RTOL as DOP853_RTOL
from .constants import LONG_RUN_SECONDS as LONG_RUN_SECONDS, MIN_TIMED_SECONDS as MIN_TIMED_SECONDS
from .constants import MAX_DTS as MAX_DTS, MAX_STEPS as MAX_STEPS, PROBE_STEPS as PROBE_STEPS
from .constants import NOISE_QUANTILE as NOISE_QUANTILE, ORDER_AGREEMENT as ORDER_AGREEMENT
from .constants import REFERENCE_MARGIN as REFERENCE_MARGIN, REFERENCE_TARGET as REFERENCE_TARGET
from .constants import ROUND_OFF_PER_STEP as ROUND_OFF_PER_STEP, SAMPLES as SAMPLES
from .states import States as States

__all__ = ["COLUMNS", "MEASURES", "Recommendation", "TradeoffResult", "cheapest", "measure_unit", "pareto_front",
           "reference_states", "timing_noise", "tradeoff"]
