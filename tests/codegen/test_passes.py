"""Facts loading and the normalisation passes from the grammar's IR to the renderer's."""

from __future__ import annotations

import copy
import dataclasses
import textwrap
from pathlib import Path

import pytest

from codegen import ir, passes, render
from codegen.facts import AttributeOverride, EnumFact, Facts, FactsError, load_facts, parse_facts
from codegen.grammar import parse_grammar
from codegen.passes import normalize

REFERENCE = Path("/work/shared/reference/mjcf.schema")

GRAMMAR = """\
    enum jt { hinge = 1
      slide = 2 }
    enum unused { x = 1 }
    element mujoco {
      model : ref<model>
      child default R
      child body R
      child asset *
    }
    element asset {
      child model *
    }
    element model {
      name : id<model>
    }
    element default {
      class : id<default>
      child default R
      child joint ?
      child default_equality ?
    }
    element body : mjsBody {
      name : id<body>
      child body R
      child joint *
    }
    element worldbody (alias=body) {
      child body *
    }
    element joint : mjsJoint {
      name  : id<joint>
      class : ref<default>
      type  : enum<jt> = hinge
      body  : ref<body> (nodefault)
      axis  : double[3] (required)   # the axis
      exclusive type axis
    }
    element default_equality (xml=equality) {
      active : bool
    }
    element cycle_a {
      child cycle_b ?
    }
    element cycle_b {
      child cycle_a ?
    }
    """

FACTS = Facts(
    root_children={"body": "worldbody"},
    single={"mujoco": ["default", "worldbody", "asset"]},
    attributes=[AttributeOverride("mujoco", "model", kind="string")],
)


def grammar(text: str = GRAMMAR) -> ir.Schema:
    return parse_grammar(textwrap.dedent(text), "t.schema")


def normalized(facts: Facts = FACTS, text: str = GRAMMAR) -> ir.Schema:
    return normalize(grammar(text), facts)


# ------------------------------------------------------------------------------- facts


def test_repository_facts_load() -> None:
    facts = load_facts()
    assert facts.root_children["body"] == "worldbody"
    assert "worldbody" in facts.single["mujoco"]
    model = next(o for o in facts.attributes if (o.element, o.name) == ("mujoco", "model"))
    assert model.kind == "string"


def test_every_facts_table_is_parsed_into_typed_fields() -> None:
    facts = parse_facts(textwrap.dedent("""\
        [root_children]
        body = "worldbody"

        [single]
        mujoco = ["option"]

        [[attribute]]
        element = "joint"
        name = "axis"
        arity = [3, 3]
        required = false
        reason = "because"

        [[attribute]]
        element = "key"
        name = "qpos"
        kind = "real"
        dtype = "double"
        arity = [0]
        reason = "any number"

        [directories]
        "mesh@file" = ["meshdir", "assetdir"]

        [class_names]
        asset = "AssetSection"

        [compose]
        default = "nest"

        [attachment_sites]
        site = "dm_control does"

        [default_rows]
        default_tendon = ["spatial", "fixed"]
        """), "f.toml")
    assert facts == Facts(
        root_children={"body": "worldbody"},
        single={"mujoco": ["option"]},
        attributes=[AttributeOverride("joint", "axis", arity=(3, 3), required=False,
                                      reason="because"),
                    AttributeOverride("key", "qpos", kind="real", dtype="double",
                                      arity=(0, None), reason="any number")],
        directories={("mesh", "file"): ["meshdir", "assetdir"]},
        class_names={"asset": "AssetSection"},
        compose={"default": "nest"},
        attachment_sites={"site": "dm_control does"},
        default_rows={"default_tendon": ["spatial", "fixed"]},
    )


def test_flags_keys_of_an_attribute_entry() -> None:
    facts = parse_facts(ENTRY + 'alone = ["jt", "unused"]\nordered = true\n', "f.toml")
    assert facts.attributes == [AttributeOverride("a", "b", alone=("jt", "unused"), ordered=True,
                                                  reason="r")]


