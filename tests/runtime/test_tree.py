"""The element tree: add/insert/remove, once-only children, look-ups, attributes, copies."""

from __future__ import annotations

import copy
from collections.abc import Callable

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core import grammar as _grammar
from typed_mjcf._core import tree as _tree


@pytest.fixture
def model() -> mjcf.RootElement:
    model = mjcf.RootElement(model="arm")
    arm = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1))
    arm.add_geom(name="upper", type="capsule", size=(0.04, 0.2))
    arm.add_joint(name="shoulder", type="hinge")
    fore = arm.add_body(name="forearm")
    fore.add_joint(name="elbow")
    fore.add_geom(size=(0.05,))
    model.actuator.add_motor(name="m", joint="shoulder")
    return model


def test_add_returns_the_typed_child_and_child_lists_are_by_tag(model: mjcf.RootElement) -> None:
    arm = model.find("body", "upper_arm")
    assert isinstance(arm, mjcf.Body)
    geom = arm.add("geom", name="extra", size=(0.1,))
    assert isinstance(geom, mjcf.Geom)
    assert [g.name for g in arm.geom] == ["upper", "extra"]
    assert [j.name for j in arm.joint] == ["shoulder"]
    assert arm.get_children("geom") == arm.geom
    assert geom.parent is arm and geom.root is model and geom.tag == "geom"


def test_insert_places_the_child_at_a_position(model: mjcf.RootElement) -> None:
    arm = model.worldbody.body[0]
    first = arm.insert("site", 0, name="tip")
    assert arm.get_children()[0] is first
    assert model.to_xml_string().index('name="tip"') < model.to_xml_string().index('name="upper"')


def test_illegal_child_is_refused_with_a_suggestion(model: mjcf.RootElement) -> None:
    with pytest.raises(mjcf.ChildError, match=r"<motor> is not a valid child of <worldbody>"):
        model.worldbody.add("motor")
    with pytest.raises(mjcf.ChildError, match="did you mean 'geom'"):
        model.worldbody.add("goem")
    with pytest.raises(ValueError):  # also a ValueError, as in dm_control
        model.worldbody.body[0].joint[0].add("geom")


def test_second_once_only_child_raises_value_error(model: mjcf.RootElement) -> None:
    model.compiler.angle = "radian"
    with pytest.raises(ValueError, match="a <compiler> child already exists"):
        model.add("compiler")
    body = model.worldbody.body[0]
    body.add_inertial(pos=(0, 0, 0), mass=1.0)
    with pytest.raises(mjcf.ChildError):
        body.add_inertial(pos=(0, 0, 0), mass=2.0)
    assert body.inertial.mass == 1.0


def test_once_only_children_are_created_on_use_and_written_in_grammar_order() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b")
    model.option.timestep = 0.01
    model.compiler.angle = "radian"
    xml = model.to_xml_string()
    assert xml.index("<compiler") < xml.index("<option") < xml.index("<worldbody")
    assert "<size" not in xml  # read but never set: not written


def test_remove_detaches_the_subtree_and_frees_its_names(model: mjcf.RootElement) -> None:
    fore = model.find("body", "forearm")
    assert fore is not None
    fore.remove()
    assert fore.parent is None
    assert model.find("body", "forearm") is None
    assert model.find("joint", "elbow") is None
    assert "forearm" not in model.to_xml_string()
    model.worldbody.add_body(name="forearm")  # the name is free again
    with pytest.raises(mjcf.ChildError):
        fore.remove()


def test_find_is_by_namespace_and_find_all_in_document_order(model: mjcf.RootElement) -> None:
    assert model.find("joint", "elbow") is model.worldbody.body[0].body[0].joint[0]
    assert model.find("geom", "shoulder") is None
    assert [j.name for j in model.find_all("joint")] == ["shoulder", "elbow"]
    assert len(model.find_all("geom")) == 2  # unnamed ones included
    with pytest.raises(mjcf.InvalidValueError, match="did you mean 'joint'"):
        model.find("jiont", "elbow")


def test_renaming_updates_the_namespace(model: mjcf.RootElement) -> None:
    elbow = model.find("joint", "elbow")
    assert elbow is not None
    elbow.name = "knee"
    assert model.find("joint", "elbow") is None and model.find("joint", "knee") is elbow
    elbow.name = None
    assert model.find("joint", "knee") is None


def test_get_and_set_attributes(model: mjcf.RootElement) -> None:
    geom = model.find("geom", "upper")
    assert geom is not None
    attributes = geom.get_attributes()
    assert list(attributes) == ["name", "type", "size"]  # grammar order
    geom.set_attributes(rgba=(1, 0, 0, 1), class_="main")
    assert geom.class_ == "main"
    assert geom.rgba is not None and geom.rgba.dtype == np.float32


