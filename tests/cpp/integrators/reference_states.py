"""Expected states for tests/cpp/integrators/test_every_model.cpp: every method of rigiddyn.methods()
stepped on every model type (particle, planar body, rigid body with a spherical, a principal and a
full inertia) under every load kind (none, fixed, turning), computed by the numpy reference
(tests/reference/rigiddyn_ref, which never imports rigiddyn).

    PYTHONPATH=tests/reference python3 tests/cpp/integrators/reference_states.py OUT.txt

ctest runs it as the fixture of the GoogleTest, so the expected states always come from the
reference as it stands. OUT.txt holds one block per case:

    case <model> <form> <kind> <method>    model: particle, planar, rigid; form: -, spherical, principal, full
    mass <kg>
    inertia <I_zz> (planar) | <9 entries of I, row-major> (rigid) | - (particle)   [kg m²]
    gravity <g_W (3)>                                                               [m/s²]
    load <world|body> <force (3)> <torque (3)>                                      (zero or more) [N], [N m]
    h <step [s]>
    steps <N>
    y0 <coordinates>                       the layout of the models (reference and core alike)
    y1 <coordinates after N steps>
    reference_bound <bound>                the reference's own stated error over the N steps, beyond
                                           round-off: its closed free flow (free_flow.step_error_bound,
                                           summed) for exact_flow_kick and exact, else 0
    end

The rigid-body methods are the reference's own (integrators.step, geometric.step). For a particle
and a planar body (no attitude, no gyroscopic term) the structure-preserving methods are, as the
core documents them: velocity Verlet kick(h/2) drift(h) kick(h/2) (splitting_dlm, exact_flow_kick,
exact), Yoshida's triple jump of it (splitting_dlm_yoshida4; Yoshida, Phys. Lett. A 150, 1990) and
the implicit midpoint rule y1 = y0 + h f((y0 + y1)/2) (Hairer, Lubich & Wanner, GNI I.1), composed
here from the reference models' kick, drift and rate.
"""

from __future__ import annotations

import sys

import numpy as np

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import free_flow, geometric
from rigiddyn_ref import integrators as ref

METHODS = ref.METHODS + geometric.METHODS  # every name of rigiddyn.methods()
STEPS = 10
H = 0.01
GRAVITY = np.array([0.3, -9.81, 0.0])  # in the xy plane, so that the planar body takes it too


def loads_of(model, kind, torque_free):
    """(gravity, schedule) of `kind`: none = no load, no gravity; fixed = gravity, a world force and a
    body couple (constant in their frames, independent of the attitude); turning = also a body force
    and a world couple (they turn with the body). `torque_free` leaves the couples out ('exact'); the
    particle takes no couple (and its 'body' force is a world force: it has no attitude), the planar
    body in-plane forces and couples about z."""
    if kind == "none":
        return np.zeros(3), []
    in_plane = np.array([1.0, 1.0, 0.0]) if model == "planar" else np.ones(3)
    about_z = np.array([0.0, 0.0, 1.0]) if model == "planar" else np.ones(3)
    couples = 0.0 if model == "particle" or torque_free else 1.0
    schedule = [dyn.Load(in_plane * [0.4, -0.2, 1.0], np.zeros(3), "world"),
                dyn.Load(np.zeros(3), couples * about_z * [-0.1, 0.2, 0.15], "body")]
    if kind == "turning":
        schedule += [dyn.Load(in_plane * [0.3, 0.1, -0.2], np.zeros(3), "body"),
                     dyn.Load(np.zeros(3), couples * about_z * [0.05, 0.1, -0.2], "world")]
    return GRAVITY, [load for load in schedule if np.any(load.force) or np.any(load.torque)]


# ---------------------------------------------------------------- models without attitude
def velocity_verlet(model, y, h):
    """Kick–drift–kick: the loads' exact flow over h/2 (their work the kinetic energy it gives), the free flow over
    h, the loads' over h/2 (the splittings and the exact free flow on a body without a gyroscopic term)."""
    y = np.array(y, dtype=float)
    model.loads_kick(y, h / 2)
    model.free_flow(y, h)
    model.loads_kick(y, h / 2)
    return y


