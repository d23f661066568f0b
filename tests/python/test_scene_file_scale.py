"""Scenes of many bodies and scene files from anyone: adding N bodies takes O(N) (a name index, not a
comparison with every body), a file of 10^6 generated particles loads, a [[cluster]] count beyond the memory
is refused before any draw, a file of [[cluster]] tables only is a scene file, and TOML nested too deep is a
ValueError naming the file (scene and problem loaders alike)."""

import pickle
import re
import subprocess
import sys

import pytest

import rigiddyn
from rigiddyn import scene_file
from rigiddyn.problem import MAX_TOML_NESTING, load_problem, parse_problem
from rigiddyn.scene_file import CLUSTER_BYTES_PER_PARTICLE, is_scene_toml, load_scene, parse_scene, read_scene

CLUSTER_ONLY = """
[[cluster]]
model = "plummer"
count = {count}
total_mass = 1
scale_radius = 1
G = 1
seed = 3
"""

# 10^6 bodies added one by one, then a file of 10^6 generated particles loaded: measured at 4.5 s and 10 s
# on a loaded 2-core machine (one name compared with every body's took 296 s for 10^5 bodies and did not
# finish for 10^6). The subprocess timeout, 600 s, only catches the quadratic build.
MILLION = """
import rigiddyn as rd
from rigiddyn.scene_file import load_scene

n = 10**6
scene = rd.Scene()
particle = rd.Particle(1.0)
for i in range(n):
    assert scene.add_body(particle) == i
try:
    scene.add_body(particle, name="body123456")
except ValueError as e:
    assert "'body123456' is body 123456's" in str(e), e
else:
    raise SystemExit("a name taken by a default name was accepted")
assert scene.add_body(particle, name="last") == n
assert len(scene.bodies) == n + 1 and scene.body_names[-2:] == (f"body{{n - 1}}", "last")

text = {text!r}
loaded, initial, _ = load_scene(text)
assert len(loaded.bodies) == n and len(initial) == n
assert loaded.body_names[0] == "cluster0_0" and loaded.body_names[-1] == f"cluster0_{{n - 1}}"
assert type(loaded.elements[0]).__name__ == "MutualGravity"
print("ok")
"""


def test_a_million_bodies_are_added_and_loaded_in_linear_time():
    code = MILLION.format(text=CLUSTER_ONLY.format(count=10**6))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "ok"


def test_a_name_clash_is_still_found_among_many_bodies():
    scene = rigiddyn.Scene(bodies=[rigiddyn.Particle(1.0)] * 1000, body_names=[f"p{i}" for i in range(1000)])
    with pytest.raises(ValueError, match=r"name: expected a name no other body of the scene has \('p999' is body "
                                         r"999's\), got 'p999'"):
        scene.add_body(rigiddyn.Particle(1.0), name="p999")
    with pytest.raises(ValueError, match=r"body_names\[1\]: expected a name no other body of the scene has"):
        rigiddyn.Scene(bodies=[rigiddyn.Particle(1.0)] * 2, body_names=["a", "a"])
    assert scene.add_body(rigiddyn.Particle(2.0), name="body1001") == 1000
    with pytest.raises(ValueError, match=r"'body1001' is body 1000's\), got None"):
        scene.add_body(rigiddyn.Particle(2.0))  # index 1001: its default name is taken
    restored = pickle.loads(pickle.dumps(scene))  # a scene rebuilt from its pickle has its own name index
    with pytest.raises(ValueError, match=r"'p5' is body 5's"):
        restored.add_body(rigiddyn.Particle(1.0), name="p5")
    assert restored.add_body(rigiddyn.Particle(1.0), name="p1000") == 1001
    copied = scene.compile("rk4").scene  # a C++ copy: its name index starts empty and refills on first use
    with pytest.raises(ValueError, match=r"'p7' is body 7's"):
        copied.add_body(rigiddyn.Particle(1.0), name="p7")


def test_a_force_refers_to_a_body_among_many_and_a_wrong_name_lists_a_few():
    text = CLUSTER_ONLY.format(count=2000) + '\n[[force]]\ntype = "drag"\nlinear = 0.1\nbodies = ["cluster0_1999"]\n'
    scene, _, _ = load_scene(text)
    assert scene.elements[0].bodies == (1999,)
    bad = text.replace('bodies = ["cluster0_1999"]', 'bodies = ["cluster0_2000"]')
    with pytest.raises(ValueError) as e:
        load_scene(bad)
    message = str(e.value)
    assert message.startswith("force[0].bodies[0]: expected the name of a [[body]]: one of 'cluster0_0', ")
    assert "'cluster0_19', ... (2000 bodies)" in message and len(message) < 1000


def test_a_cluster_count_beyond_the_memory_is_refused_before_any_draw(monkeypatch):
    def no_draw(*args, **kwargs):
        raise AssertionError("plummer_sphere called")

    monkeypatch.setattr(scene_file, "plummer_sphere", no_draw)
    monkeypatch.setattr(scene_file, "available_bytes", lambda: 2**30)
    per = CLUSTER_BYTES_PER_PARTICLE
    with pytest.raises(ValueError) as e:
        load_scene(CLUSTER_ONLY.format(count=10**9))
    assert str(e.value) == (f"cluster[0].count: expected a count whose particles fit in the available memory "
                            f"(1 GiB: at most {2**30 // per} particles of about {per} bytes), got 1000000000 (an "
                            f"estimated {scene_file.format_bytes(10**9 * per)})")


