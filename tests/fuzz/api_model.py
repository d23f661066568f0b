"""The public API of a module as call targets, and the call specifications the fuzz sends to its worker.

Introspection: every name in `module.__all__` (functions, classes: their constructors, static and
instance methods and arithmetic/`repr` operators) with its signatures, read from pybind11's docstrings
(one line per overload: ``name(arg: type = default, ...) -> type``) or from `inspect.signature` for
Python callables. A function added to `__all__` is fuzzed without any change here.

A call is described by a *spec*, a tree of tagged tuples that pickles small (a huge broadcast view is
sent as its base and shape) and prints as the Python expression that rebuilds it (the reproducer):

  ("lit", value)                  a Python or numpy scalar, string, None, or (nested) list/tuple of them
  ("array", ndarray)              a small array of any dtype and byte order
  ("layout", kind, spec)          the array re-laid out: "fortran", "reversed", "strided", "unaligned"
  ("broadcast", ndarray, shape)   np.broadcast_to(ndarray, shape): a read-only view, possibly huge
  ("list", [spec, ...]) / ("tuple", [spec, ...])
  ("dict", [(key, spec), ...])   a dict of literal keys
  ("file", name, text)            a file `name` written with `text` in the working directory; its name
  ("rng", seed)                   numpy.random.default_rng(seed)
  ("lambda", spec)                a callable returning the value of spec whatever it is passed
  ("per_row", spec)               a callable returning the value of spec once per row of its first argument
  ("scipy_rotation", spec)        scipy.spatial.transform.Rotation.from_quat(value of spec)
  ("call", path, args, kwargs)    module.<path>(*args, **kwargs), path "f" or "Class" or "Class.static"
  ("method", self, name, args, kwargs)   (value of self).name(*args, **kwargs)
  ("chain", self, [(name, args, kwargs), ...])  self after calling each mutating method on it
  ("check", module, name, params) <module>.<name>(**params): a property of results (properties.py), found by
                                  the fuzz's import path
"""

from __future__ import annotations

import importlib
import inspect
import math
import re
from dataclasses import dataclass, fields, is_dataclass
from pathlib import Path

import numpy as np

# operators a user reaches through Python syntax (a + b, 2 * m, -m, repr(m), str(m))
OPERATORS = {"__add__", "__sub__", "__mul__", "__rmul__", "__neg__", "__matmul__", "__call__", "__repr__", "__str__",
             "__getitem__", "__len__"}


# ---------------------------------------------------------------------------------------------
# signatures


@dataclass(frozen=True)
class Param:
    name: str
    annotation: str  # as written in the signature ('' when there is none)
    keyword_only: bool
    optional: bool  # has a default


@dataclass(frozen=True)
class Target:
    """One public callable: `path` from the module ("quat_to_matrix", "Transform" for its constructor,
    "Transform.from_quat" for a static method); `owner` is the class for an instance method (called on an
    instance built by the fuzz), else None."""

    path: str
    owner: str | None
    overloads: tuple[tuple[Param, ...], ...]
    returns: tuple[str, ...]  # return annotation of each overload
    doc: str


def _split_top_level(text: str, sep: str) -> list[str]:
    """Split at `sep` outside brackets and quotes."""
    parts, depth, quote, start = [], 0, "", 0
    i = 0
    while i < len(text):
        c = text[i]
        if quote:
            if c == quote:
                quote = ""
        elif c in "'\"":
            quote = c
        elif c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        elif depth == 0 and text.startswith(sep, i):
            parts.append(text[start:i])
            start = i + len(sep)
            i += len(sep) - 1
        i += 1
    parts.append(text[start:])
    return [p.strip() for p in parts if p.strip()]


def _parse_params(text: str, drop_self: bool) -> tuple[Param, ...] | None:
    params, keyword_only = [], False
    for item in _split_top_level(text, ","):
        if item == "/":
            continue
        if item == "*":
            keyword_only = True
            continue
        if item.startswith("*"):
            return None  # *args / **kwargs: the real signature is elsewhere
        head, *default = _split_top_level(item, " = ")
        name, _, annotation = head.partition(":")
        params.append(Param(name.strip(), annotation.strip(), keyword_only, bool(default)))
    if drop_self and params and params[0].name == "self":
        params = params[1:]
    return tuple(params)


def pybind_overloads(name: str, doc: str, drop_self: bool) -> list[tuple[tuple[Param, ...], str]]:
    """(params, return annotation) of each overload listed in a pybind11 docstring."""
    found = []
    pattern = re.compile(rf"^(?:\d+\. )?{re.escape(name)}\((.*)\) -> (.+)$")
    for line in (doc or "").splitlines():
        m = pattern.match(line.strip())
        if m:
            params = _parse_params(m.group(1), drop_self)
            if params is not None:
                found.append((params, m.group(2).strip()))
    return found


