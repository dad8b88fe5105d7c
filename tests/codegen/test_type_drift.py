"""The generator's type probe (codegen/drift.py) against the installed MuJoCo's parser.

Each test changes one fact of a copy of the committed schema to what an older or newer MuJoCo
would have said, and checks that probing the installed parser finds the change, types it when
it can (count, keyword set, default) and otherwise names the attribute and the facts.toml
entry. The last test is the held-out check of issue 24: the three MuJoCo 4.0.0 changes that
the 4.0.0 bindings first got wrong, found again from the schema as it was.
"""

from __future__ import annotations

import copy
import dataclasses

import pytest

from codegen import drift, ir, probe, unset
from codegen.facts import load_facts
from codegen.reconcile import sync
from codegen.wheel import Wheel, read_wheel


@pytest.fixture(scope="module")
def wheel() -> Wheel:
    return read_wheel()


@pytest.fixture
def schema() -> ir.Schema:
    return copy.deepcopy(_COMMITTED)


_COMMITTED = ir.load()


def check(schema: ir.Schema, wheel: Wheel, rows: set[str],
          hand: frozenset[tuple[str, str]] = frozenset()) -> drift.Drift:
    assert wheel.drift_parser is not None
    return drift.check(schema, wheel.drift_parser, wheel.reference, wheel.enums, wheel.structs,
                       drift.load_sites(), set(hand), set(), rows)


def lines(found: drift.Drift) -> list[str]:
    return [c.line() for c in found.applied]


@pytest.mark.parametrize(("message", "expected"), [
    (None, "ok"),
    ("XML Error: attribute 'pos' does not have enough data\nElement 'geom', line 1", "short"),
    ("XML Error: attribute 'pos' has too much data", "long"),
    ("XML Error: attribute 'size' has too much data", "ok"),  # another attribute
    ("XML Error: invalid keyword: 'vert'", "keyword"),
    ("XML Error: invalid keyword: '(null)'", "keyword"),  # flags quote no value
    ("XML Error: bad format in attribute 'pos'", "bad"),
    ("XML Error: problem reading attribute 'pos'", "bad"),
    ("XML Error: Schema violation: unrecognized attribute: 'pos'", "unknown"),
    ("Error: size 0 must be positive in geom", "ok"),  # read; failed later
])
def test_verdict(message: str | None, expected: drift.Verdict) -> None:
    outcome = probe.Outcome(error=message) if message else probe.Outcome(saved="<mujoco/>")
    assert drift.verdict("pos", "vert", outcome) == expected


def test_the_committed_rows_agree(schema: ir.Schema, wheel: Wheel) -> None:
    found = check(schema, wheel, {"geom", "joint", "flexcomp_edge", "headlight", "flex"},
                  frozenset((o.element, o.name) for o in load_facts().attributes))
    assert found.applied == [] and found.untypable == []
    assert found.probed > 40 and found.defaults > 10


def test_a_value_count_change_is_typed(schema: ir.Schema, wheel: Wheel) -> None:
    schema.elements["geom"].attribute("pos").arity = (2, 2)
    schema.elements["default_geom"].attribute("pos").arity = (2, 2)
    found = check(schema, wheel, {"geom"})
    assert lines(found) == ["geom@pos count: 2 -> 3"]
    assert schema.elements["geom"].attribute("pos").arity == (3, 3)
    assert schema.elements["default_geom"].attribute("pos").arity == (3, 3)  # the copy too


def test_an_open_count_that_closed_is_seen(schema: ir.Schema, wheel: Wheel) -> None:
    schema.elements["geom"].attribute("fromto").arity = (1, None)
    found = check(schema, wheel, {"geom"})
    assert lines(found) == ["geom@fromto count: 1.. -> 6"]


def test_a_removed_keyword_is_typed(schema: ir.Schema, wheel: Wheel) -> None:
    schema.enums["jointtype"].values.append(("hinge2", "mjJNT_HINGE"))
    found = check(schema, wheel, {"joint"})
    assert lines(found) == [("joint@type keywords: [free, ball, slide, hinge, hinge2] -> "
                            "[free, ball, slide, hinge]")]
    assert schema.enums["jointtype"].keywords == ["free", "ball", "slide", "hinge"]


def test_an_added_keyword_is_typed_and_bound_to_its_constant(schema: ir.Schema,
                                                             wheel: Wheel) -> None:
    schema.enums["jointtype"].values.remove(("ball", "mjJNT_BALL"))
    found = check(schema, wheel, {"joint"})
    assert lines(found) == [("joint@type keywords: [free, slide, hinge] -> "
                            "[free, slide, hinge, ball]")]
    assert ("ball", "mjJNT_BALL") in schema.enums["jointtype"].values


