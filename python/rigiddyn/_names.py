"""The closest known name to a mistyped one, for the "did you mean ...?" of an error message."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


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