def test_repository_facts_type_input_as_flags_with_keywords_alone() -> None:
    entries = {(o.element, o.name): o for o in load_facts().attributes}
    expected = {"general": ("inputbit", ("inputchart", "inputkeyword")),
                "pid": ("pid_input", ("inputchart",)),  # a pid compiles with no none
                "dcmotor": ("dcmotor_input", ("inputchart", "inputkeyword"))}
    for row, (enum, alone) in expected.items():
        entry = entries[(row, "input")]
        assert (entry.enum, entry.alone, entry.ordered) == (enum, alone, True), row


def test_enum_entries() -> None:
    facts = parse_facts(ENUM + 'ctype = "mjtE"\ndoc = "d"\n' + ENUM.replace('"e"', '"f"'))
    assert facts.enums == [EnumFact("e", (("a", "mjA"),), "mjtE", "d", "r"),
                           EnumFact("f", (("a", "mjA"),), reason="r")]


def test_repository_facts_give_inputbit_the_pressure_token() -> None:
    inputbit = next(e for e in load_facts().enums if e.name == "inputbit")
    assert [k for k, _ in inputbit.values] == ["pos", "vel", "ff", "voltage", "pressure"]
    assert all(e.reason.strip() for e in load_facts().enums)


def test_empty_facts() -> None:
    assert parse_facts("") == Facts()


ENTRY = '[[attribute]]\nelement = "a"\nname = "b"\nreason = "r"\n'
ENUM = '[[enum]]\nname = "e"\nvalues = [["a", "mjA"]]\nreason = "r"\n'


@pytest.mark.parametrize(("text", "message"), [
    ("[root_children\n", "f.toml: Expected ']' at the end of a table declaration"),
    ("[root_childern]\nbody = \"worldbody\"\n",
     ("f.toml: unknown table 'root_childern' (known tables: root_children, single, enum, "
      "attribute, constraint, directories, class_names, compose, attachment_sites, "
      "default_rows, language)")),
    ("[[attribute_type]]\nelement = \"a\"\n", "f.toml: unknown table 'attribute_type'"),
    ("root_children = 3\n", "f.toml: [root_children]: expected a table"),
    ("[root_children]\nbody = 1\n", "f.toml: [root_children] body: expected a string, got 1"),
    ("[single]\nmujoco = \"option\"\n", "f.toml: [single] mujoco: expected a list of strings"),
    ("[single]\nmujoco = [1]\n", "f.toml: [single] mujoco: expected a string, got 1"),
    ("attribute = 1\n", "f.toml: [[attribute]]: expected an array of tables"),
    ("[[attribute]]\nelement = \"a\"\nreason = \"r\"\n",
     "f.toml: [[attribute]] #1: missing key 'name'"),
    ('[[attribute]]\nelement = "a"\nname = "b"\nkind = "string"\n',
     "f.toml: [[attribute]] #1: missing key 'reason'"),
    (ENTRY + 'kin = "string"\n', "f.toml: [[attribute]] #1: unknown key 'kin'"),
    (ENTRY + 'kind = "text"\n',
     ("f.toml: [[attribute]] #1 kind: 'text' is not one of string, file, chars, bool, int, "
     "real, keyword, flags, id, ref")),
    (ENTRY + 'dtype = "single"\n',
     "f.toml: [[attribute]] #1 dtype: 'single' is not one of double, float, int"),
    (ENTRY + "arity = [1, 2, 3]\n",
     "f.toml: [[attribute]] #1 arity: expected [lo, hi] or [lo] integers, got [1, 2, 3]"),
    (ENTRY + "required = 1\n", "f.toml: [[attribute]] #1 required: expected true or false, got 1"),
    (ENTRY + 'alone = "jt"\n', "f.toml: [[attribute]] #1 alone: expected a list of strings"),
    (ENTRY + "alone = []\n",
     "f.toml: [[attribute]] #1 alone: expected a non-empty list of distinct enum names, got []"),
    (ENTRY + 'alone = ["jt", "jt"]\n',
     "f.toml: [[attribute]] #1 alone: expected a non-empty list of distinct enum names"),
    (ENTRY + "ordered = 1\n", "f.toml: [[attribute]] #1 ordered: expected true or false, got 1"),
    (ENTRY + "doc = 2\n", "f.toml: [[attribute]] #1 doc: expected a string, got 2"),
    ('[[attribute]]\nelement = "a"\nname = "b"\nreason = 2\n',
     "f.toml: [[attribute]] #1 reason: expected a string, got 2"),
    (ENTRY + ENTRY, "f.toml: [[attribute]] #2: a second entry for a@b"),
    ("enum = 1\n", "f.toml: [[enum]]: expected an array of tables ([[enum]] entries)"),
    ('[[enum]]\nname = "e"\nreason = "r"\n', "f.toml: [[enum]] #1: missing key 'values'"),
    (ENUM + 'ctyp = "x"\n', "f.toml: [[enum]] #1: unknown key 'ctyp'"),
    (ENUM.replace('[["a", "mjA"]]', '["a"]'),
     ("f.toml: [[enum]] #1 values: expected a non-empty list of [keyword, C constant] string "
      "pairs, got ['a']")),
    (ENUM.replace('[["a", "mjA"]]', "[]"), "f.toml: [[enum]] #1 values: expected a non-empty"),
    (ENUM.replace('[["a", "mjA"]]', '[["a", ""]]'), "f.toml: [[enum]] #1 values: expected"),
    (ENUM.replace('[["a", "mjA"]]', '[["a", "0"], ["a", "1"]]'),
     "f.toml: [[enum]] #1 values: a keyword is listed twice in ['a', 'a']"),
    (ENUM + ENUM, "f.toml: [[enum]] #2: a second entry for enum 'e'"),
    ('[directories]\n"mesh" = ["meshdir"]\n',
     'f.toml: [directories] mesh: expected a key "row@attribute"'),
    ('[directories]\n"mesh@file" = "meshdir"\n',
     "f.toml: [directories] mesh@file: expected a list of strings"),
    ("[class_names]\nasset = 3\n", "f.toml: [class_names] asset: expected a string, got 3"),
    ('[compose]\ndefault = "nested"\n',
     "f.toml: [compose] default: 'nested' is not one of attributes, nest, keyframes"),
    ("[attachment_sites]\nsite = true\n",
     "f.toml: [attachment_sites] site: expected a string, got True"),
    ('[default_rows]\ndefault_tendon = "spatial"\n',
     "f.toml: [default_rows] default_tendon: expected a list of strings"),
])
def test_malformed_facts(text: str, message: str) -> None:
    with pytest.raises(FactsError) as info:
        parse_facts(text, "f.toml")
    assert str(info.value).startswith(message)


