"""Models whose names are not plain (``shapes.py``): names with '/', replicate copies,
flexcomp bodies. Each loads, validates without an error, compiles to the model MuJoCo
compiles from the text, and writes back unchanged; edits keep that."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.compare import model_differences

from .shapes import BIMANUAL, FLAG, PARTICLES, SHAPES


def _errors(model: mjcf.RootElement) -> list[str]:
    return [str(f) for f in model.validate() if f.severity == "error"]


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_loads_validates_compiles_and_round_trips(name: str) -> None:
    text = SHAPES[name]
    expected = mujoco.MjModel.from_xml_string(text)
    model = mjcf.from_xml_string(text)
    assert _errors(model) == []
    assert model_differences(expected, model.compile()) == []
    xml = model.to_xml_string()
    assert mjcf.from_xml_string(xml).to_xml_string() == xml
    assert model_differences(expected, mujoco.MjModel.from_xml_string(xml)) == []


def test_bimanual_names_are_found_edited_and_written_as_they_are() -> None:
    model = mjcf.from_xml_string(BIMANUAL)
    gripper = model.find("body", "left/gripper_link")
    assert gripper is not None and gripper.path.endswith("body[left/gripper_link]")
    camera = model.find("camera", "left/wrist_cam")
    assert camera is not None and camera.target is gripper  # a link, not text
    visual = model.find("default", "robot/visual")
    assert visual is not None
    # edits: a class value, a new site and actuator by element, a part moved
    visual.geom.rgba = (0.2, 0.2, 0.2, 1)
    gripper.add_site(name="tip", pos=(0.08, 0, 0))
    wrist = model.find("joint", "right/wrist")
    assert wrist is not None
    model.actuator.add_motor(name="extra", joint=wrist, gear=(2,))
    base = model.find("body", "right/base_link")
    assert base is not None
    base.pos = (0.5, 0, 0)
    model.keyframe.key[0].ctrl = (0, 0, 0, 0, 0)  # one more actuator
    assert _errors(model) == []
    xml = model.to_xml_string()
    assert 'name="left/gripper_link"' in xml and 'class="robot/visual"' in xml
    assert 'joint="right/wrist"' in xml
    compiled = model.compile()
    assert model_differences(mujoco.MjModel.from_xml_string(xml), compiled) == []
    assert compiled.actuator("extra").gear[0] == 2
    assert compiled.site("tip").bodyid[0] == compiled.body("left/gripper_link").id
    assert np.allclose(compiled.body("right/base_link").pos, (0.5, 0, 0))
    visual_geom = compiled.geom(compiled.body("left/base_link").geomadr[0])
    assert np.allclose(visual_geom.rgba, (0.2, 0.2, 0.2, 1))  # from the edited class
    again = mjcf.from_xml_string(xml)
    assert again.to_xml_string() == xml


def test_bimanual_literal_names_and_attached_scopes_do_not_mix() -> None:
    model = mjcf.from_xml_string(BIMANUAL)
    other = mjcf.RootElement(model="left")
    other.worldbody.add_body(name="base_link")
    with pytest.raises(mjcf.ChildError, match="left/"):
        model.worldbody.attach_model(other)
    other.model = "helper"
    model.worldbody.attach_model(other)
    assert model.find("body", "left/base_link") is not other.find("body", "base_link")
    assert model.find("body", "helper/base_link") is other.find("body", "base_link")


@pytest.mark.parametrize(("text", "old", "new"), [
    (FLAG, 'body1="flag_0"', 'body1="flag_01"'),  # MuJoCo writes vertex numbers plainly
    (FLAG, 'body1="flag_0"', 'body1="flag0"'),
    (FLAG, 'body1="flag_0"', 'body1="flag_0_0_0"'),  # a grid node: not this dof
    (PARTICLES, 'objname="s1_112"', 'objname="s2_112"'),  # the inner count is 2
    (PARTICLES, 'objname="s1_112"', 'objname="s1_12"'),  # the middle index has 2 digits
    (PARTICLES, 'objname="s1_112"', 'objname="s1112"'),  # the middle separator is '_'
    (PARTICLES, 'joint="x1_112"', 'joint="x1_113"'),  # the outer count is 3
])
def test_names_mujoco_does_not_make_are_still_reported(text: str, old: str, new: str) -> None:
    assert old in text
    changed = text.replace(old, new)
    with pytest.raises(ValueError):
        mujoco.MjModel.from_xml_string(changed)
    errors = _errors(mjcf.from_xml_string(changed))
    assert len(errors) == 1 and "unresolved-reference" in errors[0], errors
