"""The tables of ``mjcf.Physics``: which ``MjModel``/``MjData`` arrays belong to which kind of
element, read from the installed MuJoCo.

``mujoco.introspect`` gives every array of ``mjModel``/``mjData`` with its extent in the C
header (``body_pos: (nbody, 3)``); a compiled empty model gives the dtype and rank the Python
bindings expose. An array belongs to a kind when its first extent is the kind's count
(``njnt`` for joints, from the kind's ``name_jntadr``) or a size its elements own rows of
(``nq``, by ``jnt_qposadr``: ``schema/bindings.toml``, the few facts the headers say only in
words). ``python -m codegen generate`` writes the result to ``schema/bindings.json``; ``render``
turns it into ``generated/typed_mjcf_generated/bindings.py`` (the runtime table) and
``bindings.pyi`` (one binding class per kind, one property per array).
"""

from __future__ import annotations

import importlib
import json
import keyword
import operator
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import cast

from codegen import ir

FORMAT_VERSION = 1
FACTS_PATH = ir.SCHEMA_DIR / "bindings.toml"
BINDINGS_PATH = ir.SCHEMA_DIR / "bindings.json"
STRUCTS = ("MjModel", "MjData")


class BindingFactsError(ValueError):
    """schema/bindings.toml says something the generator cannot use."""


# ---------------------------------------------------------------------------- hand facts


@dataclass(frozen=True)
class Ragged:
    owner: str
    adr: str | None = None
    num: str | None = None
    index: str | None = None
    single: str | None = None  # "row": a single element owning one row is bound to it


@dataclass(frozen=True)
class Facts:
    abbreviations: dict[str, str]
    prefixes: dict[str, list[str]]
    ragged: dict[str, Ragged]
    columns: dict[str, list[str]]
    column_fields: dict[str, list[str]]
    data_inputs: list[str]
    model_cosmetic: list[str]
    clear_on_write: dict[str, list[str]]


def _table(raw: object, where: str) -> dict[str, object]:
    if not isinstance(raw, dict):
        raise BindingFactsError(f"{FACTS_PATH.name}: [{where}] must be a table")
    return cast(dict[str, object], raw)


def _strings(raw: object, where: str) -> list[str]:
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in cast(list[object], raw)):
        raise BindingFactsError(f"{FACTS_PATH.name}: {where} must be a list of strings")
    return cast(list[str], raw)


def _keys(table: dict[str, object], allowed: set[str], where: str) -> None:
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise BindingFactsError(f"{FACTS_PATH.name}: [{where}] has unknown keys {unknown}; "
                                f"expected {sorted(allowed)}")


def load_facts(path: Path = FACTS_PATH) -> Facts:
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    _keys(raw, {"abbreviations", "prefixes", "ragged", "columns", "column_fields", "dirty",
                "clear_on_write"}, "top level")
    abbreviations = {k: str(v) for k, v in _table(raw.get("abbreviations", {}),
                                                   "abbreviations").items()}
    prefixes = {k: _strings(v, f"prefixes.{k}")
                for k, v in _table(raw.get("prefixes", {}), "prefixes").items()}
    ragged: dict[str, Ragged] = {}
    for size, body in _table(raw.get("ragged", {}), "ragged").items():
        entry = _table(body, f"ragged.{size}")
        _keys(entry, {"owner", "adr", "num", "index", "single"}, f"ragged.{size}")
        values = {k: str(v) for k, v in entry.items()}
        if "owner" not in values or ("adr" in values) == ("index" in values):
            raise BindingFactsError(f"{FACTS_PATH.name}: [ragged.{size}] needs owner and one "
                                    "of adr or index")
        if values.get("single", "row") != "row":
            raise BindingFactsError(f"{FACTS_PATH.name}: [ragged.{size}] single must be "
                                    f"\"row\", got {values['single']!r}")
        ragged[size] = Ragged(**values)
    columns = {k: _strings(v, f"columns.{k}")
               for k, v in _table(raw.get("columns", {}), "columns").items()}
    column_fields = {k: _strings(v, f"column_fields.{k}")
                     for k, v in _table(raw.get("column_fields", {}), "column_fields").items()}
    if set(column_fields) - set(columns):
        raise BindingFactsError(f"{FACTS_PATH.name}: [column_fields] names columns "
                                f"{sorted(set(column_fields) - set(columns))} not in [columns]")
    dirty = _table(raw.get("dirty", {}), "dirty")
    _keys(dirty, {"data_inputs", "model_cosmetic"}, "dirty")
    clear = {k: _strings(v, f"clear_on_write.{k}")
             for k, v in _table(raw.get("clear_on_write", {}), "clear_on_write").items()}
    return Facts(abbreviations, prefixes, ragged, columns, column_fields,
                 _strings(dirty.get("data_inputs", []), "dirty.data_inputs"),
                 _strings(dirty.get("model_cosmetic", []), "dirty.model_cosmetic"), clear)


