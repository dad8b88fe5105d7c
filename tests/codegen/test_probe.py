"""The parser probe: classifying load outcomes, probe models, and the installed MuJoCo."""

from __future__ import annotations

import re
from collections.abc import Collection

import pytest

from codegen import ir, naming, probe
from codegen.probe import PROBE_VALUE, Discovery, Outcome, ProbeError, Site

# ------------------------------------------------------------------------------ classify

BASE = Outcome(saved="<mujoco/>")


def error(first_line: str, tag: str = "frame") -> Outcome:
    """A load failure as MuJoCo words it: the message, then the element and line."""
    return Outcome(error=f"XML Error: {first_line}\nElement '{tag}', line 1\n")


@pytest.mark.parametrize(("name", "outcome", "verdict"), [
    ("pos", error("bad format in attribute 'pos'"), "read"),
    ("scaling", error(f"invalid keyword: '{PROBE_VALUE}'"), "read"),
    ("class", error(f"unknown default class name '{PROBE_VALUE}'"), "read"),
    ("childclass", error("unknown default childclass"), "read"),
    # "class" inside "childclass" does not name it
    ("class", error("unknown default childclass"), "refused"),
    ("bogus", error("Schema violation: unrecognized attribute: 'bogus'", "worldbody"), "unknown"),
    ("pos", error("World body cannot have attributes", "worldbody"), "refused"),
    # the element line names the element, not the attribute
    ("frame", error("World body cannot have attributes", "frame"), "refused"),
    ("name", Outcome(saved='<mujoco><frame name="x"/></mujoco>'), "read"),
    ("bogus", Outcome(saved="<mujoco/>"), "unknown"),
])
def test_classify(name: str, outcome: Outcome, verdict: probe.Verdict) -> None:
    assert probe.classify(name, outcome, BASE) == verdict


# ------------------------------------------------------------------------------ discover


def fake_parser(reads: Collection[str], stores: Collection[str] = (),
                refuses: Collection[str] = (), checks_names: bool = False) -> probe.Parser:
    """A parser that rejects the probe value on ``reads``, keeps ``stores`` in the saved
    model, refuses the element for ``refuses`` and ignores every other name (or, when it
    ``checks_names``, reports it as the schema check does)."""

    def parse(xml: str) -> Outcome:
        if "broken" in xml:
            return error("the probe model itself is wrong")
        for name in re.findall(rf'(\w+)="{PROBE_VALUE}"', xml):
            if name in reads:
                return error(f"bad format in attribute '{name}'")
            if name in refuses:
                return error("element cannot have attributes")
            if name in stores:
                return Outcome(saved=f"<saved {name}/>")
            if checks_names:
                return error(f"Schema violation: unrecognized attribute: '{name}'")
        return Outcome(saved="<saved/>")

    return parse


SITE = Site(("mujoco", "worldbody", "frame"), holds_bodies=True)


def test_discover_keeps_candidate_order_and_skips_what_is_no_name() -> None:
    parser = fake_parser(reads={"pos", "euler"}, stores={"name"}, refuses={"mocap", "user"})
    found = probe.discover(SITE, ["pos", "name", "bogus", "data =", "euler", "pos", "mocap",
                                  "user"], parser)
    assert found == Discovery(("pos", "name", "euler"),
                              {"XML Error: element cannot have attributes": ("mocap", "user")},
                              ignores_unknown=True)


def test_discover_tells_whether_the_reader_checks_names() -> None:
    checked = probe.discover(SITE, ["pos"], fake_parser(reads={"pos"}, checks_names=True))
    assert checked == Discovery(("pos",), {}, ignores_unknown=False)


def test_discover_needs_a_probe_model_that_loads() -> None:
    site = Site(("mujoco", "broken"))
    with pytest.raises(ProbeError, match="probe of <broken>: the model without a candidate does "
                                         "not load: XML Error: the probe model itself"):
        probe.discover(site, ["pos"], fake_parser(reads={"pos"}))


# --------------------------------------------------------------------------- probe sites


def test_site_model_nests_the_path_and_sets_the_candidate_last() -> None:
    site = Site(("mujoco", "worldbody", "replicate"), {"replicate": {"count": "1"}}, True)
    assert site.model() == ('<mujoco><worldbody><replicate count="1"><body name="b">'
                            '<geom size="0.1"/></body></replicate></worldbody></mujoco>')
    assert site.model("sep") == (
        f'<mujoco><worldbody><replicate count="1" sep="{PROBE_VALUE}"><body name="b">'
        '<geom size="0.1"/></body></replicate></worldbody></mujoco>')
    # a required attribute probed takes the probe value instead of its valid one
    assert f'<replicate count="{PROBE_VALUE}">' in site.model("count")
    assert Site(("mujoco", "worldbody")).model("pos") == (
        f'<mujoco><worldbody pos="{PROBE_VALUE}"></worldbody></mujoco>')


