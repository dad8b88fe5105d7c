"""The library's errors have one public home: importable from ``typed_mjcf`` and
``typed_mjcf.errors`` (every one the docs name), and shown under ``typed_mjcf.errors`` in
tracebacks, wherever the runtime defines them."""

from __future__ import annotations

import builtins
import re
import traceback
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf import errors

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *(ROOT / "docs").rglob("*.md")]


def test_every_error_is_the_same_object_from_both_homes() -> None:
    for name in errors.__all__:
        public = getattr(errors, name)
        if isinstance(public, type):
            assert getattr(mjcf, name) is public, name
            assert public.__module__ == "typed_mjcf.errors", name


def test_every_error_the_docs_name_is_importable_from_both() -> None:
    named = {m for page in PAGES if "_build" not in page.parts
             for m in re.findall(r"\b([A-Z]\w*(?:Error|Warning))\b", page.read_text("utf-8"))}
    named -= set(dir(builtins))  # ValueError, OSError, ...
    assert {"BindingError", "ValidationError", "ParseError", "PhysicsError"} <= named
    for name in named:
        assert getattr(errors, name) is getattr(mjcf, name), name


def test_a_traceback_names_the_public_module() -> None:
    model = mjcf.RootElement()
    model.actuator.add_motor(joint="nosuch")
    with pytest.raises(mjcf.ValidationError) as caught:
        model.compile()
    shown = "".join(traceback.format_exception_only(caught.value))
    assert shown.startswith("typed_mjcf.errors.ValidationError: "), shown


def test_physics_errors_are_the_public_ones() -> None:
    from typed_mjcf import physics

    assert physics.PhysicsError is errors.PhysicsError
    model = mjcf.RootElement()
    model.worldbody.add_geom(size=(0.1,))
    with pytest.raises(errors.BindingError):
        mjcf.Physics.from_mjcf_model(model).bind(mjcf.RootElement().worldbody.add_body())
