"""Tables and plots in the user's units (rigiddyn.output_units): every converted column is its SI column
times the exact factor, to the factor's own float64 rounding; the files hold the converted columns and
read back; the simulate command's --units writes them and run.json says so; bad units are refused by name.

The exact factors below come from the units' definitions (km = 1000 m, h = 3600 s, g = 1e-3 kg,
kJ = 1000 J, kN = 1000 N, mW = 1e-3 W, deg = pi/180 rad), evaluated with mpmath to 40 digits, and each
column's new unit is written out by hand: neither is taken from the code under test.
"""

from __future__ import annotations

import doctest
import importlib
import json
import re

import mpmath
import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import scene_result, trajectory
from rigiddyn.__main__ import main
from rigiddyn.out_folder import EXIT_BAD_INPUT, EXIT_OK
from rigiddyn.output_units import (DIMENSIONS, check_units, convert_columns, convert_unit, parse_units_option,
                                   units_record)

mpmath.mp.dps = 40
UNITS = {"length": "km", "angle": "deg", "time": "h", "mass": "g", "energy": "kJ", "power": "mW", "force": "kN"}
# each SI unit of a column -> (its unit under UNITS, the exact factor from SI to it)
PER = {"m": mpmath.mpf(1) / 1000, "s": mpmath.mpf(1) / 3600, "rad": 180 / mpmath.pi, "kg": mpmath.mpf(1000)}
EXPECTED = {
    "s": ("h", PER["s"]),
    "m": ("km", PER["m"]),
    "m/s": ("km/h", PER["m"] / PER["s"]),
    "rad/s": ("deg/h", PER["rad"] / PER["s"]),
    "kg": ("g", PER["kg"]),
    "J": ("kJ", mpmath.mpf(1) / 1000),
    "W": ("mW", mpmath.mpf(1000)),
    "N": ("kN", mpmath.mpf(1) / 1000),
    "kg m/s": ("g km/h", PER["kg"] * PER["m"] / PER["s"]),
    "kg m^2/s": ("g km^2/h", PER["kg"] * PER["m"] ** 2 / PER["s"]),
}
# the factor is pint's conversion of 1: a few float64 operations on the units' definitions, each rounded
# to 2^-53 relative, so within 1e-15 (about 9 roundings) of the exact factor
FACTOR_ROUNDING = 1e-15
U = 2.0**-53  # the rounding of the one multiply of each value by its factor


def body_result(scalar_first=False, sample=True):
    """A run that moves every column: a tumbling, translating body under gravity with a torque; a batch
    sample, or with sample=False simulate's: the same SceneResult of the one body."""
    body = rd.RigidBody(1.5, np.diag([0.02, 0.03, 0.04]))
    start = rd.RigidBodyState(p_W=[0.1, -0.2, 3.0], v_W=[1.0, 0.5, 4.0], w_B=[0.3, 7.0, -0.2])
    options = dict(record_every=7, gravity=True, scalar_first=scalar_first, error=False,
                   loads=[rd.AppliedLoad(torque=[0.0, 0.0, 0.01], frame="body")])
    if sample:
        return rd.simulate_batch(body, [start], 1e-3, 200, "rk4", **options)[0]
    return rd.simulate(body, start, 1e-3, 200, "rk4", **options)


def scene_result_of_pendulum():
    """A pivoted body under gravity: pivot reactions [N], element work [J] and power [W] are all recorded."""
    scene, initial, _ = rd.load_scene("pendulum")
    return rd.simulate(scene, initial, dt=0.01, steps=30, method="rk4", record_every=3, error=False)


def split(column):
    """(base, SI unit or None) of a column's name."""
    match = re.fullmatch(r"(.*) \[([^\[\]]+)\]", column)
    return (column, None) if match is None else (match[1], match[2])


def assert_exact_conversion(si, converted):
    """`converted` holds every column of `si` in the units of UNITS: its name with the unit of EXPECTED, its
    values the SI values times pint's factor (bitwise: one multiply), that factor within FACTOR_ROUNDING of
    the exact one; the dimensionless columns unchanged."""
    assert len(converted) == len(si)
    for (name, values), (new_name, new_values) in zip(si.items(), converted.items()):
        base, unit = split(name)
        if unit is None:  # the quaternion's columns, quaternion_norm_error: never converted
            assert new_name == name
            np.testing.assert_array_equal(new_values, values, strict=True)
            continue
        new_unit, exact = EXPECTED[unit]
        assert new_name == f"{base} [{new_unit}]"
        factor, written = convert_unit(unit, UNITS)
        assert written == new_unit
        assert abs(mpmath.mpf(factor) - exact) <= FACTOR_ROUNDING * abs(exact), (name, factor)
        np.testing.assert_array_equal(new_values, values * factor, strict=True, err_msg=name)  # the one multiply
        # so each value is the exact product to the factor's rounding and the multiply's
        np.testing.assert_allclose(new_values, values * float(exact), rtol=FACTOR_ROUNDING + 2 * U, atol=0.0,
                                   err_msg=name)


