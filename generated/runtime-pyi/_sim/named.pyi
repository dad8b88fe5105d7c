# Generated from src/typed_mjcf/_sim/named.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Named indexers: ``physics.named.data.qpos["arm/elbow"]``, as dm_control has them.

Every array of ``MjModel`` and ``MjData`` whose rows (or columns) are MuJoCo objects is
indexed by the objects' names: the rows of ``xpos`` by body names, ``qpos`` by joint names
(a free joint's seven rows at once), ``sensordata`` by sensor names; columns by name where
they are coordinates (``xpos[..., "z"]``, ``geom_rgba["floor", "a"]``) or objects
(``key_qpos["home", "arm/elbow"]``). Which size names which rows is the generated table.
"""
from __future__ import annotations
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Generic, NamedTuple, TypeAlias, TypeVar, cast
import numpy as np
from typed_mjcf.types import Array, MuJoCoArray
import mujoco
S = TypeVar("S", np.float64, np.float32, np.int64, np.int32, np.int8, np.uint64, np.uint8,
            np.bool_)

class Axis:
    """One dimension of an array: names (or none) to numpy indices."""
    names: list[str]
    rows: dict[str, Array[np.intp] | int]
    slices: bool
    def __init__(self, names: Sequence[str] = (),
                 rows_of: Sequence[Array[np.intp]] | None = None) -> None: ...
    def key(self, item: object) -> object:
        """``item`` (a name, a list of names, or a numpy index) as a numpy index."""
        ...
    def convert_key_item(self, key_item: object) -> object:
        """dm_control's name for :meth:`key` (``inverse_kinematics`` calls it)."""
        ...
UNNAMED = Axis()

class Axes(NamedTuple):
    """An indexer's axes, as dm_control names them: ``axes.row``, ``axes.col`` (``None``
    for a one-dimensional array)."""
    row: Axis
    col: Axis | None = None

class FieldIndexer(Generic[S]):
    """An array of MuJoCo's indexed by names as well as numbers (``__array__``, ``shape``,
    ``dtype`` as the array's; ``indexer[...]`` reads, ``indexer[...] = v`` writes)."""
    _array: Array[S]
    _axes: tuple[Axis, ...]
    _name: str
    def __init__(self, name: str, array: Array[S], axes: tuple[Axis, ...]) -> None: ...
    @property
    def axes(self) -> Axes:
        """The row axis and, for a two-dimensional array, the column axis."""
        ...
    @property
    def shape(self) -> tuple[int, ...]: ...
    @property
    def dtype(self) -> np.dtype[S]: ...
    @property
    def ndim(self) -> int: ...
    def __len__(self) -> int: ...
    def __array__(self, dtype: None = None, copy: bool | None = None) -> Array[S]: ...
    def __getitem__(self, key: object) -> Array[S]: ...
    def __setitem__(self, key: object, value: object) -> None: ...
    def __repr__(self) -> str: ...
AnyIndexer: TypeAlias = (
    FieldIndexer[np.float64] | FieldIndexer[np.float32] | FieldIndexer[np.int64]
    | FieldIndexer[np.int32] | FieldIndexer[np.int8] | FieldIndexer[np.uint64]
    | FieldIndexer[np.uint8] | FieldIndexer[np.bool_])

class StructIndexer:
    """Named indexers for every array of ``MjModel`` (``physics.named.model``) or ``MjData``
    (``physics.named.data``) that MuJoCo indexes by object."""
    def __init__(self, indexers: dict[str, AnyIndexer]) -> None: ...
    def __dir__(self) -> Iterator[str]: ...

def make_axes(model: mujoco.MjModel) -> dict[str, Axis]:
    """Each size MuJoCo's arrays have (``nbody``, ``nq``, ...) with its names, and each set
    of column names."""
    ...

def struct_indexers(model: mujoco.MjModel, data: mujoco.MjData,
                    axes: dict[str, Axis]) -> tuple[dict[str, AnyIndexer],
                                                    dict[str, AnyIndexer]]:
    """The named indexers of ``model``'s and ``data``'s arrays."""
    ...
