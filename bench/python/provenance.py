"""Provenance of generated documents: the command that wrote a document, when, on what machine, and a
digest of every input it was generated from (the generator script and the sources whose behaviour it
measures), so that tests/python/test_generated_docs.py fails when a document is older than its inputs.

A generator declares its inputs as glob patterns relative to the repository root and calls `stamp()`;
a markdown document carries the stamp in a visible sentence and an HTML comment (`markdown_stamp`), a
PNG in its text chunks (`png_stamp`). Digests are of file contents (not times: a git checkout does not
keep them), so a document is stale exactly when an input's content differs from what it was made from.
"""

from __future__ import annotations

import datetime
import hashlib
import json
import os
import platform
import re
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# What a simulate / tradeoff run executes: the Python layer, and the C++ sources the compiler reads for
# the simulation's objects (the transitive includes of src/{simulate,models,integrators,exact,dynamics}
# and of bind_{bodies,dynamics,exact}, numpy_io, module, as `ninja -t deps` lists them), by whole layers
# so that a new file in one of them counts. Only the frames layer and the other bindings stay out.
SIMULATION_INPUTS = [
    "python/rigiddyn/__init__.py", "python/rigiddyn/work_precision/*.py", "python/rigiddyn/stability.py",
    "python/rigiddyn/problem.py", "python/rigiddyn/scene_precision.py", "python/rigiddyn/_mass_properties.py",
    "python/rigiddyn/_load_table.py", "python/rigiddyn/_core_call.py",
    "cpp/include/rigiddyn/*.hpp",
    *(f"cpp/{kind}/{layer}/*" for kind in ("include/rigiddyn", "src")
      for layer in ("dynamics", "exact", "inertia", "integrators", "models", "simulate", "so3", "spatial")),
    "cpp/bindings/bindings.hpp", "cpp/bindings/module.cpp", "cpp/bindings/numpy_io.*",
    "cpp/bindings/bind_bodies.cpp", "cpp/bindings/bind_dynamics.cpp", "cpp/bindings/bind_exact.cpp",
]
_COMMENT = re.compile(r"<!-- provenance: (\{.*?\}) -->", re.S)


def input_digests(patterns: list[str], root: Path = ROOT) -> dict[str, str]:
    """{path relative to root: sha256 of its content (16 hex digits)} of every file the patterns match."""
    files = sorted({p for pattern in patterns for p in root.glob(pattern) if p.is_file()})
    return {p.relative_to(root).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()[:16] for p in files}


def changed_inputs(recorded: dict[str, str], patterns: list[str], root: Path = ROOT) -> list[str]:
    """Inputs whose content differs from the recorded digests: 'changed: x', 'new: y', 'removed: z'."""
    now = input_digests(patterns, root)
    out = [f"changed: {p}" for p in sorted(now.keys() & recorded.keys()) if now[p] != recorded[p]]
    out += [f"new: {p}" for p in sorted(now.keys() - recorded.keys())]
    out += [f"removed: {p}" for p in sorted(recorded.keys() - now.keys())]
    return out


def _cpu() -> str:
    try:
        text = Path("/proc/cpuinfo").read_text()
        model = re.search(r"model name\s*:\s*(.+)", text).group(1).strip()
    except (OSError, AttributeError):
        model = platform.processor() or platform.machine()
    return f"{model}, {os.cpu_count()} CPUs"


def _git_revision() -> str:
    try:
        return subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def invocation() -> str:
    """The command line that is running, with the PYTHONPATH it was given (as a user would retype it)."""
    script = Path(sys.argv[0]).resolve()
    try:
        script = script.relative_to(ROOT)
    except ValueError:
        pass
    command = " ".join(shlex.quote(a) for a in ["python3", str(script), *sys.argv[1:]])
    path = os.environ.get("PYTHONPATH")
    return f"PYTHONPATH={shlex.quote(path)} {command}" if path else command


def stamp(patterns: list[str], command: str | None = None) -> dict:
    """What a generated document records about its making."""
    import rigiddyn

    return {
        "command": command or invocation(),
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "machine": _cpu(),
        "load_average": round(os.getloadavg()[0], 2),
        "rigiddyn": f"{rigiddyn.__version__} (git {_git_revision()})",
        "inputs": input_digests(patterns),
    }


def measured_sentence(s: dict) -> str:
    """How the figures were measured, for the reader (the stamp is taken as the measurement starts)."""
    return (f"Measured on {s['date']} with `{s['command']}` (rigiddyn {s['rigiddyn']}; {s['machine']}, shared "
            f"with other jobs, load average {s['load_average']:g} at the start).")


def markdown_comment(s: dict) -> str:
    """The stamp as an HTML comment (invisible in rendered markdown), read back by read_markdown_stamp."""
    return f"<!-- provenance: {json.dumps(s, sort_keys=True)} -->\n"


def read_markdown_stamp(text: str) -> dict | None:
    m = _COMMENT.search(text)
    return json.loads(m.group(1)) if m else None


def png_stamp(path: Path, s: dict) -> None:
    """Write the stamp into the PNG's text chunks (Pillow, installed with matplotlib)."""
    from PIL import Image, PngImagePlugin

    info = PngImagePlugin.PngInfo()
    info.add_text("provenance", json.dumps(s, sort_keys=True))
    with Image.open(path) as image:
        image.load()
        image.save(path, pnginfo=info)


def read_png_stamp(path: Path) -> dict | None:
    from PIL import Image

    with Image.open(path) as image:
        text = image.text.get("provenance") if hasattr(image, "text") else None
    return json.loads(text) if text else None
