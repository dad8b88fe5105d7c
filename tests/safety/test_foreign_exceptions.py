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
from typed_mjcf._sim.binding import BindingError


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
    # Entry points taking a path, a file or a model (round two of the audit).
    "zip-int": (lambda m, _: _call(mjcf.from_zip, 5),
                mjcf.InvalidTypeError, "from_zip needs a path or an open binary file, got int"),
    "zip-none": (lambda m, _: _call(mjcf.from_zip, None),
                 mjcf.InvalidTypeError, "from_zip needs a path .*got NoneType"),
    "asset-missing-file": (lambda m, p: mjcf.Asset.from_path(p / "x.obj"),
                           mjcf.FileReadError, r"x\.obj: cannot read the file: No such file"),
    "asset-folder": (lambda m, p: mjcf.Asset.from_path(p),
                     mjcf.FileReadError, "cannot read the file: Is a directory"),
    "asset-path-int": (lambda m, _: _call(mjcf.Asset.from_path, 5),
                       mjcf.InvalidTypeError, "Asset.from_path needs a path .*got int"),
    "render-png-path-int": (lambda m, _: _call(m.render_png, 5),
                            mjcf.InvalidTypeError, "render_png: path must be a path"),
    "render-size-positional": (lambda m, _: _call(m.render, 8),
                               mjcf.InvalidTypeError, "the size is given by keyword"),
    "spec-int": (lambda m, _: _call(mjcf.from_spec, 5),
                 mjcf.InvalidTypeError, "from_spec needs a mujoco.MjSpec, got int"),
    "physics-model-int": (lambda m, _: _call(mjcf.Physics.from_mjcf_model, 5),
                          mjcf.InvalidTypeError, "mjcf_model must be a model .*got int"),
    "physics-path-int": (lambda m, _: _call(mjcf.Physics.from_xml_path, 5),
                         mjcf.InvalidTypeError, "file_path must be a path .*got int"),
    "physics-text-int": (lambda m, _: _call(mjcf.Physics.from_xml_string, 5),
                         mjcf.InvalidTypeError, "xml_string must be a str, got int"),
    "physics-binary-missing": (lambda m, p: mjcf.Physics.from_binary_path(p / "x.mjb"),
                               mjcf.FileReadError, "x.mjb: cannot read the file: No such"),
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


def test_bind_of_what_is_no_element_is_a_binding_error() -> None:
    model = _model()
    model.worldbody.body[0].add_geom(size=(0.1,))  # a moving body needs mass to compile
    physics = mjcf.Physics.from_mjcf_model(model)
    with pytest.raises(BindingError, match=r"cannot bind 5: bind takes an MJCF "
                                                        r"element or a sequence of them"):
        _call(physics.bind, 5)
    with pytest.raises(mjcf.InvalidTypeError, match=r"mjcf_model must be a model"):
        _call(physics.reload_from_mjcf_model, 5)


def test_a_bad_command_line_setting_is_one_line_exit_2(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from typed_mjcf.cli import main

    (tmp_path / "m.xml").write_text("<mujoco/>")
    assert main(["check", "--compile", "--allow-files", "", str(tmp_path / "m.xml")]) == 2
    assert capsys.readouterr().err == (
        "typed-mjcf check: --allow-files: FileAccess.roots holds '', not a folder path\n")
