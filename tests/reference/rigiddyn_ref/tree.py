"""Kinematic trees from the definitions, without Featherstone's recursions.

A tree is a list of links (plain dicts, :func:`link`): parent index (-1 for the world W), joint kind
and axis, placement (R_T, p_T) of the joint frame in the parent's frame, and the link's mass, centre of
mass and inertia about it (in the link frame). Joint conventions are those of rigiddyn's joint classes:
revolute/prismatic q (1,), spherical q = (x, y, z, w) with the angular velocity in the link frame, free
q = (p, x, y, z, w) with the link-frame twist [w; v], fixed (no coordinate).

Each quantity comes from its definition, link by link, in world coordinates:

- poses X_Wi as 4x4 homogeneous matrices, composed along the path from the root;
- the world Jacobian J_i (6, nv): column k is the spatial twist (at W's origin, expressed in W,
  angular first) that a unit velocity of coordinate k gives link i, Ad(X_Wj) S_j for the joints j that
  support i, 0 for the others;
- the mass matrix H = sum_i J_i^T M_i J_i (T = 1/2 v^T H v, M_i the 6x6 inertia in W);
- inverse dynamics by the principle of virtual power, tau = sum_i J_i^T (M_i A_i + V_i x* M_i V_i - f_i),
  with V_i = J_i v, A_i = J_i a + Jdot_i v and Jdot_i v = sum_j (V_j x) (Ad(X_Wj) S_j qd_j) (a column fixed in
  link j moves with link j's twist), f_i the gravity wrench and the external wrench in W.
"""

from __future__ import annotations

import numpy as np

from rigiddyn_ref import so3

KINDS = {"revolute": (1, 1), "prismatic": (1, 1), "spherical": (4, 3), "free": (7, 6), "fixed": (0, 0)}


