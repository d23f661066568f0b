"""Scene files for the fuzz: hypothesis strategies of scene data (rigiddyn.scene_file's format: bodies of
every kind, every force type, frames, mass flows, clusters, [run] and [tradeoff]) and their TOML text.

A scene is drawn as a tree of plain values whose numbers are `Q(value, unit)` leaves: a value in SI and
the SI unit the file format reads it in. `render(data, units)` writes the TOML text with each Q as a plain
number (units=None) or as a unit string in a unit of the same dimension drawn from UNITS ("3.28 ft" for
1 m): the same scene, in the file's own words. `mutated` replaces a drawn leaf or key with something no
scene file should hold (a wrong type, a unit of another dimension, a torture string, an unknown key, a
missing required key), so the reader's messages are fuzzed too.

Sizes keep a run short and stable: masses 0.1-10 kg, box inertias, speeds of a few m/s and rad/s, at most
three bodies, runs of at most 40 steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import tomli_w
from hypothesis import strategies as st


@dataclass(frozen=True)
class Q:
    """A number of a scene file: `value` in the SI unit `unit` (the pint expression scene_file reads)."""

    value: float
    unit: str


# SI unit -> units of the same dimension with the size of one of them in SI (pint's own definitions)
UNITS = {
    "kg": [("kg", 1.0), ("g", 1e-3), ("lb", 0.45359237), ("slug", 0.45359237 * 9.80665 / 0.3048)],
    "m": [("m", 1.0), ("km", 1e3), ("cm", 1e-2), ("ft", 0.3048), ("inch", 0.0254), ("mm", 1e-3)],
    "s": [("s", 1.0), ("ms", 1e-3), ("min", 60.0), ("h", 3600.0)],
    "rad": [("rad", 1.0), ("deg", math.pi / 180.0)],
    "rad/s": [("rad/s", 1.0), ("rpm", 2.0 * math.pi / 60.0), ("deg/s", math.pi / 180.0)],
    "m/s": [("m/s", 1.0), ("km/h", 1.0 / 3.6), ("ft/s", 0.3048)],
    "m/s^2": [("m/s^2", 1.0), ("ft/s^2", 0.3048)],
    "kg*m^2": [("kg*m^2", 1.0), ("kg m^2", 1.0), ("g*cm^2", 1e-7), ("lb*ft^2", 0.45359237 * 0.3048**2)],
    "m^3/s^2": [("m^3/s^2", 1.0), ("km^3/s^2", 1e9)],
    "m^3/(kg*s^2)": [("m^3/(kg*s^2)", 1.0), ("N*m^2/kg^2", 1.0)],
    "N": [("N", 1.0), ("kN", 1e3), ("lbf", 0.45359237 * 9.80665)],
    "N*m": [("N*m", 1.0), ("N m", 1.0), ("kN*m", 1e3)],
    "kg/s": [("kg/s", 1.0), ("g/s", 1e-3), ("kg/min", 1.0 / 60.0)],
    "N/m": [("N/m", 1.0), ("kN/m", 1e3)],
    "N*s/m": [("N*s/m", 1.0)],
    "N*s^2/m^2": [("N*s^2/m^2", 1.0)],
    "N*m*s/rad": [("N*m*s/rad", 1.0)],
    "N*m*s^2/rad^2": [("N*m*s^2/rad^2", 1.0)],
    "A*m^2": [("A*m^2", 1.0), ("mA*cm^2", 1e-7)],
    "T": [("T", 1.0), ("mT", 1e-3)],
    "1": [("", 1.0)],
}

# strings no quantity should be read from (towers, commas, hundreds of digits, nesting: refused in bounded time)
TORTURE = ["", " ", "m", "3", "3 kg m", "3 m s", "3 ft ft", "1 m/0", "2 (", "1 m 2 s", "3 degF", "3 degC", "5 %",
           "0x10 m", "1_000 m", "½ m", "１ m", "nan m", "inf kg", "-inf s", "1e308 km", "1e-320 m", "-0 s",
           "1e999 m", "3 ft**2", "3 m^-1", "3 1/s", "1 hour", "2 slug*ft", "1 m; 2 m", "1 meter meter meter",
           "1 m^9^9^9", "1,5 m", "1" + "0" * 400 + " m", "1 " + "m*" * 200 + "m", "(" * 200 + "1" + ")" * 200 + " m",
           "1 m**1e9", "1 m**(1/3)", "1 m^0.5", "1 rad^2", "1e3", "1 dimensionless", "3 mol", "2 cd", "1 Hz"]

METHODS = ["rk4", "rk4", "rk4", "splitting_dlm", "implicit_midpoint", "explicit_euler", "splitting_dlm_yoshida4",
           "exact_flow_kick", "exact"]

SMALL = st.floats(-2.0, 2.0)
POSITIVE = st.floats(0.1, 10.0)


def _q(values, unit):
    return values.map(lambda v: Q(float(v), unit))


def _vector(n, values, unit):
    return st.lists(_q(values, unit), min_size=n, max_size=n)


@st.composite
def _box_moments(draw):
    """Principal moments of a solid box of mass m: m (b^2 + c^2)/12, ...: a real body's."""
    m = draw(POSITIVE)
    a, b, c = (draw(st.floats(0.2, 2.0)) ** 2 for _ in range(3))
    return m, [m * (b + c) / 12.0, m * (a + c) / 12.0, m * (a + b) / 12.0]


