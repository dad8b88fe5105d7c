"""``sync`` on a small synthetic IR and a synthetic wheel."""

from __future__ import annotations

import re
import textwrap
from collections.abc import Mapping

import pytest

from codegen import ir, naming
from codegen.facts import AttributeOverride, EnumFact, Facts, FactsError
from codegen.probe import PROBE_VALUE, Outcome, Parser
from codegen.reconcile import Report, describe, sync
from codegen.wheel import Wheel, parse_print_schema, parse_reference


def attr(name: str, kind: ir.AttrKind = "string", **fields: object) -> ir.AttributeDef:
    a = ir.AttributeDef(name=name, py_name=naming.py_name(name), kind=kind)
    for key, value in fields.items():
        setattr(a, key, value)
    return a


def row(name: str, attributes: list[ir.AttributeDef], children: list[tuple[str, str]],
        **fields: object) -> ir.ElementDef:
    tag = str(fields.pop("tag", name))
    el = ir.ElementDef(name=name, tag=tag, class_name=naming.class_name(name),
                       attributes=attributes,
                       children=[ir.ChildDef(c, ir_card(card), card in "?!")
                                 for c, card in children])
    for key, value in fields.items():
        setattr(el, key, value)
    return el


def ir_card(card: str) -> ir.Cardinality:
    cards: dict[str, ir.Cardinality] = {"?": "?", "!": "!", "*": "*", "R": "R"}
    return cards[card]


BODY_CHILDREN = [("body", "R"), ("frame", "R"), ("joint", "*"), ("geom", "?"), ("composite", "*")]


def schema() -> ir.Schema:
    """mujoco 1.0: <composite> in bodies, no <site>, no springyield, no default/texture."""
    rows = [
        row("mujoco", [attr("model")],
            [("default", "R"), ("asset", "*"), ("worldbody", "R"), ("tendon", "*")]),
        row("default", [attr("class", "id", namespace="default")],
            [("default", "R"), ("default_joint", "?"), ("default_tendon", "?")]),
        row("default_joint", [attr("type", "keyword", enum="jointtype", default="hinge"),
                              attr("damping", "real", dtype="double")], [],
            tag="joint", projection_of="joint", struct="mjsJoint"),
        row("default_tendon", [attr("springlength", "real", dtype="double", arity=(1, 2))], [],
            tag="tendon"),
        row("asset", [], [("texture", "*")]),
        row("texture", [attr("name", "id", namespace="texture"),
                        attr("type", "keyword", enum="jointtype")], []),
        row("worldbody", [], [("body", "*"), ("frame", "*"), ("geom", "*"), ("composite", "*")],
            alias="body"),
        row("body", [attr("name", "id", namespace="body"),
                     attr("pos", "real", dtype="double", arity=(3, 3))], BODY_CHILDREN,
            struct="mjsBody"),
        row("frame", [attr("name", "id", namespace="frame")], BODY_CHILDREN, alias="body"),
        row("joint", [attr("name", "id", namespace="joint"),
                      attr("class", "ref", namespace="default"),
                      attr("type", "keyword", enum="jointtype", default="hinge"),
                      attr("damping", "real", dtype="double")], [], struct="mjsJoint"),
        row("geom", [attr("name", "id", namespace="geom"),
                     attr("class", "ref", namespace="default"),
                     attr("size", "real", dtype="double", arity=(1, 3)),
                     attr("obsolete", "real", dtype="double")], [],
            constraints=[ir.ConstraintDef("exclusive", [["size"], ["obsolete"]])]),
        row("composite", [attr("type", "keyword", enum="comp")], []),
        row("tendon", [], [("spatial", "*"), ("fixed", "*")]),
        row("spatial", [attr("name", "id", namespace="tendon"),
                        attr("springlength", "real", dtype="double", arity=(1, 2))], []),
        row("fixed", [attr("name", "id", namespace="tendon"),
                      attr("springlength", "real", dtype="double", arity=(1, 2))], []),
    ]
    enums = {
        "jointtype": ir.EnumDef("jointtype", [("slide", "mjJNT_SLIDE"), ("hinge", "mjJNT_HINGE"),
                                              ("gone", "mjJNT_GONE")], "mjtJoint"),
        "comp": ir.EnumDef("comp", [("a", "0"), ("b", "1")]),
    }
    return ir.Schema("1.0", "mujoco", enums, {r.name: r for r in rows})


