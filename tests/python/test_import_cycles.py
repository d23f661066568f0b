"""No import cycle among the modules of the rigiddyn package.

The graph is read from the source files of python/rigiddyn with ast, without importing the package (so
the test needs no build). Its nodes are the package's modules: ``rigiddyn`` (``__init__.py``),
``rigiddyn.x`` for ``x.py``, for ``x.pyi`` (the stub of an extension such as ``_core``) and for a
subpackage ``x/``. An edge a -> b says that importing a imports b, under these rules:

- Counted: every import statement of the module, wherever it is: at module level, also inside ``if``,
  ``try``, ``with`` and class bodies, under ``if TYPE_CHECKING:`` (such an import ties the module's
  annotations to the other module: type checkers and ``typing.get_type_hints`` follow it, and a guard
  that only hides it from the interpreter layers nothing), and inside a function (``def``, ``async
  def``, ``lambda``): a lazy import defers the cycle to the call, it does not layer the modules.
- ``from . import x``, ``from rigiddyn import x``, ``import rigiddyn.x`` with ``x`` a submodule: an
  edge to ``rigiddyn.x`` only. Importing a submodule first imports its parent packages, but the
  packages that contain the importing module have already started importing and need not finish
  first, so they are not edges: ``__init__`` importing submodules that import their siblings this way
  is not a cycle. A parent package of the target that does not contain the importer is an edge.
- ``from . import name`` with ``name`` not a submodule (a name that ``__init__`` defines), and
  ``import rigiddyn`` in a submodule: an edge to ``rigiddyn``, since the module reads the package's
  names; if ``__init__`` imports that submodule, this is a cycle (the names may not exist yet).
- ``from .x import y``: an edge to ``rigiddyn.x``, and to ``rigiddyn.x.y`` when that is a module.
- A module importing itself makes no edge (it is already in ``sys.modules``).

A cycle is reported as the modules along it, e.g. ``rigiddyn.a -> rigiddyn.b -> rigiddyn.a``, with the
file and line of each import on it.
"""

from __future__ import annotations

import ast
import collections
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "python" / "rigiddyn"

# an edge: (importing module, imported module) -> where the first import making it is ("file.py:line")
Edges = dict[tuple[str, str], str]


def module_names(package: Path) -> dict[str, Path | None]:
    """The modules of a package directory, by full name.

    Parameters
    ----------
    package : Path
        The package's directory (holding ``__init__.py``); its name is the package's name.

    Returns
    -------
    dict of str to Path or None
        Full module name -> the source file to read, ``None`` for a module without Python source (an
        extension known by its ``.pyi`` stub). A subpackage's name maps to its ``__init__.py``.
    """
    modules: dict[str, Path | None] = {}

    def walk(directory: Path, name: str) -> None:
        modules[name] = directory / "__init__.py"
        for path in sorted(directory.iterdir()):
            if path.is_dir() and (path / "__init__.py").is_file():
                walk(path, f"{name}.{path.name}")
            elif path.suffix == ".py" and path.name != "__init__.py":
                modules[f"{name}.{path.stem}"] = path
            elif path.suffix == ".pyi":
                modules.setdefault(f"{name}.{path.stem}", None)

    walk(package, package.name)
    return modules


def _imports(tree: ast.Module) -> list[ast.Import | ast.ImportFrom]:
    """The import statements of a module, wherever they are.

    Parameters
    ----------
    tree : ast.Module
        The module's parsed source.

    Returns
    -------
    list of ast.Import or ast.ImportFrom
        Every import statement (at module level and inside functions, classes, ``if`` and ``try``
        blocks), in source order.
    """
    found = [node for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))]
    return sorted(found, key=lambda node: (node.lineno, node.col_offset))


def _parents(name: str) -> list[str]:
    """The packages that contain a module, outermost first.

    Parameters
    ----------
    name : str
        A full module name, e.g. ``a.b.c``.

    Returns
    -------
    list of str
        Its parent packages, e.g. ``["a", "a.b"]``; empty for a top-level name.
    """
    parts = name.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts))]