def test_repository_facts_entries_all_give_a_reason() -> None:
    assert all(o.reason.strip() for o in load_facts().attributes)


# ---------------------------------------------------------------------- root children


def test_root_body_child_becomes_worldbody() -> None:
    schema = normalized()
    root = schema.elements["mujoco"]
    assert [c.element for c in root.children] == ["default", "worldbody", "asset"]
    assert root.children[1] == ir.ChildDef("worldbody", "R", single=True)
    assert schema.elements["worldbody"].alias == "body"
    assert schema.elements["worldbody"].children == [ir.ChildDef("body", "*", single=False)]


def test_root_children_errors() -> None:
    with pytest.raises(ValueError, match="root 'mujoco' has no child 'nope'"):
        normalized(Facts(root_children={"nope": "worldbody"}))
    with pytest.raises(ValueError, match="no row 'world'"):
        normalized(Facts(root_children={"body": "world"}))


# ----------------------------------------------------------------------------- single


def test_single_names_child_tags() -> None:
    root = normalized().elements["mujoco"]
    assert all(c.single for c in root.children)
    plain = normalized(Facts(root_children={"body": "worldbody"})).elements["mujoco"]
    assert [c.single for c in plain.children] == [False, False, False]


def test_single_errors() -> None:
    with pytest.raises(ValueError, match="row 'mujoco' has no child tag 'option'"):
        normalized(Facts(single={"mujoco": ["option"]}))
    with pytest.raises(ValueError, match="single: no row 'nope'"):
        normalized(Facts(single={"nope": ["a"]}))


