"""Notebooks show a model as its picture, with the MJCF a click away; never an exception."""

from __future__ import annotations

import base64
import re
import struct

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._sim import gl as _gl

from .scenes import box_scene, decode_png


@pytest.fixture(autouse=True)
def _default_display() -> object:
    yield
    mjcf.set_notebook_display()


def test_repr_png_is_a_valid_png_of_the_default_view() -> None:
    model = box_scene()
    data = model._repr_png_()
    assert data is not None and data[:8] == b"\x89PNG\r\n\x1a\n"
    assert data[12:16] == b"IHDR" and struct.unpack(">II", data[16:24]) == (480, 360)
    assert np.array_equal(decode_png(data), model.render(width=480, height=360))


def test_the_mimebundle_renders_once_and_folds_the_xml() -> None:
    model = box_scene()
    bundle = model._repr_mimebundle_()
    png = bundle["image/png"]
    html = bundle["text/html"]
    assert isinstance(png, bytes) and isinstance(html, str)
    embedded = re.search(r'src="data:image/png;base64,([^"]+)"', html)
    assert embedded is not None and base64.b64decode(embedded[1]) == png
    assert "<details><summary>MJCF</summary><pre>&lt;mujoco model=&quot;box_scene&quot;&gt;" in html


def test_the_display_switch_shows_the_xml_only() -> None:
    mjcf.set_notebook_display("xml")
    model = box_scene()
    assert model._repr_png_() is None
    bundle = model._repr_mimebundle_()
    assert list(bundle) == ["text/html"]
    assert str(bundle["text/html"]).startswith("<pre>&lt;mujoco")


def test_the_picture_size_is_a_setting() -> None:
    mjcf.set_notebook_display("picture", size=(64, 48))
    data = box_scene()._repr_png_()
    assert data is not None and struct.unpack(">II", data[16:24]) == (64, 48)
    with pytest.raises(mjcf.InvalidValueError, match=r"size=\(64, 0\)"):
        mjcf.set_notebook_display("picture", size=(64, 0))
    with pytest.raises(mjcf.InvalidValueError, match=r"mode='png'"):
        mjcf.set_notebook_display("png")  # type: ignore[arg-type]


def test_no_picture_falls_back_to_the_text_with_a_warning(monkeypatch: pytest.MonkeyPatch
                                                          ) -> None:
    monkeypatch.setattr(_gl, "_chosen", {})
    monkeypatch.setenv("MUJOCO_GL", "disable")
    model = box_scene()
    with pytest.warns(RuntimeWarning, match="no picture of the model: cannot render: "
                      "MUJOCO_GL=disable"):
        assert model._repr_png_() is None
    with pytest.warns(RuntimeWarning):
        bundle = model._repr_mimebundle_()
    assert list(bundle) == ["text/html"] and "&lt;mujoco" in str(bundle["text/html"])


def test_a_model_that_does_not_compile_shows_its_text() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_geom(type="mesh", mesh="nothing")
    with pytest.warns(RuntimeWarning, match="no picture of the model"):
        assert model._repr_png_() is None