def _imported(importer: str, target: str, modules: dict[str, Path | None]) -> list[str]:
    """The package's modules that an import of `target` in `importer` needs to have run.

    Parameters
    ----------
    importer : str
        The full name of the importing module.
    target : str
        The full name of the module it imports.
    modules : dict of str to Path or None
        The package's modules (`module_names`).

    Returns
    -------
    list of str
        `target` after those of its parent packages that do not contain `importer` (they are imported
        first; those that contain it have already started), the modules of the package only, without
        `importer` itself.
    """
    first = [p for p in _parents(target) if p not in _parents(importer) and p != importer]
    return [m for m in [*first, target] if m in modules and m != importer]


def _targets(node: ast.Import | ast.ImportFrom, own_package: str, top: str,
             modules: dict[str, Path | None]) -> list[str]:
    """The modules of package `top` that an import statement names (module docstring's rules).

    Parameters
    ----------
    node : ast.Import or ast.ImportFrom
        The import statement.
    own_package : str
        The package its module is in (the module itself for an ``__init__.py``): what ``.`` means.
    top : str
        The package's name; imports of other packages name nothing.
    modules : dict of str to Path or None
        The package's modules (`module_names`).

    Returns
    -------
    list of str
        For ``import a.b``: ``a.b``; for ``from base import x, y``: ``base.x`` where it is a module, else
        ``base``, for each name. Empty for an import of another package.
    """
    if isinstance(node, ast.Import):
        return [a.name for a in node.names if a.name == top or a.name.startswith(top + ".")]
    base = node.module or ""
    if node.level:
        base = ".".join(filter(None, [own_package.rsplit(".", node.level - 1)[0], node.module]))
    if base != top and not base.startswith(top + "."):
        return []
    return [f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names]


def import_graph(package: Path) -> tuple[dict[str, set[str]], Edges]:
    """The graph of the imports between a package's own modules (module docstring).

    Parameters
    ----------
    package : Path
        The package's directory (holding ``__init__.py``).

    Returns
    -------
    graph : dict of str to set of str
        Every module of the package (`module_names`) -> the package's modules it imports.
    where : dict of (str, str) to str
        Each edge -> ``"path:line"`` of the first import statement making it, the path relative to the
        package's parent directory.
    """
    modules = module_names(package)
    graph: dict[str, set[str]] = {name: set() for name in modules}
    where: Edges = {}
    for name, path in modules.items():
        if path is None:
            continue
        own_package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        for node in _imports(tree):
            for target in _targets(node, own_package, package.name, modules):
                for module in _imported(name, target, modules):
                    graph[name].add(module)
                    where.setdefault((name, module), f"{path.relative_to(package.parent)}:{node.lineno}")
    return graph, where


