"""Closed forms of the new models, with numpy and scipy.special (ellipj, ellipk, ellipkm1, ellipkinc, elliprf,
elliprj); it never imports rigiddyn. The oracle of rigiddyn's CompoundPendulumSolution, LagrangeTopSolution,
RotatingFrameFreeParticle and ConstantThrustSolution.

Compound pendulum (DLMF §22.19(i)): with v the angle of R c from g (v = 0 the stable equilibrium) the equation
I_O v̈ = −m g d sin v, ω0² = m g d / I_O, has the energy integral (v̇/(2ω0))² + sin²(v/2) = k².
  libration (k < 1): sin(v/2) = k sn(ω0 t + u0 | k²), v̇ = 2 k ω0 cn(·), period 4 K(k²)/ω0;
  rotation (k > 1):  v/2 = ± am(k ω0 t + u0 | 1/k²), v̇ = ± 2 k ω0 dn(·), one turn in 2 K(1/k²)/(k ω0).
Near the separatrix K is taken from the complementary parameter 1 − k² (ellipkm1), formed without cancellation.

Heavy symmetric (Lagrange) top (Landau & Lifshitz §35; the integrals E, p_φ, p_ψ): with u = cos θ (θ the tilt of the
symmetry axis e3 from the upward vertical), I1 the transverse and I3 the axial moment about O, l = |OC|,
    u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)²,  α = 2 E'/I1, β = 2 m g l / I1, a = I3 ω3 / I1, b = p_φ / I1
(E' = E − ½ I3 ω3²). f = β (u − u1)(u − u2)(u − u3), u1 ≤ u ≤ u2 ≤ 1 ≤ u3, and
    u = u1 + (u2 − u1) sn²(λ t + τ0 | m),  m = (u2 − u1)/(u3 − u1),  λ = √(β (u3 − u1))/2
(substitute: u̇² = 4 λ² (u2 − u1)² sn² cn² dn² = β (u − u1)(u − u2)(u − u3)); the nutation period is 2 K(m)/λ.
    φ̇ = (b − a u)/(1 − u²) = ½ [(b − a)/(1 − u) + (b + a)/(1 + u)],
    ψ̇ = ω3 − u φ̇ = ω3 − a − ½ [(b − a)/(1 − u) − (b + a)/(1 + u)],
and with 1 ∓ u = (1 ∓ u1)(1 − n± sn²), n+ = (u2 − u1)/(1 − u1), n− = −(u2 − u1)/(1 + u1):
    ∫ dt/(1 − n sn²(λ t)) = Π(n; am(λ t) | m)/λ      (Legendre's third kind, in Carlson's R_F, R_J: DLMF 19.25.14).

Constant-thrust burn (Rigid-body notes (4.36): m v̇ = m g + ṁ u_rel, m = m0 + ṁ t):
    v = v0 + g t + u_rel ln(m/m0),   p = p0 + v0 t + ½ g t² + u_rel ((m/ṁ) ln(m/m0) − t),
and Tsiolkovsky's Δv = |u_rel| ln(m0/m1).
"""

from __future__ import annotations

import numpy as np
from scipy import special

from .dynamics import cross
from .so3 import matrix_to_quat, quat_to_matrix

PI_LOW = 1.2246467991473532e-16  # π − fl(π): the part of π a double misses (sin(fl(π)) to full precision)


# ---------------------------------------------------------------- Legendre's third kind
def legendre_pi(n, phi, m) -> float:
    """Π(n; φ | m) = ∫0^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ)) for any real φ: with φ = j π + r, |r| ≤ π/2,
    Π = 2 j Π(n | m) + sign(r) (s R_F(c², Δ², 1) + n s³/3 R_J(c², Δ², 1, 1 − n s²)), s = |sin r|, c = cos r,
    Δ² = 1 − m s² (DLMF 19.25.14; 19.2.9 for the quasi-period); n < 1, m < 1."""
    j = np.round(phi / np.pi)
    r = phi - j * np.pi
    s, c = abs(np.sin(r)), np.cos(r)
    delta2 = 1.0 - m * s * s
    part = (s * special.elliprf(c * c, delta2, 1.0)
            + n * s ** 3 / 3.0 * special.elliprj(c * c, delta2, 1.0, 1.0 - n * s * s))
    complete = special.elliprf(0.0, 1.0 - m, 1.0) + n / 3.0 * special.elliprj(0.0, 1.0 - m, 1.0, 1.0 - n)
    return 2.0 * j * complete + np.sign(r) * part