def test_a_changed_default_takes_the_documented_one(schema: ir.Schema, wheel: Wheel) -> None:
    schema.elements["geom"].attribute("density").default = "999"
    found = check(schema, wheel, {"geom"})
    assert lines(found) == ['geom@density default: "999" -> "1000"']
    assert schema.elements["geom"].attribute("density").default == "1000"


def test_a_kind_change_stops_with_the_facts_entry(schema: ir.Schema, wheel: Wheel) -> None:
    density = schema.elements["geom"].attribute("density")
    density.kind, density.dtype = "int", "int"
    found = check(schema, wheel, {"geom"})
    ((change, fact),) = found.untypable
    assert change.line() == "geom@density kind: int -> real"
    assert fact.startswith('[[attribute]] element = "geom", name = "density", kind = "real"')
    assert density.kind == "int"  # left for facts.toml


def test_facts_toml_takes_over_what_it_types(schema: ir.Schema, wheel: Wheel) -> None:
    density = schema.elements["geom"].attribute("density")
    density.kind, density.dtype = "int", "int"
    found = check(schema, wheel, {"geom"}, frozenset({("geom", "density")}))
    assert found.untypable == []


def test_keywords_a_shared_enum_now_splits_on_stop(schema: ir.Schema, wheel: Wheel) -> None:
    # joint@type and a made-up second user of jointtype that MuJoCo reads as geom types
    schema.elements["geom"].attribute("type").enum = "jointtype"
    found = check(schema, wheel, {"geom", "joint"})
    assert [c.what for c, _ in found.untypable] == ["keywords"]
    assert "[[enum]]" in found.untypable[0][1]


# --------------------------------------------------------- held out: MuJoCo 4.0.0's changes


def as_first_generated(schema: ir.Schema) -> ir.Schema:
    """The 4.0.0 schema before the probe: what 3.17 had for the three attributes."""
    active = schema.elements["headlight"].attribute("active")
    active.kind, active.dtype, active.enum, active.default = "int", "int", None, "1"
    del schema.enums["headlight_active"]
    schema.enums["flexeq"].values.insert(2, ("vert", "2"))
    for row in ("flex", "flexcomp"):
        material = schema.elements[row].attribute("material")
        material.kind, material.namespace, material.arity = "ref", "material", None
    return schema


def test_the_three_4_0_0_changes_are_found(schema: ir.Schema, wheel: Wheel) -> None:
    facts = load_facts()
    mine = {("headlight", "active"), ("flex", "material"), ("flexcomp", "material")}
    facts = dataclasses.replace(
        facts, attributes=[o for o in facts.attributes if (o.element, o.name) not in mine],
        enums=[e for e in facts.enums if e.name != "headlight_active"])
    _, report = sync(as_first_generated(schema), wheel, facts)
    assert report.drifted == [
        "flexcomp_edge@equality keywords: [false, true, vert, strain] -> [false, true, strain]"]
    errors = [line.split(";")[0] for line in report.drift_errors]
    assert errors == ["flex@material count: 1 -> 1..",
                      "headlight@active kind: int -> keyword [false, true, auto]"]
    assert "facts.toml" in report.format() and "schema/ not written" in report.format()


@pytest.mark.parametrize(("name", "after"), [("density", "a number"), ("type", "keyword")])
def test_free_text_that_the_reader_now_types_stops(schema: ir.Schema, wheel: Wheel,
                                                   name: str, after: str) -> None:
    attr = schema.elements["geom"].attribute(name)
    attr.kind, attr.dtype, attr.enum, attr.arity, attr.default = "string", None, None, None, None
    found = check(schema, wheel, {"geom"})
    assert [c.line() for c, _ in found.untypable] == [f"geom@{name} kind: string -> {after}"]


# ---------------------------------------------------------------- spellings (check_spellings)


def spellings(schema: ir.Schema, parser: probe.Parser, wheel: Wheel,
              rows: set[str]) -> list[str]:
    found = drift.check_spellings(schema, parser, wheel.enums, drift.load_sites(), rows)
    assert found.probed > 0
    return lines(found)


def test_numbers_a_reader_starts_taking_are_recorded(schema: ir.Schema, wheel: Wheel) -> None:
    """The schema as 3.x typed <headlight active> (no numbers) against 4.0.0's reader."""
    assert wheel.drift_parser is not None
    for row in ("headlight",):
        schema.elements[row].attribute("active").numbers = None
    assert spellings(schema, wheel.drift_parser, wheel, {"headlight"}) == [
        "headlight@active spellings: [] -> [false=0, true=1, auto=2]"]
    assert schema.elements["headlight"].attribute("active").numbers == {
        "false": 0, "true": 1, "auto": 2}


