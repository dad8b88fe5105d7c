"""Many worlds on MuJoCo Warp (the optional extra ``warp``: ``pip install typed-mjcf[warp]``).

:func:`put_worlds` makes a batched Warp model and data of ``nworld`` worlds from a typed model
and a draw (per-world values, as :mod:`typed_mjcf.parametric` takes them): the values go
into per-world copies of the compiled model (``mj_setConst`` deriving what depends on them),
and each Warp model field that then differs between worlds is batched
(``mujoco_warp.put_model(..., batch_sizes=...)``). ``worlds.bind(element)`` gives the arrays
``Physics.bind`` gives, by the same names (the same generated table), with a leading axis of
worlds::

    worlds = put_worlds(model, [(ball, "friction", frictions)], device="cpu")
    worlds.step(100)
    worlds.bind(ball).xpos        # shape (nworld, 3)
    worlds.bind(ball).friction    # shape (nworld, 3)

:func:`warp_refusals` (and ``typed-mjcf check --backend warp``) says what of a model the
installed MuJoCo Warp refuses, element by element.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Iterable, Sequence
from types import ModuleType
from typing import TYPE_CHECKING, Protocol, cast

import mujoco
import numpy as np
import numpy.typing as npt

from typed_mjcf._core.errors import BindingError, InvalidValueError, UnbatchedWarning
from typed_mjcf._core.tree import Element
from typed_mjcf._generated.bindings import Bind
from typed_mjcf._sim.binding import Binding, binding_parts, binding_tables, new_binding
from typed_mjcf._sim.ids import kind_of
from typed_mjcf._sim.parametric import Draw, world_models
from typed_mjcf._sim.warp_refusals import Refusal, WarpMissingError, warp_modules, warp_refusals
from typed_mjcf.parametric import plan
from typed_mjcf.physics import Physics
from typed_mjcf.types import MuJoCoArray

if TYPE_CHECKING:
    from typed_mjcf._base import Element as _BaseElement
    from typed_mjcf._base import ModelRoot

__all__ = ["Refusal", "UnbatchedWarning", "WarpMissingError", "Worlds", "put_worlds",
           "warp_modules", "warp_refusals"]

class _WarpArray(Protocol):
    shape: tuple[int, ...]
    device: object
    dtype: object

    def numpy(self) -> MuJoCoArray: ...
    def assign(self, src: MuJoCoArray) -> None: ...


class Worlds(Bind):
    """A batched MuJoCo Warp model and data of ``nworld`` worlds, and the typed model and
    compiled ``MjModel`` they come from; :meth:`bind` as ``Physics.bind``, per world."""

    nworld: int
    warp_model: object  # mujoco_warp.Model
    warp_data: object  # mujoco_warp.Data
    batched: tuple[str, ...]  # the Model fields that hold one row per world
    device: str | None  # Warp's device (None: Warp's default)
    _physics: Physics  # the CPU physics of the base model: compiled ids, row sizes

    def __init__(self, physics: Physics, warp_model: object, warp_data: object, nworld: int,
                 batched: Sequence[str], device: str | None = None) -> None:
        self._physics = physics
        self.device = device
        self.warp_model = warp_model
        self.warp_data = warp_data
        self.nworld = nworld
        self.batched = tuple(batched)

    # what a binding reads of its physics (the CPU model: rows; never stale)
    @property
    def model(self) -> mujoco.MjModel:
        """The compiled model every world was made from (world values not written)."""
        return self._physics.model

    @property
    def data(self) -> mujoco.MjData:
        return self._physics.data

    @property
    def is_dirty(self) -> bool:
        return False

    def mark_as_dirty(self) -> None:
        """Warp's data is derived by ``step``: nothing to mark."""

    def forward(self) -> None:
        """Run ``mujoco_warp.forward`` on every world."""
        wp, mjw = warp_modules()
        with wp.ScopedDevice(self.device):
            mjw.forward(self.warp_model, self.warp_data)

    def step(self, nstep: int = 1) -> None:
        """Step every world ``nstep`` times."""
        wp, mjw = warp_modules()
        with wp.ScopedDevice(self.device):
            for _ in range(nstep):
                mjw.step(self.warp_model, self.warp_data)

    if not TYPE_CHECKING:  # typed per kind of element by Bind (bindings.pyi)

        def bind(self, mjcf_elements):
            """The arrays of an element (or of several of one kind) in every world: the
            names ``Physics.bind`` has, each with a leading axis of ``nworld``."""
            return self._bind(mjcf_elements)

    def _bind(self, mjcf_elements: Element | Iterable[Element]) -> Binding:
        single = isinstance(mjcf_elements, Element)
        elements = [mjcf_elements] if isinstance(mjcf_elements, Element) else list(
            mjcf_elements)
        if not elements:
            raise BindingError("bind takes an element or a non-empty sequence of them")
        kinds = {kind_of(element) for element in elements}
        kind = next(iter(kinds))
        if len(kinds) > 1 or kind is None:
            # the CPU physics says why (an element of no kind, mixed kinds)
            self._physics.bind(cast("Sequence[_BaseElement]", elements))
            raise BindingError(f"cannot bind {elements!r}")
        cpu = self._physics.bind(cast("_BaseElement | Sequence[_BaseElement]",
                                      mjcf_elements if single else elements))
        ids = np.atleast_1d(np.asarray(cpu.element_id, dtype=np.intp))
        label = elements[0].path if single else f"{len(elements)} <{kind}> elements"
        cls = _warp_class(binding_tables().kinds[kind].binding)
        return new_binding(cls, cast("Physics", self), kind, ids, single, label)

    def write(self, draw: Draw) -> None:
        """Write a new draw's values into these worlds (an episode's randomisation), without
        putting the model again: every field the new values change must be one these worlds
        batch (:attr:`batched`; else put_worlds again with such a draw)."""
        _, mjw = warp_modules()
        _, _, columns, count = plan(draw, self._physics)
        if count != self.nworld:
            raise InvalidValueError(f"the draw has values for {count} worlds; these are "
                                    f"{self.nworld}")
        base = self._physics.model
        models = world_models(base, columns, count)
        changed = _differing(base, models, _batchable(mjw))
        unbatched = sorted(set(changed) - set(self.batched))
        if unbatched:
            raise InvalidValueError(f"the draw changes MjModel.{', '.join(unbatched)}, which "
                                    f"these worlds hold once for all: put_worlds with a draw "
                                    f"that varies them")
        for name in self.batched:
            _fill(self.warp_model, name, models if models else [base] * count, base)

    def arrays(self, struct: str, field: str) -> tuple[_WarpArray, tuple[int, ...]]:
        """The Warp array of ``struct.field`` and its CPU array's shape."""
        holder = self.warp_model if struct == "MjModel" else self.warp_data
        array = getattr(holder, field, None)
        if array is None:
            raise AttributeError(f"MuJoCo Warp's {'Model' if struct == 'MjModel' else 'Data'}"
                                 f" has no {field!r}")
        cpu = getattr(self.model if struct == "MjModel" else self.data, field)
        return cast(_WarpArray, array), tuple(np.shape(cpu))


