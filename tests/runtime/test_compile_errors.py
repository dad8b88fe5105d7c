"""A CompileError names the element MuJoCo's message is about (``error.path``), in plain and
composed models, for objects MuJoCo reports by name and line, by name alone, or by number
alone; where nothing identifies one, it says which section, and names no element."""

from __future__ import annotations

import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl


def compile_error(model: mjcf.RootElement) -> mjcf.CompileError:
    with pytest.raises(mjcf.CompileError) as caught:
        model.compile()
    return caught.value


def arm(*, named: bool = True) -> mjcf.RootElement:
    """An arm whose second link has no mass (MuJoCo refuses a moving massless body)."""
    arm = mjcf.RootElement(model="arm")
    arm.worldbody.add_body(name="base").add_geom(size=(0.05,))
    link = arm.worldbody.add_body(name="link") if named else arm.worldbody.add_body()
    link.add_joint(name="elbow")
    return arm


def test_massless_body_in_an_attached_arm_is_named_not_the_hosts_actuator() -> None:
    # the case that pairing the text's lines with our elements in order got wrong
    host = mjcf.RootElement(model="host")
    host.worldbody.add_body(name="table").add_geom(size=(0.1,))
    attached = arm()
    host.worldbody.attach_model(attached)
    host.actuator.add_motor(name="motor", joint="arm/elbow")
    error = compile_error(host)
    link = attached.find("body", "link")
    assert link is not None
    assert error.path == link.path
    assert "mass and inertia" in str(error) and f"(the element is {link.path})" in str(error)


@pytest.mark.parametrize("with_keys", [False, True])
def test_unnamed_body_deep_in_a_composed_model(with_keys: bool) -> None:
    host = mjcf.RootElement(model="host")
    host.worldbody.add_body(name="table").add_geom(size=(0.1,))
    attached = arm(named=False)
    host.worldbody.add_body().add_body(pos=(0, 0, 1)).attach(attached)
    host.actuator.add_motor(joint="arm/elbow")
    if with_keys:  # keyframes are combined after compiling the rest: MuJoCo refuses that
        host.keyframe.add_key(name="home", ctrl=(0.1,))
    error = compile_error(host)
    assert error.path == attached.worldbody.body[1].path


def test_unnamed_body_of_a_plain_model() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="a").add_geom(size=(0.1,))
    model.worldbody.add_body().add_joint()
    assert compile_error(model).path == "worldbody/body[1]"


@pytest.mark.parametrize("name", ["home", None])
def test_keyframe_of_the_wrong_length_by_name_or_number(name: str | None) -> None:
    # MuJoCo gives a keyframe's name and number but no line: keys compile apart
    model = mjcf.RootElement()
    body = model.worldbody.add_body()
    body.add_freejoint()
    body.add_geom(size=(0.1,))
    model.keyframe.add_key(qpos=(0, 0, 0, 1, 0, 0, 0))
    model.keyframe.add_key(name=name, qpos=(0, 0, 0, 1, 0, 0, 0, 1))
    error = compile_error(model)
    assert "invalid qpos size" in str(error)
    assert error.path == model.keyframe.key[1].path


def test_an_equality_mujoco_makes_itself_has_no_element_only_its_section() -> None:
    # <edge equality="strain"> makes an equality with no name and no line
    model = mjcf.from_xml_string("""
<mujoco>
  <worldbody>
    <body name="pole"><geom size="0.1"/></body>
    <flexcomp name="cloth" type="grid" count="3 3 1" spacing=".1 .1 .1" radius=".01" dim="2">
      <edge equality="strain"/>
    </flexcomp>
  </worldbody>
  <equality>
    <weld body1="pole"/>
  </equality>
</mujoco>""")
    error = compile_error(model)
    message = str(error)
    assert error.path is None
    assert "flex strain equality requires an interpolated flex 'cloth'" in message
    assert "MuJoCo names no element" in message and "<equality> section" in message
    assert "'cloth' in its message is worldbody/flexcomp[cloth]" in message
    assert "the element is" not in message and "weld" not in message


def test_a_replicate_copy_names_the_element_it_copies() -> None:
    model = mjcf.from_xml_string("""
<mujoco>
  <worldbody>
    <geom size="1 1 0.1" type="plane"/>
    <replicate count="3" offset="0.1 0 0">
      <frame><body name="ball"><joint/></body></frame>
    </replicate>
  </worldbody>
</mujoco>""")
    error = compile_error(model)
    assert "Element name 'ball0'" in str(error)
    assert error.path == "worldbody/replicate[0]/frame[0]/body[ball]"


def test_an_object_from_a_model_file_names_the_attach_that_reads_it() -> None:
    # MuJoCo's line is of the attached file: it must not pick the host's element there
    child = mjcf.RootElement(model="gripper")
    child.worldbody.add_body(name="finger").add_joint()  # massless
    host = mjcf.from_xml_string("""
<mujoco>
  <asset>
    <model name="gripper" file="gripper.xml"/>
  </asset>
  <worldbody>
    <geom size="1 1 0.1" type="plane"/>
    <body name="hand"><geom size="0.1"/><attach model="gripper" body="finger" prefix="g-"/></body>
  </worldbody>
</mujoco>""")
    host.asset.model[0].file = mjcf.Asset(child.to_xml_string().encode(), ".xml")
    error = compile_error(host)
    assert "Element name 'g-finger'" in str(error)
    assert error.path == "worldbody/body[hand]/attach[0]"
    assert "which MuJoCo's 'g-finger' is made from" in str(error)


def test_an_xml_error_in_a_composed_model() -> None:
    host = mjcf.RootElement(model="host")
    host.asset.add_mesh(name="box", file=mjcf.Asset(box_stl(0.1), ".stl", name="a"))
    # an error only MuJoCo's mesh reader finds (validate() finds a repeated name first)
    host.asset.add_mesh(file=mjcf.Asset(b"solid nonsense\n", ".stl", name="b"))
    attached = arm()
    attached.worldbody.body[1].add_geom(size=(0.1,))
    host.worldbody.attach_model(attached)
    error = compile_error(host)
    assert "invalid header in STL file" in str(error)
    assert error.path == "asset/mesh[1]"


def test_to_spec_errors_name_the_element_too() -> None:
    host = mjcf.RootElement(model="host")
    host.asset.add_mesh(name="box", file=mjcf.Asset(box_stl(0.1), ".stl", name="a"))
    host.asset.add_mesh(file=mjcf.Asset(box_stl(0.2), ".stl", name="box"))
    with pytest.raises(mjcf.CompileError) as caught:
        host.to_spec()
    assert caught.value.path == "asset/mesh[1]"