def test_numbers_a_reader_stops_taking_are_dropped(schema: ir.Schema, wheel: Wheel) -> None:
    assert wheel.drift_parser is not None
    schema.elements["joint"].attribute("type").numbers = {"hinge": 3}
    schema.elements["default_joint"].attribute("type").numbers = {"hinge": 3}
    assert spellings(schema, wheel.drift_parser, wheel, {"joint"}) == [
        "joint@type spellings: [hinge=3] -> []"]
    assert schema.elements["default_joint"].attribute("type").numbers is None  # the copy too


def test_a_release_reading_a_keyword_s_c_value_is_seen(schema: ir.Schema, wheel: Wheel) -> None:
    """A simulated MuJoCo whose reader takes joint type="3" (mjJNT_HINGE) as hinge."""
    real = wheel.drift_parser
    assert real is not None

    def newer(xml: str) -> probe.Outcome:
        return real(xml.replace('<joint type="3"', '<joint type="hinge"'))

    assert spellings(schema, newer, wheel, {"joint"}) == ["joint@type spellings: [] -> [hinge=3]"]
    assert schema.elements["default_joint"].attribute("type").numbers == {"hinge": 3}


def test_a_reader_taking_any_word_is_not_probed_for_numbers(schema: ir.Schema,
                                                            wheel: Wheel) -> None:
    """A frame sensor's reftype is not read without a refname: every word loads."""
    assert wheel.drift_parser is not None
    found = drift.check_spellings(schema, wheel.drift_parser, wheel.enums, drift.load_sites(),
                                  {"framepos"})
    assert found.applied == [] and found.probed == 2  # interp and objtype, not reftype


# ------------------------------------------------------------ defaults the schema lacked


def test_a_missing_default_is_the_value_the_reader_saves_back_as_absent(
        schema: ir.Schema, wheel: Wheel) -> None:
    for row in ("joint", "default_joint"):
        schema.elements[row].attribute("damping").default = None
    found = check(schema, wheel, {"joint"})
    assert lines(found) == ['joint@damping default: (none) -> "0 0 0"']
    assert schema.elements["default_joint"].attribute("damping").default == "0 0 0"


def test_a_value_mujoco_computes_is_recorded_with_why(schema: ir.Schema, wheel: Wheel) -> None:
    """A geom's mass comes from its density and volume: no written value reads as absent."""
    for row in ("geom", "default_geom"):
        schema.elements[row].attribute("mass").computed = None
    found = check(schema, wheel, {"geom"})
    assert lines(found) == ["geom@mass default: (none) -> (computed)"]
    assert schema.elements["geom"].attribute("mass").computed == \
        unset.computed()[("geom", "mass")]  # schema/unset.toml says how
    assert schema.elements["geom"].attribute("mass").default is None


def test_an_alternative_to_an_attribute_with_a_default_gets_none(schema: ir.Schema,
                                                                  wheel: Wheel) -> None:
    """axisangle="1 0 0 0" reads as absent, but quat's default applies: no default."""
    found = check(schema, wheel, {"body"})
    assert found.applied == []
    assert schema.elements["body"].attribute("axisangle").default is None
    assert schema.elements["body"].attribute("axisangle").computed is None


def test_an_actuator_s_defaults_are_probed_with_its_target(schema: ir.Schema,
                                                           wheel: Wheel) -> None:
    """MuJoCo compiles (and saves) a motor only with a joint: the probe gives it one."""
    for row in ("motor", "default_motor"):
        schema.elements[row].attribute("ctrlrange").default = None
    found = check(schema, wheel, {"motor"})
    assert lines(found) == ['motor@ctrlrange default: (none) -> "0 0"']


def test_the_release_day_report_lists_changed_spellings_and_defaults(
        schema: ir.Schema, wheel: Wheel) -> None:
    """`python -m codegen generate`'s report, after a simulated MuJoCo release whose reader
    reads headlight@active's numbers (newly) and a joint's damping when absent as 0."""
    schema.elements["headlight"].attribute("active").numbers = None
    for row in ("joint", "default_joint"):
        schema.elements[row].attribute("damping").default = None
    _, report = sync(schema, wheel, load_facts())
    text = report.format()
    assert "  ~ headlight@active spellings: [] -> [false=0, true=1, auto=2]" in text
    assert '  ~ joint@damping default: (none) -> "0 0 0"' in text
    assert not report.drift_errors
