"""Problem files: the attitude as q_WB, Euler angles, a rotation vector or an axis
and angle, in degrees where `degrees = true`; a near-unit quaternion normalised with a note; angular
rates with a unit; "did you mean" for unknown keys in every table; the documented example."""

import math
import re
import textwrap
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn import problem as problem_module
from rigiddyn.problem import Problem, load_problem, parse_problem

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

EPS = np.finfo(float).eps
BODY = {"mass": 2.0, "inertia": [1.0, 2.0, 2.5]}


def parse_initial(initial):
    return parse_problem({"horizon": 1.0, "body": dict(BODY), "initial": initial})


def parse_text(text):
    return parse_problem(tomllib.loads(textwrap.dedent(text)))


def assert_normalised_from(q_WB, q_core):
    # q_WB is q / |q| twice (when the file is read, again in Problem): the first moves each component
    # (|q_i| <= 1) from the core's by <= | 1 / |q| - 1 | (the measured defect) + eps / 2 (rounding);
    # its result has | |q| - 1 | <= 2 eps (four components rounded once, summed in double), so the
    # second moves it by <= 2 eps + eps / 2: together the defect + 3 eps
    defect = abs(1.0 / np.linalg.norm(q_core) - 1.0)
    np.testing.assert_allclose(q_WB, q_core, rtol=0, atol=defect + 3 * EPS)


def same_rotation(q1, q2):
    """q2 with the sign of q1 (q and -q are the same rotation)."""
    return q2 if np.dot(q1, q2) >= 0 else -q2


# ---------------------------------------------------------------- orientation forms vs the core

SEQUENCES = ["ZYX", "XYZ", "zyx", "xyz", "ZXZ", "yzy"]


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("degrees", [False, True])
def test_euler_is_the_cores_conversion(seq, degrees):
    rng = np.random.default_rng(sum(map(ord, seq)) + degrees)
    for _ in range(5):
        angles = rng.uniform(-180, 180, 3) if degrees else rng.uniform(-math.pi, math.pi, 3)
        p = parse_initial({"euler": {"seq": seq, "angles": angles.tolist(), "degrees": degrees}})
        radians = np.deg2rad(angles) if degrees else angles
        assert_normalised_from(p.q_WB, rigiddyn.euler_to_quat(seq, radians))


@pytest.mark.parametrize("degrees", [False, True])
def test_rotvec_is_the_cores_conversion(degrees):
    rng = np.random.default_rng(7 + degrees)
    for _ in range(10):
        rotvec = rng.normal(size=3) * (90.0 if degrees else 1.5)
        initial = {"rotvec": {"value": rotvec.tolist(), "degrees": True}} if degrees else {"rotvec": rotvec.tolist()}
        radians = np.deg2rad(rotvec) if degrees else rotvec
        assert_normalised_from(parse_initial(initial).q_WB, rigiddyn.rotvec_to_quat(radians))
    # the table form in radians is the bare array
    np.testing.assert_array_equal(parse_initial({"rotvec": {"value": [0.1, 0.2, 0.3]}}).q_WB,
                                  parse_initial({"rotvec": [0.1, 0.2, 0.3]}).q_WB)


@pytest.mark.parametrize("degrees", [False, True])
def test_axis_angle_is_the_cores_conversion(degrees):
    rng = np.random.default_rng(11 + degrees)
    for _ in range(10):
        axis = rng.normal(size=3) * rng.uniform(0.1, 10)  # any non-zero length
        angle = float(rng.uniform(-360, 360) if degrees else rng.uniform(-2 * math.pi, 2 * math.pi))
        p = parse_initial({"axis_angle": {"axis": axis.tolist(), "angle": angle, "degrees": degrees}})
        radians = float(np.deg2rad(angle)) if degrees else angle
        assert_normalised_from(p.q_WB, rigiddyn.axis_angle_to_quat(axis, radians))


