"""Passes over a parsed draft stub, each with one job, run in the order of :data:`PASSES`.

They encode what the drafts get wrong about MuJoCo's bindings, measured against the running
module (see the comments), as rules rather than per-name edits; the per-name knowledge lives
in ``facts.py``.
"""

from __future__ import annotations

import ast
import copy
import importlib
from collections.abc import Callable

from codegen.mujoco_stubs import cdocs
from codegen.mujoco_stubs.syntax import (
    classes,
    docstring_of,
    dotted,
    functions,
    is_getter,
    is_none,
    is_setter,
    members,
    parse_expr,
    statements,
    union,
)

NDARRAY = "numpy.typing.NDArray"
ARRAY_LIKE = "numpy.typing.ArrayLike"


def _map_annotations(tree: ast.Module,
                     rewrite: Callable[[ast.expr, bool], ast.expr]) -> None:
    """Apply ``rewrite(annotation, is_parameter)`` to every annotation in ``tree``."""
    for function, _ in functions(tree):
        for arg in (*function.args.posonlyargs, *function.args.args, *function.args.kwonlyargs,
                    *filter(None, (function.args.vararg, function.args.kwarg))):
            if arg.annotation is not None:
                arg.annotation = rewrite(arg.annotation, True)
        if function.returns is not None:
            function.returns = rewrite(function.returns, False)
    for node in statements(tree):
        if isinstance(node, ast.AnnAssign):
            node.annotation = rewrite(node.annotation, False)


class _Transform(ast.NodeTransformer):
    """A NodeTransformer whose visit of an expression returns an expression."""

    def expr(self, node: ast.expr) -> ast.expr:
        result = self.visit(node)
        assert isinstance(result, ast.expr)
        return result


# ------------------------------------------------------------------------------- arrays


class _Annotated(_Transform):
    """``Annotated[NDArray[float64], "[3, 1]", "flags.writeable"]``: the array parameters.

    pybind11's Eigen caster converts an input from any numpy array or (nested) sequence of
    numbers of the right shape (a list, a float32 array), but not from a scalar; an output
    must be an array of exactly that dtype (flagged ``writeable``) or MuJoCo's result would
    land in a temporary copy. Inputs become ``NDArray[Any] | Sequence[float]`` (a sequence of
    sequences for a matrix, ``int`` for integer arrays); outputs and return values keep
    ``NDArray[dtype]``.
    """

    def __init__(self, parameter: bool) -> None:
        self.parameter = parameter

    def visit_Subscript(self, node: ast.Subscript) -> ast.expr:
        if dotted(node.value) != "typing.Annotated" or not isinstance(node.slice, ast.Tuple):
            return self.generic_visit_expr(node)
        inner, *meta = node.slice.elts
        writeable = any(isinstance(m, ast.Constant) and m.value == "flags.writeable"
                        for m in meta)
        is_array = isinstance(inner, ast.Subscript) and dotted(inner.value) == NDARRAY
        if is_array and self.parameter and not writeable:
            assert isinstance(inner, ast.Subscript)
            number = "int" if "int" in ast.unparse(inner.slice) else "float"
            dims = next((m.value for m in meta if isinstance(m, ast.Constant)
                         and isinstance(m.value, str) and m.value.startswith("[")), "")
            matrix = bool(dims) and not dims.replace(" ", "").endswith(",1]")
            items = (f"collections.abc.Sequence[collections.abc.Sequence[{number}]]" if matrix
                     else f"collections.abc.Sequence[{number}]")
            return parse_expr(f"numpy.typing.NDArray[typing.Any] | {items}")
        return self.expr(inner)

    def generic_visit_expr(self, node: ast.expr) -> ast.expr:
        result = self.generic_visit(node)
        assert isinstance(result, ast.expr)
        return result


def annotated_arrays(tree: ast.Module, module: str) -> None:
    _map_annotations(tree, lambda a, parameter: _Annotated(parameter).expr(a))


