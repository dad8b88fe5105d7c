"""A minimal PNG encoder (zlib from the standard library): enough to save a rendered image
without a dependency on an imaging library."""

from __future__ import annotations

import struct
import zlib

import numpy as np

from typed_mjcf.types import MuJoCoArray

_COLOR_TYPES = {1: 0, 2: 4, 3: 2, 4: 6}  # channels -> PNG colour type (grey, +alpha, RGB, RGBA)


def _chunk(kind: bytes, payload: bytes) -> bytes:
    return (struct.pack(">I", len(payload)) + kind + payload
            + struct.pack(">I", zlib.crc32(kind + payload) & 0xFFFFFFFF))


def encode_png(array: MuJoCoArray) -> bytes:
    """``array`` (height x width, or height x width x 1-4 channels; 8 bits each) as PNG
    bytes. Other dtypes must hold values 0-255; ``ValueError`` otherwise."""
    pixels = np.asarray(array)
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    if pixels.ndim != 3 or pixels.shape[2] not in _COLOR_TYPES or 0 in pixels.shape[:2]:
        raise ValueError(f"a PNG image is height x width x 1-4 channels, got shape "
                         f"{pixels.shape}")
    if pixels.dtype != np.uint8:
        if pixels.size and (pixels.min() < 0 or pixels.max() > 255
                            or not np.array_equal(pixels, np.round(pixels))):
            raise ValueError(f"PNG pixels are whole numbers 0-255; got {pixels.dtype} values "
                             f"from {pixels.min()} to {pixels.max()}")
        pixels = pixels.astype(np.uint8)
    height, width, channels = pixels.shape
    # each row starts with its filter type: 0, none
    rows = np.concatenate([np.zeros((height, 1), np.uint8),
                           np.ascontiguousarray(pixels).reshape(height, width * channels)],
                          axis=1)
    header = struct.pack(">IIBBBBB", width, height, 8, _COLOR_TYPES[channels], 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header)
            + _chunk(b"IDAT", zlib.compress(rows.tobytes(), 6)) + _chunk(b"IEND", b""))