def python_overloads(fn, drop_self: bool) -> list[tuple[tuple[Param, ...], str]]:
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return []
    params = []
    for p in sig.parameters.values():
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        params.append(Param(p.name, _annotation_text(p.annotation, p.empty), p.kind == p.KEYWORD_ONLY,
                            p.default is not p.empty))
    if drop_self and params and params[0].name == "self":
        params = params[1:]
    return [(tuple(params), _annotation_text(sig.return_annotation, sig.empty))]


def _annotation_text(annotation, empty) -> str:
    if annotation is empty:
        return ""
    return annotation if isinstance(annotation, str) else getattr(annotation, "__name__", str(annotation))


def _overloads(fn, name: str, drop_self: bool):
    # Python (a function, a method, a class, a decorated function such as functools.lru_cache's): a real signature
    if inspect.isfunction(fn) or inspect.ismethod(fn) or isinstance(fn, type) or hasattr(fn, "__wrapped__"):
        return python_overloads(fn, drop_self)
    return pybind_overloads(name, getattr(fn, "__doc__", "") or "", drop_self)


def _target(path, owner, fn, name, drop_self):
    found = _overloads(fn, name, drop_self)
    if not found:
        raise RuntimeError(f"fuzz: cannot read the signature of {path} from its docstring")
    return Target(path, owner, tuple(p for p, _ in found), tuple(r for _, r in found), getattr(fn, "__doc__", "") or "")


def public_targets(module, submodules: tuple[str, ...] = ()) -> tuple[list[Target], dict[str, str]]:
    """Every callable of module.__all__, and the names that have none with the reason. A module among
    them, and each of `submodules` (public modules the package does not list in
    __all__, such as rigiddyn.units, rigiddyn.dispersion), is walked in turn: its callables get paths "<submodule>.<name>"."""
    targets, skipped = [], {}
    for name in module.__all__:
        obj = getattr(module, name)
        if inspect.ismodule(obj):
            targets += _module_targets(name, obj, skipped)
        else:
            targets += _named_targets(name, obj, skipped)
    for name in submodules:
        targets += _module_targets(name, importlib.import_module(f"{module.__name__}.{name}"), skipped)
    return targets, skipped


def public_names(submodule) -> list[str]:
    """The public names of a submodule: its __all__, else the names it defines (not those it imports)."""
    if hasattr(submodule, "__all__"):
        return list(submodule.__all__)
    return [n for n, obj in vars(submodule).items() if not n.startswith("_") and not inspect.ismodule(obj)
            and getattr(obj, "__module__", None) == submodule.__name__]


def public_classes(module, submodules: tuple[str, ...] = ()) -> dict[str, type]:
    """{path: class} of every class the fuzz may build or take: module.__all__'s, and the public classes of
    its submodules (those in __all__ and `submodules`) as "<submodule>.<Class>"."""
    found = {}
    walked = [(n, getattr(module, n)) for n in module.__all__ if inspect.ismodule(getattr(module, n))]
    walked += [(n, importlib.import_module(f"{module.__name__}.{n}")) for n in submodules]
    for prefix, names, owner in [("", module.__all__, module)] + [(f"{n}.", public_names(m), m) for n, m in walked]:
        for name in names:
            obj = getattr(owner, name)
            if isinstance(obj, type) and not issubclass(obj, BaseException):
                found[prefix + name] = obj
    return found


def _module_targets(prefix: str, submodule, skipped: dict[str, str]) -> list[Target]:
    targets = []
    for name in public_names(submodule):
        targets += _named_targets(f"{prefix}.{name}", getattr(submodule, name), skipped)
    return targets


def _named_targets(path: str, obj, skipped: dict[str, str]) -> list[Target]:
    if isinstance(obj, type):
        if issubclass(obj, BaseException):
            skipped[path] = "an exception or warning category (raised by the API, not called)"
            return []
        found = _class_targets(path, obj)
        if not found:
            skipped[path] = "a class with no constructor or methods (reached as a result, its properties read)"
        return found
    if callable(obj):
        return [_target(path, None, obj, getattr(obj, "__name__", path.split(".")[-1]), False)]
    skipped[path] = f"a constant ({type(obj).__name__})"
    return []