# -------------------------------------------------------------------------- overrides


def test_override_changes_kind_and_forgets_namespace() -> None:
    model = normalized().elements["mujoco"].attribute("model")
    assert (model.kind, model.namespace) == ("string", None)


def test_override_on_primary_reaches_its_projection() -> None:
    facts = Facts(attributes=[AttributeOverride("joint", "type", default="slide", doc="d")])
    schema = normalized(facts)
    for row in ("joint", "default_joint"):
        assert (schema.elements[row].attribute("type").default,
                schema.elements[row].attribute("type").doc) == ("slide", "d")


def test_override_may_name_a_projection_row() -> None:
    facts = Facts(attributes=[AttributeOverride("default_joint", "axis", arity=(1, 3))])
    schema = normalized(facts)
    assert schema.elements["default_joint"].attribute("axis").arity == (1, 3)
    assert schema.elements["joint"].attribute("axis").arity == (3, 3)


def test_override_to_keyword_needs_an_enum() -> None:
    facts = Facts(attributes=[AttributeOverride("joint", "body", kind="keyword", enum="jt")])
    body = normalized(facts).elements["joint"].attribute("body")
    assert (body.kind, body.enum, body.namespace) == ("keyword", "jt", None)
    with pytest.raises(ValueError, match=r"joint@body: keyword attribute needs a declared enum"):
        normalized(Facts(attributes=[AttributeOverride("joint", "body", kind="keyword")]))


@pytest.mark.parametrize(("override", "message"), [
    (AttributeOverride("joint", "type", kind="real"),
     "schema/facts.toml [[attribute]] joint@type: a real attribute needs dtype 'double' or 'float'"),
    (AttributeOverride("joint", "type", kind="chars"),
     "schema/facts.toml [[attribute]] joint@type: chars attribute needs a bounded arity"),
    (AttributeOverride("joint", "type", kind="ref"),
     "schema/facts.toml [[attribute]] joint@type: ref attribute needs a namespace"),
])
def test_override_errors(override: AttributeOverride, message: str) -> None:
    with pytest.raises(FactsError) as info:
        normalized(Facts(root_children=FACTS.root_children, attributes=[override]))
    assert str(info.value) == message


def test_override_naming_no_grammar_attribute_is_left_to_sync() -> None:
    # the installed wheel may add the attribute; sync types it or rejects the entry
    facts = Facts(root_children=FACTS.root_children, attributes=[
        AttributeOverride("joint", "nope", kind="string"),
        AttributeOverride("nope", "x", kind="string")])
    assert normalized(facts) == normalized(Facts(root_children=FACTS.root_children))
    with pytest.raises(ValueError, match="joint@nope: row 'joint' has no such attribute"):
        passes.apply_overrides(normalized(facts), facts.attributes)


FLAGS = AttributeOverride("joint", "type", kind="flags", alone=("unused",), ordered=True)


def test_override_to_flags_taking_keywords_alone_reaches_the_projection() -> None:
    schema = normalized(Facts(root_children=FACTS.root_children, attributes=[FLAGS]))
    for row in ("joint", "default_joint"):
        joint_type = schema.elements[row].attribute("type")
        assert (joint_type.kind, joint_type.enum, joint_type.alone, joint_type.ordered) == (
            "flags", "jt", ["unused"], True)
    assert set(schema.enums) == {"jt", "unused"}  # an enum used only alone is kept
    passes.check(schema)


def test_a_kind_other_than_flags_forgets_alone_and_order() -> None:
    schema = normalized(Facts(root_children=FACTS.root_children, attributes=[FLAGS]))
    joint_type = schema.elements["joint"].attribute("type")
    passes.apply_override(joint_type, AttributeOverride("joint", "type", kind="keyword"), schema)
    assert (joint_type.kind, joint_type.enum, joint_type.alone, joint_type.ordered) == (
        "keyword", "jt", None, False)