# ------------------------------------------------------------------------------- integers


class _Integers(_Transform):
    """``SupportsInt | SupportsIndex`` -> ``SupportsIndex``.

    pybind11 writes the pair for every C ``int``, but its integer caster refuses ``float``
    (``mj_step(m, d, 2.0)`` raises TypeError): ``SupportsIndex`` admits int, bool, numpy
    integers and MuJoCo's enums, and rejects floats, as the binding does.
    """

    def visit_BinOp(self, node: ast.BinOp) -> ast.expr:
        parts = [self.expr(p) for p in members(node)]
        names = [dotted(p) for p in parts]
        if "typing.SupportsInt" in names and "typing.SupportsIndex" in names:
            parts = [p for p, n in zip(parts, names, strict=True) if n != "typing.SupportsInt"]
        return union(parts)


def integers(tree: ast.Module, module: str) -> None:
    _map_annotations(tree, lambda a, parameter: _Integers().expr(a))


# ------------------------------------------------------------------------------- defaults


def none_defaults(tree: ast.Module, module: str) -> None:
    """``default: MjsDefault = None`` -> ``MjsDefault | None``: pybind11 accepts the None."""
    for function, _ in functions(tree):
        positional = [*function.args.posonlyargs, *function.args.args]
        pairs = list(zip(positional[len(positional) - len(function.args.defaults):],
                         function.args.defaults, strict=True))
        pairs += [(a, d) for a, d in zip(function.args.kwonlyargs, function.args.kw_defaults,
                                         strict=True) if d is not None]
        overload = any(dotted(d) == "typing.overload" for d in function.decorator_list)
        if overload and function.args.defaults and is_none(function.args.defaults[-1]) \
                and len(function.args.defaults) == 1:
            # bind_scalar(spec: MjsBody = None) in each of 20 overloads: with the None
            # they all match bind_scalar(), so the spec is required
            function.args.defaults = []
            continue
        for arg, default in pairs:
            if arg.annotation is None or not is_none(default):
                continue
            parts = members(arg.annotation)
            if not any(is_none(p) or dotted(p) in ("typing.Any", "Incomplete") for p in parts):
                arg.annotation = union([*parts, ast.Constant(value=None)])


# ------------------------------------------------------------------------------- sequences


def _plural(word: str) -> str:
    if word.endswith("y") and word[-2:-1] not in ("a", "e", "o", "u"):
        return word[:-1] + "ies"
    if word.endswith(("s", "x", "sh", "ch")):
        return word + "es"
    return word + "s"


def element_sequences(tree: ast.Module, module: str) -> None:
    """Bare ``list``/``tuple`` getters that hold one kind of element, typed with it.

    ``spec.joints`` (py::list) holds ``MjsJoint``s: a property named the plural of a spec
    element kind lists that kind. ``scene.geoms`` (a tuple) holds ``MjvGeom``s: the C field
    (``mjvGeom* geoms`` in ``mjvScene``, from mujoco.introspect) names the struct.
    """
    defined = {c.name for c in tree.body if isinstance(c, ast.ClassDef)}
    plurals = {_plural(name[3:].lower()): name for name in defined if name.startswith("Mjs")}
    for cls in classes(tree):
        for f in cls.body:
            if not (isinstance(f, ast.FunctionDef) and is_getter(f) and f.returns is not None):
                continue
            kind = dotted(f.returns)
            if kind == "list" and f.name in plurals:
                f.returns = parse_expr(f"list[{plurals[f.name]}]")
            elif kind == "tuple":
                struct = cdocs.element_struct(cls.name, f.name)
                name = None if struct is None else "M" + struct[1:]
                if name in defined:
                    f.returns = parse_expr(f"tuple[{name}, ...]")


# ------------------------------------------------------------------------------- generics

