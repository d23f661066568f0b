"""The numpy reference of the magnetic dipole element (rigiddyn_ref.scene.magnetic_dipole) checked against
itself and the textbook, without rigiddyn: the dipole's field on and across its axis (Jackson, §5.6), the
force = −∇V and the torque = −∂V/∂θ by central differences (Jackson, §5.7: V = −m·B, τ = m × B), action and
reaction against the source (force and moment), and T + V conserved by the reference's RK4 at its order."""

import numpy as np
import pytest

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

EPS = np.finfo(float).eps
K = ref.MU0 / (4.0 * np.pi)  # μ0/(4π) [N/A²]
SEEDS = range(8)


def random_setup(rng):
    """A rigid body, a planar body and a particle (all listed) at 0.8–2 m from a source dipole of moment
    ~1e7 A m² (k |M| ~ 1 T m³) near W's origin, in a uniform field ≤ 1 T; the body dipole m_B ≤ 1 A m²: fields
    ~1 T, torques ~1 N m, forces ~1 N."""
    source_p_W = rng.uniform(-0.2, 0.2, 3)
    params = dict(m_B=rng.uniform(-1, 1, 3), B_W=rng.uniform(-1, 1, 3), source_moment_W=rng.uniform(-1e7, 1e7, 3),
                  source_p_W=source_p_W, bodies=[0, 1, 2])

    def around(z_free):
        direction = rng.normal(size=3)
        if not z_free:
            direction[2] = 0.0
        offset = rng.uniform(0.8, 2.0) * direction / np.linalg.norm(direction)
        return source_p_W + offset if z_free else np.append(source_p_W[:2] + offset[:2], 0.0)

    bodies = [ref.rigid(1.5, [0.2, 0.3, 0.4]), ref.planar(1.0, 0.3), ref.particle(0.7)]
    # the planar body's plane z = 0 passes within 0.2 m of the source: its distance is set in the plane only,
    # so that it stays ≥ 0.8 m
    kin = [ref.Kinematics(around(True), so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-1, 1, 3),
                          rng.uniform(-2, 2, 3)),
           ref.Kinematics(around(False), ref.rz_quat(rng.uniform(-3, 3)), np.append(rng.uniform(-1, 1, 2), 0.0),
                          np.array([0.0, 0.0, rng.uniform(-2, 2)])),
           ref.Kinematics(around(True), ref.IDENTITY, rng.uniform(-1, 1, 3), np.zeros(3))]
    return bodies, kin, ref.Element("MagneticDipole", params)


# ---------------------------------------------------------------- the field
def test_the_dipole_field_on_and_across_its_axis():
    """On the axis of M at distance r: B = 2 k M/r³ along M; in the plane through the dipole normal to M:
    B = −k M/r³ (Jackson, §5.6); a few roundings of each: 8 eps relative."""
    M, r = 3.0e6, 1.7
    axis = np.array([0.0, 0.6, 0.8])
    normal = np.array([0.0, 0.8, -0.6])
    on_axis = ref.dipole_field(M * axis, r * axis)
    across = ref.dipole_field(M * axis, r * normal)
    np.testing.assert_allclose(on_axis, 2 * K * M / r ** 3 * axis, rtol=0, atol=8 * EPS * 2 * K * M / r ** 3)
    np.testing.assert_allclose(across, -K * M / r ** 3 * axis, rtol=0, atol=8 * EPS * 3 * K * M / r ** 3)


def test_the_uniform_field_alone_is_defined_at_the_source_point():
    """Without a source moment the field is B_W everywhere (no 1/|r|³ term is evaluated, even at r = 0), and the
    element exerts no force: f = ∇(m·B_W) = 0."""
    B_W = np.array([0.1, -0.2, 0.3])
    np.testing.assert_array_equal(ref.magnetic_field(np.zeros(3), B_W, np.zeros(3), np.zeros(3)), B_W)
    bodies = [ref.rigid(1.0, [1.0, 2.0, 3.0])]
    kin = [ref.Kinematics(np.zeros(3), so3.rotvec_to_quat([0.1, 0.2, 0.3]), np.zeros(3), np.zeros(3))]
    effect = ref.magnetic_dipole(bodies, kin, 0.0, m_B=[1.0, 0.0, 0.0], B_W=B_W)
    assert np.all(effect.f_W == 0.0) and np.all(np.isfinite(effect.tau_B))