def test_q_WB_scalar_first_reorders():
    rng = np.random.default_rng(3)
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)  # | |q| - 1 | of a few eps: far below the 1e-12 note threshold
    last = parse_initial({"q_WB": q.tolist()}).q_WB
    first = parse_initial({"q_WB": np.roll(q, 1).tolist(), "scalar_first": True}).q_WB
    np.testing.assert_array_equal(first, last)
    assert_normalised_from(last, q)


# one rotation, 90 degrees about z, written in every form: q_WB = (0, 0, sin 45, cos 45)
QUARTER_TURN_Z = [
    {"q_WB": [0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)]},
    {"q_WB": [math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)], "scalar_first": True},
    {"euler": {"seq": "ZYX", "angles": [90, 0, 0], "degrees": True}},
    {"euler": {"seq": "xyz", "angles": [0, 0, math.pi / 2]}},
    {"rotvec": [0.0, 0.0, math.pi / 2]},
    {"rotvec": {"value": [0, 0, 90], "degrees": True}},
    {"axis_angle": {"axis": [0, 0, 5], "angle": 90, "degrees": True}},
    {"axis_angle": {"axis": [0, 0, 1], "angle": math.pi / 2}},
]


@pytest.mark.parametrize("initial", QUARTER_TURN_Z, ids=lambda d: "-".join(d))
def test_every_form_of_a_quarter_turn_gives_the_same_q_WB(initial):
    q = parse_initial(initial).q_WB
    # the exact q is (0, 0, 1/sqrt 2, 1/sqrt 2); each form rounds pi/2 (or 90 pi/180) once (1/2 ulp
    # of pi/2, i.e. eps / 2 of the half angle), takes a sine and cosine (<= 1 ulp of 0.7 each), or is
    # typed as sqrt(0.5) (1/2 ulp), then is normalised twice (<= 3 eps, see assert_normalised_from):
    # within eps / 2 + eps / 2 + 3 eps = 4 eps, given as 6 eps for the core's half-angle arithmetic
    np.testing.assert_allclose(q, [0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)], rtol=0, atol=6 * EPS)


@pytest.mark.parametrize("seq", SEQUENCES)
def test_euler_degrees_match_scipy(seq):
    Rotation = pytest.importorskip("scipy.spatial.transform").Rotation
    rng = np.random.default_rng(5)
    for _ in range(5):
        angles = rng.uniform(-90, 90, 3)
        q = parse_initial({"euler": {"seq": seq, "angles": angles.tolist(), "degrees": True}}).q_WB
        q_scipy = Rotation.from_euler(seq, angles, degrees=True).as_quat()
        # two implementations from the same doubles: the degree conversion (1/2 ulp), three half-angle
        # sines and cosines (1 ulp each) and two quaternion products (a few roundings of terms <= 1
        # per component) on each side: each within 8 eps of the exact quaternion, so 16 eps apart
        np.testing.assert_allclose(q, same_rotation(q, q_scipy), rtol=0, atol=16 * EPS)


def test_degrees_are_converted_as_np_deg2rad():
    # `degrees = true` is the radian file with np.deg2rad of each angle written out (repr round-trips)
    rad = np.deg2rad([30.0, -10.0, 5.5]).tolist()
    degrees_file = parse_initial({"euler": {"seq": "ZYX", "angles": [30, -10, 5.5], "degrees": True}})
    radians_file = parse_text(f"""
        horizon = 1.0
        [body]
        mass = 2.0
        inertia = [1.0, 2.0, 2.5]
        [initial]
        euler = {{seq = "ZYX", angles = [{rad[0]!r}, {rad[1]!r}, {rad[2]!r}]}}
    """)
    np.testing.assert_array_equal(degrees_file.q_WB, radians_file.q_WB)


@pytest.mark.parametrize("forms", [("q_WB", "euler"), ("euler", "rotvec"), ("rotvec", "axis_angle"),
                                   ("q_WB", "axis_angle")])
