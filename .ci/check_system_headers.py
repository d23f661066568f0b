"""Fails when the C++ build read a system header that a fresh machine would not have.

Usage: python3 .ci/check_system_headers.py BUILD_DIR [BUILD_DIR ...]

For every Ninja build directory given, `ninja -t deps` lists the headers each object file was
compiled from (the compiler's dependency files). Every header outside the repository must come
from one of:
  - a Debian package that tests/run_all.sh installs, or one of their dependencies (the toolchain:
    g++ is in that list, so libstdc++, libc and the kernel headers are covered through it);
  - the Python interpreter or a package pip installed into it (pybind11, cmeel-eigen: declared in
    pyproject.toml, installed by the README's commands).
A header owned by any other Debian package, or by nothing known, fails the check with the package
to add to tests/run_all.sh's install list.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import sysconfig
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def listed_packages() -> list[str]:
    """The Debian packages tests/run_all.sh installs (its own --list-packages answer)."""
    out = subprocess.run(["bash", str(REPO / "tests/run_all.sh"), "--list-packages"],
                         check=True, capture_output=True, text=True).stdout
    return out.split()


def installed_dependencies() -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    """For each installed package, the installed packages it depends on (Depends, Pre-Depends;
    every installed alternative), and the map from virtual package name to its providers."""
    fmt = "${Package}\\t${Status}\\t${Depends}, ${Pre-Depends}\\t${Provides}\\n"
    rows = subprocess.run(["dpkg-query", "-W", "-f=" + fmt], check=True, capture_output=True,
                          text=True).stdout.splitlines()
    raw: dict[str, list[list[str]]] = {}
    providers: dict[str, set[str]] = {}
    for row in rows:
        name, status, depends, provides = (row.split("\t") + ["", "", ""])[:4]
        if not status.endswith(" installed"):
            continue
        name = name.split(":")[0]
        raw[name] = [[_bare(alt) for alt in clause.split("|")] for clause in depends.split(",") if clause.strip()]
        for virtual in provides.split(","):
            if virtual.strip():
                providers.setdefault(_bare(virtual), set()).add(name)
    deps: dict[str, set[str]] = {}
    for name, clauses in raw.items():
        deps[name] = set()
        for clause in clauses:
            for alt in clause:
                if alt in raw:
                    deps[name].add(alt)
                deps[name] |= providers.get(alt, set())
    return deps, providers


def _bare(spec: str) -> str:
    """'libfoo:amd64 (>= 1.2)' -> 'libfoo'."""
    return re.split(r"[\s:(]", spec.strip(), maxsplit=1)[0]


def closure(roots: list[str], deps: dict[str, set[str]]) -> set[str]:
    """Every package reached from `roots` through dependencies."""
    seen: set[str] = set()
    todo = list(roots)
    while todo:
        p = todo.pop()
        if p not in seen:
            seen.add(p)
            todo.extend(deps.get(p, ()))
    return seen


def headers_read(build_dir: Path) -> set[str]:
    """Absolute paths of the files outside the repository that the build's objects depend on.

    A dependency is recorded relative to the build folder where the compiler was given a relative
    path (ccache's base_dir rewrites the repository's paths so), hence the folder's absolute form."""
    build_dir = build_dir.absolute()
    out = subprocess.run(["ninja", "-C", str(build_dir), "-t", "deps"], check=True, capture_output=True,
                         text=True).stdout
    found: set[str] = set()
    for line in out.splitlines():
        if not line.startswith("    "):
            continue  # "target: #deps N, ..." header lines
        path = Path(os.path.normpath(build_dir / line.strip()))
        if not (path == REPO or REPO in path.parents):
            found.add(str(path))
    return found


def owners(paths: set[str]) -> dict[str, str]:
    """Map each path (as given, or its resolved form) to the Debian package that owns it."""
    owner_of: dict[str, str] = {}
    info = Path("/var/lib/dpkg/info")
    wanted = {p: {p, os.path.realpath(p)} for p in paths}
    index: dict[str, str] = {}
    for lst in info.glob("*.list"):
        pkg = lst.stem.split(":")[0]
        for f in lst.read_text(errors="replace").splitlines():
            index[f] = pkg
    for p, forms in wanted.items():
        for form in forms:
            # dpkg records the path as shipped; /usr-merge may alias /lib and /usr/lib
            for candidate in (form, re.sub(r"^/usr/", "/", form), "/usr" + form):
                if candidate in index:
                    owner_of[p] = index[candidate]
                    break
            if p in owner_of:
                break
    return owner_of


def python_roots() -> list[str]:
    """Directories of the interpreter and of packages pip installs into it."""
    keys = ("stdlib", "platstdlib", "purelib", "platlib", "include", "platinclude", "data")
    roots = {os.path.realpath(p) for k in keys if (p := sysconfig.get_paths().get(k))}
    roots |= {os.path.realpath(sys.prefix), os.path.realpath(sys.base_prefix)}
    return sorted(roots)


def main(build_dirs: list[str]) -> int:
    listed = listed_packages()
    deps, _ = installed_dependencies()
    provided = closure(listed, deps)
    headers: set[str] = set()
    for d in build_dirs:
        headers |= headers_read(Path(d))
    owned = owners(headers)
    py_roots = python_roots()
    missing: dict[str, list[str]] = {}
    unknown: list[str] = []
    for h in sorted(headers):
        pkg = owned.get(h)
        if pkg is None:
            real = os.path.realpath(h)
            if not any(real == r or real.startswith(r + os.sep) for r in py_roots):
                unknown.append(h)
        elif pkg not in provided:
            missing.setdefault(pkg, []).append(h)
    print(f"check_system_headers: {len(headers)} files outside the repository read by {', '.join(build_dirs)}; "
          f"{len(provided)} Debian packages provided by tests/run_all.sh's list {listed}")
    for pkg, files in sorted(missing.items()):
        print(f"ERROR: the build read {len(files)} header(s) of Debian package '{pkg}', which tests/run_all.sh "
              f"does not install (add it to `packages=(...)`), e.g. {files[0]}")
    for h in unknown:
        print(f"ERROR: the build read {h}, which no Debian package and no Python/pip package provides")
    return 1 if (missing or unknown) else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1:]))
