"""mjcf.Physics: binding elements (named or not, composed, replicated), named indexers,
write-through, reset and keyframes, copies, rendering, and the errors."""

from __future__ import annotations

import struct
import zlib

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._sim.png import encode_png
from typed_mjcf.physics import BindingError


def arm() -> mjcf.RootElement:
    model = mjcf.RootElement(model="arm")
    model.compiler.angle = "radian"
    model.worldbody.add_light(pos=(0, 0, 3))
    model.worldbody.add_geom(name="floor", type="plane", size=(1, 1, 0.1), rgba=(1, 1, 1, 1))
    base = model.worldbody.add_body(name="base", pos=(0, 0, 1))
    base.add_freejoint(name="root")
    base.add_geom(type="box", size=(0.1, 0.1, 0.1))
    link = base.add_body(name="link", pos=(0, 0, 0.2))
    link.add_joint(name="elbow", axis=(0, 1, 0), range=(-1, 1))
    link.add_geom(type="capsule", size=(0.02,), fromto=(0, 0, 0, 0, 0, 0.3))
    link.add_site(name="tip", pos=(0, 0, 0.3))
    link.add_joint(axis=(1, 0, 0))  # unnamed
    model.actuator.add_motor(joint="elbow")  # unnamed
    model.sensor.add_framepos(name="tip_pos", objtype="site", objname="tip")
    model.keyframe.add_key(name="bent", qpos=(0, 0, 1, 1, 0, 0, 0, 0.5, 0.25))
    return model


def test_the_model_is_the_one_compile_gives() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    compiled = model.compile()
    assert physics.model.__getstate__() == compiled.__getstate__()
    assert isinstance(physics.model, mujoco.MjModel)


def test_named_indexers_have_rows_and_columns() -> None:
    physics = mjcf.Physics.from_mjcf_model(arm())
    named = physics.named
    assert named.data.qpos["root"].shape == (7,)  # a free joint's seven entries
    assert named.data.qpos["elbow"].shape == (1,)
    assert named.data.qvel["root"].shape == (6,)
    assert named.data.xpos["base", "z"] == 1.0
    np.testing.assert_array_equal(named.data.xpos["base", ["x", "z"]], [0, 1])
    np.testing.assert_array_equal(named.data.xpos[["base", "link"], "z"], [1.0, 1.2])
    assert named.model.geom_rgba["floor", "a"] == 1.0
    named.model.geom_rgba["floor", "r"] = 0.25
    assert physics.model.geom_rgba[0, 0] == np.float32(0.25)
    assert named.model.key_qpos["bent", "elbow"] == 0.5  # columns named by joints
    assert named.data.qpos[["root", "elbow"]].shape == (8,)
    np.testing.assert_array_equal(named.data.qpos[7:], physics.data.qpos[7:])  # numbers too
    with pytest.raises(KeyError, match="elbw"):
        named.data.qpos["elbw"]
    with pytest.raises(AttributeError, match="qpso"):
        print(named.data.qpso)
    assert "elbow" in repr(named.data.qpos)


def test_binding_reads_and_writes_through() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    elbow = model.find("joint", "elbow")
    tip = model.find("site", "tip")
    assert elbow is not None and tip is not None
    bound = physics.bind(elbow)
    assert bound is physics.bind(elbow)  # cached
    bound.qpos = 0.5
    assert physics.data.qpos[7] == 0.5 and physics.is_dirty
    z_before = physics.named.data.site_xpos["tip", "x"]
    x = physics.bind(tip).xpos  # a derived quantity: mj_forward runs first
    assert not physics.is_dirty and x[0] != z_before
    view = physics.bind(elbow).qpos
    view[0] = -0.5  # in place
    assert physics.data.qpos[7] == -0.5 and physics.is_dirty
    np.testing.assert_array_equal(physics.bind(elbow).range, [-1, 1])
    physics.bind(elbow).range = (-2, 2)  # a model array
    np.testing.assert_array_equal(physics.model.jnt_range[1], [-2, 2])


