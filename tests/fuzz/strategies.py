"""Hypothesis strategies that draw call specs (see api_model) for every target of the public API.

Each argument is either *plausible* (what its annotation, its name and the docstring's shapes suggest:
unit quaternions, rotations, symmetric positive inertias, method names, objects built by the API's own
constructors and factories, each possibly scaled by a magnitude from 1e-323 to 1e308) or *wild* (any
type; arrays of random shape, dtype (float64/32/16, int, bool, complex, object, big-endian) and layout
(Fortran, reversed, strided, unaligned); magnitudes log-uniform from 1e-323 to 1e308 of both signs,
NaN, inf, subnormals, the largest double; empty and 0-d arrays; read-only broadcast views with up to
1e12 rows). A call has all arguments plausible (half the calls), exactly one wild, or each wild by a coin flip;
shrinking moves toward plausible values and omitted optional arguments, so a reproducer keeps only
what makes it fail.
"""

from __future__ import annotations

import functools
import math
import re

import numpy as np
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from api_model import Param, Target, public_classes
from scene_files import TORTURE, UNITS, scene_texts

OMIT = object()  # an optional argument left out
MAX_DEPTH = 3  # nesting of objects built to be passed to (or called as `self` of) a target

NAN, INF = float("nan"), float("inf")

# ---------------------------------------------------------------------------------------------
# numbers

SIGN = st.sampled_from([1.0, -1.0])
# log-uniform magnitudes over the whole double range, 1e-323 (subnormal) .. 1e308, of both signs
# (shrinks to 1.0); the boundary values themselves, where scalings overflow or underflow
EXTREME = st.builds(lambda s, m, e: s * m * 10.0**e, SIGN, st.floats(1.0, 10.0, exclude_max=True), st.integers(-323, 307))
POSITIVE_EXTREME = st.builds(lambda m, e: m * 10.0**e, st.floats(1.0, 10.0, exclude_max=True), st.integers(-323, 307))
POSITIVE_BOUNDARY = st.sampled_from([1e300, 1e306, 1.7976931348623157e308, 1e-300, 2.2250738585072014e-308, 5e-324,
                                     1e154, 1e-154])
MODERATE = st.builds(lambda m, e: m * 10.0**e, st.floats(1.0, 10.0, exclude_max=True), st.integers(-3, 3))
SPECIAL = st.one_of(st.sampled_from([NAN, INF, -INF, 0.0, -0.0, 2.0**53 + 2.0]), POSITIVE_BOUNDARY,
                    POSITIVE_BOUNDARY.map(lambda x: -x))
FLOATS = st.one_of(MODERATE, EXTREME, SPECIAL)
UNIT_INTERVAL = st.floats(0.0, 1.0)
PLAIN = st.one_of(st.floats(-10.0, 10.0), MODERATE)
PLAUSIBLE_FLOAT = st.one_of(MODERATE, st.sampled_from([0.0, 1.0, 0.5, 0.1, 2.0]), UNIT_INTERVAL,
                            st.floats(-10.0, 10.0), POSITIVE_EXTREME, POSITIVE_BOUNDARY)
POSITIVE_FLOAT = st.one_of(MODERATE, st.sampled_from([1.0, 0.5, 2.0]), POSITIVE_EXTREME, POSITIVE_BOUNDARY)
INTS = st.one_of(st.integers(-3, 20),
                 st.sampled_from([2**31 - 1, 2**31, 2**32, 2**53 + 1, 2**63 - 1, 2**63, 2**64, -2**63, -2**63 - 1, 10**30]),
                 st.builds(lambda s, e: int(s) * 10**e, SIGN, st.integers(0, 25)))
SMALL_INT = st.integers(0, 30)
COMPLEX = st.builds(complex, FLOATS, FLOATS)
NUMPY_SCALAR = st.one_of(st.builds(np.float32, FLOATS), st.builds(np.float64, FLOATS), st.builds(np.float16, FLOATS),
                         st.builds(np.int64, st.integers(-2**63, 2**63 - 1)), st.builds(np.bool_, st.booleans()))
# strings stay inside the worker's scratch directory when used as paths: no separator
SAFE_TEXT = st.text(alphabet=st.characters(blacklist_characters="/\\", blacklist_categories=("Cs",)), max_size=10)


def lit(strategy):
    return strategy.map(lambda v: ("lit", v))


def _call_spec(path, args=(), **kwargs):
    return ("call", path, list(args), list(kwargs.items()))


# A scene of a particle and a rigid body under gravity (body indices 0 and 1), and its initial states.
_SCENE = _call_spec("Scene", bodies=("list", [_call_spec("Particle", [("lit", 2.0)]),
                                              _call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])])]),
                    elements=("list", [_call_spec("UniformGravity")]))
_PIVOTED = _call_spec("PivotedBody", [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])]),
                                      ("lit", [0.0, 0.0, 0.5])])
# a gyrostat: a body with one wheel along z
_WHEEL = _call_spec("Wheel", [("lit", [0.0, 0.0, 1.0]), ("lit", 0.05)])
_GYROSTAT = _call_spec("Gyrostat", [_call_spec("RigidBody", [("lit", 100.0), ("lit", [10.0, 12.0, 15.0])]),
                                    ("list", [_WHEEL])])
_SCENE_STATES = ("list", [_call_spec("ParticleState", v_W=("lit", [0.0, 1.0, 0.0])),
                          _call_spec("RigidBodyState", w_B=("lit", [0.1, 1.0, 0.1]))])
# a one-link tree (a rod on a revolute joint) in a scene, and its link's body (a TreeLink: Scene.add_tree makes them)
_TREE = ("chain", _call_spec("Tree"), [("add_link", [("lit", "rod"), ("lit", -1), _call_spec("RevoluteJoint"),
                                                     _call_spec("SpatialInertia", [("lit", 1.0), ("lit", [0.5, 0.0, 0.0]),
                                                                                   ("lit", [[1e-3, 0.0, 0.0], [0.0, 0.1, 0.0],
                                                                                            [0.0, 0.0, 0.1]])])], [])])
_TREE_LINK = ("method", ("method", ("chain", _call_spec("Scene"), [("add_tree", [_TREE], [])]), "__getattribute__",
                         [("lit", "bodies")], []), "__getitem__", [("lit", 0)], [])

