"""The committed schema/mjcf.json against the installed mujoco wheel.

A failure means MuJoCo's grammar moved: run ``nox -s generate`` and review the diff. Each
assertion prints what differs, one ``+`` (wheel has it, schema lacks it) or ``-`` line each.
"""

from __future__ import annotations

import copy
import math
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from codegen import ir, probe
from codegen.facts import load_facts
from codegen.pipeline import build_from_grammar, refresh
from codegen.reconcile import sync
from codegen.wheel import SpecValue, Wheel, WheelRow, read_wheel, spec_defaults

pytestmark = pytest.mark.skipif(
    not ir.SCHEMA_PATH.exists(),
    reason="schema/mjcf.json does not exist yet: run `python -m codegen generate`")


@pytest.fixture(scope="module")
def schema() -> ir.Schema:
    return ir.load()


@pytest.fixture(scope="module")
def wheel() -> Wheel:
    return read_wheel()


def diff(lines: list[str]) -> str:
    return "schema/mjcf.json differs from the installed mujoco:\n  " + "\n  ".join(lines)


# ------------------------------------------------------------------------- grammar tree


class _Walk:
    """printSchema's tree alongside the IR rows, collecting differences."""

    def __init__(self, schema: ir.Schema) -> None:
        self.rows = schema.elements
        self.seen: set[str] = set()
        self.lines: list[str] = []

    def child(self, row: ir.ElementDef, wchild: WheelRow) -> ir.ElementDef | None:
        for edge in row.children:
            target = self.rows[edge.element]
            if target.tag in wchild.spellings:
                if edge.card != wchild.card:
                    self.lines.append(f"~ {row.name}/{target.name}: {edge.card} in the schema, "
                                      f"{wchild.card} in the wheel")
                return target
        self.lines.append(f"+ {row.name}/{wchild.tag} (a row with its children)")
        return None

    def visit(self, row: ir.ElementDef, wrow: WheelRow) -> None:
        if row.name in self.seen:
            return
        self.seen.add(row.name)
        if row.alias is None:  # worldbody: printSchema lists the body row's attributes
            have, want = {a.name for a in row.attributes}, set(wrow.attributes)
            self.lines += [f"+ {row.name}@{a}" for a in sorted(want - have)]
            self.lines += [f"- {row.name}@{a}" for a in sorted(have - want)]
        for wchild in wrow.children:
            if row.alias is not None and all(self.rows[e.element].tag not in wchild.spellings
                                             for e in row.children):
                continue  # worldbody is a restricted body: no inertial, joints, ...
            target = self.child(row, wchild)
            if target is not None:
                self.visit(target, wchild)
        for edge in row.children:
            target = self.rows[edge.element]
            recursive = wrow.card == "R" and target.tag in wrow.spellings
            if recursive:
                self.visit(target, wrow)
            elif wrow.child(target.tag) is None and target.alias is None:
                self.lines.append(f"- {row.name}/{target.name}")


def test_rows_children_and_attributes_match_print_schema(schema: ir.Schema,
                                                         wheel: Wheel) -> None:
    walk = _Walk(schema)
    walk.visit(schema.elements[schema.root], wheel.schema)
    assert not walk.lines, diff(walk.lines)


def test_alias_rows_only_use_what_the_body_row_allows(schema: ir.Schema, wheel: Wheel) -> None:
    body = wheel.schema.child("body")
    assert body is not None
    lines = [f"- {row.name}/{edge.element}"
             for row in schema.elements.values() if row.alias == "body"
             for edge in row.children
             if body.child(schema.elements[edge.element].tag) is None
             and schema.elements[edge.element].tag not in body.spellings
             and schema.elements[edge.element].alias is None]
    assert not lines, diff(lines)


def test_frame_and_replicate_have_their_documented_attributes(schema: ir.Schema,
                                                              wheel: Wheel) -> None:
    lines: list[str] = []
    for name in ("frame", "replicate"):
        documented = {a.removeprefix(f"{name}-") for a in wheel.reference.anchors
                      if re.fullmatch(rf"{name}-\w+", a)}
        have = {a.name for a in schema.elements[name].attributes}
        lines += [f"+ {name}@{a}" for a in sorted(documented - have)]
    assert not lines, diff(lines)


# ------------------------------------------------------------- rows printSchema omits