def test_particles_are_skipped_even_when_listed():
    """A particle has no attitude, so no dipole direction: no force, no torque, no potential."""
    effect = ref.magnetic_dipole([ref.particle(1.0)], [ref.Kinematics(np.ones(3), ref.IDENTITY, np.ones(3),
                                                                      np.zeros(3))], 0.0, m_B=[1.0, 2.0, 3.0],
                                 B_W=[0.5, 0.0, 0.0], source_moment_W=[0.0, 0.0, 1e7], bodies_acted=[0])
    assert np.all(effect.f_W == 0.0) and np.all(effect.tau_B == 0.0) and effect.potential == 0.0


# ---------------------------------------------------------------- force and torque from the potential
def potential_at(bodies, kin, element, body, k):
    """The element's potential with body's kinematics replaced by k."""
    moved = list(kin)
    moved[body] = k
    return ref.evaluate(element, bodies, moved, 0.0).potential


@pytest.mark.parametrize("seed", SEEDS)
def test_force_is_minus_the_gradient_of_the_potential(seed):
    """f_W = −∂V/∂p_W by central differences with h = 1e-5 m, on the rigid and the planar body (x, y: its
    plane). V = −m·B_W − k m·∇(M·∇ 1/|r|) is a second derivative of 1/|r|; its third derivative along e is a
    fifth one, a symmetric 5-linear form whose norm is its largest value on one unit vector (Banach's theorem
    on Hilbert spaces), 5! P_5/|r|⁶ ≤ 120/|r|⁶: truncation h²/6 |V'''| ≤ 20 h² k|m||M|/|r|⁶. Round-off: each V
    sums terms ≤ |m|(|B_W| + 4 k|M|/|r|³) with ≤ 16 roundings of eps, over 2h: ≤ 16 eps (terms)/h; and
    p ± h rounds the step by eps |p|, a relative eps |p|/h of |f|."""
    rng = np.random.default_rng(seed)
    bodies, kin, element = random_setup(rng)
    h = 1e-5
    effect = ref.evaluate(element, bodies, kin, 0.0)
    m, M, B = (np.linalg.norm(element.params[key]) for key in ("m_B", "source_moment_W", "B_W"))
    for body, coordinates in ((0, range(3)), (1, range(2))):
        k = kin[body]
        r = np.linalg.norm(k.p_W - element.params["source_p_W"])
        bound = (20 * h ** 2 * K * m * M / r ** 6 + 16 * EPS * m * (B + 4 * K * M / r ** 3) / h
                 + EPS * np.linalg.norm(k.p_W) / h * np.linalg.norm(effect.f_W[body]))
        for c in coordinates:
            step = h * np.eye(3)[c]
            gradient = (potential_at(bodies, kin, element, body, k._replace(p_W=k.p_W + step))
                        - potential_at(bodies, kin, element, body, k._replace(p_W=k.p_W - step))) / (2 * h)
            assert abs(effect.f_W[body, c] + gradient) <= bound, (body, c)


