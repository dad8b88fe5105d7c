"""A scene whose pictures are known in advance, and a PNG reader for the tests."""

from __future__ import annotations

import math
import struct
import zlib

import numpy as np
from numpy.typing import NDArray

import typed_mjcf as mjcf

Image = NDArray[np.uint8]
BOX_AT = (0.5, 0.0, 0.2)  # the red box's centre; it is 0.4 m on a side
HALF = 0.2
ABOVE = 3.0  # the height of the camera "above", looking straight down at the origin
FOVY = 45.0  # MuJoCo's default field of view, cameras and free views alike


def box_scene() -> mjcf.RootElement:
    """A red box on a grey plane, lit from above; it slides along y (keyframe "moved")."""
    model = mjcf.RootElement(model="box_scene")
    model.worldbody.add_light(pos=(0, 0, 3), dir=(0, 0, -1))
    model.worldbody.add_geom(name="floor", type="plane", size=(3, 3, 0.1),
                             rgba=(0.5, 0.5, 0.5, 1))
    box = model.worldbody.add_body(name="box", pos=BOX_AT)
    box.add_joint(name="slide", type="slide", axis=(0, 1, 0))
    box.add_geom(name="box", type="box", size=(HALF, HALF, HALF), rgba=(1, 0, 0, 1))
    model.worldbody.add_camera(name="above", pos=(0, 0, ABOVE))
    model.keyframe.add_key(name="moved", qpos=(0.8,))
    return model


def red(image: Image) -> NDArray[np.bool_]:
    """Pixels of the red box (lit or in its own shade)."""
    r, g, b = (image[..., i].astype(np.int32) for i in range(3))
    return (r > 60) & (r > 2 * g + 20) & (r > 2 * b + 20)


def grey(image: Image) -> NDArray[np.bool_]:
    """Pixels of an uncoloured surface (the plane, lit or in shadow)."""
    channels = image.astype(np.int32)
    return np.ptp(channels, axis=2) <= 12


def centroid(mask: NDArray[np.bool_]) -> tuple[float, float]:
    """(column, row) of the mask's pixels."""
    rows, columns = np.nonzero(mask)
    assert rows.size, "no pixels in the mask"
    return float(columns.mean()), float(rows.mean())


def projected_top(width: int, height: int, y_shift: float = 0.0) -> tuple[float, float,
                                                                         float, float]:
    """Where the box's top face lands, seen from ``ABOVE`` m straight down at the origin
    (+x to the right, +y up): (left, right, top, bottom) in pixel coordinates."""
    focal = (height / 2) / math.tan(math.radians(FOVY / 2))
    depth = ABOVE - (BOX_AT[2] + HALF)
    x0, x1 = BOX_AT[0] - HALF, BOX_AT[0] + HALF
    y0, y1 = BOX_AT[1] + y_shift - HALF, BOX_AT[1] + y_shift + HALF
    return (width / 2 + focal * x0 / depth, width / 2 + focal * x1 / depth,
            height / 2 - focal * y1 / depth, height / 2 - focal * y0 / depth)


def decode_png(data: bytes) -> Image:
    """The pixels of an 8-bit, non-interlaced grey, RGB or RGBA PNG (any row filters)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG signature"
    at, chunks = 8, {}
    idat = b""
    while at < len(data):
        (length,) = struct.unpack(">I", data[at : at + 4])
        kind, body = data[at + 4 : at + 8], data[at + 8 : at + 8 + length]
        (crc,) = struct.unpack(">I", data[at + 8 + length : at + 12 + length])
        assert crc == zlib.crc32(kind + body) & 0xFFFFFFFF, f"bad CRC in {kind!r}"
        if kind == b"IDAT":
            idat += body
        chunks[kind] = body
        at += 12 + length
    assert list(chunks)[-1] == b"IEND" and next(iter(chunks)) == b"IHDR"
    width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks[b"IHDR"])
    assert depth == 8 and interlace == 0
    channels = {0: 1, 2: 3, 6: 4}[colour]
    stride = width * channels
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8).reshape(height, 1 + stride)
    out = np.zeros((height, stride), dtype=np.int32)
    for y in range(height):
        kind, row = raw[y, 0], raw[y, 1:].astype(np.int32)
        above = out[y - 1] if y else np.zeros(stride, dtype=np.int32)
        if kind in (0, 2):
            out[y] = (row + (above if kind == 2 else 0)) % 256
            continue
        for x in range(stride):  # Sub, Average, Paeth: each byte needs the one to its left
            left = out[y, x - channels] if x >= channels else 0
            corner = above[x - channels] if x >= channels else 0
            if kind == 1:
                guess = left
            elif kind == 3:
                guess = (left + above[x]) // 2
            else:
                p = left + above[x] - corner
                pa, pb, pc = abs(p - left), abs(p - above[x]), abs(p - corner)
                guess = left if pa <= pb and pa <= pc else above[x] if pb <= pc else corner
            out[y, x] = (row[x] + guess) % 256
    pixels = out.astype(np.uint8).reshape(height, width, channels)
    return pixels[:, :, 0] if channels == 1 else pixels
