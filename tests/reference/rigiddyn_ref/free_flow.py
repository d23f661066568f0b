"""The exact torque-free (Euler–Poinsot) flow over one step, in plain numpy: the reference's
"exact free flow" for exact_flow_kick and exact.

Theory (Landau & Lifshitz, Mechanics §37; Jacobi): principal moments I1 < I2 < I3, body angular
momentum m = I ω in the principal frame P, ṁ = m × ω, Ṙ_WP = R_WP ω̂, L_W = R_WP m constant.
With G² = |m|², 2T = Σ m_i²/I_i and Δ_j = G² − 2T I_j (Δ1, Δ3 summed without cancellation):
  case A (Δ2 ≥ 0): m = (I1 A1 cn, s I2 A2 sn, s I3 A3 dn)(u | k),  s = sign m3, dn axis 3
  case B (Δ2 < 0): m = (s I1 A1 dn, s I2 A2 sn, I3 A3 cn)(u | k),  s = sign m1, dn axis 1
  u = λ t + u0, amplitudes A_i, rate λ, parameter k and its complement 1 − k as in Landau &
  Lifshitz §37.

The route differs on purpose from rigiddyn's (which evaluates sn, cn, dn at λt + u0, with u0 from
Carlson's R_F, and the attitude through Legendre's Π):
- momentum: no phase u0 and no K. The current (sn, cn, dn) are read off m itself (dividing by the
  amplitudes) and advanced by the addition theorem (DLMF 22.8.1–3) by a small argument
  v = λ τ, |v| ≤ MAX_PHASE per sub-step; the functions of a small argument come from the
  arithmetic-geometric mean (DLMF 22.20(ii)) with 1 − k passed in, so no step ever evaluates them
  near K, where they lose precision as k → 1 (the separatrix).
- attitude: Z-X-Z angles about L (L&L §37) on the body axes (a, b, s), s the dn axis: θ and ψ are
  algebraic in m (cos θ = m_s/G, tan ψ = m_a/m_b), and the precession φ is the integral of
  φ̇ = G (m_a²/I_a + m_b²/I_b)/(m_a² + m_b²) > 0 by adaptive Gauss–Legendre quadrature; its
  error estimate (one rule against the same rule on the two halves) is asserted below
  QUADRATURE_TOLERANCE relative, else FloatingPointError.
- symmetric body (two moments within SYMMETRY_TOLERANCE): R(t) = exp(t G/I_t L̂_W) R0
  exp(t β ê_s), β = m_s (1/I_s − 1/I_t); sphere and steady spin: R0 exp(t ω̂).

Error bound per call (step_error_bound): with κ = I3/I1 (principal moments), for a call of one
sub-step (|λ h| ≤ MAX_PHASE, every call of the tests' steps),
  attitude error [rad] and |Δω|/|ω|  ≤  16 eps κ (1 + |h ω|):
the closed form itself is a fixed sequence of O(10) correctly rounded operations per sub-step on
quantities of size ≤ G, plus the quadrature's 8 eps |Δφ| (≤ 8 eps, measured ≤ 3 eps); the passage
ω → m = I ω → ω turns a relative error eps of m (size ≤ I3 |ω|) into κ eps of ω; the
eigen-decomposition of a full I is backward stable (an exact one of some I + δI,
|δI| ≤ ~3 eps |I|), which moves ω by ≤ ~3 κ eps (1 + |h ω|) over the step. Checked against a Taylor
series of Euler's equations in extended precision (tests/python/test_reference_selfcheck.py;
measured ≤ 4 κ eps there). Asserted in every call, cheaply: the identities sn² + cn² = 1 and
dn² + k sn² = 1 of the state read off m (≤ IDENTITY_TOLERANCE, which fails where amplitudes
underflow), the quadrature's error estimate, and the invariants |m| and T at the end of the
elliptic flow (≤ INVARIANT_TOLERANCE relative); FloatingPointError where one fails.
Between sub-steps the state is put back on its orbit (project: sn² + cn² = 1 by scaling, dn from
cn without cancellation), so round-off leaves only a shift of the phase u, which the flow keeps as a
shift (below), instead of a drift off the orbit that the walk amplifies exponentially near the
separatrix (measured: 1e-9 off it, 10 s in 40 sub-steps, |m| drifted by 8e3 eps without it).
A call of P > 1 sub-steps rounds P times, and the flow carries a shift of phase made at t_j to the
end scaled by |ṁ(t + h)|/|ṁ(t_j)|, up to A = max |ṁ| / min |ṁ| on the orbit (1/√(1 − k) near the
separatrix, unbounded on it): the bound is then 16 eps κ (P + |h ω|) A κ (the last κ: a phase
shift δt turns the attitude by |ω| δt, and |ω| varies by up to κ along the orbit).
"""