PRINT_SCHEMA = """\
mujoco (!)                    model
   default (R)                class
      texture (?)             type
      joint (?)               damping springyield type
      tendon (?)              springlength springyield
   asset (*)
      texture (*)             embed name type
   (world)body (R)            name pos
      joint (*)               class damping name springyield type
      geom (*)                class name size
      site (*)                name size
   tendon (*)
      spatial (*)             name springlength springyield
      fixed (*)               name springlength springyield
"""

REFERENCE = textwrap.dedent("""\
    .. _body:

    **body**

    .. _body-joint:

    **joint**

    .. _body-joint-type:

    :at:`type`: :at-val:`[slide, hinge], "hinge"`

    .. _body-joint-springyield:

    :at:`springyield`: :at-val:`real, "0"`

    .. _body-site-name:

    :at:`name`: :at-val:`string, optional`

    .. _body-site-size:

    :at:`size`: :at-val:`real(3), "0.005 0.005 0.005"`

    .. _asset-texture-embed:

    :at:`embed`: :at-val:`[false, true, auto], "auto"`

    .. _frame-name:

    :at:`name`: :at-val:`string, optional`

    .. _frame-scale:

    :at:`scale`: :at-val:`real(1 or 3), "1"`

    .. _tendon-spatial-springyield:

    :at:`springyield`: :at-val:`real, "0"`

    .. _tendon-fixed-springyield:

    .. |tendon/fixed attrib list| replace:: :at:`springyield`

    |tendon/fixed attrib list|
       Same as in :ref:`spatial <tendon-spatial>`.

    .. _default-joint:

    **default/joint**
""")

ENUMS = {
    "mjtJoint": {"mjJNT_SLIDE": 2, "mjJNT_HINGE": 3},
    "mjtEmbed": {"mjEMBED_FALSE": 0, "mjEMBED_TRUE": 1, "mjEMBED_AUTO": 2},
    "mjtLimited": {"mjLIMITED_FALSE": 0, "mjLIMITED_TRUE": 1, "mjLIMITED_AUTO": 2, "mjNLIM": 3},
}


def parser(reads: Mapping[str, set[str]]) -> Parser:
    """A parser that rejects the probe value on the names ``reads`` lists for the element
    carrying it, and ignores every other name (as MuJoCo does on frames)."""

    def parse(xml: str) -> Outcome:
        probed = re.search(rf'<(\w+)[^<>]* (\w+)="{PROBE_VALUE}"', xml)
        if probed is not None and probed[2] in reads.get(probed[1], set()):
            return Outcome(error=f"XML Error: bad format in attribute '{probed[2]}'")
        return Outcome(saved="<mujoco/>")

    return parse


# frame@scale is spelt by the reference alone: neither printSchema nor the IR has a "scale"
FRAME_READS = {"frame": {"name", "scale"}}


def wheel(print_schema: str = PRINT_SCHEMA,
          reads: Mapping[str, set[str]] = FRAME_READS) -> Wheel:
    return Wheel("2.0", parse_print_schema(print_schema), ENUMS, parse_reference(REFERENCE),
                 {"mjsJoint": {"springyield": "float"}}, parser(reads))


SITE_NAME_UNTYPED = ("site@name: body-site-name says 'string, optional', but name is an "
                     "identifier elsewhere")
FACTS = Facts(single={"mujoco": ["default", "asset", "worldbody", "tendon"]})
SITE_NAME_ID = AttributeOverride("site", "name", kind="id", namespace="site",
                                 reason="the docs say string")


@pytest.fixture(scope="module")
def synced() -> tuple[ir.Schema, Report]:
    return sync(schema(), wheel(), FACTS)


def children(s: ir.Schema, name: str) -> dict[str, tuple[str, bool]]:
    return {c.element: (c.card, c.single) for c in s.elements[name].children}


def names(s: ir.Schema, name: str) -> list[str]:
    return [a.name for a in s.elements[name].attributes]


# -------------------------------------------------------------------------- attributes


