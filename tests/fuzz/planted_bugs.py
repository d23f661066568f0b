"""A module with one planted bug of each kind the API fuzz must report, next to functions it must not
report (tests/python/test_fuzz_api.py runs fuzz_api.py --module planted_bugs and checks that the
findings are exactly EXPECTED). Every function returns a finite constant unless its bug fires."""

import ctypes
import math
import signal
import time
import warnings

__all__ = ["crash", "hang", "silent_nan", "warned_nan", "wrong_exception", "empty_message", "validated",
           "slow_but_interruptible", "Box"]

# (call, kind) of every planted bug
EXPECTED = {("crash", "crash"), ("hang", "hang"), ("silent_nan", "non-finite"), ("wrong_exception", "exception"),
            ("empty_message", "message"), ("Box", "non-finite"), ("Box.ratio", "exception"),
            ("check.mean_within_range", "wrong result")}


def crash(x: float) -> float:
    """Dies of SIGSEGV for x > 1e100."""
    if x > 1e100:
        ctypes.string_at(0)
    return 0.0


def hang(n: int) -> int:
    """Never returns for n > 10, ignoring SIGINT (a C loop that never checks for signals)."""
    if n > 10:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        while True:
            pass
    return 0


def silent_nan(x: float) -> float:
    """NaN without a word for x < 0."""
    return math.nan if x < 0 else 1.0


def warned_nan(x: float) -> float:
    """NaN for x < 0, with a RuntimeWarning: allowed."""
    if x < 0:
        warnings.warn("warned_nan: x < 0 gives NaN", RuntimeWarning)
        return math.nan
    return 1.0


def wrong_exception(x: float) -> float:
    """ZeroDivisionError for x = 0 (neither TypeError nor ValueError)."""
    1.0 / x
    return 1.0


def empty_message(x: float) -> float:
    """ValueError without a message for x < 0."""
    if x < 0:
        raise ValueError()
    return 1.0


def validated(x: float) -> float:
    """Refuses what it cannot take, naming the argument: never a finding."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise TypeError(f"x: expected a number, got {type(x).__name__}")
    if not math.isfinite(x) or x < 0:
        raise ValueError(f"x: expected a finite number >= 0, got {x}")
    return 1.0


def slow_but_interruptible(n: int) -> int:
    """Computes for a minute for n > 10 but stops on Ctrl-C: slow, not a hang."""
    if n > 10:
        end = time.monotonic() + 60
        while time.monotonic() < end:  # busy: the fuzz judges a call by the CPU time it uses
            pass
    return 0


class Box:
    """A cube of edge `size`; accepts a negative size, whose volume is then NaN (the bug)."""

    def __init__(self, size: float):
        if isinstance(size, bool) or not isinstance(size, (int, float)):
            raise TypeError(f"size: expected a number, got {type(size).__name__}")
        self.size = size

    @property
    def volume(self) -> float:
        return math.nan if self.size < 0 else 1.0

    def ratio(self, other: float) -> float:
        """ZeroDivisionError for other = 0."""
        self.size / other
        return 1.0


# properties of results (as tests/fuzz/properties.py): one that holds, one that fails for some inputs (the bug)


def mean_is_symmetric(a: float, b: float) -> None:
    """(a + b) / 2 == (b + a) / 2: holds."""
    assert (a + b) / 2 == (b + a) / 2, f"mean not symmetric: {a!r}, {b!r}"


def mean_within_range(a: float, b: float) -> None:
    """min(a, b) <= (a + b) / 2 <= max(a, b): fails where a + b overflows (the planted wrong result)."""
    m = (a + b) / 2
    assert min(a, b) <= m <= max(a, b), f"mean out of range: ({a!r} + {b!r}) / 2 = {m!r}"


def _strategies():
    from hypothesis import strategies as st

    pairs = st.fixed_dictionaries({"a": st.floats(0.0, 1.7e308), "b": st.floats(0.0, 1.7e308)})
    return {"mean_is_symmetric": pairs, "mean_within_range": pairs}


STRATEGIES = _strategies()