# ---------------------------------------------------------------------------- the wheel


def read_wheel(facts: Facts | None = None) -> dict[str, object]:
    """The bindings IR from the installed mujoco (and the hand facts), as JSON-ready data."""
    import mujoco

    # mujoco.introspect has no stubs: read as codegen/wheel.py reads it
    structs = cast(Mapping[str, object], importlib.import_module("mujoco.introspect.structs").STRUCTS)
    facts = load_facts() if facts is None else facts
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    data = mujoco.MjData(model)
    instances: dict[str, object] = {"MjModel": model, "MjData": data}
    fields: dict[str, dict[str, object]] = {}
    for struct, c_name in (("MjModel", "mjModel"), ("MjData", "mjData")):
        table: dict[str, object] = {}
        for field in cast(list[object], operator.attrgetter("fields")(structs[c_name])):
            extent = getattr(field, "array_extent", None)
            name = getattr(field, "name", "")
            if not extent:
                continue
            value = getattr(instances[struct], name, None)
            dtype = getattr(value, "dtype", None)
            ndim = getattr(value, "ndim", None)
            if dtype is None or dtype.fields is not None or not isinstance(ndim, int):
                continue  # text, or structs (contacts): no numeric array to bind
            table[name] = {"dims": [str(e) for e in extent][:ndim] if ndim else [],
                           "dtype": str(dtype), "doc": str(getattr(field, "doc", ""))}
        fields[struct] = dict(sorted(table.items()))
    model_fields = fields["MjModel"]
    objects: dict[str, dict[str, str]] = {}
    members = set(mujoco.mjtObj.__members__)
    for name, spec in model_fields.items():
        if not (name.startswith("name_") and name.endswith("adr")):
            continue
        prefix = name[len("name_"):-len("adr")]
        kind = facts.abbreviations.get(prefix, prefix)
        objtype = f"mjOBJ_{kind.upper()}"
        if objtype not in members:
            raise BindingFactsError(f"{name}: no mjtObj {objtype}; add the abbreviation "
                                    f"{prefix!r} to [abbreviations] of {FACTS_PATH.name}")
        size = cast(list[str], cast(dict[str, object], spec)["dims"])[0]
        plural = next((p for p in (kind + "s", kind + "es", kind[:-1] + "ies")
                       if isinstance(getattr(mujoco.MjSpec, p, None), property)), "")
        objects[kind] = {"size": size, "prefix": prefix, "objtype": objtype,
                         "spec_list": plural}
    _check_facts(facts, fields, {o["size"] for o in objects.values()})
    return {
        "format": FORMAT_VERSION,
        "mujoco_version": mujoco.__version__,
        "objects": dict(sorted(objects.items())),
        "ragged": {k: {a: v for a, v in vars(r).items() if v is not None}
                   for k, r in sorted(facts.ragged.items())},
        "prefixes": dict(sorted(facts.prefixes.items())),
        "columns": dict(sorted(facts.columns.items())),
        "column_fields": {k: sorted(v) for k, v in sorted(facts.column_fields.items())},
        "data_inputs": sorted(facts.data_inputs),
        "model_cosmetic": sorted(facts.model_cosmetic),
        "clear_on_write": dict(sorted(facts.clear_on_write.items())),
        "fields": fields,
    }


