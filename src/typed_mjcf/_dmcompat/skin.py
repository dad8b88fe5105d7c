"""``dm_control.mjcf.skin``: MuJoCo's binary skin files (``.skn``) read into arrays and
written back, bones naming their bodies through ``body_getter`` (a name -> element)."""

from __future__ import annotations

import struct
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from typed_mjcf._skin import NAME_BYTES

MAX_BODY_NAME_LENGTH = NAME_BYTES


class Bone(NamedTuple):
    """One bone: the body it follows (an element), its bind pose and its vertices."""

    body: Any  # whatever body_getter gave: an element with a full_identifier
    bindpos: np.ndarray[Any, np.dtype[np.float32]]
    bindquat: np.ndarray[Any, np.dtype[np.float32]]
    vertex_ids: np.ndarray[Any, np.dtype[np.int32]]
    vertex_weights: np.ndarray[Any, np.dtype[np.float32]]


class Skin(NamedTuple):
    """A skin file's contents."""

    vertices: np.ndarray[Any, np.dtype[np.float32]]
    texcoords: np.ndarray[Any, np.dtype[np.float32]]
    faces: np.ndarray[Any, np.dtype[np.int32]]
    bones: list[Bone]


def parse(contents: bytes, body_getter: Callable[[str], Any]) -> Skin:
    """Read a skin file; each bone's body is ``body_getter(name)``."""
    nvertex, ntexcoord, nface, nbone = struct.unpack_from("<iiii", contents, 0)
    offset = 16

    def take(dtype: type[np.generic], count: int) -> np.ndarray[Any, Any]:
        nonlocal offset
        array = np.frombuffer(contents, dtype, count, offset).copy()
        offset += 4 * count
        return array

    vertices = take(np.float32, 3 * nvertex).reshape(-1, 3)
    texcoords = take(np.float32, 2 * ntexcoord).reshape(-1, 2)
    faces = take(np.int32, 3 * nface).reshape(-1, 3)
    bones: list[Bone] = []
    for _ in range(nbone):
        name = contents[offset:offset + NAME_BYTES].split(b"\0", 1)[0].decode("utf-8")
        offset += NAME_BYTES
        bindpos, bindquat = take(np.float32, 3), take(np.float32, 4)
        (count,) = struct.unpack_from("<i", contents, offset)
        offset += 4
        bones.append(Bone(body_getter(name), bindpos, bindquat, take(np.int32, count),
                          take(np.float32, count)))
    return Skin(vertices, texcoords, faces, bones)


def serialize(skin: Skin) -> bytes:
    """A skin file's bytes; each bone names its body by ``full_identifier``."""
    parts = [struct.pack("<iiii", len(skin.vertices), len(skin.texcoords), len(skin.faces),
                         len(skin.bones)),
             np.asarray(skin.vertices, np.float32).tobytes(),
             np.asarray(skin.texcoords, np.float32).tobytes(),
             np.asarray(skin.faces, np.int32).tobytes()]
    for bone in skin.bones:
        name = str(bone.body.full_identifier).encode("utf-8")
        if len(name) > NAME_BYTES:
            raise ValueError(f"the body name {name.decode()!r} is longer than the "
                             f"{NAME_BYTES} bytes a skin file allows")
        parts += [name.ljust(NAME_BYTES, b"\0"), np.asarray(bone.bindpos, np.float32).tobytes(),
                  np.asarray(bone.bindquat, np.float32).tobytes(),
                  struct.pack("<i", len(bone.vertex_ids)),
                  np.asarray(bone.vertex_ids, np.int32).tobytes(),
                  np.asarray(bone.vertex_weights, np.float32).tobytes()]
    return b"".join(parts)
