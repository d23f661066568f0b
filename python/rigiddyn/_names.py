"""The closest known name to a mistyped one, for the "did you mean ...?" of an error message."""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping
from typing import Any


def closest(word: str, choices: Iterable[str]) -> str | None:
    """The choice most like `word` (difflib's ratio >= 0.6, ignoring case: w_b -> w_B), or None."""
    lower = {c.lower(): c for c in choices}
    close = difflib.get_close_matches(word.lower(), list(lower), n=1, cutoff=0.6)
    return lower[close[0]] if close else None


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """" (did you mean '<closest>'?)" for the closest choice to `word`, or "" when none is close."""
    close = closest(word, choices)
    return f" (did you mean {close!r}?)" if close else ""


def require_method(method: object, argument: str = "method") -> str:
    """`method` if it names one of rigiddyn.methods(), else ValueError "<argument>: expected one of ...
    (did you mean '<closest>'?), got <method>" (as the compiled functions say it)."""
    from . import _core

    names = [m["name"] for m in _core.methods()]
    if method not in names:
        raise ValueError(f"{argument}: expected one of {', '.join(names)}{did_you_mean(str(method), names)}, "
                         f"got {method!r}")
    return str(method)


def check_keys(table: Any, name: str, known: frozenset[str] | set[str], where: str) -> Mapping[str, Any]:
    """`table` checked to be a table (a Mapping) whose keys are all in `known`, as a file's reader needs: else
    ValueError "<name>: expected a table <where>, got ..." or, for the first unknown key, "<name>.<key>: expected a
    key of <where>; did you mean '<closest>'? (one of: ...), got an unknown key"."""
    from .units import _shown

    if not isinstance(table, Mapping):
        raise ValueError(f"{name}: expected a table {where}, got {_shown(table)}")
    unknown = sorted(set(table) - known, key=str)
    if unknown:
        close = closest(str(unknown[0]), known)
        hint = f"; did you mean {close!r}?" if close else ""
        raise ValueError(f"{name}.{unknown[0]}: expected a key of {where}{hint} (one of: {', '.join(sorted(known))}), "
                         "got an unknown key")
    return table