def _check_facts(facts: Facts, fields: dict[str, dict[str, object]], sizes: set[str]) -> None:
    """Every field and size the hand facts name exists in the installed MuJoCo."""
    every = {**fields["MjModel"], **fields["MjData"]}
    named: list[tuple[str, str]] = []
    for size, ragged in facts.ragged.items():
        if ragged.owner not in sizes:
            raise BindingFactsError(f"[ragged.{size}]: owner {ragged.owner!r} is not the count "
                                    "of a kind of MuJoCo object")
        named += [(f"ragged.{size}", f) for f in (ragged.adr, ragged.num, ragged.index) if f]
    named += [(f"column_fields.{k}", f) for k, v in facts.column_fields.items() for f in v]
    named += [("dirty.data_inputs", f) for f in facts.data_inputs]
    named += [("dirty.model_cosmetic", f) for f in facts.model_cosmetic]
    named += [(f"clear_on_write.{k}", f) for k, v in facts.clear_on_write.items()
              for f in [k, *v]]
    missing = [f"[{where}] {field}" for where, field in named if field not in every]
    if missing:
        raise BindingFactsError(f"{FACTS_PATH.name} names fields the installed MuJoCo does "
                                f"not have: {', '.join(missing)}")


def dumps(table: dict[str, object]) -> str:
    return json.dumps(table, indent=1, sort_keys=False) + "\n"


def load(path: Path = BINDINGS_PATH) -> dict[str, object]:
    raw = cast(dict[str, object], json.loads(path.read_text(encoding="utf-8")))
    if raw.get("format") != FORMAT_VERSION:
        raise ValueError(f"{path.name}: format {raw.get('format')!r}, expected {FORMAT_VERSION}")
    return raw


def dump(table: dict[str, object], path: Path = BINDINGS_PATH) -> bool:
    """Write the table; whether the file changed."""
    text = dumps(table)
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return False
    path.write_text(text, encoding="utf-8")
    return True


# ---------------------------------------------------------------------------- rendering

# numpy's scalar type of each dtype the bindings expose, as the typing surface names it
_SCALARS = {"bool": "_np.bool_", "float32": "_np.float32", "float64": "_np.float64",
            "int8": "_np.int8", "int32": "_np.int32", "int64": "_np.int64",
            "uint8": "_np.uint8", "uint64": "_np.uint64"}


@dataclass(frozen=True)
class AttributeView:
    name: str  # on the binding
    struct: str  # "MjModel" or "MjData"
    field: str
    scalar: str  # numpy scalar type
    doc: str


@dataclass(frozen=True)
class KindView:
    kind: str
    class_name: str
    objtype: str
    size: str
    spec_list: str  # MjSpec's list of these objects
    element_classes: list[str]
    attributes: list[AttributeView]


@dataclass(frozen=True)
class FieldView:
    struct: str
    field: str
    row: str  # the size naming its rows ("" when it has none)
    column: str  # a size or a column-names key naming its columns, or ""


def class_name(kind: str) -> str:
    return kind[:1].upper() + kind[1:] + "Binding"


def _kinds_of_elements(schema: ir.Schema) -> dict[str, list[str]]:
    """Each namespace -> the classes of its elements (the world body is a body)."""
    found: dict[str, list[str]] = {}
    for element in schema.elements.values():
        for attribute in element.attributes:
            if attribute.kind == "id" and attribute.namespace is not None:
                found.setdefault(attribute.namespace, []).append(element.class_name)
    body = schema.elements.get(schema.language.body) if schema.language else None
    root = schema.elements[schema.root]
    for child in root.children:
        row = schema.elements[child.element]
        if body is not None and any(c.element == body.name for c in row.children) \
                and not row.attributes:  # the world body: bodies, and no attribute of its own
            found.setdefault(body.tag, []).append(row.class_name)
    return {k: sorted(set(v)) for k, v in found.items()}


def _describe(struct: str, field: str, spec: dict[str, object]) -> str:
    dims = cast(list[str], spec["dims"])
    doc = str(spec.get("doc", "")).strip()
    shape = " x ".join(dims) if dims else "scalar"
    head = f"``{struct}.{field}`` ({shape})"
    return f"{head}: {doc}." if doc else f"{head}."