@st.composite
def _attitude(draw):
    """One of the attitude forms of a [[body]] (none, q_WB, euler, rotvec, axis_angle)."""
    form = draw(st.sampled_from(["none", "q_WB", "euler", "rotvec", "axis_angle"]))
    if form == "q_WB":
        q = np.array([draw(st.floats(-1.0, 1.0)) for _ in range(4)])
        q = q / np.linalg.norm(q) if np.linalg.norm(q) > 1e-3 else np.array([0.0, 0.0, 0.0, 1.0])
        return {"q_WB": [float(x) for x in q]}
    if form == "euler":
        return {"euler": {"seq": draw(st.sampled_from(["ZYX", "xyz", "zxz"])),
                          "angles": draw(_vector(3, st.floats(-3.0, 3.0), "rad"))}}
    if form == "rotvec":
        return {"rotvec": draw(_vector(3, st.floats(-2.0, 2.0), "rad"))}
    if form == "axis_angle":
        return {"axis_angle": {"axis": [1.0, draw(st.floats(-1.0, 1.0)), 0.5], "angle": draw(_q(st.floats(-3.0, 3.0), "rad"))}}
    return {}


@st.composite
def body_table(draw, name):
    kind = draw(st.sampled_from(["particle", "planar", "rigid", "rigid", "pivoted", "pivoted_planar"]))
    mass, moments = draw(_box_moments())
    table = {"name": name, "kind": kind, "mass": Q(mass, "kg")}
    n = 2 if "planar" in kind else 3
    if kind in ("particle", "planar", "rigid"):
        table["p_W"] = draw(_vector(n, st.floats(-5.0, 5.0), "m"))
        table["v_W"] = draw(_vector(n, SMALL, "m/s"))
    if kind in ("planar", "pivoted_planar"):
        table["inertia"] = Q(moments[2], "kg*m^2")
        table["theta"] = draw(_q(st.floats(-3.0, 3.0), "rad"))
        table["omega"] = draw(_q(st.floats(-5.0, 5.0), "rad/s"))
    if kind in ("rigid", "pivoted"):
        table["inertia"] = [Q(J, "kg*m^2") for J in moments]
        table["w_B"] = draw(_vector(3, st.floats(-5.0, 5.0), "rad/s"))
        table.update(draw(_attitude()))
    if kind.startswith("pivoted"):
        table["p_OC_B"] = draw(_vector(n, st.floats(-0.5, 0.5), "m"))
        table["p_WO"] = draw(_vector(n, st.floats(-1.0, 1.0), "m"))
    if kind in ("particle", "rigid") and draw(st.integers(0, 3)) == 0:  # losing up to 1 % of its mass a second: far from empty in a short run
        table["mass_flow"] = {"rate": Q(-mass * draw(st.floats(0.0, 0.01)), "kg/s"), "inertia_rule": "scaled"}
    return table


