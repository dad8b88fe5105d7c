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
import numpy.typing as npt

from typed_mjcf._core.errors import did_you_mean
from typed_mjcf._sim.binding import DATA, MODEL, assign_array, binding_tables, index_array, rows
from typed_mjcf.types import Array, MuJoCoArray

if TYPE_CHECKING:
    import mujoco

S = TypeVar("S", np.float64, np.float32, np.int64, np.int32, np.int8, np.uint64, np.uint8,
            np.bool_)


class Axis:
    """One dimension of an array: names (or none) to numpy indices."""

    __slots__ = ("names", "rows", "slices")

    names: list[str]
    rows: dict[str, Array[np.intp] | int]
    slices: bool  # ragged: each name has rows of its own

    def __init__(self, names: Sequence[str] = (),
                 rows_of: Sequence[Array[np.intp]] | None = None) -> None:
        self.names = list(names)
        # each name's rows (a ragged axis: a joint's qpos rows); else its position
        self.rows = {}
        for position, name in enumerate(self.names):
            if name:
                self.rows[name] = position if rows_of is None else rows_of[position]
        self.slices = rows_of is not None

    def key(self, item: object) -> object:
        """``item`` (a name, a list of names, or a numpy index) as a numpy index."""
        if item is Ellipsis or item is None:
            raise IndexError(f"{item!r} is not supported in a named index")
        if isinstance(item, str):
            return self._one(item, True)
        if isinstance(item, list | tuple | np.ndarray):
            array = np.asarray(cast("npt.ArrayLike", item))
            if not array.size or array.dtype.kind not in "USO" or not isinstance(
                    array.flat[0], str):
                return array
            found = [self._one(str(name), False) for name in array.flat]
            if all(isinstance(f, int) for f in found):  # one row each: keep the shape
                return np.asarray(found, dtype=np.intp).reshape(array.shape)
            return np.concatenate([np.atleast_1d(np.asarray(f)) for f in found])
        return item

    def convert_key_item(self, key_item: object) -> object:
        """dm_control's name for :meth:`key` (``inverse_kinematics`` calls it)."""
        return self.key(key_item)

    def _one(self, name: str, alone: bool) -> object:
        if not name:
            raise IndexError("Empty strings are not allowed in a named index")
        found = self.rows.get(name)
        if found is None:
            raise KeyError(f"no name {name!r} on this axis{did_you_mean(name, self.rows)}")
        if isinstance(found, int):
            return found
        if alone and len(found) and bool((np.diff(found) == 1).all()):
            return slice(int(found[0]), int(found[-1]) + 1)  # a view of the element's rows
        return found


UNNAMED = Axis()


class Axes(NamedTuple):
    """An indexer's axes, as dm_control names them: ``axes.row``, ``axes.col`` (``None``
    for a one-dimensional array)."""

    row: Axis
    col: Axis | None = None


class FieldIndexer(Generic[S]):
    """An array of MuJoCo's indexed by names as well as numbers (``__array__``, ``shape``,
    ``dtype`` as the array's; ``indexer[...]`` reads, ``indexer[...] = v`` writes)."""

    __slots__ = ("_array", "_axes", "_name")

    _array: Array[S]
    _axes: tuple[Axis, ...]
    _name: str

    def __init__(self, name: str, array: Array[S], axes: tuple[Axis, ...]) -> None:
        self._name = name
        self._array = array
        self._axes = axes

    @property
    def axes(self) -> Axes:
        """The row axis and, for a two-dimensional array, the column axis."""
        return Axes(*self._axes)

    @property
    def shape(self) -> tuple[int, ...]:
        return self._array.shape

    @property
    def dtype(self) -> np.dtype[S]:
        return self._array.dtype

    @property
    def ndim(self) -> int:
        return self._array.ndim

    def __len__(self) -> int:
        return len(self._array)

    def __array__(self, dtype: None = None, copy: bool | None = None) -> Array[S]:
        return self._array

    def _key(self, key: object) -> object:
        if not isinstance(key, tuple):
            return self._axes[0].key(key)
        items = cast("tuple[object, ...]", key)
        if len(items) > self._array.ndim:
            raise IndexError(f"{self._name}: an index of {len(items)} items for an array of "
                             f"{self._array.ndim} dimensions")
        return tuple(axis.key(item) for axis, item in zip(self._axes, items, strict=False))

    def __getitem__(self, key: object) -> Array[S]:
        return cast("Array[S]", index_array(cast(MuJoCoArray, self._array), self._key(key)))

    def __setitem__(self, key: object, value: object) -> None:
        assign_array(cast(MuJoCoArray, self._array), self._key(key), value)

    def __repr__(self) -> str:
        lines = [f"FieldIndexer({self._name}):"]
        names = [""] * (self._array.shape[0] if self._array.ndim else 0)
        for name, where in self._axes[0].rows.items():
            for row in np.atleast_1d(np.asarray(where)):
                names[int(row)] = name
        width = max((len(n) for n in names), default=0)
        for i, row in enumerate(self._array):
            lines.append(f"{i:3d} {names[i]:>{width}} {np.array2string(np.atleast_1d(row))}")
        return "\n".join(lines) if len(lines) > 1 else lines[0] + "\n(empty)"