@pytest.mark.parametrize("seed", SEEDS)
def test_torque_is_minus_the_derivative_of_the_potential_under_a_body_frame_turn(seed):
    """tau_B = −∂V/∂δθ with R → R exp([δθ]×) (q → q ⊗ exp(δθ/2)) about each B axis of the rigid body, and
    about z (θ → θ + δ) for the planar body, by central differences with h = 2e-5 rad. V(δ) = −(R exp(δ[e]×)
    m_B)·B(p): its third derivative is −(R [e]×³ exp(δ[e]×) m_B)·B, ≤ |m||B(p)|: truncation h²/6 |m||B(p)|.
    Round-off: 16 eps |m|(|B_W| + 4 k|M|/|r|³)/h for V, and the turned quaternion rounds the angle by ≤ 4 eps,
    a relative 4 eps/h of |τ|."""
    rng = np.random.default_rng(seed)
    bodies, kin, element = random_setup(rng)
    h = 2e-5
    effect = ref.evaluate(element, bodies, kin, 0.0)
    m, M, B = (np.linalg.norm(element.params[key]) for key in ("m_B", "source_moment_W", "B_W"))
    for body, axes in ((0, range(3)), (1, [2])):
        k = kin[body]
        r = np.linalg.norm(k.p_W - element.params["source_p_W"])
        field = np.linalg.norm(ref.magnetic_field(k.p_W, element.params["B_W"], element.params["source_moment_W"],
                                                  element.params["source_p_W"]))
        bound = (h ** 2 / 6 * m * field + 16 * EPS * m * (B + 4 * K * M / r ** 3) / h
                 + 4 * EPS / h * np.linalg.norm(effect.tau_B[body]))
        for axis in axes:
            turned = [k._replace(q_WB=dyn.quat_product(k.q_WB, so3.rotvec_to_quat(s * h * np.eye(3)[axis])))
                      for s in (1, -1)]
            derivative = (potential_at(bodies, kin, element, body, turned[0])
                          - potential_at(bodies, kin, element, body, turned[1])) / (2 * h)
            assert abs(effect.tau_B[body, axis] + derivative) <= bound, (body, axis)


@pytest.mark.parametrize("seed", SEEDS)
def test_torque_is_m_cross_b_in_the_body_frame(seed):
    """τ_B = m_B × R_WBᵀ B(p) (Jackson, §5.7), by the rotation matrix instead of the quaternion: a dozen
    roundings of products ≤ |m||B|: 16 eps |m||B| (+ the same of the matrix's own rounding)."""
    rng = np.random.default_rng(seed)
    bodies, kin, element = random_setup(rng)
    effect = ref.evaluate(element, bodies, kin, 0.0)
    for body in (0, 1):
        k = kin[body]
        field = ref.magnetic_field(k.p_W, element.params["B_W"], element.params["source_moment_W"],
                                   element.params["source_p_W"])
        want = np.cross(element.params["m_B"], so3.quat_to_matrix(k.q_WB).T @ field)
        scale = np.linalg.norm(element.params["m_B"]) * np.linalg.norm(field)
        np.testing.assert_allclose(effect.tau_B[body], want, rtol=0, atol=32 * EPS * scale)


# ---------------------------------------------------------------- action and reaction
@pytest.mark.parametrize("seed", SEEDS)
def test_the_source_feels_the_opposite_force_and_the_moments_balance(seed):
    """Swap the roles: the source M at s in the field of the body's dipole m_W at p feels f_s =
    ∇_s (M·B_m(s)) = dipole_dipole_force(M, m_W, s − p), and the torque M × B_m(s). Newton's third law: f + f_s = 0;
    and the total moment about W's origin, p × f + m_W × B_M(p) + s × f_s + M × B_m(s), is zero (Rigid-body notes
    (4.49), strong form: the pair conserves angular momentum). Each force sums 4 terms ≤ 5 × 3 k|m||M|/|r|⁴ and
    each torque terms ≤ 4 k|m||M|/|r|³, each with ≤ 16 roundings: both sides 2 × 16 eps × (Σ |p||f|-scale +
    torque scale)."""
    rng = np.random.default_rng(seed)
    m_W, M_W = rng.uniform(-1, 1, 3), rng.uniform(-1e7, 1e7, 3)
    s = rng.uniform(-1, 1, 3)
    direction = rng.normal(size=3)
    p = s + rng.uniform(0.5, 2.0) * direction / np.linalg.norm(direction)
    r = np.linalg.norm(p - s)
    f = ref.dipole_dipole_force(m_W, M_W, p - s)
    f_s = ref.dipole_dipole_force(M_W, m_W, s - p)
    force_scale = 15 * K * np.linalg.norm(m_W) * np.linalg.norm(M_W) / r ** 4
    torque_scale = 4 * K * np.linalg.norm(m_W) * np.linalg.norm(M_W) / r ** 3
    np.testing.assert_allclose(f + f_s, 0.0, rtol=0, atol=2 * 16 * EPS * force_scale)
    moment = (np.cross(p, f) + np.cross(m_W, ref.dipole_field(M_W, p - s))
              + np.cross(s, f_s) + np.cross(M_W, ref.dipole_field(m_W, s - p)))
    scale = (np.linalg.norm(p) + np.linalg.norm(s)) * force_scale + 2 * torque_scale
    np.testing.assert_allclose(moment, 0.0, rtol=0, atol=2 * 16 * EPS * scale)