# Bare generic classes in the drafts (pybind11 says ``dict``, ``list``, ``numpy.ndarray`` for a
# py::dict, py::list, py::array). Their element types are whatever the caller put in or
# MuJoCo decided at run time; facts.py names them where they are known.
_BARE = {
    "dict": "dict[typing.Any, typing.Any]",
    "list": "list[typing.Any]",
    "tuple": "tuple[typing.Any, ...]",
    "numpy.ndarray": "numpy.typing.NDArray[typing.Any]",
    "np.ndarray": "numpy.typing.NDArray[typing.Any]",
}


class _Bare(_Transform):
    def visit_Subscript(self, node: ast.Subscript) -> ast.expr:
        node.slice = self.expr(node.slice)  # keep the generic itself, rewrite its arguments
        return node

    def visit_Name(self, node: ast.Name) -> ast.expr:
        return parse_expr(_BARE[node.id]) if node.id in _BARE else node

    def visit_Attribute(self, node: ast.Attribute) -> ast.expr:
        name = dotted(node)
        return parse_expr(_BARE[name]) if name in _BARE else node


def bare_generics(tree: ast.Module, module: str) -> None:
    _map_annotations(tree, lambda a, parameter: _Bare().expr(a))


# ------------------------------------------------------------------------------- properties


def _is_array(node: ast.expr | None) -> bool:
    return (node is not None and isinstance(node, ast.Subscript)
            and dotted(node.value) == NDARRAY)


def setters(tree: ast.Module, module: str) -> None:
    """Property setters typed ``Any`` take what the getter gives, arrays anything array-like.

    pybind11 types a setter's value ``object`` when the C++ setter takes a py::object: for an
    array field it copies any array-like of the right size in (``d.qpos = [0, 1]``,
    ``m.opt.gravity = (0, 0, -1)``); for the rest it converts to the getter's type.
    """
    for cls in classes(tree):
        getters = {f.name: f.returns for f in cls.body
                   if isinstance(f, ast.FunctionDef) and is_getter(f)}
        for f in cls.body:
            if not isinstance(f, ast.FunctionDef) or not is_setter(f) or len(f.args.args) != 2:
                continue
            value = f.args.args[1]
            value.arg = "value"
            if value.annotation is None or dotted(value.annotation) != "typing.Any":
                continue
            getter = getters.get(f.name)
            if _is_array(getter):
                value.annotation = parse_expr(ARRAY_LIKE)
            elif getter is not None and dotted(getter) != "typing.Any":
                value.annotation = copy.deepcopy(getter)


def private_fields(tree: ast.Module, module: str) -> None:
    """Drop ``_all_fields``-style class attributes: bookkeeping of the bindings, not API."""
    for cls in classes(tree):
        cls.body = [s for s in cls.body
                    if not (isinstance(s, ast.AnnAssign) and isinstance(s.target, ast.Name)
                            and s.target.id.startswith("_") and not s.target.id.startswith("__"))]
        if not cls.body:
            cls.body = [ast.Expr(ast.Constant(...))]


def field_docs(tree: ast.Module, module: str) -> None:
    """The C header's comment and shape as the docstring of each struct field (cdocs.py)."""
    for cls in classes(tree):
        body: list[ast.stmt] = []
        for stmt in cls.body:
            body.append(stmt)
            if isinstance(stmt, ast.FunctionDef) and is_getter(stmt) \
                    and docstring_of(stmt.body) is None:
                doc = cdocs.field_doc(cls.name, stmt.name)
                if doc:
                    stmt.body = [ast.Expr(ast.Constant(doc))]
            elif isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name):
                doc = cdocs.field_doc(cls.name, stmt.target.id)
                if doc:  # an attribute docstring: pyright shows it on hover
                    body.append(ast.Expr(ast.Constant(doc)))
        cls.body = body