# Objects that only a run makes (a body's SceneResult: simulate needs a body and a state of the same kind;
# SceneResult: a scene and one state per body), or that random
# arguments rarely make (a scene with bodies, compilable; loads on body 0), built by a valid call with drawn
# sizes, so that every such class's methods are fuzzed on every machine.
RECIPES = {
    "BodySceneResult": st.tuples(st.integers(0, 30), st.integers(1, 5)).map(lambda nr: _call_spec(
        "simulate",
        [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])]),
         _call_spec("RigidBodyState", w_B=("lit", [0.1, 1.0, 0.1]))],
        dt=("lit", 0.01), steps=("lit", nr[0]), record_every=("lit", nr[1]))),
    "Scene": st.just(_SCENE),
    "CompiledScene": st.sampled_from(["rk4", "splitting_dlm", "implicit_midpoint"]).map(
        lambda method: ("method", _SCENE, "compile", [("lit", method)], [])),
    "SceneResult": st.tuples(st.integers(0, 30), st.integers(1, 5)).map(lambda nr: _call_spec(
        "simulate", [_SCENE, _SCENE_STATES], dt=("lit", 0.01), steps=("lit", nr[0]), record_every=("lit", nr[1]))),
    # batches of drawn sizes: of a scene (samples, steps), of a body (samples, steps, record_every, the SIMD path
    # across up to 9 samples: lanes and remainders)
    "BatchSceneResult": st.one_of(
        st.tuples(st.integers(1, 3), st.integers(0, 30)).map(lambda sn: _call_spec(
            "simulate_batch", [_SCENE, ("list", [_SCENE_STATES] * sn[0])], dt=("lit", 0.01), steps=("lit", sn[1]))),
        st.tuples(st.integers(1, 9), st.integers(0, 30), st.integers(1, 5), st.booleans()).map(
            lambda snrs: _call_spec(
                "simulate_batch",
                [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])]),
                 ("list", [_call_spec("RigidBodyState", w_B=("lit", [0.1 * k, 1.0, 0.1])) for k in range(snrs[0])])],
                dt=("lit", 0.01), steps=("lit", snrs[1]), record_every=("lit", snrs[2]), threads=("lit", 2),
                simd=("lit", snrs[3])))),
    # a density integral needs a callable rho: a constant density per point, over a drawn box
    "DensityIntegral": st.floats(0.1, 10.0).map(lambda rho: _call_spec(
        "integrate_density_over_box", [("per_row", ("lit", rho)), ("lit", [0.0, 0.0, 0.0]), ("lit", [1.0, 2.0, 0.5])])),
    "ScheduledLoads": st.just(_call_spec("ScheduledLoads", body=("lit", 0),
                                         loads=("list", [_call_spec("AppliedLoad", force=("lit", [1.0, 0.0, 0.0]))]))),
    # bodies about a fixed point: a top pinned below its centre of mass; the frames of a scene; a pivoted
    # run's records
    "PivotedBody": st.just(_PIVOTED),
    "PivotedPlanarBody": st.just(_call_spec("PivotedPlanarBody", [("lit", 1.0), ("lit", 0.1), ("lit", [0.0, -0.5])])),
    "ReactionWheel": st.tuples(st.floats(-100.0, 100.0), st.floats(-10.0, 10.0)).map(lambda sa: _call_spec(
        "ReactionWheel", body=("lit", 1), axis_B=("lit", [0.0, 0.6, 0.8]), inertia=("lit", 0.01), speed=("lit", sa[0]),
        acceleration=("lit", sa[1]))),
    # an atmosphere, exponential (a drawn scale height) or tabulated (two rows, drawn densities)
    "AtmosphericDrag": st.tuples(st.booleans(), st.floats(1e-3, 1.0), st.floats(1e-3, 1.0)).map(
        lambda tab: _call_spec("AtmosphericDrag", radius=("lit", 2.0), drag_area=("lit", 0.5),
                               **({"table_altitude": ("lit", [0.0, 5.0]), "table_density": ("lit", [tab[1], tab[2]])}
                                  if tab[0] else {"density0": ("lit", tab[1]), "scale_height": ("lit", 10.0 * tab[2])}))),
    # a gyrostat with a wheel whose motor torque and initial speed are drawn
    "Wheel": st.floats(-1.0, 1.0).map(lambda u: _call_spec("Wheel", [("lit", [0.0, 0.0, 1.0]), ("lit", 0.05)],
                                                         motor_torque=("lit", u))),
    "Gyrostat": st.just(_GYROSTAT),
    "TreeLink": st.just(_TREE_LINK),
    # the joint elements with drawn stiffness and damping, torque or force and end (their body a tree link of a
    # scene's: Scene.add checks it)
    "RevoluteSpringDamper": st.tuples(st.floats(0.0, 100.0), st.floats(0.0, 10.0)).map(lambda kc: _call_spec(
        "RevoluteSpringDamper", body=("lit", 0), stiffness=("lit", kc[0]), damping=("lit", kc[1]))),
    "PrismaticSpringDamper": st.tuples(st.floats(0.0, 100.0), st.floats(0.0, 10.0)).map(lambda kc: _call_spec(
        "PrismaticSpringDamper", body=("lit", 0), stiffness=("lit", kc[0]), damping=("lit", kc[1]))),
    "RevoluteMotor": st.tuples(st.floats(-100.0, 100.0), st.floats(0.0, 10.0)).map(lambda ut: _call_spec(
        "RevoluteMotor", body=("lit", 0), torque=("lit", ut[0]), t_end=("lit", ut[1] + 0.1))),
    "PrismaticMotor": st.tuples(st.floats(-100.0, 100.0), st.floats(0.0, 10.0)).map(lambda ut: _call_spec(
        "PrismaticMotor", body=("lit", 0), force=("lit", ut[0]), t_end=("lit", ut[1] + 0.1))),
    "SphericalSpringDamper": st.tuples(st.floats(0.0, 100.0), st.floats(-3.0, 3.0), st.floats(0.0, 10.0)).map(
        lambda kac: _call_spec("SphericalSpringDamper", body=("lit", 0), stiffness=("lit", kac[0]),
                               rest_rotation=("lit", [0.0, kac[1], 0.0]), damping=("lit", kac[2]))),
    "GyrostatState": st.floats(-100.0, 100.0).map(lambda w: _call_spec(
        "GyrostatState", w_B=("lit", [0.1, 0.0, 0.2]), wheel_speeds=("lit", [w]))),
    "Thrust": st.sampled_from(["body", "world"]).map(lambda frame: _call_spec(
        "Thrust", [("lit", 0), ("lit", [0.0, 0.0, -100.0])], frame=("lit", frame))),
    "SceneFrame": st.sampled_from([_call_spec("SceneFrame.rotating", [("lit", [0.0, 0.0, 1.0]), ("lit", 0.5)]),
                                   _call_spec("SceneFrame.earth", [("lit", 0.85)])]),
    "PivotedAcceleration": st.just(_call_spec("forward_dynamics", [_PIVOTED, _call_spec("PivotedBodyState")],
                                              gravity=("lit", True))),
    # their exact references: a pendulum at a drawn angle and rate (libration or rotation), a symmetric top
    # (inertia about O symmetric about O->C) tilted by a drawn angle about x with a drawn spin (not 0: its axis would
    # swing through the vertical, refused), a particle seen from a rotating frame, a rocket losing mass at a drawn rate
    "CompoundPendulumSolution": st.tuples(st.floats(-3.1, 3.1), st.floats(-20.0, 20.0)).map(lambda tw: _call_spec(
        "CompoundPendulumSolution", [_call_spec("PivotedPlanarBody", [("lit", 1.0), ("lit", 0.1), ("lit", [0.0, -0.5])]),
                                     ("lit", [0.0, -9.81]),
                                     _call_spec("PivotedPlanarBodyState", theta=("lit", tw[0]), omega=("lit", tw[1]))])),
    "LagrangeTopSolution": st.tuples(st.floats(0.1, 3.0), SIGN, st.floats(1.0, 20.0)).map(lambda ts: _call_spec(
        "LagrangeTopSolution", [_call_spec("PivotedBody", [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 1.0, 0.5])]),
                                                           ("lit", [0.0, 0.0, 0.2])]),
                                ("lit", [0.0, 0.0, -9.81]),
                                _call_spec("PivotedBodyState", w_B=("lit", [0.1, 0.0, ts[1] * ts[2]]),
                                           q_WB=("lit", [math.sin(ts[0] / 2), 0.0, 0.0, math.cos(ts[0] / 2)]))])),
    "RotatingFrameFreeParticle": st.just(_call_spec(
        "RotatingFrameFreeParticle", [_call_spec("SceneFrame.rotating", [("lit", [0.0, 0.0, 1.0]), ("lit", 0.5)]),
                                      ("lit", [1.0, 0.0, 0.0]), ("lit", [0.0, 1.0, 0.0])])),
    "ConstantThrustSolution": st.tuples(st.floats(0.1, 100.0), st.floats(-10.0, -0.01)).map(lambda mr: _call_spec(
        "ConstantThrustSolution", [("lit", mr[0]), ("lit", mr[1]), ("lit", [0.0, 0.0, -100.0])],
        g_W=("lit", [0.0, 0.0, -9.81]))),
}
# a run's error estimate (read from a result as its attribute); a spatial inertia and a Transform from a valid call
# (the joints' transform(q) also return a Transform, but rarely from drawn q)
RECIPES["GlobalError"] = st.one_of(RECIPES["BodySceneResult"], RECIPES["SceneResult"]).map(
    lambda run: ("method", run, "__getattribute__", [("lit", "error")], []))