def test_every_body_column_is_its_si_column_times_the_exact_factor():
    result = body_result()
    assert_exact_conversion(trajectory.columns(result), trajectory.columns(result, units=UNITS))
    assert scene_result.column_names(result, units=UNITS) == list(trajectory.columns(result, units=UNITS))
    run = body_result(sample=False)  # simulate's SceneResult: the same conversion of its wide table
    assert_exact_conversion(trajectory.columns(run), trajectory.columns(run, units=UNITS))


def test_the_units_of_the_task_name_their_columns():
    names = list(body_result().to_dataframe(units={"length": "km", "angle": "deg", "time": "h"}).columns)
    assert names[:8] == ["t [h]", "body0:p_W_x [km]", "body0:p_W_y [km]", "body0:p_W_z [km]", "body0:q_WB_x",
                         "body0:q_WB_y", "body0:q_WB_z", "body0:q_WB_w"]
    assert names[8:14] == ["body0:v_W_x [km/h]", "body0:v_W_y [km/h]", "body0:v_W_z [km/h]", "body0:w_B_x [deg/h]",
                           "body0:w_B_y [deg/h]", "body0:w_B_z [deg/h]"]
    assert "angular_momentum_W_x [kg km^2/h]" in names and "work[1] ScheduledLoads [J]" in names


def test_a_dimension_not_named_stays_si_bitwise():
    result = body_result()
    si, km = trajectory.columns(result), trajectory.columns(result, units={"length": "km"})
    assert list(km)[:2] == ["t [s]", "body0:p_W_x [km]"]
    for name in ("t [s]", "body0:w_B_x [rad/s]", "kinetic_energy [J]", "body0:q_WB_w"):
        np.testing.assert_array_equal(km[name], si[name], strict=True)
    for units in (None, {}):
        assert {k: v.tobytes() for k, v in trajectory.columns(result, units=units).items()} == \
            {k: v.tobytes() for k, v in si.items()}


def test_the_method_a_scalar_first_result_and_a_batch_sample_share_the_conversion():
    result = body_result(scalar_first=True)
    frame = result.to_dataframe(units=UNITS)
    table = trajectory.columns(result, units=UNITS)
    assert list(frame.columns) == list(table) and list(table)[4] == "body0:q_WB_w"
    for name, values in table.items():
        np.testing.assert_array_equal(frame[name].to_numpy(), values, strict=True)
    body = rd.RigidBody(1.5, np.diag([0.02, 0.03, 0.04]))
    batch = rd.simulate_batch(body, [rd.RigidBodyState(w_B=[0.1, 2.0, 0.1]), rd.RigidBodyState(v_W=[3.0, 0, 0])],
                              0.01, 20, threads=1)
    for i in range(2):
        assert_exact_conversion(trajectory.columns(batch[i]), trajectory.columns(batch[i], units=UNITS))


def test_every_scene_column_is_its_si_column_times_the_exact_factor():
    result = scene_result_of_pendulum()
    si = scene_result.columns(result)
    assert {split(name)[1] for name in si} >= {"s", "m", "m/s", "rad/s", "N", "kg m^2/s", "kg", "J", "W"}
    converted = scene_result.columns(result, units=UNITS)
    assert_exact_conversion(si, converted)
    frame = result.to_dataframe(units=UNITS)
    assert list(frame.columns) == list(converted)
    assert "rod:pivot_reaction_W_x [kN]" in frame and "power[0] UniformGravity [mW]" in frame


def test_a_scene_batch_sample_converts_as_a_scene_result():
    scene, initial, _ = rd.load_scene("pendulum")
    batch = rd.simulate_batch(scene.compile("rk4"), [initial, initial], 0.01, 6, threads=1)
    assert_exact_conversion(scene_result.columns(batch[1]), batch[1].to_dataframe(units=UNITS).to_dict("series"))


@pytest.mark.parametrize("suffix", [".csv", ".npz", ".parquet"])
def test_the_files_hold_the_converted_columns_and_read_back(tmp_path, suffix):
    if suffix == ".parquet":
        pytest.importorskip("pyarrow")
    result = body_result()
    writer = {".csv": trajectory.write_csv, ".npz": trajectory.write_npz, ".parquet": trajectory.write_parquet}[suffix]
    path = writer(result, tmp_path / f"table{suffix}", units=UNITS)
    back = trajectory.read_columns(path)
    table = trajectory.columns(result, units=UNITS)
    assert list(back) == list(table)
    for name, values in table.items():
        # bitwise: CSV prints each double by repr (read back to the same double), npz and Parquet store the bits
        np.testing.assert_array_equal(back[name], values, strict=True, err_msg=name)


