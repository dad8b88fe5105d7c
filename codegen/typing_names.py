"""Python type annotations for IR attributes: the naming and typing logic of the renderer.

The typing surface (``elements.pyi``) annotates through ``_builtins`` (attributes are called
``type``, ``range``, ``dir`` ...), the public aliases of ``typed_mjcf.types`` imported as
``_t``, and aliases of its own that give long unions a name: one per keyword set
(``GeomType``), per array shape (``Reals3``, ``Reals1To3``) and per namespace with several
classes (``AnyJoint``).
"""

from __future__ import annotations

from dataclasses import dataclass

from codegen import ir

# Above this many values a fixed-length array is typed as a list: a 10-tuple literal helps nobody.
MAX_TUPLE = 12

_ARRAY_GET = {"double": "_t.Float64Array", "float": "_t.Float32Array", "int": "_t.Int32Array"}


@dataclass(frozen=True)
class Alias:
    """A named type: ``name: TypeAlias = value``."""

    name: str
    value: str
    doc: str


def _camel(text: str) -> str:
    return "".join(part[:1].upper() + part[1:] for part in text.replace("-", "_").split("_"))


def _alone_key(a: ir.AttributeDef) -> tuple[str, tuple[str, ...]] | None:
    """What names the keywords flags take alone: their enum and the alone enums."""
    if a.kind != "flags" or not a.alone or a.enum is None:
        return None
    return a.enum, tuple(a.alone)


def _literal(keywords: list[str]) -> str:
    return "Literal[" + ", ".join(f'"{k}"' for k in keywords) + "]"


