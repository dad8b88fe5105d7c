"""How a model shows itself in a notebook: its picture, with its MJCF a click away."""

from __future__ import annotations

import base64
import html
import warnings
from dataclasses import dataclass
from typing import Literal, cast

from typed_mjcf._core.errors import InvalidValueError, MjcfError
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._sim.png import encode_png
from typed_mjcf._sim.preview import render
from typed_mjcf._sim.text import model_text

Display = Literal["picture", "xml"]


@dataclass
class _Settings:
    mode: Display = "picture"
    size: tuple[int, int] = (480, 360)


_SETTINGS = _Settings()


def set_notebook_display(mode: Display = "picture", size: tuple[int, int] = (480, 360)) -> None:
    """How notebooks show a model: ``"picture"`` (its default view, ``size`` = (width,
    height) in pixels, the MJCF folded under a click) or ``"xml"`` (the MJCF; no rendering)."""
    if mode not in ("picture", "xml"):
        raise InvalidValueError(f"set_notebook_display: mode={mode!r}: expected 'picture' or "
                                f"'xml'")
    if not _is_size(size):
        raise InvalidValueError(f"set_notebook_display: size={size!r}: expected (width, "
                                f"height) in pixels")
    _SETTINGS.mode, _SETTINGS.size = mode, size


def _is_size(size: object) -> bool:
    """Whether ``size`` is (width, height), two positive ints (checked: a notebook user may
    pass anything)."""
    if not isinstance(size, tuple):
        return False
    items = cast("tuple[object, ...]", size)
    return len(items) == 2 and all(type(n) is int and n > 0 for n in items)


def repr_png(model: ModelBase) -> bytes | None:
    """The picture as PNG bytes; ``None`` (the notebook shows the text instead) when the
    display is set to XML or the model cannot be rendered (a warning says why)."""
    return _picture(model) if _SETTINGS.mode == "picture" else None


def repr_mimebundle(model: ModelBase) -> dict[str, str | bytes]:
    """What IPython shows, rendered once: the picture (PNG, and HTML with the MJCF under a
    ``<details>`` click), or the MJCF alone in XML mode or when there is no picture."""
    try:
        xml = model_text(model)
    except MjcfError as error:  # a model that cannot be written yet: say so, don't raise
        xml = f"<!-- the model cannot be written as MJCF: {error} -->"
    code = f"<pre>{html.escape(xml)}</pre>"
    picture = _picture(model) if _SETTINGS.mode == "picture" else None
    if picture is None:
        return {"text/html": code}
    image = base64.b64encode(picture).decode("ascii")
    return {"image/png": picture,
            "text/html": (f'<img src="data:image/png;base64,{image}" alt="the model">'
                          f"<details><summary>MJCF</summary>{code}</details>")}


def _picture(model: ModelBase) -> bytes | None:
    try:
        width, height = _SETTINGS.size
        return encode_png(render(model, width=width, height=height))
    except Exception as error:  # noqa: BLE001 - never raise into a notebook: show the text
        warnings.warn(f"typed-mjcf: no picture of the model: {error}", RuntimeWarning,
                      stacklevel=3)
        return None
