"""The naming facts (``schema/facts.toml`` [language]) measured against the installed MuJoCo:
models are compiled, every name MuJoCo gives is read back, and each must be one that
:class:`CompiledNames` derives from the element it comes from (and names next to them must
not be). A MuJoCo release that names copies or flexcomp bodies otherwise fails here."""

from __future__ import annotations

import itertools

import mujoco
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.tree import Element, grammar_facts
from typed_mjcf._model.compiled_names import CompiledNames

# The MuJoCo object types of the namespaces checked here.
OBJECTS = {
    "body": mujoco.mjtObj.mjOBJ_BODY, "joint": mujoco.mjtObj.mjOBJ_JOINT,
    "geom": mujoco.mjtObj.mjOBJ_GEOM, "site": mujoco.mjtObj.mjOBJ_SITE,
    "tendon": mujoco.mjtObj.mjOBJ_TENDON, "equality": mujoco.mjtObj.mjOBJ_EQUALITY,
    "pair": mujoco.mjtObj.mjOBJ_PAIR, "exclude": mujoco.mjtObj.mjOBJ_EXCLUDE,
    "actuator": mujoco.mjtObj.mjOBJ_ACTUATOR, "sensor": mujoco.mjtObj.mjOBJ_SENSOR,
    "tuple": mujoco.mjtObj.mjOBJ_TUPLE, "flex": mujoco.mjtObj.mjOBJ_FLEX,
}
COUNTS = {"body": "nbody", "joint": "njnt", "geom": "ngeom", "site": "nsite",
          "tendon": "ntendon", "equality": "neq", "pair": "npair", "exclude": "nexclude",
          "actuator": "nu", "sensor": "nsensor", "tuple": "ntuple", "flex": "nflex"}


def compiled_names(m: mujoco.MjModel, namespace: str) -> list[str]:
    count = int(getattr(m, COUNTS[namespace]))
    names = [mujoco.mj_id2name(m, OBJECTS[namespace], i) for i in range(count)]
    return [name for name in names if name]


def origins(model: mjcf.RootElement, namespace: str, names: list[str]) -> list[Element | None]:
    compiled = CompiledNames(model)
    scope = _tree.scope_of(model)
    return [compiled.origin(scope, namespace, name) for name in names]


def replicated(inner: int, outer: int, sep: str) -> str:
    return f"""
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <replicate count="{outer}" offset="0.1 0 0" sep="{sep}">
      <frame>
        <replicate count="{inner}" offset="0 0.1 0">
          <body name="b" pos="0 0 0.3">
            <joint name="j"/>
            <geom name="g" size="0.02"/>
            <site name="s"/>
          </body>
        </replicate>
      </frame>
    </replicate>
  </worldbody>
</mujoco>"""


@pytest.mark.parametrize(("inner", "outer", "sep"),
                         [(1, 1, ""), (9, 10, "-"), (10, 12, ""), (3, 101, "_"), (2, 2, "/")])
def test_replicate_copies_are_named_as_the_facts_say(inner: int, outer: int, sep: str) -> None:
    text = replicated(inner, outer, sep)
    m = mujoco.MjModel.from_xml_string(text)
    model = mjcf.from_xml_string(text)
    for namespace, base in (("body", "b"), ("joint", "j"), ("geom", "g"), ("site", "s")):
        element = model.find(namespace, base)
        names = [n for n in compiled_names(m, namespace) if n not in ("world", "floor")]
        assert len(names) == inner * outer
        assert origins(model, namespace, names) == [element] * len(names), names
        # an index past the last copy is not a name, nor indices written with other widths
        wi, wo = len(str(inner)), len(str(outer))
        wrong = [f"{base}{inner:0{wi}d}{sep}{0:0{wo}d}", f"{base}{0:0{wi}d}{sep}{outer:0{wo}d}",
                 f"{base}{0:0{wi}d}{sep}{0:0{wo + 1}d}"]
        if sep:
            wrong.append(f"{base}{sep}{0:0{wi + wo}d}")
        assert origins(model, namespace, wrong) == [None] * len(wrong), wrong