def hat(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def rotation_about(axis, angle):
    """Rodrigues' formula R = 1 + sin(θ) [a]x + (1 - cos θ) [a]x² for a unit axis a."""
    K = hat(axis)
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * K @ K


def quat_matrix(q):
    """R(q) of a unit quaternion (x, y, z, w), Hamilton convention, active."""
    x, y, z, w = np.asarray(q) / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def homogeneous(R, p):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


def motion_adjoint(T):
    """Ad(X): twist in B -> twist in A for T = X_AB, angular first: [[R, 0], [p^ R, R]]."""
    R, p = T[:3, :3], T[:3, 3]
    Ad = np.zeros((6, 6))
    Ad[:3, :3] = Ad[3:, 3:] = R
    Ad[3:, :3] = hat(p) @ R
    return Ad


def crm(V):
    """V x (motion cross product), angular first."""
    out = np.zeros((6, 6))
    out[:3, :3] = out[3:, 3:] = hat(V[:3])
    out[3:, :3] = hat(V[3:])
    return out


def spatial_inertia(mass, com, inertia_com):
    """6x6 inertia about the frame's origin, angular first: [[I_C + m c^ c^T, m c^], [m c^T, m 1]]."""
    C = hat(com)
    return np.block([[inertia_com + mass * C @ C.T, mass * C], [mass * C.T, mass * np.eye(3)]])


def link(parent, kind, mass, com, inertia_com, axis=(0.0, 0.0, 1.0), R_T=np.eye(3), p_T=np.zeros(3)):
    return {"parent": parent, "kind": kind, "axis": np.asarray(axis, float) / np.linalg.norm(axis),
            "R_T": np.asarray(R_T, float), "p_T": np.asarray(p_T, float), "mass": float(mass),
            "com": np.asarray(com, float), "inertia_com": np.asarray(inertia_com, float)}


def sizes(links):
    """(idx_q, idx_v) of each link and (nq, nv)."""
    idx, nq, nv = [], 0, 0
    for l in links:
        idx.append((nq, nv))
        dq, dv = KINDS[l["kind"]]
        nq, nv = nq + dq, nv + dv
    return idx, nq, nv


def joint_matrix(l, q):
    """X_J(q) as a 4x4 matrix and the motion subspace S (6, nv) in the link frame."""
    kind, a = l["kind"], l["axis"]
    if kind == "revolute":
        return homogeneous(rotation_about(a, q[0]), np.zeros(3)), np.concatenate([a, np.zeros(3)])[:, None]
    if kind == "prismatic":
        return homogeneous(np.eye(3), a * q[0]), np.concatenate([np.zeros(3), a])[:, None]
    if kind == "spherical":
        return homogeneous(quat_matrix(q), np.zeros(3)), np.vstack([np.eye(3), np.zeros((3, 3))])
    if kind == "free":
        return homogeneous(quat_matrix(q[3:]), q[:3]), np.eye(6)
    return np.eye(4), np.zeros((6, 0))


def poses(links, q):
    """X_Wi (n, 4, 4) and the world columns Ad(X_Wi) S_i of each joint."""
    idx, _, _ = sizes(links)
    T_W, columns = [], []
    for i, l in enumerate(links):
        nq = KINDS[l["kind"]][0]
        X_J, S = joint_matrix(l, q[idx[i][0]:idx[i][0] + nq])
        T = homogeneous(l["R_T"], l["p_T"]) @ X_J
        T_W.append(T if l["parent"] < 0 else T_W[l["parent"]] @ T)
        columns.append(motion_adjoint(T_W[i]) @ S)
    return np.array(T_W), columns


def supports(links, i):
    """The links on the path from i to the root, i included."""
    path = []
    while i >= 0:
        path.append(i)
        i = links[i]["parent"]
    return path


def jacobians(links, q):
    """World Jacobians J_i (n, 6, nv) and the world columns of each joint."""
    idx, _, nv = sizes(links)
    T_W, columns = poses(links, q)
    J = np.zeros((len(links), 6, nv))
    for i in range(len(links)):
        for j in supports(links, i):
            J[i][:, idx[j][1]:idx[j][1] + columns[j].shape[1]] = columns[j]
    return J, T_W, columns


def inertias_in_world(links, T_W):
    """M_i in W about W's origin: Ad^-T M_i Ad^-1."""
    out = []
    for l, T in zip(links, T_W):
        Ad_inv = np.linalg.inv(motion_adjoint(T))
        out.append(Ad_inv.T @ spatial_inertia(l["mass"], l["com"], l["inertia_com"]) @ Ad_inv)
    return out


def mass_matrix(links, q):
    """H = sum_i J_i^T M_i J_i."""
    J, T_W, _ = jacobians(links, q)
    M = inertias_in_world(links, T_W)
    return sum(J[i].T @ M[i] @ J[i] for i in range(len(links)))


def link_twists(links, q, v):
    """Each link's twist expressed in its own frame, (n, 6): Ad(X_Wi)^-1 J_i v."""
    J, T_W, _ = jacobians(links, q)
    return np.array([np.linalg.solve(motion_adjoint(T_W[i]), J[i] @ v) for i in range(len(links))])


def inverse_dynamics(links, q, v, a, gravity=np.zeros(3), f_ext=None):
    """tau = sum_i J_i^T (M_i A_i + V_i x* M_i V_i - f_gravity,i - f_ext,i), all in W (module docstring)."""
    idx, _, _ = sizes(links)
    J, T_W, columns = jacobians(links, q)
    M = inertias_in_world(links, T_W)
    V = [J[i] @ v for i in range(len(links))]
    tau = np.zeros(len(v))
    for i, l in enumerate(links):
        # Jdot_i v = sum over supports j of V_j x (column_j qd_j)
        Jdot_v = sum(crm(V[j]) @ columns[j] @ v[idx[j][1]:idx[j][1] + columns[j].shape[1]] for j in supports(links, i))
        A = J[i] @ a + Jdot_v
        f = M[i] @ A - crm(V[i]).T @ M[i] @ V[i]  # V x* = -crm(V)^T
        c_W = T_W[i][:3, :3] @ l["com"] + T_W[i][:3, 3]
        f -= np.concatenate([np.cross(c_W, l["mass"] * gravity), l["mass"] * gravity])
        if f_ext is not None:  # the link-frame wrench in W: Ad^-T f
            f -= np.linalg.inv(motion_adjoint(T_W[i])).T @ f_ext[i]
        tau += J[i].T @ f
    return tau


def forward_dynamics(links, q, v, tau, gravity=np.zeros(3), f_ext=None):
    """a = H^-1 (tau - C), C = inverse_dynamics(a = 0)."""
    C = inverse_dynamics(links, q, v, np.zeros(len(v)), gravity, f_ext)
    return np.linalg.solve(mass_matrix(links, q), tau - C)


def potential_energy(links, q, gravity):
    T_W, _ = poses(links, q)
    return -sum(l["mass"] * gravity @ (T[:3, :3] @ l["com"] + T[:3, 3]) for l, T in zip(links, T_W))


def quat_rate(q, w_L):
    """q̇ = ½ q ⊗ (w_L, 0) for q = (x, y, z, w) and the angular velocity w_L in the moving frame (the quaternion
    kinematics of the "Rigid body kinematics and dynamics" notes; Solà (2017), the local form)."""
    x, y, z, s = q
    return 0.5 * np.array([s * w_L[0] + y * w_L[2] - z * w_L[1], s * w_L[1] + z * w_L[0] - x * w_L[2],
                           s * w_L[2] + x * w_L[1] - y * w_L[0], -(x * w_L[0] + y * w_L[1] + z * w_L[2])])


def configuration_rate(links, q, v):
    """q̇ (nq,) of the velocity v, joint by joint: qd for revolute and prismatic joints, ½ q ⊗ (w_L, 0) for a
    quaternion, ṗ_JL = R(q_JL) v_L for a free joint's position (its twist [w_L; v_L] is in the link frame)."""
    idx, nq, _ = sizes(links)
    q_dot = np.zeros(nq)
    for l, (iq, iv) in zip(links, idx):
        if l["kind"] in ("revolute", "prismatic"):
            q_dot[iq] = v[iv]
        elif l["kind"] == "spherical":
            q_dot[iq:iq + 4] = quat_rate(q[iq:iq + 4], v[iv:iv + 3])
        elif l["kind"] == "free":
            q_dot[iq:iq + 3] = quat_matrix(q[iq + 3:iq + 7]) @ v[iv + 3:iv + 6]
            q_dot[iq + 3:iq + 7] = quat_rate(q[iq + 3:iq + 7], v[iv:iv + 3])
    return q_dot


def kinetic_energy_gradient(links, q, v):
    """∂T/∂q (nv,) at fixed v for revolute, prismatic and fixed joints, from T = 1/2 sum_i V_i . M_i V_i in W.

    Turning q_j moves the subtree of j by the world twist c_j = Ad(X_Wj) S_j: each of its columns c_k changes by
    c_j x c_k (so V_i by c_j x (V_i - V_parent(j))) and each of its inertias M_i by -crm(c_j)^T M_i - M_i crm(c_j);
    the sum is -sum over the subtree of (M_i V_i) . (c_j x V_parent(j)).
    """
    idx, _, nv = sizes(links)
    J, T_W, columns = jacobians(links, q)
    M = inertias_in_world(links, T_W)
    V = [J[i] @ v for i in range(len(links))]
    dT_dq = np.zeros(nv)
    for j, l in enumerate(links):
        if l["kind"] not in ("revolute", "prismatic"):
            continue
        V_parent = V[l["parent"]] if l["parent"] >= 0 else np.zeros(6)
        c_j = columns[j][:, 0]
        dT_dq[idx[j][1]] = -sum(M[i] @ V[i] @ (crm(c_j) @ V_parent) for i in range(len(links)) if j in supports(links, i))
    return dT_dq


def variational_midpoint_step(links, q0, v0, h, generalized_force):
    """One step of the variational integrator of the midpoint discrete Lagrangian L_d = h T((q0 + q1)/2,
    (q1 - q0)/h) with the midpoint forces (Marsden & West 2001, the discrete Lagrange-d'Alembert principle) for a
    tree of revolute, prismatic and fixed joints: the discrete Euler-Lagrange equations p0 = -∂L_d/∂q0 - (h/2) Q,
    p1 = ∂L_d/∂q1 + (h/2) Q with p = H(q) v, i.e.

        H(q̄) v̄ = p0 + (h/2) F(q̄, v̄),  q̄ = q0 + (h/2) v̄,  q1 = q0 + h v̄,  H(q1) v1 = p0 + h F(q̄, v̄),

    F = ∂T/∂q + Q, Q = generalized_force(q, v) (every applied force, gravity included). Solved by Newton's method
    with a central-difference Jacobian (it sets only the rate of convergence) until the correction is at round-off.
    """
    p0 = mass_matrix(links, q0) @ v0

    def force(q, v):
        return kinetic_energy_gradient(links, q, v) + generalized_force(q, v)

    def residual(v_bar):
        q_bar = q0 + 0.5 * h * v_bar
        return mass_matrix(links, q_bar) @ v_bar - p0 - 0.5 * h * force(q_bar, v_bar)

    v_bar = v0.copy()
    for _ in range(50):
        eps = 1e-6 * (1.0 + np.abs(v_bar))
        jac = np.column_stack([(residual(v_bar + e) - residual(v_bar - e)) / (2.0 * e[k])
                               for k, e in enumerate(np.diag(eps))])
        step = np.linalg.solve(jac, residual(v_bar))
        v_bar -= step
        if np.linalg.norm(step) <= 1e-14 * (1.0 + np.linalg.norm(v_bar)):  # Newton: the error is now ~ step²
            break
    q_bar = q0 + 0.5 * h * v_bar
    q1 = q0 + h * v_bar
    return q1, np.linalg.solve(mass_matrix(links, q1), p0 + h * force(q_bar, v_bar))


def _retract(links, q0, phi):
    """q0 ⊕ φ joint by joint: angles and offsets added, a quaternion q0 ⊗ exp(φ_ω) (the body frame), a free joint's
    position p0 + φ_p in the parent's frame."""
    idx, _, _ = sizes(links)
    q = q0.copy()
    for l, (iq, iv) in zip(links, idx):
        if l["kind"] in ("revolute", "prismatic"):
            q[iq] = q0[iq] + phi[iv]
        elif l["kind"] == "spherical":
            q[iq:iq + 4] = so3.quat_multiply(q0[iq:iq + 4], so3.rotvec_to_quat(phi[iv:iv + 3]))
        elif l["kind"] == "free":
            q[iq:iq + 3] = q0[iq:iq + 3] + phi[iv + 3:iv + 6]
            q[iq + 3:iq + 7] = so3.quat_multiply(q0[iq + 3:iq + 7], so3.rotvec_to_quat(phi[iv:iv + 3]))
    return q


def group_discrete_lagrangian(links, qa, qb, h, gravity):
    """L_d(qa, qb) = h L(q̄, w) on the curve of constant joint velocity from qa to qb: per rotation (ball joint, a free
    joint's attitude) ξ = log(R_aᵀ R_b), its midpoint R_a exp(ξ/2) and body rate w = ξ/h; per vector part the
    straight line, its midpoint and slope; a free joint's v_L = R̄ᵀ (p_b − p_a)/h. L = ½ vᵀ H v − V of gravity."""
    idx, _, nv = sizes(links)
    half, w = np.zeros(nv), np.zeros(nv)
    for l, (iq, iv) in zip(links, idx):
        if l["kind"] in ("revolute", "prismatic"):
            half[iv], w[iv] = 0.5 * (qb[iq] - qa[iq]), (qb[iq] - qa[iq]) / h
        elif l["kind"] in ("spherical", "free"):
            at = iq if l["kind"] == "spherical" else iq + 3
            xi = so3.quat_to_rotvec(so3.quat_multiply(so3.quat_inverse(qa[at:at + 4]), qb[at:at + 4]))
            half[iv:iv + 3], w[iv:iv + 3] = 0.5 * xi, xi / h
            if l["kind"] == "free":
                dp = qb[iq:iq + 3] - qa[iq:iq + 3]
                R_bar = quat_matrix(so3.quat_multiply(qa[at:at + 4], so3.rotvec_to_quat(0.5 * xi)))
                half[iv + 3:iv + 6], w[iv + 3:iv + 6] = 0.5 * dp, R_bar.T @ dp / h
    q_bar = _retract(links, qa, half)
    return h * (0.5 * w @ mass_matrix(links, q_bar) @ w - potential_energy(links, q_bar, gravity))


def _chart_momentum(links, q, p):
    """The momentum conjugate to the chart q ⊕ φ at φ = 0 of the body momentum p: p itself but a free joint's
    linear part, R p_v (the chart moves its position in the parent's frame)."""
    idx, _, _ = sizes(links)
    out = p.copy()
    for l, (iq, iv) in zip(links, idx):
        if l["kind"] == "free":
            out[iv + 3:iv + 6] = quat_matrix(q[iq + 3:iq + 7]) @ p[iv + 3:iv + 6]
    return out


def group_variational_midpoint_step(links, q0, v0, h, gravity, eps=1e-6):
    """One step of the variational integrator of group_discrete_lagrangian for any joints: the discrete Legendre
    transforms p0 = −D₁L_d(q0, q1), p1 = D₂L_d(q0, q1) along body perturbations q ⊕ δ, by central differences of
    step eps (error ~ eps² |L_d'''| + eps_machine |L_d| / eps), the first solved for q1 = q0 ⊕ φ₁ by a simplified
    Newton iteration (its Jacobian by differences too, at the first guess: it sets only the rate of convergence),
    p = H(q) v."""
    nv = len(v0)
    zero = np.zeros(nv)

    def gradient(f):
        return np.array([(f(zero + e) - f(zero - e)) / (2.0 * eps) for e in np.eye(nv) * eps])

    p0 = _chart_momentum(links, q0, mass_matrix(links, q0) @ v0)

    def residual(phi1):
        q1 = _retract(links, q0, phi1)
        return -gradient(lambda d: group_discrete_lagrangian(links, _retract(links, q0, d), q1, h, gravity)) - p0

    phi1 = h * v0.copy()
    jac = np.column_stack([(residual(phi1 + e) - residual(phi1 - e)) / (2.0 * eps) for e in np.eye(nv) * eps])
    for _ in range(30):  # the simplified Newton iteration: its Jacobian at the first guess
        step = np.linalg.solve(jac, residual(phi1))
        phi1 -= step
        if np.linalg.norm(step) <= 1e-13 * (1.0 + np.linalg.norm(phi1)):
            break
    q1 = _retract(links, q0, phi1)
    p1 = gradient(lambda d: group_discrete_lagrangian(links, q0, _retract(links, q1, d), h, gravity))
    idx, _, _ = sizes(links)
    for l, (iq, iv) in zip(links, idx):  # back to body momenta
        if l["kind"] == "free":
            p1[iv + 3:iv + 6] = quat_matrix(q1[iq + 3:iq + 7]).T @ p1[iv + 3:iv + 6]
    return q1, np.linalg.solve(mass_matrix(links, q1), p1)
