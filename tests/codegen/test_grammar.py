"""The ``mjcf.schema`` reader: every construct of the syntax, and every kind of error."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from codegen import ir
from codegen.grammar import GrammarError, parse_grammar

REFERENCE = Path("/work/shared/reference/mjcf.schema")
CONSTANTS = {"mjNREF": 2, "mjNIMP": 5}


def parse(text: str) -> ir.Schema:
    return parse_grammar(textwrap.dedent(text), "t.schema", CONSTANTS)


def error(text: str, constants: dict[str, int] | None = None) -> str:
    with pytest.raises(GrammarError) as info:
        parse_grammar(textwrap.dedent(text), "t.schema", CONSTANTS if constants is None
                      else constants)
    exc = info.value
    assert str(exc) == f"{exc.path}:{exc.line}: {exc.message}"
    return str(exc)


# ------------------------------------------------------------------------------ enums


def test_enums_with_ctype_quoted_keys_integers_and_docs() -> None:
    schema = parse("""\
        enum joint : mjtJoint {   # joint kinds
          free  = mjJNT_FREE      # six dofs
          hinge = mjJNT_HINGE
        }
        enum tex { "2d" = 0
          "cos(s)" = -1 }
        element mujoco {
          kind : enum<joint>
          t : enum<tex>
        }
        """)
    assert schema.enums["joint"] == ir.EnumDef(
        "joint", [("free", "mjJNT_FREE"), ("hinge", "mjJNT_HINGE")], "mjtJoint", "joint kinds")
    assert schema.enums["tex"] == ir.EnumDef("tex", [("2d", "0"), ("cos(s)", "-1")])


# ------------------------------------------------------------------------ attributes


ATTRIBUTES = """\
    enum jt { hinge = 1
      slide = 2 }
    element mujoco {
      name   : id<thing> (required)
      class  : ref<thing>
      r      : double
      f      : float = 3 (min=0, max=10, positive)
      i      : int = -1
      v4     : double[4] = {1, 0, 0, 0}
      v13    : double[1..3] (dim="1, L, L")
      vref   : double[1..mjNREF] = {0.02, 1} (dim=solref)
      vany   : int[]
      small  : double = 1e-08
      b      : bool = true
      s      : string = "a b" (pattern="[a-z ]+")
      p      : file (nodefault, field=path_)   # where it lives
      c3     : chars[3] (pattern="[xyz]{3}")
      c12    : chars[1..12] (reading=custom, writing=custom)
      k      : enum<jt> = hinge
      ks     : enum<jt>[]
      fl     : flags<jt> = slide
    }
    """


def attr(name: str) -> ir.AttributeDef:
    return parse(ATTRIBUTES).elements["mujoco"].attribute(name)


@pytest.mark.parametrize(("name", "expected"), [
    ("name", ir.AttributeDef("name", "name", "id", namespace="thing", required=True)),
    ("class", ir.AttributeDef("class", "class_", "ref", namespace="thing")),
    ("r", ir.AttributeDef("r", "r", "real", "double")),
    ("f", ir.AttributeDef("f", "f", "real", "float", default="3")),
    ("i", ir.AttributeDef("i", "i", "int", "int", default="-1")),
    ("v4", ir.AttributeDef("v4", "v4", "real", "double", (4, 4), default="1 0 0 0")),
    ("v13", ir.AttributeDef("v13", "v13", "real", "double", (1, 3))),
    ("vref", ir.AttributeDef("vref", "vref", "real", "double", (1, 2), default="0.02 1")),
    ("vany", ir.AttributeDef("vany", "vany", "int", "int", (0, None))),
    ("small", ir.AttributeDef("small", "small", "real", "double", default="1e-08")),
    ("b", ir.AttributeDef("b", "b", "bool", default="true")),
    ("s", ir.AttributeDef("s", "s", "string", default="a b", pattern="[a-z ]+")),
    ("p", ir.AttributeDef("p", "p", "file", nodefault=True, field="path_",
                          doc="where it lives")),
    ("c3", ir.AttributeDef("c3", "c3", "chars", arity=(3, 3), pattern="[xyz]{3}")),
    ("c12", ir.AttributeDef("c12", "c12", "chars", arity=(1, 12))),
    ("k", ir.AttributeDef("k", "k", "keyword", enum="jt", default="hinge")),
    ("ks", ir.AttributeDef("ks", "ks", "flags", enum="jt")),
    ("fl", ir.AttributeDef("fl", "fl", "flags", enum="jt", default="slide")),
])
def test_attribute_types_defaults_and_facets(name: str, expected: ir.AttributeDef) -> None:
    assert attr(name) == expected


def test_attributes_keep_declaration_order() -> None:
    names = [a.name for a in parse(ATTRIBUTES).elements["mujoco"].attributes]
    assert names[:4] == ["name", "class", "r", "f"]
    assert names[-1] == "fl"


def test_any_word_names_an_attribute() -> None:
    schema = parse("""\
        element mujoco {
          child   : int
          use     : int
          element : double[]
          exclusive : bool
          child element *
        }
        element element { }
        """)
    mujoco = schema.elements["mujoco"]
    assert [a.name for a in mujoco.attributes] == ["child", "use", "element", "exclusive"]
    assert mujoco.children == [ir.ChildDef("element", "*", single=False)]


# ------------------------------------------------------------------------------ groups


def test_groups_splice_in_place_and_variants_are_exclusive() -> None:
    schema = parse("""\
        group orientation variant {
          quat  : double[4] = {1, 0, 0, 0}
          euler : double[3]
        }
        group base {
          name : id<body>
          low  : double
          high : double
          together low high
        }
        element mujoco {
          pos : double[3]
          use orientation
          use base
          mass : double
        }
        """)
    mujoco = schema.elements["mujoco"]
    assert [a.name for a in mujoco.attributes] == ["pos", "quat", "euler", "name", "low",
                                                   "high", "mass"]
    assert mujoco.constraints == [
        ir.ConstraintDef("exclusive", [["quat"], ["euler"]]),
        ir.ConstraintDef("together", [["low"], ["high"]]),
    ]


def test_groups_may_use_groups_declared_later() -> None:
    schema = parse("""\
        group outer {
          a : int
          use inner
        }
        element mujoco {
          use outer
        }
        group inner {
          b : int
        }
        """)
    assert [a.name for a in schema.elements["mujoco"].attributes] == ["a", "b"]


def test_spliced_attributes_are_copies() -> None:
    schema = parse("""\
        group g {
          a : int
        }
        element mujoco {
          use g
          child other ?
        }
        element other {
          use g
        }
        """)
    assert schema.elements["mujoco"].attributes[0] is not schema.elements["other"].attributes[0]


# ---------------------------------------------------------------------------- elements


def test_element_header_struct_facets_and_doc() -> None:
    schema = parse("""\
        element mujoco : mjSpec {   # the root
          child body *
          child equality_joint *
          child worldbody *
          child global ?
        }
        element body : mjsBody (control="F L^-2", output=1) {
          child body R
        }
        element worldbody (alias=body) {
          child body *
        }
        element equality_joint : mjsEquality (xml=joint) {
          joint1 : int
        }
        element global : mjVisual (field=global) {
          x : int
        }
        """)
    assert schema.mujoco_version == ""
    assert schema.root == "mujoco"
    mujoco = schema.elements["mujoco"]
    assert (mujoco.tag, mujoco.class_name, mujoco.struct, mujoco.doc) == (
        "mujoco", "RootElement", "mjSpec", "the root")
    joint = schema.elements["equality_joint"]
    assert (joint.tag, joint.class_name, joint.struct) == (
        "joint", "EqualityJoint", "mjsEquality")
    assert schema.elements["worldbody"].alias == "body"
    assert schema.elements["body"].alias is None
    assert schema.elements["global"].struct == "mjVisual"


def test_children_cardinalities_and_forward_references() -> None:
    schema = parse("""\
        element mujoco {
          child a ?
          child b !
          child c *
          child d R   # recursive
        }
        element a { }
        element b { }
        element c { }
        element d {
          child d R
        }
        """)
    assert schema.elements["mujoco"].children == [
        ir.ChildDef("a", "?", single=True),
        ir.ChildDef("b", "!", single=True),
        ir.ChildDef("c", "*", single=False),
        ir.ChildDef("d", "R", single=False),
    ]


def test_set_lines_are_ignored_and_constraints_may_precede_attributes() -> None:
    schema = parse("""\
        element mujoco {
          set type    = mjSENS_TOUCH
          set objtype = 3
          exclusive site1+site2 body1   # semantics cannot mix
          oneof site1+site2 body1
          requires site2 site1
          site1 : string
          site2 : string
          body1 : string
        }
        """)
    mujoco = schema.elements["mujoco"]
    assert [a.name for a in mujoco.attributes] == ["site1", "site2", "body1"]
    assert mujoco.constraints == [
        ir.ConstraintDef("exclusive", [["site1", "site2"], ["body1"]]),
        ir.ConstraintDef("oneof", [["site1", "site2"], ["body1"]]),
        ir.ConstraintDef("requires", [["site2"], ["site1"]]),
    ]


def test_comments_and_blank_lines_anywhere() -> None:
    schema = parse("""\
        # header

        enum e {   # doc
          # between items
          a = 1

        }
        element mujoco {
          # before
          x : enum<e>   # trailing

          # after
        }
        # end""")
    assert schema.elements["mujoco"].attribute("x").doc == "trailing"


