"""A result's rows in CSV and JSON: the columns' types, non-finite numbers, and the text to read them from."""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from .._measures import MEASURES
from .constants import COLUMNS

INT_COLUMNS = {"steps", "order", "evaluations_per_step", "total_evaluations"}
# absent from the CSV files of earlier versions
OPTIONAL_COLUMNS = {"time_noise", "estimate", "effectivity", "estimate_verdict"}
STR_COLUMNS = {"method", "reference", "reference_check", "order_note", "stability", "estimate_verdict"}
FLOAT_COLUMNS = set(COLUMNS) - INT_COLUMNS - STR_COLUMNS - {"diverged"}


def typed_row(r: dict[str, str]) -> dict[str, Any]:
    """A CSV row with each column's type back (int, str, bool, float); ValueError on a bad `diverged`."""
    out: dict[str, Any] = {}
    for k, v in r.items():
        if k in INT_COLUMNS:
            out[k] = int(v)
        elif k in STR_COLUMNS:
            out[k] = v
        elif k == "diverged":
            if v not in ("True", "False"):
                raise ValueError(f"diverged: expected True or False, got {v!r}")
            out[k] = v == "True"
        else:
            out[k] = float(v)
    return out


def json_safe(x: Any) -> Any:
    """x with every non-finite float as None (JSON null: JSON has no nan or inf)."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: json_safe(v) for k, v in x.items()}
    if isinstance(x, list):
        return [json_safe(v) for v in x]
    return x


def json_row(row: Any) -> Any:
    """A row read from JSON: null in a number column back to inf (an error of a diverged run) or nan."""
    if not isinstance(row, dict):
        return row
    diverged = row.get("diverged") is True
    return {k: ((math.inf if diverged and k in MEASURES else math.nan) if v is None and k in FLOAT_COLUMNS else v)
            for k, v in row.items()}


def _is_file(x: Any) -> bool:
    try:
        return Path(x).is_file()
    except (OSError, ValueError):
        return False


def read_text(path_or_text: Any) -> str:
    """The text of the file path_or_text names, or path_or_text itself (a str that names no file)."""
    if not isinstance(path_or_text, (str, os.PathLike)):
        raise TypeError(f"path_or_text: expected a file path or the text (str or os.PathLike), got {path_or_text!r}")
    if _is_file(path_or_text):
        return Path(path_or_text).read_text()
    if not isinstance(path_or_text, str):
        raise ValueError(f"path_or_text: expected an existing file, got {str(path_or_text)!r}")
    return path_or_text


def describe_text(path_or_text: Any, text: str) -> str:
    """Where `text` came from, for an error message: the file, or text, and how it begins."""
    where = f"the file {str(path_or_text)!r}" if _is_file(path_or_text) else "text"
    return f"{where} beginning {text[:40]!r}"
