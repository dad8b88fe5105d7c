"""``dm_control.mjcf.skin``: MuJoCo's binary skin files (``.skn``) read into arrays and
written back, bones naming their bodies through ``body_getter`` (a name -> element)."""

from __future__ import annotations

import struct
from collections.abc import Callable
from typing import NamedTuple, TypeAlias

import numpy as np

from typed_mjcf._text.skin import NAME_BYTES

MAX_BODY_NAME_LENGTH = NAME_BYTES

Floats: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float32]]
Ints: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.int32]]


class Bone(NamedTuple):
    """One bone: the body it follows (an element), its bind pose and its vertices."""

    body: object  # what body_getter gave: an element (written by its full_identifier)
    bindpos: Floats
    bindquat: Floats
    vertex_ids: Ints
    vertex_weights: Floats


class Skin(NamedTuple):
    """A skin file's contents."""

    vertices: Floats
    texcoords: Floats
    faces: Ints
    bones: list[Bone]


def parse(contents: bytes, body_getter: Callable[[str], object]) -> Skin:
    """Read a skin file; each bone's body is ``body_getter(name)``."""
    nvertex, ntexcoord, nface, nbone = struct.unpack_from("<iiii", contents, 0)
    offset = 16

    def floats(count: int) -> Floats:
        nonlocal offset
        array = np.frombuffer(contents, np.float32, count, offset).copy()
        offset += 4 * count
        return array

    def ints(count: int) -> Ints:
        nonlocal offset
        array = np.frombuffer(contents, np.int32, count, offset).copy()
        offset += 4 * count
        return array

    vertices = floats(3 * nvertex).reshape(-1, 3)
    texcoords = floats(2 * ntexcoord).reshape(-1, 2)
    faces = ints(3 * nface).reshape(-1, 3)
    bones: list[Bone] = []
    for _ in range(nbone):
        name = contents[offset:offset + NAME_BYTES].split(b"\0", 1)[0].decode("utf-8")
        offset += NAME_BYTES
        bindpos, bindquat = floats(3), floats(4)
        (count,) = struct.unpack_from("<i", contents, offset)
        offset += 4
        bones.append(Bone(body_getter(name), bindpos, bindquat, ints(count), floats(count)))
    return Skin(vertices, texcoords, faces, bones)


def serialize(skin: Skin) -> bytes:
    """A skin file's bytes; each bone names its body by ``full_identifier``."""
    parts = [struct.pack("<iiii", len(skin.vertices), len(skin.texcoords), len(skin.faces),
                         len(skin.bones)),
             np.asarray(skin.vertices, np.float32).tobytes(),
             np.asarray(skin.texcoords, np.float32).tobytes(),
             np.asarray(skin.faces, np.int32).tobytes()]
    for bone in skin.bones:
        name = str(getattr(bone.body, "full_identifier")).encode("utf-8")  # noqa: B009 - any object with one
        if len(name) > NAME_BYTES:
            raise ValueError(f"the body name {name.decode()!r} is longer than the "
                             f"{NAME_BYTES} bytes a skin file allows")
        parts += [name.ljust(NAME_BYTES, b"\0"), np.asarray(bone.bindpos, np.float32).tobytes(),
                  np.asarray(bone.bindquat, np.float32).tobytes(),
                  struct.pack("<i", len(bone.vertex_ids)),
                  np.asarray(bone.vertex_ids, np.int32).tobytes(),
                  np.asarray(bone.vertex_weights, np.float32).tobytes()]
    return b"".join(parts)
