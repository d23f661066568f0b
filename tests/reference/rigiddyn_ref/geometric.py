"""Structure-preserving integrators for the spatial rigid body, in plain numpy (the oracle of
rigiddyn's implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4, exact_flow_kick and exact).

State and model: integrators.RigidBodyModel, y = (p_W:3, q_WB (x,y,z,w):4, v_W:3, w_B:3, W) (14,),
loads held constant over a step. Written from the literature, independently of the C++ formulation:

- implicit_midpoint (Hairer, Lubich, Wanner, GNI I.1): y1 = y0 + h f((y0 + y1)/2) on the 14
  coordinates as they stand (the quaternion as a 4-vector), solved by fixed-point iteration to
  round-off in every coordinate; order 2.
- splitting_dlm (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107, 1997; McLachlan & Reich):
  Strang kick(h/2) · free(h) · kick(h/2); the free rotation split over the principal axes
  H = Σ m_i²/(2 I_i), each term's flow a rotation of m_P by -θ and of R_WP by +θ about e_i,
  θ = h m_i / I_i, in the sequence a(h/2) b(h/2) c(h) b(h/2) a(h/2) with I_a <= I_b <= I_c;
  rotation MATRICES here (quaternions in the core). A sphere's free rotation is R exp(h ω̂).
- splitting_dlm_yoshida4: Yoshida's triple jump (Phys. Lett. A 150, 1990) of three full DLM
  steps (the core merges the adjacent kicks; equal in exact arithmetic).
- exact_flow_kick (Celledoni, Fassò, Säfström, Zanna 2008): kick(h/2) · exact free flow(h) ·
  kick(h/2), the free flow in closed form by free_flow.free_rotation (Jacobi's functions advanced
  by their addition theorem, the precession by asserted quadrature; a route independent of the
  core's), accurate per step to free_flow.step_error_bound = 16 eps κ (1 + h|ω|), κ = I3/I1.
- exact: exact_flow_kick for torque-free bodies (raises ValueError on a couple).
Kicks: v += h f/m, ω += h I⁻¹ n at the current attitude, work += h (f·v̄ + n·ω̄).
"""

from __future__ import annotations

import numpy as np

from . import dynamics as dyn
from .free_flow import free_rotation
from .so3 import axis_rotation, matrix_to_quat, quat_to_matrix, rotvec_to_matrix

METHODS = ("implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick", "exact")

YOSHIDA_GAMMA1 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
YOSHIDA_GAMMA0 = -(2.0 ** (1.0 / 3.0)) / (2.0 - 2.0 ** (1.0 / 3.0))
MIDPOINT_TOLERANCE = np.finfo(float).eps  # per coordinate, relative to max(1, |coordinate|)
MIDPOINT_STALL = 64 * np.finfo(float).eps  # a change that stops shrinking below this is round-off
MIDPOINT_MAX_ITERATIONS = 200


def principal_frame(I):
    """(moments (3,), R_BP (3, 3) with det +1) of a symmetric inertia."""
    I = np.asarray(I, float)
    if np.count_nonzero(I - np.diag(np.diag(I))) == 0:
        return np.diag(I).copy(), np.eye(3)
    moments, R_BP = np.linalg.eigh(I)
    if np.linalg.det(R_BP) < 0:
        R_BP[:, 2] *= -1
    return moments, R_BP


def dlm_free_rotation(I, R_WB, w_B, h):
    """DLM splitting of the Euler–Poinsot flow over h: returns (R_WB, w_B)."""
    moments, R_BP = principal_frame(I)
    if np.ptp(moments) == 0.0:  # sphere: the free rotation is exact
        return R_WB @ rotvec_to_matrix(h * w_B), w_B.copy()
    R_WP = R_WB @ R_BP
    m = moments * (R_BP.T @ w_B)
    a, b, c = np.argsort(moments, kind="stable")
    for axis, tau in ((a, h / 2), (b, h / 2), (c, h), (b, h / 2), (a, h / 2)):
        theta = tau * m[axis] / moments[axis]
        m = axis_rotation(axis, -theta) @ m
        R_WP = R_WP @ axis_rotation(axis, theta)
    return R_WP @ R_BP.T, R_BP @ (m / moments)


