"""Mass properties in plain numpy: point sets, primitives, meshes, parallel axis, rotation,
principal axes, composites and the 6x6 spatial inertia.

A body's mass properties are an `Inertia(mass, com, inertia_com)`: mass m [kg], centre of mass c
[m] and rotational inertia I_C about the centre of mass [kg m^2], both in one frame. Primitives
are built in their natural frame (centre of mass at the origin, symmetry axis z). Where the core
uses a handbook formula, this reference derives the value another way when one is at hand
(composites of simpler parts, quadrature rules exact for quadratics, Eberly's surface integrals),
so that the two are independent.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .so3 import hat


class Inertia(NamedTuple):
    mass: float
    com: np.ndarray
    inertia_com: np.ndarray


def _mass(measure: float, mass=None, density=None) -> float:
    """Total mass from a given mass, or density times the volume/area/length `measure`."""
    if (mass is None) == (density is None):
        raise ValueError("give exactly one of mass and density")
    return float(mass) if mass is not None else float(density) * measure


def _diag(m: float, moments) -> Inertia:
    return Inertia(m, np.zeros(3), np.diag(np.asarray(moments, dtype=float)))


# ---------------------------------------------------------------- point sets and shifts
def point_inertia(mass, r) -> np.ndarray:
    """Inertia of a point mass m at r about the origin: m (|r|^2 1 - r r^T) = -m [r]x [r]x
    (Rigid-body notes (4.71))."""
    return -np.asarray(mass, dtype=float)[..., None, None] * (hat(r) @ hat(r))


def from_point_masses(masses, positions) -> Inertia:
    """m = Σ m_i (Rigid-body notes (4.53)), c = Σ m_i r_i / m (4.54),
    I_C = Σ m_i (|r_i - c|^2 1 - (r_i - c)(r_i - c)^T) (Rigid-body notes (4.70) as a sum)."""
    masses = np.asarray(masses, dtype=float)
    positions = np.asarray(positions, dtype=float)
    m = masses.sum()
    c = masses @ positions / m
    return Inertia(m, c, point_inertia(masses, positions - c).sum(axis=0))


def inertia_about_point(body: Inertia, point) -> np.ndarray:
    """Parallel axis (Craig "[I]_2 = [I]_C + m [[b²+c², -ab, -ac], ...]"): I_P = I_C + m (|r|^2 1 -
    r r^T), r = c - p. Written element by element as in Craig."""
    a, b, c = np.asarray(body.com, dtype=float) - np.asarray(point, dtype=float)
    shift = np.array([[b * b + c * c, -a * b, -a * c],
                      [-a * b, c * c + a * a, -b * c],
                      [-a * c, -b * c, a * a + b * b]])
    return body.inertia_com + body.mass * shift


def from_inertia_about_point(mass, com, inertia_about_p, point) -> Inertia:
    """The parallel axis theorem the other way: I_C = I_P - m (|r|^2 1 - r r^T), r = c - p."""
    com = np.asarray(com, dtype=float)
    return Inertia(float(mass), com,
                   np.asarray(inertia_about_p, float) - point_inertia(mass, com - np.asarray(point)))


def rotated(body: Inertia, R_AB) -> Inertia:
    """Re-expressed in A: c_A = R c_B, I_A = R I_B R^T (tensor transformation rule)."""
    R = np.asarray(R_AB, dtype=float)
    return Inertia(body.mass, R @ body.com, R @ body.inertia_com @ R.T)


def transformed(body: Inertia, R_AB, p_AB) -> Inertia:
    """Re-expressed in A by X_AB: c_A = R c_B + p, I_A = R I_B R^T (about the same centre of mass)."""
    r = rotated(body, R_AB)
    return Inertia(r.mass, r.com + np.asarray(p_AB, dtype=float), r.inertia_com)


def composite(parts) -> Inertia:
    """Parts in one frame: m = Σ m_i, c = Σ m_i c_i / m (Rigid-body notes (4.54)), I_C = Σ [I_i + m_i
    (|d_i|^2 1 - d_i d_i^T)], d_i = c_i - c (parallel axis for each part)."""
    m = sum(p.mass for p in parts)
    c = sum(p.mass * np.asarray(p.com, dtype=float) for p in parts) / m
    inertia = sum(inertia_about_point(p, c) for p in parts)
    return Inertia(m, c, inertia)


def remove(body: Inertia, part: Inertia) -> Inertia:
    """The rest of `body` after taking out `part` (a hole): composite solved for the rest,
    m_r = m - m_p, c_r = (m c - m_p c_p)/m_r, I_r about c_r = I_body(c_r) - I_part(c_r)."""
    m = body.mass - part.mass
    c = (body.mass * np.asarray(body.com) - part.mass * np.asarray(part.com)) / m
    return Inertia(m, c, inertia_about_point(body, c) - inertia_about_point(part, c))


# ---------------------------------------------------------------- derived quantities
def spatial_inertia_matrix(body: Inertia) -> np.ndarray:
    """6x6 spatial inertia about the frame's origin, angular first (RBDA (2.63)):
    [[I_C + m [c]x [c]x^T, m [c]x], [m [c]x^T, m 1]]."""
    C = hat(body.com)
    m = body.mass
    return np.block([[body.inertia_com + m * C @ C.T, m * C], [m * C.T, m * np.eye(3)]])


def momentum(body: Inertia, twist) -> np.ndarray:
    """Spatial momentum h = I V about the origin for the twist V = [w; v_O] (RBDA (2.62))."""
    return spatial_inertia_matrix(body) @ np.asarray(twist, dtype=float)


def kinetic_energy(body: Inertia, twist) -> float:
    """T = 1/2 m v_C·v_C + 1/2 w·I_C w with v_C = v_O + w x c (Craig "Kinetic Energy")."""
    twist = np.asarray(twist, dtype=float)
    w, v_O = twist[:3], twist[3:]
    v_C = v_O + np.cross(w, body.com)
    return 0.5 * body.mass * v_C @ v_C + 0.5 * w @ body.inertia_com @ w


def angular_momentum_about_com(body: Inertia, w) -> np.ndarray:
    """H_C = I_C w (Rigid-body notes (4.67))."""
    return body.inertia_com @ np.asarray(w, dtype=float)


def angular_momentum_about_point(body: Inertia, w, v_C, point) -> np.ndarray:
    """H_P = r_PC x L + H_C, L = m v_C (Craig "H_P = (r^PC x L) + H")."""
    r_PC = np.asarray(body.com, dtype=float) - np.asarray(point, dtype=float)
    return np.cross(r_PC, body.mass * np.asarray(v_C, float)) + angular_momentum_about_com(body, w)


def principal_axes(inertia):
    """Principal moments (ascending) and axes (columns, right-handed) of a symmetric inertia (Craig,
    "Principal Axes") by numpy's symmetric eigensolver. Sign convention for distinct moments:
    axes 0 and 1 with their largest-magnitude component positive, axis 2 = axis 0 x axis 1."""
    moments, axes = np.linalg.eigh(np.asarray(inertia, dtype=float))
    for k in (0, 1):
        a = axes[:, k]
        if a[np.argmax(np.abs(a))] < 0.0:
            axes[:, k] = -a
    axes[:, 2] = np.cross(axes[:, 0], axes[:, 1])
    return moments, axes


def triangle_margins(inertia) -> np.ndarray:
    """(I1 + I2 - I0, I0 + I2 - I1, I0 + I1 - I2) of the ascending principal moments."""
    I0, I1, I2 = np.linalg.eigvalsh(np.asarray(inertia, dtype=float))
    return np.array([I1 + I2 - I0, I0 + I2 - I1, I0 + I1 - I2])


# ---------------------------------------------------------------- primitives
def solid_sphere(radius, mass=None, density=None) -> Inertia:
    """I = 2/5 m r^2 (integral of (x²+y²) over the ball)."""
    m = _mass(4.0 / 3.0 * np.pi * radius**3, mass, density)
    return _diag(m, [0.4 * m * radius**2] * 3)


def hollow_sphere(outer_radius, inner_radius, mass=None, density=None) -> Inertia:
    """Solid sphere R minus solid sphere r of the same density (remove)."""
    volume = 4.0 / 3.0 * np.pi * (outer_radius**3 - inner_radius**3)
    rho = _mass(volume, mass, density) / volume
    return remove(solid_sphere(outer_radius, density=rho), solid_sphere(inner_radius, density=rho))


def spherical_shell(radius, mass=None, density=None) -> Inertia:
    """Thin shell: I = 2/3 m r^2 (the limit of hollow_sphere as the wall thins: d/dr of r^5 over
    d/dr of r^3 gives 2/5 · 5/3 r^2)."""
    m = _mass(4.0 * np.pi * radius**2, mass, density)
    return _diag(m, [2.0 / 3.0 * m * radius**2] * 3)


def solid_box(size, mass=None, density=None) -> Inertia:
    """I = m/12 diag(b²+c², a²+c², a²+b²)."""
    a, b, c = np.asarray(size, dtype=float)
    m = _mass(a * b * c, mass, density)
    return _diag(m, [m / 12 * (b * b + c * c), m / 12 * (a * a + c * c), m / 12 * (a * a + b * b)])


def _plate(size_u, size_v, normal_axis: int, offset: float, sigma: float) -> Inertia:
    """A thin plate of area density sigma, edges size_u, size_v along the two axes other than
    `normal_axis` (in increasing order), centred at offset along normal_axis."""
    u, v = [k for k in range(3) if k != normal_axis]
    m = sigma * size_u * size_v
    second = np.zeros(3)  # diagonal of the second moment ∫ x x^T dA about the plate's centre
    second[u], second[v] = m * size_u**2 / 12, m * size_v**2 / 12
    com = np.zeros(3)
    com[normal_axis] = offset
    return Inertia(m, com, np.trace(np.diag(second)) * np.eye(3) - np.diag(second))


def thin_plate(size_x, size_y, mass=None, density=None) -> Inertia:
    """Plate in the xy plane: I = m/12 diag(b², a², a²+b²)."""
    m = _mass(size_x * size_y, mass, density)
    return _plate(size_x, size_y, 2, 0.0, m / (size_x * size_y))


def box_shell(size, mass=None, density=None) -> Inertia:
    """The six faces as thin plates, composed with the parallel axis theorem (composite)."""
    a, b, c = np.asarray(size, dtype=float)
    area = 2.0 * (a * b + b * c + a * c)
    sigma = _mass(area, mass, density) / area
    faces = [_plate(b, c, 0, s * a / 2, sigma) for s in (-1, 1)]
    faces += [_plate(a, c, 1, s * b / 2, sigma) for s in (-1, 1)]
    faces += [_plate(a, b, 2, s * c / 2, sigma) for s in (-1, 1)]
    return composite(faces)


def solid_cylinder(radius, height, mass=None, density=None) -> Inertia:
    """I_zz = m r²/2, I_xx = I_yy = m (3 r² + h²)/12."""
    m = _mass(np.pi * radius**2 * height, mass, density)
    t = m * (3 * radius**2 + height**2) / 12
    return _diag(m, [t, t, m * radius**2 / 2])


def hollow_cylinder(outer_radius, inner_radius, height, mass=None, density=None) -> Inertia:
    """Solid cylinder R minus solid cylinder r of the same density and height (remove)."""
    volume = np.pi * (outer_radius**2 - inner_radius**2) * height
    rho = _mass(volume, mass, density) / volume
    return remove(solid_cylinder(outer_radius, height, density=rho),
                  solid_cylinder(inner_radius, height, density=rho))


def thin_rod(length, mass=None, density=None) -> Inertia:
    """Rod along z: I_xx = I_yy = m L²/12, I_zz = 0."""
    m = _mass(length, mass, density)
    return _diag(m, [m * length**2 / 12, m * length**2 / 12, 0.0])


def thin_disk(radius, mass=None, density=None) -> Inertia:
    """Disk in the xy plane: I_zz = m r²/2 (polar), I_xx = I_yy = I_zz/2 (perpendicular axis)."""
    m = _mass(np.pi * radius**2, mass, density)
    return _diag(m, [m * radius**2 / 4, m * radius**2 / 4, m * radius**2 / 2])


def solid_cone(radius, height, mass=None, density=None) -> Inertia:
    """Apex at z = +3h/4, base at z = -h/4. About the apex: I_zz = 3/10 m r², I_xx = 3/20 m r² +
    3/5 m h²; parallel axis to the centre of mass (3h/4 from the apex)."""
    m = _mass(np.pi * radius**2 * height / 3, mass, density)
    about_apex = np.diag([0.15 * m * radius**2 + 0.6 * m * height**2] * 2 + [0.3 * m * radius**2])
    return from_inertia_about_point(m, np.zeros(3), about_apex, [0.0, 0.0, 0.75 * height])


def solid_ellipsoid(semi_axes, mass=None, density=None) -> Inertia:
    """The unit ball's second moment diag(1,1,1) m/5 scaled by the semi-axes: C = m/5 diag(a², b², c²),
    I = tr(C) 1 - C."""
    a, b, c = np.asarray(semi_axes, dtype=float)
    m = _mass(4.0 / 3.0 * np.pi * a * b * c, mass, density)
    C = np.diag([a * a, b * b, c * c]) * m / 5
    return Inertia(m, np.zeros(3), np.trace(C) * np.eye(3) - C)


def _hemisphere(radius, rho, up: bool, base_z: float) -> Inertia:
    """Solid hemisphere of density rho with its flat face at z = base_z, dome up or down. About the
    sphere centre I = 2/5 m r² (half a sphere); centre of mass 3r/8 from the flat face."""
    m = rho * 2.0 / 3.0 * np.pi * radius**3
    centre = np.array([0.0, 0.0, base_z])
    com = centre + np.array([0.0, 0.0, (0.375 if up else -0.375) * radius])
    return from_inertia_about_point(m, com, 0.4 * m * radius**2 * np.eye(3), centre)


def solid_capsule(radius, length, mass=None, density=None) -> Inertia:
    """Cylinder (radius r, length h along z) plus two hemispherical caps, composed (composite)."""
    volume = np.pi * radius**2 * length + 4.0 / 3.0 * np.pi * radius**3
    rho = _mass(volume, mass, density) / volume
    parts = [_hemisphere(radius, rho, True, length / 2), _hemisphere(radius, rho, False, -length / 2)]
    if length > 0:
        parts.append(solid_cylinder(radius, length, density=rho))
    return composite(parts)


# Degree-2 rule for a tetrahedron (Keast 1986, 4 points): barycentric (a, b, b, b) and permutations,
# weights V/4, exact for quadratics such as x x^T.
_TET_A = (5.0 + 3.0 * np.sqrt(5.0)) / 20.0
_TET_B = (5.0 - np.sqrt(5.0)) / 20.0


def solid_tetrahedron(v0, v1, v2, v3, mass=None, density=None) -> Inertia:
    """m = ρ V, c = mean vertex, C = ∫ρ d d^T dV by the 4-point degree-2 rule, I = tr(C) 1 - C."""
    verts = np.array([v0, v1, v2, v3], dtype=float)
    volume = abs(np.linalg.det(verts[1:] - verts[0])) / 6.0
    m = _mass(volume, mass, density)
    c = verts.mean(axis=0)
    bary = np.full((4, 4), _TET_B) + np.eye(4) * (_TET_A - _TET_B)
    d = bary @ verts - c
    C = m / 4.0 * d.T @ d
    return Inertia(m, c, np.trace(C) * np.eye(3) - C)


# ---------------------------------------------------------------- meshes
def _eberly_subexpressions(w0, w1, w2):
    """Eberly (2002) "Polyhedral Mass Properties (Revisited)": the per-face polynomial terms."""
    temp0 = w0 + w1
    f1 = temp0 + w2
    temp1 = w0 * w0
    temp2 = temp1 + w1 * temp0
    f2 = temp2 + w2 * f1
    f3 = w0 * temp1 + w1 * temp2 + w2 * f2
    g0 = f2 + w0 * (f1 + w0)
    g1 = f2 + w1 * (f1 + w1)
    g2 = f2 + w2 * (f1 + w2)
    return f1, f2, f3, g0, g1, g2


def _volume_integrals(vertices, faces) -> np.ndarray:
    """∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx over the solid, by the divergence theorem
    reduced to face sums (Eberly 2002, after Mirtich 1996), vectorised over the faces."""
    p = np.asarray(vertices, dtype=float)[np.asarray(faces)]  # (f, 3 vertices, 3 coords)
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    e1, e2 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    d = np.cross(e1, e2)  # (d0, d1, d2) = edge cross product
    f1x, f2x, f3x, g0x, g1x, g2x = _eberly_subexpressions(x[:, 0], x[:, 1], x[:, 2])
    _, f2y, f3y, g0y, g1y, g2y = _eberly_subexpressions(y[:, 0], y[:, 1], y[:, 2])
    _, f2z, f3z, g0z, g1z, g2z = _eberly_subexpressions(z[:, 0], z[:, 1], z[:, 2])
    terms = np.stack([
        d[:, 0] * f1x,
        d[:, 0] * f2x, d[:, 1] * f2y, d[:, 2] * f2z,
        d[:, 0] * f3x, d[:, 1] * f3y, d[:, 2] * f3z,
        d[:, 0] * (y[:, 0] * g0x + y[:, 1] * g1x + y[:, 2] * g2x),
        d[:, 1] * (z[:, 0] * g0y + z[:, 1] * g1y + z[:, 2] * g2y),
        d[:, 2] * (x[:, 0] * g0z + x[:, 1] * g1z + x[:, 2] * g2z),
    ])
    mult = np.array([1 / 6, 1 / 24, 1 / 24, 1 / 24, 1 / 60, 1 / 60, 1 / 60, 1 / 120, 1 / 120, 1 / 120])
    return terms.sum(axis=1) * mult


def mesh_volume(vertices, faces) -> float:
    """Signed volume enclosed by the faces (positive for outward normals)."""
    origin = np.asarray(vertices, dtype=float).mean(axis=0)
    return float(_volume_integrals(np.asarray(vertices, dtype=float) - origin, faces)[0])


def solid_mesh(vertices, faces, mass=None, density=None) -> Inertia:
    """Uniform solid bounded by a closed outward-oriented mesh (Eberly's integrals, computed about
    the mean vertex to avoid cancellation, then moved back)."""
    vertices = np.asarray(vertices, dtype=float)
    origin = vertices.mean(axis=0)
    k = _volume_integrals(vertices - origin, faces)
    volume = k[0]
    m = _mass(volume, mass, density)
    rho = m / volume
    c = k[1:4] / volume  # relative to origin
    # second moment about the centre of mass: ∫ d d^T = ∫ x x^T - V c c^T
    S = np.array([[k[4], k[7], k[9]], [k[7], k[5], k[8]], [k[9], k[8], k[6]]])
    C = rho * (S - volume * np.outer(c, c))
    return Inertia(m, c + origin, np.trace(C) * np.eye(3) - C)


def mesh_shell(vertices, faces, mass=None, density=None) -> Inertia:
    """Thin shell of uniform area density on the faces. Per triangle the edge-midpoint rule
    ∫ f dA = A/3 Σ f(midpoints), exact for quadratics, gives area, first and second moments."""
    p = np.asarray(vertices, dtype=float)[np.asarray(faces)]
    areas = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=-1)
    mids = 0.5 * (p + np.roll(p, -1, axis=1))  # (f, 3, 3): midpoints of the three edges
    area = areas.sum()
    m = _mass(area, mass, density)
    sigma = m / area
    w = np.repeat(areas / 3.0, 3)
    pts = mids.reshape(-1, 3)
    c = w @ pts / area
    d = pts - c
    C = sigma * (d.T * w) @ d
    return Inertia(m, c, np.trace(C) * np.eye(3) - C)