def test_units_are_checked_before_a_file_is_opened(tmp_path):
    for writer in (trajectory.write_csv, trajectory.write_npz, trajectory.write_parquet):
        with pytest.raises(ValueError, match=r"^units: expected a dimension"):
            writer(body_result(), tmp_path / "t.csv", units={"lenght": "km"})
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------------------------------ bad input, named


@pytest.mark.parametrize(("units", "error", "message"), [
    ({"lenght": "km"}, ValueError, "units: expected a dimension among length, angle, time, mass, energy, power, "
                                   "force, got 'lenght' (did you mean 'length'?)"),
    ({"Time": "h"}, ValueError, "got 'Time' (did you mean 'time'?)"),
    ({"angular_velocity": "rpm"}, ValueError, "got 'angular_velocity' (a compound unit follows its parts: rad/s "
                                              "follows angle and time)"),
    ({"length": "s"}, ValueError, "units['length']: expected a unit of length (as m), got 's' (a unit of time)"),
    ({"time": "km"}, ValueError, "units['time']: expected a unit of time (as s), got 'km' (a unit of length)"),
    ({"energy": "N"}, ValueError, "units['energy']: expected a unit of energy (as J), got 'N' (a unit of force)"),
    ({"angle": "percent"}, ValueError, "units['angle']: expected a unit of angle (as rad), got 'percent' "
                                       "(a pure number)"),
    ({"angle": "rpm"}, ValueError, "units['angle']: expected a unit of angle (as rad), got 'rpm'"),
    ({"length": "km/s"}, ValueError, "units['length']: expected a unit of length (as m), got 'km/s' "
                                     "(a unit of [length] / [time])"),
    ({"length": "kilometre_x"}, ValueError, "units['length']: expected a unit such as \"km\", got 'kilometre_x' "
                                            "(unknown unit 'kilometre_x')"),
    ({"length": "2 km"}, ValueError, "units['length']: expected a unit such as \"km\", got '2 km'"),
    ({"length": "__import__('os')"}, ValueError, "units['length']: expected a unit such as \"km\""),
    ({"length": ""}, ValueError, "units['length']: expected a unit such as \"km\", got '' (no unit)"),
    ({"length": 1000}, TypeError, "units['length']: expected a unit as a string such as \"km\", got 1000"),
    ("length=km", TypeError, "units: expected a mapping of dimension to unit"),
    ([("length", "km")], TypeError, "units: expected a mapping of dimension to unit"),
])
def test_bad_units_are_refused_naming_the_value(units, error, message):
    with pytest.raises(error) as caught:
        body_result().to_dataframe(units=units)
    assert message in str(caught.value)
    with pytest.raises(error):
        scene_result_of_pendulum().to_dataframe(units=units)


@pytest.mark.parametrize(("text", "message"), [
    ("length:km", "--units: expected dimension=unit pairs separated by commas such as length=km,angle=deg,time=h, "
                  "got 'length:km'"),
    ("length=km,", "got ''"),
    ("length=km,length=m", "--units: expected each dimension once, got 'length' twice"),
    ("lenght=km", "--units: expected a dimension among length, angle, time, mass, energy, power, force, got "
                  "'lenght' (did you mean 'length'?)"),
    ("time=m", "--units time: expected a unit of time (as s), got 'm' (a unit of length)"),
])
def test_the_option_text_is_checked(text, message):
    with pytest.raises(ValueError) as caught:
        parse_units_option(text)
    assert message in str(caught.value)


def test_the_record_names_every_dimension():
    assert units_record(None) == DIMENSIONS
    assert units_record(parse_units_option(" length = km , time=h")) == {**DIMENSIONS, "length": "km", "time": "h"}
    assert check_units({"angle": "°"}) == {"angle": "°"}
    rpm = convert_columns({"w [rad/s]": np.array([np.pi])}, {"angle": "turn", "time": "min"})
    assert list(rpm) == ["w [turn/min]"]  # pi rad/s = 30 turns a minute, to the factor's and pi's roundings
    np.testing.assert_allclose(rpm["w [turn/min]"], [30.0], rtol=FACTOR_ROUNDING + 3 * U, atol=0.0)


