# Generated from src/typed_mjcf/_sim/notebook.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""How a model shows itself in a notebook: its picture, with its MJCF a click away."""
from __future__ import annotations
from typing import Literal, cast
from typed_mjcf._core.tree import ModelBase
Display = Literal["picture", "xml"]

def set_notebook_display(mode: Display = "picture", size: tuple[int, int] = (480, 360)) -> None:
    """How notebooks show a model: ``"picture"`` (its default view, ``size`` = (width,
    height) in pixels, the MJCF folded under a click) or ``"xml"`` (the MJCF; no rendering)."""
    ...

def repr_png(model: ModelBase) -> bytes | None:
    """The picture as PNG bytes; ``None`` (the notebook shows the text instead) when the
    display is set to XML or the model cannot be rendered (a warning says why)."""
    ...

def repr_mimebundle(model: ModelBase) -> dict[str, str | bytes]:
    """What IPython shows, rendered once: the picture (PNG, and HTML with the MJCF under a
    ``<details>`` click), or the MJCF alone in XML mode or when there is no picture."""
    ...