# one body's records of a scene's run (SceneResult.body, its index drawn, negative ones too)
RECIPES["BodyRecords"] = st.tuples(RECIPES["SceneResult"], st.integers(-2, 1)).map(
    lambda rk: ("method", rk[0], "body", [("lit", rk[1])], []))
# a run's energy and momentum balance (read from a result as its attribute)
RECIPES["Balance"] = st.one_of(RECIPES["BodySceneResult"], RECIPES["SceneResult"]).map(
    lambda run: ("method", run, "__getattribute__", [("lit", "balance")], []))
# what a run to a drawn tolerance chose (read from its result)
RECIPES["ToleranceChoice"] = st.floats(1e-9, 1e-3).map(lambda tol: ("method", _call_spec(
    "simulate", [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])]),
                 _call_spec("RigidBodyState", w_B=("lit", [0.1, 1.0, 0.1]))],
    duration=("lit", 1.0), tolerance=("lit", tol)), "__getattribute__", [("lit", "choice")], []))
RECIPES["SpatialInertia"] = st.tuples(st.floats(0.01, 10.0), st.floats(0.1, 100.0)).map(
    lambda rm: _call_spec("solid_sphere", [("lit", rm[0])], mass=("lit", rm[1])))  # the primitives' draws mostly
# give both or neither of mass= and density=
RECIPES["Transform"] = st.tuples(st.floats(-3.1, 3.1), st.lists(st.floats(-10.0, 10.0), min_size=3, max_size=3)).map(
    lambda ap: _call_spec("Transform", [_call_spec("rot_z", [("lit", ap[0])]), ("lit", ap[1])]))
# a pivoted top's run (the one-body scene of the body and gravity)
RECIPES["PivotedSceneResult"] = st.tuples(st.integers(0, 30), st.sampled_from(["rk4", "implicit_midpoint", "splitting_dlm"])
                                          ).map(lambda nm: _call_spec(
    "simulate", [_PIVOTED, _call_spec("PivotedBodyState", w_B=("lit", [0.0, 0.0, 10.0]))], dt=("lit", 0.01),
    steps=("lit", nm[0]), method=("lit", nm[1]), gravity=("lit", True)))
# the recipes that are valid calls of a target: that target's calls also draw them, whole or with one argument wild
RECIPE_CALLS = {
    "simulate": ["BodySceneResult", "SceneResult", "PivotedSceneResult"], "simulate_batch": ["BatchSceneResult"],
    "integrate_density_over_box": ["DensityIntegral"], "forward_dynamics": ["PivotedAcceleration"],
    "dispersion.monte_carlo": ["dispersion.MonteCarloResult"],
    **{name: [name] for name in ("Scene", "ScheduledLoads", "PivotedBody", "PivotedPlanarBody", "Thrust", "Wheel",
                                 "Gyrostat", "GyrostatState",
                                 "CompoundPendulumSolution", "LagrangeTopSolution", "RotatingFrameFreeParticle",
                                 "ConstantThrustSolution")},
}
UNTYPED = ("", "object", "typing.Any", "Any")  # annotations that say nothing of the argument
# monte_carlo: a valid run of a body or of the scene above with drawn dispersions, sizes and seed (rigiddyn.monte_carlo)
_MC_KEYS = ["p_W", "q_WB", "v_W", "w_B", "mass", "inertia", "gravity", "loads"]


def _mc_dispersion(key: str):
    """A valid dispersion spec of one monte_carlo key (a body's field name, or a scene's "<body>.<field>")."""
    field = key.rsplit(".", 1)[-1]
    normal = st.floats(0.0, 0.5).map(lambda s: _call_spec("dispersion.Normal", std=("lit", s)))
    uniform = st.floats(0.0, 0.5).map(lambda h: _call_spec("dispersion.Uniform", [("lit", 1.0 - h), ("lit", 1.0 + h)]))
    if field == "q_WB":
        return st.one_of(st.just(_call_spec("dispersion.UniformRotation")),
                         st.floats(0.0, 1.0).map(lambda s: _call_spec("dispersion.RotationNormal", [("lit", s)])))
    if field == "inertia":
        return st.tuples(st.floats(0.0, 0.5), st.floats(0.0, 0.5)).map(lambda ra: _call_spec(
            "dispersion.InertiaDispersion", [("lit", ra[0]), ("lit", ra[1])]))
    if field == "loads":
        return st.tuples(normal, uniform).map(lambda fu: _call_spec("dispersion.LoadDispersion", force=fu[0], torque=fu[1]))
    return st.one_of(normal, uniform)


def _mc_dispersions(keys):
    return st.lists(st.sampled_from(keys), unique=True, max_size=4).flatmap(
        lambda ks: st.tuples(*[_mc_dispersion(k) for k in ks]).map(lambda ds: ("dict", list(zip(ks, ds)))))


