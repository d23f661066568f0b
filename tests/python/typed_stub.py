"""The type stub of the compiled core, python/rigiddyn/_core.pyi: pybind11-stubgen's stub with each parameter's
type read from its docstring.

The bindings take their arguments as untyped Python objects (they convert and check them themselves, naming a
wrong one), so pybind11-stubgen writes ``typing.Any`` for every parameter. Their numpydoc ``Parameters`` sections
state each type in words; this reads them into annotations, so that mypy checks a call:

- ``array_like`` -> ``numpy.typing.ArrayLike``; ``float``, ``int``, ``bool``, ``str``, ``callable``, ``None``;
- ``{'a', 'b'}`` -> ``typing.Literal['a', 'b']``; ``pint.Quantity`` -> a protocol of pint's quantities;
- a class of the core -> that class; ``sequence of X`` -> ``collections.abc.Sequence[X]``;
- a parameter ``method`` of type ``str`` -> the literal names of ``rigiddyn.methods()``;
- ``shape``, units in brackets, ``default``, ``optional``, ``required``, ``keyword-only`` qualify, and a
  default of None adds ``None``. A type in other words stays ``typing.Any``.

A class that only the core makes (no public constructor: its ``__init__(self, *args, **kwargs)`` raises TypeError)
gets ``typing.Never`` for both, so that a type checker refuses a call with arguments.

Regenerate the stub (from the worktree root, the extension built)::

    PYTHONPATH=build/py/python python3 tests/python/typed_stub.py
"""

from __future__ import annotations

import ast
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUB = ROOT / "python" / "rigiddyn" / "_core.pyi"

# The names the stub declares for its annotations (private: they exist only for a type checker)
DECLARATIONS = '''
class _Quantity(typing.Protocol):
    """A pint Quantity of any registry (the core converts it to SI by its magnitude and units)."""
    @property
    def magnitude(self) -> typing.Any: ...
    @property
    def units(self) -> typing.Any: ...
_MethodName: typing.TypeAlias = typing.Literal[{methods}]
'''

def generate_untyped(out: pathlib.Path) -> str:
    """pybind11-stubgen's stub of rigiddyn._core (the extension importable from sys.path / PYTHONPATH)."""
    # RIGIDDYN_STUBGEN=1: the core leaves out the runtime signatures (__text_signature__), so that the generator
    # reads the typed signature lines of the docstrings (it reads them only where inspect finds no signature)
    subprocess.run(
        [sys.executable, "-m", "pybind11_stubgen", "rigiddyn._core", "--exit-code",
         "--enum-class-locations", "InertiaCheck:rigiddyn._core", "-o", str(out)],
        check=True, capture_output=True, text=True, env=dict(os.environ, RIGIDDYN_STUBGEN="1"),
    )
    return (out / "rigiddyn" / "_core.pyi").read_text()


def split_top_level(text: str, separator: str) -> list[str]:
    """text split at `separator` outside brackets, braces and parentheses."""
    parts, depth, start, i = [], 0, 0, 0
    while i < len(text):
        depth += text[i] in "([{"
        depth -= text[i] in ")]}"
        if depth == 0 and text.startswith(separator, i):
            parts.append(text[start:i])
            start = i = i + len(separator)
            continue
        i += 1
    return parts + [text[start:]]


def one_type(words: str, classes: set[str]) -> str | None:
    """The annotation of one alternative of a numpydoc type ('float', 'sequence of Wheel'); None if unknown."""
    words = re.sub(r"\s*\[[^\]]*\]", "", words).strip()  # a unit: float [m]
    simple = {"float": "float", "int": "int", "bool": "bool", "str": "str", "None": "None",
              "callable": "collections.abc.Callable[..., typing.Any]", "pint.Quantity": "_Quantity",
              "numpy.random.Generator": "numpy.random.Generator"}
    if words in simple:
        return simple[words]
    if words.startswith("array_like"):
        return "numpy.typing.ArrayLike"
    if words in classes:
        return words
    if re.fullmatch(r"\{'[^']*'(, '[^']*')*\}", words):
        return f"typing.Literal[{words[1:-1]}]"
    sequence = re.fullmatch(r"(?:sequence|list) of (.+)", words)
    if sequence:
        item = one_type(sequence.group(1), classes)
        return f"collections.abc.Sequence[{item}]" if item else None
    return None


QUALIFIERS = ("shape", "default", "optional", "required", "keyword-only")


