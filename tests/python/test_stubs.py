"""The type stubs shipped with the package describe the compiled core as it is, with the types its docstrings
state (tests/python/typed_stub.py), and mypy accepts the package with them and checks a call (editors and type
checkers see the API)."""

import os
import pathlib
import re
import subprocess
import sys

import pytest

import rigiddyn
import typed_stub

PACKAGE = pathlib.Path(rigiddyn.__file__).resolve().parent
ROOT = pathlib.Path(__file__).resolve().parents[2]
STUB = ROOT / "python" / "rigiddyn" / "_core.pyi"


def test_stub_matches_the_extension(tmp_path: pathlib.Path) -> None:
    generated = typed_stub.generate(tmp_path)
    assert generated == STUB.read_text(), (
        "python/rigiddyn/_core.pyi is out of date: regenerate it with\n"
        "  PYTHONPATH=build/py/python python3 tests/python/typed_stub.py"
    )


@pytest.fixture(scope="module")
def mypy_cache(tmp_path_factory: pytest.TempPathFactory) -> pathlib.Path:
    """One mypy cache for the module's runs (same options): the second run reuses the first one's analysis of
    numpy and the package (most of a run's time). Its tests share an xdist worker (tests/run_all.sh: --dist
    loadgroup), so the cache is filled once."""
    return tmp_path_factory.mktemp("mypy_cache")


def _mypy(cache: pathlib.Path, *targets: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", str(ROOT / "pyproject.toml"), "--cache-dir", str(cache),
         *targets],
        capture_output=True, text=True, cwd=ROOT / "python", env=dict(os.environ, MYPYPATH=str(ROOT / "python")),
    )


@pytest.mark.xdist_group("mypy")
def test_mypy_strict_accepts_the_package(mypy_cache: pathlib.Path) -> None:
    result = _mypy(mypy_cache, "-p", "rigiddyn")
    assert result.returncode == 0, result.stdout + result.stderr


REJECTED = """\
import numpy as np
import rigiddyn as rd

body, state = rd.RigidBody(1.0, np.eye(3)), rd.RigidBodyState()
rd.simulate(body, state, dt="1", steps=10)  # line 5: a str for a float
rd.simulate(body, state, dt=0.01, steps=10, method="rk5")  # line 6: no such method
rd.Scene().compile("rk4").describe()
rd.quat_rotate([0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0], scalar_first="no")  # line 8: a str for a bool
"""


@pytest.mark.xdist_group("mypy")
def test_mypy_strict_accepts_the_readme_and_rejects_wrong_types(tmp_path: pathlib.Path,
                                                                mypy_cache: pathlib.Path) -> None:
    (example,) = re.findall(r"```python\n(.*?)```", (ROOT / "README.md").read_text(), flags=re.DOTALL)
    readme, rejected = tmp_path / "readme_example.py", tmp_path / "rejected.py"
    # allow-redefinition (for this file only): the README's example is one script that reuses names (run, start,
    # exact) for values of other classes, as a reader's script does
    readme.write_text("# mypy: allow-redefinition\n" + example)
    rejected.write_text(REJECTED)
    result = _mypy(mypy_cache, str(readme), str(rejected))
    errors = re.findall(r"^(\S+?):(\d+): error", result.stdout, flags=re.MULTILINE)
    assert {(pathlib.Path(f).name, int(line)) for f, line in errors} == {
        ("rejected.py", 5), ("rejected.py", 6), ("rejected.py", 8)}, result.stdout + result.stderr


@pytest.mark.parametrize("words, default_none, expected", [
    ("array_like, shape (3,), or pint.Quantity, optional", True, "numpy.typing.ArrayLike | _Quantity | None"),
    ("float [m], default 0.0", False, "float"),
    ("{'body', 'world'}, default 'body'", False, "typing.Literal['body', 'world']"),
    ("AppliedLoad or sequence of AppliedLoad, optional", True,
     "AppliedLoad | collections.abc.Sequence[AppliedLoad] | None"),
    ("None, bool or array_like, default None", True, "bool | numpy.typing.ArrayLike | None"),
    ("ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, ..., or list", False, None),
])
def test_docstring_types_become_annotations(words: str, default_none: bool, expected: str | None) -> None:
    classes = {"AppliedLoad", "ParticleState", "PlanarBodyState", "RigidBodyState", "PivotedBodyState"}
    assert typed_stub.annotation(words, default_none, classes) == expected
