"""The typed intermediate representation of the MJCF grammar (the contents of ``schema/``).

Everything the renderer knows about MJCF comes from here. The IR is explicit: default-class
projections, Python names and API cardinalities are spelled out, so the renderer has no
grammar rules of its own.
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal, cast

from codegen.errors import FactsError
from codegen.language import GrammarFacts, read_table, to_plain

FORMAT_VERSION = 3
# 1 lacks the language facts, 2 the flags' ``alone`` and ``ordered``: the next generate adds them
READABLE_FORMATS = (1, 2, 3)

AttrKind = Literal[
    "string",  # free text
    "file",  # a path, resolved against asset dirs / the VFS
    "chars",  # a fixed-alphabet character string (``chars[3]``), arity counts characters
    "bool",  # "true" / "false"
    "int",  # integer number(s)
    "real",  # floating-point number(s); ``dtype`` says double or float
    "keyword",  # one keyword of ``enum``
    "flags",  # several keywords of ``enum``, space separated
    "id",  # declares the element's name into ``namespace``
    "ref",  # names an object of ``namespace``
]
ATTR_KINDS: tuple[AttrKind, ...] = (
    "string", "file", "chars", "bool", "int", "real", "keyword", "flags", "id", "ref",
)
DType = Literal["double", "float", "int"]
Cardinality = Literal["?", "!", "*", "R"]
ConstraintKind = Literal["exclusive", "together", "requires", "oneof"]


@dataclass
class EnumDef:
    """A keyword set. ``values`` pairs each keyword with its C constant (or integer text)."""

    name: str
    values: list[tuple[str, str]]
    ctype: str | None = None  # e.g. "mjtJoint" when bound to a MuJoCo C enum
    doc: str = ""

    @property
    def keywords(self) -> list[str]:
        return [k for k, _ in self.values]


@dataclass
class AttributeDef:
    name: str  # XML name
    py_name: str  # Python identifier (``class`` -> ``class_``)
    kind: AttrKind
    dtype: DType | None = None  # numbers only
    arity: tuple[int, int | None] | None = None  # None: scalar; (n, n): fixed; (lo, hi|None)
    enum: str | None = None  # keyword / flags
    # flags only: enums whose keywords the attribute also takes, each alone in place of flags
    # (``input``: "pos ff", or just "expmap"); their keywords are distinct from ``enum``'s
    alone: list[str] | None = None
    ordered: bool = False  # flags only: MuJoCo reads them only in ``enum``'s order
    namespace: str | None = None  # id / ref
    namespace_from: str | None = None  # a reference whose namespace this attribute's keyword names
    default: str | None = None  # MJCF text of the default value, e.g. "0 0 1"
    required: bool = False
    nodefault: bool = False  # not settable in <default> classes
    pattern: str | None = None  # regex a string value must match
    field: str | None = None  # bound mjs struct field, when it differs from the name
    directory: list[str] | None = None  # files: <compiler> attributes naming their folder, in order
    doc: str = ""  # one-line description
    anchor: str | None = None  # XMLreference.rst anchor, e.g. "body-joint-type"
    # numbers: bounds every value keeps, e.g. ["> 0"] (MuJoCo refuses others; facts.toml)
    bounds: list[str] | None = None
    # keywords: the integer MuJoCo's reader also takes for a keyword, read as an int attribute
    # is (headlight@active="1" is "true" in 4.0.0); probed by codegen.drift, never by hand
    numbers: dict[str, int] | None = None
    # no default: why MuJoCo computes the value when the attribute is absent (codegen.drift
    # found no written value that MuJoCo reads as the attribute left out)
    computed: str | None = None
    # numbers: a value that keeps all of these counts as not set in presence constraints
    # (inheritrange="0" is off; facts.toml)
    off: list[str] | None = None


@dataclass
class ChildDef:
    element: str  # declaration name of the child row
    card: Cardinality  # the grammar's cardinality
    single: bool  # API: a property created on first use (repeats are merged when parsing)


@dataclass
class ConstraintDef:
    kind: ConstraintKind
    bundles: list[list[str]]  # each bundle is a set of attribute names appearing together


@dataclass
class ElementDef:
    name: str  # declaration name, unique (e.g. "equality_joint")
    tag: str  # XML tag (e.g. "joint")
    class_name: str  # Python class (e.g. "EqualityJoint")
    attributes: list[AttributeDef] = field(default_factory=lambda: [])
    children: list[ChildDef] = field(default_factory=lambda: [])
    constraints: list[ConstraintDef] = field(default_factory=lambda: [])
    struct: str | None = None  # bound mjs struct, e.g. "mjsJoint"
    alias: str | None = None  # validated against this row's grammar (worldbody, frame, ...)
    projection_of: str | None = None  # default-context rows: the primary declaration
    anchor: str | None = None  # XMLreference.rst anchor of the element
    doc: str = ""
    compose: str | None = None  # top-level sections: how an attached model's section joins
    attachable: bool = False  # a model can be attached here (a body-holder, or a posed element in one)
    default_row: str | None = None  # the <default> child row holding this element's defaults
    # MuJoCo's reader ignores attributes it does not know here (no schema check: found by
    # codegen.probe on the rows printSchema omits)
    ignores_unknown: bool = False

    def attribute(self, name: str) -> AttributeDef:
        for a in self.attributes:
            if a.name == name:
                return a
        raise KeyError(f"{self.name} has no attribute {name!r}")


@dataclass
class Schema:
    mujoco_version: str
    root: str
    enums: dict[str, EnumDef]
    elements: dict[str, ElementDef]
    # the [language] facts (None: a grammar not normalized with facts.toml yet, or a stored
    # table GrammarFacts no longer declares: why, in stale_language; a sync re-reads them)
    language: GrammarFacts | None = None
    stale_language: str = ""

    def facts(self) -> GrammarFacts:
        """The language facts, which rendering needs (a normalized schema has them)."""
        if self.language is None:
            why = f" ({self.stale_language})" if self.stale_language else ""
            raise FactsError(f"schema/mjcf.json has no language facts{why}; run "
                             "`nox -s generate`")
        return self.language

    def parents_of(self, name: str) -> list[str]:
        return sorted(e.name for e in self.elements.values()
                      if any(c.element == name for c in e.children))


# --------------------------------------------------------------------------- serialisation
# Deterministic text: enums and elements sorted by name; attributes, children and
# constraints keep grammar order (it is semantic: it sets the export order); one attribute
# per line so a diff reads as a list of changed attributes.


def _compact(obj: object) -> str:
    return json.dumps(obj, ensure_ascii=False, separators=(", ", ": "))


def _attr_to_json(a: AttributeDef) -> dict[str, object]:
    d: dict[str, object] = {"name": a.name}
    if a.py_name != a.name:
        d["py_name"] = a.py_name
    d["kind"] = a.kind
    for key in ("dtype", "arity", "enum", "alone", "namespace", "namespace_from", "default",
                "pattern", "field", "directory", "anchor", "bounds", "off", "numbers",
                "computed"):
        value: object = getattr(a, key)
        if isinstance(value, tuple):
            value = list(cast(tuple[object, ...], value))
        if value is not None:
            d[key] = value
        if key == "alone" and a.ordered:
            d["ordered"] = True
    if a.required:
        d["required"] = True
    if a.nodefault:
        d["nodefault"] = True
    if a.doc:
        d["doc"] = a.doc
    return d


def dumps(schema: Schema) -> str:
    lines: list[str] = ["{"]
    lines.append(f'  "format": {FORMAT_VERSION},')
    lines.append(f'  "mujoco_version": {_compact(schema.mujoco_version)},')
    lines.append(f'  "root": {_compact(schema.root)},')
    lines.append(f'  "language": {_compact(_language_to_json(schema.language))},')
    lines.append('  "enums": {')
    enum_items = sorted(schema.enums.items())
    for i, (name, e) in enumerate(enum_items):
        body: dict[str, object] = {"values": [list(v) for v in e.values]}
        if e.ctype:
            body["ctype"] = e.ctype
        if e.doc:
            body["doc"] = e.doc
        comma = "," if i < len(enum_items) - 1 else ""
        lines.append(f"    {_compact(name)}: {_compact(body)}{comma}")
    lines.append("  },")
    lines.append('  "elements": {')
    elem_items = sorted(schema.elements.items())
    for i, (name, el) in enumerate(elem_items):
        lines.append(f"    {_compact(name)}: {{")
        head: dict[str, object] = {"tag": el.tag, "class_name": el.class_name}
        for key in ("struct", "alias", "projection_of", "anchor", "compose", "default_row"):
            value = getattr(el, key)
            if value is not None:
                head[key] = value
        if el.attachable:
            head["attachable"] = True
        if el.ignores_unknown:
            head["ignores_unknown"] = True
        if el.doc:
            head["doc"] = el.doc
        for key, value in head.items():
            lines.append(f"      {_compact(key)}: {_compact(value)},")
        lines.append('      "attributes": [')
        for j, a in enumerate(el.attributes):
            comma = "," if j < len(el.attributes) - 1 else ""
            lines.append(f"        {_compact(_attr_to_json(a))}{comma}")
        lines.append("      ],")
        lines.append('      "children": [')
        for j, c in enumerate(el.children):
            comma = "," if j < len(el.children) - 1 else ""
            lines.append(f"        {_compact([c.element, c.card, 'single' if c.single else 'list'])}{comma}")
        lines.append("      ],")
        lines.append('      "constraints": [')
        for j, k in enumerate(el.constraints):
            comma = "," if j < len(el.constraints) - 1 else ""
            lines.append(f"        {_compact([k.kind, k.bundles])}{comma}")
        lines.append("      ]")
        comma = "," if i < len(elem_items) - 1 else ""
        lines.append(f"    }}{comma}")
    lines.append("  }")
    lines.append("}")
    return "\n".join(lines) + "\n"


def _language_to_json(language: GrammarFacts | None) -> object:
    return None if language is None else to_plain(language)


def _language_from_json(raw: object, root: str) -> tuple[GrammarFacts | None, str]:
    """The stored facts, or None and why when GrammarFacts declares others now (a fact was
    added: ``generate`` reads it from facts.toml)."""
    if raw is None:
        return None, ""
    try:
        facts = read_table(GrammarFacts, raw, "language")
    except FactsError as error:
        return None, str(error)
    return dataclasses.replace(facts, root=root), ""


def _attr_from_json(d: dict[str, object]) -> AttributeDef:
    arity = d.get("arity")
    arity_t: tuple[int, int | None] | None = None
    if arity is not None:
        lo, hi = cast(list[int | None], arity)
        assert lo is not None
        arity_t = (lo, hi)
    name = cast(str, d["name"])
    return AttributeDef(
        name=name,
        py_name=cast(str, d.get("py_name", name)),
        kind=cast(AttrKind, d["kind"]),
        dtype=cast("DType | None", d.get("dtype")),
        arity=arity_t,
        enum=cast("str | None", d.get("enum")),
        alone=cast("list[str] | None", d.get("alone")),
        ordered=bool(d.get("ordered", False)),
        namespace=cast("str | None", d.get("namespace")),
        namespace_from=cast("str | None", d.get("namespace_from")),
        default=cast("str | None", d.get("default")),
        required=bool(d.get("required", False)),
        nodefault=bool(d.get("nodefault", False)),
        pattern=cast("str | None", d.get("pattern")),
        field=cast("str | None", d.get("field")),
        directory=cast("list[str] | None", d.get("directory")),
        doc=cast(str, d.get("doc", "")),
        anchor=cast("str | None", d.get("anchor")),
        bounds=cast("list[str] | None", d.get("bounds")),
        numbers=cast("dict[str, int] | None", d.get("numbers")),
        computed=cast("str | None", d.get("computed")),
        off=cast("list[str] | None", d.get("off")),
    )


def loads(text: str) -> Schema:
    raw = cast(dict[str, object], json.loads(text))
    if raw.get("format") not in READABLE_FORMATS:
        raise ValueError(f"schema format {raw.get('format')!r}, expected {FORMAT_VERSION}")
    enums: dict[str, EnumDef] = {}
    for name, body in cast(dict[str, dict[str, object]], raw["enums"]).items():
        values = [(k, v) for k, v in cast(list[list[str]], body["values"])]
        enums[name] = EnumDef(name, values, cast("str | None", body.get("ctype")),
                              cast(str, body.get("doc", "")))
    elements: dict[str, ElementDef] = {}
    for name, body in cast(dict[str, dict[str, object]], raw["elements"]).items():
        elements[name] = ElementDef(
            name=name,
            tag=cast(str, body["tag"]),
            class_name=cast(str, body["class_name"]),
            attributes=[_attr_from_json(a) for a in cast(list[dict[str, object]], body["attributes"])],
            children=[ChildDef(c[0], cast(Cardinality, c[1]), c[2] == "single")
                      for c in cast(list[list[str]], body["children"])],
            constraints=[ConstraintDef(cast(ConstraintKind, k[0]), cast(list[list[str]], k[1]))
                         for k in cast(list[list[object]], body["constraints"])],
            struct=cast("str | None", body.get("struct")),
            alias=cast("str | None", body.get("alias")),
            projection_of=cast("str | None", body.get("projection_of")),
            anchor=cast("str | None", body.get("anchor")),
            doc=cast(str, body.get("doc", "")),
            compose=cast("str | None", body.get("compose")),
            default_row=cast("str | None", body.get("default_row")),
            attachable=bool(body.get("attachable", False)),
            ignores_unknown=bool(body.get("ignores_unknown", False)),
        )
    root = cast(str, raw["root"])
    language, stale = _language_from_json(raw.get("language"), root)
    return Schema(cast(str, raw["mujoco_version"]), root, enums, elements, language, stale)


SCHEMA_DIR = Path(__file__).resolve().parent.parent / "schema"
SCHEMA_PATH = SCHEMA_DIR / "mjcf.json"


def load(path: Path = SCHEMA_PATH) -> Schema:
    return loads(path.read_text(encoding="utf-8"))


def dump(schema: Schema, path: Path = SCHEMA_PATH) -> None:
    path.write_text(dumps(schema), encoding="utf-8")