def test_two_orientations_are_an_error_naming_both(forms):
    every = {"q_WB": [0.0, 0, 0, 1], "euler": {"seq": "ZYX", "angles": [0, 0, 0]}, "rotvec": [0.0, 0, 0],
             "axis_angle": {"axis": [0, 0, 1], "angle": 0}}
    message = rf"^initial: expected at most one orientation .*, got {forms[0]} and {forms[1]}$"
    with pytest.raises(ValueError, match=message):
        parse_initial({k: every[k] for k in forms})


@pytest.mark.parametrize("initial", [{"scalar_first": True}, {"scalar_first": False, "rotvec": [0.0, 0, 1]}])
def test_scalar_first_only_beside_q_WB(initial):
    with pytest.raises(ValueError, match=r"^initial.scalar_first: expected it only beside q_WB"):
        parse_initial(initial)


@pytest.mark.parametrize("initial, field, expected", [
    ({"euler": {"angles": [0, 0, 0]}}, "initial.euler.seq", "a value"),
    ({"euler": {"seq": "ZYX"}}, "initial.euler.angles", "a value"),
    ({"euler": {"seq": "ZYQ", "angles": [0, 0, 0]}}, "initial.euler.seq", "one of the 12 axis sequences"),
    ({"euler": {"seq": 3, "angles": [0, 0, 0]}}, "initial.euler.seq", "an axis sequence"),
    ({"euler": {"seq": "ZYX", "angles": [0, 0]}}, "initial.euler.angles", "an array of 3 numbers"),
    ({"euler": {"seq": "ZYX", "angles": [0, 0, 0], "degrees": "yes"}}, "initial.euler.degrees", "true"),
    ({"euler": [0, 0, 0]}, "initial.euler", "a table"),
    ({"rotvec": {"degrees": True}}, "initial.rotvec.value", "a rotation vector"),
    ({"rotvec": [0, 0]}, "initial.rotvec", "an array of 3 numbers"),
    ({"rotvec": "z"}, "initial.rotvec",
     r"an array of 3 numbers \[rad\] or a table \{value = \[x, y, z\], degrees = true\}"),
    ({"axis_angle": {"axis": [0, 0, 0], "angle": 1.0}}, "initial.axis_angle.axis", "a non-zero vector"),
    ({"axis_angle": {"axis": [0, 0, 1]}}, "initial.axis_angle.angle", "a value"),
    ({"axis_angle": {"axis": [0, 0, 1], "angle": "30"}}, "initial.axis_angle.angle", "rad, got '30' \\(a unit"),
    ({"axis_angle": {"axis": [0, 0, 1], "angle": math.inf}}, "initial.axis_angle.angle", "a finite number"),
])
def test_orientation_errors_name_the_field(initial, field, expected):
    with pytest.raises(ValueError, match=rf"^{re.escape(field)}: expected {expected}"):
        parse_initial(initial)


# ---------------------------------------------------------------- near-unit quaternions

def test_hand_typed_quaternion_is_normalised_with_a_note():
    typed = [0.0, 0.0, 0.7071, 0.7071]
    norm = math.hypot(0.7071, 0.7071)  # 0.99999040..., within 1e-3 of 1
    with pytest.warns(UserWarning, match=rf"^initial.q_WB: normalised \[0.0, 0.0, 0.7071, 0.7071\] "
                                         rf"\(\|q\| = {norm:.9g}\) to unit norm") as caught:
        q = parse_initial({"q_WB": typed}).q_WB
    assert caught[0].filename == __file__  # the note points at the caller, not into the package
    # q / |q| when read (1/2 ulp from 0.7071 / norm, norm from hypot within 1 ulp: ~1.5 eps relative),
    # normalised again by Problem (<= 2.5 eps, see assert_normalised_from): 4 eps relative; the
    # stored |q| within 2 eps of 1 (four components, each rounded once, summed in double)
    np.testing.assert_allclose(q, np.array(typed) / norm, rtol=4 * EPS, atol=0)
    assert abs(np.linalg.norm(q) - 1.0) <= 2 * EPS