def test_single_line_blocks() -> None:
    schema = parse("""\
        enum e { a = 1 }
        element mujoco { x : enum<e> }
        """)
    assert schema.elements["mujoco"].attribute("x").enum == "e"


def test_root_is_the_element_no_other_lists() -> None:
    schema = parse("""\
        element leaf { }
        element top {
          child leaf *
          child top R
        }
        element alias (alias=leaf) { }
        """)
    assert schema.root == "top"
    assert schema.elements["top"].class_name == "RootElement"
    assert schema.elements["leaf"].class_name == "Leaf"


# ----------------------------------------------------------------------------- errors

ROOT = "element mujoco { }\n"

MALFORMED = [
    ("unknown-declaration", "elemnt mujoco { }\n",
     "t.schema:1: expected 'enum', 'group' or 'element', got 'elemnt'"),
    ("bad-character", "element mujoco {\n  a : int @\n}\n",
     "t.schema:2: unexpected character '@'"),
    ("unterminated-string", 'element mujoco {\n  a : string = "abc\n}\n',
     "t.schema:2: unterminated string"),
    ("missing-open-brace", "element mujoco\n  a : int\n}\n",
     "t.schema:1: expected '{' to open element 'mujoco' at the end of the line"),
    ("unterminated-at-eof", "\nelement mujoco {\n  a : int\n",
     "t.schema:2: unterminated element 'mujoco': missing '}' before end of file"),
    ("unterminated-before-declaration", "element mujoco {\n  a : int\nelement b {\n}\n",
     "t.schema:1: unterminated element 'mujoco': missing '}' before line 3"),
    ("unterminated-enum", "enum e {\n  a = 1\n" + ROOT,
     "t.schema:1: unterminated enum 'e': missing '}' before line 3"),
    ("duplicate-element", ROOT + "\n" + ROOT,
     "t.schema:3: duplicate element 'mujoco' (first declared on line 1)"),
    ("duplicate-enum", "enum e { a = 1 }\nenum e { b = 1 }\n" + ROOT,
     "t.schema:2: duplicate enum 'e' (first declared on line 1)"),
    ("duplicate-group", "group g { a : int }\ngroup g { b : int }\n" + ROOT,
     "t.schema:2: duplicate group 'g' (first declared on line 1)"),
    ("duplicate-attribute", "element mujoco {\n  a : int\n  a : double\n}\n",
     "t.schema:3: duplicate attribute 'a' in element 'mujoco', first on line 2"),
    ("duplicate-attribute-via-use", ("group g { a : int }\nelement mujoco {\n  a : int\n"
                                    "  use g\n}\n"),
     "t.schema:4: duplicate attribute 'a' in element 'mujoco' (via use), first on line 3"),
    ("duplicate-keyword", "enum e {\n  a = 1\n  a = 2\n}\n" + ROOT,
     "t.schema:3: duplicate keyword 'a' in enum 'e'"),
    ("empty-enum", "enum e {\n}\n" + ROOT, "t.schema:1: enum 'e' is empty"),
    ("bad-enum-value", "enum e {\n  a = 1.5\n}\n" + ROOT,
     "t.schema:2: expected a C constant or an integer for keyword 'a', got '1.5'"),
    ("bad-enum-keyword", "enum e {\n  2d = 1\n}\n" + ROOT,
     ("t.schema:2: expected an enum keyword, got '2' (quote keywords that are not names, "
     'like "2d")')),
    ("header-junk", "element mujoco mjsX {\n}\n",
     "t.schema:1: expected '{' to open element 'mujoco', got 'mjsX'"),
    ("member-punctuation", "element mujoco {\n  a : int\n  + b\n}\n",
     "t.schema:3: expected an attribute, 'child', 'use', 'set' or a constraint, got '+'"),
    ("unknown-type", "element mujoco {\n  a : doubel\n}\n",
     "t.schema:2: unknown type 'doubel' of attribute 'a'"),
    ("missing-colon-type", "element mujoco {\n  a : = 3\n}\n",
     "t.schema:2: expected a type for attribute 'a', got '='"),
    ("arity-not-increasing", "element mujoco {\n  a : double[3..1]\n}\n",
     "t.schema:2: arity [3..1] of attribute 'a' is not increasing"),
    ("arity-zero", "element mujoco {\n  a : double[0]\n}\n",
     "t.schema:2: arity [0] of attribute 'a' is empty"),
    ("arity-negative", "element mujoco {\n  a : double[-1]\n}\n",
     "t.schema:2: expected a count in the arity of attribute 'a', got '-1'"),
    ("unknown-bound", "element mujoco {\n  a : double[1..mjNFOO]\n}\n",
     "t.schema:2: unknown arity bound 'mjNFOO' of attribute 'a' (pass it in constants)"),
    ("unclosed-arity", "element mujoco {\n  a : double[1..3\n}\n",
     "t.schema:2: expected ']' to close the arity of attribute 'a' at the end of the line"),
    ("unknown-enum", "element mujoco {\n  a : enum<nope>\n}\n",
     "t.schema:2: attribute 'a' uses undeclared enum 'nope'"),
    ("arity-on-ref", "element mujoco {\n  a : id<x>\n  b : ref<x>[2]\n}\n",
     "t.schema:3: ref<x> of attribute 'b' takes no arity"),
    ("enum-list-with-count", "enum e { a = 1 }\nelement mujoco {\n  a : enum<e>[2]\n}\n",
     "t.schema:3: expected ']' after 'enum<e>[' (only '[]' lists are allowed), got '2'"),
    ("unbounded-chars", "element mujoco {\n  a : chars[]\n}\n",
     "t.schema:2: chars attribute 'a' needs a bounded length, e.g. chars[3] or chars[1..12]"),
    ("bool-vector", "element mujoco {\n  a : bool[2]\n}\n",
     "t.schema:2: bool attribute 'a' may not be a vector"),
    ("bad-cardinality", "element mujoco {\n  child a +\n}\nelement a { }\n",
     "t.schema:2: bad cardinality '+' of child 'a': expected one of ? ! * R"),
    ("missing-cardinality", "element mujoco {\n  child a\n}\nelement a { }\n",
     "t.schema:2: missing cardinality of child 'a': expected one of ? ! * R"),
    ("undeclared-child", "element mujoco {\n  child a ?\n  child b ?\n}\nelement a { }\n",
     "t.schema:3: child of 'mujoco' names undeclared element 'b'"),
    ("duplicate-child", "element mujoco {\n  child a ?\n  child a *\n}\nelement a { }\n",
     "t.schema:3: duplicate child 'a' of 'mujoco'"),
    ("unknown-keyword", "element mujoco {\n  chil a ?\n}\n",
     ("t.schema:2: unknown keyword 'chil': expected 'name : type', 'child', 'use', 'set' or "
     "a constraint")),
    ("trailing-junk", "element mujoco {\n  a : int = 3 extra\n}\n",
     "t.schema:2: unexpected 'extra' after the element member on this line"),
    ("two-keywords-on-a-line", "enum e {\n  a = 1 b = 2\n}\n" + ROOT,
     "t.schema:2: unexpected 'b' after keyword 'a'"),
    ("constraint-unknown-attribute", "element mujoco {\n  exclusive a b\n  a : int\n}\n",
     "t.schema:2: constraint 'exclusive' names unknown attribute 'b' of element 'mujoco'"),
    ("constraint-in-group-unknown-attribute", "group g {\n  a : int\n  together a b\n}\n"
                                              + ROOT,
     "t.schema:3: constraint 'together' names unknown attribute 'b' of group 'g'"),
    ("constraint-one-bundle", "element mujoco {\n  oneof a+b\n  a : int\n  b : int\n}\n",
     "t.schema:2: 'oneof' needs at least two attribute bundles"),
    ("constraint-repeats", "element mujoco {\n  exclusive a a+b\n  a : int\n  b : int\n}\n",
     "t.schema:2: 'exclusive' names 'a' twice"),
    ("requires-bundle", ("element mujoco {\n  requires a b+c\n  a : int\n  b : int\n"
                        "  c : int\n}\n"),
     "t.schema:2: 'requires' takes exactly two attributes"),
    ("undeclared-group", "element mujoco {\n  use nope\n}\n",
     "t.schema:2: use of undeclared group 'nope'"),
    ("group-cycle", "group a {\n  use b\n}\ngroup b {\n  use a\n}\n" + ROOT,
     "t.schema:5: group use cycle: a -> b -> a"),
    ("variant-required", "group g variant {\n  a : int (required)\n  b : int\n}\n" + ROOT,
     "t.schema:2: attribute 'a' of variant group 'g' may not be required"),
    ("variant-use", "group h { c : int }\ngroup g variant {\n  a : int\n  use h\n}\n" + ROOT,
     "t.schema:4: variant group 'g' may not 'use' a group"),
    ("child-in-group", "group g {\n  child a ?\n}\n" + ROOT,
     "t.schema:2: 'child' is not allowed in a group"),
    ("set-in-group", "group g {\n  set type = X\n}\n" + ROOT,
     "t.schema:2: 'set' is not allowed in a group"),
    ("empty-group", "group g {\n}\n" + ROOT, "t.schema:1: group 'g' is empty"),
    ("unknown-facet", "element mujoco {\n  a : int (requird)\n}\n",
     "t.schema:2: unknown facet 'requird' of attribute 'a'"),
    ("unknown-element-facet", "element mujoco (tag=x) { }\n",
     "t.schema:1: unknown facet 'tag' of element 'mujoco'"),
    ("duplicate-facet", "element mujoco {\n  a : int (min=0, min=1)\n}\n",
     "t.schema:2: duplicate facet 'min' of attribute 'a'"),
    ("facet-needs-value", "element mujoco {\n  a : int (field)\n}\n",
     "t.schema:2: facet 'field' of attribute 'a' needs a value"),
    ("facet-takes-no-value", "element mujoco {\n  a : int (required=yes)\n}\n",
     "t.schema:2: facet 'required' of attribute 'a' takes no value"),
    ("facet-value-kind", "element mujoco {\n  a : int (min=low)\n}\n",
     "t.schema:2: expected a number as the value of facet 'min' of attribute 'a', got 'low'"),
    ("unclosed-facets", "element mujoco {\n  a : int (min=0\n}\n",
     ("t.schema:2: expected ',' or ')' in the facets of attribute 'a' at the end of the "
     "line")),
    ("min-above-max", "element mujoco {\n  a : int (min=2, max=1)\n}\n",
     "t.schema:2: facet 'min' of attribute 'a' exceeds 'max'"),
    ("numeric-facet-on-text", "element mujoco {\n  a : string (positive)\n}\n",
     "t.schema:2: facet 'positive' needs a numeric attribute, 'a' is string"),
    ("dim-on-int", "element mujoco {\n  a : int (dim=L)\n}\n",
     "t.schema:2: facet 'dim' needs a real-valued attribute, 'a' is int"),
    ("pattern-on-number", 'element mujoco {\n  a : int (pattern="x")\n}\n',
     "t.schema:2: facet 'pattern' needs a text attribute, 'a' is int"),
    ("bad-pattern", 'element mujoco {\n  a : string (pattern="[x")\n}\n',
     "t.schema:2: bad pattern of attribute 'a': unterminated character set at position 0"),
    ("required-with-default", "element mujoco {\n  a : int = 1 (required)\n}\n",
     "t.schema:2: attribute 'a' is required and has a default"),
    ("default-not-keyword", "enum e { a = 1 }\nelement mujoco {\n  k : enum<e> = b\n}\n",
     "t.schema:3: default 'b' of attribute 'k' is not a keyword of enum 'e'"),
    ("default-not-flag", "enum e { a = 1 }\nelement mujoco {\n  k : flags<e> = \"a b\"\n}\n",
     "t.schema:3: default 'a b' of attribute 'k' is not a keyword of enum 'e'"),
    ("bool-default", "element mujoco {\n  a : bool = 1\n}\n",
     "t.schema:2: default of bool attribute 'a' must be true or false"),
    ("string-default", "element mujoco {\n  a : string = 1\n}\n",
     "t.schema:2: default of string attribute 'a' must be text"),
    ("numeric-default", "element mujoco {\n  a : double = big\n}\n",
     "t.schema:2: default of numeric attribute 'a' must be numeric"),
    ("int-default", "element mujoco {\n  a : int = 1.5\n}\n",
     "t.schema:2: default of int attribute 'a' must be integers"),
    ("vector-default-count", "element mujoco {\n  a : double[3] = {0, 0}\n}\n",
     "t.schema:2: default of attribute 'a' has 2 values, arity is [3..3]"),
    ("vector-default-of-scalar", "element mujoco {\n  a : double = {0, 0}\n}\n",
     "t.schema:2: vector default of scalar attribute 'a'"),
    ("default-list-of-names", "element mujoco {\n  a : double[2] = {a, b}\n}\n",
     "t.schema:2: expected a number in the default of 'a', got 'a'"),
    ("missing-default", "element mujoco {\n  a : double =\n}\n",
     "t.schema:2: expected a default value for attribute 'a' at the end of the line"),
    ("ref-default", "element mujoco {\n  name : id<x>\n  a : ref<x> = foo\n}\n",
     "t.schema:3: ref attribute 'a' may not have a default"),
    ("undeclared-namespace", "element mujoco {\n  a : ref<body>\n}\n",
     "t.schema:2: attribute 'a' refers to namespace 'body', which no id<body> declares"),
    ("undeclared-alias", "element mujoco {\n  child w *\n}\nelement w (alias=body) { }\n",
     "t.schema:4: element 'w' is an alias of undeclared element 'body'"),
    ("ambiguous-root", "element a { }\nelement b { }\n",
     "t.schema:2: ambiguous root: 'a' (line 1), 'b' (line 2) are children of no element"),
    ("no-root", "element a {\n  child b ?\n}\nelement b {\n  child a ?\n}\n",
     "t.schema:1: no root element: every element is another's child"),
    ("no-element", "enum e { a = 1 }\n", "t.schema:1: no element declared"),
]


