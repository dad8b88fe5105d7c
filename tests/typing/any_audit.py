"""Count ``Any`` in the types of typed-mjcf's public API, and say where each one comes from.

    python tests/typing/any_audit.py            # as this repository checks itself
    python tests/typing/any_audit.py --as-user  # a user's mypy: unresolved imports are Any
    python tests/typing/any_audit.py --json     # machine-readable

mypy (as a library) analyses ``typed_mjcf`` from the source tree; the audit then walks the
public surface the way a user meets it: every name in ``typed_mjcf.__all__`` and in the
public submodules (``types``, ``errors``, ``io``, ``assets``), every public member of every
class reached (inherited ones included: ``Element``, ``ModelRoot``), and every typed-mjcf
class or ``TypedDict`` named in those signatures (``BodyAttributes``, ``ElementSpec``, ...).
In each declared type it counts ``AnyType`` nodes after expanding aliases, by kind:
``explicit`` (written ``Any`` or ``Callable[..., T]``), ``unannotated`` (a function or
variable without annotation), ``unresolved`` (from an import mypy could not resolve, e.g.
``mujoco`` without stubs), and the others mypy distinguishes.

``--as-user`` ignores missing imports, as a user's mypy may. ``mujoco`` is typed either
way, by ``generated/mujoco-stubs`` (copied into a project by ``typed-mjcf mujoco-stubs``).

Relies on mypy internals (mypy is pinned in the dev extra).
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

from mypy import build
from mypy.modulefinder import BuildSource
from mypy.nodes import (
    Decorator,
    FuncDef,
    MypyFile,
    OverloadedFuncDef,
    SymbolNode,
    TypeAlias,
    TypeInfo,
    Var,
)
from mypy.options import Options
from mypy.types import (
    AnyType,
    CallableType,
    Instance,
    LiteralType,
    NoneType,
    Overloaded,
    Parameters,
    ParamSpecType,
    ProperType,
    TupleType,
    Type,
    TypeAliasType,
    TypedDictType,
    TypeOfAny,
    TypeType,
    TypeVarTupleType,
    TypeVarType,
    UninhabitedType,
    UnionType,
    UnpackType,
    get_proper_type,
)

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("typed_mjcf",)
PUBLIC_MODULES = ("typed_mjcf", "typed_mjcf.types", "typed_mjcf.errors", "typed_mjcf.io",
                  "typed_mjcf.assets", "typed_mjcf.parametric", "typed_mjcf.warp")
# Where Any is by design; none so far (the generic ``add(tag: str, **kwargs: object)``
# fallback takes ``object``, not ``Any``).
ALLOWED: frozenset[str] = frozenset()

KINDS = {
    TypeOfAny.unannotated: "unannotated",
    TypeOfAny.explicit: "explicit",
    TypeOfAny.from_unimported_type: "unresolved",
    TypeOfAny.from_omitted_generics: "omitted generics",
    TypeOfAny.from_error: "unresolved",
    TypeOfAny.special_form: "special form",
    TypeOfAny.from_another_any: "from another Any",
    TypeOfAny.implementation_artifact: "implementation artifact",
    TypeOfAny.suggestion_engine: "suggestion engine",
}


@dataclass(frozen=True)
class Finding:
    """One ``Any`` in a public type."""

    symbol: str  # e.g. typed_mjcf.RootElement.compile
    where: str  # e.g. "return type"
    kind: str  # see KINDS
    declared: str  # the declared type as mypy prints it


@dataclass
class Audit:
    """What was walked and what was found."""

    symbols: int
    classes: int
    findings: list[Finding]
    inferred: list[str]  # public attributes without a declared type (not Any; ambiguous)

    @property
    def unexpected(self) -> list[Finding]:
        return [f for f in self.findings if f.symbol not in ALLOWED]


# ----------------------------------------------------------------------------- types


class _AnyFinder:
    """Every ``AnyType`` in a type, aliases expanded, typed-mjcf classes collected."""

    def __init__(self, packages: Sequence[str] = PACKAGES) -> None:
        self.packages = tuple(packages)
        self.anys: list[AnyType] = []
        self.classes: list[TypeInfo] = []
        self._aliases: set[str] = set()

    def visit(self, t: Type | None) -> None:
        if t is None:
            return
        if isinstance(t, TypeAliasType):
            if t.alias is not None and t.alias.fullname not in self._aliases:
                self._aliases.add(t.alias.fullname)  # recursive aliases: expand once
                self.visit(get_proper_type(t))
            for arg in t.args:
                self.visit(arg)
            return
        self._visit_proper(get_proper_type(t))

    def _visit_proper(self, t: ProperType) -> None:
        if isinstance(t, AnyType):
            self.anys.append(t)
        elif isinstance(t, Instance):
            if t.type.fullname.split(".")[0] in self.packages:
                self.classes.append(t.type)
            for arg in t.args:
                self.visit(arg)
        elif isinstance(t, UnionType):
            for item in t.items:
                self.visit(item)
        elif isinstance(t, CallableType):
            for arg in t.arg_types:
                self.visit(arg)
            self.visit(t.ret_type)
        elif isinstance(t, Overloaded | TupleType):
            for item in t.items:
                self.visit(item)
        elif isinstance(t, TypedDictType):
            if t.fallback.type.fullname.split(".")[0] in self.packages:
                self.classes.append(t.fallback.type)
            for item in t.items.values():
                self.visit(item)
        elif isinstance(t, UnpackType | TypeType):
            self.visit(t.type if isinstance(t, UnpackType) else t.item)
        elif isinstance(t, TypeVarType):
            self.visit(t.upper_bound)
        elif isinstance(t, Parameters):
            for arg in t.arg_types:
                self.visit(arg)
        elif isinstance(t, LiteralType | NoneType | UninhabitedType | ParamSpecType
                        | TypeVarTupleType):
            pass
        else:
            raise TypeError(f"any_audit does not know mypy type {type(t).__name__}: {t}")


# ----------------------------------------------------------------------------- symbols


def _types_of(node: SymbolNode) -> Iterator[tuple[str, Type | None]]:
    """(what, declared type) for a module- or class-level symbol; None: unannotated."""
    if isinstance(node, Var):
        yield "type", node.type
    elif isinstance(node, FuncDef):
        yield "signature", node.type
    elif isinstance(node, Decorator):
        yield ("getter" if node.func.is_property else "signature"), node.func.type
    elif isinstance(node, OverloadedFuncDef):
        if node.is_property:
            for item in node.items:
                if isinstance(item, Decorator):
                    setter = item.func.name == node.name and item is not node.items[0]
                    yield ("setter" if setter else "getter"), item.func.type
        else:
            for i, item in enumerate(node.items):
                func = item.func if isinstance(item, Decorator) else item
                yield f"overload {i + 1}", func.type
    elif isinstance(node, TypeAlias):
        yield "alias", node.target


def _public(name: str) -> bool:
    return not name.startswith("_") or (name.startswith("__") and name.endswith("__")
                                         and name not in ("__slots__", "__all__"))


def _describe(where: str, t: Type | None, index: int, anys: list[AnyType]) -> str:
    if isinstance(t, CallableType) and len(anys) == 1:
        ret = _has_any(t.ret_type)
        if ret:
            return f"{where}: return type"
        for name, arg in zip(t.arg_names, t.arg_types, strict=True):
            if _has_any(arg):
                return f"{where}: parameter {name}"
    return where if len(anys) == 1 else f"{where} (#{index + 1})"


def _has_any(t: Type) -> bool:
    finder = _AnyFinder()
    finder.visit(t)
    return bool(finder.anys)


def _exported_names(module: str, tree: MypyFile) -> list[str]:
    """The module's ``__all__`` as Python computes it; else its public names."""
    try:
        exported = getattr(importlib.import_module(module), "__all__", None)
    except ImportError:  # analysed from text only
        exported = None
    if exported is not None:
        return sorted(str(name) for name in exported)
    return sorted(n for n, e in tree.names.items() if e.module_public and not n.startswith("_"))


