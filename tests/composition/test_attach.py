"""Composing models: attach/detach with scoped names, defaults, keyframes, copies."""

from __future__ import annotations

import copy

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf

from .robots import home, make_arm


def make_world() -> mjcf.RootElement:
    world = mjcf.RootElement(model="world")
    world.worldbody.add_geom(name="floor", type="plane", size=(2, 2, 0.1))
    world.worldbody.add_site(name="left", pos=(-0.5, 0, 0.1))
    world.worldbody.add_site(name="right", pos=(0.5, 0, 0.1))
    return world


def site(world: mjcf.RootElement, name: str) -> mjcf.Site:
    found = world.find("site", name)
    assert isinstance(found, mjcf.Site)
    return found


def test_two_arms_on_two_sites_compile_with_scoped_names_and_one_keyframe() -> None:
    world = make_world()
    site(world, "left").attach(make_arm("left_arm"))
    site(world, "right").attach(make_arm("right_arm"))
    m = world.compile()
    assert (m.njnt, m.nu, m.nsensor, m.nkey) == (6, 2, 2, 1)
    names = {mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, i) for i in range(m.njnt)}  # type: ignore[attr-defined]
    assert names == {f"{side}_arm/joint{i}" for side in ("left", "right") for i in range(3)}
    assert m.key_qpos.tolist() == [home(3) + home(3)]
    # the attached model's defaults apply to it: damping from its main class
    assert np.allclose(m.dof_damping, 0.5)  # type: ignore[attr-defined]
    assert world.find("joint", "left_arm/joint2") is not None
    assert world.find("joint", "joint2") is None
    assert len(world.find_all("joint")) == 6


def test_attachment_frame_sits_at_the_site() -> None:
    world = make_world()
    frame = site(world, "left").attach(make_arm("arm"))
    assert isinstance(frame, mjcf.Body)
    assert frame.pos is not None and frame.pos.tolist() == [-0.5, 0, 0.1]
    m = world.compile()
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    assert np.allclose(data.body("arm/link0").xpos, [-0.5, 0, 0.1])  # type: ignore[attr-defined]


def test_detach_restores_the_previous_export() -> None:
    world = make_world()
    before = world.to_xml_string()
    arm = make_arm("arm")
    frame = site(world, "left").attach(arm)
    frame.add_freejoint()
    assert world.to_xml_string() != before
    arm.detach()
    assert world.to_xml_string() == before
    assert world.find("joint", "arm/joint0") is None
    site(world, "right").attach(arm)  # can be attached again
    assert world.compile().njnt == 3


def test_deepcopy_after_attach_is_independent() -> None:
    world = make_world()
    arm = make_arm("arm")
    site(world, "left").attach(arm)
    clone = copy.deepcopy(world)
    assert clone.to_xml_string() == world.to_xml_string()
    cloned_joint = clone.find("joint", "arm/joint0")
    assert cloned_joint is not None and cloned_joint is not arm.find("joint", "joint0")
    cloned_joint.damping = 3.0
    assert arm.find("joint", "joint0").damping is None  # type: ignore[union-attr]
    arm.detach()
    assert clone.compile().njnt == 3
    assert clone.find("joint", "arm/joint0") is cloned_joint


def test_free_floating_attachment_adds_a_free_joint() -> None:
    world = make_world()
    fixed = world.compile()
    frame = world.worldbody.attach_model(make_arm("arm"))
    frame.add_freejoint()
    m = world.compile()
    assert (m.nq, m.nv) == (fixed.nq + 7 + 3, fixed.nv + 6 + 3)
    # the whole-model keyframe: the free joint keeps its qpos0, the arm its own values
    assert m.key_qpos[0][7:].tolist() == home(3)
    assert m.key_qpos[0][:7].tolist() == m.qpos0[:7].tolist()  # type: ignore[attr-defined]


def test_attaching_twice_or_into_itself_is_refused_and_taken_names_are_made_free() -> None:
    world = make_world()
    arm = make_arm("arm")
    site(world, "left").attach(arm)
    with pytest.raises(mjcf.ChildError, match="already attached"):
        site(world, "right").attach(arm)
    with pytest.raises(mjcf.ChildError, match="into itself"):
        arm.worldbody.attach_model(world)
    with pytest.raises(mjcf.ChildError, match="into itself"):
        world.worldbody.attach_model(world)
    # as in dm_control, a taken (or no) name is made free: the model is renamed
    second = make_arm("arm")
    site(world, "right").attach(second)
    assert second.model == "arm_1"
    anonymous = mjcf.RootElement()
    world.worldbody.attach_model(anonymous)
    assert anonymous.model == "unnamed_model"
    assert world.find("joint", "arm_1/joint0") is second.find("joint", "joint0")
    assert world.compile().njnt == 6


def test_global_sections_merge_when_compatible_and_conflicts_name_both_values() -> None:
    world = make_world()
    world.option.timestep = 0.005
    arm = make_arm("arm")
    arm.option.timestep = 0.005  # same value: fine
    arm.option.gravity = (0, 0, -9.81)  # the default: fine
    world.worldbody.attach_model(arm)
    assert 'timestep="0.005"' in world.to_xml_string()
    other = make_arm("other")
    world.compiler.angle = "degree"
    other.compiler.angle = "radian"
    with pytest.raises(mjcf.InvalidValueError,
                       match=r"Conflicting values for attribute `angle` of <compiler>: 'radian' "
                             r"in the attached model 'other', 'degree' in the model it is "
                             r"attached to"):
        world.worldbody.attach_model(other)
    assert world.find("joint", "other/joint0") is None