_CLASSES: dict[type[Binding], type[Binding]] = {}


def _warp_class(cls: type[Binding]) -> type[Binding]:
    """``cls`` (``GeomBinding``, ...) reading and writing a :class:`Worlds`' arrays."""
    found = _CLASSES.get(cls)
    if found is None:
        found = _CLASSES[cls] = type(f"Warp{cls.__name__}", (cls,), {
            "__slots__": (), "_get": _get, "_set": _set, "__doc__": cls.__doc__})
    return found


def _rows(binding: Binding, name: str) -> tuple[Worlds, str, str, npt.NDArray[np.intp] | int,
                                                 _WarpArray, tuple[int, ...], str]:
    physics, struct, field, index, label = binding_parts(binding, name)
    worlds = cast(Worlds, physics)
    array, cpu_shape = worlds.arrays(struct, field)
    return worlds, struct, field, index, array, cpu_shape, label


def _get(self: Binding, name: str) -> npt.NDArray[np.generic]:
    worlds, _, _, index, array, cpu_shape, _ = _rows(self, name)
    stored: npt.NDArray[np.generic] = array.numpy()
    host = stored.reshape((stored.shape[0], *cpu_shape))  # Warp's vectors: MuJoCo's columns
    out = host[:, index]
    if host.shape[0] != worlds.nworld:  # one row shared by every world
        out = np.broadcast_to(out, (worlds.nworld, *out.shape[1:]))
    return out


def _set(self: Binding, name: str, value: object) -> None:
    worlds, struct, field, index, array, cpu_shape, label = _rows(self, name)
    host = array.numpy()
    shaped = host.reshape((host.shape[0], *cpu_shape))
    if shaped.shape[0] != worlds.nworld and np.ndim(cast("npt.ArrayLike", value)) > (
            shaped[:, index].ndim - 1):
        raise BindingError(f"{label}: {struct}.{field} is one array for every world "
                           f"(not batched): pass {name!r} in put_worlds' draw to give each "
                           f"world its own")
    try:
        shaped[:, index] = cast("npt.ArrayLike", value)
    except (ValueError, TypeError) as error:
        raise InvalidValueError(f"{label}: cannot set {name} ({struct}.{field}) to "
                                f"{value!r}: {error}") from None
    if str(array.device) != "cpu":  # a copy of device memory: back to the device
        array.assign(host)


