"""The docstring renderer of the API reference (docs/_ext/rigiddyn_docstrings.py) turns any free-form
text into reST that parses without a warning, and keeps the text: the summary sentence as a paragraph,
the rest verbatim."""

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
from rigiddyn_docstrings import render_docstring  # noqa: E402


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