def test_set_attributes_is_all_or_nothing(model: mjcf.RootElement) -> None:
    geom = model.find("geom", "upper")
    assert geom is not None
    before = model.to_xml_string()
    with pytest.raises(mjcf.InvalidValueError):
        geom.set_attributes(name="renamed", rgba=(1, 0, 0, 1), size=(1, 2, 3, 4))
    assert model.to_xml_string() == before
    assert model.find("geom", "upper") is geom and model.find("geom", "renamed") is None
    with pytest.raises(mjcf.UnknownAttributeError):
        geom.set_attributes(name="renamed", rgab=(1, 0, 0, 1))
    assert model.to_xml_string() == before


def test_failed_add_changes_nothing(model: mjcf.RootElement) -> None:
    before = model.to_xml_string()
    arm = model.worldbody.body[0]
    with pytest.raises(mjcf.InvalidValueError):
        arm.add_geom(name="new", size=(1, 2, 3, 4))
    with pytest.raises(mjcf.DuplicateIdentifierError):
        arm.add_geom(name="upper")
    with pytest.raises(mjcf.UnknownAttributeError, match="did you mean 'size'"):
        arm.add("geom", name="new", szie=(1,))
    assert model.to_xml_string() == before
    assert model.find("geom", "new") is None


def test_unknown_attribute_is_an_attribute_error_with_path_and_suggestion(model: mjcf.RootElement) -> None:
    geom = model.find("geom", "upper")
    with pytest.raises(AttributeError) as caught:
        geom.rgab = (1, 0, 0, 1)  # type: ignore[union-attr]
    assert isinstance(caught.value, mjcf.MjcfError)
    assert "worldbody/body[upper_arm]/geom[upper]" in str(caught.value)
    assert "did you mean 'rgba'" in str(caught.value)
    with pytest.raises(AttributeError):
        _ = geom.rgab  # type: ignore[union-attr]


def test_error_paths_name_unnamed_elements_by_index(model: mjcf.RootElement) -> None:
    geom = model.worldbody.body[0].body[0].geom[0]
    assert geom.path == "worldbody/body[upper_arm]/body[forearm]/geom[0]"
    with pytest.raises(mjcf.InvalidValueError) as caught:
        geom.size = "a b"
    message = str(caught.value)
    assert message.startswith("worldbody/body[upper_arm]/body[forearm]/geom[0]:")
    assert "size='a b'" in message and "expected 1 to 3 numbers" in message


def test_values_are_converted(model: mjcf.RootElement) -> None:
    joint = model.find("joint", "shoulder")
    assert joint is not None
    joint.axis = "0 1 0"
    assert joint.axis is not None and joint.axis.tolist() == [0.0, 1.0, 0.0]
    joint.type = "SLIDE"  # keywords are case-insensitive; stored canonical
    assert joint.type == "slide"
    joint.limited = True  # a bool for a false/true/auto keyword
    assert joint.limited == "true"
    joint.group = 3.0  # an integral float is an int
    assert joint.group == 3 and isinstance(joint.group, int)
    joint.range = np.array([-1, 1])
    assert joint.range is not None and joint.range.dtype == np.float64
    model.worldbody.body[0].geom[0].size = 0.1  # one value for a 1..3 array
    with pytest.raises(mjcf.InvalidValueError, match="truncated"):
        joint.group = 3.5


def test_reference_by_element_is_written_as_its_name(model: mjcf.RootElement) -> None:
    elbow = model.find("joint", "elbow")
    assert elbow is not None
    motor = model.actuator.add_motor(joint=elbow)
    assert motor.joint is elbow
    elbow.name = "knee"  # the reference follows the element
    assert '<motor joint="knee"/>' in model.to_xml_string()
    unnamed = model.worldbody.body[0].body[0].geom[0]
    pair = model.contact.add_pair(geom1=unnamed, geom2="upper")  # named when written
    assert pair.geom1 is unnamed and unnamed.name is None
    text = model.to_xml_string()
    assert '<pair geom1="unnamed_geom_0" geom2="upper"/>' in text
    assert text.count('name="unnamed_geom_0"') == 1
    reread = mjcf.from_xml_string(text)
    assert reread.find("geom", "unnamed_geom_0") is not None


def test_deepcopy_is_independent(model: mjcf.RootElement) -> None:
    clone = copy.deepcopy(model)
    assert clone.to_xml_string() == model.to_xml_string()
    clone_motor = clone.actuator.motor[0]
    clone.find("joint", "shoulder").name = "hip"  # type: ignore[union-attr]
    assert model.find("joint", "shoulder") is not None
    clone.worldbody.body[0].pos = (0, 0, 5.0)
    assert model.worldbody.body[0].pos is not None and model.worldbody.body[0].pos[2] == 1.0
    assert clone_motor.root is clone
    shallow = copy.copy(model)
    assert shallow.to_xml_string() == model.to_xml_string()


