"""Error bounds for long-run comparisons of the core with the numpy reference.

Two implementations of one fixed-step method differ after N steps only by their round-off: each
step k adds a local difference e_k (both sides round differently, |e_k| ≤ e_core + e_ref), and the
difference made at step k reaches step N through the method's own Jacobian J(N, k) = ∂y_N/∂y_k:
    |y_N(core) − y_N(ref)| ≤ Σ_{k=1..N} ‖J(N, k)‖ (e_core + e_ref)_k      (first order in e).
‖J(N, k)‖ is what the dynamics amplifies (linear phase drift on regular motion, e^{λ t} near a
separatrix or on chaotic motion), so the bound follows the problem instead of a figure seen once.

Here the norm is the max-norm of the scaled coordinates: each of p, v, ω, work divided by
max(1, |value|) component by component, the attitude as the body-frame rotation vector [rad]; the
same norm as `scaled_difference`. J(N, k) is the product of one-step Jacobians of the CORE's method
(finite differences of one step, relative perturbation FD_STEP: truncation O(FD_STEP) and round-off
O(eps/FD_STEP), both ≲ 1e-6 relative: negligible next to the worst case, linear accumulation the
bound assumes; random round-off accumulates as a random walk, measured 40-1000x below it).
The core may be used to measure the amplification: it is the discrete map under test, and the
one-step comparisons (tolerance `local_roundoff` per side) check that map against the reference.
"""

import numpy as np

import rigiddyn as rd

SUBNORMAL = float(np.finfo(np.float64).smallest_subnormal)  # 2^-1074, the spacing of the subnormals
EPS = np.finfo(float).eps
FD_STEP = 1e-7
# substeps of one step of each method: the number of times its state is rebuilt from increments
# (a composition of s steps rounds s times); implicit methods iterate to round-off: like one stage
STAGES = {"explicit_euler": 1, "semi_implicit_euler": 1, "semi_implicit_euler_implicit_gyroscopic": 1, "rk4": 1,
          "rkmk4": 1, "implicit_midpoint": 1, "splitting_dlm": 1, "splitting_dlm_yoshida4": 3,
          "exact_flow_kick": 1, "exact": 1}


def inertia_condition(inertia):
    """κ = I_max/I_min of a rotational inertia (1 for a particle or a planar body)."""
    moments = np.linalg.eigvalsh(np.atleast_2d(np.asarray(inertia, float)))
    return moments[-1] / moments[0]


def local_roundoff(method, kappa=1.0):
    """Bound on the round-off of ONE step of `method` on one side, relative to
    max(1, |y|, |y1 − y|) componentwise (the state or the step's increment, whichever is larger):
    16 eps κ per stage. A stage is y + (increment) with the increment a fixed sequence of O(30)
    correctly rounded operations: ≤ 4 eps from the sums and the quaternion renormalisation; the
    passage ω -> I ω -> ω (principal or full form, solve or inverse) turns a relative error eps of
    I ω into κ eps of ω (κ = I_max/I_min); the reference's closed free flow adds
    ≤ 16 eps κ (1 + h|ω|) (rigiddyn_ref.free_flow, h|ω| ≤ 1 here). Measured on random one-step
    problems (test_dynamics_vs_reference): ≤ 1.9 κ eps per side and stage."""
    return 16.0 * EPS * kappa * STAGES[method]


def step_tolerance(method, kappa, y0, y1):
    """Tolerance of one core step against one reference step from the same y0 (both sides'
    local_roundoff), relative to max(1, |y1|) as test_dynamics_vs_reference.close takes it."""
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(np.asarray(y1) - y0)))
    return 2.0 * local_roundoff(method, kappa) * size / max(1.0, np.max(np.abs(y1)))


def magnitude(x):
    """Σ |x_i| (bounds the 2-norm; no under- or overflow where |x| ~ 1e-200 or 1e200)."""
    return float(np.sum(np.abs(x)))


def evaluation_tolerance(terms, value, kappa=1.0, roundings=8):
    """Tolerance of one evaluation on both sides, relative to max(1, |value|): each side rounds
    ≤ `roundings` times on numbers ≤ `terms` (the sum of the magnitudes of the terms that make up
    the value: the condition of a sum), and a solve with the inertia adds its condition κ; results
    in the subnormal range round absolutely."""
    # an underflowing result rounds by up to half the smallest subnormal per operation instead
    absolute = 2.0 * roundings * (EPS * kappa * terms + np.finfo(float).smallest_subnormal)
    return absolute / max(1.0, np.max(np.abs(value)))


