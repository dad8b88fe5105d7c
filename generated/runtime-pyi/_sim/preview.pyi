# Generated from src/typed_mjcf/_sim/preview.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Pictures of models: compile, pose, render offscreen, and lay out labelled views.

A model is compiled through :func:`typed_mjcf._sim.bridge.compile_model` (the same path as
``compile()``), posed in a fresh ``MjData`` (a keyframe, then ``time`` seconds of
simulation), and rendered with MuJoCo's own renderer (``MjrContext``, as ``mujoco.Renderer``
does) on a context of the back end :mod:`typed_mjcf._sim.gl` chose.
"""
from __future__ import annotations
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING, Final, Self, cast
import numpy as np
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.resource_limits import (
    DEFAULT_RENDER_LIMITS,
    RenderLimits,
    check_offscreen,
    check_steps,
)
from numpy.typing import NDArray
Image = NDArray[np.uint8]
Point = tuple[float, float, float]

@dataclass(frozen=True)
class FreeView:
    """A free camera looking at ``lookat`` from ``distance`` away, turned ``azimuth``
    degrees about the vertical axis and tilted ``elevation`` degrees (negative: from above),
    as in MuJoCo's viewer. What is left ``None`` is as the default view has it: the
    model's centre, 1.5 times its extent, ``<visual><global azimuth elevation>``."""
    azimuth: float | None = None
    elevation: float | None = None
    distance: float | None = None
    lookat: Point | None = None
VIEWS: Final[dict[str, tuple[float, float]]] = ...
MAX_SIZE: Final = 8192

def render(model: ModelBase, camera: object = None, *, width: object = 640,
           height: object = 480, time: object = 0.0, keyframe: object = None,
           views: object = None, limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Image:
    """The model as a height x width x 3 ``uint8`` image (see ``RootElement.render``); the
    arguments are checked here, whatever their static types said."""
    ...

def render_png(model: ModelBase, path: str | os.PathLike[str], camera: object = None, *,
               width: object = 640, height: object = 480, time: object = 0.0,
               keyframe: object = None, views: object = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> None:
    """Write :func:`render`'s picture to ``path`` as a PNG file."""
    ...

def write_png(path: str | os.PathLike[str], picture: Image) -> None:
    """Write ``picture`` as a PNG file; a path that cannot be written is a RenderError."""
    ...

def render_pair(a: ModelBase, b: ModelBase, width: int = 640, height: int = 480,
                labels: tuple[str, str] = ("A", "B"), camera: str | FreeView | None = None,
                lighting: bool = False, limits: RenderLimits = DEFAULT_RENDER_LIMITS
                ) -> tuple[Image, int]:
    """Two models side by side from the same camera, and a third panel showing the first
    with the pixels where the two models differ painted magenta; also how many differ.

    Both are framed together (the default view of their union) and rendered with the same
    visual scale, so a pixel differs only where the models differ. Which pixels differ is
    found on pictures drawn without shadows, reflections, fog and haze (unless
    ``lighting``): a changed size or position then lights the geometry that changed, not the
    floor where its shadow and reflection moved.
    """
    ...

def key_from_text(model: ModelBase, text: str) -> str | int:
    """A key as a command line names it: its name, or its index when it is a number that
    no key of the model is named."""
    ...