def test_adds_attribute_typed_from_the_reference(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    springyield = s.elements["joint"].attribute("springyield")
    # real from the reference; float because mjsJoint stores it as float
    assert describe(springyield) == 'real float = "0"'
    assert springyield.anchor == "body-joint-springyield"
    assert 'joint@springyield: real float = "0"  [body-joint-springyield]' in \
        report.added_attributes


def test_substituted_entries_type_through_their_target(synced: tuple[ir.Schema, Report]) -> None:
    s, _ = synced
    assert describe(s.elements["fixed"].attribute("springyield")) == 'real double = "0"'
    assert s.elements["fixed"].attribute("springyield").anchor == "tendon-fixed-springyield"


def test_keyword_attribute_binds_a_new_enum_to_its_c_enum(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    embed = s.elements["texture"].attribute("embed")
    assert (embed.kind, embed.enum, embed.default) == ("keyword", "embed", "auto")
    # mjtLimited spells the same keywords, but only mjtEmbed is named after the attribute
    assert s.enums["embed"] == ir.EnumDef("embed", [("false", "mjEMBED_FALSE"),
                                                    ("true", "mjEMBED_TRUE"),
                                                    ("auto", "mjEMBED_AUTO")], "mjtEmbed")
    assert "embed (mjtEmbed): false, true, auto" in report.added_enums


def test_keyword_attribute_reuses_an_enum_with_the_same_keywords() -> None:
    base = schema()
    base.enums["FalseTrueAuto"] = ir.EnumDef("FalseTrueAuto", [("false", "0"), ("true", "1"),
                                                               ("auto", "2")])
    base.elements["body"].attributes.append(attr("x", "keyword", enum="FalseTrueAuto"))
    s, report = sync(base, wheel(PRINT_SCHEMA.replace("name pos", "name pos x")), FACTS)
    assert s.elements["texture"].attribute("embed").enum == "FalseTrueAuto"
    assert "embed" not in s.enums and report.added_enums == []


def test_removes_attribute_and_its_constraints(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert names(s, "geom") == ["name", "class", "size"]
    assert s.elements["geom"].constraints == []
    assert 'geom@obsolete: real double' in report.removed_attributes
    assert any("dropped constraint exclusive" in n for n in report.notes)


def test_default_projection_copies_the_primary(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    copied = s.elements["default_joint"].attribute("springyield")
    assert copied == s.elements["joint"].attribute("springyield")
    assert names(s, "default_joint") == ["type", "damping", "springyield"]
    assert "default_joint@springyield: real float = \"0\"  [copied from joint]" in \
        report.added_attributes


def test_default_family_row_takes_the_definition_its_family_shares(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert describe(s.elements["default_tendon"].attribute("springyield")) == 'real double = "0"'
    assert any(line.endswith("[shared by fixed, spatial]") for line in report.added_attributes)


# ------------------------------------------------------------------------ rows and children


def test_adds_child_edge_and_new_row(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert children(s, "body")["site"] == ("*", False)
    site = s.elements["site"]
    assert (site.tag, site.class_name, site.projection_of) == ("site", "Site", None)
    assert describe(site.attribute("size")) == 'real double[3] = "0.005 0.005 0.005"'
    assert "body/site *" in report.added_children
    assert "site <site> (Site)" in report.added_rows


def test_removes_child_edges_and_unreachable_rows(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    for parent in ("body", "worldbody", "frame"):
        assert "composite" not in children(s, parent)
        assert f"{parent}/composite *" in report.removed_children
    assert "composite" not in s.elements and report.removed_rows == ["composite"]
    assert "comp" not in s.enums and report.removed_enums == ["comp"]


def test_cardinality_from_the_wheel(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert children(s, "body")["geom"] == ("*", False)
    assert "body/geom: ? -> *" in report.changed_children


def test_new_top_level_section_is_single_when_facts_say_so() -> None:
    facts = Facts(single={"mujoco": ["keyframe"]})
    s, report = sync(schema(), wheel(PRINT_SCHEMA + "   keyframe (*)\n      key (*)   time\n"),
                     facts)
    assert children(s, "mujoco")["keyframe"] == ("*", True)
    assert children(s, "keyframe") == {"key": ("*", False)}
    assert "keyframe <keyframe> (Keyframe)" in report.added_rows
    assert "key@time: string  [UNTYPED]" in report.added_attributes  # undocumented here
    assert sorted(report.untyped) == ["key@time: no XMLreference.rst anchor", SITE_NAME_UNTYPED]


def test_recursion_and_alias_rows_are_kept(synced: tuple[ir.Schema, Report]) -> None:
    s, _ = synced
    assert children(s, "body")["body"] == ("R", False)
    assert {"body", "frame"} <= set(children(s, "body"))
    assert children(s, "default")["default"] == ("R", False)


def test_alias_rows_follow_what_the_body_row_gained_not_its_whole_grammar(
        synced: tuple[ir.Schema, Report]) -> None:
    s, _ = synced
    # <site> is new to bodies, so worldbody and frame get it; worldbody stays without joints
    assert children(s, "worldbody") == {"body": ("*", False), "frame": ("*", False),
                                        "geom": ("*", False), "site": ("*", False)}
    assert "site" in children(s, "frame") and "joint" in children(s, "frame")
    assert names(s, "worldbody") == []


def test_alias_row_attributes_are_what_the_parser_reads_typed_from_the_reference(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert names(s, "frame") == ["name", "scale"]
    assert describe(s.elements["frame"].attribute("scale")) == 'real double[1..3] = "1"'
    assert s.elements["frame"].attribute("scale").anchor == "frame-scale"
    assert 'frame@scale: real double[1..3] = "1"  [frame-scale]' in report.added_attributes


def test_alias_row_attribute_the_parser_no_longer_reads_is_removed() -> None:
    s, report = sync(schema(), wheel(reads={"frame": {"scale"}}), FACTS)
    assert names(s, "frame") == ["scale"]
    assert "frame@name: id<frame>" in report.removed_attributes
    assert "frame@name is documented (frame-name) but the parser does not read it" in \
        report.notes


def test_alias_row_attribute_nothing_types_is_untyped_until_facts_do() -> None:
    reads = {"frame": {"name", "scale", "pos"}}
    s, report = sync(schema(), wheel(reads=reads), FACTS)
    assert names(s, "frame") == ["name", "scale", "pos"]
    assert "frame@pos: no XMLreference.rst anchor" in report.untyped
    facts = Facts(single=FACTS.single, attributes=[AttributeOverride(
        "frame", "pos", kind="real", dtype="double", arity=(3, 3), reason="r")])
    s, report = sync(schema(), wheel(reads=reads), facts)
    assert describe(s.elements["frame"].attribute("pos")) == "real double[3]"
    assert "frame@pos: real double[3]  [facts.toml]" in report.added_attributes


def test_alias_rows_are_left_alone_without_a_parser() -> None:
    bare = Wheel("2.0", parse_print_schema(PRINT_SCHEMA), ENUMS, parse_reference(REFERENCE))
    s, report = sync(schema(), bare, FACTS)
    assert names(s, "frame") == ["name"]
    assert "frame: attributes not checked (the wheel has no parser)" in report.notes


def test_new_default_child_is_a_projection_of_its_primary(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    texture = s.elements["default_texture"]
    assert (texture.tag, texture.class_name, texture.projection_of) == (
        "texture", "DefaultTexture", "texture")
    assert names(s, "default_texture") == ["type"]
    assert texture.attributes[0] == s.elements["texture"].attribute("type")
    assert children(s, "default")["default_texture"] == ("?", True)
    assert "default_texture <texture> (DefaultTexture), projection of texture" in \
        report.added_rows


# ----------------------------------------------------------------- untyped, enums, facts


def test_untyped_attribute_is_added_as_a_string_and_reported(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    # documented as a string, but every other "name" is an identifier: no namespace to guess
    assert s.elements["site"].attribute("name").kind == "string"
    assert report.untyped == [SITE_NAME_UNTYPED]
    assert "UNTYPED" in report.format()


def test_untyped_attribute_stays_loud_until_facts_type_it(
        synced: tuple[ir.Schema, Report]) -> None:
    s, _ = synced
    name = s.elements["site"].attribute("name")
    assert name.doc.startswith("UNTYPED: body-site-name says")
    _, again = sync(s, wheel(), FACTS)
    assert again.untyped == [f"site@name: still a string ({name.doc.removeprefix('UNTYPED: ')})"]
    assert not again.is_empty()
    facts = Facts(single=FACTS.single, attributes=[SITE_NAME_ID])
    typed, report = sync(s, wheel(), facts)
    assert report.untyped == [] and typed.elements["site"].attribute("name").doc == ""
    assert report.changed_attributes == ["site@name: string -> id<site>  [facts.toml]"]


def test_hand_kept_type_from_facts() -> None:
    facts = Facts(single=FACTS.single, attributes=[SITE_NAME_ID])
    s, report = sync(schema(), wheel(), facts)
    assert describe(s.elements["site"].attribute("name")) == "id<site>"
    assert report.untyped == []
    assert "site@name: id<site>  [facts.toml]" in report.added_attributes


def test_hand_kept_type_overrides_an_existing_attribute() -> None:
    facts = Facts(attributes=[AttributeOverride("geom", "size", kind="real", dtype="float",
                                                arity=(3, None))])
    s, report = sync(schema(), wheel(), facts)
    assert describe(s.elements["geom"].attribute("size")) == "real float[3..]"
    assert report.changed_attributes == [
        "geom@size: real double[1..3] -> real float[3..]  [facts.toml]"]


def test_override_sets_only_the_fields_it_gives() -> None:
    facts = Facts(attributes=[AttributeOverride("joint", "damping", default="2", doc="d")])
    s, report = sync(schema(), wheel(), facts)
    damping = s.elements["joint"].attribute("damping")
    assert (describe(damping), damping.doc) == ('real double = "2"', "d")
    assert 'joint@damping: real double -> real double = "2"  [facts.toml]' in \
        report.changed_attributes


def test_override_on_a_primary_reaches_its_default_projection() -> None:
    facts = Facts(attributes=[AttributeOverride("joint", "damping", dtype="float",
                                                required=True)])
    s, _ = sync(schema(), wheel(), facts)
    assert describe(s.elements["joint"].attribute("damping")) == "real float (required)"
    assert describe(s.elements["default_joint"].attribute("damping")) == "real float"


def test_override_without_a_kind_does_not_type_a_new_attribute() -> None:
    facts = Facts(single=FACTS.single,
                  attributes=[AttributeOverride("site", "name", doc="its name")])
    s, report = sync(schema(), wheel(), facts)
    assert s.elements["site"].attribute("name").kind == "string"
    assert s.elements["site"].attribute("name").doc == "its name"
    assert report.untyped == [SITE_NAME_UNTYPED]


def test_flags_taking_keywords_alone_keep_their_enums() -> None:
    # composite (the only user of enum comp) is gone from the wheel; flags taking comp's
    # keywords alone keep it
    facts = Facts(attributes=[AttributeOverride("joint", "type", kind="flags",
                                                alone=("comp",), ordered=True)])
    s, report = sync(schema(), wheel(), facts)
    assert describe(s.elements["joint"].attribute("type")) == \
        'flags<jointtype> or alone <comp> (ordered) = "hinge"'
    assert describe(s.elements["default_joint"].attribute("type")) == \
        'flags<jointtype> or alone <comp> (ordered) = "hinge"'
    assert "comp" in s.enums and "comp" not in report.removed_enums
    assert ('joint@type: keyword<jointtype> = "hinge" -> flags<jointtype> or alone <comp> '
            '(ordered) = "hinge"  [facts.toml]') in report.changed_attributes
    again, second = sync(s, wheel(), facts)
    assert second.changed_attributes == [] and ir.dumps(again) == ir.dumps(s)
    assert ir.loads(ir.dumps(s)).elements["joint"].attribute("type").alone == ["comp"]


def test_enum_facts_add_enums_and_replace_keywords() -> None:
    facts = Facts(enums=[
        EnumFact("jointtype", (("hinge", "mjJNT_HINGE"), ("slide", "mjJNT_SLIDE")), reason="r"),
        EnumFact("extra", (("x", "mjLIMITED_FALSE"),), ctype="mjtLimited", reason="r")],
        attributes=[AttributeOverride("texture", "type", kind="flags", alone=("extra",))])
    s, report = sync(schema(), wheel(), facts)
    assert s.enums["jointtype"].values == [("hinge", "mjJNT_HINGE"), ("slide", "mjJNT_SLIDE")]
    assert s.enums["jointtype"].ctype == "mjtJoint"  # left out: as the schema had it
    assert s.enums["extra"] == ir.EnumDef("extra", [("x", "mjLIMITED_FALSE")], "mjtLimited")
    assert "extra (mjtLimited): x  [facts.toml]" in report.added_enums
    assert report.changed_enums == ["jointtype: - gone  [facts.toml]"]
    again, second = sync(s, wheel(), facts)
    assert ir.dumps(again) == ir.dumps(s)
    assert second.added_enums == second.changed_enums == []
    reordered = Facts(enums=[EnumFact("jointtype", (("slide", "mjJNT_SLIDE"),
                                                    ("hinge", "mjJNT_HINGE")), reason="r")])
    _, third = sync(s, wheel(), reordered)
    assert third.changed_enums == ["jointtype: keyword order  [facts.toml]"]


@pytest.mark.parametrize("override, message", [
    (AttributeOverride("joint", "nope", kind="string"),
     "schema/facts.toml [[attribute]] joint@nope: the synced schema has no such attribute"),
    (AttributeOverride("nope", "x", kind="string"),
     "schema/facts.toml [[attribute]] nope@x: the synced schema has no such attribute"),
    (AttributeOverride("site", "name", kind="ref"),
     "schema/facts.toml [[attribute]] site@name: ref attribute needs a namespace"),
    (AttributeOverride("joint", "type", kind="real"),
     "schema/facts.toml [[attribute]] joint@type: a real attribute needs dtype 'double' or 'float'"),
    (AttributeOverride("joint", "type", kind="flags", alone=("nope",)),
     "schema/facts.toml [[attribute]] joint@type: alone names undeclared enum 'nope'"),
])
def test_malformed_overrides(override: AttributeOverride, message: str) -> None:
    with pytest.raises(FactsError) as info:
        sync(schema(), wheel(), Facts(single=FACTS.single, attributes=[override]))
    assert str(info.value).startswith(message)


def test_enum_constants_missing_from_the_wheel_are_dropped(
        synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert s.enums["jointtype"].keywords == ["slide", "hinge"]
    assert report.changed_enums == ["jointtype: - gone (mjJNT_GONE is not in mjtJoint)"]


def test_anchors(synced: tuple[ir.Schema, Report]) -> None:
    s, _ = synced
    assert s.elements["joint"].attribute("type").anchor == "body-joint-type"
    assert s.elements["joint"].anchor == "body-joint"
    assert s.elements["body"].anchor == "body"
    assert s.elements["worldbody"].anchor == "body"  # through its alias
    # default-class rows link to the primary's documentation
    assert s.elements["default_joint"].attribute("type").anchor == "body-joint-type"
    assert s.elements["default_joint"].anchor == "default-joint"


# -------------------------------------------------------------------------------- report


def test_version_and_report(synced: tuple[ir.Schema, Report]) -> None:
    s, report = synced
    assert s.mujoco_version == "2.0" and report.version == ("1.0", "2.0")
    text = report.format()
    assert text.startswith("mujoco_version: 1.0 -> 2.0\nrows:\n  + ")
    assert "\n  - body/composite *\n" in text and "\n  ~ body/geom: ? -> *\n" in text
    assert not report.is_empty()


def test_sync_is_idempotent_and_leaves_its_input_alone() -> None:
    facts = Facts(single=FACTS.single, attributes=[SITE_NAME_ID])
    s, _ = sync(schema(), wheel(), facts)
    again, report = sync(s, wheel(), facts)
    assert report.is_empty(), report.format()
    assert ir.dumps(again) == ir.dumps(s)
    assert report.format().startswith("schema agrees with the installed mujoco")
    assert "composite" in schema().elements  # the input was copied


def test_wheel_without_reference_keeps_anchors() -> None:
    s, _ = sync(schema(), wheel(), FACTS)
    bare = Wheel("2.0", parse_print_schema(PRINT_SCHEMA), ENUMS)
    again, report = sync(s, bare, FACTS)
    assert report.anchors == 0
    assert again.elements["joint"].attribute("type").anchor == "body-joint-type"