def test_vectorised_bindings_keep_the_order_given() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    joints = model.find_all("joint")
    bound = physics.bind(joints[::-1])
    assert bound.qpos.shape == (9,)  # the unnamed hinge, the elbow, the free joint
    bound.qpos += 1.0  # a copy of the rows, written back
    np.testing.assert_array_equal(physics.data.qpos, np.r_[[1, 1, 2, 2, 1, 1, 1], 1, 1])
    bodies = physics.bind(model.find_all("body"))
    bodies.xfrc_applied[:, 2] = [5.0, 6.0]
    np.testing.assert_array_equal(physics.data.xfrc_applied[1:, 2], [5, 6])
    np.testing.assert_array_equal(physics.bind(model.find_all("body")).element_id, [1, 2])
    assert physics.bind([]).xpos.shape == (0,)
    with pytest.raises(BindingError, match="multiple element types"):
        physics.bind([joints[0], model.find_all("geom")[0]])


def test_unnamed_elements_bind_by_where_they_were_compiled() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    hinge = model.find_all("joint")[2]
    motor = model.find_all("actuator")[0]
    assert hinge.full_identifier is None and motor.full_identifier is None
    assert physics.bind(hinge).element_id == 2
    physics.bind(motor).ctrl = 0.75
    assert physics.data.ctrl[0] == 0.75
    # its one output, bound as that row (a single actuator owning one row of a size)
    np.testing.assert_array_equal(physics.bind(motor).gear[:1], [1])
    assert physics.bind([motor]).gear.shape == (1, 6)
    assert physics.bind(model.worldbody).element_id == 0
    # a physics made from the model's text finds them the same way
    text = mjcf.Physics.from_xml_string(model.to_xml_string())
    assert text.bind(hinge).element_id == 2


def test_attached_models_frames_and_replicates() -> None:
    world = arm()
    world.keyframe.key[0].remove()  # its qpos is the arm's alone
    hand = mjcf.RootElement(model="hand")
    finger = hand.worldbody.add_body(name="finger")
    finger.add_joint(name="knuckle", axis=(0, 0, 1))
    finger.add_geom(size=(0.01,))
    unnamed = finger.add_joint(axis=(1, 0, 0))
    tip = world.find("site", "tip")
    assert tip is not None
    frame = tip.attach(hand)
    frame_joint = frame.add_joint(name="wrist", axis=(0, 0, 1))
    frame.add_geom(size=(0.01,))
    framed = world.worldbody.add_frame(pos=(1, 0, 0)).add_site(name="in_frame")
    row = world.worldbody.add_replicate(count=3, offset=(0.2, 0, 0))
    ball = row.add_body(pos=(0, 0, 2))
    ball.add_geom(type="sphere", size=(0.05,))
    physics = mjcf.Physics.from_mjcf_model(world)
    knuckle = hand.find("joint", "knuckle")
    assert knuckle is not None
    assert physics.model.id2name(physics.bind(knuckle).element_id, "joint") == "hand/knuckle"
    assert physics.model.id2name(physics.bind(frame_joint).element_id, "joint") == "hand/wrist"
    assert physics.bind(unnamed).element_id == physics.bind(knuckle).element_id + 1
    assert physics.bind(frame).element_id == physics.model.name2id("hand/", "body")
    np.testing.assert_array_equal(physics.bind(framed).xpos, [1, 0, 0])
    copies = physics.bind(ball)  # one element, three compiled copies
    assert copies.xpos.shape == (3, 3)
    np.testing.assert_allclose(copies.xpos[:, 0], [0, 0.2, 0.4])


def test_errors_name_the_element() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    floor = model.find("geom", "floor")
    assert floor is not None
    with pytest.raises(AttributeError, match=r"<geom> does not have attribute 'qpos'"):
        print(physics.bind(floor).qpos)
    later = model.worldbody.add_body(name="later")
    with pytest.raises(BindingError, match=r"body\[later\].*added after.*reload_from_mjcf"):
        physics.bind(later)
    unnamed_later = model.worldbody.add_geom(size=(1,))
    with pytest.raises(BindingError, match="not in the model as this physics compiled it"):
        physics.bind(unnamed_later)
    link = model.find("body", "link")
    assert link is not None
    site = link.site[0]
    site.remove()
    with pytest.raises(BindingError, match="removed from its model"):
        physics.bind(site)
    frame = model.worldbody.add_frame()
    with pytest.raises(BindingError, match="<frame> cannot be bound"):
        physics.bind(frame)
    with pytest.raises(BindingError, match="is None"):
        physics.bind(None)
    other = mjcf.Physics.from_xml_string("<mujoco><worldbody><geom size='1'/></worldbody>"
                                         "</mujoco>")
    hinge = model.find_all("joint")[2]
    with pytest.raises(BindingError, match="from_mjcf_model"):
        other.bind(hinge)
    with pytest.raises(mjcf.MjcfError, match="no joint named 'nope'"):
        physics.model.name2id("nope", "joint")
    with pytest.raises(AttributeError, match="mocap"):
        print(physics.bind(link).mocap_pos)


