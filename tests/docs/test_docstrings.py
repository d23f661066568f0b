"""The docstring renderer of the API reference (docs/_ext/rigiddyn_docstrings.py) turns any free-form
text into reST that parses without a warning, and keeps the text: the summary sentence as a paragraph,
the rest verbatim; and a docstring in numpydoc form into reST that napoleon makes fields of and that parses
without a warning, its equations' markup characters shown as written."""

from __future__ import annotations

import inspect
import random
import sys
from pathlib import Path

import docutils.core
import docutils.utils
import pytest

import rigiddyn

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "docs" / "_ext"))
from rigiddyn_docstrings import is_numpydoc, render_docstring, render_numpydoc  # noqa: E402
from sphinx.ext.napoleon import Config  # noqa: E402
from sphinx.ext.napoleon.docstring import NumpyDocstring  # noqa: E402


def parse(rst: str) -> tuple[str, list[str]]:
    """The text docutils makes of `rst`, and its system messages (warnings and errors)."""
    document = docutils.core.publish_doctree(rst, settings_overrides={"report_level": 5, "halt_level": 5})
    messages = [m.astext() for m in document.findall(docutils.nodes.system_message)]
    return document.astext(), messages


def docstrings() -> list[tuple[str, str]]:
    out = []
    for name in rigiddyn.__all__:
        obj = getattr(rigiddyn, name)
        out.append((name, inspect.getdoc(obj) or ""))
        for member, value in vars(obj).items() if inspect.isclass(obj) else ():
            if not member.startswith("_") and getattr(value, "__doc__", None):
                out.append((f"{name}.{member}", inspect.cleandoc(value.__doc__)))
    return out


@pytest.mark.parametrize("name, doc", docstrings(), ids=lambda x: x if isinstance(x, str) and "\n" not in x else "")
def test_package_docstrings_render_cleanly(name, doc):
    if is_numpydoc(doc.splitlines()):
        return  # test_numpydoc_docstrings_render_cleanly
    rst = "\n".join(render_docstring(doc.splitlines()))
    text, messages = parse(rst)
    assert not messages, f"{name}: {messages}"
    # nothing is lost: every word of the docstring is in the rendered text
    assert text.split() == doc.split()


def test_any_text_renders_cleanly():
    """Random text made of reST's markup characters, indentation and blank lines parses without a
    message (seeded: the same texts every run)."""
    rng = random.Random(14)
    alphabet = list("ab1 .:*`_|\\-+#=[]<>()") + ["  ", "\n", "\n\n", "\n  ", ".. ", "::", "1. ", "- "]
    for _ in range(2000):
        doc = "".join(rng.choice(alphabet) for _ in range(rng.randint(1, 60)))
        rst = "\n".join(render_docstring(doc.splitlines()))
        text, messages = parse(rst)
        assert not messages, (doc, rst, messages)
        assert text.split() == doc.split(), (doc, rst, text)


# Sphinx's own roles and directives in napoleon's output, which plain docutils does not know
SPHINX_MARKUP = ("Unknown interpreted text role", "No role entry", 'Unknown directive type "seealso"',
                 'No directive entry for "seealso"', 'Trying "seealso" as canonical directive name')
NAPOLEON = Config(napoleon_google_docstring=False, napoleon_numpy_docstring=True, napoleon_use_ivar=True)
NUMPYDOC = [(name, doc) for name, doc in docstrings() if is_numpydoc(doc.splitlines())]


@pytest.mark.parametrize("name, doc", NUMPYDOC, ids=[name for name, _ in NUMPYDOC])
def test_numpydoc_docstrings_render_cleanly(name, doc):
    lines = doc.splitlines()
    if lines and "(" in lines[0] and lines[0].split("(")[0].isidentifier():
        lines = lines[1:]  # pybind11's typed signature line (autodoc takes it as the signature)
    rst = str(NumpyDocstring(render_numpydoc(lines), NAPOLEON))
    _, messages = parse(rst)
    messages = [m for m in messages if not any(known in m for known in SPHINX_MARKUP)]
    assert not messages, f"{name}: {messages}"


def test_numpydoc_text_keeps_its_equations():
    """|v|, a product a * b and a word ending in _ show as written; doctest and literal blocks are untouched."""
    doc = ["Energy 1/2 m |v|^2 = a * b, for x_ only.", "", "Examples", "--------", ">>> 2 * 3", "6"]
    rst = "\n".join(render_numpydoc(doc))
    text, messages = parse(rst)
    assert not messages
    assert "Energy 1/2 m |v|^2 = a * b, for x_ only." in text
    assert ">>> 2 * 3" in rst
