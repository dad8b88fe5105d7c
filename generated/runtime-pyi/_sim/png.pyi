# Generated from src/typed_mjcf/_sim/png.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""PNG files from pixel arrays, with the standard library only (``zlib`` and ``struct``)."""
from __future__ import annotations
from typed_mjcf.types import MuJoCoArray

def encode_png(array: MuJoCoArray) -> bytes:
    """``array`` (height x width, or height x width x 1, 3 or 4 channels of ``uint8``) as
    the bytes of a PNG file: 8 bits per channel, no interlacing, no filtering."""
    ...
