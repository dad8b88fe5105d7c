# Generated from src/typed_mjcf/_dmcompat/skin.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.skin``: MuJoCo's binary skin files (``.skn``) read into arrays and
written back, bones naming their bodies through ``body_getter`` (a name -> element)."""
from __future__ import annotations
from collections.abc import Callable
from typing import NamedTuple, TypeAlias
import numpy as np
from typed_mjcf._text.skin import NAME_BYTES
MAX_BODY_NAME_LENGTH = NAME_BYTES
Floats: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float32]]
Ints: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.int32]]

class Bone(NamedTuple):
    """One bone: the body it follows (an element), its bind pose and its vertices."""
    body: object
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
    ...

def serialize(skin: Skin) -> bytes:
    """A skin file's bytes; each bone names its body by ``full_identifier``."""
    ...