_SCENE_MC_KEYS = [f"body0.{f}" for f in ("p_W", "v_W", "mass")] + [f"body1.{f}" for f in _MC_KEYS[:6]]
RECIPES["dispersion.MonteCarloResult"] = st.one_of(
    st.tuples(st.integers(1, 4), st.integers(0, 2**64), _mc_dispersions(_MC_KEYS), st.integers(0, 20)).map(
        lambda a: _call_spec("dispersion.monte_carlo", [_call_spec("RigidBody", [("lit", 1.0), ("lit", [1.0, 2.0, 2.5])]),
                                                         _call_spec("RigidBodyState", w_B=("lit", [0.1, 1.0, 0.1])),
                                                         ("lit", a[0])],
                             seed=("lit", a[1]), dispersions=a[2], dt=("lit", 0.01), steps=("lit", a[3]))),
    st.tuples(st.integers(1, 3), st.integers(0, 100), _mc_dispersions(_SCENE_MC_KEYS), st.integers(0, 20)).map(
        lambda a: _call_spec("dispersion.monte_carlo", [_SCENE, _SCENE_STATES, ("lit", a[0])], seed=("lit", a[1]),
                             dispersions=a[2], dt=("lit", 0.01), steps=("lit", a[3]))))
RECIPES["dispersion.Statistics"] = st.tuples(RECIPES["dispersion.MonteCarloResult"], st.sampled_from(
    ["t", "w_B", "total_energy", "kinetic_energy"])).map(lambda rq: ("method", rq[0], "statistics", [("lit", rq[1])], []))

# what a controller's law sees at a sample: nb bodies and nw wheels
RECIPES["SampledState"] = st.tuples(st.floats(0.0, 10.0), st.integers(1, 3), st.integers(0, 3)).map(
    lambda a: _call_spec("SampledState", [("lit", a[0]), ("lit", [[0.0, 0.0, 0.0]] * a[1]),
                                          ("lit", [[0.0, 0.0, 0.0, 1.0]] * a[1]), ("lit", [[0.0, 0.0, 0.0]] * a[1]),
                                          ("lit", [[0.0, 0.0, 0.0]] * a[1]), ("lit", [0.0] * a[2])]))

# the force element classes of a scene (Scene.add, Scene(elements=...))
ELEMENT_CLASSES = ("UniformGravity", "PointMassGravity", "MutualGravity", "GravityGradient", "SpringDamper", "Drag",
                   "ScheduledLoads", "PythonForce", "Thrust", "MagneticDipole",
                   "ReactionWheel", "ZonalGravity", "AtmosphericDrag", "SolarRadiationPressure",
                   "RevoluteSpringDamper", "PrismaticSpringDamper", "RevoluteMotor", "PrismaticMotor",
                   "SphericalSpringDamper")
# a field of an element class's table (each class's `fields`)
RECIPES["ElementField"] = st.tuples(st.sampled_from(ELEMENT_CLASSES), st.integers(0, 1)).map(
    lambda ci: _call_spec(f"{ci[0]}.fields.__getitem__", [("lit", ci[1])]))


# ---------------------------------------------------------------------------------------------
# arrays

COMMON_SHAPES = [(), (0,), (1,), (2,), (3,), (4,), (6,), (3, 3), (4, 4), (6, 6), (2, 3), (2, 4), (0, 3), (0, 4),
                 (3, 4), (2, 3, 3), (0, 3, 3), (1, 1, 3), (3, 0)]
SHAPES = st.one_of(st.sampled_from(COMMON_SHAPES), hnp.array_shapes(min_dims=0, max_dims=4, min_side=0, max_side=4))
DTYPES = ["<f8", "<f4", "<f2", ">f8", "<i8", "<i4", "|u1", "|b1", "<c16", "|O"]
HUGE_ROWS = [10**5, 10**10, 10**12]  # 1e5 can be copied within the worker's memory limit; the others cannot


def _cast(a: np.ndarray, dtype: str) -> np.ndarray:
    with np.errstate(all="ignore"):
        return a.astype(dtype)


@functools.lru_cache(maxsize=None)
def _floats_array(shape, elements=None):
    return hnp.arrays(np.float64, shape, elements=FLOATS if elements is None else elements)


@st.composite
def wild_array(draw, shapes=SHAPES):
    shape = draw(shapes)
    dtype = draw(st.sampled_from(DTYPES))
    kind = np.dtype(dtype).kind
    if kind == "f":
        a = _cast(draw(_floats_array(shape)), dtype)
    elif kind in "iu":
        a = _cast(draw(hnp.arrays(np.int64, shape, elements=st.one_of(st.integers(-3, 10), st.integers(-2**63, 2**63 - 1)))),
                  dtype)
    elif kind == "b":
        a = draw(hnp.arrays(np.bool_, shape))
    elif kind == "c":
        a = np.empty(shape, dtype=complex)
        a.real, a.imag = draw(_floats_array(shape)), draw(_floats_array(shape))
    else:
        a = np.empty(shape, dtype=object)
        items = draw(st.lists(st.one_of(FLOATS, st.integers(-3, 3), SAFE_TEXT, st.none()), min_size=a.size, max_size=a.size))
        for i, item in enumerate(items):
            a.flat[i] = item
    return ("array", a)


LAYOUTS = st.sampled_from(["c", "c", "c", "fortran", "reversed", "strided", "unaligned"])


def laid_out(arrays):
    """An array spec possibly re-laid out (reversed and strided need a first axis)."""

    def wrap(spec_layout):
        spec, layout = spec_layout
        if layout == "c" or (layout in ("reversed", "strided") and spec[1].ndim == 0) or (
                layout == "unaligned" and spec[1].dtype.hasobject):
            return spec
        return ("layout", layout, spec)

    return st.tuples(arrays, LAYOUTS).map(wrap)


def huge(items):
    """np.broadcast_to(item, (rows,) + item.shape): a read-only view of a batch of `rows` copies."""
    return st.tuples(items, st.sampled_from(HUGE_ROWS)).map(lambda ir: ("broadcast", ir[0][1], (ir[1],) + ir[0][1].shape))


@functools.lru_cache(maxsize=None)
def _components(n, low, high):
    return st.lists(st.floats(low, high), min_size=n, max_size=n)


def _unit_quaternions(draw, batch):
    q = np.array(draw(_components(4 * math.prod(batch), -1.0, 1.0)), dtype=float).reshape(batch + (4,))
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    q = np.where(norm > 1e-3, q / np.where(norm > 0, norm, 1.0), np.array([0.0, 0.0, 0.0, 1.0]))
    return q


def _rotations(q):
    x, y, z, w = np.moveaxis(q, -1, 0)
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
                     np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
                     np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1)], -2)


@st.composite
def quaternions(draw, batch=()):
    return _unit_quaternions(draw, batch)


@st.composite
def rotations(draw, batch=()):
    return _rotations(_unit_quaternions(draw, batch))


@st.composite
def inertias(draw, batch=()):
    """Symmetric positive definite inertias about the centre of mass, R diag(I) R^T with the triangle
    inequality (a box's moments) or sometimes a sphere's."""
    n = math.prod(batch)
    sides = np.array(draw(_components(3 * n, 0.05, 5.0))).reshape(batch + (3,))
    s2 = sides**2
    moments = np.stack([s2[..., 1] + s2[..., 2], s2[..., 0] + s2[..., 2], s2[..., 0] + s2[..., 1]], -1) / 12.0
    R = _rotations(_unit_quaternions(draw, batch)) if draw(st.booleans()) else np.broadcast_to(np.eye(3), batch + (3, 3))
    inertia = R @ (moments[..., :, None] * np.swapaxes(R, -1, -2))
    return (inertia + np.swapaxes(inertia, -1, -2)) / 2