def test_a_cluster_count_no_machine_holds_is_refused():
    with pytest.raises(ValueError, match=r"^cluster\[0\]\.count: expected a count whose particles fit in the "
                                         r"available memory .*, got 1000000000000000000 \(an estimated"):
        load_scene(CLUSTER_ONLY.format(count=10**18))


def test_a_file_of_clusters_only_is_a_scene_file(tmp_path):
    from rigiddyn.scene_precision import is_scene_source
    from rigiddyn.scene_simulate import is_scene_file

    path = tmp_path / "cluster.toml"
    path.write_text(CLUSTER_ONLY.format(count=20))
    problem = tmp_path / "problem.toml"
    problem.write_text("horizon = 1.0\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 2.5]\n")
    assert is_scene_toml(path) and is_scene_file(str(path)) and is_scene_source(str(path))
    assert not is_scene_toml(problem) and not is_scene_file(str(problem)) and not is_scene_source(str(problem))
    assert len(read_scene(path).scene.bodies) == 20


def test_the_simulate_command_runs_a_file_of_clusters_only(tmp_path):
    from rigiddyn.__main__ import main

    path = tmp_path / "cluster.toml"
    path.write_text(CLUSTER_ONLY.format(count=5))
    assert main(["simulate", str(path), "--dt", "0.01", "--steps", "3", "--out", str(tmp_path / "out"),
                 "--no-progress"]) == 0
    assert (tmp_path / "out" / "run.json").is_file()


DEEP = 10**4
NESTED = {
    "array": "x = " + "[" * DEEP + "]" * DEEP + "\n",
    "inline table": "x = " + "{a = " * DEEP + "1" + "}" * DEEP + "\n",
    "dotted keys": "name." + ".".join(["a"] * DEEP) + " = 1\n",
    "table header": "[" + ".".join(["a"] * DEEP) + "]\n",
}
NESTING = f"expected arrays and tables nested at most {MAX_TOML_NESTING} deep, got deeper ones"


@pytest.mark.parametrize("form", NESTED)
def test_toml_nested_too_deep_is_named_by_the_scene_loader(form, tmp_path):
    text = '[[body]]\nkind = "particle"\nmass = 1\n' + NESTED[form] if form != "table header" else NESTED[form]
    path = tmp_path / "deep.toml"
    path.write_text(text)
    with pytest.raises(ValueError, match=rf"^deep: {NESTING}$"):
        load_scene(path)
    with pytest.raises(ValueError, match=rf"^scene: {NESTING}$"):
        load_scene(text)


@pytest.mark.parametrize("form", NESTED)
def test_toml_nested_too_deep_is_named_by_the_problem_loader(form, tmp_path):
    path = tmp_path / "deep.toml"
    path.write_text("horizon = 1.0\n" + NESTED[form])
    with pytest.raises(ValueError, match=rf"^{re.escape(str(path))}: {NESTING}$"):
        load_problem(path)


def _nested(levels):
    """A table of `levels` tables within each other."""
    table = {}
    for _ in range(levels - 1):
        table = {"a": table}
    return table


def test_parsed_data_nested_too_deep_is_named():
    bodies = [{"kind": "particle", "mass": 1.0}]
    # the top-level table is the first level: x holds the other MAX_TOML_NESTING - 1, then one more
    with pytest.raises(ValueError, match=r"^scene\.x: expected a key of the top level"):
        parse_scene({"body": bodies, "x": _nested(MAX_TOML_NESTING - 1)}, "s")
    with pytest.raises(ValueError, match=rf"^s: {NESTING}$"):
        parse_scene({"body": bodies, "x": _nested(MAX_TOML_NESTING)}, "s")
    with pytest.raises(ValueError, match=rf"^p: {NESTING}$"):
        parse_problem({"horizon": 1.0, "x": [_nested(MAX_TOML_NESTING - 1)]}, source="p")


@pytest.mark.parametrize("form", NESTED)
def test_the_command_line_names_a_deep_file(form, tmp_path, capsys):
    from rigiddyn.__main__ import main

    path = tmp_path / "deep.toml"
    path.write_text('[[body]]\nkind = "particle"\nmass = 1\n' + NESTED[form])
    # taken for a scene file (dotted keys) or, where tomllib cannot read it, handed to the problem loader
    assert main(["simulate", str(path), "--dt", "0.1", "--steps", "1", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert f"{path}: {NESTING}" in err or f"deep: {NESTING}" in err, err


def test_integers_beyond_the_float_range_in_files_are_named(tmp_path):
    digits = "1" * 400  # a TOML integer tomllib reads as a Python int
    with pytest.raises(ValueError, match=r"^body\[0\]\.mass: expected kg, got 1{160}\.\.\. \(400 characters\) "
                                         r"\(beyond the float range\)$"):
        load_scene(f'[[body]]\nkind = "particle"\nmass = {digits}\n')
    path = tmp_path / "big.toml"
    path.write_text(f"horizon = {digits}\n[body]\nmass = 1.0\ninertia = [1.0, 2.0, 2.5]\n")
    # the problem file's number read by the same code as the scene file's: the same message
    with pytest.raises(ValueError, match=r"^horizon: expected s, got 1{160}\.\.\. \(400 characters\) "
                                         r"\(beyond the float range\)$"):
        load_problem(path)
    path.write_text(f"horizon = {'1' * 5000}\n")  # more digits than Python's int() converts
    with pytest.raises(ValueError, match=rf"^{re.escape(str(path))}: expected valid TOML, got Exceeds the limit"):
        load_problem(path)
    with pytest.raises(ValueError, match=r"^scene: expected valid TOML, got Exceeds the limit"):
        load_scene(f'[[body]]\nkind = "particle"\nmass = {"1" * 5000}\n')
