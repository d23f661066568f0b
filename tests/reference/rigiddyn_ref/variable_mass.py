"""Bodies that gain or lose mass, in plain numpy. The oracle of rigiddyn's MassFlow and Thrust; it never imports
rigiddyn.

Rigid-body notes eq. (4.36), Newton's law as f = d(m v)/dt, written for a body that exchanges mass: in dt the mass
dm = ṁ dt leaves (ṁ < 0) or joins (ṁ > 0) with the absolute velocity v + u_rel (u_rel relative to the body), so
the momentum of body plus exchanged mass balances as
    d(m v)/dt = f + ṁ (v + u_rel)      ⇒      m v̇ = f + ṁ u_rel      (thrust ṁ u_rel).
A rigid body's rotation: the mass leaving carries its own angular momentum (no jet damping), I(m) ω̇ + ω × I(m) ω = τ;
with the inertia scaled with the mass, I(m) = I_0 m/m_0.
"""

from __future__ import annotations

import numpy as np

from .dynamics import cross


def momentum_rate(mass, mass_rate, v_W, u_rel_W, f_W) -> np.ndarray:
    """d(m v)/dt = f + ṁ (v + u_rel) [N] (Rigid-body notes (4.36) with the exchanged mass's momentum)."""
    return np.asarray(f_W, float) + mass_rate * (np.asarray(v_W, float) + np.asarray(u_rel_W, float))


def acceleration(mass, mass_rate, u_rel_W, f_W) -> np.ndarray:
    """v̇ = (f + ṁ u_rel)/m [m/s²]: d(m v)/dt = ṁ v + m v̇ subtracted from momentum_rate."""
    return (np.asarray(f_W, float) + mass_rate * np.asarray(u_rel_W, float)) / mass


def particle_rate(mass_rate, u_rel_W, g_W, y) -> np.ndarray:
    """ẏ of y = (p 3, v 3, m, t) under gravity m g and the thrust ṁ u_rel (world direction); mass_rate a number
    or a function of t [kg/s]."""
    m, t = y[6], y[7]
    mdot = mass_rate(t) if callable(mass_rate) else mass_rate
    return np.concatenate([y[3:6], acceleration(m, mdot, u_rel_W, m * np.asarray(g_W, float)), [mdot, 1.0]])


def angular_acceleration_scaled(mass, mass0, inertia0, w_B, tau_B) -> np.ndarray:
    """α = I_0⁻¹ ((m_0/m) τ − ω × I_0 ω): I(m) ω̇ + ω × I(m) ω = τ with I(m) = I_0 m/m_0, divided by m/m_0."""
    inertia0, w = np.asarray(inertia0, float), np.asarray(w_B, float)
    return np.linalg.solve(inertia0, mass0 / mass * np.asarray(tau_B, float) - cross(w, inertia0 @ w))


def angular_acceleration(inertia, w_B, tau_B) -> np.ndarray:
    """α = I(m)⁻¹ (τ − ω × I(m) ω) for a given inertia I(m) [kg m²] in B."""
    inertia, w = np.asarray(inertia, float), np.asarray(w_B, float)
    return np.linalg.solve(inertia, np.asarray(tau_B, float) - cross(w, inertia @ w))


def rk4_step(rate, y, h) -> np.ndarray:
    """Classical RK4 (Kutta 1901) of ẏ = rate(y)."""
    k1 = rate(y)
    k2 = rate(y + 0.5 * h * k1)
    k3 = rate(y + 0.5 * h * k2)
    k4 = rate(y + h * k3)
    return y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)


__all__ = ["acceleration", "angular_acceleration", "angular_acceleration_scaled", "momentum_rate",
           "particle_rate", "rk4_step"]