def scaled(values):
    """Plausible values times a magnitude (3 in 5 times 1, else log-uniform over the double range or a
    boundary value)."""
    return st.tuples(values, st.one_of(st.just(1.0), st.just(1.0), st.just(1.0), POSITIVE_EXTREME, POSITIVE_BOUNDARY)).map(
        lambda vs: vs[0] * vs[1] if vs[1] != 1.0 else vs[0])


def _batch(shape):
    return st.sampled_from([(), (1,), (2,), (3,), (0,)]) if shape is None else st.just(shape)


@functools.lru_cache(maxsize=None)
def plausible_array_for_shape(shape):
    """Values for a shape read from a docstring ('n' is a batch of 0 to 3)."""
    batch_dims = tuple(d for d in shape if d == "n")

    @st.composite
    def draw_it(draw):
        sizes = {d: draw(st.integers(0, 3)) for d in batch_dims}
        concrete = tuple(sizes.get(d, d) if d == "n" else d for d in shape)
        if concrete and concrete[-1] == 4 and draw(st.booleans()):
            return _unit_quaternions(draw, concrete[:-1])
        if concrete[-2:] == (3, 3):
            which = draw(st.sampled_from(["rotation", "inertia", "any"]))
            if which == "rotation":
                return _rotations(_unit_quaternions(draw, concrete[:-2]))
            if which == "inertia":
                return draw(inertias(concrete[:-2]))
        return draw(_floats_array(concrete, PLAIN))

    return draw_it()


def array_spec(values):
    return laid_out(scaled(values).map(lambda a: ("array", np.asarray(a, dtype=float))))


SHAPE_PATTERN = re.compile(r"\((?:\d+|n)(?:,\s*(?:\d+|n))*,?\)")


def _shape_of(text: str):
    return tuple(int(d) if d.isdigit() else "n" for d in re.findall(r"\d+|n", text))


MONOGRAM = re.compile(r"_[A-Z]")  # p_FQ_F, w_B, R_PF: a vector or a matrix (docs/conventions.md)


def doc_shapes(doc: str, name: str) -> tuple[list[tuple], bool]:
    """Shapes the docstring gives for argument `name` ("q: (4,) or (n, 4)"), else every shape it names;
    and whether `name` is known to be an array (a shape follows it in the docstring, or it is a
    monogram name); if not, it may as well be a number."""
    near = []
    for m in re.finditer(rf"\b{re.escape(name)}\b", doc):
        near += [_shape_of(s) for s in SHAPE_PATTERN.findall(doc[m.end():m.end() + 40])]
    shapes = near or [_shape_of(s) for s in SHAPE_PATTERN.findall(doc)]
    shapes = list(dict.fromkeys(s for s in shapes if len(s) <= 3)) or [(3,)]
    return shapes, bool(near) or bool(MONOGRAM.search(name))


# ---------------------------------------------------------------------------------------------
# the model's vocabulary (hints by argument name; the annotation-based strategies apply as well)

EULER_SEQUENCES = ["xyz", "ZYX", "zxz", "XYX", "yzy", "xyx", "ZXZ", "xYz", "xy", "xyzz", "abc", ""]
FRAMES = ["world", "body", "A", "B"]
MEASURES = ["final_attitude_error", "max_state_error", "energy_drift", "momentum_drift"]
BOX_VERTICES = np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])
BOX_FACES = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1], [2, 3, 7], [2, 7, 6],
                      [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
TETRAHEDRON = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])