def test_reset_keyframes_and_steps() -> None:
    physics = mjcf.Physics.from_mjcf_model(arm())
    physics.reset(keyframe_id=0)
    assert physics.named.data.qpos["elbow"] == 0.5
    with pytest.raises(mjcf.MjcfError, match="between 0 and 0"):
        physics.reset(keyframe_id=1)
    with physics.reset_context():
        physics.named.data.qpos["elbow"] = 0.25
    assert physics.named.data.qpos["elbow"] == 0.25
    physics.set_control([0.1])
    np.testing.assert_array_equal(physics.control(), [0.1])
    physics.step(5)
    assert physics.time() == pytest.approx(5 * physics.timestep())
    state = physics.get_state()
    physics.step()
    physics.set_state(state)
    np.testing.assert_array_equal(physics.get_state(), state)
    physics.reset()
    assert physics.time() == 0.0 and physics.named.data.qpos["elbow"] == 0.0


def test_invalid_state_raises() -> None:
    physics = mjcf.Physics.from_mjcf_model(arm())
    physics.data.qpos[7] = np.nan
    with pytest.raises(mjcf.PhysicsError, match="BADQPOS"):
        physics.step()
    quiet = mjcf.Physics.from_mjcf_model(arm())
    quiet.data.qpos[7] = np.nan
    with quiet.suppress_physics_errors(), pytest.warns(RuntimeWarning, match="BADQPOS"):
        quiet.step()


def test_copies_are_independent() -> None:
    model = arm()
    physics = mjcf.Physics.from_mjcf_model(model)
    physics.named.data.qpos["elbow"] = 0.3
    twin = physics.copy()
    shared = physics.copy(share_model=True)
    assert twin.named.data.qpos["elbow"] == 0.3
    twin.named.data.qpos["elbow"] = -0.3
    assert physics.named.data.qpos["elbow"] == 0.3
    assert shared.model is physics.model and twin.model is not physics.model
    hinge = model.find_all("joint")[2]
    assert twin.bind(hinge).element_id == 2  # the copy binds unnamed elements too
    physics.reload_from_mjcf_model(model)
    assert physics.named.data.qpos["elbow"] == 0.0


def test_render_rgb_depth_and_segmentation() -> None:
    physics = mjcf.Physics.from_mjcf_model(arm())
    rgb = physics.render(48, 64)
    assert rgb.shape == (48, 64, 3) and rgb.dtype == np.uint8 and rgb.max() > rgb.min()
    depth = physics.render(48, 64, depth=True)
    assert depth.shape == (48, 64) and depth.dtype == np.float32 and float(depth.min()) > 0
    segments = physics.render(48, 64, segmentation=True)
    assert segments.shape == (48, 64, 2)
    geoms = set(np.unique(segments[..., 0][segments[..., 1] == mujoco.mjtObj.mjOBJ_GEOM]))
    assert 0 in geoms  # the floor is seen
    with pytest.raises(mjcf.MjcfError, match="offscreen buffer"):
        physics.render(5000, 64)
    with pytest.raises(mjcf.MjcfError, match="cameras"):
        physics.render(48, 64, camera_id=3)


def test_png_encoding() -> None:
    pixels = np.arange(2 * 3 * 3, dtype=np.uint8).reshape(2, 3, 3)
    data = encode_png(pixels)
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height, depth, colour = struct.unpack(">IIBB", data[16:26])
    assert (width, height, depth, colour) == (3, 2, 8, 2)
    length = struct.unpack(">I", data[33:37])[0]
    raw = zlib.decompress(data[41:41 + length])
    assert raw == b"\x00" + pixels[0].tobytes() + b"\x00" + pixels[1].tobytes()
    with pytest.raises(ValueError, match="height x width"):
        encode_png(np.zeros((2, 3, 5), np.uint8))
    with pytest.raises(ValueError, match="uint8 pixels"):
        encode_png(np.full((2, 2), 300))