def parser_differences(schema: ir.Schema, wheel: Wheel) -> list[str]:
    """``+``/``-`` lines: the attributes the installed parser reads on the rows printSchema
    omits (worldbody, frame, replicate) against the schema's, over every attribute name the
    schema, printSchema and XMLreference.rst spell."""
    assert wheel.parser is not None
    candidates = sorted({a.name for row in schema.elements.values() for a in row.attributes}
                        | {a for row in wheel.schema.walk() for a in row.attributes}
                        | wheel.reference.names)
    lines: list[str] = []
    for row in sorted((r for r in schema.elements.values() if r.alias is not None),
                      key=lambda r: r.name):
        site = probe.site_for(schema, row.name)
        assert site is not None, f"no probe model for {row.name}"
        read = set(probe.discover(site, candidates, wheel.parser).read)
        have = {a.name for a in row.attributes}
        lines += [f"+ {row.name}@{a}" for a in sorted(read - have)]
        lines += [f"- {row.name}@{a}" for a in sorted(have - read)]
    return lines


def test_rows_print_schema_omits_have_what_the_parser_reads(schema: ir.Schema,
                                                            wheel: Wheel) -> None:
    assert {r.name for r in schema.elements.values() if r.alias is not None} == {
        "worldbody", "frame", "replicate"}
    lines = parser_differences(schema, wheel)
    assert not lines, diff(lines)


@pytest.mark.parametrize(("row", "name", "added"), [
    # sep: spelt on no other row; found through XMLreference.rst
    ("replicate", "sep", "replicate@sep: string  [replicate-sep]"),
    # class: undocumented on replicate; typed by schema/facts.toml
    ("replicate", "class", "replicate@class: ref<default>  [facts.toml]"),
    ("frame", "scale", 'frame@scale: real double[1..3] = "1"  [frame-scale]'),
])
def test_an_attribute_the_parser_reads_and_the_schema_lacks_is_reported(
        schema: ir.Schema, wheel: Wheel, row: str, name: str, added: str) -> None:
    damaged = copy.deepcopy(schema)
    damaged.elements[row].attributes = [a for a in damaged.elements[row].attributes
                                        if a.name != name]
    assert parser_differences(damaged, wheel) == [f"+ {row}@{name}"]
    synced, report = sync(damaged, wheel, load_facts())
    assert report.added_attributes == [added]
    assert f"  + {added}" in report.format().splitlines()
    # typed as committed (sync appends it: attribute order is the export order)
    assert synced.elements[row].attribute(name) == schema.elements[row].attribute(name)


def test_an_attribute_the_parser_does_not_read_is_reported(schema: ir.Schema,
                                                           wheel: Wheel) -> None:
    # MuJoCo 4.0.0 ignores <replicate prefix> (as any unknown attribute of a replicate)
    damaged = copy.deepcopy(schema)
    damaged.elements["replicate"].attributes.append(
        ir.AttributeDef("prefix", "prefix", "string"))
    assert parser_differences(damaged, wheel) == ["- replicate@prefix"]
    synced, report = sync(damaged, wheel, load_facts())
    assert report.removed_attributes == ["replicate@prefix: string"]
    assert ir.dumps(synced) == ir.dumps(schema)


def test_schema_describes_the_installed_version(schema: ir.Schema, wheel: Wheel) -> None:
    assert schema.mujoco_version == wheel.version


def test_sync_changes_nothing(schema: ir.Schema, wheel: Wheel) -> None:
    """The committed schema is what `nox -s generate` writes for this wheel (anchors, types
    of wheel-only attributes and enum constants included)."""
    _, report = sync(schema, wheel, load_facts())
    assert report.is_empty(), report.format()
    synced, again = refresh(schema, None)
    assert again.is_empty() and ir.dumps(synced) == ir.dumps(schema)


GRAMMAR = Path("/work/shared/reference/mjcf.schema")


@pytest.mark.skipif(not GRAMMAR.exists(), reason="MuJoCo's grammar file is not available")
def test_grammar_and_wheel_rebuild_the_committed_schema(schema: ir.Schema, wheel: Wheel) -> None:
    rebuilt, _ = build_from_grammar(GRAMMAR, installed=wheel)
    assert ir.dumps(rebuilt) == ir.dumps(schema), (
        "schema/mjcf.json is stale: run `python -m codegen generate --grammar "
        f"{GRAMMAR}`")


def test_refresh_needs_a_schema_or_a_grammar() -> None:
    with pytest.raises(ValueError, match="no schema/mjcf.json"):
        refresh(None, None)


# -------------------------------------------------------------------------------- enums


def test_enum_constants_exist_in_introspect(schema: ir.Schema, wheel: Wheel) -> None:
    lines: list[str] = []
    for enum in sorted(schema.enums.values(), key=lambda e: e.name):
        if enum.ctype is None:
            continue
        consts = wheel.enums.get(enum.ctype)
        if consts is None:
            lines.append(f"- enum {enum.name}: {enum.ctype} is not a mujoco.introspect enum")
            continue
        lines += [f"- enum {enum.name}: {keyword} = {const} is not in {enum.ctype}"
                  for keyword, const in enum.values if const not in consts]
        values = [consts[c] for _, c in enum.values if c in consts]
        if len(set(values)) != len(values):
            lines.append(f"~ enum {enum.name}: two keywords share a {enum.ctype} value")
    assert not lines, diff(lines)


