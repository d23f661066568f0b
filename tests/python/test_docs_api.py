"""The API reference (docs/api/*.rst) documents exactly the package's public names, each once.

Runs without Sphinx: it reads the reST sources (the names listed under ``.. autosummary::`` in the
module set by ``.. currentmodule::``, and the modules of ``.. automodule::``) and compares them with
``rigiddyn.__all__`` and the public names of the public modules. A name added to the package without a
place in the reference, or a name documented twice or no longer in the package, fails here (the -W
Sphinx build catches a name that does not import, not one that is missing).
"""

from __future__ import annotations

import collections
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import rigiddyn

API = Path(__file__).resolve().parents[2] / "docs" / "api"

# the modules of rigiddyn that are not documented as modules, and why
INTERNAL = {
    "_core": "the compiled core: re-exported by rigiddyn (rigiddyn.__all__)",
    "__main__": "the command line (python3 -m rigiddyn --help)",
    "simulate_command": "the command line: python3 -m rigiddyn simulate",
    "tradeoff_command": "the command line: python3 -m rigiddyn tradeoff",
    "scene_simulate": "the command line: simulate on scene files",
    "out_folder": "the command line: the --out folder",
    "worked_example": "the command line: python3 -m rigiddyn worked-example",
    "inertia_mesh": "its names are rigiddyn's (solid_mesh, mesh_shell)",
    "rotation_scipy": "its names are rigiddyn's (to_scipy, from_scipy)",
    "scene_describe": "attaches Scene.describe and CompiledScene.describe",
    "scene_precision": "tradeoff's machinery for scenes (documented through rigiddyn.tradeoff)",
    "_names": "the closest known name for the 'did you mean' of error messages (their messages state it)",
    "_measures": "the names, units and meanings of tradeoff's error measures (rigiddyn.work_precision's)",
    "_memory": "the memory estimates of scene_file's [[cluster]] and dispersion (their docs state them)",
    "_loaded_file": "SceneFile and RunOptions, documented as rigiddyn.scene_file's (which re-exports them)",
    "_balance": "its names are rigiddyn's (Balance, AccuracyWarning; simulate makes the balance of every run)",
    "_core_call": "the core's messages re-addressed to a file's fields (the file formats' messages state them)",
    "_mass_properties": "the body forms of problem and scene files (rigiddyn.problem and rigiddyn.scene_file list them)",
    "_load_table": "the load tables of problem and scene files (rigiddyn.problem and rigiddyn.scene_file list them)",
    "_controlled_samples": "monte_carlo's samples under a controller (rigiddyn.dispersion.monte_carlo states them)",
    "_controller_table": "the [controller] table of scene files (rigiddyn.scene_file and the spacecraft guide list it)",
    "_tree_table": "the [[tree]] tables of scene files (rigiddyn.scene_file lists their keys)",
}

_DIRECTIVE = re.compile(r"^\.\. (currentmodule|automodule|autosummary)::\s*(\S*)\s*$")


def documented_names(sources: list[Path]) -> list[str]:
    """The full names the API pages document, with repeats: every autosummary entry (qualified by the
    current module) and every automodule."""
    names: list[str] = []
    for path in sources:
        module = None
        in_summary = False
        for line in path.read_text(encoding="utf-8").splitlines():
            match = _DIRECTIVE.match(line)
            if match:
                kind, argument = match.groups()
                in_summary = kind == "autosummary"
                if kind == "currentmodule":
                    module = argument
                elif kind == "automodule":
                    names.append(argument)
                continue
            if not in_summary or not line.strip():
                continue
            if not line[0].isspace():          # the directive's body has ended
                in_summary = False
            elif not line.strip().startswith(":"):   # an entry (not an option such as :toctree:)
                assert module is not None, f"{path.name}: autosummary before any currentmodule"
                names.append(f"{module}.{line.strip()}")
    return names


def public_names(module: object) -> list[str]:
    """A module's public names: its __all__, or (without one) the classes and functions defined in it
    and its UPPER_CASE constants."""
    if hasattr(module, "__all__"):
        return list(module.__all__)
    name = module.__name__  # type: ignore[attr-defined]
    return [n for n, obj in vars(module).items()
            if not n.startswith("_") and not inspect.ismodule(obj)
            and (getattr(obj, "__module__", None) == name or n.isupper())]


def expected_names(modules: list[str]) -> list[str]:
    """rigiddyn.__all__, the public modules `modules` and their public names, each under one full name:
    a name that rigiddyn re-exports (the same object) is documented as rigiddyn.<name>."""
    expected = [f"rigiddyn.{n}" for n in rigiddyn.__all__] + list(modules)
    for module_name in modules:
        module = importlib.import_module(module_name)
        for n in public_names(module):
            reexported = n in rigiddyn.__all__ and getattr(rigiddyn, n) is getattr(module, n)
            expected.append(f"rigiddyn.{n}" if reexported else f"{module_name}.{n}")
    return expected


def test_sources_exist():
    assert (API / "index.md").is_file()
    assert len(sorted(API.glob("*.rst"))) >= 2


def test_every_public_name_is_documented_once():
    documented = documented_names(sorted(API.glob("*.rst")))
    modules = sorted({n for n in documented if inspect.ismodule(_resolve(n))})
    expected = expected_names(modules)
    counts = collections.Counter(documented)
    missing = sorted(set(expected) - set(counts))
    repeated = sorted(n for n, c in counts.items() if c > 1)
    unknown = sorted(set(counts) - set(expected))
    assert not missing, f"public names without a place in docs/api: {missing}"
    assert not repeated, f"names documented more than once in docs/api: {repeated}"
    assert not unknown, f"documented in docs/api but not public names of the package: {unknown}"


def test_every_module_is_documented_or_internal():
    documented = set(documented_names(sorted(API.glob("*.rst"))))
    for info in pkgutil.iter_modules(rigiddyn.__path__):
        full = f"rigiddyn.{info.name}"
        assert (full in documented) != (info.name in INTERNAL), (
            f"{full}: expected either documented in docs/api (automodule) or listed in INTERNAL, not both")
    for name in ("inertia_mesh", "rotation_scipy"):
        module = importlib.import_module(f"rigiddyn.{name}")
        assert all(getattr(rigiddyn, n, None) is getattr(module, n) for n in public_names(module)), name


def test_parser_sees_what_it_should(tmp_path):
    """The parser itself: entries under the current module, options skipped, the block ended by text."""
    page = ("x\n=\n\n.. currentmodule:: rigiddyn\n\n.. autosummary::\n   :toctree: generated\n\n"
            "   simulate\n   step\n\nText.\n\n   not_an_entry\n\n.. automodule:: rigiddyn.units\n"
            ".. currentmodule:: rigiddyn.units\n.. autosummary::\n\n   to_si\n")
    path = tmp_path / "page.rst"
    path.write_text(page, encoding="utf-8")
    assert documented_names([path]) == ["rigiddyn.simulate", "rigiddyn.step", "rigiddyn.units",
                                        "rigiddyn.units.to_si"]


def _resolve(full_name: str) -> object:
    """The object of a dotted name under rigiddyn (a module or an attribute of one); None if there is none."""
    parts = full_name.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr, None)
        return obj
    return None