class Strategies:
    """Strategies for the targets of one module."""

    def __init__(self, module, targets: list[Target], words: list[str], submodules: tuple[str, ...] = ()):
        self.module = module
        self.targets = targets
        # class paths: "Scene", and a submodule's "dispersion.Normal"; found in annotations by the last part
        self.class_objects = public_classes(module, submodules)
        self.classes = list(self.class_objects)
        self._short = {path.split(".")[-1]: path for path in self.classes}
        self.words = sorted(set(words)) or ["x"]
        self._objects: dict[tuple[str, int], st.SearchStrategy] = {}
        self.hints, self.untyped_hints = self._hints()

    # -- types named in annotations
    def _class_in(self, annotation: str) -> str | None:
        name = annotation.strip().strip("'\"").split(".")[-1]
        return self._short.get(name)

    def objects_of(self, classes, depth: int) -> st.SearchStrategy:
        """Instances of any of `classes`."""
        return st.one_of(*[self.objects(c, depth) for c in classes])

    def _producers(self, cls: str) -> list[tuple[Target, tuple[Param, ...]]]:
        out = []
        for t in self.targets:
            for params, ret in zip(t.overloads, t.returns):
                if t.path == cls or self._class_in(ret) == cls:
                    out.append((t, params))
        return out

    def objects(self, cls: str, depth: int) -> st.SearchStrategy:
        """Instances of `cls` made by the API itself (constructors, factories, methods returning one),
        with plausible arguments; a constructed object may get a few of its mutating methods called."""
        key = (cls, depth)
        if cls not in self.classes:
            return st.nothing()
        if key not in self._objects:
            self._objects[key] = st.deferred(lambda: self._objects_now(cls, depth))
        return self._objects[key]

    def _objects_now(self, cls: str, depth: int) -> st.SearchStrategy:
        if depth > MAX_DEPTH:
            return st.nothing()
        made = [self._call(t, params, depth, wild=False) for t, params in self._producers(cls)]
        # a base class (monte_carlo.Dispersion) is also taken by its public subclasses' objects
        made += [self.objects(sub, depth) for sub, klass in self.class_objects.items()
                 if sub != cls and issubclass(klass, self.class_objects[cls])]
        if not made and cls not in RECIPES:
            return st.nothing()
        if cls in RECIPES:  # half the draws: a valid call that always makes one (random producers rarely match their
            # arguments: with 20 primitives making a SpatialInertia, a recipe among them was drawn once in 21)
            made = st.one_of(RECIPES[cls], st.one_of(*made)) if made else RECIPES[cls]
        else:
            made = st.one_of(*made)
        mutators = [t for t in self.targets if t.owner == cls and all(r == "None" for r in t.returns)
                    and not t.path.split(".")[-1].startswith("_")]
        if not mutators:
            return made
        step = st.sampled_from(mutators).flatmap(
            lambda t: st.sampled_from(t.overloads).flatmap(
                lambda params: self.arguments(params, t.doc, depth + 1, False, cls).map(
                    lambda a: (t.path.split(".")[-1], a[0], a[1]))))
        return st.one_of(made, st.tuples(made, st.lists(step, min_size=1, max_size=3)).map(
            lambda ms: ("chain", ms[0], ms[1])))

    def _call(self, t: Target, params, depth: int, wild: bool):
        args = self.arguments(params, t.doc, depth + 1, wild, t.owner)
        if t.owner is None:
            return args.map(lambda a: ("call", t.path, a[0], a[1]))
        method = t.path.split(".")[-1]
        return st.tuples(self.objects(t.owner, depth + 1), args).map(
            lambda sa: ("method", sa[0], method, sa[1][0], sa[1][1]))

    @functools.lru_cache(maxsize=None)
    def call(self, t: Target) -> st.SearchStrategy:
        """A top-level call of target t (arguments plausible and wild); where a recipe makes a valid call of it
        (RECIPE_CALLS), that call too, whole or with one argument replaced by a wild value."""
        calls = [self._call(t, params, 0, wild=True) for params in t.overloads]
        for name in RECIPE_CALLS.get(t.path, []):
            calls += [RECIPES[name], RECIPES[name].flatmap(lambda spec: self._one_wild(spec))]
        return st.one_of(*calls)

    def _one_wild(self, spec) -> st.SearchStrategy:
        """spec ("call", path, args, kwargs) with one of its arguments replaced by a wild value."""
        _, path, args, kwargs = spec
        n = len(args) + len(kwargs)
        if n == 0:
            return st.just(spec)

        def replace(i_value):
            i, value = i_value
            if i < len(args):
                return ("call", path, args[:i] + [value] + args[i + 1:], kwargs)
            j = i - len(args)
            return ("call", path, args, kwargs[:j] + [(kwargs[j][0], value)] + kwargs[j + 1:])

        return st.tuples(st.integers(0, n - 1), self.wild(1)).map(replace)

    # -- arguments
    @functools.lru_cache(maxsize=None)
    def arguments(self, params, doc: str, depth: int, wild: bool, owner: str | None = None):
        """(args, kwargs) for one overload; `owner`: the class whose method takes them, if any."""
        plausible = [self.plausible(p, doc, depth, owner) for p in params]
        wild_value = self.wild(depth)

        @st.composite
        def draw_args(draw):
            mode = draw(st.sampled_from(("plausible", "plausible", "one_wild", "mixed"))) if wild and params else "plausible"
            wild_index = draw(st.integers(0, len(params) - 1)) if mode == "one_wild" else -1
            values = []
            for i, p in enumerate(params):
                is_wild = draw(st.booleans()) if mode == "mixed" else i == wild_index
                if p.optional and not is_wild and not draw(st.booleans()):
                    values.append(OMIT)
                else:
                    values.append(draw(wild_value if is_wild else plausible[i]))
            return _assemble(params, values)

        return draw_args()

    @functools.lru_cache(maxsize=None)
    def plausible(self, p: Param, doc: str, depth: int, owner: str | None = None) -> st.SearchStrategy:
        hints = self.hints + (self.untyped_hints if p.annotation in UNTYPED else [])
        options = [make(self, p, doc, depth) for pattern, make in hints if pattern.fullmatch(p.name)]
        # a name hint is better knowledge than an untyped signature; a typed one adds to it
        if not options or p.annotation not in UNTYPED:
            options.append(self.by_annotation(p.annotation, p.name, doc, depth))
        if owner is not None and p.name in ("other", "arg0"):  # the other operand of a binary operation
            options.append(self.objects(owner, depth + 1))
        return st.one_of(*options)

    @functools.lru_cache(maxsize=None)
    def by_annotation(self, annotation: str, name: str, doc: str, depth: int) -> st.SearchStrategy:
        parts = [a.strip() for a in annotation.split("|")] if annotation else ["object"]
        options = []
        for a in parts:
            cls = self._class_in(a)
            low = a.lower()
            if "callable" in low:
                options.append(self.callables(doc, depth))
            elif cls is not None:
                options.append(self.objects(cls, depth))
            elif "supportsfloat" in low or low == "float":
                options.append(lit(PLAUSIBLE_FLOAT))
            elif "supportsint" in low or "supportsindex" in low or low == "int":
                if "supportsfloat" not in annotation.lower():
                    options.append(lit(SMALL_INT))
            elif low == "bool":
                options.append(lit(st.booleans()))
            elif low in ("str", "path"):
                options.append(lit(st.sampled_from(self.words)))
            elif low == "none":
                options.append(lit(st.none()))
            elif low.startswith(("sequence", "collections.abc.sequence", "list", "iterable", "collections.abc.iterable",
                                 "tuple")):
                options.append(st.lists(self.plausible_array(name, doc), max_size=3).map(lambda xs: ("list", xs)))
            elif low.startswith(("mapping", "dict")):
                options.append(lit(st.just({})))
            else:
                options.append(self.plausible_array(name, doc))
        return st.one_of(*options)

    @functools.lru_cache(maxsize=None)
    def plausible_array(self, name: str, doc: str) -> st.SearchStrategy:
        shapes, named = doc_shapes(doc, name)
        values = st.sampled_from(shapes).flatmap(plausible_array_for_shape)
        singles = [s for s in shapes if "n" not in s]
        as_list = values.map(lambda a: ("lit", a.tolist()))
        options = [array_spec(values), array_spec(values), array_spec(values), as_list]
        if not named:
            options.insert(0, lit(PLAUSIBLE_FLOAT))
        if singles:  # a huge read-only batch of one valid item
            options.append(huge(st.sampled_from(singles).flatmap(plausible_array_for_shape).map(
                lambda a: ("array", np.asarray(a, float)))))
        return st.one_of(*options)

    @functools.lru_cache(maxsize=None)
    def callables(self, doc: str, depth: int) -> st.SearchStrategy:
        """Callables returning a fixed value: a plausible number, or an object of a class the
        docstring names, or anything."""
        returned = [lit(PLAUSIBLE_FLOAT)]
        returned += [self.objects(c, depth + 1) for c in self.classes if re.search(rf"\b{c.split('.')[-1]}\b", doc)]
        returned.append(self.wild(depth + 1))
        return st.one_of(*returned).map(lambda v: ("lambda", v))

    @functools.lru_cache(maxsize=None)
    def wild(self, depth: int) -> st.SearchStrategy:
        scalars = lit(st.one_of(FLOATS, FLOATS, INTS, st.booleans(), COMPLEX, NUMPY_SCALAR, st.none()))
        options = [
            laid_out(wild_array()),
            scalars,
            laid_out(wild_array()),
            scalars,
            lit(st.one_of(SAFE_TEXT, st.sampled_from(self.words))),
            lit(st.lists(FLOATS, max_size=5)),
            lit(st.lists(st.lists(FLOATS, max_size=4), max_size=4)),  # ragged
            huge(wild_array(st.sampled_from([(), (3,), (4,), (3, 3)]))),
            lit(st.just({})),
        ]
        if depth < MAX_DEPTH:
            options.append(st.sampled_from(self.classes).flatmap(lambda c: self.objects(c, depth + 1)))
            options.append(st.deferred(lambda: self.wild(depth + 1)).map(lambda v: ("lambda", v)))
        return st.one_of(*options)

    # -- hints by argument name
    def _hints(self):
        words = lambda ws: lambda s, p, doc, depth: lit(st.sampled_from(ws))  # noqa: E731
        arr = lambda values: lambda s, p, doc, depth: array_spec(values)  # noqa: E731
        method_names = _method_names(self.module)

        def obj(*classes):
            return lambda s, p, doc, depth: st.one_of(*[s.objects(c, depth + 1) for c in classes])

        def returning(*classes):
            return lambda s, p, doc, depth: st.one_of(
                lit(PLAUSIBLE_FLOAT), *[s.objects(c, depth + 1) for c in classes]).map(lambda v: ("lambda", v))

        # for arguments the signature leaves untyped (object): objects, by the monogram and noun names
        # of docs/conventions.md
        untyped = [
            (r"K_[A-Za-z]+", obj("FrameKinematics")),
            (r"X_[A-Za-z]+", obj("Transform")),
            (r"motion", obj("FrameMotion")),
            (r"spatial_vector", obj("Motion", "Force")),
            (r"twist|m", obj("Motion")),
            (r"f", obj("Force")),
            (r"screw", obj("Screw")),
            (r"check|inertia_check", obj("InertiaCheck")),
            (r"part", obj("SpatialInertia")),
            (r"body|model", obj("RigidBody", "Particle", "PlanarBody", "PivotedBody", "PivotedPlanarBody", "Gyrostat")),
            (r"frame_motion", obj("FrameMotion")),
            (r"mass_flow", lambda s, p, doc, depth: st.one_of(lit(st.none()), s.objects("MassFlow", depth + 1))),
            (r"model", obj("Scene", "CompiledScene")),
            (r"scene", obj("Scene")),
            (r"element", obj(*ELEMENT_CLASSES)),
            (r"elements", lambda s, p, doc, depth: _list_of(s.objects_of(ELEMENT_CLASSES, depth + 1), depth)),
            (r"bodies", lambda s, p, doc, depth: st.one_of(  # indices (an element's), or bodies (a Scene's)
                lit(st.one_of(st.none(), st.lists(st.integers(0, 2), min_size=1, max_size=3, unique=True))),
                _list_of(s.objects_of(("Particle", "RigidBody", "PlanarBody"), depth + 1), depth))),
            (r"body_a|body_b", lambda s, p, doc, depth: lit(st.one_of(st.integers(0, 2), st.none()))),
            (r"body_names", lambda s, p, doc, depth: lit(st.one_of(st.none(), st.lists(
                st.one_of(st.none(), st.sampled_from(["a", "b", "c"])), max_size=3)))),
            (r"fn", lambda s, p, doc, depth: st.one_of(  # a force fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W, tau_B)
                array_spec(st.just(np.zeros(3))).map(lambda a: ("lambda", ("tuple", [a, a]))),
                s.callables(doc, depth))),
            (r"state|initial", obj("RigidBodyState", "ParticleState", "PlanarBodyState", "PivotedBodyState",
                                   "PivotedPlanarBodyState", "GyrostatState")),
            (r"rho", lambda s, p, doc, depth: st.one_of(  # a density per point [kg/m^3], or anything
                lit(POSITIVE_FLOAT).map(lambda v: ("per_row", v)), returning()(s, p, doc, depth))),
            (r"kinematics_at", returning("FrameKinematics")),
            (r"frame", obj("SceneFrame")),  # a Scene's frame (an element's frame is a word, below)
            (r"mass_flows", lambda s, p, doc, depth: _list_of(st.one_of(
                lit(st.none()), s.objects("MassFlow", depth + 1)), depth)),
            # a MassFlow: dm/dt [kg/s] (negative: losing mass) or rate(t); inertia_rule 'scaled' or I(m) (3, 3)
            (r"rate", lambda s, p, doc, depth: st.one_of(lit(st.floats(-10.0, 10.0)), lit(st.floats(-10.0, 0.0)).map(
                lambda v: ("lambda", v)))),
            (r"inertia_rule", lambda s, p, doc, depth: st.one_of(
                lit(st.sampled_from(["scaled", "constant", ""])), array_spec(inertias()).map(lambda a: ("lambda", a)))),
        ]
        table = [
            (r"scalar_first|degrees|canonical|return_sensitivity|progress", lambda s, p, doc, depth: lit(st.booleans())),
            (r"q|q\d|q_[A-Za-z]+|quat", arr(_batch(None).flatmap(quaternions))),
            (r"R|R_[A-Za-z0-9]+", arr(_batch(None).flatmap(rotations))),
            (r"rotation", lambda s, p, doc, depth: st.one_of(
                array_spec(rotations()), quaternions().map(lambda q: ("scipy_rotation", ("array", q))))),
            (r"inertia(?!_check)\w*", arr(_batch(None).flatmap(inertias))),
            (r"masses", arr(st.lists(st.floats(0.1, 10.0), min_size=1, max_size=5).map(np.array))),
            (r"mass|density|\w*radius|length|height|size_[xy]|inertia_zz|horizon|magnitude|scale|tolerance|prec|rate",
             lambda s, p, doc, depth: lit(POSITIVE_FLOAT)),
            (r"size|semi_axes", arr(st.lists(st.floats(0.05, 5.0), min_size=3, max_size=3).map(np.array))),
            (r"dt", lambda s, p, doc, depth: lit(st.sampled_from([1e-3, 1e-2, 0.05, 1e-4]))),
            (r"dts", lambda s, p, doc, depth: lit(st.lists(st.sampled_from([1e-3, 2e-3, 1e-2, 0.05]), min_size=1, max_size=3))),
            (r"steps|record_every|samples|order|subdivisions|max_reference_steps|n_vertices",
             lambda s, p, doc, depth: lit(st.integers(0, 60))),
            (r"t|t0|t_start|t_end|u", lambda s, p, doc, depth: st.one_of(lit(PLAUSIBLE_FLOAT), s.plausible_array(p.name, doc))),
            (r"seq", words(EULER_SEQUENCES)),
            (r"method", words(method_names or ["rk4"])),
            (r"methods", lambda s, p, doc, depth: lit(st.lists(st.sampled_from(method_names or ["rk4"]), max_size=3))),
            (r"frame|relative_to|expressed_in|from_frame|to_frame|parent|name", words(FRAMES)),
            (r"measure", words(MEASURES)),
            (r"cost", words(["time", "evaluations"])),
            (r"problem|path_or_name", words(_examples())),
            (r"vertices", lambda s, p, doc, depth: array_spec(st.sampled_from([BOX_VERTICES, TETRAHEDRON]))),
            (r"faces", lambda s, p, doc, depth: lit(st.just(BOX_FACES.tolist()))),
            (r"positions|points", arr(st.integers(1, 5).flatmap(
                lambda n: hnp.arrays(np.float64, (n, 3), elements=st.floats(-2.0, 2.0))))),
            (r"parts", lambda s, p, doc, depth: _list_of(st.one_of(
                s.objects("SpatialInertia", depth + 1),
                st.tuples(s.objects("Transform", depth + 1), s.objects("SpatialInertia", depth + 1)).map(
                    lambda xy: ("tuple", list(xy)))), depth)),
            (r"loads", lambda s, p, doc, depth: _list_of(s.objects("AppliedLoad", depth + 1), depth)),
            (r"gravity", lambda s, p, doc, depth: st.one_of(array_spec(st.just(np.array([0.0, 0.0, -9.81]))),
                                                            lit(st.sampled_from([True, False, None])))),
            (r"formats", lambda s, p, doc, depth: lit(st.sampled_from([["png"], ["svg"], []]))),
            (r"path", lambda s, p, doc, depth: lit(st.sampled_from(["out", "result.csv", ""]))),
            # a scene file: its text, a file holding it, a shipped scene's name, or a path that is none
            (r"path_or_text", lambda s, p, doc, depth: st.one_of(
                lit(scene_texts()), scene_texts().map(lambda text: ("file", "scene.toml", text)),
                lit(st.sampled_from(_shipped_scenes() + ["out", "result.csv", "", "no_such.toml", "kepler.toml"])))),
            # monte_carlo: its dispersions (a body's keys or the RECIPES scene's), a nominal state, seeds, no cluster
            (r"dispersions", lambda s, p, doc, depth: st.one_of(
                _mc_dispersions(_MC_KEYS), _mc_dispersions(_SCENE_MC_KEYS), lit(st.none()))),
            (r"nominal_state", lambda s, p, doc, depth: st.one_of(s.objects("RigidBodyState", depth + 1),
                                                                   st.just(_SCENE_STATES))),
            (r"seed", lambda s, p, doc, depth: lit(st.one_of(st.integers(0, 2**64), st.sampled_from([-1, 2**128, None])))),
            (r"client", lambda s, p, doc, depth: lit(st.none())),  # a Dask cluster is rigiddyn.distributed's fuzz
            (r"quantity", lambda s, p, doc, depth: st.one_of(
                lit(st.sampled_from(["t", "p_W", "q_WB", "w_B", "total_energy", "mass", "work", "pivot_reaction_W", "x"])),
                s.callables(doc, depth))),
            (r"at", lambda s, p, doc, depth: lit(st.sampled_from([None, 0.0, 0.01, 0.05, 0.1, 1.0, -1.0, NAN, 1e300]))),
            (r"q", lambda s, p, doc, depth: lit(st.one_of(st.lists(st.floats(0.0, 100.0), max_size=4), st.floats(0.0, 100.0)))
             if "percent" in doc else st.nothing()),
            (r"mean|std|low|high|rel_std|axis_std", lambda s, p, doc, depth: st.one_of(
                lit(st.one_of(st.none(), st.floats(-2.0, 2.0), st.lists(st.floats(0.0, 2.0), min_size=3, max_size=3))),
                lit(POSITIVE_FLOAT))),
            (r"nominal", lambda s, p, doc, depth: st.one_of(
                lit(st.none()), arr(st.sampled_from([(3,), (3, 3)]).flatmap(plausible_array_for_shape))(s, p, doc, depth),
                array_spec(quaternions()), lit(POSITIVE_FLOAT))),
            (r"rng", lambda s, p, doc, depth: st.integers(0, 2**32).map(lambda seed: ("rng", seed))),
            (r"max_redraws", lambda s, p, doc, depth: lit(st.integers(-1, 5))),
            (r"batch", obj("BatchSceneResult")),
            (r"inputs|redraws", lambda s, p, doc, depth: lit(st.just({}))),
            # rigiddyn.units: values with units, the SI unit expected
            (r"value", lambda s, p, doc, depth: UNIT_VALUES),
            (r"unit", lambda s, p, doc, depth: lit(st.sampled_from(sorted(UNITS) + ["kg m^2", "degC", "", "nope", "m^"]))),
        ]
        return ([(re.compile(pattern), make) for pattern, make in table],
                [(re.compile(pattern), make) for pattern, make in untyped])