REFERRING = """
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <site name="ceiling" pos="0 0 2"/>
    <replicate count="3" offset="0.1 0 0">
      <body name="b1" pos="0 0 0.5">
        <joint name="j" type="slide"/>
        <geom name="g1" size="0.02"/>
        <site name="s"/>
      </body>
      <body name="b2" pos="0 0.1 0.5">
        <joint type="slide"/>
        <geom name="g2" size="0.02"/>
      </body>
    </replicate>
  </worldbody>
  <deformable>
    <flex name="rope" dim="1" body="b1 b2" vertex="0 0 0 0 0 0" element="0 1"/>
  </deformable>
  <contact>
    <pair name="pair" geom1="g1" geom2="floor"/>
    <exclude name="exclude" body1="b1" body2="b2"/>
  </contact>
  <tendon>
    <spatial name="tendon">
      <site site="ceiling"/>
      <site site="s"/>
    </spatial>
  </tendon>
  <equality>
    <connect name="equality" body1="b1" body2="b2" anchor="0 0 0"/>
  </equality>
  <actuator>
    <motor name="actuator" joint="j"/>
  </actuator>
  <sensor>
    <actuatorfrc name="sensor" actuator="actuator"/>
  </sensor>
  <custom>
    <tuple name="tuple">
      <element objtype="body" objname="b1"/>
    </tuple>
  </custom>
</mujoco>"""


def test_elements_referring_into_a_replicate_are_copied_as_the_facts_say() -> None:
    m = mujoco.MjModel.from_xml_string(REFERRING)
    model = mjcf.from_xml_string(REFERRING)
    copied = set()
    for namespace in ("flex", "pair", "exclude", "tendon", "equality", "actuator", "sensor",
                      "tuple"):
        element = model.find(namespace, namespace if namespace != "flex" else "rope")
        assert element is not None, namespace
        names = compiled_names(m, namespace)
        assert len(names) == 3, (namespace, names)
        assert origins(model, namespace, names) == [element] * 3, (namespace, names)
        parent = element.parent
        assert parent is not None
        copied.add(parent.tag)
    assert copied == set(grammar_facts().copied_with_replicate)


def flexcomps() -> list[tuple[str, str]]:
    """Every dof keyword of the grammar, with flexcomp types of each kind of point set."""
    flexcomp = grammar_facts().flexcomp
    assert flexcomp is not None
    row = next(cls.spec for cls in _tree.element_classes().values()
               if cls.spec.tag == flexcomp.tag)
    solids = ('type="grid" count="3 3 3" dim="3"', 'type="box" count="3 3 3" dim="3"')
    others = ('type="grid" count="4 3 1" dim="2"', 'type="circle" count="6 1 1" dim="1"',
              'type="direct" dim="2" point="0 0 0 .1 0 0 0 .1 0 .1 .1 0" element="0 1 2 1 3 2"')
    found: list[tuple[str, str]] = []
    for dof in row.by_name[flexcomp.dof].keywords:
        # MuJoCo interpolates only solids (others: "flex grid rotation is not orthonormal")
        found += itertools.product([dof], solids if dof in flexcomp.nodes else solids + others)
    return found


@pytest.mark.parametrize(("dof", "kind"), flexcomps())
def test_flexcomp_bodies_are_named_as_the_facts_say(dof: str, kind: str) -> None:
    text = (f'<mujoco><worldbody><flexcomp name="F" {kind} dof="{dof}" spacing=".1 .1 .1" '
            f'radius=".01" pos="0 0 1"/></worldbody></mujoco>')
    try:
        m = mujoco.MjModel.from_xml_string(text)
    except ValueError as error:
        pytest.skip(f"MuJoCo refuses dof={dof} for {kind}: {str(error).splitlines()[0]}")
    model = mjcf.from_xml_string(text)
    flexcomp = model.find("flex", "F")
    names = [n for n in compiled_names(m, "body") if n != "world"]
    assert names
    assert origins(model, "body", names) == [flexcomp] * len(names), names
    assert origins(model, "flex", compiled_names(m, "flex")) == [None]  # its own name: literal
    others = ["F", "F_", "F_01", "F_0_0", "F_-1", "F_0_0_0_0", "F_1 "]
    assert origins(model, "body", others) == [None] * len(others)