def audit(files: dict[str, MypyFile], modules: Sequence[str] = PUBLIC_MODULES,
          packages: Sequence[str] = PACKAGES) -> Audit:
    findings: list[Finding] = []
    seen_classes: set[str] = set()
    queue: list[TypeInfo] = []
    symbols = 0

    inferred: list[str] = []

    def check(symbol: str, node: SymbolNode) -> None:
        nonlocal symbols
        if isinstance(node, Var) and node.is_inferred and not node.explicit_self_type:
            inferred.append(symbol)
        for where, declared in _types_of(node):
            symbols += 1
            if declared is None:
                findings.append(Finding(symbol, where, "unannotated", "(no annotation)"))
                continue
            finder = _AnyFinder(packages)
            finder.visit(declared)
            queue.extend(finder.classes)
            for i, found in enumerate(finder.anys):
                findings.append(Finding(symbol, _describe(where, declared, i, finder.anys),
                                        KINDS.get(found.type_of_any, "?"), str(declared)))

    for module in modules:
        tree = files[module]
        for name in _exported_names(module, tree):
            entry = tree.names.get(name)
            if entry is None or entry.node is None:
                findings.append(Finding(f"{module}.{name}", "export", "unresolved",
                                        "(mypy does not see this name)"))
            elif isinstance(entry.node, TypeInfo):
                queue.append(entry.node)
            elif not isinstance(entry.node, MypyFile):
                check(f"{module}.{name}", entry.node)

    while queue:
        info = queue.pop()
        if info.fullname in seen_classes:
            continue
        seen_classes.add(info.fullname)
        for base in info.mro:
            if base.fullname.split(".")[0] not in packages:
                continue
            queue.append(base)
            for name, entry in sorted(base.names.items()):
                if entry.node is None or not _public(name):
                    continue
                if entry.plugin_generated and isinstance(entry.node, Var) and name.startswith("__"):
                    continue  # e.g. a dataclass's __dataclass_fields__: bookkeeping, not API
                if info.names.get(name) is not None and base is not info:
                    continue  # overridden: checked on the subclass
                if isinstance(entry.node, TypeInfo):
                    queue.append(entry.node)
                    continue
                check(f"{info.fullname}.{name}" if base is info
                      else f"{info.fullname}.{name} (from {base.name})", entry.node)
        if info.typeddict_type is not None:
            check(f"{info.fullname}", Var("items", info.typeddict_type))
    return Audit(symbols, len(seen_classes), findings, inferred)