def unhashable(tree: ast.Module, module: str) -> None:
    """Drop ``__hash__: ClassVar[None] = None``: both checkers reject it as an override of
    ``object.__hash__`` (typeshed silences that with a type: ignore); the structs are then
    typed hashable, which only matters to code that hashes them."""
    for cls in classes(tree):
        cls.body = [s for s in cls.body
                    if not (isinstance(s, ast.AnnAssign) and isinstance(s.target, ast.Name)
                            and s.target.id == "__hash__")]


def _drop_repeated_overloads(cls: ast.ClassDef) -> None:
    """pybind11 lists some constructors twice (``__init__(value: int)`` as two overloads)."""
    seen: set[str] = set()
    body: list[ast.stmt] = []
    for stmt in cls.body:
        text = ast.unparse(stmt)
        if isinstance(stmt, ast.FunctionDef) and text in seen:
            continue
        seen.add(text)
        body.append(stmt)
    cls.body = body
    overloaded: dict[str, int] = {}
    for stmt in cls.body:
        if isinstance(stmt, ast.FunctionDef):
            overloaded[stmt.name] = overloaded.get(stmt.name, 0) + 1
    for stmt in cls.body:  # a single overload left is a plain function
        if isinstance(stmt, ast.FunctionDef) and overloaded[stmt.name] == 1:
            stmt.decorator_list = [d for d in stmt.decorator_list
                                   if dotted(d) != "typing.overload"]


def _enum_for_index(later: ast.FunctionDef, earlier: ast.FunctionDef) -> bool:
    """``later`` is ``earlier`` with an enum where ``earlier`` takes ``SupportsIndex``."""
    a, b = later.args.args, earlier.args.args
    if len(a) != len(b) or ast.unparse(later.returns or ast.Constant(None)) != \
            ast.unparse(earlier.returns or ast.Constant(None)):
        return False
    differs = False
    for x, y in zip(a, b, strict=True):
        tx = "" if x.annotation is None else ast.unparse(x.annotation)
        ty = "" if y.annotation is None else ast.unparse(y.annotation)
        if tx == ty:
            continue
        if ty == "typing.SupportsIndex" and tx.startswith("mujoco._enums."):
            differs = True
            continue
        return False
    return differs


def subsumed_overloads(tree: ast.Module, module: str) -> None:
    """Drop ``__getitem__(key: mjtWarning)`` after ``__getitem__(key: SupportsIndex)``: enums
    have ``__index__``, so the first overload already takes them (mypy: cannot match)."""
    for cls in classes(tree):
        kept: list[ast.stmt] = []
        for stmt in cls.body:
            if isinstance(stmt, ast.FunctionDef) and any(
                    isinstance(k, ast.FunctionDef) and k.name == stmt.name
                    and _enum_for_index(stmt, k) for k in kept):
                continue
            kept.append(stmt)
        cls.body = kept


def sequence_iteration(tree: ast.Module, module: str) -> None:
    """``for contact in d.contact``: Python iterates a class with ``__getitem__(int)`` and no
    ``__iter__`` by indexing until IndexError, which pyright models and mypy does not; an
    ``__iter__`` yielding what the integer ``__getitem__`` returns says it to both."""
    for cls in classes(tree):
        names = {f.name for f in cls.body if isinstance(f, ast.FunctionDef)}
        if "__iter__" in names or "__getitem__" not in names:
            continue
        item = next((f.returns for f in cls.body
                     if isinstance(f, ast.FunctionDef) and f.name == "__getitem__"
                     and len(f.args.args) == 2 and f.args.args[1].annotation is not None
                     and dotted(f.args.args[1].annotation) == "typing.SupportsIndex"), None)
        if item is not None:
            cls.body += ast.parse("def __iter__(self) -> collections.abc.Iterator["
                                  f"{ast.unparse(item)}]: ...").body


# ------------------------------------------------------------------------------- enums

ENUM_BASE = "_Enum"


def _is_enum(cls: ast.ClassDef) -> bool:
    return any(isinstance(s, ast.AnnAssign) and isinstance(s.target, ast.Name)
               and s.target.id == "__members__" for s in cls.body)