# ---------------------------------------------------------------------------- making


def put_worlds(model: ModelRoot | Physics, draw: Draw = (), *, nworld: int | None = None,
               device: str | None = None) -> Worlds:
    """A batched MuJoCo Warp model and data of ``nworld`` worlds of ``model`` (a typed model,
    or a ``Physics`` compiled from one), each world with its values of ``draw`` (which sets
    ``nworld`` when given); ``device``: Warp's (``"cpu"``, ``"cuda:0"``; Warp's default if
    ``None``)."""
    wp, mjw = warp_modules()
    physics = model if isinstance(model, Physics) else Physics.from_mjcf_model(model)
    triples = list(draw)
    if triples:
        _, _, columns, count = plan(triples, physics)
        if nworld is not None and nworld != count:
            raise InvalidValueError(f"nworld={nworld}, but the draw has values for {count} "
                                    f"worlds")
        models = world_models(physics.model, columns, count)
        nworld = count
    else:
        models = []
        nworld = 1 if nworld is None else nworld
    if nworld < 1:
        raise InvalidValueError(f"nworld must be at least 1, got {nworld}")
    base = physics.model
    spec = _batchable(mjw)
    batched = _differing(base, models, spec)
    with wp.ScopedDevice(device):
        warp_model = mjw.put_model(base, batch_sizes={name: nworld for name in batched})
        for name in batched:
            _fill(warp_model, name, models, base, fresh=True)
        warp_data = mjw.put_data(base, mujoco.MjData(base), nworld=nworld)
    return Worlds(physics, warp_model, warp_data, nworld, batched, device)


def _batchable(mjw: ModuleType) -> dict[str, bool]:
    """Each array field of MuJoCo Warp's ``Model``: whether it can hold one row per world
    (its declared shape starts with ``"*"``)."""
    out: dict[str, bool] = {}
    fields = cast("dict[str, dataclasses.Field[object]]", mjw.Model.__dataclass_fields__)
    for item in fields.values():
        shape: object = getattr(item.type, "shape", None)
        if isinstance(shape, tuple) and shape:
            out[item.name] = shape[0] == "*"
    return out


def _differing(base: mujoco.MjModel, models: Sequence[mujoco.MjModel],
               spec: dict[str, bool]) -> list[str]:
    """The Warp Model fields whose values differ between the worlds' models; an error if
    MuJoCo Warp cannot batch one."""
    out: list[str] = []
    shared: list[str] = []
    for name, batchable in sorted(spec.items()):
        reference: object = getattr(base, name, None)
        if not isinstance(reference, np.ndarray) or not models:
            continue
        if all(np.array_equal(getattr(m, name), cast("npt.NDArray[np.generic]", reference))
               for m in models):
            continue
        if batchable:
            out.append(name)
        else:
            shared.append(name)
    if shared:
        # as MuJoCo Warp's own set_const does (it skips them: "unbatched in mjwarp")
        warnings.warn(f"the worlds differ in MjModel.{', '.join(shared)}, which the installed "
                      f"MuJoCo Warp holds once for every world (not batched): every world "
                      f"keeps the compiled model's", UnbatchedWarning, stacklevel=3)
    return out


def _fill(warp_model: object, name: str, models: Sequence[mujoco.MjModel],
          base: mujoco.MjModel, fresh: bool = False) -> None:
    """Write each world's ``name`` into the batched Warp array (``fresh``: as put_model
    made it, every world ``base``'s: checking first that Warp holds MuJoCo's numbers as
    they are)."""
    array = cast(_WarpArray, getattr(warp_model, name))
    host = array.numpy()
    if fresh and not np.array_equal(host[0].reshape(-1), np.asarray(getattr(base, name)).reshape(-1)
                          .astype(host.dtype)):
        raise InvalidValueError(f"MuJoCo Warp holds MjModel.{name} otherwise than MuJoCo "
                                f"does: its per-world values cannot be written")
    stacked = np.stack([np.asarray(getattr(m, name)) for m in models]).astype(host.dtype)
    host[...] = stacked.reshape(host.shape)
    if str(array.device) != "cpu":
        array.assign(host)
