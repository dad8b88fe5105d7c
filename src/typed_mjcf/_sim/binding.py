"""Bindings: the ``MjModel``/``MjData`` arrays of one element, or of several of one kind.

Which arrays a kind of element has is the generated table (``bindings.py``, read from
MuJoCo): a joint's ``qpos`` is the rows of ``MjData.qpos`` its ``jnt_qposadr`` gives, a
geom's ``rgba`` its row of ``MjModel.geom_rgba``. A binding reads them as numpy arrays that
write through to MuJoCo: a view where numpy can make one (one element), else a copy that
writes its changes back (several elements). Writing an input of the simulation (``qpos``,
``ctrl``, a model array) marks the physics stale, and the next read of a derived quantity
(``xpos``, ``sensordata``) runs ``mj_forward`` first, as dm_control's bindings do.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import EllipsisType
from typing import TYPE_CHECKING, Final, Literal, Protocol, Self, TypeAlias, cast

import numpy as np
import numpy.typing as npt

from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.errors import BindingError, InvalidValueError, did_you_mean
from typed_mjcf.types import Array, MuJoCoArray

if TYPE_CHECKING:
    import mujoco

PICKLING_NOT_SUPPORTED: Final = "Objects of type {type} cannot be pickled."
MODEL: Final = "MjModel"  # the tables' names of the two structs
DATA: Final = "MjData"

# What indexes MuJoCo's arrays here: rows (a number, a slice, an array of numbers), and columns
_Item: TypeAlias = int | slice | EllipsisType | npt.NDArray[np.intp]
ArrayIndex: TypeAlias = _Item | tuple[_Item, ...]


def index_array(array: npt.NDArray[np.generic], index: object) -> npt.NDArray[np.generic]:
    """``array[index]`` (a view or a copy, as numpy gives it)."""
    out: npt.NDArray[np.generic] = array[cast(ArrayIndex, index)]
    return out


def assign_array(array: npt.NDArray[np.generic], index: object, value: object) -> None:
    """``array[index] = value``."""
    array[cast(ArrayIndex, index)] = cast("npt.ArrayLike", value)


# ---------------------------------------------------------------------------- the tables


@dataclass(frozen=True, slots=True)
class Ragged:
    """A size whose rows belong to the elements of ``owner``: each owns ``num`` rows from
    ``adr`` (without ``num``: up to the next element's address), or the one row ``index``
    gives (-1: none). ``single="row"``: a single element that owns one row is bound to that
    row itself (as to a row of its own size), as dm_control's named indexers give it."""

    owner: str
    adr: str | None = None
    num: str | None = None
    index: str | None = None
    single: str | None = None


@dataclass(frozen=True, slots=True)
class Kind:
    """A kind of element MuJoCo compiles: its ``mjtObj``, its count, its binding class, the
    arrays it binds (binding name -> ``("MjModel" | "MjData", field)``), MjSpec's list."""

    objtype: str
    size: str
    binding: type[Binding]
    attributes: Mapping[str, tuple[str, str]]
    spec_list: str


@dataclass(frozen=True, slots=True)
class BindingTables:
    """What the generated ``bindings.py`` says about MuJoCo's arrays."""

    mujoco_version: str
    kinds: Mapping[str, Kind]
    ragged: Mapping[str, Ragged]
    columns: Mapping[str, tuple[str, ...]]
    # (struct, field) -> (the size naming its rows, the size or column names of its columns)
    fields: Mapping[tuple[str, str], tuple[str, str]]
    data_inputs: frozenset[str]
    model_cosmetic: frozenset[str]
    clear_on_write: Mapping[str, tuple[str, ...]]
    # every count of objects MuJoCo names (kinds without an element too) -> its mjtObj
    objects: Mapping[str, str] = field(default_factory=lambda: {})
    sizes: frozenset[str] = field(default=frozenset())


_TABLES: list[BindingTables] = []


def finish_bindings(tables: BindingTables) -> None:
    """Called once by the generated ``bindings.py``."""
    sizes = frozenset({k.size for k in tables.kinds.values()} | set(tables.ragged))
    _TABLES[:] = [BindingTables(tables.mujoco_version, tables.kinds, tables.ragged,
                                tables.columns, tables.fields, tables.data_inputs,
                                tables.model_cosmetic, tables.clear_on_write, tables.objects,
                                sizes)]


def binding_tables() -> BindingTables:
    return _TABLES[0]


# ---------------------------------------------------------------------------- the physics


class Bound(Protocol):
    """What a binding needs of its physics."""

    @property
    def model(self) -> mujoco.MjModel: ...
    @property
    def data(self) -> mujoco.MjData: ...
    @property
    def is_dirty(self) -> bool: ...
    def mark_as_dirty(self) -> None: ...
    def forward(self) -> None: ...


def _array(physics: Bound, struct: str, name: str) -> npt.NDArray[np.generic]:
    source: object = physics.model if struct == MODEL else physics.data
    return cast("npt.NDArray[np.generic]", getattr(source, name))


def triggers_dirty(struct: str, name: str) -> bool:
    """Whether writing ``struct.name`` makes MjData's derived quantities stale."""
    tables = binding_tables()
    return name in tables.data_inputs if struct == DATA else (
        name not in tables.model_cosmetic)


def rows(model: mujoco.MjModel, size: str, ids: npt.NDArray[np.intp]) -> (
        npt.NDArray[np.intp] | None):
    """The rows of the arrays sized ``size`` that the objects ``ids`` own, in order; ``None``
    for an object that owns none where it must own one (a body that is not a mocap body)."""
    tables = binding_tables()
    ragged = tables.ragged.get(size)
    if ragged is None:
        return ids
    if ragged.index is not None:
        found = np.asarray(getattr(model, ragged.index), dtype=np.intp)[ids]
        return None if bool((found < 0).any()) else found
    assert ragged.adr is not None
    adr = np.asarray(getattr(model, ragged.adr), dtype=np.intp).ravel()
    if ragged.num is not None:
        num = np.asarray(getattr(model, ragged.num), dtype=np.intp).ravel()
    else:  # up to the next address (the last: to the end)
        total = int(getattr(model, size))
        num = np.diff(np.append(adr, total))
    starts, counts = adr[ids], np.where(adr[ids] >= 0, num[ids], 0)
    if bool((counts == 1).all()):
        return starts  # one row each (hinges, slides): their addresses
    # each element's rows in order: its start, repeated, plus 0, 1, ... within it
    total = int(counts.sum())
    offsets = np.arange(total, dtype=np.intp) - np.repeat(np.cumsum(counts) - counts, counts)
    out: npt.NDArray[np.intp] = np.repeat(starts, counts) + offsets
    return out


# ---------------------------------------------------------------------------- arrays


class BoundArray(np.ndarray[tuple[int, ...], np.dtype[np.generic]]):
    """An array of a binding: writing into it writes into MuJoCo's array (a copy writes its
    rows back), clears the flags the write invalidates, and marks the physics stale."""

    _physics: Bound
    _backing: npt.NDArray[np.generic]
    _rows: npt.NDArray[np.intp] | None  # a copy's rows in the backing array; None: a view
    _struct: str
    _field: str
    _clear: tuple[tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int], ...]

    @classmethod
    def of(cls, physics: Bound, struct: str, name: str, index: npt.NDArray[np.intp] | int,
           clear: tuple[tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int], ...],
           ) -> BoundArray:
        backing = _array(physics, struct, name)
        if isinstance(index, int):
            out = backing[index, ...].view(cls)  # a view, 0-d for a 1-d array
            out._rows = None
        else:
            out = backing[index].view(cls)
            out._rows = index
        out._physics = physics
        out._backing = backing
        out._struct = struct
        out._field = name
        out._clear = clear
        return out

    def __array_finalize__(self, obj: object) -> None:
        # slices and results of numpy operations are plain arrays' data with our class: they
        # carry no backing, and write nowhere else
        if not hasattr(self, "_rows"):
            self._rows = None
            self._clear = ()

    def __array_wrap__(self, array: npt.NDArray[np.generic],  # type: ignore[override]
                       context: object = None, return_scalar: bool = False, /,
                       ) -> npt.NDArray[np.generic] | np.generic:
        # an operation on a single element's value gives a numpy scalar, as on a plain 0-d
        # array (dm_control gives scalars: np.ogrid[-1:1:nrow * 1j] needs one)
        if return_scalar:
            return cast(np.generic, array[()])  # 0-d: indexing by () gives the scalar
        return array.view(type(self))

    def __setitem__(self, index: object, value: object) -> None:
        physics = getattr(self, "_physics", None)
        dirty = physics is not None and triggers_dirty(self._struct, self._field)
        if physics is not None and physics.is_dirty and not dirty:
            physics.forward()
        assign_array(self.view(np.ndarray), index, value)
        if physics is None:
            return
        if self._rows is not None:  # a copy: its rows back into MuJoCo's array
            self._backing[self._rows] = np.asarray(self).reshape(
                self._backing[self._rows].shape)
        for array, where in self._clear:
            array[where] = 0
        if dirty:
            physics.mark_as_dirty()

    # a copy is a plain array, independent of MuJoCo's (dm_control's)
    def copy(self, order: Literal["K", "A", "C", "F"] | None = "C",  # type: ignore[override]
             ) -> npt.NDArray[np.generic]:
        out: npt.NDArray[np.generic] = np.array(self.view(np.ndarray), order=order, copy=True)
        return out

    def __reduce__(self) -> str:
        raise NotImplementedError(PICKLING_NOT_SUPPORTED.format(type=type(self)))


