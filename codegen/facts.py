"""Hand-kept facts about MJCF (``schema/facts.toml``) as typed values.

This module owns every table of the file and checks it strictly: an unknown table, an unknown
key in an ``[[enum]]`` or ``[[attribute]]`` entry or a value of the wrong type raises
FactsError naming the file, the table and the key. The passes read the typed fields only.
"""

from __future__ import annotations

import dataclasses
import re
import tomllib
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Literal, TypeVar, cast

from codegen import ir
from codegen.errors import FactsError
from codegen.language import GrammarFacts, read_table

__all__ = ["FactsError"]  # raised here, and by the passes applying the facts

FACTS_PATH = Path(__file__).resolve().parent.parent / "schema" / "facts.toml"

Compose = Literal["attributes", "nest", "keyframes"]
_COMPOSE: dict[str, Compose] = {"attributes": "attributes", "nest": "nest",
                                "keyframes": "keyframes"}
_DTYPES: dict[str, ir.DType] = {"double": "double", "float": "float", "int": "int"}
_KINDS: dict[str, ir.AttrKind] = {k: k for k in ir.ATTR_KINDS}
_T = TypeVar("_T")
# The top-level tables of facts.toml, in the file's order.
TABLES = ("root_children", "single", "enum", "attribute", "constraint", "directories",
          "class_names", "compose", "attachment_sites", "default_rows", "language")
_CONSTRAINT_KINDS: dict[str, ir.ConstraintKind] = {
    "exclusive": "exclusive", "together": "together", "requires": "requires", "oneof": "oneof"}


@dataclasses.dataclass(frozen=True)
class AttributeOverride:
    """One ``[[attribute]]`` entry: fields of ``element@name`` set by hand (None: unchanged).

    It applies to an attribute the grammar file declares and to one the installed wheel adds
    (for which ``kind`` gives the whole type, as nothing else may know it)."""

    element: str  # declaration name of the row
    name: str  # XML name of the attribute
    kind: ir.AttrKind | None = None
    dtype: ir.DType | None = None
    arity: tuple[int, int | None] | None = None
    enum: str | None = None
    alone: tuple[str, ...] | None = None  # flags: enums whose keywords it also takes alone
    ordered: bool | None = None  # flags: MuJoCo reads them only in the enum's order
    namespace: str | None = None
    default: str | None = None
    required: bool | None = None
    nodefault: bool | None = None
    pattern: str | None = None
    field: str | None = None
    doc: str | None = None
    bounds: tuple[str, ...] | None = None  # numbers: "> 0", ">= -1", "<= 5" (each value)
    off: tuple[str, ...] | None = None  # numbers: values that count as not set ("<= 0")
    reason: str = ""  # why the entry exists (required in facts.toml); documentation only


@dataclasses.dataclass(frozen=True)
class EnumFact:
    """One ``[[enum]]`` entry: the keywords of an enum, set by hand (it is added to the schema,
    or replaces the keywords the sources give; ``ctype`` and ``doc``, None: unchanged)."""

    name: str
    values: tuple[tuple[str, str], ...]  # (keyword, C constant or integer text), in order
    ctype: str | None = None
    doc: str | None = None
    reason: str = ""  # why the entry exists (required in facts.toml); documentation only


@dataclasses.dataclass(frozen=True)
class ConstraintFact:
    """One ``[[constraint]]`` entry: a presence constraint over a row's attributes that the
    grammar file does not state (added to the row's own)."""

    element: str  # declaration name of the row
    kind: ir.ConstraintKind
    bundles: tuple[tuple[str, ...], ...]  # attribute names, each bundle complete together
    reason: str = ""  # why the entry exists (required in facts.toml); documentation only


