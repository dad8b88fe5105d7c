"""Per-world values written into a compiled model, without compiling again.

Which compiled field holds an attribute is learnt from MuJoCo, not from a list: the model is
compiled once more with the attribute changed (:func:`find_route`), and every ``MjModel``
array compared. The attribute is *parametric* when one field's rows took the value written
and everything else that changed is what ``mj_setConst`` derives again from that field (a
sphere's size gives its ``rbound`` and ``aabb``, a mass the subtree masses and
``invweight0``), checked by doing exactly that on a copy and comparing again. Otherwise the
attribute is refused (:class:`~typed_mjcf._core.errors.NotParametricError`): the model must be
compiled per world.

Of the compiler's statistics (``MjModel.stat``), ``mj_setConst`` recomputes none:
``meanmass`` and ``meaninertia`` (the solver's tolerance is scaled by the latter) are
computed here as MuJoCo's compiler computes them (``user_model.cc``: the mean of the
moving bodies' masses; the mean diagonal of the inertia matrix at ``qpos0``); ``meansize``,
``extent`` and ``center`` only scale what a viewer draws, and keep the compiled model's.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Final, TypeAlias, cast

import numpy as np
import numpy.typing as npt

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import InvalidValueError, MjcfError, NotParametricError
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.validate import keeps
from typed_mjcf._sim.bridge import compile_model
from typed_mjcf.types import Array, MuJoCoArray

if TYPE_CHECKING:
    import mujoco

# A draw: (element, attribute's Python name, values with one row per world)
Draw: TypeAlias = Iterable[tuple[Element, str, MuJoCoArray]]

# the statistics the compiler derives that are computed again here (the others: drawing)
RECOMPUTED_STATS: Final = ("meanmass", "meaninertia")
VISUAL_STATS: Final = ("meansize", "extent", "center")


@dataclass(frozen=True, slots=True)
class Route:
    """Where an attribute of an element lives in the compiled model: ``field``'s ``rows``,
    of which its value fills the first ``width`` numbers; ``derived``: the fields the
    compiler derives from it (rewritten by ``mj_setConst``), ``stats`` the statistics."""

    element: Element
    attribute: str
    field: str
    rows: tuple[int, ...]
    width: int
    derived: tuple[str, ...]
    stats: tuple[str, ...]


def model_arrays(model: mujoco.MjModel) -> dict[str, npt.NDArray[np.generic]]:
    """Every array of ``model`` by name (copies)."""
    out: dict[str, npt.NDArray[np.generic]] = {}
    for name in _array_names(model):
        out[name] = np.array(getattr(model, name), copy=True)
    return out


_NAMES: list[tuple[str, ...]] = []


def _array_names(model: mujoco.MjModel) -> tuple[str, ...]:
    if not _NAMES:
        _NAMES.append(tuple(name for name in dir(model) if not name.startswith("_")
                            and isinstance(getattr(model, name, None), np.ndarray)))
    return _NAMES[0]


def changed_rows(before: mujoco.MjModel, after: mujoco.MjModel,
                 ) -> dict[str, tuple[int, ...]]:
    """The arrays that differ between two compilations of one model, with the rows that do
    (an array whose shape changed: every row)."""
    out: dict[str, tuple[int, ...]] = {}
    for name in _array_names(before):
        a = np.asarray(getattr(before, name))
        b = np.asarray(getattr(after, name))
        if a.shape != b.shape:
            out[name] = tuple(range(max(len(a), len(b))))
            continue
        if a.size == 0:
            continue
        same = (a == b) | (_isnan(a) & _isnan(b))
        if not bool(same.all()):
            rows = np.nonzero(~same.reshape(len(a), -1).all(axis=1))[0]
            out[name] = tuple(int(r) for r in rows)
    return out


def _isnan(array: npt.NDArray[np.generic]) -> npt.NDArray[np.bool_]:
    if array.dtype.kind != "f":
        return np.zeros(array.shape, dtype=np.bool_)
    out: npt.NDArray[np.bool_] = np.isnan(array)
    return out


def changed_stats(before: mujoco.MjModel, after: mujoco.MjModel) -> tuple[str, ...]:
    return tuple(name for name in (*RECOMPUTED_STATS, *VISUAL_STATS)
                 if not np.array_equal(np.asarray(getattr(before.stat, name)),
                                       np.asarray(getattr(after.stat, name)), equal_nan=True))


# ---------------------------------------------------------------------------- values


def attribute_values(element: Element, attribute: str, values: npt.ArrayLike,
                     ) -> Array[np.float64]:
    """``values`` (one per world) as a 2-D array of numbers, each world's value checked as
    assigning it to the attribute checks it, against the attribute's bounds, and finite;
    the error names the element, the attribute, the value and the world."""
    spec = _tree.attribute_of(element, attribute)  # unknown: the element's own error
    array = np.asarray(values)
    if array.ndim == 0 or len(array) == 0:
        raise InvalidValueError(f"{element.path}: the values of {attribute!r} need one row "
                                f"per world (a leading axis of at least 1), got "
                                f"{_short(array)}")
    rows: list[Array[np.float64]] = []
    for world, value in enumerate(array):
        item: object = value.tolist() if isinstance(value, np.ndarray) else value
        try:
            stored = _tree.convert(element, spec, item)
        except MjcfError as error:
            message = str(error).removeprefix(f"{element.path}: ")
            raise type(error)(f"{element.path}: world {world}: {message}") from None
        try:
            numbers = np.atleast_1d(np.asarray(stored, dtype=np.float64))
        except (TypeError, ValueError):
            raise NotParametricError(
                f"{element.path}: {attribute!r} of <{element.spec.tag}> is not a number "
                f"(world {world}: {_short(item)}); only numbers are written into a compiled "
                f"model: compile one model per world") from None
        if not np.isfinite(numbers).all() or not keeps(numbers, spec.bounds):
            expected = " and ".join(["finite", *(f"{op} {limit:g}" for op, limit in
                                                 spec.bounds)])
            raise InvalidValueError(f"{element.path}: world {world}: invalid {attribute}="
                                    f"{_short(item)} on <{element.spec.tag}>: expected each "
                                    f"number {expected}")
        rows.append(numbers)
    widths = {len(r) for r in rows}
    if len(widths) > 1:
        raise InvalidValueError(f"{element.path}: the worlds' values of {attribute!r} have "
                                f"different lengths ({sorted(widths)}); give each world as "
                                f"many numbers")
    return np.stack(rows)


def _short(value: object, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


# ---------------------------------------------------------------------------- routes


def find_route(root: ModelBase, base: mujoco.MjModel, element: Element, attribute: str,
               example: Array[np.float64]) -> Route:
    """Where ``element``'s ``attribute`` lives in ``base`` (``root`` compiled), learnt by
    compiling ``root`` with the attribute set to a value of ``example``'s length that
    differs in every number from both ``example`` and the current value (restored after)."""
    spec = _tree.attribute_of(element, attribute)
    restore = _tree.snapshot(element)
    probe = _probe_value(example, _tree.read_value(element, spec))
    try:
        element.set_attributes(**{attribute: probe.tolist() if spec.is_array
                                  else float(probe[0])})
        try:
            probed = compile_model(root)
        except MjcfError as error:
            raise NotParametricError(
                f"{element.path}: {attribute!r} of <{element.spec.tag}> could not be probed "
                f"(MuJoCo refused the model with {attribute}={_short(probe.tolist())}: "
                f"{error}); compile one model per world") from None
    finally:
        restore()
    changed = changed_rows(base, probed)
    stats = changed_stats(base, probed)
    width = len(probe)
    candidates = [name for name, rows in changed.items()
                  if _holds(probed, name, rows, probe)]
    refused = ""
    for name in candidates:
        route = Route(element, attribute, name, changed[name], width,
                      tuple(sorted(set(changed) - {name})), stats)
        trial = copy.copy(base)
        write(trial, route, probe)
        finish(trial, (route,))
        left = changed_rows(trial, probed)
        left_stats = [s for s in changed_stats(trial, probed) if s not in VISUAL_STATS]
        if not left and not left_stats and _stats_close(trial, probed):
            return route
        refused = (f"writing MjModel.{name} and mj_setConst leave "
                   f"{', '.join([*left, *('stat.' + s for s in left_stats)])} "
                   f"different from a compile")
    if not candidates:
        refused = ("no compiled field took the value written" if changed else
                   "the compiled model did not change")
    raise NotParametricError(
        f"{element.path}: {attribute!r} of <{element.spec.tag}> cannot be written into the "
        f"compiled model ({refused}; fields the compile changed: "
        f"{', '.join(sorted(changed)) or 'none'}); compile one model per world instead")


def _probe_value(example: Array[np.float64], current: object,
                 ) -> Array[np.float64]:
    """A value like ``example`` with every number different from it and from
    ``current`` (so that every number the compile takes shows in the diff)."""
    now = np.atleast_1d(np.asarray(current, dtype=np.float64)) if current is not None else (
        np.zeros(0))
    probe = np.where(example == 0, 0.0625, example * 1.25)
    for i in range(len(probe)):
        while i < len(now) and probe[i] == now[i] or probe[i] == example[i]:
            probe[i] = probe[i] * 1.25 + 0.03125
    return probe


def _holds(model: mujoco.MjModel, name: str, rows: Sequence[int],
           value: Array[np.float64]) -> bool:
    array = np.asarray(getattr(model, name))
    if array.dtype.kind != "f" or not rows:
        return False
    flat = array.reshape(len(array), -1)
    if flat.shape[1] < len(value):
        return False
    return bool(np.allclose(flat[list(rows), :len(value)], value, rtol=1e-12, atol=0))


def _stats_close(model: mujoco.MjModel, compiled: mujoco.MjModel) -> bool:
    return all(math.isclose(float(getattr(model.stat, name)),
                            float(getattr(compiled.stat, name)), rel_tol=1e-12)
               for name in RECOMPUTED_STATS)


# ---------------------------------------------------------------------------- writing


def write(model: mujoco.MjModel, route: Route, value: Array[np.float64]) -> None:
    """Write one world's ``value`` into ``route``'s rows of ``model`` (no derived field)."""
    array = np.asarray(getattr(model, route.field))
    for row in route.rows:
        if array.ndim == 1:
            array[row] = value[0]
        else:
            array[row].reshape(-1)[:len(value)] = value


def finish(model: mujoco.MjModel, routes: Iterable[Route]) -> None:
    """Derive again what the compiler derives from the fields ``routes`` wrote."""
    import mujoco

    listed = list(routes)
    if not any(route.derived for route in listed):
        return
    data = mujoco.MjData(model)
    mujoco.mj_setConst(model, data)
    stats = {s for route in listed for s in route.stats}
    if "meanmass" in stats and model.nbody > 1:
        model.stat.meanmass = float(np.mean(model.body_mass[1:]))
    if "meaninertia" in stats and model.nv:
        data.qpos[:] = model.qpos0
        mujoco.mj_forward(model, data)
        diagonal = np.asarray(model.M_rowadr) + np.asarray(model.M_rownnz) - 1
        total = 0.0
        for x in np.asarray(data.M)[diagonal].tolist():  # in order, as MuJoCo sums
            total += x
        model.stat.meaninertia = total / model.nv


def world_models(base: mujoco.MjModel, columns: Sequence[tuple[Route, Array[np.float64]]],
                 nworld: int) -> list[mujoco.MjModel]:
    """``nworld`` copies of ``base``, world ``i`` with row ``i`` of each route's values."""
    out: list[mujoco.MjModel] = []
    routes = [route for route, _ in columns]
    for world in range(nworld):
        model = copy.copy(base)
        for route, values in columns:
            write(model, route, values[world])
        finish(model, routes)
        out.append(model)
    return out


