# Generated from src/typed_mjcf/_sim/parametric.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Final, TypeAlias, cast
import numpy as np
import numpy.typing as npt
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf.types import Array, MuJoCoArray
import mujoco
Draw: TypeAlias = Iterable[tuple[Element, str, MuJoCoArray]]
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
    ...

def changed_rows(before: mujoco.MjModel, after: mujoco.MjModel,
                 ) -> dict[str, tuple[int, ...]]:
    """The arrays that differ between two compilations of one model, with the rows that do
    (an array whose shape changed: every row)."""
    ...

def changed_stats(before: mujoco.MjModel, after: mujoco.MjModel) -> tuple[str, ...]: ...

def attribute_values(element: Element, attribute: str, values: npt.ArrayLike,
                     ) -> Array[np.float64]:
    """``values`` (one per world) as a 2-D array of numbers, each world's value checked as
    assigning it to the attribute checks it, against the attribute's bounds, and finite;
    the error names the element, the attribute, the value and the world."""
    ...

def find_route(root: ModelBase, base: mujoco.MjModel, element: Element, attribute: str,
               example: Array[np.float64]) -> Route:
    """Where ``element``'s ``attribute`` lives in ``base`` (``root`` compiled), learnt by
    compiling ``root`` with the attribute set to a value of ``example``'s length that
    differs in every number from both ``example`` and the current value (restored after)."""
    ...

def write(model: mujoco.MjModel, route: Route, value: Array[np.float64]) -> None:
    """Write one world's ``value`` into ``route``'s rows of ``model`` (no derived field)."""
    ...

def finish(model: mujoco.MjModel, routes: Iterable[Route]) -> None:
    """Derive again what the compiler derives from the fields ``routes`` wrote."""
    ...

def world_models(base: mujoco.MjModel, columns: Sequence[tuple[Route, Array[np.float64]]],
                 nworld: int) -> list[mujoco.MjModel]:
    """``nworld`` copies of ``base``, world ``i`` with row ``i`` of each route's values."""
    ...

def routes_for(root: ModelBase, base: mujoco.MjModel, draw: Draw,
               cache: dict[tuple[int, str, int], Route] | None = None,
               ) -> tuple[list[tuple[Route, Array[np.float64]]], int]:
    """Each triple of ``draw`` checked and routed, and the number of worlds."""
    ...
