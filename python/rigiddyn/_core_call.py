"""The core's "<argument>: expected ..." messages re-addressed to the field of a file that gave the argument."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any


def core_call(make: Callable[..., Any], name: str, *args: Any, keys: Mapping[str, str] | None = None,
              **kwargs: Any) -> Any:
    """make(*args, **kwargs), its "<arg>: expected ..." errors re-addressed to "<name>.<key>", key the
    file's key of the argument (keys[arg], default arg itself), as a ValueError."""
    try:
        return make(*args, **kwargs)
    except (ValueError, TypeError) as e:
        arg, sep, rest = str(e).partition(": ")
        text = f"{name}.{(keys or {}).get(arg, arg)}: {rest}" if sep and " " not in arg else f"{name}: {e}"
        raise ValueError(text) from None