# ------------------------------------------------------------------------------ defaults

# Attributes whose default cannot be checked against the MjSpec default object, with why.
# Everything else with a default on an mjs-bound row must equal the object's field.
KNOWN_DEFAULT_DIFFERENCES = {
    # New in 4.0.0 and typed from XMLreference.rst, which does not name the C field: the
    # value lives in mjsFlex.stressyield (two values), so there is no field to compare.
    ("elasticity", "yield"): "no mjsFlex field of that name (stressyield)",
}


def _spec_kind(struct: str | None, kinds: set[str]) -> str | None:
    """``mjsJoint`` -> ``joint`` when ``MjSpec().default`` has that object."""
    if struct is None or not struct.startswith("mjs"):
        return None
    kind = struct[3:4].lower() + struct[4:]
    return kind if kind in kinds else None


def _numbers(schema: ir.Schema, wheel: Wheel, attr: ir.AttributeDef) -> list[float] | None:
    """The IR default as numbers: keywords through their C constants or integer values."""
    text = attr.default
    if text is None:
        return None
    if attr.kind == "bool":
        return [1.0 if text == "true" else 0.0]
    if attr.kind in ("keyword", "flags") and attr.enum is not None:
        enum = schema.enums[attr.enum]
        consts = wheel.enums.get(enum.ctype or "", {})
        values = [dict(enum.values)[word] for word in text.split()]
        if not all(re.fullmatch(r"-?\d+", v) or v in consts for v in values):
            return None
        return [float(consts[v]) if v in consts else float(v) for v in values]
    if attr.kind in ("int", "real"):
        return [float(v) for v in text.split()]
    return None


def _spec_numbers(value: SpecValue) -> list[float] | None:
    if isinstance(value, str):
        return None
    if isinstance(value, tuple):
        return list(value)
    return [float(value)]


def _same(attr: ir.AttributeDef, ir_values: list[float], spec_values: list[float]) -> bool:
    """Equal values; a default shorter than a variable-length field is padded with zeros,
    as the parser fills the values an element leaves out (``dynprm="1"``)."""
    if attr.arity is not None and attr.arity[0] != attr.arity[1]:
        ir_values = ir_values + [0.0] * (len(spec_values) - len(ir_values))
    if len(ir_values) != len(spec_values):
        return False
    return all(math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-9) for a, b in zip(ir_values,
                                                                                spec_values))


def _default_rows(schema: ir.Schema, kinds: set[str]) -> Iterator[tuple[ir.ElementDef, str]]:
    for row in sorted(schema.elements.values(), key=lambda r: r.name):
        kind = _spec_kind(row.struct, kinds)
        if kind is not None and row.projection_of is None:
            yield row, kind


def test_defaults_match_the_mjspec_default_objects(schema: ir.Schema, wheel: Wheel) -> None:
    spec = spec_defaults(wheel.structs)
    lines: list[str] = []
    compared = 0
    for row, kind in _default_rows(schema, set(spec)):
        for attr in row.attributes:
            ours = _numbers(schema, wheel, attr)
            if ours is None or (row.name, attr.name) in KNOWN_DEFAULT_DIFFERENCES:
                continue
            where = f"MjSpec().default.{kind}.{attr.field or attr.name}"
            if (attr.field or attr.name) not in wheel.structs.get(row.struct or "", {}):
                continue  # no field (position@kp sets gainprm): test_sync_changes_nothing
                # holds it to the reader (codegen/drift.py's default probe)
            value = spec[kind].get(attr.field or attr.name)
            theirs = _spec_numbers(value) if value is not None else None
            if theirs is None:
                lines.append(f"? {row.name}@{attr.name}: default {attr.default!r}, no {where}")
                continue
            compared += 1
            if not _same(attr, ours, theirs):
                lines.append(f"~ {row.name}@{attr.name}: {attr.default!r} in the schema, "
                             f"{value!r} on {where}")
    assert compared > 100, f"only {compared} defaults compared: the mapping is broken"
    assert not lines, diff(lines)


def test_known_default_differences_are_current(schema: ir.Schema) -> None:
    stale = [f"{row}@{name}" for row, name in KNOWN_DEFAULT_DIFFERENCES
             if row not in schema.elements
             or all(a.name != name or a.default is None for a in schema.elements[row].attributes)]
    assert not stale, f"KNOWN_DEFAULT_DIFFERENCES lists what the schema no longer has: {stale}"