@dataclasses.dataclass(frozen=True)
class Facts:
    """The tables of ``schema/facts.toml``; see the comments there for what each means."""

    # root child -> the row standing for it at the root (``body`` -> ``worldbody``)
    root_children: dict[str, str] = dataclasses.field(default_factory=dict[str, str])
    # parent row -> child tags exposed as properties created on first use
    single: dict[str, list[str]] = dataclasses.field(default_factory=dict[str, list[str]])
    enums: list[EnumFact] = dataclasses.field(default_factory=list[EnumFact])
    attributes: list[AttributeOverride] = dataclasses.field(
        default_factory=list[AttributeOverride])
    constraints: list[ConstraintFact] = dataclasses.field(default_factory=list[ConstraintFact])
    # (row, file attribute) -> the <compiler> attributes naming its folder, in order
    directories: dict[tuple[str, str], list[str]] = dataclasses.field(
        default_factory=dict[tuple[str, str], list[str]])
    # row -> Python class name, where the declaration name would clash with the runtime
    class_names: dict[str, str] = dataclasses.field(default_factory=dict[str, str])
    # top-level section tag -> how an attached model's section joins the parent's
    compose: dict[str, Compose] = dataclasses.field(default_factory=dict[str, Compose])
    # row -> why a model can be attached beside it
    attachment_sites: dict[str, str] = dataclasses.field(default_factory=dict[str, str])
    # default-class row -> the element rows taking their defaults from it
    default_rows: dict[str, list[str]] = dataclasses.field(
        default_factory=dict[str, list[str]])
    # facts about the language as a whole (typed_mjcf._core.language declares them); None: the
    # file has no [language] table (small test files)
    language: GrammarFacts | None = None


def load_facts(path: Path | None = None) -> Facts:
    """Read ``schema/facts.toml`` (``FACTS_PATH``, read when called) or another facts file."""
    path = FACTS_PATH if path is None else path
    return parse_facts(path.read_text(encoding="utf-8"), str(path))


def parse_facts(text: str, path: str = "<string>") -> Facts:
    """Parse facts TOML text; malformed content raises FactsError naming ``path``."""
    try:
        raw: dict[str, object] = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise FactsError(f"{path}: {exc}") from None
    unknown = sorted(set(raw) - set(TABLES))
    if unknown:
        raise FactsError(f"{path}: unknown table {unknown[0]!r} (known tables: "
                         f"{', '.join(TABLES)})")

    def read(table: str, parse: Callable[[object, str], _T], empty: _T) -> _T:
        return parse(raw[table], f"{path}: {_header(table)}") if table in raw else empty

    return Facts(
        root_children=read("root_children", _strings, {}),
        single=read("single", _string_lists, {}),
        enums=read("enum", _enums, []),
        attributes=read("attribute", _overrides, []),
        constraints=read("constraint", _constraints, []),
        directories=read("directories", _directories, {}),
        class_names=read("class_names", _strings, {}),
        compose=read("compose", _compose, {}),
        attachment_sites=read("attachment_sites", _strings, {}),
        default_rows=read("default_rows", _string_lists, {}),
        language=(read_table(GrammarFacts, raw["language"], f"{path}: [language]")
                  if "language" in raw else None),
    )


# ------------------------------------------------------------------------------- tables


def _header(table: str) -> str:
    return f"[[{table}]]" if table in ("enum", "attribute", "constraint") else f"[{table}]"


def _strings(value: object, where: str) -> dict[str, str]:
    return {k: _str(v, f"{where} {k}") for k, v in _table(value, where).items()}


def _string_lists(value: object, where: str) -> dict[str, list[str]]:
    return {k: _str_list(v, f"{where} {k}") for k, v in _table(value, where).items()}


def _compose(value: object, where: str) -> dict[str, Compose]:
    return {k: _choice(v, _COMPOSE, f"{where} {k}") for k, v in _table(value, where).items()}


def _directories(value: object, where: str) -> dict[tuple[str, str], list[str]]:
    out: dict[tuple[str, str], list[str]] = {}
    for key, folders in _table(value, where).items():
        row, at, attribute = key.partition("@")
        if not (row and at and attribute):
            raise FactsError(f"{where} {key}: expected a key \"row@attribute\"")
        out[(row, attribute)] = _str_list(folders, f"{where} {key}")
    return out


def _overrides(value: object, where: str) -> list[AttributeOverride]:
    if not isinstance(value, list):
        raise FactsError(f"{where}: expected an array of tables ([[attribute]] entries)")
    entries: list[AttributeOverride] = []
    for i, raw in enumerate(cast(list[object], value)):
        entry = _override(raw, f"{where} #{i + 1}")
        if any((e.element, e.name) == (entry.element, entry.name) for e in entries):
            raise FactsError(f"{where} #{i + 1}: a second entry for "
                             f"{entry.element}@{entry.name}")
        entries.append(entry)
    return entries