def test_arrays_read_back_cannot_change_the_model(model: mjcf.RootElement) -> None:
    """What a property returns is read-only: changes go through assignment, and its checks."""
    body = model.worldbody.body[0]
    assert body.pos is not None
    with pytest.raises(ValueError, match="read-only"):
        body.pos[0] = 99
    body.pos = (99, 0, 1)
    assert body.pos.tolist() == [99, 0, 1]


def _add_to_one(body: mjcf.Body) -> None:
    body.pos[2] += 1


def _add_to_all(body: mjcf.Body) -> None:
    body.pos += 1


def _set_a_slice(body: mjcf.Body) -> None:
    body.pos[:2] = 0


def _scale(body: mjcf.Body) -> None:
    body.pos *= 2


@pytest.mark.parametrize("edit", [_add_to_one, _add_to_all, _set_a_slice, _scale])
def test_an_edit_in_place_says_to_assign_a_new_value(
        model: mjcf.RootElement, edit: Callable[[mjcf.Body], None]) -> None:
    """The library's error (numpy's says only "read-only"), and the value stays."""
    body = model.worldbody.body[0]
    before = body.to_xml_string()
    with pytest.raises(mjcf.InvalidValueError, match=r"read-only: assign a new value instead, "
                                                     r"e\.g\. `body\.pos = "):
        edit(body)
    assert body.to_xml_string() == before


def test_arithmetic_on_a_read_array_gives_a_plain_array(model: mjcf.RootElement) -> None:
    pos = model.worldbody.body[0].pos
    assert pos is not None
    moved = pos + 1
    assert type(moved) is np.ndarray and moved.flags.writeable
    assert repr(pos).startswith("array(") and type(np.asarray(pos)) is np.ndarray
    model.worldbody.body[0].pos = moved  # and back through assignment
    assert model.worldbody.body[0].pos.tolist() == moved.tolist()


def test_deepcopy_remaps_element_references(model: mjcf.RootElement) -> None:
    elbow = model.find("joint", "elbow")
    model.sensor.add_jointpos(joint=elbow)
    clone = copy.deepcopy(model)
    clone_elbow = clone.find("joint", "elbow")
    assert clone.sensor.jointpos[0].joint is clone_elbow
    assert clone_elbow is not elbow


def test_copy_of_a_subtree_is_detached(model: mjcf.RootElement) -> None:
    arm = model.worldbody.body[0]
    clone = copy.deepcopy(arm)
    assert clone.parent is None
    assert clone.to_xml_string() == arm.to_xml_string()


def test_elements_are_created_by_their_parent() -> None:
    with pytest.raises(TypeError, match="add_geom"):
        mjcf.Geom()


def _sample_text(attribute: _grammar.AttributeSpec) -> str | None:
    """A text ``attribute`` takes (``None``: a file, not stored as its codec gives it)."""
    if attribute.kind == "file":
        return None
    if attribute.kind in ("keyword", "flags"):
        return attribute.keywords[0]
    if attribute.kind == "bool":
        return "true"
    if attribute.kind in ("int", "real"):
        return " ".join(["1"] * max(attribute.lo, 1)) if attribute.is_array else "1"
    return "x" * max(attribute.lo, 1) if attribute.kind == "chars" else "x"


@pytest.mark.parametrize("tag", ["body", "geom", "joint", "site", "camera", "light"])
def test_building_assigning_and_parsing_store_a_value_alike(tag: str) -> None:
    """Building (``_init_attributes``), assigning and parsing (``assign_texts``) store every
    direct value of these rows alike (through ``_tree._store``, or as its ``bare`` case in
    the loops; test_value_routes.py compares whole models built by each route)."""
    world = mjcf.RootElement().worldbody.add_body()
    checked = 0
    for attribute in world.spec.children[tag].cls.spec.attributes.values():
        text = _sample_text(attribute)
        if not attribute.direct or text is None:
            continue
        built = world.add(tag, **{attribute.py_name: text})
        assigned = world.add(tag)
        setattr(assigned, attribute.py_name, text)
        parsed = world.add(tag)
        assert _tree.assign_texts(parsed, [(attribute.name, text)]) is None
        stored = [_tree.values(e) for e in (built, assigned, parsed)]
        assert [list(s) for s in stored] == [[attribute.name]] * 3, attribute
        read = [np.asarray(_tree.read_value(e, attribute)).tolist()
                for e in (built, assigned, parsed)]
        assert read[0] == read[1] == read[2], attribute
        checked += 1
    assert checked >= 5
