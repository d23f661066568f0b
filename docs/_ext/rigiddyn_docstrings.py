"""Faithful rendering of rigiddyn's free-form docstrings for autodoc.

rigiddyn's docstrings (the pybind11 bindings' and the Python modules' alike) are plain text, not reST:
their line layout carries meaning (the aligned forms of a constructor, "argument: ..." lines with
indented continuations, code samples, tables of keys). Parsed as reST they warn (an unmatched ``*``, an
unexpected indentation) or, worse, parse silently into something else (a definition list, a reflowed
table). So each docstring becomes:

- its first sentence, as a reST paragraph with every markup character escaped (the summary that
  autosummary's tables show): the leading unindented lines up to the first one that ends with "." or
  ":" (or up to a blank or indented line);
- the rest, verbatim, as a literal block of plain text (docutils' ``code`` directive, language text: no
  highlighting; relative indentation kept; class rigiddyn-docstring, whose long lines
  docs/_static/rigiddyn.css wraps rather than scrolls).

Neither part can produce a reST warning, whatever the text.
"""

from __future__ import annotations

import re

# inline markup (emphasis, literals, interpreted text, references, substitutions, field/role colons)
# and the escape character itself
_MARKUP = re.compile(r"([\\*`_|:])")


def _escaped(text: str) -> str:
    """`text` as one line of reST that shows it literally. The line starts with an escaped space (which
    shows nothing) so that no line-start construct (a list, a comment, a transition, a line block)
    can begin there."""
    return "\\ " + _MARKUP.sub(r"\\\1", text)


def _first_sentence(lines: list[str]) -> int:
    """The number of leading lines that form the summary paragraph (0 when the first is indented)."""
    n = 0
    for line in lines:
        if not line.strip() or line[0].isspace():
            break
        n += 1
        if line.rstrip().endswith((".", ":")):
            break
    return n


def render_docstring(lines: list[str]) -> list[str]:
    """reST lines for the free-form docstring `lines` (as autodoc hands them: dedented, one str per line):
    an escaped summary paragraph, then the remaining text verbatim in a plain-text literal block."""
    text = [line.expandtabs(8).rstrip() for line in lines]
    while text and not text[0]:
        text.pop(0)
    while text and not text[-1]:
        text.pop()
    if not text:
        return []
    n = _first_sentence(text)
    out = [_escaped(" ".join(line.strip() for line in text[:n]))] if n else []
    rest = text[n:]
    while rest and not rest[0]:
        rest.pop(0)
    if rest:
        out += ["", ".. code:: text", "   :class: rigiddyn-docstring", ""]
        out += [("    " + line) if line else "" for line in rest]
    return out + [""]