def state_of(run, i):
    """(p_W, q_WB, v_W, w_B, work) of record i of a core run (a one-body SceneResult: its body(0), the sum of its
    elements' work), as one (14,) array (a particle records q = identity and w = 0, a planar body p = (x, y, 0),
    q = Rz(θ), w = (0, 0, ω))."""
    body, work = run.body(0), np.asarray(run.work).sum(axis=1)
    return np.concatenate([body.p_W[i], body.q_WB[i], body.v_W[i], body.w_B[i], [work[i]]])


def _quat_product(a, b):
    """Hamilton product of (..., 4) quaternions (x, y, z, w), written out (no np.cross: this runs
    ~10^4 times per amplification_sum)."""
    ax, ay, az, aw = a[..., 0], a[..., 1], a[..., 2], a[..., 3]
    bx, by, bz, bw = b[..., 0], b[..., 1], b[..., 2], b[..., 3]
    return np.stack([aw * bx + bw * ax + ay * bz - az * by, aw * by + bw * ay + az * bx - ax * bz,
                     aw * bz + bw * az + ax * by - ay * bx, aw * bw - ax * bx - ay * by - az * bz], -1)


def _turn(q0, q):
    """Body-frame rotation vectors (..., 3) [rad] from unit q0 (4,) to unit q (..., 4)."""
    d = _quat_product(q0 * [-1.0, -1.0, -1.0, 1.0], q)
    d = np.where(d[..., 3:] < 0.0, -d, d)
    s = np.linalg.norm(d[..., :3], axis=-1, keepdims=True)
    angle = 2.0 * np.arctan2(s, d[..., 3:])
    return d[..., :3] * np.where(s > 0.0, angle / np.where(s > 0.0, s, 1.0), 2.0)


def _scaled_changes(ys, y0):
    """The changes from y0 (14,) to each row of ys (n, 14), in scaled coordinates (n, 13): p, body
    rotation vector, v, ω, work, each scaled by max(1, |its value in y0|) (the rotation in rad)."""
    d = np.concatenate([ys[:, 0:3] - y0[0:3], _turn(y0[3:7], ys[:, 3:7]), ys[:, 7:14] - y0[7:14]], axis=1)
    scale = np.concatenate([np.maximum(1.0, np.abs(y0[0:3])), np.ones(3), np.maximum(1.0, np.abs(y0[7:14]))])
    return d / scale


def scaled_difference(y, y_ref):
    """max over components of |y − y_ref| / max(1, |y_ref|), the attitude as the largest component
    [rad] of the body-frame rotation vector from q_ref to q (both (14,) as in state_of): the norm
    of the bounds here."""
    return np.max(np.abs(_scaled_changes(np.atleast_2d(y), y_ref)))


# the scaled coordinates a model has: p, attitude, v, ω, work (a particle has no attitude, a planar
# body moves in the xy plane and turns about z)
_DIRECTIONS = {rd.RigidBody: list(range(13)), rd.Particle: [0, 1, 2, 6, 7, 8, 12],
               rd.PlanarBody: [0, 1, 5, 6, 7, 11, 12]}


def _perturbations(y, directions, d):
    """(n, 14): y with scaled coordinate j of `directions` (as in _scaled_changes) moved by d."""
    ys = np.tile(y, (len(directions), 1))
    turned = [(row, j - 3) for row, j in enumerate(directions) if 3 <= j < 6]
    if turned:  # body-frame turns by d about each axis: q ⊗ (sin(d/2) e_j, cos(d/2))
        rows, axes = np.array(turned).T
        turns = np.zeros((len(rows), 4))
        turns[np.arange(len(rows)), axes], turns[:, 3] = np.sin(d / 2), np.cos(d / 2)
        ys[rows, 3:7] = _quat_product(y[3:7], turns)
    for row, j in enumerate(directions):
        if not 3 <= j < 6:
            i = j if j < 3 else j + 1
            ys[row, i] += d * max(1.0, abs(y[i]))
    return ys