def implicit_midpoint(model, y, h):
    """Fixed point ȳ = y0 + (h/2) f(ȳ) to round-off (a contraction: f is affine in the velocities
    here), then y1 = 2 ȳ − y0."""
    y0 = np.array(y, dtype=float)
    mid = y0.copy()
    for _ in range(geometric.MIDPOINT_MAX_ITERATIONS):
        new = y0 + 0.5 * h * model.rate(mid)
        done = np.all(np.abs(new - mid) <= np.finfo(float).eps * np.maximum(1.0, np.abs(new)))
        mid = new
        if done:
            return 2.0 * mid - y0
    raise FloatingPointError("implicit midpoint: no convergence")


def step_without_attitude(model, y, h, method):
    if method in ref.METHODS:
        return ref.step(model, y, h, method)
    if method == "implicit_midpoint":
        return implicit_midpoint(model, y, h)
    if method == "splitting_dlm_yoshida4":
        for gamma in (geometric.YOSHIDA_GAMMA1, geometric.YOSHIDA_GAMMA0, geometric.YOSHIDA_GAMMA1):
            y = velocity_verlet(model, y, gamma * h)
        return y
    return velocity_verlet(model, y, h)  # splitting_dlm, exact_flow_kick, exact


# ---------------------------------------------------------------- cases
def rigid_inertia(form):
    if form == "spherical":
        return 0.4 * np.eye(3)
    if form == "principal":
        return np.diag([1.0, 2.0, 3.0])
    axis = np.array([1.0, -2.0, 0.5]) / np.linalg.norm([1.0, -2.0, 0.5])  # the same moments, turned
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    R = np.eye(3) + np.sin(0.7) * K + (1.0 - np.cos(0.7)) * K @ K
    I = R @ np.diag([1.0, 2.0, 3.0]) @ R.T
    return 0.5 * (I + I.T)  # symmetric to the last bit


def numbers(x):
    return " ".join(repr(float(v)) for v in np.ravel(x))


def make_case(model_name, form, kind, method):
    gravity, schedule = loads_of(model_name, kind, torque_free=method == "exact")
    if model_name == "particle":
        model, inertia = ref.ParticleModel(2.0, gravity), "-"
        y0 = ref.ParticleModel.initial([0.1, -0.2, 0.3], [0.5, 0.2, -0.1])
    elif model_name == "planar":
        model, inertia = ref.PlanarBodyModel(2.0, 0.5, gravity), "0.5"
        y0 = ref.PlanarBodyModel.initial([0.1, -0.2], 0.7, [0.5, 0.2], 1.5)
    else:
        I = rigid_inertia(form)
        model, inertia = ref.RigidBodyModel(2.0, I, gravity), numbers(I)
        q0 = np.array([0.3, 0.9, -0.2]) / np.linalg.norm([0.3, 0.9, -0.2]) * np.sin(0.2)
        y0 = ref.RigidBodyModel.initial([0.1, -0.2, 0.3], np.append(q0, np.cos(0.2)), [0.5, 0.2, -0.1], [1.2, -0.7, 2.0])
    y, bound = np.array(y0), 0.0
    for i in range(STEPS):
        model.set_loads(dyn.loads_at(schedule, i * H))
        if model_name != "rigid":
            y = step_without_attitude(model, y, H, method)
            continue
        if method in ("exact_flow_kick", "exact"):  # the free flow starts after the first half kick
            after_kick = np.array(y)
            geometric.kick(model, after_kick, H / 2)
            bound += free_flow.step_error_bound(model.I, H, after_kick[10:13])
        y = ref.step(model, y, H, method) if method in ref.METHODS else geometric.step(model, y, H, method)
    lines = [f"case {model_name} {form} {kind} {method}", "mass 2.0", f"inertia {inertia}",
             "gravity " + numbers(gravity)]
    lines += [f"load {load.frame} " + numbers([load.force, load.torque]) for load in schedule]
    lines += [f"h {H!r}", f"steps {STEPS}", "y0 " + numbers(y0), "y1 " + numbers(y),
              f"reference_bound {float(bound)!r}", "end"]
    return "\n".join(lines)


def main(path):
    models = [("particle", "-"), ("planar", "-")] + [("rigid", form) for form in ("spherical", "principal", "full")]
    blocks = [make_case(model, form, kind, method)
              for model, form in models for kind in ("none", "fixed", "turning") for method in METHODS]
    with open(path, "w", encoding="utf-8") as out:
        out.write("# written by tests/cpp/integrators/reference_states.py from the numpy reference\n")
        out.write("\n".join(blocks) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: reference_states.py OUT.txt")
    main(sys.argv[1])
