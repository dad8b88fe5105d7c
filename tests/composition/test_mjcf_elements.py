"""MJCF's own composition elements, built with the typed API, compile as MuJoCo expands them."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

import typed_mjcf as mjcf
from tests.composition.robots import make_arm


def test_frame_with_scale_resizes_its_contents() -> None:
    model = mjcf.RootElement()
    frame = model.worldbody.add_frame(name="f", pos=(1, 0, 0), euler=(0, 0, 90), scale=2.0,
                                      scaling="geometry")
    body = frame.add_body(name="b", pos=(0.1, 0, 0))
    body.add_joint(name="j", type="slide", axis=(1, 0, 0))
    body.add_geom(type="sphere", size=(0.05,))
    m = model.compile()
    assert (m.nbody, m.njnt) == (2, 1)
    assert np.allclose(m.geom_size[0][0], 0.1)  # type: ignore[attr-defined]
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    assert np.allclose(data.body("b").xpos, [1.0, 0.2, 0.0])  # type: ignore[attr-defined]
    assert mjcf.from_xml_string(model.to_xml_string()).to_xml_string() == model.to_xml_string()


def test_replicate_repeats_its_contents() -> None:
    model = mjcf.RootElement()
    row = model.worldbody.add_replicate(count=5, offset=(0.2, 0, 0), sep="-")
    body = row.add_body(name="link")
    body.add_joint(name="hinge")
    body.add_geom(type="capsule", size=(0.02, 0.05))
    model.actuator.add_motor(joint="hinge-0")  # MuJoCo names the copies
    m = model.compile()
    assert (m.nbody, m.njnt, m.nu) == (6, 5, 1)


def arm_xml() -> bytes:
    arm = make_arm("arm")
    del arm.keyframe
    return arm.to_xml_string().encode()


def test_attach_element_with_an_in_memory_model_asset() -> None:
    model = mjcf.RootElement(model="scene")
    arm_model = model.asset.add_model(name="arm", file=mjcf.Asset(arm_xml(), ".xml", name="arm"))
    for i, x in enumerate((-0.5, 0.5)):
        body = model.worldbody.add_body(name=f"mount{i}", pos=(x, 0, 0))
        body.add_attach(model=arm_model, body="link0", prefix=f"a{i}_")
    m = model.compile()
    assert (m.njnt, m.nu, m.nsensor) == (6, 2, 2)
    assert m.joint("a1_joint2").id >= 0


def test_attach_element_with_a_model_file(tmp_path: Path) -> None:
    (tmp_path / "arm.xml").write_bytes(arm_xml())
    (tmp_path / "scene.xml").write_text(
        "<mujoco><asset><model name='arm' file='arm.xml'/></asset><worldbody>"
        "<body name='mount'><attach model='arm' body='link0' prefix='left_'/></body>"
        "</worldbody></mujoco>")
    model = mjcf.from_path(tmp_path / "scene.xml")
    assert model.compile().njnt == mujoco.MjModel.from_xml_path(str(tmp_path / "scene.xml")).njnt == 3