from __future__ import annotations

import numpy as np

from .so3 import axis_rotation, rotvec_to_matrix

EPS = np.finfo(float).eps
INVARIANT_TOLERANCE = 64 * EPS
MAX_PHASE = 0.5  # |v| per sub-step: sn²v ≤ tanh²0.5 < 0.22, so 1 − k sn²u sn²v ≥ 0.78
GAUSS_NODES = 10  # Gauss–Legendre, exact for degree 19
QUADRATURE_TOLERANCE = 8 * EPS  # relative; φ̇ > 0, so the sum has no cancellation
QUADRATURE_MAX_DEPTH = 30
IDENTITY_TOLERANCE = 32 * EPS
SYMMETRY_TOLERANCE = 64 * EPS  # relative to I3: what an eigen-decomposition of I resolves
AGM_MAX_ITERATIONS = 40

_GL_NODES, _GL_WEIGHTS = np.polynomial.legendre.leggauss(GAUSS_NODES)


def sorted_principal_frame(I):
    """(moments (3,) ascending [kg m²], R_BP (3, 3), det +1: columns the principal axes in B)."""
    I = np.asarray(I, float)
    if np.count_nonzero(I - np.diag(np.diag(I))) == 0:
        moments = np.diag(I).copy()
        order = np.argsort(moments, kind="stable")
        R_BP = np.eye(3)[:, order]
        moments = moments[order]
    else:
        moments, R_BP = np.linalg.eigh(I)
    if np.linalg.det(R_BP) < 0:
        R_BP[:, 2] *= -1.0
    return moments, R_BP


def jacobi_small(v, k, kc):
    """sn, cn, dn (v | k) for |v| ≤ MAX_PHASE, parameter k ∈ [0, 1] with its complement kc = 1 − k
    passed separately (it carries the precision near k = 1). Descending Landen / AGM (DLMF
    22.20(ii)): a0 = 1, b0 = √kc, c0 = √k; a_{n+1} = (a_n + b_n)/2, b_{n+1} = √(a_n b_n),
    c_{n+1} = c_n²/(4 a_{n+1}) until c_N ≤ eps a_N; φ_N = 2^N a_N v,
    φ_{n−1} = (φ_n + arcsin(c_n sin φ_n / a_n))/2; sn = sin φ0, cn = cos φ0 (> 0.87 here),
    dn = √(1 − k sn²) (≥ 0.88 here, no cancellation)."""
    v = np.asarray(v, float)
    if np.max(np.abs(v), initial=0.0) > MAX_PHASE:
        raise ValueError(f"v: expected |v| <= {MAX_PHASE}, got {np.max(np.abs(v))}")
    if kc == 0.0:  # k = 1 (DLMF 22.5.3)
        sech = 1.0 / np.cosh(v)
        return np.tanh(v), sech, sech
    a, b, c = [1.0], np.sqrt(kc), [np.sqrt(k)]
    while c[-1] > EPS * a[-1]:
        if len(a) > AGM_MAX_ITERATIONS:
            raise FloatingPointError(f"k: the AGM did not converge for k = {k}, 1 - k = {kc}")
        a_n = a[-1]
        a.append(0.5 * (a_n + b))
        b = np.sqrt(a_n * b)
        c.append(c[-1] ** 2 / (4.0 * a[-1]))
    phi = 2.0 ** (len(a) - 1) * a[-1] * v
    for n in range(len(a) - 1, 0, -1):
        phi = 0.5 * (phi + np.arcsin(c[n] / a[n] * np.sin(phi)))
    sn = np.sin(phi)
    return sn, np.cos(phi), np.sqrt(1.0 - k * sn * sn)


def jacobi_add(sn_u, cn_u, dn_u, sn_v, cn_v, dn_v, k):
    """(sn, cn, dn)(u + v | k) from those of u and of v (addition theorem, DLMF 22.8.1–3)."""
    d = 1.0 - k * sn_u**2 * sn_v**2
    return ((sn_u * cn_v * dn_v + sn_v * cn_u * dn_u) / d,
            (cn_u * cn_v - sn_u * dn_u * sn_v * dn_v) / d,
            (dn_u * dn_v - k * sn_u * cn_u * sn_v * cn_v) / d)


