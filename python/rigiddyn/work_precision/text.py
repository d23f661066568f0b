"""Numbers, durations and paragraphs as the reports print them."""

from __future__ import annotations

import math
import textwrap
from typing import Any


def fmt(x: Any) -> str:
    """A float to 3 significant digits (inf and nan as words); anything else as str."""
    if isinstance(x, float):
        return f"{x:.3g}" if math.isfinite(x) else str(x)
    return str(x)


def duration(seconds: float) -> str:
    """A duration [s] in the largest unit of d, h, min that it reaches, else in s; ? if not finite."""
    if not math.isfinite(seconds):
        return "?"
    for unit, size in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


def wrap(text: str, width: int) -> list[str]:
    """text in lines of at most `width` characters, continuation lines indented by 4."""
    indent = " " * (len(text) - len(text.lstrip(" ")))
    return textwrap.wrap(text, width, initial_indent="", subsequent_indent=indent + "    ",
                         break_long_words=True, break_on_hyphens=False) or [""]