# ---------------------------------------------------------------------------- bindings


class Binding:
    """The arrays of one element, or of a sequence of elements of one kind, in a physics.

    ``physics.bind(joint).qpos``; ``physics.bind(joints).qpos += 0.1``; numpy-style
    ``binding["pos", "z"]`` and ``binding["pos", ["x", "z"]]`` (columns by name where the
    named indexers have them). The properties each kind has are in its class
    (``JointBinding``, ``GeomBinding``, ...).
    """

    __slots__ = ("_ids", "_indices", "_kind", "_label", "_physics", "_single")

    _physics: Bound
    _kind: str
    _ids: npt.NDArray[np.intp]
    _single: bool
    _label: str
    _indices: dict[str, npt.NDArray[np.intp] | int]

    def __new__(cls, physics: Bound, namespace: str, named_index: str | Sequence[str]) -> Self:
        """dm_control's constructor: a binding by scoped names (``physics.bind`` binds
        elements)."""
        kind = binding_tables().kinds.get(namespace)
        if kind is None:
            raise BindingError(f"elements of type {namespace!r} cannot be bound to physics; "
                               f"kinds: {', '.join(sorted(binding_tables().kinds))}")
        import mujoco

        objtype = getattr(mujoco.mjtObj, kind.objtype)
        names = [named_index] if isinstance(named_index, str) else list(named_index)
        ids: list[int] = []
        for name in names:
            _check_name(namespace, name)
            found = mujoco.mj_name2id(physics.model, objtype, name)
            if found < 0:
                raise BindingError(f"no {namespace} named {name!r} in the compiled model")
            ids.append(found)
        binding = new_binding(kind.binding, physics, namespace,
                              np.asarray(ids, dtype=np.intp), isinstance(named_index, str),
                              repr(named_index))
        return cast(Self, binding)

    # ------------------------------------------------------------------ what it binds

    @property
    def element_id(self) -> int | Array[np.intp]:
        """The compiled id of the element (of each element, for several)."""
        if self._single and len(self._ids) == 1:
            return int(self._ids[0])
        out = self._ids.copy()
        out.flags.writeable = False
        return out

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self._label}>"

    def __dir__(self) -> list[str]:
        return sorted({*super().__dir__(), *binding_tables().kinds[self._kind].attributes})

    # ------------------------------------------------------------------ arrays

    def _where(self, name: str) -> tuple[str, str]:
        found = binding_tables().kinds[self._kind].attributes.get(name)
        if found is None:
            known = binding_tables().kinds[self._kind].attributes
            raise AttributeError(
                f"bound element <{self._kind}> does not have attribute {name!r}"
                f"{did_you_mean(name, list(known))}")
        return found

    def _index(self, name: str, struct: str, field_name: str) -> npt.NDArray[np.intp] | int:
        index = self._indices.get(name)
        if index is not None:
            return index
        tables = binding_tables()
        size = tables.fields[(struct, field_name)][0]
        found = rows(self._physics.model, size, self._ids)
        if found is None:
            raise AttributeError(f"{self._label}: {name!r} is only for elements that have "
                                 f"rows of {size} (a body's mocap_pos: mocap bodies)")
        kind = tables.kinds[self._kind]
        ragged = tables.ragged.get(size)
        one_each = size == kind.size or (ragged is not None and (
            ragged.index is not None or ragged.single == "row"))
        single_row = self._single and one_each and len(found) == 1
        index = int(found[0]) if single_row else found
        self._indices[name] = index
        return index

    def _clears(self, name: str, field_name: str) -> tuple[
            tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int], ...]:
        out: list[tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int]] = []
        for other in binding_tables().clear_on_write.get(field_name, ()):
            out.append((_array(self._physics, MODEL, other), self._index(
                f"{name}->{other}", MODEL, other)))
        return tuple(out)

    def _get(self, name: str) -> BoundArray:
        struct, field_name = self._where(name)
        physics = self._physics
        if physics.is_dirty and not triggers_dirty(struct, field_name):
            physics.forward()
        return BoundArray.of(physics, struct, field_name, self._index(name, struct, field_name),
                             self._clears(name, field_name) if struct == MODEL else ())

    def _set(self, name: str, value: object) -> None:
        struct, field_name = self._where(name)
        physics = self._physics
        dirty = triggers_dirty(struct, field_name)
        if physics.is_dirty and not dirty:
            physics.forward()
        index = self._index(name, struct, field_name)
        array = _array(physics, struct, field_name)
        try:
            assign_array(array, (index, ...) if isinstance(index, int) else index, value)
        except (ValueError, TypeError) as error:
            raise InvalidValueError(f"{self._label}: cannot set {name} ({struct}."
                                    f"{field_name}) to {value!r}: {error}") from None
        if struct == MODEL:
            for other, where in self._clears(name, field_name):
                other[where] = 0
        if dirty:
            physics.mark_as_dirty()

    if not TYPE_CHECKING:  # run time only: each kind's class declares its arrays

        def __getattr__(self, name: str) -> BoundArray | np.generic:
            if name.startswith("__"):
                raise AttributeError(name)
            found = self._get(name)
            if found.ndim == 0 and FLAGS.scalar_copies:
                # dm_control gives a single element's value as a numpy scalar, a copy: its
                # code saves values that way before writing (composer's prop placer saves
                # a geom's contype, sets 0, restores it), so a view would restore the 0
                return cast(np.generic, found.view(np.ndarray)[()])
            return found

        def __setattr__(self, name: str, value: object) -> None:
            if name in Binding.__slots__:
                object.__setattr__(self, name, value)
            else:
                self._set(name, value)

    def _expression(self, index: str | tuple[str, object]) -> tuple[str, object]:
        """``"pos"`` or ``("pos", columns)``: the array's name and the index of its rows and
        columns, columns by name where its named indexer has names for them."""
        if isinstance(index, tuple):
            name, columns = index
        else:
            name, columns = index, None
        struct, field_name = self._where(name)
        rows_index = self._index(name, struct, field_name)
        if columns is None:
            return name, rows_index
        column_index = column_key(struct, field_name, columns)
        if isinstance(rows_index, int):
            return name, (rows_index, column_index)
        if isinstance(column_index, np.ndarray | list):
            return name, np.ix_(rows_index, np.asarray(column_index, dtype=np.intp))
        return name, (rows_index, column_index)

    def __getitem__(self, index: str | tuple[str, object]) -> MuJoCoArray:
        name, where = self._expression(index)
        struct, field_name = self._where(name)
        if self._physics.is_dirty and not triggers_dirty(struct, field_name):
            self._physics.forward()
        return cast(MuJoCoArray, index_array(_array(self._physics, struct, field_name), where))

    def __setitem__(self, index: str | tuple[str, object], value: object) -> None:
        name, where = self._expression(index)
        struct, field_name = self._where(name)
        dirty = triggers_dirty(struct, field_name)
        if self._physics.is_dirty and not dirty:
            self._physics.forward()
        assign_array(_array(self._physics, struct, field_name), where, value)
        if struct == MODEL:
            for other, at in self._clears(name, field_name):
                other[at] = 0
        if dirty:
            self._physics.mark_as_dirty()