def routes_for(root: ModelBase, base: mujoco.MjModel, draw: Draw,
               cache: dict[tuple[int, str, int], Route] | None = None,
               ) -> tuple[list[tuple[Route, Array[np.float64]]], int]:
    """Each triple of ``draw`` checked and routed, and the number of worlds."""
    columns: list[tuple[Route, Array[np.float64]]] = []
    nworld: int | None = None
    cache = {} if cache is None else cache
    for element, attribute, values in draw:
        if not isinstance(cast(object, element), Element):
            raise InvalidValueError(f"a draw names elements, got {element!r} for "
                                    f"{attribute!r}")
        numbers = attribute_values(element, attribute, values)
        if nworld is None:
            nworld = len(numbers)
        elif len(numbers) != nworld:
            raise InvalidValueError(f"{element.path}: {len(numbers)} values of {attribute!r} "
                                    f"for {nworld} worlds (the draw's other values have "
                                    f"{nworld})")
        key = (id(element), attribute, numbers.shape[1])
        route = cache.get(key)
        if route is None or route.element is not element:
            route = cache[key] = find_route(root, base, element, attribute, numbers[0])
        columns.append((route, numbers))
    if nworld is None:
        raise InvalidValueError("the draw is empty: nothing says how many worlds")
    return columns, nworld
