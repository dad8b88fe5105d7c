"""Why an attribute of schema/ has no default.

Every attribute has a default (MuJoCo's, probed by :mod:`codegen.drift`), or ``computed``
(MuJoCo derives the value), or a reason here: a rule for the kinds that have none by nature
(names, references, files, free text, user data, lists as long as the model needs, an
alternative to another attribute's default, what MuJoCo requires), else a reason recorded by
hand in ``schema/unset.toml``. ``tests/codegen/test_default_states.py`` holds every attribute
to one of these.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import cast

from codegen import ir

UNSET = Path(__file__).resolve().parents[1] / "schema" / "unset.toml"

_KINDS = {
    "id": "a name: the element has none unless given",
    "ref": "a reference: it names nothing unless given",
    "file": "a file: none unless given",
    "string": "free text: none unless given",
}


NOT_PROBED = "not probed: "  # a recorded reason from [unprobed.ROW]: the default is unknown


def load(path: Path = UNSET) -> dict[tuple[str, str], str]:
    """schema/unset.toml: (row, attribute) -> why it has no default ([none.ROW]), or why the
    probe cannot tell it ([unprobed.ROW], the text starting with :data:`NOT_PROBED`)."""
    sections = _sections(path)
    return {**sections["none"],
            **{key: NOT_PROBED + why for key, why in sections["unprobed"].items()}}


def computed(path: Path = UNSET) -> dict[tuple[str, str], str]:
    """schema/unset.toml's [computed.ROW]: (row, attribute) -> how MuJoCo computes the value
    (codegen/drift.py records it as the attribute's ``computed``)."""
    return _sections(path)["computed"]


_SECTIONS = ("none", "unprobed", "computed")


def _sections(path: Path) -> dict[str, dict[tuple[str, str], str]]:
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    out: dict[str, dict[tuple[str, str], str]] = {}
    for section in _SECTIONS:
        found = out[section] = {}
        for row, attrs in _table(raw.pop(section, {}), f"{path}: [{section}]").items():
            where = f"{path}: [{section}.{row}]"
            for name, why in _table(attrs, where).items():
                if not isinstance(why, str) or not why:
                    raise ValueError(f"{where} {name}: a non-empty string")
                found[(row, name)] = why
    if raw:
        raise ValueError(f"{path}: unknown tables {sorted(raw)} ({', '.join(_SECTIONS)})")
    return out


def _table(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise TypeError(f"{where} must be a table")
    return cast("dict[str, object]", value)


def rule(row: ir.ElementDef, attr: ir.AttributeDef) -> str | None:
    """The reason a rule gives ``attr`` of ``row`` for having no default, if any."""
    if attr.required:
        return "required: MuJoCo refuses the element without it"
    if attr.kind in _KINDS:
        return _KINDS[attr.kind]
    if attr.name == "user":
        return "user data: none unless given (MuJoCo pads it with zeros to the model's nuser)"
    owner = _owner(row, attr)
    if owner is not None:
        return f"an alternative to {owner}, whose default applies when neither is given"
    partner = _partner(row, attr)
    if partner is not None:
        return f"given only together with {partner}, which has no default"
    if attr.arity is not None and attr.arity[1] is None:
        return "a list as long as the model needs: none unless given"
    return None


def reason(schema: ir.Schema, row: ir.ElementDef, attr: ir.AttributeDef,
           recorded: Mapping[tuple[str, str], str]) -> str | None:
    """Why ``attr`` has no default, or None; a <default> row's copy of an attribute has the
    reason of the row it projects (whose constraints it does not hold)."""
    primary = schema.elements[row.projection_of] if row.projection_of else row
    same = next((a for a in primary.attributes if a.name == attr.name), attr)
    return rule(row, attr) or rule(primary, same) or recorded.get((primary.name, attr.name))


def _owner(row: ir.ElementDef, attr: ir.AttributeDef) -> str | None:
    """The attribute of an exclusive constraint of ``attr`` that holds a default."""
    for c in row.constraints:
        if c.kind != "exclusive" or not any(attr.name in b for b in c.bundles):
            continue
        for name in (n for b in c.bundles if attr.name not in b for n in b):
            other = next((a for a in row.attributes if a.name == name), None)
            if other is not None and other.default is not None:
                return name
    return None


def _partner(row: ir.ElementDef, attr: ir.AttributeDef) -> str | None:
    """An attribute without a default that ``attr`` must be given together with."""
    for c in row.constraints:
        names = [n for b in c.bundles for n in b]
        if c.kind != "together" or attr.name not in names:
            continue
        for name in names:
            other = next((a for a in row.attributes if a.name == name), None)
            if name != attr.name and other is not None and other.default is None \
                    and other.computed is None:
                return name
    return None


def states(schema: ir.Schema, primary_numbers: bool = False) -> dict[str, int]:
    """How many attributes have a default, are computed, have no default (by a rule or a
    recorded reason) or are not probed; ``primary_numbers``: only numbers, bools, keywords
    and flags of rows outside <default>."""
    recorded = load()
    out: dict[str, int] = {}
    for row in schema.elements.values():
        for attr in row.attributes:
            if primary_numbers and (row.projection_of is not None or attr.kind not in
                                    ("int", "real", "keyword", "bool", "flags")):
                continue
            why = reason(schema, row, attr, recorded)
            state = ("default" if attr.default is not None else "computed" if attr.computed
                     else "unknown" if why is None else "unprobed" if why.startswith(NOT_PROBED)
                     else "no default (recorded)" if why in recorded.values()
                     else "no default (rule)")
            out[state] = out.get(state, 0) + 1
    return out


if __name__ == "__main__":  # python -m codegen.unset: the counts of schema/mjcf.json
    committed = ir.load()
    print("every attribute:", states(committed))
    print("rows' numbers, bools, keywords, flags:", states(committed, primary_numbers=True))