def test_settings_the_parent_leaves_unset_are_adopted_and_some_combine() -> None:
    """dm_control's rules: the parent adopts what it leaves unset; size's memory takes the
    larger, option's timestep the smaller."""
    world = make_world()
    world.size.memory = "10000"
    world.option.timestep = 0.002
    arm = make_arm("arm")
    arm.compiler.angle = "radian"
    arm.size.memory = "1M"
    arm.option.timestep = 0.001
    world.worldbody.attach_model(arm)
    assert world.compiler.angle == "radian"
    assert world.size.memory == "1048576"
    assert world.option.timestep == 0.001
    arm.size.memory = "1K"  # changed after attaching: the export still takes the larger
    assert 'memory="1048576"' in world.to_xml_string()
    assert world.compile().opt.timestep == 0.001


def test_nested_attachments_scope_twice() -> None:
    world = make_world()
    arm = make_arm("arm")
    gripper = make_arm("gripper", links=2)
    site(arm, "tip").attach(gripper)
    site(world, "left").attach(arm)
    m = world.compile()
    assert m.njnt == 5 and m.nkey == 1
    assert world.find("joint", "arm/gripper/joint1") is gripper.find("joint", "joint1")
    assert m.key_qpos.tolist() == [home(3) + home(2)]
    assert gripper.full_identifier == "arm/gripper/"
    assert gripper.namescope.full_prefix() == "arm/gripper/"


def test_references_from_the_parent_to_attached_elements_are_scoped() -> None:
    world = make_world()
    arm = make_arm("arm")
    world.worldbody.attach_model(arm)
    joint = arm.find("joint", "joint2")
    world.sensor.add_jointvel(name="wrist_speed", joint=joint)
    assert 'joint="arm/joint2"' in world.to_xml_string()
    assert world.compile().nsensor == 2


def test_a_subtree_can_be_copied_into_another_model() -> None:
    source = make_arm("arm")
    target = mjcf.RootElement(model="target")
    link = source.find("body", "link1")
    assert link is not None
    copied = target.worldbody.paste(link)
    assert isinstance(copied, mjcf.Body)
    assert target.find("joint", "joint2") is copied.body[0].joint[0]
    copied.name = "renamed"
    assert source.find("body", "link1") is link  # the source is untouched
    with pytest.raises(mjcf.DuplicateIdentifierError):
        target.worldbody.paste(link.body[0])  # its names are taken now
    with pytest.raises(mjcf.ChildError):
        target.actuator.paste(link)


@pytest.mark.parametrize("attribute", ["damping", "armature", "axis"])
def test_joint_defaults_resolution_agrees_with_mujoco(attribute: str) -> None:
    model = mjcf.RootElement()
    model.default.add_joint(damping=0.5, armature=0.01)
    heavy = model.default.add_default(class_="heavy")
    heavy.add_joint(damping=4.0, axis=(1, 0, 0))
    heavier = heavy.add_default(class_="heavier")
    heavier.add_joint(armature=0.2)
    body = model.worldbody.add_body(childclass="heavy")
    joints = [body.add_joint(), body.add_joint(class_="main"), body.add_joint(class_="heavier"),
              body.add_joint(damping=7.0)]
    body.add_geom(size=(0.1,))
    m = model.compile()
    # damping is a polynomial: its first coefficient is dof_damping, the rest dof_dampingpoly
    damping = np.column_stack([m.dof_damping, m.dof_dampingpoly])  # type: ignore[attr-defined]
    compiled = {"damping": damping, "armature": m.dof_armature,  # type: ignore[attr-defined]
                "axis": m.jnt_axis}  # type: ignore[attr-defined]
    for i, joint in enumerate(joints):
        assert np.allclose(np.asarray(joint.resolve(attribute), dtype=float),
                           compiled[attribute][i]), (i, attribute)


def test_geom_defaults_resolution_agrees_with_mujoco() -> None:
    model = mjcf.RootElement()
    model.default.add_geom(friction=(0.7, 0.01, 0.001), rgba=(0, 0, 1, 1))
    red = model.default.add_default(class_="red")
    red.add_geom(rgba=(1, 0, 0, 1), condim=4)
    body = model.worldbody.add_body()
    body.add_freejoint()
    geoms = [body.add_geom(size=(0.1,)), body.add_geom(class_="red", size=(0.1,)),
             body.add_geom(class_="red", size=(0.1,), condim=1)]
    m = model.compile()
    for i, geom in enumerate(geoms):
        assert np.allclose(np.asarray(geom.resolve("rgba"), dtype=float), m.geom_rgba[i])  # type: ignore[attr-defined]
        assert np.allclose(np.asarray(geom.resolve("friction"), dtype=float), m.geom_friction[i])  # type: ignore[attr-defined]
        assert geom.resolve("condim") == m.geom_condim[i]  # type: ignore[attr-defined]
    with pytest.raises(mjcf.UnknownAttributeError):
        geoms[0].resolve("colour")