@pytest.mark.parametrize(("override", "message"), [
    (AttributeOverride("joint", "type", alone=("unused",)),
     "only flags take keywords alone or in order, not a keyword attribute"),
    (AttributeOverride("joint", "type", ordered=True),
     "only flags take keywords alone or in order, not a keyword attribute"),
    (AttributeOverride("joint", "type", kind="flags", alone=("nope",)),
     "alone names undeclared enum 'nope'"),
    (AttributeOverride("joint", "type", kind="flags", alone=("jt",)),
     "keyword 'hinge' of enum 'jt' is also one of enum 'jt': a value would be ambiguous"),
])
def test_keywords_alone_errors(override: AttributeOverride, message: str) -> None:
    with pytest.raises(FactsError) as info:
        normalized(Facts(root_children=FACTS.root_children, attributes=[override]))
    assert str(info.value) == f"schema/facts.toml [[attribute]] joint@type: {message}"


def test_check_keywords_alone() -> None:
    schema = normalized(Facts(root_children=FACTS.root_children, attributes=[FLAGS]))
    schema.elements["default_joint"].attribute("type").kind = "keyword"
    schema.elements["joint"].attribute("type").alone = ["unused", "gone"]
    assert check_message(schema) == (
        "2 schema problem(s):\n"
        "  row 'joint': attribute 'type' uses missing enum 'gone'\n"
        "  row 'default_joint': attribute 'type': only flags take keywords alone or in order, "
        "not a keyword attribute")


def test_enum_facts_replace_keywords_or_add_an_enum() -> None:
    facts = Facts(root_children=FACTS.root_children,
                  enums=[EnumFact("jt", (("hinge", "1"), ("slide", "2"), ("ball", "3")),
                                  reason="r"),
                         EnumFact("extra", (("x", "mjX"),), ctype="mjtX", doc="d", reason="r")],
                  attributes=[AttributeOverride("joint", "type", kind="flags", alone=("extra",),
                                                reason="r")])
    schema = normalized(facts)
    assert schema.enums["jt"] == ir.EnumDef("jt", [("hinge", "1"), ("slide", "2"),
                                                    ("ball", "3")])
    assert schema.enums["extra"] == ir.EnumDef("extra", [("x", "mjX")], "mjtX", "d")
    assert schema.elements["default_joint"].attribute("type").alone == ["extra"]


def test_override_to_int_sets_dtype() -> None:
    facts = Facts(attributes=[AttributeOverride("joint", "type", kind="int")])
    joint_type = normalized(facts).elements["joint"].attribute("type")
    assert (joint_type.kind, joint_type.dtype, joint_type.enum) == ("int", "int", None)


# ------------------------------------------------------------------ default projections


def test_default_projection_rows() -> None:
    schema = normalized()
    row = schema.elements["default_joint"]
    assert (row.tag, row.class_name, row.projection_of, row.struct) == (
        "joint", "DefaultJoint", "joint", "mjsJoint")
    assert [a.name for a in row.attributes] == ["type", "axis"]  # no name, class, nodefault
    axis = row.attribute("axis")
    assert (axis.required, axis.arity, axis.doc) == (False, (3, 3), "the axis")
    assert schema.elements["joint"].attribute("axis").required
    assert row.children == [] and row.constraints == []
    assert row.attribute("type") is not schema.elements["joint"].attribute("type")


def test_default_row_children() -> None:
    schema = normalized()
    assert schema.elements["default"].children == [
        ir.ChildDef("default", "R", single=False),
        ir.ChildDef("default_joint", "?", single=True),
        ir.ChildDef("default_equality", "?", single=True),
    ]
    assert schema.elements["default_equality"].projection_of is None
    assert schema.elements["default_equality"].tag == "equality"


def test_projection_collision_is_an_error() -> None:
    text = GRAMMAR.replace("child default_equality ?", "child default_equality ?\n"
                                                      "      child default_joint ?")
    text += "    element default_joint (xml=joint) { }\n"
    with pytest.raises(ValueError, match="default projection of 'joint' collides with "
                                         "declared row 'default_joint'"):
        normalized(text=text)


# ------------------------------------------------------------------------------ pruning