def _tilt(n):
    """Q = Rx(θ) Rz(ψ) with Q n = e_z for a unit n = (sin θ sin ψ, sin θ cos ψ, cos θ): the Z-X-Z
    angles θ, ψ of L&L §37 read off the momentum direction (ψ = 0 where sin θ = 0)."""
    rho = np.hypot(n[0], n[1])
    s_psi, c_psi = (n[0] / rho, n[1] / rho) if rho > 0.0 else (0.0, 1.0)
    Rz = np.array([[c_psi, -s_psi, 0.0], [s_psi, c_psi, 0.0], [0.0, 0.0, 1.0]])
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, n[2], -rho], [0.0, rho, n[2]]])
    return Rx @ Rz


class _EllipticOrbit:
    """The orbit of m (principal frame) through m0: amplitudes, rate, parameter and the (a, b, s)
    relabelling; `triple(m)` reads (sn, cn, dn) off a point of the orbit, `momentum` the reverse."""

    def __init__(self, I, m0):
        I1, I2, I3 = I
        m1, m2, m3 = m0
        self.I = I
        d1 = m2**2 * (I2 - I1) / I2 + m3**2 * (I3 - I1) / I3  # Δ1 ≥ 0
        d3 = m1**2 * (I1 - I3) / I1 + m2**2 * (I2 - I3) / I2  # Δ3 ≤ 0
        d2 = m1**2 * (I1 - I2) / I1 + m3**2 * (I3 - I2) / I3  # Δ2, sign picks the case
        if d2 >= 0.0:  # case A: circulates about axis 3
            self.perm = (0, 1, 2)
            self.sign = 1.0 if m3 >= 0.0 else -1.0
            A = np.sqrt([-d3 / (I1 * (I3 - I1)), -d3 / (I2 * (I3 - I2)), d1 / (I3 * (I3 - I1))])
            self.rate = np.sqrt((I3 - I2) * d1 / (I1 * I2 * I3))
            self.k = min(1.0, (I2 - I1) * -d3 / ((I3 - I2) * d1))
            self.kc = (I3 - I1) * d2 / ((I3 - I2) * d1)
            # m = (I1 A1 cn, s I2 A2 sn, s I3 A3 dn)
            self.scale = I * A * np.array([1.0, self.sign, self.sign])
            self.slots = (1, 0, 2)  # component i of m carries slot[i] of (sn, cn, dn)
        else:  # case B: circulates about axis 1
            self.perm = (1, 2, 0)
            self.sign = 1.0 if m1 >= 0.0 else -1.0
            A = np.sqrt([-d3 / (I1 * (I3 - I1)), d1 / (I2 * (I2 - I1)), d1 / (I3 * (I3 - I1))])
            self.rate = np.sqrt((I2 - I1) * -d3 / (I1 * I2 * I3))
            self.k = min(1.0, (I3 - I2) * d1 / ((I2 - I1) * -d3))
            self.kc = (I3 - I1) * -d2 / ((I2 - I1) * -d3)
            # m = (s I1 A1 dn, s I2 A2 sn, I3 A3 cn)
            self.scale = I * A * np.array([self.sign, self.sign, 1.0])
            self.slots = (2, 0, 1)
        self.deltas = (d1, d2, d3)

    def sub_steps(self, sigma):
        """Sub-steps of the addition theorem for a scaled time sigma = G h: |λ sigma| / P ≤ MAX_PHASE."""
        return max(1, int(np.ceil(abs(self.rate * sigma) / MAX_PHASE)))

    def phase_amplification(self):
        """A = max |ṁ| / min |ṁ| on the orbit (unit momentum). |ṁ|² = G² Σ m_i²/I_i² − (2T)² is
        linear in (m_1², m_2², m_3²), which run along a segment whose ends have one m_i = 0; there
        |ṁ|² = −Δ_j Δ_k / (I_j I_k) ({i, j, k} = {1, 2, 3}; the Δ carry no cancellation); the ends
        on the orbit are the two with a positive value (inf on the separatrix)."""
        d, I = self.deltas, self.I
        ends = [-d[j] * d[k] / (I[j] * I[k]) for j, k in ((1, 2), (0, 2), (0, 1))]
        ends = sorted(e for e in ends if e >= 0.0)[-2:]
        return np.sqrt(ends[-1] / ends[0]) if ends[0] > 0.0 else np.inf

    def triple(self, m):
        snd = [0.0, 0.0, 0.0]
        for i, slot in enumerate(self.slots):
            snd[slot] = m[i] / self.scale[i]
        sn, cn, dn = snd
        defect = max(abs(sn * sn + cn * cn - 1.0), abs(dn * dn + self.k * sn * sn - 1.0))
        if not defect <= IDENTITY_TOLERANCE:
            raise FloatingPointError(f"m: (sn, cn, dn) read off m = {m} miss their identities by {defect:.3g} "
                                     "(amplitudes underflow or the inertia is not resolved)")
        return sn, cn, dn

    def project(self, sn, cn, dn):
        """The point of the orbit at the phase of (sn, cn): (sn, cn) scaled onto the unit circle,
        dn = √(1 − k sn²) = √(kc + k cn²) > 0 (DLMF 22.6.1; no cancellation near k = 1)."""
        r = np.hypot(sn, cn)
        sn, cn = sn / r, cn / r
        return sn, cn, np.sqrt(self.kc + self.k * cn * cn)

    def momentum(self, sn, cn, dn):
        snd = (sn, cn, dn)
        return np.stack([self.scale[i] * snd[slot] for i, slot in enumerate(self.slots)], -1)

    def advance(self, triple, tau):
        """(sn, cn, dn) a time tau (scalar or array, |λ tau| ≤ MAX_PHASE) later."""
        return jacobi_add(*triple, *jacobi_small(self.rate * np.asarray(tau), self.k, self.kc), self.k)

    def precession_rate(self, n):
        """φ̇/G = (n_a²/I_a + n_b²/I_b)/(n_a² + n_b²) at unit momenta n (..., 3) [1/(kg m²)]."""
        a, b = self.perm[0], self.perm[1]
        na, nb = n[..., a], n[..., b]
        return (na * na / self.I[a] + nb * nb / self.I[b]) / (na * na + nb * nb)


