"""Whole-model keyframes of composed models: what counts as a joint or an actuator, where
each part's values go, and what cannot be combined (said, never dropped)."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.codecs import DEFAULT_FORMAT
from typed_mjcf._core.tree import element_classes, grammar_facts
from typed_mjcf._model import write
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS
from typed_mjcf._sim import compile as compile_module
from typed_mjcf._sim import text

from .robots import site


def gripper(key: str | None = None) -> mjcf.RootElement:
    """Two fingers coupled by an <equality><joint> and a fixed tendon (both name joints)."""
    keyframe = f"<keyframe>{key}</keyframe>" if key else ""
    return mjcf.from_xml_string(f"""
<mujoco model="hand">
  <worldbody>
    <body name="f1"><joint name="j1"/><geom size=".01"/></body>
    <body name="f2"><joint name="j2"/><geom size=".01"/></body>
  </worldbody>
  <tendon><fixed name="t"><joint joint="j1" coef="1"/><joint joint="j2" coef="1"/></fixed></tendon>
  <equality><joint joint1="j1" joint2="j2"/></equality>
  <actuator><general name="grip" tendon="t"/></actuator>
  {keyframe}
</mujoco>""")


def arm(extra_bodies: str = "", key: str = '<key name="home" qpos="1 2" ctrl="3"/>'
        ) -> mjcf.RootElement:
    return mjcf.from_xml_string(f"""
<mujoco model="arm">
  <worldbody>
    <body name="b"><joint name="b1"/><geom size=".1"/>
      <body name="c"><joint name="c1"/><geom size=".1"/><site name="tip"/></body>
    </body>
    {extra_bodies}
  </worldbody>
  <actuator><motor name="m" joint="b1"/></actuator>
  <keyframe>{key}</keyframe>