def test_unreachable_rows_and_unused_enums_are_dropped() -> None:
    schema = normalized()
    assert "cycle_a" not in schema.elements and "cycle_b" not in schema.elements
    assert set(schema.enums) == {"jt"}
    # without the root route, the worldbody alias row is reached by nothing
    assert "worldbody" not in normalized(Facts()).elements


def test_normalize_leaves_its_input_alone_and_is_idempotent() -> None:
    schema = grammar()
    before = copy.deepcopy(schema)
    once = normalize(schema, FACTS)
    assert schema == before
    assert normalize(once, FACTS) == once


# ------------------------------------------------------------------------------- checks


def check_message(schema: ir.Schema) -> str:
    with pytest.raises(ValueError) as info:
        passes.check(schema)
    return str(info.value)


def test_check_passes_a_clean_schema() -> None:
    passes.check(normalized())


def test_check_class_names_unique() -> None:
    schema = normalized()
    schema.elements["joint"].class_name = "Body"
    assert check_message(schema) == (
        "1 schema problem(s):\n  class name 'Body' is shared by rows 'body', 'joint'")


def test_check_child_tags_unique() -> None:
    schema = normalized()
    schema.elements["default_joint"].tag = "default"
    assert check_message(schema) == (
        "1 schema problem(s):\n  row 'default': children 'default' and 'default_joint' "
        "share tag 'default'")


def test_check_attribute_and_child_python_names() -> None:
    schema = normalized()
    schema.elements["body"].attributes.append(ir.AttributeDef("joint", "joint", "int", "int"))
    assert check_message(schema) == (
        "1 schema problem(s):\n  row 'body': attribute 'joint' and child tag 'joint' share the "
        "Python name 'joint'")


def test_check_reserved_names() -> None:
    """An attribute may not take a runtime name; a child tag that has one takes a trailing
    underscore instead (the rule the renderer applies)."""
    schema = normalized()
    schema.elements["body"].attributes.append(ir.AttributeDef("path", "path", "string"))
    schema.elements["model"].tag = "find"
    assert check_message(schema) == (
        "1 schema problem(s):\n"
        "  row 'body': attribute name 'path' is reserved by the runtime API")
    assert render.child_py_name("find") == "find_"
    assert render.child_py_name("attach") == "attach_"
    assert render.child_py_name("geom") == "geom"


def test_check_dangling_references() -> None:
    schema = normalized()
    schema.elements["body"].children.append(ir.ChildDef("ghost", "*", single=False))
    schema.elements["joint"].attribute("type").enum = "gone"
    assert check_message(schema) == (
        "2 schema problem(s):\n"
        "  row 'body': child names missing row 'ghost'\n"
        "  row 'joint': attribute 'type' uses missing enum 'gone'")


# -------------------------------------------------------------------- the real grammar


@pytest.mark.skipif(not REFERENCE.is_file(), reason="MuJoCo's mjcf.schema is not available")
def test_reference_grammar_normalizes() -> None:
    mujoco = pytest.importorskip("mujoco")
    constants = {k: int(getattr(mujoco, k)) for k in
                 ("mjNREF", "mjNIMP", "mjNDYN", "mjNGAIN", "mjNBIAS", "mjNPOLY")}
    schema = parse_grammar(REFERENCE.read_text(encoding="utf-8"), str(REFERENCE), constants)
    out = normalize(schema, load_facts())
    assert len(out.elements) > 150
    joint_type = out.elements["joint"].attribute("type")
    assert (joint_type.kind, joint_type.enum, joint_type.default) == (
        "keyword", "jointtype", "hinge")
    assert out.elements["geom"].attribute("size").arity == (1, 3)
    default_joint = {a.name for a in out.elements["default_joint"].attributes}
    assert "name" not in default_joint and "class" not in default_joint
    assert "target" in {a.name for a in out.elements["camera"].attributes}
    assert "target" not in {a.name for a in out.elements["default_camera"].attributes}
    assert out.elements["mujoco"].attribute("model").kind == "string"
    assert any(c.element == "worldbody" and c.single for c in out.elements["mujoco"].children)
    assert out.elements["default_equality"].projection_of is None
    assert out.elements["default_geom"].class_name == "DefaultGeom"
    servos = {"general": ("inputbit", ["inputchart", "inputkeyword"]),
              "pid": ("pid_input", ["inputchart"]),
              "dcmotor": ("dcmotor_input", ["inputchart", "inputkeyword"])}
    for tag, (enum, alone) in servos.items():
        for row in (tag, f"default_{tag}"):
            servo_input = out.elements[row].attribute("input")
            assert (servo_input.kind, servo_input.enum, servo_input.alone,
                    servo_input.ordered) == ("flags", enum, alone, True), row
    assert out.elements["site"].attribute("type").enum == "sitetype"
    assert out.enums["inputkeyword"].keywords == ["none"]
    assert out.enums["inputbit"].keywords == ["pos", "vel", "ff", "voltage", "pressure"]


