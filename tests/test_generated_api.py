"""The generated classes cover the installed MuJoCo's grammar, and equal a fresh render.

Coverage is checked two ways: at run time (descriptors and ``add_<tag>`` methods on the
classes) and statically (typed attribute (``pos: _Attr[...]``) / ``add_<tag>`` declarations in
the generated source, which is what mypy, pyright and IDEs read).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from functools import cache

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from codegen import ir, render
from codegen.wheel import WheelRow, read_print_schema, read_reference
from typed_mjcf import Element
from typed_mjcf._core.tree import Attribute, element_class

ELEMENTS_PYI = render.GENERATED_DIR / "elements.pyi"


def test_generated_equals_a_fresh_render() -> None:
    files = render.render(ir.load())
    for name, text in files.items():
        on_disk = (render.GENERATED_DIR / name).read_text(encoding="utf-8")
        assert on_disk == text, f"generated/{name} is stale: run `nox -s generate`"
    on_disk = [p.name for p in render.GENERATED_DIR.iterdir() if p.suffix in (".py", ".pyi")]
    assert sorted(on_disk) == sorted(files)


@cache
def static_members() -> dict[str, set[str]]:
    """Per generated class: the names declared for type checkers (attributes, properties and
    methods)."""
    tree = ast.parse(ELEMENTS_PYI.read_text(encoding="utf-8"))
    members: dict[str, set[str]] = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names: set[str] = set()
            for statement in ast.walk(node):
                if isinstance(statement, ast.FunctionDef):
                    names.add(statement.name)
                elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
                    names.add(statement.target.id)
            for base in node.bases:  # what every class inherits (find, find_all)
                if isinstance(base, ast.Name) and base.id in members:
                    names |= members[base.id]
            members[node.name] = names
    return members


def child_class(cls: type[Element], row: WheelRow) -> tuple[str, type[Element] | None]:
    """The tag and class a printSchema row stands for under ``cls``.

    ``(world)body`` under the root is the <worldbody> section, and its attributes and children
    are those of the <body> rows inside it: the class returned is then ``Body``.
    """
    children = cls.spec.children
    tag = next((t for t in row.spellings if t in children), row.spellings[-1])
    if tag not in children:
        return tag, None
    found = element_class(children[tag].class_name)
    last = row.spellings[-1]
    if last != tag and last in found.spec.children:
        found = element_class(found.spec.children[last].class_name)
    return tag, found


def _pairs(row: WheelRow, cls: type[Element], path: str) -> Iterator[tuple[str, type[Element], str]]:
    for attribute in row.attributes:
        yield path, cls, attribute
    for child in row.children:
        tag, found = child_class(cls, child)
        assert found is not None, f"{path}: <{tag}> is missing from {cls.__name__}"
        yield from _pairs(child, found, f"{path}/{tag}")


def wheel_pairs() -> list[tuple[str, type[Element], str]]:
    root = read_print_schema()
    pairs = list(_pairs(root, mjcf.RootElement, "mujoco"))
    assert len(pairs) > 1500
    return pairs


def test_every_attribute_mujoco_lists_is_a_typed_property() -> None:
    members = static_members()
    missing: list[str] = []
    for path, cls, name in wheel_pairs():
        attribute = cls.spec.by_name.get(name)
        if attribute is None:
            missing.append(f"{path}@{name}: not in {cls.__name__}'s grammar row")
            continue
        if not isinstance(cls.__dict__.get(attribute.py_name), Attribute):
            missing.append(f"{path}@{name}: no run-time descriptor {cls.__name__}.{attribute.py_name}")
        if attribute.py_name not in members[cls.__name__]:
            missing.append(f"{path}@{name}: no typed property {cls.__name__}.{attribute.py_name}")
    assert not missing, "\n".join(missing)


def test_every_legal_child_has_an_add_method() -> None:
    members = static_members()
    missing: list[str] = []
    root = read_print_schema()

    def visit(row: WheelRow, cls: type[Element], path: str) -> None:
        for child in row.children:
            tag, found = child_class(cls, child)
            if found is None:
                missing.append(f"{path}: <{tag}> is not a child of {cls.__name__}")
                continue
            method = f"add_{tag}"
            if not callable(getattr(cls, method, None)) or method not in members[cls.__name__]:
                missing.append(f"{path}: {cls.__name__}.{method} is missing")
            visit(child, found, f"{path}/{tag}")

    visit(root, mjcf.RootElement, "mujoco")
    assert not missing, "\n".join(missing)


@pytest.mark.parametrize(("class_name", "prefix"), [("Frame", "frame-"), ("Replicate", "replicate-")])
def test_frame_and_replicate_attributes_from_the_reference(class_name: str, prefix: str) -> None:
    """mj_printSchema has no rows for frame and replicate; MuJoCo's reference documents them."""
    reference = read_reference()
    documented = {a[len(prefix):] for a in reference.anchors
                  if a.startswith(prefix) and reference.at_val(a) is not None}
    assert documented
    cls = element_class(class_name)
    members = static_members()[class_name]
    for name in sorted(documented):
        attribute = cls.spec.by_name.get(name)
        assert attribute is not None, f"{class_name} lacks {name}"
        assert attribute.py_name in members


