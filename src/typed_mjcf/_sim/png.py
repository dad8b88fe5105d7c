"""PNG files from pixel arrays, with the standard library only (``zlib`` and ``struct``)."""

from __future__ import annotations

import struct
import zlib

import numpy as np

from typed_mjcf._core.errors import InvalidValueError
from typed_mjcf.types import MuJoCoArray

_SIGNATURE = b"\x89PNG\r\n\x1a\n"
# PNG colour types by channel count: grayscale, RGB, RGBA.
_COLOUR_TYPES = {1: 0, 3: 2, 4: 6}


def encode_png(array: MuJoCoArray) -> bytes:
    """``array`` (height x width, or height x width x 1, 3 or 4 channels of ``uint8``) as
    the bytes of a PNG file: 8 bits per channel, no interlacing, no filtering."""
    pixels = np.asarray(array)
    if pixels.dtype != np.uint8:
        raise InvalidValueError(f"a PNG needs uint8 pixels, got an array of {pixels.dtype}")
    if pixels.ndim == 2:
        pixels = pixels[:, :, np.newaxis]
    if pixels.ndim != 3 or pixels.shape[2] not in _COLOUR_TYPES or 0 in pixels.shape[:2]:
        raise InvalidValueError(f"a PNG needs a height x width (x 1, 3 or 4) array of pixels, "
                                f"got shape {pixels.shape}")
    height, width, channels = pixels.shape
    # Each row starts with its filter type: 0, none (zlib alone compresses renders well).
    rows = np.zeros((height, 1 + width * channels), dtype=np.uint8)
    rows[:, 1:] = pixels.reshape(height, width * channels)
    header = struct.pack(">IIBBBBB", width, height, 8, _COLOUR_TYPES[channels], 0, 0, 0)
    return b"".join((_SIGNATURE, _chunk(b"IHDR", header),
                     _chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)), _chunk(b"IEND", b"")))


def _chunk(kind: bytes, data: bytes) -> bytes:
    """A PNG chunk: length, type, data and the CRC of type and data."""
    return (struct.pack(">I", len(data)) + kind + data
            + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