class Typer:
    """Annotations for the attributes of one schema, and the aliases they use."""

    def __init__(self, schema: ir.Schema) -> None:
        self.schema = schema
        self._namespace_classes: dict[str, list[str]] = {}
        for element in sorted(schema.elements.values(), key=lambda e: e.name):
            for a in element.attributes:
                if a.kind == "id" and a.namespace is not None:
                    self._namespace_classes.setdefault(a.namespace, []).append(element.class_name)
        self._keyword_names = self._name_keyword_sets()
        self._alone_names = self._name_alone_sets()
        self._arrays: dict[str, Alias] = {}
        self._targets: dict[str, Alias] = {}

    # ------------------------------------------------------------------ names

    def _name_keyword_sets(self) -> dict[str, str]:
        """A public name per keyword set: the set's own name, split where it ends with the
        attribute that uses it (``geomtype`` -> ``GeomType``); ``<Tag><Attribute>`` when that
        is a class's name (``texture`` -> ``TextureType``)."""
        uses: dict[str, set[tuple[str, str]]] = {}
        for element in self.schema.elements.values():
            for a in element.attributes:
                if a.enum is not None:
                    uses.setdefault(a.enum, set()).add((element.tag, a.name))
        taken = self.class_names()
        names: dict[str, str] = {}
        for enum, users in sorted(uses.items()):
            base = enum
            for attribute in sorted({a for _, a in users}, key=len, reverse=True):
                if enum.endswith(attribute) and len(enum) > len(attribute):
                    base = f"{enum[:-len(attribute)]}_{attribute}"
                    break
            name = _camel(base)
            if name in taken and len(users) == 1:
                tag, attribute = next(iter(users))
                name = _camel(tag) + _camel(attribute)
            while name in taken:
                name += "Keyword"
            taken.add(name)
            names[enum] = name
        return names

    def _name_alone_sets(self) -> dict[tuple[str, tuple[str, ...]], str]:
        """A public name per set of keywords flags also take alone: the flags' name and
        ``Alone`` (``InputbitAlone``); ``<Tag><Attribute>Alone`` when flags of one enum take
        different sets."""
        taken = self.class_names() | set(self._keyword_names.values())
        names: dict[tuple[str, tuple[str, ...]], str] = {}
        for element in sorted(self.schema.elements.values(), key=lambda e: e.name):
            for a in element.attributes:
                key = _alone_key(a)
                if key is None or key in names:
                    continue
                name = self._keyword_names[key[0]] + "Alone"
                if name in taken:
                    name = _camel(element.tag) + _camel(a.name) + "Alone"
                while name in taken:
                    name += "Keyword"
                taken.add(name)
                names[key] = name
        return names

    def class_names(self) -> set[str]:
        return {e.class_name for e in self.schema.elements.values()}

    def keyword_aliases(self) -> list[Alias]:
        """The public name of every keyword set, in name order."""
        aliases = [Alias(name, _literal(self.schema.enums[enum].keywords),
                         f"The keywords of {self.schema.enums[enum].doc or enum}.")
                   for enum, name in self._keyword_names.items()]
        aliases += [Alias(name, _literal(self._keywords_of(alone)),
                          f"The keywords ``{self._keyword_names[enum]}`` flags also take, one "
                          f"alone in place of the flags (from {', '.join(alone)}).")
                    for (enum, alone), name in self._alone_names.items()]
        return sorted(aliases, key=lambda a: a.name)

    def _keywords_of(self, enums: tuple[str, ...]) -> list[str]:
        return [k for enum in enums for k in self.schema.enums[enum].keywords]

    def namespace_aliases(self) -> list[Alias]:
        """``AnyJoint = Joint | Freejoint``: each namespace of more than one class."""
        return [Alias(self.namespace_type(ns), " | ".join(classes),
                      f"An element of namespace ``{ns}``.")
                for ns, classes in self.namespaces().items() if len(classes) > 1]

    def array_aliases(self) -> list[Alias]:
        """The array shapes used so far (call after every annotation is made)."""
        return sorted(self._arrays.values(), key=lambda a: a.name)

    def namespaces(self) -> dict[str, list[str]]:
        """Each identifier namespace and the classes that declare names into it."""
        return dict(sorted(self._namespace_classes.items()))

    def namespace_type(self, namespace: str) -> str:
        """The type of an element of ``namespace``: its class, or the alias of its classes."""
        classes = self._namespace_classes.get(namespace, [])
        if len(classes) == 1:
            return classes[0]
        return "Any" + _camel(namespace)

    def keyword_type(self, a: ir.AttributeDef) -> str:
        assert a.enum is not None
        return self._keyword_names[a.enum]

    def alone_type(self, a: ir.AttributeDef) -> str | None:
        """The name of the keywords flags take alone, or None when they take none."""
        key = _alone_key(a)
        return None if key is None else self._alone_names[key]

    # ------------------------------------------------------------------ annotations

    def getter(self, a: ir.AttributeDef) -> str:
        """The type a property returns (``None`` when unset is added by the template)."""
        if a.arity is not None and a.kind in ("int", "real"):
            return _ARRAY_GET[a.dtype or ("int" if a.kind == "int" else "double")]
        if a.kind == "int":
            return "_builtins.int"
        if a.kind == "real":
            return "_builtins.float"
        if a.kind == "bool":
            return "_builtins.bool"
        if a.kind == "keyword":
            return self.keyword_type(a)
        if a.kind == "flags":
            alone = self.alone_type(a)
            flags = f"tuple[{self.keyword_type(a)}, ...]"
            return flags if alone is None else f"{flags} | {alone}"
        if a.kind == "file":
            return "_builtins.str | _t.Asset"
        if a.kind == "ref" or a.namespace_from is not None:
            return self._reference_union(a)
        return "_builtins.str"

    def setter(self, a: ir.AttributeDef) -> str:
        """The types a property accepts (``None`` unsets it; added by the template)."""
        if a.arity is not None and a.kind in ("int", "real"):
            return self._array_setter(a)
        if a.kind == "int":
            return "_t.Integer"
        if a.kind == "real":
            return "_t.Real"
        if a.kind == "keyword":
            keywords = self.schema.enums[a.enum or ""].keywords
            takes_bool = "true" in keywords and "false" in keywords
            name = self.keyword_type(a)
            return f"{name} | _builtins.bool" if takes_bool else name
        if a.kind == "flags":
            name = self.keyword_type(a)
            alone = self.alone_type(a)
            flags = f"{name} | Collection[{name}]"
            return flags if alone is None else f"{flags} | {alone}"
        if a.kind == "file":
            return "_t.FileLike"
        return self.getter(a)

    def _array_setter(self, a: ir.AttributeDef) -> str:
        assert a.arity is not None
        is_int = a.kind == "int"
        item = "_t.Integer" if is_int else "_t.Real"
        lo, hi = a.arity
        stem = "Integers" if is_int else "Reals"
        sequence = f"_t.NumberList[{item}] | {'_t.IntArrayLike' if is_int else '_t.FloatArrayLike'}"
        if hi is None or hi > MAX_TUPLE:
            name = f"{stem}{lo}OrMore" if lo else f"{stem}Any"
            scalar = f"{item} | " if lo <= 1 else ""
            value = f"{scalar}tuple[{item}, ...] | {sequence}"
            doc = f"{lo} or more numbers" if lo else "any number of numbers"
        else:
            name = f"{stem}{lo}" if lo == hi else f"{stem}{lo}To{hi}"
            one = [item] if lo <= 1 <= hi else []  # one value may be given as a number
            tuples = [f"tuple[{', '.join([item] * n)}]" for n in range(max(lo, 1), hi + 1)]
            value = " | ".join([*one, *tuples, sequence])
            doc = f"{lo} numbers" if lo == hi else f"{lo} to {hi} numbers"
        doc = doc.replace("numbers", "integers") if is_int else doc
        self._arrays.setdefault(name, Alias(name, value, f"{doc[:1].upper()}{doc[1:]}: a tuple "
                                            "of that length, a list or a numpy array."))
        return name

    def _reference_union(self, a: ir.AttributeDef) -> str:
        """``str | <the element types>``; a union of several element types is named once (a
        checker then reads it once, and a hover shows its name, not 27 classes)."""
        types = self.reference_types(a)
        value = " | ".join(["_builtins.str", *types])
        if len(types) < 2:
            return value
        for alias in self._targets.values():
            if alias.value == value:
                return alias.name
        name = self._target_name(a)
        self._targets[name] = Alias(name, value, "A reference: a name, or the element itself.")
        return name

    def _target_name(self, a: ir.AttributeDef) -> str:
        """``<type keywords>Target`` (``FrameobjTarget``) when the type attribute has keywords;
        ``AnyTarget`` when it is free text (any namespace)."""
        if a.namespace_from is None:
            return self.namespace_type(a.namespace or "") + "Target"
        row = next(e for e in self.schema.elements.values() if any(x is a for x in e.attributes))
        enum = row.attribute(a.namespace_from).enum
        name = "AnyTarget" if enum is None else self._keyword_names[enum] + "Target"
        taken = self.class_names() | set(self._keyword_names.values())
        while name in taken or name in self._targets:
            name += "Keyword"
        return name

    def target_aliases(self) -> list[Alias]:
        """The reference unions named so far (call after every annotation is made)."""
        return sorted(self._targets.values(), key=lambda a: a.name)

    def reference_types(self, a: ir.AttributeDef) -> list[str]:
        """The element types a reference may be given as."""
        if a.namespace is not None:
            return [self.namespace_type(a.namespace)] if a.namespace in self._namespace_classes else []
        return [self.namespace_type(ns) for ns in self.typed_reference_namespaces(a)]

    def typed_reference_namespaces(self, a: ir.AttributeDef) -> list[str]:
        """The namespaces a reference whose type attribute names it can refer to."""
        return sorted(set(self.typed_reference_map(a).values()))

    def typed_reference_map(self, a: ir.AttributeDef) -> dict[str, str]:
        """Type keyword -> namespace, for a reference whose namespace another attribute names:
        the type attribute's keywords, or every namespace when it is free text."""
        rows = [e for e in self.schema.elements.values() if any(x is a for x in e.attributes)]
        type_name = a.namespace_from
        assert type_name is not None and rows
        type_attribute = rows[0].attribute(type_name)
        language = self.schema.language
        renames = dict(language.type_namespaces) if language is not None else dict[str, str]()
        if type_attribute.enum is not None:
            words = self.schema.enums[type_attribute.enum].keywords
        else:
            words = [*self._namespace_classes, *renames]
        found = {word: renames.get(word, word) for word in words}
        return {word: ns for word, ns in sorted(found.items()) if ns in self._namespace_classes}

    def describe(self, a: ir.AttributeDef) -> str:
        """The MJCF type in words, for docstrings."""
        if a.kind in ("keyword", "flags"):
            words = ", ".join(self.schema.enums[a.enum or ""].keywords)
            if a.kind == "keyword":
                return f"one of: {words}"
            alone = f"; or alone one of: {', '.join(self._keywords_of(tuple(a.alone)))}" \
                if a.alone else ""
            return f"any of: {words}{alone}"
        if a.kind in ("id", "ref"):
            verb = "name declared in" if a.kind == "id" else "reference to"
            return f"{verb} namespace ``{a.namespace}``"
        if a.namespace_from is not None:
            return f"reference to the element ``{a.namespace_from}`` names"
        base = a.dtype if a.kind == "real" and a.dtype else a.kind
        if a.arity is None:
            return base
        lo, hi = a.arity
        if hi is None:
            return f"{base}[] (any length)" if lo == 0 else f"{base}[{lo}..] (at least {lo})"
        return f"{base}[{lo}]" if lo == hi else f"{base}[{lo}..{hi}] ({lo} to {hi} values)"