def attr(name: str, kind: ir.AttrKind, **fields: object) -> ir.AttributeDef:
    a = ir.AttributeDef(name=name, py_name=naming.py_name(name), kind=kind)
    for key, value in fields.items():
        setattr(a, key, value)
    return a


def row(name: str, attributes: list[ir.AttributeDef], children: list[str],
        **fields: object) -> ir.ElementDef:
    el = ir.ElementDef(name=name, tag=str(fields.pop("tag", name)),
                       class_name=naming.class_name(name), attributes=attributes,
                       children=[ir.ChildDef(c, "*", False) for c in children])
    for key, value in fields.items():
        setattr(el, key, value)
    return el


def schema() -> ir.Schema:
    rows = [
        row("mujoco", [], ["default", "worldbody"]),
        # a path through <default> is as short, and found first if not skipped
        row("default", [], ["default_frame", "frame"]),
        row("default_frame", [], [], tag="frame", projection_of="frame"),
        row("worldbody", [], ["body", "frame", "replicate"], alias="body"),
        row("body", [attr("name", "id", namespace="body")], ["body", "frame", "replicate"]),
        row("frame", [attr("name", "id", namespace="frame")], ["body", "frame"], alias="body"),
        row("replicate", [attr("count", "int", dtype="int", required=True),
                          attr("mode", "keyword", enum="mode", required=True),
                          attr("pitch", "real", dtype="double", arity=(2, 2), required=True),
                          attr("tag", "string", required=True),
                          attr("sep", "string")], ["body"], alias="body"),
        row("reflike", [attr("target", "ref", namespace="body", required=True)], [],
            alias="body"),
    ]
    enums = {"mode": ir.EnumDef("mode", [("fast", "0"), ("slow", "1")])}
    return ir.Schema("1.0", "mujoco", enums, {r.name: r for r in rows})


def test_site_for_takes_the_shortest_path_outside_default() -> None:
    s = schema()
    assert probe.site_for(s, "frame") == Site(("mujoco", "worldbody", "frame"), {}, True)
    assert probe.site_for(s, "worldbody") == Site(("mujoco", "worldbody"), {}, True)


def test_site_for_makes_up_required_values() -> None:
    site = probe.site_for(schema(), "replicate")
    assert site is not None
    assert site.required == {"replicate": {"count": "1", "mode": "fast", "pitch": "1 1",
                                           "tag": "p"}}


def test_site_for_gives_up_where_it_cannot() -> None:
    s = schema()
    assert probe.site_for(s, "reflike") is None  # not reachable from the root
    s.elements["worldbody"].children.append(ir.ChildDef("reflike", "*", False))
    assert probe.site_for(s, "reflike") is None  # a required reference names nothing here


# ------------------------------------------------------------------- the installed MuJoCo


@pytest.fixture(scope="module")
def parser() -> probe.Parser:
    return probe.MujocoParser()


CANDIDATES = ["bogus", "class", "childclass", "count", "name", "pos", "sep", "size", "type"]


def test_mujoco_frame(parser: probe.Parser) -> None:
    site = Site(("mujoco", "worldbody", "frame"), {}, True)
    found = probe.discover(site, CANDIDATES, parser)
    assert found.read == ("class", "childclass", "name", "pos")
    assert found.ignores_unknown  # no schema check: a misspelt attribute loads silently


def test_mujoco_replicate(parser: probe.Parser) -> None:
    site = Site(("mujoco", "worldbody", "replicate"), {"replicate": {"count": "1"}}, True)
    # sep is a string the reader keeps: it shows only in the names of the replicas
    found = probe.discover(site, CANDIDATES, parser)
    assert found.read == ("class", "childclass", "count", "sep")
    assert found.ignores_unknown


def test_mujoco_worldbody_reads_no_attribute(parser: probe.Parser) -> None:
    found = probe.discover(Site(("mujoco", "worldbody"), {}, True), CANDIDATES, parser)
    assert found.read == () and not found.ignores_unknown
    assert found.refused == {"XML Error: World body cannot have attributes":
                             ("childclass", "name", "pos")}


def test_mujoco_parser_outcomes(parser: probe.Parser) -> None:
    assert parser("<mujoco/>").error is None and "<mujoco" in parser("<mujoco/>").saved
    assert parser("<mujoco><nope/></mujoco>").error is not None
    assert parser("<mujoco/>") is parser("<mujoco/>")  # kept per model text