def _class_targets(name: str, cls: type) -> list[Target]:
    out = []
    init = vars(cls).get("__init__")
    python_class = not _is_pybind(cls)
    # a class only the core makes has an __init__ that refuses every call ("... has no public constructor: ..."),
    # and pybind11 gives a class without a constructor one that only raises "No constructor defined"
    doc = (init.__doc__ or "") if init is not None else ""
    if init is not None and not doc.startswith("Initialize self.") and "has no public constructor" not in doc:
        fn = cls if inspect.isfunction(init) else init  # a Python class: its signature without self
        out.append(_target(name, None, fn, "__init__", True))
    elif init is None and python_class:  # a Python class constructed by its base's __init__ (or object's)
        out.append(_target(name, None, cls, "__init__", True))
    for attr, raw in vars(cls).items():
        if attr.startswith("_") and attr not in OPERATORS:
            continue
        if isinstance(raw, (staticmethod, classmethod)):
            out.append(_target(f"{name}.{attr}", None, getattr(cls, attr), attr, False))
        elif callable(raw) and not isinstance(raw, type):
            out.append(_target(f"{name}.{attr}", name, raw, attr, True))
    return out


def _is_pybind(cls: type) -> bool:
    return any(type(k).__name__ == "pybind11_type" for k in cls.__mro__)


# ---------------------------------------------------------------------------------------------
# specs: build and print