def _initial_state(body, y):
    """The core state of `body`'s model at coordinates y (14,)."""
    if isinstance(body, rd.Particle):
        return rd.ParticleState(y[0:3], y[7:10])
    if isinstance(body, rd.PlanarBody):
        return rd.PlanarBodyState(y[0:2], 2.0 * np.arctan2(y[5], y[6]), y[7:9], y[12])
    return rd.RigidBodyState(p_W=y[0:3], q_WB=y[3:7], v_W=y[7:10], w_B=y[10:13])


def _core_step(body, y, dt, t, method, loads, gravity):
    """One core step from y (14,) at time t; the work accumulates onto y[13]."""
    run = rd.simulate(body, _initial_state(body, y), dt, 1, method=method, record_every=1, loads=loads,
                      gravity=gravity, t0=t)
    y1 = state_of(run, -1)
    y1[13] += y[13]
    return y1


def amplification_sum(body, run, dt, method, loads, gravity, t0=0.0):
    """Σ_{k=1..N} ‖J(N, k)‖ w_k along the recorded core run `run` of `body` (Particle, PlanarBody
    or RigidBody; record_every=1, N steps from t0), in the scaled max-norm (induced norm: the
    largest row sum), from one-step finite differences of the core's `method` (module docstring);
    w_k = max(1, scaled size of step k's increment) (local_roundoff's size). 'exact' is measured
    with 'exact_flow_kick' (the same flow, which 'exact' evaluates in closed form)."""
    method = "exact_flow_kick" if method == "exact" else method
    directions = _DIRECTIONS[type(body)]
    states = [state_of(run, i) for i in range(len(run.t))]
    product, total = np.eye(13), _step_weight(states[-2], states[-1])
    for k in range(len(states) - 2, 0, -1):  # J(N, k) = J(N, k + 1) J(k + 1, k)
        y, t = states[k], t0 + k * dt
        base = _core_step(body, y, dt, t, method, loads, gravity)
        moved = np.array([_core_step(body, yj, dt, t, method, loads, gravity)
                          for yj in _perturbations(y, directions, FD_STEP)])
        J = np.zeros((13, 13))
        J[:, directions] = _scaled_changes(moved, base).T / FD_STEP
        product = product @ J
        total += np.max(np.sum(np.abs(product), axis=1)) * _step_weight(states[k - 1], y)
    return total


def _step_weight(y0, y1):
    """max(1, largest scaled increment of the step y0 -> y1): local_roundoff is relative to the
    larger of the state and the increment."""
    return max(1.0, np.max(np.abs(_scaled_changes(np.atleast_2d(y1), y0))))


def propagated_bound(body, run, dt, method, loads, gravity, kappa=1.0, t0=0.0):
    """Bound on the scaled difference of the core's and the reference's run at its end, both
    started from the same state: Σ_k ‖J(N, k)‖ (e_core + e_ref)_k, e = local_roundoff(method, κ)
    times step k's size weight."""
    return amplification_sum(body, run, dt, method, loads, gravity, t0) * 2.0 * local_roundoff(method, kappa)


def propagated_bounds(body, run, dt, method, loads, gravity, kappa=1.0, t0=0.0):
    """propagated_bound at every step k = 0..N of a short run (record_every=1), by the products
    J(k, j) for all j < k (O(N²): for N up to ~100), plus 4 eps for the initial state's own
    conversion (the core normalises q): (N + 1,) array."""
    method_fd = "exact_flow_kick" if method == "exact" else method
    directions = _DIRECTIONS[type(body)]
    states = [state_of(run, i) for i in range(len(run.t))]
    products, weights, bounds = [], [], [0.0]
    for k in range(1, len(states)):
        y, t = states[k - 1], t0 + (k - 1) * dt
        base = _core_step(body, y, dt, t, method_fd, loads, gravity)
        moved = np.array([_core_step(body, yj, dt, t, method_fd, loads, gravity)
                          for yj in _perturbations(y, directions, FD_STEP)])
        J = np.zeros((13, 13))
        J[:, directions] = _scaled_changes(moved, base).T / FD_STEP
        products = [J @ P for P in products] + [np.eye(13)]  # J(k, j) for j = 1..k
        weights.append(_step_weight(y, states[k]))
        bounds.append(sum(np.max(np.sum(np.abs(P), axis=1)) * w for P, w in zip(products, weights)))
    return 4.0 * EPS + np.array(bounds) * 2.0 * local_roundoff(method, kappa)