def kick(model, y, h):
    """The loads' flow over h at the current attitude; returns h I⁻¹ n_B."""
    f_W, n_B = dyn.body_wrench(y[3:7], model.loads, model.mass, model.g_W)
    dv, dw = h * f_W / model.mass, h * np.linalg.solve(model.I, n_B)
    y[13] += h * (f_W @ (y[7:10] + dv / 2) + n_B @ (y[10:13] + dw / 2))
    y[7:10] += dv
    y[10:13] += dw
    return dw


def _free(model, y, h, rotation):
    y[0:3] += h * y[7:10]
    R, w = rotation(model.I, quat_to_matrix(y[3:7]), y[10:13].copy(), h)
    y[3:7] = matrix_to_quat(R)
    y[10:13] = w


def strang(model, y, h, rotation):
    y = np.array(y, dtype=float)
    kick(model, y, h / 2)
    _free(model, y, h, rotation)
    kick(model, y, h / 2)
    return y


def splitting_dlm(model, y, h):
    return strang(model, y, h, dlm_free_rotation)


def splitting_dlm_yoshida4(model, y, h):
    for gamma in (YOSHIDA_GAMMA1, YOSHIDA_GAMMA0, YOSHIDA_GAMMA1):
        y = splitting_dlm(model, y, gamma * h)
    return y


def exact_flow_kick(model, y, h):
    return strang(model, y, h, free_rotation)


def exact(model, y, h):
    f_W, n_B = dyn.body_wrench(y[3:7], model.loads, model.mass, model.g_W)
    if np.any(n_B != 0):
        raise ValueError("method: expected a torque-free body for 'exact', got a couple")
    return exact_flow_kick(model, y, h)


def implicit_midpoint(model, y, h):
    """Fixed-point iteration ȳ <- y0 + (h/2) f(ȳ) (a contraction for h |∂f/∂y| < 2) until the
    change of every coordinate is ≤ MIDPOINT_TOLERANCE max(1, |coordinate|) (one ulp of the
    largest, each coordinate in its own unit) or stops shrinking at round-off level; then
    y1 = 2 ȳ − y0. FloatingPointError if it has not converged after MIDPOINT_MAX_ITERATIONS."""
    y0 = np.array(y, dtype=float)
    mid, previous = y0.copy(), np.inf
    for _ in range(MIDPOINT_MAX_ITERATIONS):
        new = y0 + 0.5 * h * model.rate(mid)
        change = np.max(np.abs(new - mid) / np.maximum(1.0, np.abs(new)))
        mid = new
        if change <= MIDPOINT_TOLERANCE or (change >= previous and change <= MIDPOINT_STALL):
            break
        previous = change
    else:
        raise FloatingPointError(f"h: the implicit midpoint iteration did not converge at h = {h}")
    y1 = 2.0 * mid - y0
    y1[3:7] /= np.linalg.norm(y1[3:7])
    return y1


def step(model, y, h, method):
    """One step of `method` (a name from METHODS)."""
    if method not in METHODS:
        raise ValueError(f"method: expected one of {METHODS}, got {method!r}")
    return globals()[method](model, y, h)


def simulate(model, y0, h, steps, method, schedule=(), t0=0.0):
    """`steps` steps from y0 at t0; a step across a switch time of the schedule is split there
    (dynamics.step_pieces), each piece with the loads active on it. Returns the final coordinates."""
    y = np.array(y0, dtype=float)
    for i in range(steps):
        for start, length in dyn.step_pieces(schedule, t0 + i * h, h):
            model.set_loads(dyn.loads_at(schedule, start))
            y = step(model, y, length, method)
    return y