def _shipped_scenes() -> list[str]:
    try:
        from rigiddyn.scene_file import example_scenes

        return example_scenes()
    except Exception:  # another module (the planted bugs): no scenes
        return ["kepler"]


@st.composite
def unit_strings(draw) -> str:
    """"<number> <unit>" in a unit of some dimension (UNITS), or (one in four) a string no quantity should be
    read from (TORTURE)."""
    units = draw(st.sampled_from(sorted(UNITS)))
    name, _ = draw(st.sampled_from(UNITS[units]))
    number = draw(st.one_of(PLAIN, FLOATS, st.integers(-10**6, 10**6)))
    return f"{number!r} {name}" if draw(st.integers(0, 3)) else draw(st.sampled_from(TORTURE))


UNIT_STRINGS = unit_strings()
# a value a units function reads: a unit string, a number (SI), a list of them, a {value, unit} table, a pint
# Quantity (made by rigiddyn.units.registry()), or something else
UNIT_VALUES = st.one_of(
    lit(UNIT_STRINGS), lit(UNIT_STRINGS), lit(FLOATS), lit(st.lists(st.one_of(UNIT_STRINGS, PLAIN), min_size=2, max_size=4)),
    lit(st.tuples(st.lists(PLAIN, min_size=2, max_size=4), UNIT_STRINGS.map(lambda u: u.split(" ", 1)[-1])).map(
        lambda vu: {"value": vu[0], "unit": vu[1]})),
    st.tuples(st.one_of(PLAIN, FLOATS), st.sampled_from([u for us in UNITS.values() for u, _ in us if u])).map(
        lambda mu: ("method", ("call", "units.registry", [], []), "Quantity", [("lit", mu[0]), ("lit", mu[1])], [])),
    lit(st.one_of(st.none(), st.booleans(), st.just({}), st.just([]))))