def closed_form_error(kappa, w_B, t):
    """Bound on the core's TorqueFreeSolution.state_at(t) error (attitude [rad], |Δω|/|ω|):
    16 eps κ (1 + |ω t|), as exact/free_body.hpp states it ("a few ulps at t = 0, growing as
    eps·|phase|"), with the same κ and eigen-decomposition terms as rigiddyn_ref.free_flow."""
    return 16.0 * EPS * kappa * (1.0 + abs(t) * np.linalg.norm(w_B))


def derived_tolerances(bound, body, run, gravity=None, i=-1):
    """Tolerances, relative to max(1, |value|) as tests/python/test_dynamics_vs_reference.close
    takes them, for quantities computed from record i of `run` when every scaled coordinate
    is within `bound` (|Δx_i| <= bound max(1, |x_i|)), plus their own evaluation (<= 8 eps each side):
    kinetic T = (m v.v + w.I w)/2: |ΔT| <= m |v|.s(v) bound + |I w|.s(w) bound;
    potential V = -m g.p: |ΔV| <= m |g|.s(p) bound; |H| = |I w|: |Δ|H|| <= ||I|| |s(w)| bound;
    the work W: as integrated (within bound) or, under gravity alone, W = V(t0) - V(t) from the records
    (|ΔW| <= ΔV(t0) + ΔV(t) + 2 eps |W|: the potentials' round-off, not the work's, sets it)
    (s(x) = max(1, |x_i|) componentwise, |.| componentwise, "." a dot product)."""
    s = lambda x: np.maximum(1.0, np.abs(x))  # noqa: E731
    records = run.body(0)
    v, w, p = records.v_W[i], records.w_B[i], records.p_W[i]
    mass = body.mass
    inertia = (body.inertia_com if isinstance(body, rd.RigidBody)
               else np.diag([0.0, 0.0, body.inertia_zz]) if isinstance(body, rd.PlanarBody) else np.zeros((3, 3)))
    g = np.zeros(3) if gravity is None else np.asarray(gravity, float)
    dT = bound * (mass * np.abs(v) @ s(v) + np.abs(inertia @ w) @ s(w)) + 16 * EPS * run.kinetic_energy[i]
    potential_error = lambda p: bound * mass * np.abs(g) @ s(p) + 16 * EPS * abs(mass * g @ p)  # noqa: E731
    dV = potential_error(p)
    work = float(np.sum(run.work[i]))
    dW = bound * max(1.0, abs(work)) + dV + potential_error(records.p_W[0]) + 2 * EPS * abs(work)
    dH = bound * np.linalg.norm(inertia, 2) * np.linalg.norm(s(w)) + 16 * EPS * records.angular_momentum_norm[i]
    rel = lambda d, value: d / max(1.0, abs(value))  # noqa: E731
    return {"kinetic": rel(dT, run.kinetic_energy[i]), "total": rel(dT + dV, run.total_energy[i]),
            "momentum": rel(dH, records.angular_momentum_norm[i]), "work": rel(dW, work)}


def body_condition(body):
    """κ of a core body's rotational inertia (1 for a particle or a planar body: a scalar inertia)."""
    return inertia_condition(body.inertia_com) if isinstance(body, rd.RigidBody) else 1.0


def product_tolerance(A, x):
    """Absolute bound on the difference of two evaluations of A @ x (any summation order, both
    sides): |fl(A x) − A x| ≤ γ_n |A| |x| per side with γ_n ≈ n eps (Higham, "Accuracy and
    Stability of Numerical Algorithms", (3.4)), n the inner dimension; A and x exact inputs. Products
    and sums that fall into the subnormal range add an absolute error of at most one subnormal unit each
    (gradual underflow, Higham §2.1): 2n of them per side."""
    A, x = np.abs(np.asarray(A, float)), np.abs(np.asarray(x, float))
    n = A.shape[-1]
    return 2.0 * n * EPS * float(np.max(A @ x)) + 4.0 * n * SUBNORMAL


def roundoff(size, roundings=8):
    """Absolute bound on the difference of two evaluations (both sides) that each round at most
    `roundings` times on numbers no larger than `size` (for a sum: the sum of the terms' magnitudes,
    Higham's gamma_n bound with n = roundings)."""
    return 2.0 * roundings * EPS * float(size)
