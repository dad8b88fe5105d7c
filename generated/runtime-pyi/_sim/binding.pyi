# Generated from src/typed_mjcf/_sim/binding.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
from typed_mjcf.types import Array, MuJoCoArray
import mujoco
PICKLING_NOT_SUPPORTED: Final = "Objects of type {type} cannot be pickled."
MODEL: Final = "MjModel"
DATA: Final = "MjData"
_Item: TypeAlias = int | slice | EllipsisType | npt.NDArray[np.intp]
ArrayIndex: TypeAlias = _Item | tuple[_Item, ...]

def index_array(array: npt.NDArray[np.generic], index: object) -> npt.NDArray[np.generic]:
    """``array[index]`` (a view or a copy, as numpy gives it)."""
    ...

def assign_array(array: npt.NDArray[np.generic], index: object, value: object) -> None:
    """``array[index] = value``."""
    ...

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
    fields: Mapping[tuple[str, str], tuple[str, str]]
    data_inputs: frozenset[str]
    model_cosmetic: frozenset[str]
    clear_on_write: Mapping[str, tuple[str, ...]]
    objects: Mapping[str, str] = field(default_factory=lambda: {})
    sizes: frozenset[str] = field(default=frozenset())

def finish_bindings(tables: BindingTables) -> None:
    """Called once by the generated ``bindings.py``."""
    ...

def binding_tables() -> BindingTables: ...

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

def triggers_dirty(struct: str, name: str) -> bool:
    """Whether writing ``struct.name`` makes MjData's derived quantities stale."""
    ...

def rows(model: mujoco.MjModel, size: str, ids: npt.NDArray[np.intp]) -> (
        npt.NDArray[np.intp] | None):
    """The rows of the arrays sized ``size`` that the objects ``ids`` own, in order; ``None``
    for an object that owns none where it must own one (a body that is not a mocap body)."""
    ...

class BoundArray(np.ndarray[tuple[int, ...], np.dtype[np.generic]]):
    """An array of a binding: writing into it writes into MuJoCo's array (a copy writes its
    rows back), clears the flags the write invalidates, and marks the physics stale."""
    _physics: Bound
    _backing: npt.NDArray[np.generic]
    _rows: npt.NDArray[np.intp] | None
    _struct: str
    _field: str
    _clear: tuple[tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int], ...]
    @classmethod
    def of(cls, physics: Bound, struct: str, name: str, index: npt.NDArray[np.intp] | int,
           clear: tuple[tuple[npt.NDArray[np.generic], npt.NDArray[np.intp] | int], ...],
           ) -> BoundArray: ...
    def __array_finalize__(self, obj: object) -> None: ...
    def __array_wrap__(self, array: npt.NDArray[np.generic],  # type: ignore[override]
                       context: object = None, return_scalar: bool = False, /,
                       ) -> npt.NDArray[np.generic] | np.generic: ...
    def __setitem__(self, index: object, value: object) -> None: ...
    def copy(self, order: Literal["K", "A", "C", "F"] | None = "C",  # type: ignore[override]
             ) -> npt.NDArray[np.generic]: ...
    def __reduce__(self) -> str: ...

class Binding:
    """The arrays of one element, or of a sequence of elements of one kind, in a physics.

    ``physics.bind(joint).qpos``; ``physics.bind(joints).qpos += 0.1``; numpy-style
    ``binding["pos", "z"]`` and ``binding["pos", ["x", "z"]]`` (columns by name where the
    named indexers have them). The properties each kind has are in its class
    (``JointBinding``, ``GeomBinding``, ...).
    """
    _physics: Bound
    _kind: str
    _ids: npt.NDArray[np.intp]
    _single: bool
    _label: str
    _indices: dict[str, npt.NDArray[np.intp] | int]
    def __new__(cls, physics: Bound, namespace: str, named_index: str | Sequence[str]) -> Self:
        """dm_control's constructor: a binding by scoped names (``physics.bind`` binds
        elements)."""
        ...
    @property
    def element_id(self) -> int | Array[np.intp]:
        """The compiled id of the element (of each element, for several)."""
        ...
    def __repr__(self) -> str: ...
    def __dir__(self) -> list[str]: ...
    def __getitem__(self, index: str | tuple[str, object]) -> MuJoCoArray: ...
    def __setitem__(self, index: str | tuple[str, object], value: object) -> None: ...

def new_binding(cls: type[Binding], physics: Bound, kind: str, ids: npt.NDArray[np.intp],
                single: bool, label: str) -> Binding:
    """A binding of the compiled objects ``ids`` of ``kind`` (``single``: of one element)."""
    ...

class EmptyBinding(Binding):
    """The binding of no elements: every array is empty, and cannot be assigned."""

def column_key(struct: str, field_name: str, columns: object) -> object:
    """A column index with names (``"z"``, ``["x", "z"]``) made numeric for ``field``."""
    ...

def binding_parts(binding: Binding, name: str) -> tuple[Bound, str, str,
                                                        npt.NDArray[np.intp] | int, str]:
    """For a back end of its own (MuJoCo Warp's batched worlds): ``binding``'s physics, the
    struct and field ``name`` binds, its rows there, and the binding's label."""
    ...