def annotation(type_text: str, default_none: bool, classes: set[str]) -> str | None:
    """The annotation of a numpydoc parameter type ('array_like, shape (3,), or pint.Quantity, optional'), or
    None when a word of it is not a type this knows."""
    alternatives: list[str] = []
    for piece in split_top_level(type_text, ","):
        piece = piece.strip().removeprefix("or ").strip()
        if not piece or piece.startswith(QUALIFIERS):
            continue
        for word in split_top_level(piece, " or "):
            typed = one_type(word, classes)
            if typed is None:
                return None
            alternatives.append(typed)
    if default_none:
        alternatives.append("None")
    unique = list(dict.fromkeys(alternatives))
    if "None" in unique:  # last, as one writes it
        unique = [a for a in unique if a != "None"] + ["None"]
    return " | ".join(unique) if unique else None


def parameter_types(docstring: str) -> dict[str, str]:
    """name -> type text of the docstring's numpydoc Parameters section."""
    section = re.search(r"^\s*Parameters\n\s*-+\n(.*?)(?:\n\s*\n\s*\w[\w ]*\n\s*-+\n|\Z)", docstring, re.S | re.M)
    if not section:
        return {}
    types = {}
    for line in section.group(1).splitlines():
        item = re.fullmatch(r"(\*{0,2}[A-Za-z_]\w*(?:, \*{0,2}[A-Za-z_]\w*)*) : (.+)", line)
        if item and not line[:1].isspace():  # not a description line
            for name in item.group(1).split(", "):
                types.setdefault(name.lstrip("*"), item.group(2))
    return types


def typed(stub: str, method_names: list[str]) -> str:
    """The stub with each documented parameter's `typing.Any` replaced by its docstring's type."""
    tree = ast.parse(stub)
    classes = {node.name for node in tree.body if isinstance(node, ast.ClassDef)}
    lines = [line.encode() for line in stub.splitlines(keepends=True)]
    edits: list[tuple[int, int, int, str]] = []  # (line index, start byte, end byte, text)

    def visit(function: ast.FunctionDef, owner: ast.ClassDef | None) -> None:
        if any(ast.unparse(d) == "typing.overload" for d in function.decorator_list):
            return
        text = ast.get_docstring(function) or ""
        if function.name == "__init__" and "has no public constructor" in text:
            for variadic in (function.args.vararg, function.args.kwarg):
                if variadic is not None and variadic.annotation is None:
                    edits.append((variadic.lineno - 1, variadic.end_col_offset or 0, variadic.end_col_offset or 0, ": typing.Never"))
            return
        types = parameter_types(text)
        if not types and function.name == "__init__" and owner is not None:
            types = parameter_types(ast.get_docstring(owner) or "")
        arguments = function.args
        positional = arguments.posonlyargs + arguments.args
        defaults = dict(zip([a.arg for a in positional][len(positional) - len(arguments.defaults):], arguments.defaults))
        defaults.update({a.arg: d for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults) if d is not None})
        for argument in positional + arguments.kwonlyargs:
            node = argument.annotation
            if node is None or ast.unparse(node) != "typing.Any" or argument.arg not in types:
                continue
            default = defaults.get(argument.arg)
            new = annotation(types[argument.arg], isinstance(default, ast.Constant) and default.value is None, classes)
            if new is not None and argument.arg == "method" and new.startswith("str"):
                new = new.replace("str", "_MethodName", 1)
            if new is not None:
                edits.append((node.lineno - 1, node.col_offset, node.end_col_offset or 0, new))

    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            visit(node, None)
        elif isinstance(node, ast.ClassDef):
            for member in node.body:
                if isinstance(member, ast.FunctionDef):
                    visit(member, node)
    for index, start, end, text in sorted(edits, reverse=True):
        lines[index] = lines[index][:start] + text.encode() + lines[index][end:]
    out = b"".join(lines).decode()
    declarations = DECLARATIONS.format(methods=", ".join(repr(name) for name in method_names))
    return re.sub(r"^(__all__: .*\n)", lambda m: m.group(1) + declarations.lstrip("\n"), out, count=1, flags=re.M)


def generate(out: pathlib.Path) -> str:
    """The typed stub of the extension importable now."""
    import rigiddyn._core

    return typed(generate_untyped(out), [m["name"] for m in rigiddyn._core.methods()])


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        STUB.write_text(generate(pathlib.Path(folder)))
    print(f"wrote {STUB.relative_to(ROOT)}")
