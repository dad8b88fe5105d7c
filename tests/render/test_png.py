"""PNG files without new dependencies: what ``encode_png`` writes reads back exactly."""

from __future__ import annotations

import struct

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._sim.png import encode_png

from .scenes import decode_png


@pytest.mark.parametrize("shape", [(7, 5), (7, 5, 1), (3, 9, 3), (4, 4, 4), (1, 1, 3)])
def test_pixels_read_back_exactly(shape: tuple[int, ...]) -> None:
    pixels = np.random.default_rng(0).integers(0, 256, size=shape, dtype=np.uint8)
    data = encode_png(pixels)
    width, height = struct.unpack(">II", data[16:24])
    assert (width, height) == (shape[1], shape[0])
    expected = pixels[:, :, 0] if len(shape) == 3 and shape[2] == 1 else pixels
    assert np.array_equal(decode_png(data), expected)


@pytest.mark.parametrize(("pixels", "message"), [
    (np.zeros((2, 2, 3), dtype=np.float32), "a PNG needs uint8 pixels, got an array of float32"),
    (np.zeros((2, 2, 2), dtype=np.uint8), r"got shape \(2, 2, 2\)"),
    (np.zeros((0, 2, 3), dtype=np.uint8), r"got shape \(0, 2, 3\)"),
])
def test_arrays_that_are_not_pictures_are_refused(pixels: np.ndarray, message: str) -> None:
    with pytest.raises(mjcf.InvalidValueError, match=message):
        encode_png(pixels)