def _force(draw, names, flows, rigid):
    kinds = ["uniform_gravity", "point_mass_gravity", "zonal_gravity", "mutual_gravity", "gravity_gradient",
             "spring_damper", "drag", "atmospheric_drag", "solar_radiation_pressure", "scheduled_loads",
             "magnetic_dipole"]
    kinds += ["thrust"] if flows else []
    kinds += ["reaction_wheel"] if rigid else []  # on a rigid body, free or pinned
    kind = draw(st.sampled_from(kinds))
    table = {"type": kind}
    some = draw(st.one_of(st.none(), st.lists(st.sampled_from(names), min_size=1, max_size=len(names), unique=True)))
    if kind == "uniform_gravity":
        table["g_W"] = draw(_vector(3, st.floats(-10.0, 10.0), "m/s^2"))
    elif kind in ("point_mass_gravity", "gravity_gradient"):
        table["gm"] = draw(_q(st.floats(1.0, 100.0), "m^3/s^2"))
        table["p_W"] = [Q(0.0, "m"), Q(0.0, "m"), Q(-50.0, "m")]
        if kind == "point_mass_gravity":
            table["softening"] = draw(_q(st.floats(0.0, 1.0), "m"))
    elif kind == "zonal_gravity":  # a central body of radius 10 m, 50 m away
        table["gm"] = draw(_q(st.floats(1.0, 100.0), "m^3/s^2"))
        table["radius"] = Q(10.0, "m")
        for key in ("j2", "j3", "j4"):
            table[key] = draw(st.floats(-0.1, 0.1))
        table["p_W"] = [Q(0.0, "m"), Q(0.0, "m"), Q(-50.0, "m")]
        table["pole_W"] = [draw(SMALL), draw(SMALL), 1.0]
    elif kind == "mutual_gravity":
        table["G"] = draw(_q(st.floats(1e-3, 1.0), "m^3/(kg*s^2)"))
        table["softening"] = draw(_q(st.floats(0.1, 1.0), "m"))
    elif kind == "spring_damper":
        table["body_a"] = draw(st.sampled_from(names))
        table["point_a_B"] = draw(_vector(3, st.floats(-0.5, 0.5), "m"))
        others = [n for n in names if n != table["body_a"]]
        if others and draw(st.booleans()):
            table["body_b"] = draw(st.sampled_from(others))
        table["point_b"] = draw(_vector(3, st.floats(-1.0, 1.0), "m"))
        table["stiffness"] = draw(_q(st.floats(0.0, 50.0), "N/m"))
        table["rest_length"] = draw(_q(st.floats(0.0, 1.0), "m"))
        table["damping"] = draw(_q(st.floats(0.0, 2.0), "N*s/m"))
        some = None
    elif kind == "drag":
        for key, unit in (("linear", "N*s/m"), ("quadratic", "N*s^2/m^2"), ("angular_linear", "N*m*s/rad"),
                          ("angular_quadratic", "N*m*s^2/rad^2")):
            table[key] = draw(_q(st.floats(0.0, 0.5), unit))
    elif kind == "atmospheric_drag":  # a planet of radius 40 m, 50 m away, its air turning (no centre of pressure:
        table["density0"] = draw(_q(st.floats(0.0, 1.0), "kg/m^3"))  # the bodies may be particles)
        table["scale_height"] = draw(_q(st.floats(1.0, 100.0), "m"))
        table["radius"] = Q(40.0, "m")
        table["p_W"] = [Q(0.0, "m"), Q(0.0, "m"), Q(-50.0, "m")]
        table["omega_W"] = draw(_vector(3, st.floats(-0.1, 0.1), "rad/s"))
        table["drag_area"] = draw(_q(st.floats(0.0, 1.0), "m^2"))
        if draw(st.booleans()):  # or a density table: 2 to 4 rows 5 m apart from 0 m, densities in (0, 1]
            rows = draw(st.integers(2, 4))
            del table["density0"], table["scale_height"]
            table["table_altitude"] = [Q(5.0 * k, "m") for k in range(rows)]
            table["table_density"] = draw(_vector(rows, st.floats(1e-3, 1.0), "kg/m^3"))
    elif kind == "solar_radiation_pressure":  # a cannonball (the bodies may be particles), a turning Sun, a shadow
        table["sun_W"] = [draw(SMALL), draw(SMALL), 1.0]
        table["sun_rate_W"] = draw(_vector(3, st.floats(-1.0, 1.0), "rad/s"))
        table["area"] = draw(_q(st.floats(0.0, 2.0), "m^2"))
        table["reflectivity"] = draw(st.floats(0.0, 2.0))
        table["shadow_radius"] = draw(_q(st.floats(0.0, 2.0), "m"))
    elif kind == "scheduled_loads":
        table["body"] = draw(st.sampled_from(names))
        table["point_B"] = draw(_vector(3, st.floats(-0.5, 0.5), "m"))
        loads = []
        for _ in range(draw(st.integers(0, 2))):
            load = {"force": draw(_vector(3, st.floats(-5.0, 5.0), "N")),
                    "torque": draw(_vector(3, st.floats(-1.0, 1.0), "N*m")),
                    "frame": draw(st.sampled_from(["world", "body"]))}
            if draw(st.booleans()):
                load["t_start"] = draw(_q(st.floats(0.0, 0.1), "s"))
            if draw(st.booleans()):
                load["t_end"] = draw(_q(st.floats(0.1, 0.3), "s"))
            loads.append(load)
        table["loads"] = loads
        some = None
    elif kind == "magnetic_dipole":
        table["m_B"] = draw(_vector(3, st.floats(-1.0, 1.0), "A*m^2"))
        table["B_W"] = draw(_vector(3, st.floats(-1.0, 1.0), "T"))
        if draw(st.booleans()):  # a source dipole far outside the bodies' reach
            table["source_moment_W"] = draw(_vector(3, st.floats(-1e7, 1e7), "A*m^2"))
            table["source_p_W"] = [Q(0.0, "m"), Q(0.0, "m"), Q(-50.0, "m")]
    elif kind == "reaction_wheel":
        table["body"] = draw(st.sampled_from(rigid))
        table["axis_B"] = [draw(SMALL), draw(SMALL), 1.0]
        table["inertia"] = draw(_q(st.floats(1e-3, 0.1), "kg*m^2"))
        table["speed"] = draw(_q(st.floats(-100.0, 100.0), "rad/s"))
        table["acceleration"] = draw(_q(st.floats(-50.0, 50.0), "rad/s^2"))
        table["t_start"] = draw(_q(st.floats(0.0, 0.1), "s"))
        table["t_end"] = draw(_q(st.floats(0.2, 0.3), "s"))
        some = None
    else:  # thrust on a body with a mass flow
        table["body"] = draw(st.sampled_from(flows))
        table["u_rel"] = draw(_vector(3, st.floats(-100.0, 100.0), "m/s"))
        table["frame"] = draw(st.sampled_from(["body", "world"]))
        table["r_B"] = draw(_vector(3, st.floats(-0.5, 0.5), "m"))
        some = None
    if some is not None:
        table["bodies"] = some
    return table