def _strongly_connected(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of a directed graph (Tarjan's algorithm).

    Parameters
    ----------
    graph : dict of str to set of str
        Node -> the nodes it has an edge to; every such node is a key.

    Returns
    -------
    list of list of str
        Each component's nodes, sorted; the components in no particular order.
    """
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            components.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return components


def _shortest_cycle(graph: dict[str, set[str]], start: str, within: set[str]) -> list[str]:
    """A shortest cycle through one module, by breadth-first search.

    Parameters
    ----------
    graph : dict of str to set of str
        Module -> the modules it imports.
    start : str
        The module the cycle passes through.
    within : set of str
        The modules the cycle may pass through (its strongly connected component).

    Returns
    -------
    list of str
        ``[start, ..., start]``: the modules along the cycle, `start` at both ends.
    """
    previous: dict[str, str] = {}
    queue = collections.deque([start])
    while queue:
        v = queue.popleft()
        for w in sorted(graph[v] & within):
            if w == start:
                path = [v]
                while path[-1] != start:
                    path.append(previous[path[-1]])
                return [start, *reversed(path[:-1]), start]
            if w not in previous:
                previous[w] = v
                queue.append(w)
    raise AssertionError(f"{start} is on no cycle within {sorted(within)}")


def import_cycles(graph: dict[str, set[str]], where: Edges) -> list[str]:
    """The import cycles of `graph`, enough of them to name every module that is on one.

    Parameters
    ----------
    graph : dict of str to set of str
        Module -> the modules it imports (`import_graph`).
    where : dict of (str, str) to str
        Edge -> where its import statement is (`import_graph`).

    Returns
    -------
    list of str, sorted
        For each strongly connected group of modules (two or more), a shortest
        cycle through each of its modules that no cycle before passes through, from the cycle's first
        module in name order: ``"a -> b -> a (a.py:3, b.py:7)"``. Empty when there is no cycle.
    """
    cycles = set()
    for component in _strongly_connected(graph):
        if len(component) == 1:  # a module is never its own import (import_graph)
            continue
        named: set[str] = set()
        for module in component:
            if module in named:
                continue
            cycle = _shortest_cycle(graph, module, set(component))[:-1]
            named.update(cycle)
            first = cycle.index(min(cycle))
            cycle = cycle[first:] + cycle[:first] + [cycle[first]]
            lines = ", ".join(where[(a, b)] for a, b in zip(cycle, cycle[1:]))
            cycles.add(f"{' -> '.join(cycle)} ({lines})")
    return sorted(cycles)


def _write_package(root: Path, files: dict[str, str]) -> Path:
    """Write a package ``pkg`` for the checks of the checker itself.

    Parameters
    ----------
    root : Path
        The directory to write it in.
    files : dict of str to str
        Path relative to the package -> source; an empty ``__init__.py`` unless given.

    Returns
    -------
    Path
        The package's directory, ``root / "pkg"``.
    """
    package = root / "pkg"
    for relative, source in {"__init__.py": "", **files}.items():
        path = package / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(source, encoding="utf-8")
    return package


def test_rigiddyn_has_no_import_cycle() -> None:
    """The package's modules import each other without a cycle (rules: module docstring)."""
    graph, where = import_graph(PACKAGE)
    cycles = import_cycles(graph, where)
    assert not cycles, ("import cycle(s) among rigiddyn's modules; move the code both sides need into a "
                        "lower module:\n  " + "\n  ".join(cycles))


def test_the_graph_of_rigiddyn_is_read() -> None:
    """The graph holds every source file and the imports the package is built on, so the test above can
    fail: a reader that found no import would find no cycle."""
    graph, _ = import_graph(PACKAGE)
    files = {p.stem for p in PACKAGE.glob("*.py") if p.name != "__init__.py"}
    assert {f"rigiddyn.{stem}" for stem in files} | {"rigiddyn", "rigiddyn._core"} <= set(graph)
    assert "rigiddyn._core" in graph["rigiddyn"]  # __init__ re-exports the compiled core
    assert "rigiddyn.scene_precision" in graph["rigiddyn.work_precision.case"]  # tradeoff sweeps scenes
    assert sum(len(targets) for targets in graph.values()) >= len(files)


def test_the_work_precision_package_is_layered() -> None:
    """rigiddyn.work_precision, a package of one concept per module: every module of it is in the graph,
    none imports the package itself (its __init__ only re-exports them, so a module that read a name from
    it would make a cycle) and the sweep is built on them, not they on it."""
    graph, _ = import_graph(PACKAGE)
    package = "rigiddyn.work_precision"
    modules = {f"{package}.{p.stem}" for p in (PACKAGE / "work_precision").glob("*.py") if p.name != "__init__.py"}
    assert modules and modules <= set(graph)
    assert not [m for m in modules if package in graph[m]], "a module reads rigiddyn.work_precision's __init__"
    assert f"{package}.sweep" in graph[package]  # __init__ re-exports tradeoff
    below = {m for m in modules if m != f"{package}.sweep"}
    assert not [m for m in below if f"{package}.sweep" in graph[m]], "a module imports the sweep it serves"


def test_a_cycle_is_named_with_its_lines(tmp_path: Path) -> None:
    """Two modules importing each other, one under TYPE_CHECKING, are a cycle named in import order."""
    package = _write_package(tmp_path, {
        "a.py": "from typing import TYPE_CHECKING\n\nif TYPE_CHECKING:\n    from .b import B\n",
        "b.py": "import pkg.a\n",
    })
    assert import_cycles(*import_graph(package)) == ["pkg.a -> pkg.b -> pkg.a (pkg/a.py:4, pkg/b.py:1)"]


def test_a_longer_cycle_is_named_whole(tmp_path: Path) -> None:
    """A cycle through three modules names all three, from the first in name order."""
    package = _write_package(tmp_path, {
        "a.py": "from .b import f\n",
        "b.py": "from . import c\n",
        "c.py": "try:\n    from pkg.a import g\nexcept ImportError:\n    g = None\n",
    })
    assert import_cycles(*import_graph(package)) == [
        "pkg.a -> pkg.b -> pkg.c -> pkg.a (pkg/a.py:1, pkg/b.py:1, pkg/c.py:2)"]


def test_imports_inside_functions_are_edges(tmp_path: Path) -> None:
    """A lazy import (in a function, a method or a lambda) is an edge: it defers a cycle, it does not break it."""
    package = _write_package(tmp_path, {
        "a.py": "from . import b\n",
        "b.py": ("def f():\n    from . import a\n\n\nclass C:\n    def g(self):\n        import pkg.c\n\n\n"
                 "h = lambda: __import__('pkg.a')\n"),
        "c.py": "",
    })
    graph, where = import_graph(package)
    assert graph["pkg.b"] == {"pkg.a", "pkg.c"}
    assert import_cycles(graph, where) == ["pkg.a -> pkg.b -> pkg.a (pkg/a.py:1, pkg/b.py:2)"]


def test_init_importing_submodules_that_import_siblings_is_no_cycle(tmp_path: Path) -> None:
    """``from . import x`` of a submodule needs the package to have started, not finished, importing."""
    package = _write_package(tmp_path, {
        "__init__.py": "from . import _ext\nfrom .a import f\nfrom .b import g\n",
        "_ext.pyi": "def h() -> None: ...\n",
        "a.py": "from . import _ext\nfrom .b import g\n",
        "b.py": "import pkg._ext\n",
    })
    graph, where = import_graph(package)
    assert graph == {"pkg": {"pkg._ext", "pkg.a", "pkg.b"}, "pkg._ext": set(), "pkg.a": {"pkg._ext", "pkg.b"},
                     "pkg.b": {"pkg._ext"}}
    assert import_cycles(graph, where) == []


def test_a_name_read_from_init_is_a_cycle(tmp_path: Path) -> None:
    """A submodule that reads a name of ``__init__`` (or binds the package) while ``__init__`` imports it."""
    package = _write_package(tmp_path, {
        "__init__.py": "__version__ = '1'\nfrom .a import f\nfrom .b import g\n",
        "a.py": "from . import __version__\n",
        "b.py": "import pkg\n",
    })
    assert import_cycles(*import_graph(package)) == ["pkg -> pkg.a -> pkg (pkg/__init__.py:2, pkg/a.py:1)",
                                                     "pkg -> pkg.b -> pkg (pkg/__init__.py:3, pkg/b.py:1)"]


def test_a_subpackage_outside_the_importer_is_imported_first(tmp_path: Path) -> None:
    """``from .sub.x import y`` runs ``sub/__init__.py`` first: an edge to ``sub`` as well."""
    package = _write_package(tmp_path, {
        "a.py": "from .sub.x import y\n",
        "sub/__init__.py": "from .. import a\n",
        "sub/x.py": "from . import z\n",
        "sub/z.py": "",
    })
    graph, where = import_graph(package)
    assert graph["pkg.a"] == {"pkg.sub", "pkg.sub.x"}
    assert graph["pkg.sub.x"] == {"pkg.sub.z"}
    assert import_cycles(graph, where) == ["pkg.a -> pkg.sub -> pkg.a (pkg/a.py:1, pkg/sub/__init__.py:1)"]
