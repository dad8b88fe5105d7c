"""Public type aliases used in the annotations of the generated classes."""

from __future__ import annotations

import os
from typing import TypeAlias

import numpy as np

from typed_mjcf.assets import Asset

Float64Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
"""What a ``double`` array attribute reads as."""
Float32Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float32]]
"""What a ``float`` array attribute reads as."""
Int32Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.int32]]
"""What an ``int`` array attribute reads as."""

FloatArrayLike: TypeAlias = (
    np.ndarray[tuple[int, ...], np.dtype[np.float64]]
    | np.ndarray[tuple[int, ...], np.dtype[np.float32]]
    | np.ndarray[tuple[int, ...], np.dtype[np.int64]]
    | np.ndarray[tuple[int, ...], np.dtype[np.int32]]
)
"""numpy arrays a real-valued array attribute accepts (checked for length at assignment)."""
IntArrayLike: TypeAlias = (
    np.ndarray[tuple[int, ...], np.dtype[np.int64]]
    | np.ndarray[tuple[int, ...], np.dtype[np.int32]]
)
"""numpy arrays an integer array attribute accepts."""

FileLike: TypeAlias = str | os.PathLike[str] | Asset
"""A file attribute: a path, or contents held in memory."""

__all__ = [
    "Asset", "FileLike", "Float32Array", "Float64Array", "FloatArrayLike", "Int32Array",
    "IntArrayLike",
]
