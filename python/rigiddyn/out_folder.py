"""The --out folder of the commands (simulate, tradeoff): checked before the run, not after it."""

from __future__ import annotations

import tempfile
from collections.abc import Sequence
from pathlib import Path


def check_out_folder(out: str, outputs: Sequence[str]) -> Path:
    """The folder `out`, created if missing, after checking that the files `outputs` can be written
    there; ValueError "--out: expected ..., got ..." otherwise (a file, a folder in the way of one of
    the outputs, not creatable, not writable)."""
    folder = Path(out)
    expected = f"--out: expected a folder where {', '.join(outputs)} can be written, got {out!r}"
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"{expected} (a file)")
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise ValueError(f"{expected} ({error.strerror or error})") from None
    taken = [name for name in outputs if (folder / name).is_dir()]
    if taken:
        raise ValueError(f"{expected} (it holds a folder named {taken[0]})")
    try:
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as error:
        raise ValueError(f"{expected} (not writable: {error.strerror or error})") from None
    return folder