@pytest.mark.parametrize(("text", "message"), [(t, m) for _, t, m in MALFORMED],
                         ids=[i for i, _, _ in MALFORMED])
def test_malformed(text: str, message: str) -> None:
    assert error(text) == message


def test_symbolic_bound_needs_constants() -> None:
    assert error("element mujoco {\n  a : double[1..mjNREF]\n}\n", constants={}) == (
        "t.schema:2: unknown arity bound 'mjNREF' of attribute 'a' (pass it in constants)")


def test_error_attributes_and_default_path() -> None:
    with pytest.raises(GrammarError) as info:
        parse_grammar("element mujoco {\n  a : nope\n}\n")
    assert (info.value.path, info.value.line) == ("<string>", 2)
    assert info.value.message == "unknown type 'nope' of attribute 'a'"
    assert isinstance(info.value, ValueError)


# -------------------------------------------------------------------- the real grammar


@pytest.mark.skipif(not REFERENCE.is_file(), reason="MuJoCo's mjcf.schema is not available")
def test_reference_grammar_parses() -> None:
    mujoco = pytest.importorskip("mujoco")
    constants = {k: int(getattr(mujoco, k)) for k in
                 ("mjNREF", "mjNIMP", "mjNDYN", "mjNGAIN", "mjNBIAS", "mjNPOLY")}
    schema = parse_grammar(REFERENCE.read_text(encoding="utf-8"), str(REFERENCE), constants)
    assert schema.root == "mujoco"
    assert len(schema.elements) > 140
    joint_type = schema.elements["joint"].attribute("type")
    assert (joint_type.kind, joint_type.enum, joint_type.default) == (
        "keyword", "jointtype", "hinge")
    assert schema.elements["geom"].attribute("size").arity == (1, 3)
    assert schema.elements["geom"].attribute("solref").arity == (1, constants["mjNREF"])
    assert schema.elements["equality_joint"].tag == "joint"
    assert schema.elements["body"].constraints[0].kind == "exclusive"