# ---------------------------------------------------------------- compound pendulum
def pendulum_omega0(mass, inertia_O, distance, g) -> float:
    """ω0 = √(m g d / I_O) [rad/s], I_O the moment about the pivot, d = |OC|."""
    return np.sqrt(mass * g * distance / inertia_O)


def pendulum_period_from_rest(omega0, amplitude) -> float:
    """4 K(k²)/ω0 [s], k = sin(θ0/2), of a libration released at rest at θ0 from the stable equilibrium,
    0 < θ0 < π. K from ellipkm1 of 1 − k² = cos²(θ0/2) = sin²((π − θ0)/2), π − θ0 formed as (fl(π) − θ0) + PI_LOW
    (Sterbenz: exact for θ0 ≥ π/2), so the period stays accurate to θ0 → π."""
    if amplitude >= np.pi / 2:
        complement = np.sin(0.5 * ((np.pi - amplitude) + PI_LOW)) ** 2
        return 4.0 * special.ellipkm1(complement) / omega0
    return 4.0 * special.ellipk(np.sin(0.5 * amplitude) ** 2) / omega0


def pendulum_motion(omega0, v0, vdot0, t):
    """(v, v̇) at times t [s] (array) of v̈ = −ω0² sin v from (v0, v̇0) (v from the stable equilibrium; DLMF §22.19(i)).
    Libration: am(u0) = atan2(sin(v0/2)/k, v̇0/(2 k ω0)), u0 = F(am0 | k²); rotation: u0 = F(s v0/2 | 1/k²),
    s = sign v̇0. Returns v continuous from v0 on the rotation; on a libration v ∈ (−π, π) (as 2 asin)."""
    t = np.asarray(t, float)
    k2 = np.sin(0.5 * v0) ** 2 + (vdot0 / (2.0 * omega0)) ** 2
    k = np.sqrt(k2)
    if k2 < 1.0:
        am0 = np.arctan2(np.sin(0.5 * v0) / k, vdot0 / (2.0 * k * omega0))
        u = omega0 * t + special.ellipkinc(am0, k2)
        sn, cn, _, _ = special.ellipj(u, k2)
        return 2.0 * np.arcsin(np.clip(k * sn, -1.0, 1.0)), 2.0 * k * omega0 * cn
    s = np.sign(vdot0)
    u = k * omega0 * t + special.ellipkinc(s * 0.5 * v0, 1.0 / k2)
    _, _, dn, ph = special.ellipj(u, 1.0 / k2)
    return 2.0 * s * ph, 2.0 * s * k * omega0 * dn


def pendulum_rotation_period(omega0, v0, vdot0) -> float:
    """One turn of a rotating pendulum: 2 K(1/k²)/(k ω0) [s]."""
    k2 = np.sin(0.5 * v0) ** 2 + (vdot0 / (2.0 * omega0)) ** 2
    return 2.0 * special.ellipk(1.0 / k2) / (np.sqrt(k2) * omega0)


