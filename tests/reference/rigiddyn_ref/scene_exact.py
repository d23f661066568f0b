"""Exact solutions for scenes, in plain numpy (no rigiddyn, no scipy): the Kepler orbit, the pitch
libration of a satellite on a circular orbit, the linear spring–damper chain and the free particle.

Kepler (two-body problem about a fixed attractor of gravitational parameter μ = GM [m³/s²]): period
T = 2π √(a³/μ), energy E = −μ m/(2a), mean motion n = √(μ/a³); the position at time t follows from the
mean anomaly M = n (t − t_p) and Kepler's equation E − e sin E = M, solved by Newton's method.
In the perifocal frame (x to the pericentre, z along the angular momentum):
    x = a (cos E − e),  y = a √(1 − e²) sin E,
    ẋ = −a n sin E/(1 − e cos E),  ẏ = a n √(1 − e²) cos E/(1 − e cos E).
"""

from __future__ import annotations

import numpy as np

from .dynamics import cross


# ---------------------------------------------------------------- Kepler
def kepler_period(gm, a) -> float:
    """T = 2π √(a³/μ) [s]."""
    return 2.0 * np.pi * np.sqrt(a ** 3 / gm)


def kepler_energy(gm, a, mass) -> float:
    """E = −μ m/(2a) [J] (kinetic plus the potential −μ m/r)."""
    return -gm * mass / (2.0 * a)


def solve_kepler(mean_anomaly, e, tol=1e-15) -> float:
    """E with E − e sin E = M (e < 1), by Newton's method from E = M + e sin M (an iteration that converges
    for every e < 1 from this start); stops when the update is below tol relative to π."""
    M = float(np.remainder(mean_anomaly + np.pi, 2.0 * np.pi) - np.pi)
    E = M + e * np.sin(M)
    for _ in range(50):
        dE = (E - e * np.sin(E) - M) / (1.0 - e * np.cos(E))
        E -= dE
        if abs(dE) < tol * np.pi:
            break
    return E + (mean_anomaly - M)


def kepler_state(gm, a, e, t, t_pericentre=0.0):
    """(p, v) in the perifocal frame at time t [s] of the orbit (a [m], e < 1) passing its pericentre at
    t_pericentre: p [m], v [m/s] (3,), z = 0."""
    n = np.sqrt(gm / a ** 3)
    E = solve_kepler(n * (t - t_pericentre), e)
    b = a * np.sqrt(1.0 - e * e)
    denominator = 1.0 - e * np.cos(E)
    p = np.array([a * (np.cos(E) - e), b * np.sin(E), 0.0])
    v = np.array([-a * n * np.sin(E) / denominator, b * n * np.cos(E) / denominator, 0.0])
    return p, v


def osculating_elements(gm, p, v):
    """The orbit through (p [m], v [m/s]) relative to the attractor: semi-major axis a from the energy
    (vis-viva v² = μ(2/r − 1/a)), eccentricity vector e = v × h/μ − p/|p| (h = p × v), and the mean
    anomaly M = E − e sin E with E from r = a(1 − e cos E) and p·v = e √(μ a) sin E. Returns (a, e_vec, M)."""
    p, v = np.asarray(p, float), np.asarray(v, float)
    r = np.sqrt(p @ p)
    a = 1.0 / (2.0 / r - (v @ v) / gm)
    e_vec = cross(v, cross(p, v)) / gm - p / r
    e = np.sqrt(e_vec @ e_vec)
    E = np.arctan2((p @ v) / np.sqrt(gm * a), 1.0 - r / a)
    return a, e_vec, E - e * np.sin(E)


# ---------------------------------------------------------------- pitch libration
def circular_mean_motion(gm, radius) -> float:
    """n = √(μ/R³) [rad/s] of a circular orbit of radius R."""
    return np.sqrt(gm / radius ** 3)


def pitch_libration_frequency(n, inertia_x, inertia_y, inertia_z) -> float:
    """ω_lib = n √(3 (I_x − I_z)/I_y) [rad/s]: body y along the orbit normal, z along the local vertical
    and x along the track at zero pitch. With the pitch angle θ about y, r̂_B = (sin θ, 0, cos θ) up to
    signs and the gravity-gradient torque τ_B = 3n² r̂_B × I r̂_B (μ/R³ = n²) has the y part
    −3n² (I_x − I_z) sin θ cos θ; Euler's y equation (ω_x = ω_z = 0 in pitch-only motion, ω_y = n + θ̇)
    gives I_y θ̈ = −3n² (I_x − I_z) sin θ cos θ ≈ −3n² (I_x − I_z) θ: stable for I_x > I_z."""
    return n * np.sqrt(3.0 * (inertia_x - inertia_z) / inertia_y)


# ---------------------------------------------------------------- spring–damper chain
def chain_matrix(n, mass, stiffness, damping) -> np.ndarray:
    """A (2n, 2n) of ẋ = A x, x = (displacements u, velocities u̇), for n equal masses m in a line, the
    first tied to a fixed wall and each to the next by a spring k and a damper c in parallel:
    m ü_i = −k (2u_i − u_{i−1} − u_{i+1}) − c (…) with u_0 = 0 (the wall) and no neighbour after the last,
    i.e. M ü = −K u − C u̇, A = [[0, 1], [−K/m, −C/m]]."""
    laplacian = 2.0 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    laplacian[-1, -1] = 1.0
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -stiffness / mass * laplacian
    A[n:, n:] = -damping / mass * laplacian
    return A


def linear_flow(A, x0, t) -> np.ndarray:
    """x(t) = exp(A t) x0 by the eigen-decomposition A = V Λ V⁻¹: x(t) = V e^{Λ t} V⁻¹ x0 (A
    diagonalisable: distinct eigenvalues, true of the damped chain for c² ≠ 4km-type coincidences)."""
    lam, V = np.linalg.eig(A)
    coefficients = np.linalg.solve(V, np.asarray(x0, float))
    return np.real(V @ (np.exp(lam * t) * coefficients))


def rk4_transfer(A, h) -> np.ndarray:
    """One classical RK4 step of ẋ = A x is exactly x1 = (Σ_{k=0..4} (hA)^k/k!) x0: the degree-4 Taylor
    polynomial of exp(hA)."""
    step = np.eye(len(A))
    term = np.eye(len(A))
    for k in range(1, 5):
        term = term @ (h * A) / k
        step = step + term
    return step


# ---------------------------------------------------------------- free particle
def free_particle(p0, v0, t):
    """p(t) = p0 + v0 t, v(t) = v0 (law of inertia, Rigid-body notes §4.11)."""
    return np.asarray(p0, float) + np.asarray(v0, float) * t, np.asarray(v0, float)
