"""Readers of the installed wheel: the printSchema tree, the reference's anchors and entries,
and the ``:at-val:`` type parser, on small inline snippets."""

from __future__ import annotations

import textwrap

import pytest

from codegen.wheel import (
    AtVal,
    PrintSchemaError,
    RstEntry,
    WheelRow,
    parse_at_val,
    parse_print_schema,
    parse_reference,
    read_constants,
    read_wheel,
    spec_defaults,
)

# ------------------------------------------------------------------------- printSchema

PRINT_SCHEMA = """\
mujoco (!)                    model 
   compiler (*)               alignfree angle assetdir autolimits 
                              balanceinertia boundinertia 
      lengthrange (?)         accel interval 
   default (R)                class 
      joint (?)               axis damping 
   (world)body (R)            axisangle childclass 
      inertial (?)            mass pos 
      geom (*)                size type 
         plugin (*)           instance plugin 
            config (*)        key value 
   keyframe (*)               
      key (*)                 qpos time 
"""


def test_print_schema_tree() -> None:
    root = parse_print_schema(PRINT_SCHEMA)
    assert (root.tag, root.card, root.attributes) == ("mujoco", "!", ("model",))
    assert [c.tag for c in root.children] == ["compiler", "default", "(world)body", "keyframe"]
    compiler = root.children[0]
    assert compiler.attributes == ("alignfree", "angle", "assetdir", "autolimits",
                                   "balanceinertia", "boundinertia")
    assert compiler.children == (WheelRow("lengthrange", "?", ("accel", "interval")),)
    body = root.children[2]
    assert body.card == "R"
    assert [c.tag for c in body.children] == ["inertial", "geom"]
    config = body.children[1].children[0].children[0]
    assert (config.tag, config.card, config.attributes) == ("config", "*", ("key", "value"))
    keyframe = root.children[3]
    assert keyframe.attributes == ()
    assert keyframe.children[0].attributes == ("qpos", "time")


def test_world_body_spellings_and_child_lookup() -> None:
    root = parse_print_schema(PRINT_SCHEMA)
    body = root.child("worldbody")
    assert body is not None and body.tag == "(world)body"
    assert body.spellings == ("worldbody", "body")
    assert root.child("body") is body
    assert root.child("compiler") is not None and root.child("geom") is None
    assert WheelRow("geom", "*").spellings == ("geom",)
    assert [r.tag for r in root.walk()][:4] == ["mujoco", "compiler", "lengthrange", "default"]


def test_print_schema_tolerates_blank_lines_and_padding() -> None:
    text = "\nmujoco (!)   a\n\n   option (*)    b \n                 c\n"
    root = parse_print_schema(text)
    assert root.children == (WheelRow("option", "*", ("b", "c")),)


@pytest.mark.parametrize("text, message", [
    ("", "no rows"),
    ("   orphan attributes\nmujoco (!)", "line 1: attributes before the first row"),
    ("mujoco (!)\nother (!)", "line 2: second root row 'other'"),
])
def test_print_schema_errors(text: str, message: str) -> None:
    with pytest.raises(PrintSchemaError, match=message):
        parse_print_schema(text)


# ------------------------------------------------------------------------------ reference

REFERENCE = textwrap.dedent("""\
    .. _body:

    **body** |R|
    ^^^^^^^^^^^^

    Prose about bodies.

    .. _body-name:

    :at:`name`: :at-val:`string, optional`
       Name of the body.

    .. _body-quat:
    .. _body-euler:

    :at:`quat`, :at:`euler`
       Orientation, see :ref:`COrientation`.

    .. _body-joint-solreflimit:
    .. _body-joint-solimplimit:

    :at:`solreflimit`, :at:`solimplimit`: :at-val:`real, "0"`
       Shared entry.

    .. _tendon-spatial-springyield:

    :at:`springyield`: :at-val:`real, "0"`
       Yield.

    .. _tendon-fixed:

    **fixed**

    .. _tendon-fixed-name:
    .. _tendon-fixed-springyield:

    .. |tendon/fixed attrib list| replace::
       :at:`name`, :at:`springyield`

    |tendon/fixed attrib list|
       Same as in the :ref:`spatial <tendon-spatial>` element.

    .. _default-joint:
    .. _default-joint-type:

    :el-prefix:`default/` |-| **joint** |?|
    ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^
""")


def test_reference_anchors_in_document_order() -> None:
    ref = parse_reference(REFERENCE)
    assert ref.anchors[:4] == ("body", "body-name", "body-quat", "body-euler")
    assert "tendon-fixed" in ref and "nope" not in ref
    assert ref.position("body") == 0 and ref.position("body-quat") == 2
    assert ref.position("nope") == len(ref.anchors)


def test_reference_entries() -> None:
    ref = parse_reference(REFERENCE)
    assert "body" not in ref.entries  # an element: prose follows the anchor
    assert ref.entries["body-name"] == RstEntry(at_val="string, optional")
    # one entry for several anchors; a shared entry without :at-val: types nothing
    assert ref.entries["body-quat"] == ref.entries["body-euler"] == RstEntry()
    assert ref.at_val("body-joint-solimplimit") == 'real, "0"'
    assert "default-joint-type" not in ref.entries  # anchors before a heading