_CONSTRAINT_KEYS = frozenset(f.name for f in dataclasses.fields(ConstraintFact))


def _constraints(value: object, where: str) -> list[ConstraintFact]:
    if not isinstance(value, list):
        raise FactsError(f"{where}: expected an array of tables ([[constraint]] entries)")
    entries: list[ConstraintFact] = []
    for i, raw in enumerate(cast(list[object], value)):
        at = f"{where} #{i + 1}"
        entry = _keyed_table(raw, at, _CONSTRAINT_KEYS, ("element", "kind", "bundles", "reason"))
        bundles = tuple(tuple(_str_list(b, f"{at} bundles")) for b in
                        (cast(list[object], entry["bundles"])
                         if isinstance(entry["bundles"], list) else [None]))
        if len(bundles) < 2 or not all(bundles):
            raise FactsError(f"{at} bundles: expected two or more non-empty lists of attribute "
                             f"names, got {entry['bundles']!r}")
        rows = entry["element"]  # one row, or a list of rows the same rule holds on
        kind = _choice(entry["kind"], _CONSTRAINT_KINDS, f"{at} kind")
        reason = _str(entry["reason"], f"{at} reason")
        entries += [ConstraintFact(element=row, kind=kind, bundles=bundles, reason=reason)
                    for row in (_str_list(rows, f"{at} element") if not isinstance(rows, str)
                                else [rows])]
    return entries


_ENUM_KEYS = frozenset(f.name for f in dataclasses.fields(EnumFact))


def _enums(value: object, where: str) -> list[EnumFact]:
    if not isinstance(value, list):
        raise FactsError(f"{where}: expected an array of tables ([[enum]] entries)")
    entries: list[EnumFact] = []
    for i, raw in enumerate(cast(list[object], value)):
        entry = _enum(raw, f"{where} #{i + 1}")
        if any(e.name == entry.name for e in entries):
            raise FactsError(f"{where} #{i + 1}: a second entry for enum {entry.name!r}")
        entries.append(entry)
    return entries


def _enum(value: object, where: str) -> EnumFact:
    entry = _keyed_table(value, where, _ENUM_KEYS, ("name", "values", "reason"))
    return EnumFact(
        name=_str(entry["name"], f"{where} name"),
        values=_enum_values(entry["values"], f"{where} values"),
        ctype=_str(entry["ctype"], f"{where} ctype") if "ctype" in entry else None,
        doc=_str(entry["doc"], f"{where} doc") if "doc" in entry else None,
        reason=_str(entry["reason"], f"{where} reason"),
    )


def _enum_values(value: object, where: str) -> tuple[tuple[str, str], ...]:
    """A non-empty list of ``[keyword, C constant]`` pairs of non-empty strings, each keyword
    once."""
    values: list[tuple[str, str]] = []
    for item in cast(list[object], value) if isinstance(value, list) else []:
        pair = cast(list[object], item) if isinstance(item, list) else []
        if len(pair) != 2 or not all(isinstance(x, str) and x for x in pair):
            values = []
            break
        values.append((cast(str, pair[0]), cast(str, pair[1])))
    if not values:
        raise FactsError(f"{where}: expected a non-empty list of [keyword, C constant] string "
                         f"pairs, got {value!r}")
    keywords = [k for k, _ in values]
    if len(set(keywords)) != len(keywords):
        raise FactsError(f"{where}: a keyword is listed twice in {keywords!r}")
    return tuple(values)


# ------------------------------------------------------------------------------- values