def test_worldbody_children_are_a_subset_of_body_children() -> None:
    worldbody = element_class("Worldbody").spec
    body = element_class("Body").spec
    assert set(worldbody.children) <= set(body.children)
    assert not worldbody.attributes


def test_default_rows_are_projections_without_names_or_nodefault_attributes() -> None:
    schema = ir.load()
    for row in schema.elements.values():
        if row.projection_of is None:
            continue
        primary = schema.elements[row.projection_of]
        names = {a.name for a in row.attributes}
        assert "name" not in names and "class" not in names, row.name
        nodefault = {a.name for a in primary.attributes if a.nodefault}
        assert not names & nodefault, (row.name, names & nodefault)


def test_removed_in_4_0_0_is_absent_and_added_is_present() -> None:
    assert "composite" not in mjcf.Body.spec.children
    assert "flexvert" not in mjcf.Equality.spec.children
    for cls, name in [(mjcf.Frame, "scale"), (mjcf.Frame, "massscale"), (mjcf.Joint, "springyield"),
                      (mjcf.Geom, "castshadow"), (mjcf.Texture, "embed"), (mjcf.Key, "plastic")]:
        assert name in cls.spec.by_name
    assert "texture" in mjcf.Default.spec.children
    for name in ("Pid", "Dcmotor", "Flexcomp", "Replicate", "Attach", "DefaultTexture",
                 "EqualityJoint", "FixedJoint", "SpatialGeom", "DefaultGeom"):
        assert hasattr(mjcf, name), name


@pytest.mark.parametrize("class_name", ["Frame", "Replicate"])
def test_frame_and_replicate_take_the_class_the_parser_reads(class_name: str) -> None:
    """MuJoCo's reader takes class= on every child of a body (codegen/probe.py finds it)."""
    attribute = element_class(class_name).spec.by_name["class"]
    assert (attribute.py_name, attribute.kind, attribute.namespace) == ("class_", "ref",
                                                                         "default")
    assert "class_" in static_members()[class_name]


CLASSED = """\
<mujoco>
  <default>
    <default class="wide">
      <geom size="0.3"/>
    </default>
  </default>
  <worldbody>
    <replicate count="2" offset="1 0 0" class="wide">
      <body name="b">
        <geom/>
      </body>
    </replicate>
    <frame pos="0 2 0" class="wide">
      <geom name="g"/>
    </frame>
  </worldbody>
</mujoco>
"""


def first_column(compiled: object, field: str) -> list[float]:
    """A numeric mjModel field by name (typings/ declares only what the library reads)."""
    values = np.asarray(getattr(compiled, field), dtype=np.float64)
    return [float(v) for v in values[:, 0]]


def test_replicate_and_frame_class_parse_export_and_compile() -> None:
    model = mjcf.from_xml_string(CLASSED)
    replicate, frame = model.worldbody.replicate[0], model.worldbody.frame[0]
    wide = model.find("default", "wide")
    assert replicate.class_ is wide and frame.class_ is wide  # references link to the class
    text = model.to_xml_string()
    assert '<replicate count="2" offset="1 0 0" class="wide">' in text
    assert '<frame pos="0 2 0" class="wide">' in text
    compiled = model.compile()
    # both replicas and the framed geom take their size from the class MuJoCo applied
    assert compiled.nbody == 3 and first_column(compiled, "geom_size") == [0.3, 0.3, 0.3]
    assert mjcf.from_xml_string(text).to_xml_string() == text


def test_replicate_and_frame_class_through_the_typed_api() -> None:
    model = mjcf.RootElement()
    wide = model.default.add_default(class_="wide")
    wide.geom.size = (0.3,)
    replicate = model.worldbody.add_replicate(count=2, offset=(1, 0, 0), class_=wide)
    replicate.add_body(name="b").add_geom()
    model.worldbody.add_frame(class_="wide").add_geom()
    assert first_column(model.compile(), "geom_size") == [0.3, 0.3, 0.3]


def test_replicate_prefix_loads_as_mujoco_reads_it_with_a_warning() -> None:
    """MuJoCo 4.0.0 does not read <replicate prefix> (nor any unknown replicate attribute):
    the replicas are named as without it. typed-mjcf loads the file, warns, drops it."""
    text = CLASSED.replace('class="wide">\n      <body', 'class="wide" prefix="r">\n      <body')
    assert 'prefix="r"' in text
    compiled = mujoco.MjModel.from_xml_string(text)
    assert compiled.nbody == 3 and (compiled.body("b0").id, compiled.body("b1").id) == (1, 2)
    with pytest.warns(mjcf.IgnoredAttributeWarning, match="<replicate> .* prefix='r'"):
        model = mjcf.from_xml_string(text)
    ours = model.compile()
    assert ours.nbody == 3 and (ours.body("b0").id, ours.body("b1").id) == (1, 2)