def _normalized(function: ast.FunctionDef, class_name: str) -> str:
    text = ast.unparse(function)
    return text.replace(f": {class_name})", ": typing.Self)")


def _number_operands(function: ast.FunctionDef) -> ast.FunctionDef:
    """``(SupportsIndex) -> int`` / ``(SupportsFloat | SupportsIndex) -> float`` overloads of
    an operator -> ``(int) -> int`` / ``(float) -> float``, as typeshed writes ``int``'s: the
    first pair overlaps with incompatible returns for both checkers."""
    returns = None if function.returns is None else dotted(function.returns)
    if len(function.args.args) == 2 and returns in ("int", "float"):
        operand = function.args.args[1]
        if operand.annotation is not None and any(
                dotted(p) in ("typing.SupportsIndex", "typing.SupportsFloat")
                for p in members(operand.annotation)):
            operand.annotation = ast.Name(returns)
    return function


def enums(tree: ast.Module, module: str) -> None:
    """One stub-only base class for what every pybind11 enum repeats (40 dunders each).

    The enums are ``py::enum_`` classes, not ``enum.IntEnum``: members are not ints
    (``isinstance(mjtObj.mjOBJ_BODY, int)`` is False), the class is not iterable, and
    arithmetic gives plain ints. The members and constructor stay on each enum; the shared
    operators move to ``_Enum``, which exists only in the stubs.
    """
    enum_classes = [c for c in tree.body if isinstance(c, ast.ClassDef) and _is_enum(c)]
    if not enum_classes:
        return
    forms: dict[str, set[str]] = {}
    count: dict[str, int] = {}
    sample: dict[str, list[ast.FunctionDef]] = {}
    for cls in enum_classes:
        seen: dict[str, list[str]] = {}
        for f in cls.body:
            if isinstance(f, ast.FunctionDef) and f.name != "__init__":
                seen.setdefault(f.name, []).append(_normalized(f, cls.name))
                if cls is enum_classes[0]:
                    sample.setdefault(f.name, []).append(f)
        for name, texts in seen.items():
            forms.setdefault(name, set()).add("\n".join(texts))
            count[name] = count.get(name, 0) + 1
    shared = {name for name, texts in forms.items()
              if len(texts) == 1 and count[name] == len(enum_classes) and name in sample}
    base_body: list[ast.stmt] = []
    for name in sorted(shared):
        if name in ("__eq__", "__ne__"):
            # overloads on the enum itself and on ints; object covers both, as at run time
            base_body += ast.parse(f"def {name}(self, other: object) -> bool: ...").body
            continue
        base_body += [_number_operands(copy.deepcopy(f)) for f in sample[name]]
    base = ast.parse(f"class {ENUM_BASE}:\n"
                     '    """What every MuJoCo enum (a pybind11 enum) supports; stubs only."""'
                     ).body[0]
    assert isinstance(base, ast.ClassDef)
    base.body += base_body
    for cls in enum_classes:
        cls.bases = [ast.Name(ENUM_BASE)]
        cls.body = [s for s in cls.body
                    if not (isinstance(s, ast.FunctionDef) and s.name in shared)]
        _drop_repeated_overloads(cls)
    at = tree.body.index(enum_classes[0])
    tree.body.insert(at, base)


# ------------------------------------------------------------------------------- bind