@st.composite
def scene_data(draw, max_bodies=3):
    """A scene file's tables: 1 to max_bodies bodies, 0 to 3 forces, maybe a frame, a cluster, [run], [tradeoff]."""
    names = [f"b{i}" for i in range(draw(st.integers(1, max_bodies)))]
    data = {"name": "fuzzed", "body": [draw(body_table(n)) for n in names]}
    flows = [t["name"] for t in data["body"] if "mass_flow" in t]
    rigid = [t["name"] for t in data["body"] if t["kind"] in ("rigid", "pivoted")]
    forces = [_force(draw, names, flows, rigid) for _ in range(draw(st.integers(0, 3)))]
    if forces:
        data["force"] = forces
    frame = draw(st.sampled_from([None, None, "rotating", "earth"]))
    if frame == "rotating":
        data["frame"] = {"kind": "rotating", "axis": [0.0, draw(SMALL), 1.0], "rate": draw(_q(st.floats(-1.0, 1.0), "rad/s"))}
    elif frame == "earth":
        data["frame"] = {"kind": "earth", "latitude": draw(_q(st.floats(-1.5, 1.5), "rad"))}
    if draw(st.integers(0, 5)) == 0:
        data["cluster"] = [{"model": "plummer", "count": draw(st.integers(2, 4)), "total_mass": Q(1.0, "kg"),
                            "scale_radius": Q(1.0, "m"), "G": Q(1.0, "m^3/(kg*s^2)"), "softening": Q(0.1, "m"),
                            "seed": draw(st.integers(0, 5))}]
    if "cluster" in data and draw(st.integers(0, 3)) == 0:  # a file of generated particles only
        data = {k: v for k, v in data.items() if k not in ("body", "force")}
    dt = draw(st.sampled_from([1e-3, 2e-3, 5e-3, 1e-2]))
    data["run"] = {"method": draw(st.sampled_from(METHODS)), "dt": Q(dt, "s"),
                   "duration": Q(dt * draw(st.integers(1, 40)), "s"), "record_every": draw(st.integers(1, 5))}
    if draw(st.integers(0, 5)) == 0:
        data["tradeoff"] = {"methods": ["rk4"], "dts": [Q(dt, "s")], "tolerance": 1e-6}
    return data