def test_note_through_load_problem_and_the_constructor(tmp_path):
    path = tmp_path / "p.toml"
    path.write_text('horizon = 1.0\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 2.5]\n'
                    '[initial]\nq_WB = [1.0, 0.0, 0.0, 0.0005]\nscalar_first = true\n')
    with pytest.warns(UserWarning, match=r"^initial.q_WB: normalised \[0.0, 0.0, 0.0005, 1.0\]"):
        p = load_problem(path)
    assert p.q_WB[3] > 0.99 and abs(np.linalg.norm(p.q_WB) - 1.0) <= 2 * EPS
    with pytest.warns(UserWarning, match=r"^q_WB: normalised") as caught:
        Problem(name="p", mass=1.0, inertia_com=np.diag([1.0, 2.0, 2.5]), horizon=1.0, q_WB=[0, 0, 0, 1.0009])
    assert caught[0].filename == __file__


@pytest.mark.parametrize("q", [
    [0.0, 0.0, 0.0, 1.0],
    [0.0, 0.0, 0.7071067811865476, 0.7071067811865476],  # 1/sqrt 2 to 16 digits: |q| = 1 to an ulp
    [0.5, 0.5, 0.5, 0.5],
])
def test_unit_quaternion_has_no_note(q):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = parse_initial({"q_WB": q})
    assert abs(np.linalg.norm(p.q_WB) - 1.0) <= 2 * EPS


@pytest.mark.parametrize("scale, accepted", [(1 - 0.999e-3, True), (1 + 0.999e-3, True),
                                             (1 - 1.001e-3, False), (1 + 1.001e-3, False), (2.0, False)])
def test_quaternion_norm_bound(scale, accepted):
    q = (np.array([1.0, 2.0, 2.0, 4.0]) / 5.0 * scale).tolist()  # |q| = scale to an ulp
    if accepted:
        with pytest.warns(UserWarning, match=r"^initial.q_WB: normalised"):
            p = parse_initial({"q_WB": q})
        # q built with two roundings per component (/ 5, * scale: eps each relative), its norm within
        # ~2 eps of scale, then normalised twice (<= 3 eps): within 8 eps of the exact (0.2, 0.4, 0.4, 0.8)
        np.testing.assert_allclose(p.q_WB, [0.2, 0.4, 0.4, 0.8], rtol=0, atol=8 * EPS)
        return
    with pytest.raises(ValueError, match=rf"^initial.q_WB: expected a unit quaternion \(\| \|q\| - 1 \| <= 0.001, "
                                         rf"then normalised\), got \[.*\] of norm \|q\| = {scale:.9g}$"):
        parse_initial({"q_WB": q})


def test_note_is_shown_by_the_command_line(tmp_path, capsys):
    from rigiddyn.__main__ import main

    path = tmp_path / "p.toml"
    path.write_text('horizon = 0.1\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 2.5]\n'
                    '[initial]\nq_WB = [0.0, 0.0, 0.7071, 0.7071]\nw_B = [0.1, 1.0, 0.0]\n')
    with warnings.catch_warnings():  # as outside pytest (whose filter turns warnings into errors)
        warnings.simplefilter("default")
        code = main(["simulate", str(path), "--method", "rk4", "--dt", "0.05", "--out", str(tmp_path / "out"),
                     "--no-plot", "--no-progress"])
    err = capsys.readouterr().err
    assert code == 0 and "rigiddyn: UserWarning: initial.q_WB: normalised [0.0, 0.0, 0.7071, 0.7071]" in err, err


# ---------------------------------------------------------------- angular rates with a unit

