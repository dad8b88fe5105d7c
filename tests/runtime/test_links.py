"""References are links: renaming, attaching, copying and removing keep them right."""

from __future__ import annotations

import copy

import pytest

import typed_mjcf as mjcf


def painted() -> tuple[mjcf.RootElement, mjcf.Material, mjcf.Geom]:
    model = mjcf.RootElement("painted")
    red = model.asset.add_material(name="red", rgba=(1, 0, 0, 1))
    geom = model.worldbody.add_geom(size=(0.1,), material="red")
    return model, red, geom


def test_a_name_that_resolves_links_and_follows_a_rename() -> None:
    model, red, geom = painted()
    assert geom.material is red
    red.name = "crimson"
    assert 'material="crimson"' in model.to_xml_string()
    assert model.compile().nmat == 1


def test_a_name_given_before_its_element_exists_links_when_it_appears() -> None:
    model = mjcf.RootElement()
    motor = model.actuator.add_motor(joint="hinge")
    assert motor.joint == "hinge"
    joint = model.worldbody.add_body().add_joint(name="hinge")
    assert motor.joint is joint
    joint.name = "knee"
    assert '<motor joint="knee"/>' in model.to_xml_string()


def test_parsed_references_are_links_and_round_trip() -> None:
    model, _, _ = painted()
    parsed = mjcf.from_xml_string(model.to_xml_string())
    geom = parsed.worldbody.geom[0]
    assert geom.material is parsed.find("material", "red")
    unresolved = mjcf.from_xml_string(model.to_xml_string(), resolve_references=False)
    assert unresolved.worldbody.geom[0].material == "red"
    unresolved.resolve_references()
    assert unresolved.worldbody.geom[0].material is unresolved.find("material", "red")
    assert parsed.to_xml_string() == model.to_xml_string()


def test_renaming_an_attached_model_keeps_find_and_references_right() -> None:
    arm = mjcf.RootElement("arm")
    elbow = arm.worldbody.add_body(name="link").add_joint(name="elbow")
    world = mjcf.RootElement("world")
    world.attach(arm)
    motor = world.actuator.add_motor(joint=elbow)
    arm.model = "left_arm"
    assert world.find("joint", "left_arm/elbow") is elbow
    assert world.find("joint", "arm/elbow") is None
    assert '<motor joint="left_arm/elbow"/>' in world.to_xml_string()
    assert motor.joint is elbow
    with pytest.raises(mjcf.ChildError, match="already attached"):
        other = mjcf.RootElement("other")
        world.attach(other)
        other.model = "left_arm"


def test_copies_link_to_their_own_elements() -> None:
    model, red, geom = painted()
    clone = copy.deepcopy(model)
    clone_geom = clone.worldbody.geom[0]
    assert clone_geom.material is clone.find("material", "red") and clone_geom.material is not red
    pasted = model.worldbody.add_body(name="b").paste(geom)
    assert pasted.material is red


def test_removing_a_referenced_element_clears_the_reference_and_validate_says_so() -> None:
    model, red, geom = painted()
    red.remove()
    assert geom.material is None
    assert "material" not in model.to_xml_string()
    findings = [str(f) for f in model.validate()]
    assert any("material referred to a <material> that was removed" in f for f in findings)
    with pytest.raises(mjcf.ValidationError, match="removed"):
        model.compile()


def test_zero_threshold_formats_float32_values_as_float32() -> None:
    """Regression: zero_threshold once wrote rgba="0.10000000149011612 ..." (a float32
    formatted as a double) where the default export writes "0.1 ..."."""
    model = mjcf.RootElement()
    model.worldbody.add_geom(size=(1e-12,), rgba=(0.1, 0.2, 0.3, 1))
    plain = model.to_xml_string()
    thresholded = model.to_xml_string(zero_threshold=1e-9)
    assert 'rgba="0.1 0.2 0.3 1"' in plain and 'rgba="0.1 0.2 0.3 1"' in thresholded
    assert 'size="0"' in thresholded and 'size="1e-12"' in plain
    assert 'rgba="0.1 0.2 0.3 1"' in model.to_xml_string(precision=4)
