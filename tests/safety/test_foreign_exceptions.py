"""Wrong arguments to the public API raise the library's errors (each also the ValueError,
TypeError or AttributeError a Python user expects), never a TypeError, AttributeError,
OverflowError or RecursionError from inside it; deep models pickle and copy."""

from __future__ import annotations

import copy
import pickle
from collections.abc import Callable
from pathlib import Path
from typing import cast

import pytest

import typed_mjcf as mjcf


def _call(function: object, *args: object) -> object:
    """``function(*args)``, arguments the type checkers would refuse included."""
    return cast("Callable[..., object]", function)(*args)


def _model() -> mjcf.RootElement:
    model = mjcf.RootElement(model="m")
    model.worldbody.add_body(name="b").add_joint(name="j")
    return model


CALLS: dict[str, tuple[Callable[[mjcf.RootElement, Path], object], type[Exception], str]] = {
    "find-name-none": (lambda m, _: _call(m.find, "joint", None),
                       mjcf.InvalidTypeError, "identifier must be a str, got None"),
    "find-namespace-none": (lambda m, _: _call(m.find, None, "j"),
                            mjcf.InvalidTypeError, "namespace must be a str, got None"),
    "find-namespace-int": (lambda m, _: _call(m.find, 5, "j"),
                           mjcf.InvalidTypeError, "namespace must be a str, got 5"),
    "find-all-none": (lambda m, _: _call(m.find_all, None),
                      mjcf.InvalidTypeError, "namespace must be a str"),
    "asset-extension": (lambda m, _: _call(mjcf.Asset, b"x", 5),
                        mjcf.InvalidTypeError, "Asset extension must be a str, got 5"),
    "asset-name": (lambda m, _: _call(mjcf.Asset, b"x", ".stl", 5),
                   mjcf.InvalidTypeError, "Asset name must be a str or None, got 5"),
    "asset-contents": (lambda m, _: _call(mjcf.Asset, 5, ".stl"),
                       mjcf.InvalidTypeError, "Asset contents must be bytes or str, got int"),
    "asset-surrogate": (lambda m, _: mjcf.Asset("\ud800", ".xml"),
                        mjcf.InvalidValueError, "Asset contents: "),
    "export-not-a-model": (lambda m, p: _call(mjcf.export_with_assets, 5, p),
                           mjcf.InvalidTypeError, "mjcf_model must be a model"),
    "export-zip-not-a-model": (
        lambda m, p: _call(mjcf.export_with_assets_as_zip, m.worldbody, p),
        mjcf.InvalidTypeError, "mjcf_model must be a model .*got Worldbody"),
}


@pytest.mark.parametrize("case", sorted(CALLS))
def test_wrong_arguments_raise_the_librarys_errors(case: str, tmp_path: Path) -> None:
    call, error, message = CALLS[case]
    with pytest.raises(error, match=message) as info:
        call(_model(), tmp_path)
    assert isinstance(info.value, mjcf.MjcfError)


def test_insert_takes_any_int_as_list_insert_does() -> None:
    model = _model()
    last = model.worldbody.insert("body", 10**30, name="last")
    first = model.worldbody.insert("body", -(10**30), name="first")
    assert [b.name for b in model.worldbody.body] == ["first", "b", "last"]
    assert (first.name, last.name) == ("first", "last")


def _deep(depth: int) -> tuple[mjcf.RootElement, mjcf.Body]:
    model = mjcf.RootElement(model="deep")
    element = model.worldbody.add_body(name="b0")
    for i in range(1, depth):
        element = element.add_body(name=f"b{i}")
    joint = element.add_joint(name="j")
    model.actuator.add_motor(name="m", joint=joint)
    return model, element


@pytest.mark.parametrize("depth", [3, 2000])
def test_a_deep_model_pickles_and_copies(depth: int) -> None:
    model, leaf = _deep(depth)
    xml = model.to_xml_string()
    for again in (pickle.loads(pickle.dumps(model)), copy.deepcopy(model)):
        assert again.to_xml_string() == xml
        joint = again.find("joint", "j")
        assert joint is not None and again.actuator.motor[0].joint is joint
        assert joint.root is again
    leaf_again = pickle.loads(pickle.dumps(leaf))  # an inner element brings its model along
    assert leaf_again.root.to_xml_string() == xml
    assert leaf_again.path == leaf.path


def test_a_removed_subtree_pickles() -> None:
    model, _ = _deep(5)
    top = model.find("body", "b1")
    inner = model.find("body", "b3")
    assert top is not None and inner is not None
    top.remove()
    again = pickle.loads(pickle.dumps(inner))
    assert again.is_removed and again.name == "b3"
    assert [b.name for b in again.body] == ["b4"]
    assert again.parent is not None and again.parent.name == "b2"
