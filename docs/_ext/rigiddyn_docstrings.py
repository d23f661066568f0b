"""Faithful rendering of rigiddyn's docstrings for autodoc.

A docstring in numpydoc form (Parameters, Returns, ..., Examples) is kept as reST, with the characters that the
equations of its text use and reST would read as markup escaped (render_numpydoc): a lone ``*`` (a product), ``|``
(a norm, |v|), a trailing ``_`` (a reference); its doctest blocks and literal blocks stay as they are. This runs
before sphinx.ext.napoleon turns the sections into reST fields. Any other docstring is free-form text:

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
# a numpydoc section header: its title, then a line of dashes under it
_SECTIONS = ("Parameters", "Returns", "Yields", "Raises", "Warns", "See Also", "Notes", "References", "Examples",
             "Attributes", "Methods", "Other Parameters")
# in numpydoc text: a lone * (a product; not **bold**), every |, a _ that ends a word
_TEXT_MARKUP = re.compile(r"(?<![*\\])\*(?![*])|(?<!\\)\||(?<=\w)_(?=\s|$|[.,;:)\]])")


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


def is_numpydoc(lines: list[str]) -> bool:
    """True for a docstring in numpydoc form: it has a section header (a title of _SECTIONS over its dashes)."""
    return any(line.strip() in _SECTIONS and nxt.strip() and set(nxt.strip()) == {"-"} and
               len(nxt.strip()) >= len(line.strip()) for line, nxt in zip(lines, lines[1:]))


# a line that reST would start an enumerated list with: a lone letter and "." or ")" (a frame's name, "B.")
_LETTER_ENUMERATOR = re.compile(r"^(\s*)([A-Za-z][.)](?: |$))")


def _escaped_text(line: str) -> str:
    """A line of numpydoc text with the equation characters that reST reads as markup escaped; ``literal``
    spans kept."""
    line = _LETTER_ENUMERATOR.sub(lambda m: m.group(1) + "\\ " + m.group(2), line)
    parts = re.split(r"(``[^`]+``)", line)
    return "".join(part if part.startswith("``") else _TEXT_MARKUP.sub(lambda m: "\\" + m.group(0), part)
                   for part in parts)


def render_numpydoc(lines: list[str]) -> list[str]:
    """reST lines for a docstring in numpydoc form (before napoleon reads its sections): the text escaped (_escaped_text), the doctest
    blocks (from a ">>>" line to the next blank line) and literal blocks (the indented lines after a "::") as
    they are."""
    out: list[str] = []
    in_doctest = False
    literal_indent: int | None = None  # the indentation of the paragraph that ended with "::"
    for line in lines:
        stripped = line.strip()
        indent = len(line) - len(line.lstrip())
        if not stripped:
            in_doctest = False
            out.append(line)
            continue
        if literal_indent is not None and indent > literal_indent:
            out.append(line)
            continue
        literal_indent = None
        if in_doctest or stripped.startswith(">>>"):
            in_doctest = True
            out.append(line)
            continue
        out.append(_escaped_text(line))
        if stripped.endswith("::"):
            literal_indent = indent
    return out


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
