"""Positive typing cases for pictures: what the checkers infer for ``render`` and friends
(checked by ``test_typecheck.py``; also run, rendering tiny pictures)."""

# pyright: reportUnnecessaryTypeIgnoreComment=true

from __future__ import annotations

from pathlib import Path
from typing import assert_type

import typed_mjcf as mjcf
from typed_mjcf.types import RgbImage


def test_render_types(tmp_path: Path) -> None:
    model = mjcf.RootElement(model="typed")
    model.worldbody.add_geom(type="sphere", size=0.1)
    camera = model.worldbody.add_camera(name="eye", pos=(0, -1, 0), xyaxes=(1, 0, 0, 0, 0, 1))
    key = model.keyframe.add_key(name="start")
    assert_type(model.render(width=32, height=24), RgbImage)
    assert_type(model.render("eye", width=32, height=24, keyframe="start", time=0.01), RgbImage)
    assert_type(model.render(camera, width=32, height=24, keyframe=key), RgbImage)
    assert_type(model.render(width=32, height=24, keyframe=0), RgbImage)
    view = mjcf.FreeView(azimuth=45, elevation=-30, distance=2.0, lookat=(0, 0, 0))
    assert_type(view.lookat, tuple[float, float, float] | None)
    assert_type(model.render(view, width=32, height=24), RgbImage)
    assert_type(model.render(width=64, height=48, views=("front", "eye")), RgbImage)
    assert_type(model.render_png(tmp_path / "a.png", width=32, height=24), None)
    assert_type(mjcf.VIEWS["front"], tuple[float, float])
    mjcf.set_notebook_display("xml")
    mjcf.set_notebook_display("picture", size=(64, 48))
    mjcf.set_notebook_display()
