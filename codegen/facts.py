"""Hand-kept facts about MJCF (``schema/facts.toml``) as typed values.

The tables this module knows are checked strictly (a typo in a key is an error, not a silent
no-op). Top-level tables it does not know are kept uninterpreted in ``Facts.extra`` so other
passes can add their own tables without touching this loader.
"""

from __future__ import annotations

import dataclasses
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import TypeVar, cast

from codegen import ir

FACTS_PATH = Path(__file__).resolve().parent.parent / "schema" / "facts.toml"

_KNOWN_TABLES = ("root_children", "single", "attribute")
_DTYPES: dict[str, ir.DType] = {"double": "double", "float": "float", "int": "int"}
_KINDS: dict[str, ir.AttrKind] = {k: k for k in ir.ATTR_KINDS}
_T = TypeVar("_T")


class FactsError(ValueError):
    """Malformed facts; the message starts with the file path."""


@dataclasses.dataclass(frozen=True)
class AttributeOverride:
    """One ``[[attribute]]`` entry: fields of ``element@name`` set by hand (None: unchanged)."""

    element: str  # declaration name of the row
    name: str  # XML name of the attribute
    kind: ir.AttrKind | None = None
    dtype: ir.DType | None = None
    arity: tuple[int, int | None] | None = None
    enum: str | None = None
    namespace: str | None = None
    default: str | None = None
    required: bool | None = None
    nodefault: bool | None = None
    pattern: str | None = None
    field: str | None = None
    doc: str | None = None
    reason: str = ""  # why the entry exists; documentation only


@dataclasses.dataclass(frozen=True)
class Facts:
    root_children: dict[str, str] = dataclasses.field(default_factory=dict[str, str])
    single: dict[str, list[str]] = dataclasses.field(default_factory=dict[str, list[str]])
    attributes: list[AttributeOverride] = dataclasses.field(
        default_factory=list[AttributeOverride])
    # top-level tables this loader does not interpret, as tomllib read them
    extra: dict[str, object] = dataclasses.field(default_factory=dict[str, object])


def load_facts(path: Path = FACTS_PATH) -> Facts:
    """Read ``schema/facts.toml`` (or another facts file)."""
    return parse_facts(path.read_text(encoding="utf-8"), str(path))


def parse_facts(text: str, path: str = "<string>") -> Facts:
    """Parse facts TOML text; malformed content raises FactsError naming ``path``."""
    try:
        raw: dict[str, object] = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise FactsError(f"{path}: {exc}") from None
    roots = _table(raw.get("root_children", {}), f"{path}: [root_children]")
    single = _table(raw.get("single", {}), f"{path}: [single]")
    entries = raw.get("attribute", [])
    if not isinstance(entries, list):
        raise FactsError(f"{path}: 'attribute' must be an array of tables ([[attribute]])")
    return Facts(
        root_children={k: _str(v, f"{path}: [root_children] {k}") for k, v in roots.items()},
        single={k: _str_list(v, f"{path}: [single] {k}") for k, v in single.items()},
        attributes=[_override(e, f"{path}: [[attribute]] #{i + 1}")
                    for i, e in enumerate(cast(list[object], entries))],
        extra={k: v for k, v in raw.items() if k not in _KNOWN_TABLES},
    )


def _table(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise FactsError(f"{where}: expected a table")
    return {str(k): v for k, v in cast(dict[object, object], value).items()}


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


def _arity(value: object, where: str) -> tuple[int, int]:
    """``[lo, hi]``; an unbounded arity cannot be written in TOML and is not needed yet."""
    items = cast(list[object], value) if isinstance(value, list) else []
    if len(items) != 2 or not all(type(v) is int for v in items):
        raise FactsError(f"{where}: expected [lo, hi] integers, got {value!r}")
    low, high = cast(list[int], items)
    return (low, high)


def _override(value: object, where: str) -> AttributeOverride:
    entry = _table(value, where)
    unknown = sorted(set(entry) - {f.name for f in dataclasses.fields(AttributeOverride)})
    if unknown:
        raise FactsError(f"{where}: unknown key {unknown[0]!r}")
    for key in ("element", "name"):
        if key not in entry:
            raise FactsError(f"{where}: missing key {key!r}")

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
        required=opt_bool("required"), nodefault=opt_bool("nodefault"),
        pattern=opt_str("pattern"), field=opt_str("field"), doc=opt_str("doc"),
        reason=opt_str("reason") or "",
    )