def _list_of(items, depth: int):
    """Lists of up to 3 objects (empty where objects may no longer be nested)."""
    if depth + 1 > MAX_DEPTH:
        return st.just(("list", []))
    return st.lists(items, max_size=3).map(lambda xs: ("list", xs))


def _assemble(params, values):
    """(args, kwargs) spec lists: positional until the first omitted argument, then by keyword."""
    args, kwargs, positional = [], [], True
    for p, v in zip(params, values):
        if v is OMIT:
            positional = False
            continue
        if positional and not p.keyword_only:
            args.append(v)
        else:
            kwargs.append((p.name, v))
    return args, kwargs


def _method_names(module) -> list[str]:
    try:
        return [m["name"] for m in module.methods()]
    except Exception:  # another module (the harness's own planted-bug module): no method table
        return []


def _examples() -> list[str]:
    try:
        from rigiddyn.problem import example_problems

        return example_problems()
    except Exception:
        return ["t_handle"]


def docstring_words(module, targets: list[Target]) -> list[str]:
    """Quoted words of the docstrings ('world', `rk4`): the strings the API documents."""
    text = "\n".join(t.doc for t in targets) + (module.__doc__ or "")
    return re.findall(r"['`\"]([A-Za-z_][A-Za-z0-9_]{0,30})['`\"]", text)