# ---------------------------------------------------------------------- naming facts


def test_naming_facts_are_read_into_the_language() -> None:
    language = load_facts().language
    assert language is not None
    assert language.replicate_copy == "{name}{sep}{index}"
    assert "sensor" in language.copied_with_replicate
    assert language.flexcomp is not None and language.flexcomp.nodes["trilinear"] == 2


def _language_text(flexcomp: str) -> str:
    """The repository's [language] table with another [language.flexcomp]."""
    text = (ir.SCHEMA_DIR / "facts.toml").read_text(encoding="utf-8")
    start = text.index("[language]")
    table = text[start:text.index("[language.flexcomp]")]
    return table + "[language.flexcomp]\n" + flexcomp


FLEXCOMP = ('tag = "flexcomp"\nnamespace = "body"\ndof = "dof"\nrigid = "rigid"\n'
            'vertex_body = "{name}_{vertex}"\nnode_body = "{name}_{i}_{j}_{k}"\n')


@pytest.mark.parametrize(("flexcomp", "message"), [
    (FLEXCOMP, "[language] flexcomp: missing key 'nodes' (a table of integers)"),
    (FLEXCOMP + "nodes = { trilinear = \"2\" }\n",
     "[language] flexcomp nodes trilinear: expected an integer, got '2'"),
    (FLEXCOMP + "nodes = {}\nextra = 1\n", ("[language] flexcomp: unknown key 'extra' (known "
                                           "keys: tag, namespace, dof, rigid, vertex_body, "
                                           "node_body, nodes)")),
])
def test_malformed_naming_facts(flexcomp: str, message: str) -> None:
    with pytest.raises(FactsError) as info:
        parse_facts(_language_text(flexcomp), "f.toml")
    assert str(info.value) == f"f.toml: {message}"


def test_naming_facts_agree_with_the_grammar() -> None:
    schema = ir.load()
    assert passes._naming_fact_problems(schema) == []  # pyright: ignore[reportPrivateUsage]
    broken = copy.deepcopy(schema)
    language = broken.facts()
    assert language.flexcomp is not None
    flexcomp = dataclasses.replace(language.flexcomp, rigid="stiff",
                                   nodes={**language.flexcomp.nodes, "cubic": 4, "linear": 0})
    broken.language = dataclasses.replace(
        language, flexcomp=flexcomp, replicate_copy="{name}{separator}{index}",
        copied_with_replicate=language.copied_with_replicate | {"sensors"},
        name_lists={**language.name_lists, "flex@bodies": "body"},
        merge_rules={**language.merge_rules, "timestep": "min"})
    assert passes._naming_fact_problems(broken) == [  # pyright: ignore[reportPrivateUsage]
        "language replicate_copy: unknown placeholder {separator} (known: index, name, sep)",
        'language merge_rules timestep: expected a key "tag@attribute"',
        "language facts: <flex> has no string attribute 'bodies'",
        "language copied_with_replicate: no root section 'sensors'",
        "language facts: <flexcomp> has no bool attribute 'stiff'",
        "language flexcomp nodes: 'cubic' is no keyword of <flexcomp> dof",
        "language flexcomp nodes: 'linear' is no keyword of <flexcomp> dof",
        "language flexcomp nodes linear: expected a positive integer, got 0",
    ]
