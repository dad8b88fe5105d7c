# Generated from src/typed_mjcf/types.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Public type aliases used in the annotations of the generated classes."""
from __future__ import annotations
import os
from collections.abc import Iterator
from typing import Protocol, TypeAlias, TypeVar
import numpy as np
from lxml import etree
from typed_mjcf.assets import Asset
Float64Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
"""What a ``double`` array attribute reads as (read-only: assign to change it)."""
Float32Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float32]]
"""What a ``float`` array attribute reads as (read-only: assign to change it)."""
Int32Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.int32]]
"""What an ``int`` array attribute reads as (read-only: assign to change it)."""
RgbImage: TypeAlias = np.ndarray[tuple[int, int, int], np.dtype[np.uint8]]
"""A picture: height x width x 3 bytes, red, green and blue (what ``render()`` returns)."""
_IntDtype: TypeAlias = (
    np.dtype[np.int64] | np.dtype[np.int32] | np.dtype[np.int16] | np.dtype[np.int8]
    | np.dtype[np.uint64] | np.dtype[np.uint32] | np.dtype[np.uint16] | np.dtype[np.uint8]
)

class IntArrayLike(Protocol):
    """numpy arrays an integer array attribute accepts: any integer dtype.

    A protocol, not a union of ``np.ndarray`` types: a checker reads numpy's types only when
    an array is passed (tuples and lists have no ``dtype``), which keeps an editor quick."""
    def __len__(self) -> int: ...
    @property
    def dtype(self) -> _IntDtype: ...

class FloatArrayLike(Protocol):
    """numpy arrays a real-valued array attribute accepts: any real dtype (the length is
    checked at assignment)."""
    def __len__(self) -> int: ...
    @property
    def dtype(self) -> (np.dtype[np.float64] | np.dtype[np.float32] | np.dtype[np.float16]
                        | np.dtype[np.longdouble] | _IntDtype): ...

class RealScalar(Protocol):
    """A real number that is not a float: an int, or a numpy scalar (``np.float32(1.5)``,
    ``np.int64(3)``); not an array."""
    def __float__(self) -> float: ...
    def __round__(self) -> int: ...

class IntegerScalar(Protocol):
    """An integer that is not an int: a numpy integer scalar (``np.int64(3)``); not a float
    (it would be truncated) and not an array."""
    def __index__(self) -> int: ...
    def is_integer(self) -> bool: ...
Real: TypeAlias = float | RealScalar
"""A real number: a float, an int, or a numpy scalar."""
Integer: TypeAlias = int | IntegerScalar
"""An integer: an int or a numpy integer scalar."""
_T_co = TypeVar("_T_co", covariant=True)

class NumberList(Protocol[_T_co]):
    """A list (or deque) of numbers, of any length (the length is checked when it is
    assigned). Tuples are typed by their length instead (``pos=(1, 2)`` is a type error where
    three numbers are expected), and numpy arrays by their dtype."""
    def __len__(self) -> int: ...
    def __getitem__(self, index: int, /) -> _T_co: ...
    def __reversed__(self) -> Iterator[_T_co]: ...
    def copy(self) -> object: ...
_S = TypeVar("_S", np.float64, np.float32, np.int64, np.int32, np.int8, np.uint64, np.uint8,
             np.bool_, np.intp)
Array: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[_S]]
"""A numpy array of MuJoCo's, by its scalar type: ``Array[np.float64]`` (bindings, named
indexers and rendered images are such arrays)."""
MuJoCoArray: TypeAlias = (
    Array[np.float64] | Array[np.float32] | Array[np.int64] | Array[np.int32]
    | Array[np.int8] | Array[np.uint64] | Array[np.uint8] | Array[np.bool_]
)
"""An array of MuJoCo's of any of the dtypes its model and data use."""
ArrayValues: TypeAlias = (
    float | RealScalar | NumberList[float | RealScalar]
    | NumberList[NumberList[float | RealScalar]] | tuple[float | RealScalar, ...]
    | FloatArrayLike | Array[np.bool_]
)
"""What an array of MuJoCo's accepts when assigned: a number (set everywhere), sequences of
numbers (one per entry, or rows of them), or a numpy array; the shape is checked by numpy."""
FileLike: TypeAlias = str | os.PathLike[str] | Asset
"""A file attribute: a path, or contents held in memory."""
XmlElement: TypeAlias = etree._Element
"""An lxml element (what ``to_xml()`` returns)."""
__all__ = [
    "Array",
    "ArrayValues",
    "Asset",
    "FileLike",
    "Float32Array",
    "Float64Array",
    "FloatArrayLike",
    "Int32Array",
    "IntArrayLike",
    "Integer",
    "IntegerScalar",
    "MuJoCoArray",
    "NumberList",
    "Real",
    "RealScalar",
    "RgbImage",
    "XmlElement",
]