def _table(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise FactsError(f"{where}: expected a table")
    return {str(k): v for k, v in cast(dict[object, object], value).items()}


def _keyed_table(value: object, where: str, allowed: frozenset[str],
                 required: Iterable[str]) -> dict[str, object]:
    """A table with only ``allowed`` keys and every ``required`` one (the first offender in
    sorted order is named)."""
    table = _table(value, where)
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise FactsError(f"{where}: unknown key {unknown[0]!r}")
    missing = [key for key in required if key not in table]
    if missing:
        raise FactsError(f"{where}: missing key {missing[0]!r}")
    return table


def _str(value: object, where: str) -> str:
    if not isinstance(value, str):
        raise FactsError(f"{where}: expected a string, got {value!r}")
    return value


def _str_list(value: object, where: str) -> list[str]:
    if not isinstance(value, list):
        raise FactsError(f"{where}: expected a list of strings")
    return [_str(v, where) for v in cast(list[object], value)]


def _bool(value: object, where: str) -> bool:
    if not isinstance(value, bool):
        raise FactsError(f"{where}: expected true or false, got {value!r}")
    return value


def _choice(value: object, choices: Mapping[str, _T], where: str) -> _T:
    text = _str(value, where)
    if text not in choices:
        raise FactsError(f"{where}: {text!r} is not one of {', '.join(choices)}")
    return choices[text]


def _arity(value: object, where: str) -> tuple[int, int | None]:
    """``[lo, hi]``, or ``[lo]`` for lo or more values (TOML has no null for "unbounded")."""
    items = cast(list[object], value) if isinstance(value, list) else []
    if not 1 <= len(items) <= 2 or not all(type(v) is int for v in items):
        raise FactsError(f"{where}: expected [lo, hi] or [lo] integers, got {value!r}")
    bounds = cast(list[int], items)
    return (bounds[0], bounds[1] if len(bounds) == 2 else None)


def _alone(value: object, where: str) -> tuple[str, ...]:
    """A non-empty list of distinct enum names."""
    names = _str_list(value, where)
    if not names or len(set(names)) != len(names):
        raise FactsError(f"{where}: expected a non-empty list of distinct enum names, "
                         f"got {value!r}")
    return tuple(names)


BOUND = re.compile(r"(>=|<=|>|<) (-?[0-9]+(?:\.[0-9]+)?)")


def _bounds(value: object, where: str) -> tuple[str, ...]:
    """A non-empty list of bounds each value must keep, like ``"> 0"`` or ``"<= 5"``."""
    bounds = _str_list(value, where) if not isinstance(value, str) else []
    if not bounds or not all(BOUND.fullmatch(b) for b in bounds):
        raise FactsError(f'{where}: expected a list of bounds like "> 0", ">= -1", "<= 5", '
                         f"got {value!r}")
    return tuple(bounds)


_OVERRIDE_KEYS = frozenset(f.name for f in dataclasses.fields(AttributeOverride))


def attribute_entry(value: object, where: str) -> AttributeOverride:
    """One ``[[attribute]]`` entry, as facts.toml holds them (schema/releases/facts.toml
    holds them too, per release: codegen/releases.py)."""
    return _override(value, where)


def _override(value: object, where: str) -> AttributeOverride:
    entry = _keyed_table(value, where, _OVERRIDE_KEYS, ("element", "name", "reason"))

    def opt_str(key: str) -> str | None:
        return _str(entry[key], f"{where} {key}") if key in entry else None

    def opt_bool(key: str) -> bool | None:
        return _bool(entry[key], f"{where} {key}") if key in entry else None

    return AttributeOverride(
        element=_str(entry["element"], f"{where} element"),
        name=_str(entry["name"], f"{where} name"),
        kind=_choice(entry["kind"], _KINDS, f"{where} kind") if "kind" in entry else None,
        dtype=_choice(entry["dtype"], _DTYPES, f"{where} dtype") if "dtype" in entry else None,
        arity=_arity(entry["arity"], f"{where} arity") if "arity" in entry else None,
        enum=opt_str("enum"), namespace=opt_str("namespace"), default=opt_str("default"),
        alone=_alone(entry["alone"], f"{where} alone") if "alone" in entry else None,
        ordered=opt_bool("ordered"),
        required=opt_bool("required"), nodefault=opt_bool("nodefault"),
        pattern=opt_str("pattern"), field=opt_str("field"), doc=opt_str("doc"),
        bounds=_bounds(entry["bounds"], f"{where} bounds") if "bounds" in entry else None,
        off=_bounds(entry["off"], f"{where} off") if "off" in entry else None,
        reason=_str(entry["reason"], f"{where} reason"),
    )