def kind_views(schema: ir.Schema, table: dict[str, object]) -> list[KindView]:
    """One view per kind of element MuJoCo compiles and the grammar names (joints, geoms,
    ...): its arrays by binding name, the kind's own fields before those of the sizes its
    elements own rows of (``jnt_solref`` is ``solref``; ``dof_solref`` keeps its name)."""
    objects = cast(dict[str, dict[str, str]], table["objects"])
    ragged = cast(dict[str, dict[str, str]], table["ragged"])
    prefixes = cast(dict[str, list[str]], table["prefixes"])
    fields = cast(dict[str, dict[str, dict[str, object]]], table["fields"])
    elements = _kinds_of_elements(schema)
    views: list[KindView] = []
    for kind, obj in sorted(objects.items()):
        if kind not in elements:
            continue  # MuJoCo's kind has no element in the grammar
        own = obj["size"]
        sizes = [own, *sorted(s for s, r in ragged.items() if r["owner"] == own)]
        strip = [obj["prefix"], *prefixes.get(kind, [])]
        chosen: dict[str, AttributeView] = {}
        for size in sizes:
            for struct in STRUCTS:
                for field, spec in fields[struct].items():
                    dims = cast(list[str], spec["dims"])
                    if not dims or dims[0] != size:
                        continue
                    name = next((field[len(p) + 1:] for p in strip
                                 if field.startswith(p + "_")), field)
                    if keyword.iskeyword(name):
                        name += "_"  # as the grammar's names: flex_yield is `yield_`
                    if name in chosen:
                        name = field  # a later size's field: its full name
                    if name in chosen or not name.isidentifier():
                        raise ValueError(f"{kind}: two arrays bind as {name!r}: "
                                         f"{chosen[name].field} and {field}")
                    chosen[name] = AttributeView(name, struct, field,
                                                 _SCALARS[str(spec["dtype"])],
                                                 _describe(struct, field, spec))
        views.append(KindView(kind, class_name(kind), obj["objtype"], own, obj["spec_list"],
                              elements[kind],
                              sorted(chosen.values(), key=lambda a: a.name)))
    return views


def field_views(table: dict[str, object]) -> list[FieldView]:
    """Every array of MjModel and MjData with the sizes naming its rows and columns."""
    fields = cast(dict[str, dict[str, dict[str, object]]], table["fields"])
    column_fields = cast(dict[str, list[str]], table["column_fields"])
    named_sizes = {o["size"] for o in cast(dict[str, dict[str, str]], table["objects"]).values()}
    named_sizes |= set(cast(dict[str, object], table["ragged"]))
    columns_of = {field: key for key, names in column_fields.items() for field in names}
    views: list[FieldView] = []
    for struct in STRUCTS:
        for field, spec in fields[struct].items():
            dims = cast(list[str], spec["dims"])
            row = dims[0] if dims and dims[0] in named_sizes else ""
            column = ""
            if len(dims) > 1:
                column = columns_of.get(field, dims[1] if dims[1] in named_sizes else "")
            views.append(FieldView(struct, field, row, column))
    return views


@dataclass(frozen=True)
class NamedView:
    field: str
    scalar: str


def _named(table: dict[str, object], struct: str) -> list[NamedView]:
    fields = cast(dict[str, dict[str, dict[str, object]]], table["fields"])
    indexed = {f.field for f in field_views(table) if f.struct == struct and (f.row or f.column)}
    return [NamedView(name, _SCALARS[str(spec["dtype"])])
            for name, spec in fields[struct].items() if name in indexed]


def render_context(schema: ir.Schema, table: dict[str, object]) -> dict[str, object]:
    """What the bindings templates lay out."""
    kinds = kind_views(schema, table)
    objects = cast(dict[str, dict[str, str]], table["objects"])
    return {
        "objects": {o["size"]: o["objtype"] for o in objects.values()},
        "named_model": _named(table, "MjModel"),
        "named_data": _named(table, "MjData"),
        "element_imports": sorted({c for k in kinds for c in k.element_classes}),
        "binding_version": table["mujoco_version"],
        "kinds": kinds,
        "fields": [f for f in field_views(table) if f.row or f.column],
        "ragged": cast(dict[str, dict[str, str]], table["ragged"]),
        "columns": cast(dict[str, list[str]], table["columns"]),
        "data_inputs": cast(list[str], table["data_inputs"]),
        "model_cosmetic": cast(list[str], table["model_cosmetic"]),
        "clear_on_write": cast(dict[str, list[str]], table["clear_on_write"]),
        "binding_exported": sorted([k.class_name for k in kinds]),
    }
