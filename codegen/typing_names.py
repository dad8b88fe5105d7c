"""Python type annotations for IR attributes: the naming and typing logic of the renderer.

Generated modules annotate through ``_builtins`` (attributes are called ``type``, ``range``,
``dir`` ...) and the public aliases of ``typed_mjcf.types`` imported as ``_t``.
"""

from __future__ import annotations

from codegen import ir

# Above this many values a fixed-length array is typed as a list: a 10-tuple literal helps nobody.
MAX_TUPLE = 12

_SCALAR = {"int": "_builtins.int", "real": "_builtins.float"}
_ARRAY_GET = {"double": "_t.Float64Array", "float": "_t.Float32Array", "int": "_t.Int32Array"}


def _literal(keywords: list[str]) -> str:
    return "Literal[" + ", ".join(f'"{k}"' for k in keywords) + "]"


def _tuple(item: str, n: int) -> str:
    return "tuple[" + ", ".join([item] * n) + "]" if n else "tuple[()]"


class Typer:
    """Annotations for the attributes of one schema."""

    def __init__(self, schema: ir.Schema) -> None:
        self.schema = schema
        self._namespace_classes: dict[str, list[str]] = {}
        for element in sorted(schema.elements.values(), key=lambda e: e.name):
            for a in element.attributes:
                if a.kind == "id" and a.namespace is not None:
                    self._namespace_classes.setdefault(a.namespace, []).append(element.class_name)

    def namespaces(self) -> dict[str, list[str]]:
        """Each identifier namespace and the classes that declare names into it."""
        return dict(sorted(self._namespace_classes.items()))

    def keywords(self, a: ir.AttributeDef) -> list[str]:
        assert a.enum is not None
        return self.schema.enums[a.enum].keywords

    def _item(self, a: ir.AttributeDef) -> str:
        return "_builtins.int" if a.kind == "int" else "_builtins.float"

    def getter(self, a: ir.AttributeDef) -> str:
        """The type a property returns (``None`` when unset is added by the template)."""
        if a.arity is not None and a.kind in ("int", "real"):
            return _ARRAY_GET[a.dtype or ("int" if a.kind == "int" else "double")]
        if a.kind in ("int", "real"):
            return _SCALAR[a.kind]
        if a.kind == "bool":
            return "_builtins.bool"
        if a.kind == "keyword":
            return _literal(self.keywords(a))
        if a.kind == "flags":
            return f"tuple[{_literal(self.keywords(a))}, ...]"
        if a.kind == "file":
            return "_builtins.str | _t.Asset"
        if a.kind == "ref":
            return " | ".join(["_builtins.str", *self.reference_classes(a)])
        return "_builtins.str"

    def setter(self, a: ir.AttributeDef) -> str:
        """The types a property accepts (``None`` unsets it; added by the template)."""
        if a.arity is not None and a.kind in ("int", "real"):
            return self._array_setter(a)
        if a.kind == "keyword":
            keywords = self.keywords(a)
            literal = _literal(keywords)
            takes_bool = "true" in keywords and "false" in keywords
            return f"{literal} | _builtins.bool" if takes_bool else literal
        if a.kind == "flags":
            literal = _literal(self.keywords(a))
            return f"{literal} | Collection[{literal}]"
        if a.kind == "file":
            return "_t.FileLike"
        return self.getter(a)

    def _array_setter(self, a: ir.AttributeDef) -> str:
        assert a.arity is not None
        item = self._item(a)
        lo, hi = a.arity
        array = "_t.IntArrayLike" if a.kind == "int" else "_t.FloatArrayLike"
        if hi is None or hi > MAX_TUPLE:
            scalar = f"{item} | " if lo <= 1 else ""
            return f"{scalar}Sequence[{item}] | {array}"
        one_number = [item] if lo <= 1 <= hi else []  # one value may be given as a number
        tuples = [_tuple(item, n) for n in range(max(lo, 1), hi + 1)]
        return " | ".join([*one_number, *tuples, f"_builtins.list[{item}]", array])

    def reference_classes(self, a: ir.AttributeDef) -> list[str]:
        assert a.namespace is not None
        return self._namespace_classes.get(a.namespace, [])

    def describe(self, a: ir.AttributeDef) -> str:
        """The MJCF type in words, for docstrings."""
        if a.kind in ("keyword", "flags"):
            words = ", ".join(self.keywords(a))
            return f"one of: {words}" if a.kind == "keyword" else f"any of: {words}"
        if a.kind in ("id", "ref"):
            verb = "name declared in" if a.kind == "id" else "reference to"
            return f"{verb} namespace ``{a.namespace}``"
        base = a.dtype if a.kind == "real" and a.dtype else a.kind
        if a.arity is None:
            return base
        lo, hi = a.arity
        if hi is None:
            return f"{base}[] (any length)" if lo == 0 else f"{base}[{lo}..] (at least {lo})"
        return f"{base}[{lo}]" if lo == hi else f"{base}[{lo}..{hi}] ({lo} to {hi} values)"