def test_a_rigid_flexcomp_makes_no_bodies() -> None:
    text = ('<mujoco><worldbody><flexcomp name="F" type="grid" count="3 3 1" dim="2" '
            'spacing=".1 .1 .1" radius=".01" rigid="true"/></worldbody></mujoco>')
    assert compiled_names(mujoco.MjModel.from_xml_string(text), "body") == ["world"]
    model = mjcf.from_xml_string(text)
    assert origins(model, "body", ["F_0"]) == [None]


def test_compiled_names_of_attached_models_are_scoped() -> None:
    arm = mjcf.from_xml_string("""
<mujoco model="arm">
  <worldbody>
    <replicate count="2" offset="0.2 0 0">
      <body name="link" pos="0 0 0.5">
        <joint name="hinge"/>
        <geom size="0.03"/>
      </body>
    </replicate>
    <body name="mount" pos="0 0 1">
      <flexcomp name="cloth" type="grid" count="3 3 1" spacing=".05 .05 .05" radius=".001"
                dim="2"/>
    </body>
  </worldbody>
</mujoco>""")
    world = mjcf.RootElement(model="world")
    world.worldbody.add_geom(type="plane", size=(1, 1, 0.1))
    world.worldbody.attach_model(arm).pos = (0, 0, 0.1)
    world.actuator.add_motor(name="second", joint="arm/hinge1")
    world.equality.add_connect(body1="arm/cloth_0", body2="arm/link0", anchor=(0, 0, 0))
    world.sensor.add_framepos(objtype="body", objname="arm/cloth_8")
    assert [str(f) for f in world.validate()] == []
    m = world.compile()
    assert m.actuator("second").trnid[0] == m.joint("arm/hinge1").id
    # (vertex numbers are not bounded: how many vertices a flexcomp has depends on its type
    # and its files)
    world.sensor.add_framepos(objtype="body", objname="arm/cloth0")
    assert [f.rule for f in world.validate()] == ["unresolved-reference"]


def test_names_an_attach_prefix_brings_from_a_model_file() -> None:
    child = mjcf.RootElement(model="gripper")
    finger = child.worldbody.add_body(name="finger")
    finger.add_joint(name="slide", type="slide")
    finger.add_geom(size=(0.02,))
    host = mjcf.from_xml_string("""
<mujoco>
  <asset><model name="gripper" file="gripper.xml"/></asset>
  <worldbody>
    <body name="hand" pos="0 0 1">
      <freejoint/>
      <geom size="0.05"/>
      <attach model="gripper" body="finger" prefix="g-"/>
    </body>
  </worldbody>
  <actuator><motor name="close" joint="g-slide"/></actuator>
</mujoco>""")
    host.asset.model[0].file = mjcf.Asset(child.to_xml_string().encode(), ".xml")
    assert [str(f) for f in host.validate()] == []
    assert host.compile().actuator("close").trnid[0] >= 0
    host.actuator.add_motor(joint="slide")  # the prefix is part of the name
    assert [f.rule for f in host.validate()] == ["unresolved-reference"]


def test_assets_of_attached_models_named_after_their_files() -> None:
    # an unnamed mesh takes its file's name; in an attached model, with the model's prefix
    def arm(name: str) -> mjcf.RootElement:
        arm = mjcf.RootElement(model=name)
        arm.asset.add_mesh(file=mjcf.Asset(box_stl(0.05), ".stl", name="forearm"))
        link = arm.worldbody.add_body(name="link")
        link.add_joint(name="elbow")
        link.add_geom(type="mesh", mesh="forearm")
        return arm

    world = mjcf.RootElement(model="world")
    world.worldbody.attach_model(arm("left")).pos = (-0.5, 0, 0)
    world.worldbody.attach_model(arm("right")).pos = (0.5, 0, 0)
    world.worldbody.add_geom(type="mesh", mesh="left/forearm", pos=(0, 0, 1))
    assert [str(f) for f in world.validate()] == []
    m = world.compile()
    assert sorted(m.mesh(i).name for i in range(m.nmesh)) == ["left/forearm", "right/forearm"]
    assert m.geom_dataid[m.body("right/link").geomadr[0]] == m.mesh("right/forearm").id
    world.worldbody.add_geom(type="mesh", mesh="left/elbow")
    assert [f.rule for f in world.validate()] == ["unresolved-reference"]