def render(data, units=None) -> str:
    """The TOML text of scene data: each Q in SI (units None) or as "<number> <unit>" with the unit of its
    dimension that `units` (a random.Random-like chooser: units(list) -> item) picks."""
    def plain(x):
        if isinstance(x, Q):
            if units is None or x.unit not in UNITS:
                return x.value
            name, size = units(UNITS[x.unit])
            return f"{x.value / size!r} {name}".rstrip() if name else x.value
        if isinstance(x, dict):
            return {k: plain(v) for k, v in x.items()}
        if isinstance(x, list):
            return [plain(v) for v in x]
        return x

    return tomli_w.dumps(plain(data))


def leaves(data, path=()):
    """(path, value) of every leaf (a Q, string, number, bool) and table key of the data tree."""
    if isinstance(data, dict):
        for k, v in data.items():
            yield from leaves(v, path + (k,))
    elif isinstance(data, list) and data and not isinstance(data[0], (Q, float, int)):
        for i, v in enumerate(data):
            yield from leaves(v, path + (i,))
    else:
        yield path, data


def replaced(data, path, value):
    """A copy of `data` with the leaf or key at `path` set to value (removed for value DELETE)."""
    head, rest = path[0], path[1:]
    out = dict(data) if isinstance(data, dict) else list(data)
    if rest:
        out[head] = replaced(data[head], rest, value)
    elif value is DELETE:
        del out[head]
    else:
        out[head] = value
    return out


DELETE = object()
WILD_VALUES = st.one_of(
    st.sampled_from(TORTURE),
    st.sampled_from([math.nan, math.inf, -math.inf, 0.0, -1.0, 1e308, -1e308, 5e-324, 1e-300, True, 2**63 - 1,
                     -2**63, [], [[]], {}, {"value": [1, 2, 3]}, {"value": [1, 2, 3], "unit": "kg"}, [1.0, 2.0],
                     [1.0, 2.0, 3.0, 4.0], ["1 m", "2 s", "3 kg"], "rk4", "body", "world", "b0", "b9", "plummer"]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(-10, 10**6),
    st.text(max_size=8),
)


@st.composite
def mutated(draw, data):
    """scene data with one leaf replaced by a wild value, or a key removed, or an unknown key added."""
    spots = list(leaves(data))
    path, _ = draw(st.sampled_from(spots))
    how = draw(st.sampled_from(["value", "value", "value", "delete", "unknown"]))
    if how == "delete":
        return replaced(data, path, DELETE)
    if how == "unknown" and isinstance(path[-1], str):  # a key no table of the format has, beside this one
        return replaced(data, path[:-1] + (path[-1] + "_x",), draw(WILD_VALUES))
    return replaced(data, path, draw(WILD_VALUES))


def _chooser(draw):
    return lambda options: draw(st.sampled_from(options))


@st.composite
def scene_texts(draw):
    """TOML scene text: valid (in SI or with units) three times in four, else mutated or broken text."""
    data = draw(scene_data())
    how = draw(st.sampled_from(["si", "units", "units", "mutated", "broken"]))
    if how == "si":
        return render(data)
    if how == "units":
        return render(data, _chooser(draw))
    if how == "mutated":
        return render(draw(mutated(data)), _chooser(draw) if draw(st.booleans()) else None)
    text = render(data)
    return draw(st.sampled_from([text[: len(text) // 2], text.replace("=", "==", 1), text + "\n[[body]]\n",
                                 text.replace("[run]", "[run]\n[run]"), "x = " + "[" * 50 + "]" * 50 + "\n" + text,
                                 "x = " + "[" * 3000 + "]" * 3000 + "\n" + text]))