def _ignore_errors(path: str | None, messages: list[str], serious: bool) -> None:
    """The audit reads types; errors are the type checks' business."""


def analyse(as_user: bool = False, sources: Sequence[BuildSource] | None = None
            ) -> dict[str, MypyFile]:
    """Analyse typed_mjcf from the source tree (or the given sources) with mypy."""
    options = Options()
    options.python_version = (3, 11)
    options.incremental = False
    options.mypy_path = [str(ROOT / "src"), str(ROOT / "generated")]
    options.follow_imports = "normal"
    options.ignore_missing_imports = as_user
    options.preserve_asts = True
    if sources is None:
        sources = [BuildSource(None, module) for module in PUBLIC_MODULES]
    result = build.build(list(sources), options, flush_errors=_ignore_errors)
    return result.files


def run(as_user: bool = False) -> Audit:
    return audit(analyse(as_user))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Count Any in the types of typed-mjcf's public API.")
    parser.add_argument("--as-user", action="store_true",
                        help="ignore missing imports, as a user's mypy may")
    parser.add_argument("--json", action="store_true", help="print the findings as JSON")
    args = parser.parse_args(argv)
    result = run(as_user=args.as_user)
    if args.json:
        print(json.dumps({"symbols": result.symbols, "classes": result.classes,
                          "findings": [asdict(f) for f in result.findings],
                          "inferred": result.inferred}, indent=1))
    else:
        for finding in result.findings:
            print(f"{finding.symbol}: {finding.where}: Any ({finding.kind}) in "
                  f"{finding.declared}")
        kinds = Counter(f.kind for f in result.findings)
        summary = ", ".join(f"{n} {kind}" for kind, n in sorted(kinds.items())) or "none"
        for symbol in result.inferred:
            print(f"{symbol}: no declared type (inferred; pyright --verifytypes may call it ambiguous)")
        print(f"{len(result.findings)} Any in {result.symbols} public declared types of "
              f"{result.classes} classes ({summary}); {len(result.unexpected)} outside the "
              f"allowed places; {len(result.inferred)} public attributes without a declared type")
    return 1 if result.unexpected else 0


if __name__ == "__main__":
    sys.exit(main())
