"""The API reference a SciPy user reads: every public name's signature and docstring in numpydoc form, its
examples run.

Each public name (``rigiddyn.__all__``, and ``rigiddyn.work_precision.__all__`` beyond what rigiddyn
re-exports) and each public member of a public class is collected with its docstring. Three checks:

- ``inspect.signature`` works on every public callable (the compiled ones carry a runtime signature, and each
  class its constructor's), so ``help()``, IDEs and Sphinx show the parameters;
- every ``>>>`` example runs as a doctest and prints what it shows (``np`` and ``rd`` are imported;
  ``ELLIPSIS`` and ``NORMALIZE_WHITESPACE`` are on, so an example may elide digits beyond its point);
- every public callable has the numpydoc sections a reader looks for: ``Parameters`` (when it takes
  any), ``Returns`` (a function) and ``Examples``.
"""

from __future__ import annotations

import doctest
import inspect
import re
from typing import Iterator

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import work_precision

OPTIONS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE

def _public_names() -> Iterator[tuple[str, object]]:
    """rigiddyn's public names, then those of rigiddyn.work_precision that rigiddyn does not re-export (the
    sweep's reference states, rankings and recommendation: documented under their package)."""
    for name in sorted(rd.__all__):
        yield name, getattr(rd, name)
    for name in sorted(work_precision.__all__):
        obj = getattr(work_precision, name)
        if getattr(rd, name, None) is not obj:
            yield f"work_precision.{name}", obj


def public_objects() -> Iterator[tuple[str, object]]:
    """(qualified name, object) of every public name and every public member of a public class."""
    for name, obj in _public_names():
        yield name, obj
        if inspect.isclass(obj):
            for member, value in sorted(vars(obj).items()):
                if not member.startswith("_"):
                    # a property as declared (its getter's text); any other member as the reader gets it (a
                    # static method's function, not its staticmethod wrapper)
                    yield f"{name}.{member}", value if isinstance(value, property) else getattr(obj, member)


def docstring_of(obj: object) -> str:
    """The docstring as the reader sees it (a property's from its getter, a static method's from its function)."""
    if isinstance(obj, (staticmethod, classmethod)):
        obj = obj.__func__
    if isinstance(obj, property):
        return obj.__doc__ or (obj.fget.__doc__ if obj.fget else "") or ""
    return getattr(obj, "__doc__", None) or ""


def examples_of(name: str, obj: object) -> list[doctest.DocTest]:
    text = docstring_of(obj)
    if ">>>" not in text:
        return []
    parser = doctest.DocTestParser()
    return [parser.get_doctest(text, {"np": np, "rd": rd}, name, None, 0)]


ALL = list(public_objects())
WITH_EXAMPLES = [(name, obj) for name, obj in ALL if ">>>" in docstring_of(obj)]


@pytest.mark.parametrize(("name", "obj"), WITH_EXAMPLES, ids=[name for name, _ in WITH_EXAMPLES])
def test_examples_run_and_print_what_they_show(name: str, obj: object) -> None:
    runner = doctest.DocTestRunner(optionflags=OPTIONS)
    for test in examples_of(name, obj):
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} examples failed (output above)"


# The public classes without a public constructor: results, reports and records that the core makes. Calling one
# raises TypeError naming what makes it (each value here is a name the message must contain).
MADE_BY_THE_CORE = {
    "BatchSceneResult": "simulate_batch",
    "BodyRecords": "SceneResult.body",
    "ElementField": "SpringDamper.fields",
    "GlobalError": "result.error",
    "InertiaReport": "inertia_report",
    "SceneFrame": "SceneFrame.rotating",
    "SceneResult": "simulate(scene",
    "ToleranceChoice": "result.choice",
    "TreeLink": "Scene.add_tree",
    "WeldedMesh": "weld_vertices",
}
CALLABLES = [(name, obj) for name, obj in _public_names() if callable(obj)]


@pytest.mark.parametrize(("name", "obj"), CALLABLES, ids=[name for name, _ in CALLABLES])
def test_every_public_callable_has_a_signature(name: str, obj: object) -> None:
    parameters = inspect.signature(obj).parameters  # type: ignore[arg-type]
    if name in MADE_BY_THE_CORE:  # the call accepts any arguments, then refuses them, naming what makes one
        assert str(inspect.signature(obj)) == "(*args, **kwargs)"  # type: ignore[arg-type]
        for call in (lambda: obj(), lambda: obj(1.0, key=2)):  # type: ignore[operator]
            with pytest.raises(TypeError, match=f"^{name} has no public constructor: .*{re.escape(MADE_BY_THE_CORE[name])}"):
                call()
    assert all(p.name.isidentifier() for p in parameters.values()), f"{name}: {list(parameters)}"


def test_signatures_name_the_parameters_and_defaults() -> None:
    """The runtime signatures are pybind11's own record of each function: names, defaults, keyword-only marks."""
    assert str(inspect.signature(rd.quat_multiply)) == "(q1, q2, scalar_first=False)"
    assert str(inspect.signature(rd.RigidBody)) == "(mass, inertia_com=None, check=None)"
    simulate = inspect.signature(rd.simulate).parameters
    assert simulate["duration"].kind is inspect.Parameter.KEYWORD_ONLY and simulate["duration"].default is None
    assert simulate["method"].default is None and simulate["record_every"].default == 1
    assert str(inspect.signature(rd.StabilityWarning)).startswith("(*args")


def _section(text: str, title: str) -> bool:
    return re.search(rf"^\s*{title}\n\s*-{{{len(title)}}}\s*$", text, flags=re.MULTILINE) is not None


def missing_sections(name: str, obj: object) -> list[str]:
    """The numpydoc sections a public callable's docstring lacks."""
    text = docstring_of(obj)
    missing = [title for title in ("Examples",) if not _section(text, title)]
    if inspect.isclass(obj) and issubclass(obj, Warning):
        return []  # a warning category: its text says when it is raised
    takes_arguments = True
    try:
        signature = inspect.signature(obj)  # type: ignore[arg-type]
        takes_arguments = any(p.name not in ("self", "cls") for p in signature.parameters.values())
    except (TypeError, ValueError):
        pass
    if name in MADE_BY_THE_CORE:
        takes_arguments = False  # no constructor: its Attributes or static constructors are the reference
    if takes_arguments and not _section(text, "Parameters"):
        missing.append("Parameters")
    if not inspect.isclass(obj) and not _section(text, "Returns") and not _section(text, "Yields"):
        missing.append("Returns")
    return missing


@pytest.mark.parametrize(("name", "obj"), CALLABLES, ids=[name for name, _ in CALLABLES])
def test_public_callables_have_numpydoc_sections(name: str, obj: object) -> None:
    assert not missing_sections(name, obj), f"{name}: no {', '.join(missing_sections(name, obj))} section"


def test_the_section_check_finds_what_is_missing() -> None:
    def undocumented(x: float) -> float:
        """Twice x."""
        return 2.0 * x

    assert missing_sections("undocumented", undocumented) == ["Examples", "Parameters", "Returns"]