def _lit(v) -> str:
    """Python source of a literal (nan/inf spelled as the reproducer's preamble names them)."""
    if isinstance(v, np.generic):
        return f"np.{type(v).__name__}({_lit(v.item())})"
    if isinstance(v, bool) or v is None or isinstance(v, (int, str, bytes)):
        return repr(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, complex):
        return f"complex({_lit(v.real)}, {_lit(v.imag)})"
    if isinstance(v, list):
        return "[" + ", ".join(_lit(x) for x in v) + "]"
    if isinstance(v, tuple):
        return "(" + ", ".join(_lit(x) for x in v) + (",)" if len(v) == 1 else ")")
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_lit(k)}: {_lit(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"fuzz: no literal for {type(v).__name__}")


_DTYPE_NAMES = {"float64", "float32", "float16", "int64", "int32", "int8", "uint8", "uint64", "bool", "complex128",
                "complex64"}


def _dtype_source(dt: np.dtype) -> str:
    if dt == object:
        return "object"
    if dt.isnative and dt.name in _DTYPE_NAMES:
        return f"np.{dt.name}"
    return f"np.dtype({dt.str!r})"


def _array_source(a: np.ndarray) -> str:
    if a.size == 0:
        return f"np.empty({a.shape!r}, dtype={_dtype_source(a.dtype)})"
    return f"np.array({_lit(a.tolist())}, dtype={_dtype_source(a.dtype)})"


def _args_source(args, kwargs) -> str:
    return ", ".join([source(a) for a in args] + [f"{k}={source(v)}" for k, v in kwargs])


def source(spec, _depth=[0]) -> str:  # noqa: B006  (depth counter for chain variable names)
    tag = spec[0]
    if tag == "lit":
        return _lit(spec[1])
    if tag == "array":
        return _array_source(spec[1])
    if tag == "layout":
        inner = source(spec[2])
        return {"fortran": f"np.asfortranarray({inner})", "reversed": f"{inner}[::-1]",
                "strided": f"np.repeat({inner}, 2, axis=0)[::2]", "unaligned": f"unaligned({inner})"}[spec[1]]
    if tag == "broadcast":
        return f"np.broadcast_to({_array_source(spec[1])}, {spec[2]!r})"
    if tag == "list":
        return "[" + ", ".join(source(s) for s in spec[1]) + "]"
    if tag == "tuple":
        return "(" + ", ".join(source(s) for s in spec[1]) + (",)" if len(spec[1]) == 1 else ")")
    if tag == "dict":
        return "{" + ", ".join(f"{_lit(k)}: {source(v)}" for k, v in spec[1]) + "}"
    if tag == "file":
        return f"(Path({spec[1]!r}).write_text({spec[2]!r}), {spec[1]!r})[1]"
    if tag == "check":
        return f"{spec[1]}.{spec[2]}(**{_lit(spec[3])})"
    if tag == "rng":
        return f"np.random.default_rng({spec[1]!r})"
    if tag == "lambda":
        return f"(lambda *args, **kwargs: {source(spec[1])})"
    if tag == "per_row":
        return f"(lambda rows, *args, **kwargs: np.full(len(rows), {source(spec[1])}))"
    if tag == "scipy_rotation":
        return f"Rotation.from_quat({source(spec[1])})"
    if tag == "call":
        return f"rd.{spec[1]}({_args_source(spec[2], spec[3])})"
    if tag == "method":
        return f"{source(spec[1])}.{spec[2]}({_args_source(spec[3], spec[4])})"
    if tag == "chain":
        _depth[0] += 1
        try:
            var = f"_o{_depth[0]}"
            calls = "".join(f"{var}.{name}({_args_source(a, k)}), " for name, a, k in spec[2])
            return f"({var} := {source(spec[1])}, {calls}{var})[-1]"
        finally:
            _depth[0] -= 1
    raise ValueError(f"fuzz: unknown spec {tag!r}")


def unaligned(a: np.ndarray) -> np.ndarray:
    """A copy of `a` whose data starts one byte past an aligned address."""
    a = np.ascontiguousarray(a)
    return np.frombuffer(b"\0" + a.tobytes(), dtype=a.dtype, offset=1).reshape(a.shape)


def reproducer(expr: str, module_name: str) -> str:
    """A runnable script that evaluates `expr` (the source of a spec) again."""
    lines = ["import numpy as np", f"import {module_name} as rd", 'nan, inf = float("nan"), float("inf")']
    if "Rotation." in expr:
        lines.append("from scipy.spatial.transform import Rotation")
    if "Path(" in expr:
        lines.append("from pathlib import Path")
    checked = re.match(r"(\w+)\.\w+\(\*\*", expr)
    if checked and checked.group(1) != "rd":  # a property of a module beside the fuzz: run from the repository root
        lines += ["import sys", "sys.path.insert(0, 'tests/fuzz')", f"import {checked.group(1)}"]
    if "unaligned(" in expr:
        lines.append("unaligned = lambda a: np.frombuffer(b'\\0' + a.tobytes(), dtype=a.dtype, offset=1)"
                     ".reshape(a.shape)")
    return "\n".join(lines + [expr])


def build(spec, module, on_call):
    """The value of `spec`; every call (target or setup) goes through on_call(path, fn, args, kwargs, call),
    `call` the spec that makes that call alone (a chain: the chain up to it), for its own reproducer."""
    tag = spec[0]
    if tag == "lit":
        return spec[1]
    if tag == "array":
        return spec[1].copy()
    if tag == "layout":
        a = build(spec[2], module, on_call)
        if spec[1] == "fortran":
            return np.asfortranarray(a)
        if spec[1] == "reversed":
            return a[::-1]
        if spec[1] == "strided":
            return np.repeat(a, 2, axis=0)[::2]
        return unaligned(a)
    if tag == "broadcast":
        return np.broadcast_to(spec[1], spec[2])
    if tag in ("list", "tuple"):
        items = [build(s, module, on_call) for s in spec[1]]
        return items if tag == "list" else tuple(items)
    if tag == "dict":
        return {k: build(v, module, on_call) for k, v in spec[1]}
    if tag == "file":
        Path(spec[1]).write_text(spec[2])
        return spec[1]
    if tag == "rng":
        return np.random.default_rng(spec[1])
    if tag == "check":
        properties = importlib.import_module(spec[1])
        return on_call(f"check.{spec[2]}", getattr(properties, spec[2]), [], dict(spec[3]), spec)
    if tag == "lambda":
        value = build(spec[1], module, on_call)
        return lambda *args, **kwargs: value
    if tag == "per_row":
        value = build(spec[1], module, on_call)
        return lambda rows, *args, **kwargs: np.full(len(rows), value)
    if tag == "scipy_rotation":
        from scipy.spatial.transform import Rotation

        return Rotation.from_quat(build(spec[1], module, on_call))
    if tag == "call":
        fn = module
        for part in spec[1].split("."):
            fn = getattr(fn, part)
        args, kwargs = _build_args(spec[2], spec[3], module, on_call)
        return on_call(spec[1], fn, args, kwargs, spec)
    if tag == "method":
        obj = build(spec[1], module, on_call)
        args, kwargs = _build_args(spec[3], spec[4], module, on_call)
        return on_call(f"{type(obj).__name__}.{spec[2]}", getattr(obj, spec[2]), args, kwargs, spec)
    if tag == "chain":
        obj = build(spec[1], module, on_call)
        for i, (name, a, k) in enumerate(spec[2]):
            args, kwargs = _build_args(a, k, module, on_call)
            on_call(f"{type(obj).__name__}.{name}", getattr(obj, name), args, kwargs, ("chain", spec[1], spec[2][:i + 1]))
        return obj
    raise ValueError(f"fuzz: unknown spec {tag!r}")


def _build_args(args, kwargs, module, on_call):
    return [build(a, module, on_call) for a in args], {k: build(v, module, on_call) for k, v in kwargs}


# ---------------------------------------------------------------------------------------------
# walking a result for its floats


def public_attributes(obj, package: str) -> list[str]:
    """Readable public attributes of an object of the fuzzed package: properties and dataclass fields."""
    cls = type(obj)
    if not (cls.__module__ or "").startswith(package) or isinstance(obj, type):
        return []
    names = [f.name for f in fields(obj)] if is_dataclass(obj) else []
    for klass in cls.__mro__:
        for name, raw in vars(klass).items():
            if not name.startswith("_") and isinstance(raw, property) and name not in names:
                names.append(name)
    return names