@pytest.mark.parametrize("unit, value, expected", [
    ("rad/s", [0.1, -2.0, 30.0], [0.1, -2.0, 30.0]),
    ("deg/s", [180.0, 90.0, -45.0], [math.pi, math.pi / 2, -math.pi / 4]),
    ("deg/s", [360.0, 1.0, 0.0], [2 * math.pi, math.pi / 180, 0.0]),
    ("rpm", [60.0, -30.0, 3000.0], [2 * math.pi, -math.pi, 100 * math.pi]),
    ("turn/s", [1.0, -0.5, 0.25], [2 * math.pi, -math.pi, math.pi / 2]),  # any unit of angle per time
])
def test_angular_rate_units(unit, value, expected):
    p = parse_initial({"w_B": {"value": value, "unit": unit}})
    # value x (factor rounded once) rounded once, against the exact product rounded once (expected,
    # from math.pi with exact scalings by powers of two or one rounding): within 2 eps relative
    np.testing.assert_allclose(p.w_B, expected, rtol=2 * EPS, atol=0)
    if unit == "rad/s":
        np.testing.assert_array_equal(p.w_B, parse_initial({"w_B": value}).w_B)


@pytest.mark.parametrize("w_B, field, expected", [
    ({"value": [1, 2, 3], "unit": "m/s"}, "initial.w_B.unit", r"rad/s, got 'm/s' \(\[length\] / \[time\]\)"),
    ({"value": [1, 2, 3]}, "initial.w_B.unit", "a value"),
    ({"unit": "rpm"}, "initial.w_B.value", "a value"),
    ({"value": [1, 2], "unit": "rpm"}, "initial.w_B.value", "an array of 3 values"),
    ("fast", "initial.w_B", "an array of 3 values, got 'fast'"),
    ({"value": [1, 2, 3], "units": "rpm"}, "initial.w_B.units", r"a key of \[initial.w_B\]; did you mean 'unit'\?"),
])
def test_angular_rate_errors_name_the_field(w_B, field, expected):
    with pytest.raises(ValueError, match=rf"^{re.escape(field)}: expected {expected}"):
        parse_initial({"w_B": w_B})


# ---------------------------------------------------------------- unknown keys: did you mean

def _with(path, key, value=1.0):
    """A valid problem with `key` added to the table at `path` (a tuple of keys and list indices)."""
    data = {"horizon": 1.0, "body": dict(BODY),
            "initial": {"euler": {"seq": "ZYX", "angles": [0, 0, 0]}, "w_B": {"value": [0, 0, 1], "unit": "rpm"}},
            "loads": [{"torque": [0.0, 0, 1]}], "tradeoff": {"dts": [0.1]}}
    if path and path[0] == "body" and len(path) == 2:
        data["body"] = ({"primitive": {"shape": "solid_sphere", "radius": 1.0, "mass": 1.0}} if path[1] == "primitive"
                        else {"mesh": {"path": "part.stl", "mass": 1.0}})
    if path == ("initial", "rotvec"):
        data["initial"] = {"rotvec": {"value": [0, 0, 1]}}
    if path == ("initial", "axis_angle"):
        data["initial"] = {"axis_angle": {"axis": [0, 0, 1], "angle": 1.0}}
    table = data
    for k in path:
        table = table[k]
    table[key] = value
    return data


DID_YOU_MEAN = [  # (table path, its name in messages, typed key, suggestion)
    ((), "problem", "horizn", "horizon"),
    ((), "problem", "Gravity", "gravity"),
    (("body",), "body", "inertia_chek", "inertia_check"),
    (("body", "primitive"), "body.primitive", "radus", "radius"),
    (("body", "mesh"), "body.mesh", "densty", "density"),
    (("initial",), "initial", "w_b", "w_B"),
    (("initial",), "initial", "omega", "w_B"),
    (("initial",), "initial", "eular", "euler"),
    (("initial", "euler"), "initial.euler", "angels", "angles"),
    (("initial", "euler"), "initial.euler", "degree", "degrees"),
    (("initial", "rotvec"), "initial.rotvec", "values", "value"),
    (("initial", "axis_angle"), "initial.axis_angle", "axes", "axis"),
    (("initial", "w_B"), "initial.w_B", "units", "unit"),
    (("loads", 0), "loads[0]", "torqe", "torque"),
    (("tradeoff",), "tradeoff", "tolerence", "tolerance"),
]