def _gauss(f, t0, t1):
    half = 0.5 * (t1 - t0)
    return half * np.dot(_GL_WEIGHTS, f(t0 + half * (_GL_NODES + 1.0)))


def integrate_positive(f, t0, t1, depth=0):
    """∫ f over [t0, t1] for f > 0, vectorised f; adaptive Gauss–Legendre: accepts the two-half
    sum when it differs from the whole-interval rule by ≤ QUADRATURE_TOLERANCE relative (the rule
    of degree 19 on the halves is then far more accurate still); FloatingPointError otherwise."""
    mid = 0.5 * (t0 + t1)
    whole, halves = _gauss(f, t0, t1), _gauss(f, t0, mid) + _gauss(f, mid, t1)
    if abs(whole - halves) <= QUADRATURE_TOLERANCE * abs(halves):
        return halves
    if depth >= QUADRATURE_MAX_DEPTH:
        raise FloatingPointError(f"quadrature of the precession rate did not converge on [{t0}, {t1}]")
    return integrate_positive(f, t0, mid, depth + 1) + integrate_positive(f, mid, t1, depth + 1)


def _elliptic_flow(I, R_WP, m, h):
    """(R_WP, m) after h [s] for distinct moments I (ascending) and a momentum m off the axes.
    Works on the unit momentum n = m/G in the scaled time s = G t (the orbit's rate and φ̇ both
    scale with G): n(s) by the addition theorem, φ = ∫ φ̇ dt = ∫ f(n(s)) ds."""
    G = np.linalg.norm(m)
    orbit = _EllipticOrbit(I, m / G)
    C = np.eye(3)[:, orbit.perm]  # (a, b, s) coordinates to P: a cyclic relabelling, det +1
    R_WL = R_WP @ C @ _tilt(C.T @ (m / G)).T  # z along L_W; φ counted from the start
    triple = orbit.project(*orbit.triple(m / G))
    pieces = orbit.sub_steps(G * h)
    sigma = G * h / pieces  # scaled time per piece
    phi = 0.0
    for _ in range(pieces):
        def f(s, start=triple):
            return orbit.precession_rate(orbit.momentum(*orbit.advance(start, s)))

        phi += integrate_positive(f, 0.0, sigma) if sigma >= 0.0 else -integrate_positive(f, sigma, 0.0)
        triple = orbit.project(*(float(x) for x in orbit.advance(triple, sigma)))
    n1 = orbit.momentum(*triple)
    _check_invariants(I, m, G * n1)
    R = R_WL @ axis_rotation(2, phi) @ _tilt(C.T @ (n1 / np.linalg.norm(n1))) @ C.T
    return R, G * n1