@pytest.mark.parametrize("module", ["output_units", "units", "trajectory", "scene_result", "trajectory_plot"])
def test_the_examples_of_the_modules_run_and_print_what_they_show(module):
    """The docstrings of these modules' functions are outside rigiddyn.__all__ (test_docstrings runs those);
    their examples run here, as there (np and rd imported)."""
    if module == "trajectory_plot":
        pytest.importorskip("matplotlib")
    pytest.importorskip("pandas")
    pytest.importorskip("pyarrow")
    found = importlib.import_module(f"rigiddyn.{module}")
    failed, attempted = doctest.testmod(found, extraglobs={"np": np, "rd": rd},
                                        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert attempted > 0 and failed == 0, f"{module}: {failed} of {attempted} examples failed (output above)"
    if module == "trajectory_plot":
        import matplotlib.pyplot as plt

        assert not plt.get_fignums(), "an example left a figure open"


# ------------------------------------------------------------------ the command line

PROBLEM = ["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--steps", "20", "--no-plot", "--no-progress",
           "--no-error"]
SCENE = ["simulate", "pendulum", "--method", "rk4", "--dt", "0.01", "--steps", "20", "--no-plot", "--no-progress",
         "--no-error"]


@pytest.mark.parametrize("argv", [PROBLEM, SCENE], ids=["problem", "scene"])
def test_the_command_writes_the_converted_columns_and_records_the_units(tmp_path, capsys, argv):
    assert main([*argv, "--out", str(tmp_path / "si")]) == EXIT_OK
    assert main([*argv, "--out", str(tmp_path / "km"), "--units", "length=km,angle=deg,time=h"]) == EXIT_OK
    capsys.readouterr()
    si = trajectory.read_columns(tmp_path / "si" / "trajectory.csv")
    units = {"length": "km", "angle": "deg", "time": "h"}
    for name in ("trajectory.csv", "trajectory.npz"):
        converted = trajectory.read_columns(tmp_path / "km" / name)
        assert list(converted) == list(convert_columns(si, units))
        for (name, values), new_values in zip(si.items(), converted.values()):
            unit = split(name)[1]  # the SI run's values times the column's factor, bitwise (one multiply)
            expected = values if unit is None else values * convert_unit(unit, units)[0]
            np.testing.assert_array_equal(new_values, expected, strict=True, err_msg=name)
    record = json.loads((tmp_path / "km" / "run.json").read_text())
    assert record["units"] == {**DIMENSIONS, "length": "km", "angle": "deg", "time": "h"}
    assert record["columns"] == list(convert_columns(si, units))
    assert json.loads((tmp_path / "si" / "run.json").read_text())["units"] == DIMENSIONS
    if (tmp_path / "km" / "trajectory.parquet").exists():
        import pyarrow.parquet as pq

        stored = json.loads(pq.read_schema(tmp_path / "km" / "trajectory.parquet").metadata[b"rigiddyn"])
        assert stored["units"] == record["units"]


@pytest.mark.parametrize("argv", [PROBLEM, SCENE], ids=["problem", "scene"])
def test_bad_units_on_the_command_line_are_bad_input(tmp_path, capsys, argv):
    assert main([*argv, "--out", str(tmp_path / "o"), "--units", "length=s"]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err == "rigiddyn simulate: --units length: expected a unit of length (as m), got 's' (a unit of time)\n"
    assert not (tmp_path / "o").exists()


# ------------------------------------------------------------------ the plots


def test_the_plots_label_every_axis_with_its_unit():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from rigiddyn.trajectory_plot import scene_figure, trajectory_figure

    fig = trajectory_figure(body_result(sample=False), attitude="rotvec", units=UNITS)
    try:
        assert [ax.get_ylabel() for ax in fig.axes] == ["angular velocity w_B [deg/h]", "rotation vector in W [deg]",
                                                        "energy change\nsince t = 0 [kJ]",
                                                        "|L| change\nsince t = 0 [g km^2/h]"]
        assert fig.axes[-1].get_xlabel() == "t [h]"
        result = body_result(sample=False).body(0)
        factor = convert_unit("rad/s", UNITS)[0]
        np.testing.assert_array_equal(fig.axes[0].lines[1].get_ydata(), result.w_B[:, 1] * factor)
    finally:
        plt.close(fig)
    result = scene_result_of_pendulum()
    fig = scene_figure(result, ["PivotedBody"], units=UNITS)
    try:
        labels = [ax.get_ylabel() for ax in fig.axes]
        assert labels[:2] == ["position p_W [km]", "angular velocity\nw_B [deg/h]"]
        assert labels[2].endswith("[deg]") and fig.axes[-1].get_xlabel() == "t [h]"
        np.testing.assert_array_equal(fig.axes[0].lines[0].get_xdata(), result.t * convert_unit("s", UNITS)[0])
    finally:
        plt.close(fig)
    with pytest.raises(ValueError, match=r"^units\['time'\]: expected a unit of time"):
        trajectory_figure(body_result(), units={"time": "m"})