def bind_methods(tree: ast.Module, module: str) -> None:
    """``m.bind(spec_element)``: one overload per element kind, from ``bind_scalar``'s.

    ``mujoco/__init__.py`` assigns ``bind`` to MjModel and MjData at import (so the draft sees a
    static function of two arguments). One element gives the same view ``bind_scalar`` does; a
    sequence gives a ``_MjBindModel``/``_MjBindData`` whose attributes are lists of whatever
    each element's view holds (``Any``: the element kinds may differ).
    """
    for cls in classes(tree):
        if cls.name not in ("MjModel", "MjData"):
            continue
        scalar = [f for f in cls.body if isinstance(f, ast.FunctionDef) and f.name == "bind_scalar"]
        if not scalar:
            continue
        overloads: list[ast.stmt] = []
        for f in scalar:
            spec = f.args.args[1].annotation
            if spec is None or f.returns is None:
                continue
            element = [p for p in members(spec) if not is_none(p)]
            overloads += ast.parse(
                f"@typing.overload\ndef bind(self, specs: {ast.unparse(union(element))}) "
                f"-> {ast.unparse(f.returns)}: ...").body
        group = "mujoco._MjBindModel" if cls.name == "MjModel" else "mujoco._MjBindData"
        overloads += ast.parse(
            "@typing.overload\ndef bind(self, specs: "
            f"collections.abc.Sequence[mujoco.MjStruct]) -> {group}: ...").body
        at = next(i for i, s in enumerate(cls.body)
                  if isinstance(s, ast.FunctionDef) and s.name == "bind")
        cls.body[at:at + 1] = overloads


# ------------------------------------------------------------------------------- exports


def exception_classes(tree: ast.Module, module: str) -> None:
    """``from mujoco import FatalError`` in ``mujoco._errors`` -> ``class FatalError(Exception)``.

    pybind11 registers the exceptions under the package's name (``__module__ == "mujoco"``),
    so the draft imports them from the package that star-imports them from here: a cycle
    with no definition. The classes and their builtin bases are read from the module.
    """
    runtime = importlib.import_module(module)
    for at, stmt in reversed(list(enumerate(tree.body))):
        if not (isinstance(stmt, ast.ImportFrom) and stmt.module == "mujoco"):
            continue
        kept: list[ast.alias] = []
        defined: list[ast.stmt] = []
        for alias in stmt.names:
            value = getattr(runtime, alias.name, None)
            if isinstance(value, type) and all(b.__module__ == "builtins" for b in value.__bases__):
                bases = ", ".join(b.__name__ for b in value.__bases__)
                defined += ast.parse(f"class {alias.name}({bases}): ...").body
            else:
                kept.append(alias)
        stmt.names = kept
        tree.body[at:at + 1] = ([stmt] if kept else []) + defined


def shadowed_exports(tree: ast.Module, module: str) -> None:
    """Leave out of ``__all__`` what a later star import replaces in ``mujoco``.

    ``mujoco._specs`` and ``mujoco._structs`` both define ``MjOption``, ``MjVisual`` and
    ``MjStatistic``; ``mujoco/__init__.py`` star-imports ``_structs`` last, so
    ``mujoco.MjOption`` is the ``_structs`` class. Both checkers reject two star imports of
    different classes under one name, so the shadowed one stays reachable only as
    ``mujoco._specs.MjOption``, as it is at run time.
    """
    package = importlib.import_module("mujoco")
    runtime = importlib.import_module(module)
    for stmt in tree.body:
        if isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name) \
                and stmt.target.id == "__all__" and isinstance(stmt.value, ast.List):
            stmt.value.elts = [
                e for e in stmt.value.elts
                if not (isinstance(e, ast.Constant) and isinstance(e.value, str)
                        and hasattr(package, e.value)
                        and getattr(package, e.value) is not getattr(runtime, e.value, None))]


# ------------------------------------------------------------------------------- order

Pass = Callable[[ast.Module, str], None]

# Rewrites of the pybind11 drafts, in order (the later ones read what the earlier wrote).
PYBIND_PASSES: tuple[Pass, ...] = (
    exception_classes,
    shadowed_exports,
    annotated_arrays,
    integers,
    none_defaults,
    element_sequences,
    bare_generics,
    setters,
    private_fields,
    unhashable,
    subsumed_overloads,
    sequence_iteration,
    field_docs,
    enums,
    bind_methods,
)

# Rewrites of the mypy stubgen drafts of the pure-Python modules.
PYTHON_PASSES: tuple[Pass, ...] = (
    bare_generics,
)