AnyIndexer: TypeAlias = (
    FieldIndexer[np.float64] | FieldIndexer[np.float32] | FieldIndexer[np.int64]
    | FieldIndexer[np.int32] | FieldIndexer[np.int8] | FieldIndexer[np.uint64]
    | FieldIndexer[np.uint8] | FieldIndexer[np.bool_])


class StructIndexer:
    """Named indexers for every array of ``MjModel`` (``physics.named.model``) or ``MjData``
    (``physics.named.data``) that MuJoCo indexes by object."""

    __slots__ = ("_indexers",)

    def __init__(self, indexers: dict[str, AnyIndexer]) -> None:
        self._indexers = indexers

    def _asdict(self) -> dict[str, AnyIndexer]:
        return dict(self._indexers)

    def __dir__(self) -> Iterator[str]:
        return iter(sorted({*super().__dir__(), *self._indexers}))

    if not TYPE_CHECKING:  # the generated classes declare each array

        def __getattr__(self, name: str) -> AnyIndexer:
            if name.startswith("__"):
                raise AttributeError(name)
            try:
                return self._indexers[name]
            except KeyError:
                raise AttributeError(f"{name!r}: no array of that name is indexed by name"
                                     f"{did_you_mean(name, self._indexers)}") from None


def make_axes(model: mujoco.MjModel) -> dict[str, Axis]:
    """Each size MuJoCo's arrays have (``nbody``, ``nq``, ...) with its names, and each set
    of column names."""
    import mujoco

    tables = binding_tables()
    names_of: dict[str, list[str]] = {}
    for size, objtype in tables.objects.items():
        count = int(getattr(model, size))
        kind = getattr(mujoco.mjtObj, objtype)
        names_of[size] = [mujoco.mj_id2name(model, kind, i) or "" for i in range(count)]
    axes: dict[str, Axis] = {size: Axis(names) for size, names in names_of.items()}
    for size, ragged in tables.ragged.items():
        owner = names_of.get(ragged.owner, [])
        if ragged.index is not None:  # a subset (mocap bodies): in the subset's order
            index = np.asarray(getattr(model, ragged.index)).ravel()
            subset = [""] * int(getattr(model, size))
            for position, row in enumerate(index):
                if row >= 0:
                    subset[int(row)] = owner[position]
            axes[size] = Axis(subset)
            continue
        per = [rows(model, size, np.asarray([i], dtype=np.intp)) for i in range(len(owner))]
        axes[size] = Axis(owner, [p if p is not None else np.zeros(0, np.intp) for p in per])
    for key, names in tables.columns.items():
        axes[key] = Axis(names)
    return axes


def struct_indexers(model: mujoco.MjModel, data: mujoco.MjData,
                    axes: dict[str, Axis]) -> tuple[dict[str, AnyIndexer],
                                                    dict[str, AnyIndexer]]:
    """The named indexers of ``model``'s and ``data``'s arrays."""
    out: dict[str, dict[str, AnyIndexer]] = {MODEL: {}, DATA: {}}
    sources: dict[str, object] = {MODEL: model, DATA: data}
    for (struct, name), (row, column) in binding_tables().fields.items():
        array = getattr(sources[struct], name, None)
        if not isinstance(array, np.ndarray):
            continue
        found = (axes.get(row, UNNAMED), axes.get(column, UNNAMED))[:max(1, array.ndim)]
        out[struct][name] = cast(AnyIndexer, FieldIndexer(
            name, cast("Array[np.float64]", array), found))  # its dtype: the generated types
    return out[MODEL], out[DATA]