# ---------------------------------------------------------------- energy
def tumbling_near_a_source():
    """A 20 kg rigid body (I = diag(0.02, 0.03, 0.04) kg m²) spinning at ~3.7 rad/s, 0.7 m from a source
    dipole of 3e5 A m² (B ~ 0.2 T there) in a uniform 0.05 T field, m_B ~ 1 A m²: potential and kinetic energy
    exchange ~0.15 J over 2 s, the body drifts ~0.05 m under the ~0.5 N dipole force."""
    bodies = [ref.rigid(20.0, [0.02, 0.03, 0.04])]
    element = ref.Element("MagneticDipole", dict(m_B=[0.8, 0.3, -0.5], B_W=[0.0, 0.05, 0.02],
                                                 source_moment_W=[0.0, 0.0, 3e5], source_p_W=[0.1, -0.1, 0.0],
                                                 bodies=None))
    scene = ref.Scene(bodies, [element])
    kin = [ref.Kinematics(np.array([0.7, 0.1, 0.2]), so3.rotvec_to_quat([0.3, -0.4, 0.2]), np.array([0.0, 0.05, 0.0]),
                          np.array([3.0, -1.0, 2.0]))]
    return scene, ref.initial_state(scene, kin)


def energy_error(scene, y0, h, duration):
    """max |E − E0| over an RK4 run of `duration` [s] at step h [s], E = T + V; and the largest |T|, |V|."""
    ys = ref.rk4_run(scene, y0, h, int(round(duration / h)))
    T = np.array([ref.kinetic_energy(scene, y) for y in ys])
    V = np.array([ref.potential_energy(scene, y) for y in ys])
    return np.max(np.abs(T + V - T[0] - V[0])), max(np.max(np.abs(T)), np.max(np.abs(V)))


def test_reference_rk4_conserves_kinetic_plus_potential_energy_at_fourth_order():
    """The element is conservative (f·v + τ·ω = −dV/dt), so T + V is a first integral; RK4 keeps it to its
    global error C h⁴ (one C in the asymptotic regime): halving h = 0.01 s divides the largest drift over 2 s
    by 16 (asserted 10–26, which a first-order error in the power, 2, or a third-order one, 8, misses), and
    Richardson bounds the drift at h/2 by 2 |e(h) − e(h/2)|/15 (factor 2 for the next order's share,
    h ω ≤ 0.04 here), which is ≤ 1e-8 of the energy scale (the run's largest |T|, |V|). Round-off (400 steps ×
    16 eps of that scale, ~1e-12) is far below."""
    scene, y0 = tumbling_near_a_source()
    coarse, _ = energy_error(scene, y0, 0.01, 2.0)
    fine, scale = energy_error(scene, y0, 0.005, 2.0)
    assert 10 <= coarse / fine <= 26
    assert fine <= 2 * abs(coarse - fine) / 15 + 400 * 16 * EPS * scale
    assert fine <= 1e-8 * scale