</mujoco>""")


def test_an_equality_joint_is_not_a_joint() -> None:
    """Issue 28: a parent with a key and an attached model with an <equality><joint> (and a
    fixed tendon's <joint>s) composed, exported and compiled."""
    model = arm()
    site(model, "tip").attach(gripper())
    m = model.compile()
    assert (m.njnt, m.nkey) == (4, 1)
    np.testing.assert_array_equal(m.key_qpos[0], [1, 2, 0, 0])
    np.testing.assert_array_equal(m.key_ctrl[0], [3, 0])
    assert 'qpos="1 2 0 0"' in model.to_xml_string()


def test_actuators_taking_several_controls() -> None:
    """A <pid> takes two controls and an <orientation> three (MuJoCo 4.0.0): a part's ctrl
    goes to its actuators' controls, whatever their number."""
    hand = mjcf.from_xml_string("""
<mujoco model="wrist">
  <worldbody><body name="w"><joint name="ball" type="ball"/><geom size=".02"/>
    <body name="v"><joint name="h"/><geom size=".02"/></body></body></worldbody>
  <actuator>
    <orientation name="o" joint="ball" kp="5"/>
    <pid name="p" joint="h" kp="1" ki="1"/>
  </actuator>
  <keyframe><key name="home" ctrl="1 2 3 4 5" act="6"/></keyframe>
</mujoco>""")
    model = arm()
    site(model, "tip").attach(hand)
    m = model.compile()
    assert (m.nactuator, m.nu, m.na) == (3, 6, 1)
    np.testing.assert_array_equal(m.key_ctrl[0], [3, 1, 2, 3, 4, 5])
    np.testing.assert_array_equal(m.key_act[0], [6])


def test_joints_are_numbered_body_by_body() -> None:
    """A body's joint written after its child body still comes first in qpos (MuJoCo numbers
    joints body by body); the attached model's joints follow the body they hang from."""
    model = mjcf.from_xml_string("""
<mujoco model="arm">
  <worldbody>
    <body name="b">
      <body name="c"><joint name="c1"/><geom size=".1"/><site name="tip"/></body>
      <joint name="b1"/><geom size=".1"/>
    </body>
  </worldbody>
  <keyframe><key name="home" qpos="1 2"/></keyframe>
</mujoco>""")
    alone = model.compile()
    site(model, "tip").attach(gripper('<key name="home" qpos="3 4"/>'))
    m = model.compile()
    assert [m.joint(i).name for i in range(m.njnt)] == ["b1", "c1", "hand/j1", "hand/j2"]
    assert [alone.joint(i).name for i in range(alone.njnt)] == ["b1", "c1"]
    np.testing.assert_array_equal(m.key_qpos[0], [1, 2, 3, 4])


def test_the_parents_joints_after_the_attachment_keep_their_values() -> None:
    """The parent's joints that follow the attached model in qpos keep the parent key's values
    (MjSpec.attach in MuJoCo 4.0.0 keeps the key's vector as it was and pads it: there the
    value of d1 lands on a gripper joint)."""
    model = arm(extra_bodies='<body name="d"><joint name="d1"/><geom size=".1"/></body>',
                key='<key name="home" qpos="1 2 5" ctrl="3"/>')
    site(model, "tip").attach(gripper())
    m = model.compile()
    assert [m.joint(i).name for i in range(m.njnt)] == ["b1", "c1", "hand/j1", "hand/j2", "d1"]
    np.testing.assert_array_equal(m.key_qpos[0], [1, 2, 0, 0, 5])


def test_a_keys_plastic_state_is_refused_not_dropped() -> None:
    hand = gripper('<key name="home" plastic="0.1"/>')
    joint = hand.find("joint", "j1")
    assert isinstance(joint, mjcf.Joint)
    joint.springyield = 0.5
    model = arm()
    site(model, "tip").attach(hand)
    with pytest.raises(mjcf.ExportError, match=r"keyframe/key\[home\].*cannot combine plastic"):
        model.to_xml_string()


def test_joints_mujoco_makes_itself_are_refused_with_a_reason() -> None:
    """A <replicate> copies its joints: the keys cannot be placed, and the error says why."""
    copies = mjcf.from_xml_string("""
<mujoco model="row">
  <worldbody><replicate count="2" offset="0.1 0 0">
    <body name="p"><joint name="s" type="slide"/><geom size=".01"/></body>
  </replicate></worldbody>
</mujoco>""")
    model = arm()
    site(model, "tip").attach(copies)
    with pytest.raises(mjcf.ExportError, match=r"MuJoCo makes 4 joints and 1 actuators of the "
                                               r"text, which has 3 and 1"):
        model.compile()
    assert mujoco.MjModel.from_xml_string(arm().to_xml_string()).nkey == 1


def test_the_rows_counted_as_joints_are_the_joint_namespace() -> None:
    """The `joints` fact names rows: the tag <joint> is also an equality, a fixed tendon's
    part and a default, none of which adds to qpos."""
    rows = {cls.spec.row: cls.spec for cls in element_classes().values()}
    joint_rows = {name for name, spec in rows.items() if spec.namespace == "joint"}
    assert grammar_facts().joints == joint_rows
    assert {spec.row for spec in rows.values() if spec.tag == "joint"} - joint_rows == {
        "equality_joint", "fixed_joint", "default_joint"}


# Export is a pure write (issue 37): what it needs compiled (a composed model's keyframe
# layout) is resolved before the writer starts; the writer neither parses nor compiles.


def test_the_writer_compiles_nothing_given_the_layout(monkeypatch: pytest.MonkeyPatch) -> None:
    """A composed model whose keyframes combine: the layout compiled first, the write then
    gives the same text as ``to_xml_string()`` with MuJoCo out of reach."""
    model = arm()
    site(model, "tip").attach(gripper())
    expected = model.to_xml_string()
    assert write.needs_layout(model)
    layout = text.keyframe_layout(model, DEFAULT_FORMAT, True, None, None,
                                  DEFAULT_COMPILE_LIMITS)

    def refuse(*args: object, **kwargs: object) -> object:
        raise AssertionError("the writer compiled")

    monkeypatch.setattr(compile_module, "compile_from_memory", refuse)
    monkeypatch.setattr(text, "compile_from_memory", refuse)
    assert write.element_text(model, layout=layout) == expected
    assert 'qpos="1 2 0 0"' in expected


def test_a_layout_is_needed_only_to_combine_keyframes() -> None:
    model = arm()
    assert not write.needs_layout(model)  # nothing attached: its keys are written as they are
    site(model, "tip").attach(gripper())
    assert write.needs_layout(model)
    assert not write.needs_layout(model, self_only=True)
    assert not write.needs_layout(model.worldbody)
    bare = arm(key="")
    site(bare, "tip").attach(gripper())
    assert not write.needs_layout(bare)  # no part has a key
    bare = arm(key="")
    site(bare, "tip").attach(gripper('<key qpos="1 2"/>'))
    assert write.needs_layout(bare)  # an attached part's key


def test_without_the_layout_the_writer_says_so() -> None:
    model = arm()
    site(model, "tip").attach(gripper())
    with pytest.raises(AssertionError, match="needs the compiled layout"):
        write.element_text(model)