def _check_name(namespace: str, name: object) -> None:
    if not isinstance(name, str):  # (MuJoCo's mj_name2id crashes on None)
        raise BindingError(f"a {namespace} is bound by its name, got {name!r}")


def new_binding(cls: type[Binding], physics: Bound, kind: str, ids: npt.NDArray[np.intp],
                single: bool, label: str) -> Binding:
    """A binding of the compiled objects ``ids`` of ``kind`` (``single``: of one element)."""
    binding = object.__new__(cls)
    object.__setattr__(binding, "_physics", physics)
    object.__setattr__(binding, "_kind", kind)
    object.__setattr__(binding, "_ids", ids)
    object.__setattr__(binding, "_single", single)
    object.__setattr__(binding, "_label", label)
    object.__setattr__(binding, "_indices", {})
    return binding


class EmptyBinding(Binding):
    """The binding of no elements: every array is empty, and cannot be assigned."""

    __slots__ = ()

    def _get(self, name: str) -> BoundArray:
        return np.zeros(0).view(BoundArray)

    def _set(self, name: str, value: object) -> None:
        raise BindingError("Cannot assign a value to an empty binding.")


def column_key(struct: str, field_name: str, columns: object) -> object:
    """A column index with names (``"z"``, ``["x", "z"]``) made numeric for ``field``."""
    tables = binding_tables()
    names = tables.columns.get(tables.fields.get((struct, field_name), ("", ""))[1])
    if names is None:
        return columns

    def one(item: object) -> object:
        if isinstance(item, str):
            if item not in names:
                raise KeyError(f"{field_name} has no column {item!r}; columns: "
                               f"{', '.join(names)}")
            return names.index(item)
        return item

    if isinstance(columns, list | tuple | np.ndarray):
        return [one(item) for item in cast("Sequence[object]", columns)]
    return one(columns)



def binding_parts(binding: Binding, name: str) -> tuple[Bound, str, str,
                                                        npt.NDArray[np.intp] | int, str]:
    """For a back end of its own (MuJoCo Warp's batched worlds): ``binding``'s physics, the
    struct and field ``name`` binds, its rows there, and the binding's label."""
    # the slots are read by name, as new_binding writes them
    where = cast("Callable[[str], tuple[str, str]]", object.__getattribute__(binding, "_where"))
    index = cast("Callable[[str, str, str], npt.NDArray[np.intp] | int]",
                 object.__getattribute__(binding, "_index"))
    struct, field_name = where(name)
    return (cast(Bound, object.__getattribute__(binding, "_physics")), struct, field_name,
            index(name, struct, field_name), cast(str, object.__getattribute__(binding, "_label")))
