"""Memory the system can still give, for the estimates that refuse work too large for it before any of it is
built (a scene file's [[cluster]] count, a Monte Carlo run's samples): as the bindings' available memory,
MemAvailable of /proc/meminfo, else the free physical pages."""

from __future__ import annotations

import os

__all__ = ["available_bytes", "format_bytes"]


def available_bytes() -> int | None:
    """Memory [bytes] the system can still give (MemAvailable, else the free pages), None where unknown."""
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                key, _, rest = line.partition(":")
                if key == "MemAvailable":
                    return int(rest.split()[0]) * 1024  # "MemAvailable:   123456 kB"
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (AttributeError, OSError, ValueError):
        return None


def format_bytes(n: float) -> str:
    """n bytes in words: "3.2 GiB", "512 MiB", "12 kiB", "100 bytes" (figures of messages)."""
    for unit, size in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("kiB", 2**10)):
        if n >= size:
            return f"{n / size:.3g} {unit}"
    return f"{n:.0f} bytes"