@pytest.mark.parametrize("path, table, key, suggestion", DID_YOU_MEAN, ids=[f"{t}.{k}" for _, t, k, _ in DID_YOU_MEAN])
def test_unknown_key_suggests_the_closest(path, table, key, suggestion):
    with pytest.raises(ValueError, match=rf"^{re.escape(table)}.{key}: expected a key of .*; did you mean "
                                         rf"'{suggestion}'\? \(one of: .*\), got an unknown key$"):
        parse_problem(_with(path, key))


def test_every_table_has_a_did_you_mean_case():
    covered = {"loads" if t.startswith("loads[") else t for _, t, _, _ in DID_YOU_MEAN}
    assert covered == set(problem_module._KEYS)


def test_misspelt_primitive_shape_and_its_key():
    with pytest.raises(ValueError, match=r"^body.primitive.shape: expected one of .* \(did you mean 'solid_box'\?\), "
                                         r"got 'solid_bx'$"):
        parse_problem({"horizon": 1.0, "body": {"primitive": {"shape": "solid_bx", "size": [1, 2, 3], "mass": 1.0}}})
    with pytest.raises(ValueError, match=r"^body.primitive.shap: expected a key of \[body.primitive\]; "
                                         r"did you mean 'shape'"):
        parse_problem({"horizon": 1.0, "body": {"primitive": {"shap": "solid_box", "size": [1, 2, 3], "mass": 1.0}}})


@pytest.mark.parametrize("path, key, home", [
    (("body",), "w_B", r"\[initial\]"),
    (("initial",), "degrees", r"\[initial.euler\] or \[initial.rotvec\] or \[initial.axis_angle\]"),
    (("initial",), "horizon", "the top level"),
    ((), "torque", r"\[\[loads\]\]"),
])
def test_key_in_the_wrong_table_names_its_table(path, key, home):
    with pytest.raises(ValueError, match=rf"; '{key}' belongs in {home} \(one of: "):
        parse_problem(_with(path, key))


def test_unrelated_key_lists_the_table_keys():
    with pytest.raises(ValueError, match=r"^tradeoff.colour: expected a key of \[tradeoff\] "
                                         r"\(one of: dts, measure, methods, tolerance\), got an unknown key$"):
        parse_problem(_with(("tradeoff",), "colour"))


# ---------------------------------------------------------------- the documented format

def _documented_example():
    """The literal block after '::' in problem.py's docstring: its indented lines and blank lines."""
    block = []
    for line in problem_module.__doc__.split("::\n\n", 1)[1].splitlines():
        if line.strip() and not line.startswith("    "):
            break
        block.append(line)
    return textwrap.dedent("\n".join(block))


def test_documented_example_parses_and_shows_every_key():
    text = _documented_example()
    p = parse_problem(tomllib.loads(text))
    assert p.name == "tumbling T-handle" and p.loads and p.tradeoff
    for table, keys in problem_module._KEYS.items():
        shown = keys if table != "body.primitive" else {"shape", "size", "mass", "density"}  # shapes: PRIMITIVES
        for key in shown:
            # `key = value` or a table header [..key] / [[key]]
            assert re.search(rf"\b{key}( =|\])", text), f"{table}.{key} is not in the documented example"


def test_documented_alternatives_of_initial_parse():
    # each commented `# key = ...` line of [initial] is a valid form of that key on its own
    lines = re.findall(r"^# ((?:w_B|euler|rotvec|axis_angle) = \{?.*?)(?:\s{2,}#.*)?$", _documented_example(), re.M)
    assert len(lines) == 6, lines
    for line in lines:
        p = parse_text(f"horizon = 1.0\n[body]\nmass = 2.0\ninertia = [1.0, 2.0, 2.5]\n[initial]\n{line}\n")
        assert abs(np.linalg.norm(p.q_WB) - 1.0) <= 2 * EPS and np.all(np.isfinite(p.w_B))
