"""The type stubs shipped with the package describe the compiled core as it is, and mypy accepts
the package with them (editors and type checkers see the API)."""

import os
import pathlib
import subprocess
import sys

import rigiddyn

PACKAGE = pathlib.Path(rigiddyn.__file__).resolve().parent
ROOT = pathlib.Path(__file__).resolve().parents[2]
STUB = ROOT / "python" / "rigiddyn" / "_core.pyi"


def generate_stub(out: pathlib.Path) -> str:
    # RIGIDDYN_STUBGEN=1: the core leaves out the runtime signatures (__text_signature__), so that the generator
    # reads the typed signature lines of the docstrings (it reads them only where inspect finds no signature)
    subprocess.run(
        [sys.executable, "-m", "pybind11_stubgen", "rigiddyn._core", "--exit-code",
         "--enum-class-locations", "InertiaCheck:rigiddyn._core", "-o", str(out)],
        check=True, capture_output=True, text=True, env=dict(os.environ, RIGIDDYN_STUBGEN="1"),
    )
    return (out / "rigiddyn" / "_core.pyi").read_text()


def test_stub_matches_the_extension(tmp_path: pathlib.Path) -> None:
    generated = generate_stub(tmp_path)
    assert generated == STUB.read_text(), (
        "python/rigiddyn/_core.pyi is out of date: regenerate it with\n"
        "  RIGIDDYN_STUBGEN=1 pybind11-stubgen rigiddyn._core --enum-class-locations InertiaCheck:rigiddyn._core -o python"
    )


def test_mypy_strict_accepts_the_package() -> None:
    env = dict(os.environ, MYPYPATH=str(ROOT / "python"))
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--config-file", str(ROOT / "pyproject.toml"),
         "--cache-dir", os.devnull, "-p", "rigiddyn"],
        capture_output=True, text=True, cwd=ROOT / "python", env=env,
    )
    assert result.returncode == 0, result.stdout + result.stderr