# ---------------------------------------------------------------- Lagrange top
def _rotation_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _rotation_x(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _frame_with_z(z, x_hint):
    """A right-handed rotation matrix whose third column is the unit z and first column x_hint's part ⊥ z."""
    x = x_hint - (x_hint @ z) * z
    x /= np.linalg.norm(x)
    return np.column_stack([x, cross(z, x), z])


class LagrangeTop:
    """The heavy symmetric top about the fixed O (module docstring). inertia_O (3, 3) [kg m²] in B, symmetric about
    c_B = p_OC_B [m]; g_W (3,) [m/s²]; the state (q_WB (x, y, z, w), w_B [rad/s]) at t = 0. Frames: N with z_N up
    (−ĝ) and x_N along the line of nodes z_N × e3 at t = 0 (φ(0) = 0); S fixed in B with e3 along c, S = N Rx(θ0)
    at t = 0 (ψ(0) = 0). The axis must not pass through a vertical (u1, u2 inside (−1, 1))."""

    def __init__(self, mass, inertia_O, c_B, g_W, q_WB, w_B):
        c_B, g_W, w_B = (np.asarray(x, float) for x in (c_B, g_W, w_B))
        inertia_O = np.asarray(inertia_O, float)
        self.l = np.linalg.norm(c_B)
        e3_B = c_B / self.l
        self.I3 = e3_B @ inertia_O @ e3_B
        self.I1 = 0.5 * (np.trace(inertia_O) - self.I3)
        g = np.linalg.norm(g_W)
        R_WB = quat_to_matrix(q_WB)
        z_N = -g_W / g
        e3_W = R_WB @ e3_B
        self.R_WN = _frame_with_z(z_N, cross(z_N, e3_W))
        u0 = e3_W @ z_N
        self.theta0 = np.arccos(u0)
        R_WS0 = self.R_WN @ _rotation_x(self.theta0)
        self.R_SB = R_WS0.T @ R_WB
        omega3 = e3_B @ w_B
        H_W = R_WB @ inertia_O @ w_B
        energy = 0.5 * w_B @ inertia_O @ w_B + mass * g * self.l * u0
        self.omega3 = omega3
        self.a, self.b = self.I3 * omega3 / self.I1, (H_W @ z_N) / self.I1
        self.alpha = 2.0 * (energy - 0.5 * self.I3 * omega3 ** 2) / self.I1
        self.beta = 2.0 * mass * g * self.l / self.I1
        self.u1, self.u2, self.u3 = self._roots()
        self.m = (self.u2 - self.u1) / (self.u3 - self.u1)
        self.lam = 0.5 * np.sqrt(self.beta * (self.u3 - self.u1))
        udot0 = (R_WB @ cross(w_B, e3_B)) @ z_N
        self.tau0 = special.ellipkinc(self._initial_amplitude(u0, udot0), self.m)
        self.n_plus, self.n_minus = (self.u2 - self.u1) / (1.0 - self.u1), -(self.u2 - self.u1) / (1.0 + self.u1)

    def _initial_amplitude(self, u0, udot0):
        """am(τ0) from u0 = u1 + (u2 − u1) sn² and u̇0 = 2 (u2 − u1) λ sn cn dn: the square root of sn² (or cn²) is
        taken where it is well conditioned (sn² ≤ 1/2: cn, near u1; else sn, near u2), the other factor from u̇0,
        which carries the sign; an arcsin of sn alone loses half the digits at a turning point."""
        s2 = np.clip((u0 - self.u1) / (self.u2 - self.u1), 0.0, 1.0)
        sn_cn = udot0 / (2.0 * (self.u2 - self.u1) * self.lam * np.sqrt(1.0 - self.m * s2))
        if s2 <= 0.5:
            cn = np.sqrt(1.0 - s2)
            return np.arctan2(sn_cn / cn, cn)
        sn = np.sqrt(s2)
        return np.arctan2(sn, sn_cn / sn)

    def _f(self, u):
        return (1.0 - u * u) * (self.alpha - self.beta * u) - (self.b - self.a * u) ** 2

    def _roots(self):
        """u1 ≤ u2 ≤ u3 of f(u) = β u³ − (α + a²) u² + (2ab − β) u + (α − b²), by numpy's companion matrix then two
        Newton steps each (f' = −2u (α − βu) − β (1 − u²) + 2a (b − a u))."""
        coefficients = [self.beta, -(self.alpha + self.a ** 2), 2.0 * self.a * self.b - self.beta,
                        self.alpha - self.b ** 2]
        roots = np.sort(np.real(np.roots(coefficients)))
        for _ in range(2):
            fp = (-2.0 * roots * (self.alpha - self.beta * roots) - self.beta * (1.0 - roots ** 2)
                  + 2.0 * self.a * (self.b - self.a * roots))
            roots = roots - np.where(fp != 0.0, self._f(roots) / np.where(fp != 0.0, fp, 1.0), 0.0)
        return np.sort(roots)

    @property
    def theta_min(self):
        return np.arccos(self.u2)

    @property
    def theta_max(self):
        return np.arccos(self.u1)

    @property
    def nutation_period(self):
        """2 K(m)/λ [s]."""
        return 2.0 * special.ellipk(self.m) / self.lam

    @property
    def mean_precession_rate(self):
        """φ's change over a nutation period / the period: am grows by π, each Π by 2 Π(n | m), so
        Δφ/T = [(b − a)/(1 − u1) Π(n+|m) + (b + a)/(1 + u1) Π(n−|m)] / (2 K(m))."""
        complete = lambda n: legendre_pi(n, np.pi / 2, self.m)  # noqa: E731
        return ((self.b - self.a) / (1.0 - self.u1) * complete(self.n_plus)
                + (self.b + self.a) / (1.0 + self.u1) * complete(self.n_minus)) / (2.0 * special.ellipk(self.m))

    def angles(self, t):
        """(φ, θ, ψ, φ̇, θ̇, ψ̇) at the time t [s] (a float)."""
        tau = self.tau0 + self.lam * t
        sn, cn, dn, ph = special.ellipj(tau, self.m)
        _, _, _, ph0 = special.ellipj(self.tau0, self.m)
        u = self.u1 + (self.u2 - self.u1) * sn * sn
        udot = 2.0 * (self.u2 - self.u1) * self.lam * sn * cn * dn
        plus = (legendre_pi(self.n_plus, ph, self.m) - legendre_pi(self.n_plus, ph0, self.m)) / self.lam
        minus = (legendre_pi(self.n_minus, ph, self.m) - legendre_pi(self.n_minus, ph0, self.m)) / self.lam
        cp, cm = (self.b - self.a) / (1.0 - self.u1), (self.b + self.a) / (1.0 + self.u1)
        phi = 0.5 * (cp * plus + cm * minus)
        psi = (self.omega3 - self.a) * t - 0.5 * (cp * plus - cm * minus)
        theta = np.arccos(u)
        phi_dot = (self.b - self.a * u) / (1.0 - u * u)
        return phi, theta, psi, phi_dot, -udot / np.sin(theta), self.omega3 - u * phi_dot

    def at(self, t):
        """(q_WB (x, y, z, w), w_B [rad/s]) at the time t [s]: R_WB = R_WN Rz(φ) Rx(θ) Rz(ψ) R_SB and the Z-X-Z
        angular velocity in S, ω_S = (φ̇ sθ sψ + θ̇ cψ, φ̇ sθ cψ − θ̇ sψ, φ̇ cθ + ψ̇)."""
        phi, theta, psi, phi_dot, theta_dot, psi_dot = self.angles(t)
        R_NS = _rotation_z(phi) @ _rotation_x(theta) @ _rotation_z(psi)
        w_S = np.array([phi_dot * np.sin(theta) * np.sin(psi) + theta_dot * np.cos(psi),
                        phi_dot * np.sin(theta) * np.cos(psi) - theta_dot * np.sin(psi),
                        phi_dot * np.cos(theta) + psi_dot])
        return matrix_to_quat(self.R_WN @ R_NS @ self.R_SB), self.R_SB.T @ w_S


# ---------------------------------------------------------------- constant thrust
def constant_thrust(m0, mass_rate, u_rel, g, p0, v0, t):
    """(p, v, m) at t [s] of the burn m v̇ = m g + ṁ u_rel (module docstring; ṁ ≠ 0). ln(m/m0) = log1p(ṁ t/m0)."""
    u_rel, g, p0, v0 = (np.asarray(x, float) for x in (u_rel, g, p0, v0))
    m = m0 + mass_rate * t
    log_ratio = np.log1p(mass_rate * t / m0)
    v = v0 + g * t + u_rel * log_ratio
    p = p0 + v0 * t + 0.5 * g * t * t + u_rel * (m / mass_rate * log_ratio - t)
    return p, v, m


def tsiolkovsky_delta_v(u_rel, m0, m1) -> float:
    """Δv = |u_rel| ln(m0/m1) [m/s] (Tsiolkovsky)."""
    return float(np.linalg.norm(u_rel) * np.log(m0 / m1))


__all__ = ["LagrangeTop", "PI_LOW", "constant_thrust", "legendre_pi", "pendulum_motion", "pendulum_omega0",
           "pendulum_period_from_rest", "pendulum_rotation_period", "tsiolkovsky_delta_v"]
