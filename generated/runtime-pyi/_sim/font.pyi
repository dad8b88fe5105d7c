# Generated from src/typed_mjcf/_sim/font.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Text on pictures: a 5x7 bitmap font drawn with numpy (labels of views and panels)."""
from __future__ import annotations
import numpy as np
from numpy.typing import NDArray
Image = NDArray[np.uint8]
GLYPH_WIDTH, GLYPH_HEIGHT = 5, 9

def text_size(text: str, scale: int = 1) -> tuple[int, int]:
    """The (width, height) in pixels that :func:`draw_text` covers."""
    ...

def draw_text(image: Image, text: str, x: int, y: int, colour: tuple[int, int, int],
              scale: int = 1) -> None:
    """Draw ``text`` into ``image`` (height x width x 3) with its top left corner at
    (``x``, ``y``), each font pixel ``scale`` pixels square; what falls outside is cut."""
    ...