def test_reference_names_every_attribute_it_spells() -> None:
    ref = parse_reference(REFERENCE + "Prose naming :at:`fromto` and :at:`data =`.\n")
    # entries, shared entries, substitution definitions and prose; not what is no name
    assert ref.names == {"name", "quat", "euler", "solreflimit", "solimplimit", "springyield",
                         "fromto"}


def test_reference_substituted_attribute_lists_defer_to_another_element() -> None:
    ref = parse_reference(REFERENCE)
    assert ref.entries["tendon-fixed-springyield"] == RstEntry(same_as="tendon-spatial")
    assert ref.at_val("tendon-fixed-springyield") == 'real, "0"'
    assert ref.at_val("tendon-fixed-name") is None  # tendon-spatial-name is not documented


# ------------------------------------------------------------------------------- :at-val:


@pytest.mark.parametrize("text, expected", [
    ('real, "0"', AtVal("real", default="0")),
    ('real(3), "0 0 0"', AtVal("real", (3, 3), default="0 0 0")),
    ('real(1), "0"', AtVal("real", default="0")),
    ('real(1 or 3), "1"', AtVal("real", (1, 3), default="1")),
    ('real(1 or 2), "0"', AtVal("real", (1, 2), default="0")),
    ("real(4), required", AtVal("real", (4, 4), required=True)),
    ("real(3), optional", AtVal("real", (3, 3))),
    ('real(10), "1 0 ... 0"', AtVal("real", (10, 10))),
    ('real(nuser_geom), "0 0 ..."', AtVal("real", (0, None))),
    ("real(3*nvert), optional", AtVal("real", (0, None))),
    ("real(mjModel.nplastic), default = initial plastic state", AtVal("real", (0, None))),
    ("int((dim+1)*nelem), required", AtVal("int", (0, None), required=True)),
    ("int", AtVal("int")),
    ('int, "-1"', AtVal("int", default="-1")),
    ('int(2), "0 5"', AtVal("int", (2, 2), default="0 5")),
    ('[false, true], "true"', AtVal("bool", default="true")),
    ('[true, false], "false"', AtVal("bool", default="false")),
    ('bool, "false"', AtVal("bool", default="false")),
    ('[disable, enable], "enable"', AtVal("keyword", keywords=("disable", "enable"),
                                          default="enable")),
    ('[2d, cube, skybox], "cube"', AtVal("keyword", keywords=("2d", "cube", "skybox"),
                                         default="cube")),
    ("[body, xbody, geom], required", AtVal("keyword", keywords=("body", "xbody", "geom"),
                                            required=True)),
    ("[trilinear, quadratic], optional", AtVal("keyword", keywords=("trilinear", "quadratic"))),
    ("string, optional", AtVal("string")),
    ("string, required", AtVal("string", required=True)),
    ('string, "hello world"', AtVal("string", default="hello world")),
    ("string", AtVal("string")),
])
def test_at_val_types(text: str, expected: AtVal) -> None:
    assert parse_at_val(text) == expected


@pytest.mark.parametrize("text", [
    '"0"',  # no type
    "(any element type that can be named), required",
    '[radian, degree], "degree" for MJCF, always "radian" for URDF',
    "string, required for slider-crank transmission",
    "string(nvert or 1), required",  # strings have no count
    'real, "0 0 0"',  # a scalar with a vector default: the entry contradicts itself
    'int, "0.5"',
    '[false, true], "maybe"',  # the default is not a keyword
    "[0, 1]",  # numbers are not keywords
    "[single]",
    "real(0)",
    "real(3) trailing",
    "[a, b] trailing",
    "float",
])
def test_at_val_unrecognised_is_untyped(text: str) -> None:
    assert parse_at_val(text) is None


# ------------------------------------------------------------------------ installed wheel


def test_installed_wheel_reads() -> None:
    wheel = read_wheel()
    assert wheel.schema.tag == "mujoco" and wheel.schema.card == "!"
    body = wheel.schema.child("worldbody")
    assert body is not None and body.card == "R" and "pos" in body.attributes
    assert wheel.enums["mjtJoint"]["mjJNT_HINGE"] == 3
    assert wheel.structs["mjsGeom"]["rgba"] == "float"
    assert wheel.structs["mjsJoint"]["pos"] == "double"
    assert wheel.reference.at_val("body-joint-type") is not None
    assert read_constants()["mjNREF"] == 2
    assert wheel.parser is not None and wheel.parser("<mujoco/>").error is None


def test_spec_defaults_are_plain_values() -> None:
    defaults = spec_defaults()
    assert {"joint", "geom", "site", "camera", "light", "material", "mesh", "pair",
            "equality", "tendon", "actuator"} <= set(defaults)
    joint = defaults["joint"]
    assert joint["type"] == 3  # mjJNT_HINGE
    assert joint["axis"] == (0.0, 0.0, 1.0)
    assert joint["solref_limit"] == (0.02, 1.0)
    assert defaults["geom"]["contype"] == 1 and defaults["geom"]["castshadow"] is True
