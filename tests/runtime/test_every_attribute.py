"""Every attribute of every generated class: a valid value is accepted, and each kind of
invalid value is refused at assignment with the library's error, leaving the element as it was.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterator

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf import Element
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import element_classes


def _routes() -> dict[str, list[str]]:
    """For each class reachable from the root, the tags leading to it from the root."""
    routes: dict[str, list[str]] = {"RootElement": []}
    queue = deque(["RootElement"])
    while queue:
        name = queue.popleft()
        for child in element_classes()[name].spec.children.values():
            if child.class_name not in routes:
                routes[child.class_name] = [*routes[name], child.tag]
                queue.append(child.class_name)
    return routes


ROUTES = _routes()


def make(class_name: str) -> tuple[mjcf.RootElement, Element]:
    model = mjcf.RootElement()
    element: Element = model
    for tag in ROUTES[class_name]:
        element = element.add(tag)
    return model, element


def test_every_class_is_reachable_from_the_root() -> None:
    assert set(ROUTES) == set(element_classes())


def _cases() -> Iterator[tuple[str, str]]:
    for class_name in sorted(ROUTES):
        for attribute in element_classes()[class_name].spec.attributes.values():
            yield class_name, attribute.name


CASES = list(_cases())


def valid_value(attribute: AttributeSpec) -> object:
    kind = attribute.kind
    if attribute.is_array:
        n = max(attribute.lo, 1)
        return [2] * n if kind == "int" else [0.25] * n
    samples: dict[str, object] = {
        "string": "text", "file": "asset.stl", "bool": True, "int": 2, "real": 0.25,
        "id": "thing", "ref": "target", "chars": ("xyz" * 4)[: max(attribute.lo, 3)],
    }
    if kind in ("keyword", "flags"):
        return attribute.keywords[-1].upper()  # case-insensitive
    return samples[kind]


def invalid_values(attribute: AttributeSpec) -> list[tuple[object, type[Exception]]]:
    """Each kind of wrong value for the attribute, with the error it must raise."""
    kind = attribute.kind
    bad: list[tuple[object, type[Exception]]] = []
    if attribute.is_array:
        item = 2 if kind == "int" else 0.25
        if attribute.lo > 0:
            bad.append(([item] * (attribute.lo - 1), mjcf.InvalidValueError))
        if attribute.hi is not None:
            bad.append(([item] * (attribute.hi + 1), mjcf.InvalidValueError))
        bad.append(("one two", mjcf.InvalidValueError))
        bad.append(([[item]] * max(attribute.lo, 1), mjcf.MjcfError))  # not flat
        if kind == "int":
            bad.append(([1.5] * max(attribute.lo, 1), mjcf.InvalidValueError))
        return bad
    if kind == "int":
        bad += [(3.5, mjcf.InvalidValueError), ("three", mjcf.InvalidValueError),
                (2**40, mjcf.InvalidValueError), (object(), mjcf.InvalidTypeError)]
    elif kind == "real":
        bad += [("heavy", mjcf.InvalidValueError), (object(), mjcf.InvalidTypeError)]
    elif kind == "bool":
        bad += [("maybe", mjcf.InvalidValueError), (3, mjcf.InvalidTypeError)]
    elif kind in ("keyword", "flags"):
        bad += [("no-such-keyword", mjcf.InvalidValueError), (3.5, mjcf.InvalidTypeError)]
    elif kind == "id":
        bad += [("a/b", mjcf.InvalidValueError), (7, mjcf.InvalidTypeError)]
    elif kind == "ref" or kind in ("string", "file"):
        bad += [(7, mjcf.InvalidTypeError)]
    elif kind == "chars":
        if attribute.hi is not None:
            bad.append(("x" * (attribute.hi + 1), mjcf.InvalidValueError))
        bad.append((7, mjcf.InvalidTypeError))
    return bad


def _same(a: object, b: object) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return bool(np.array_equal(np.asarray(a), np.asarray(b)))
    return a == b


@pytest.mark.parametrize(("class_name", "attribute_name"), CASES,
                         ids=[f"{c}.{a}" for c, a in CASES])
def test_attribute_accepts_valid_and_refuses_invalid(class_name: str, attribute_name: str) -> None:
    model, element = make(class_name)
    attribute = element.spec.by_name[attribute_name]
    value = valid_value(attribute)
    setattr(element, attribute.py_name, value)
    stored = getattr(element, attribute.py_name)
    assert stored is not None
    if attribute.is_array:
        assert isinstance(stored, np.ndarray) and stored.ndim == 1
        assert len(stored) == max(attribute.lo, 1)
    before = element.get_attributes()
    xml_before = model.to_xml_string()
    for bad, error in invalid_values(attribute):
        with pytest.raises(error) as caught:
            setattr(element, attribute.py_name, bad)
        message = str(caught.value)
        assert isinstance(caught.value, mjcf.MjcfError)
        assert element.path in message and attribute.py_name in message, message
        assert "expected" in message, message
        after = element.get_attributes()
        assert after.keys() == before.keys()
        assert all(_same(after[k], before[k]) for k in before)
        assert model.to_xml_string() == xml_before
    setattr(element, attribute.py_name, None)
    assert getattr(element, attribute.py_name) is None
    setattr(element, attribute.py_name, value)
    setattr(element, attribute.py_name, "")  # as in dm_control, the empty string unsets
    assert getattr(element, attribute.py_name) is None


def test_reference_to_an_element_of_the_wrong_namespace_is_a_type_error() -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="b")
    geom = body.add_geom(name="g", size=(0.1,))
    joint = body.add_joint(name="j")
    sensor = model.sensor.add_jointpos(joint=joint)
    with pytest.raises(mjcf.InvalidTypeError, match="namespace 'joint'") as caught:
        sensor.joint = geom  # type: ignore[assignment]
    assert isinstance(caught.value, ValueError)  # dm_control raises ValueError here
    assert sensor.joint is joint


def test_identifiers_are_unique_within_their_namespace_only() -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="x")
    body.add_geom(name="x", size=(0.1,))  # another namespace: fine
    with pytest.raises(mjcf.DuplicateIdentifierError, match=r"worldbody/body\[x\] has it"):
        model.worldbody.add_body(name="x")
    assert len(model.worldbody.body) == 1