def _symmetric_flow(I, R_WP, m, h, axis):
    """(R_WP, m) after h [s] when the two moments other than I[axis] are equal (within
    SYMMETRY_TOLERANCE, then taken as their mean I_t): R(t) = exp(t G/I_t L̂_W) R0 exp(t β ê_s),
    β = m_s (1/I_s − 1/I_t); m(t) = exp(−t β ê_s) m0."""
    I_t = 0.5 * (np.sum(I) - I[axis])
    beta = m[axis] * (1.0 / I[axis] - 1.0 / I_t)
    L_W = R_WP @ m
    R = rotvec_to_matrix(h / I_t * L_W) @ R_WP @ axis_rotation(axis, h * beta)
    return R, axis_rotation(axis, -h * beta) @ m


def step_error_bound(I, h, w_B):
    """Bound on the error of free_rotation(I, ., w_B, h): attitude [rad] and |Δω|/|ω| (module
    docstring): 16 eps κ (1 + |h ω|), κ = I3/I1, for one sub-step of the elliptic flow (or any
    other branch); 16 eps κ (P + |h ω|) A κ for P > 1 sub-steps (phase shifts amplified by A)."""
    moments, R_BP = sorted_principal_frame(I)
    kappa = moments[2] / moments[0]
    bound = 16.0 * EPS * kappa * (1.0 + abs(h) * np.linalg.norm(w_B))
    m = moments * (R_BP.T @ np.asarray(w_B, float))
    if _branch(moments, m) != "elliptic":
        return bound
    G = np.linalg.norm(m)
    orbit = _EllipticOrbit(moments, m / G)
    pieces = orbit.sub_steps(G * h)
    if pieces == 1:
        return bound
    return 16.0 * EPS * kappa * (pieces + abs(h) * np.linalg.norm(w_B)) * orbit.phase_amplification() * kappa


def _branch(moments, m):
    """Which form of the flow applies: 'constant' (sphere, rest or a steady spin about a principal
    axis: ω constant), 'symmetric' (two moments within SYMMETRY_TOLERANCE) or 'elliptic'."""
    spread = SYMMETRY_TOLERANCE * moments[2]
    transverse_zero = [np.count_nonzero(np.delete(m, i)) == 0 for i in range(3)]
    if moments[2] - moments[0] <= spread or not np.any(m) or any(transverse_zero):
        return "constant"
    if moments[1] - moments[0] <= spread or moments[2] - moments[1] <= spread:
        return "symmetric"
    return "elliptic"


def free_rotation(I, R_WB, w_B, h):
    """The exact Euler–Poinsot flow over h [s]: (R_WB, w_B) at t + h from R_WB (B to W) and w_B
    [rad/s] (angular velocity of B in W, expressed in B) at t; I: inertia about the centre of mass
    in B [kg m²]. Error ≤ step_error_bound(I, h, w_B) (module docstring); FloatingPointError where
    an assertion of that accuracy fails."""
    moments, R_BP = sorted_principal_frame(I)
    R_WP, m = R_WB @ R_BP, moments * (R_BP.T @ np.asarray(w_B, float))
    spread = SYMMETRY_TOLERANCE * moments[2]
    branch = _branch(moments, m)
    if branch == "constant":
        w_P = m / moments
        R_WP1, m1 = R_WP @ rotvec_to_matrix(h * w_P), m.copy()
    elif branch == "symmetric":
        axis = 2 if moments[1] - moments[0] <= spread else 0
        R_WP1, m1 = _symmetric_flow(moments, R_WP, m, h, axis)
    else:
        R_WP1, m1 = _elliptic_flow(moments, R_WP, m, h)
    return R_WP1 @ R_BP.T, R_BP @ (m1 / moments)


def _check_invariants(I, m0, m1):
    """|m| and 2T = Σ m_i²/I_i at the end equal those at the start to INVARIANT_TOLERANCE relative."""
    for name, a, b in (("|m|", np.linalg.norm(m0), np.linalg.norm(m1)),
                       ("2T", np.sum(m0**2 / I), np.sum(m1**2 / I))):
        if not abs(b - a) <= INVARIANT_TOLERANCE * a:
            raise FloatingPointError(f"free flow: {name} changed from {a!r} to {b!r} in one step")
