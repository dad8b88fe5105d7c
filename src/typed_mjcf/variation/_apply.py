"""The slow but general parametric route: a world's drawn values assigned to a copy of the
model, which is then compiled (each value checked again by assignment, and the model by
``validate()`` and MuJoCo's compiler, whose errors name the element and the world)."""

from __future__ import annotations

import copy
from typing import TYPE_CHECKING, TypeVar

from typed_mjcf._base import ModelRoot
from typed_mjcf._core.errors import CompileError, InvalidValueError, MjcfError
from typed_mjcf._core.tree import Element
from typed_mjcf.variation._drawn import Draws

if TYPE_CHECKING:
    import mujoco

M = TypeVar("M", bound=ModelRoot)


def world_model(model: M, draws: Draws, world: int) -> M:
    """A copy of ``model`` with world ``world``'s drawn values assigned (``model`` is left
    as it was). The draws' elements must be ``model``'s, or in models attached to it."""
    values = draws.world(world)
    memo: dict[int, object] = {}
    clone = copy.deepcopy(model, memo)
    for element, attribute, value in values:
        target = memo.get(id(element))
        if not isinstance(target, Element) or target is element:
            raise InvalidValueError(
                f"{element.path}: the draws vary an element that is not in the model "
                f"{model!r} (or a model attached to it)")
        if isinstance(value, Element):  # a drawn reference to the model's element: its copy
            value = memo.get(id(value), value)
        try:
            setattr(target, attribute, value)
        except MjcfError as error:
            error.add_note(f"drawn for world {world} (seed {draws.seed})")
            raise
    return clone


def compile_worlds(model: ModelRoot, draws: Draws) -> list[mujoco.MjModel]:
    """One compiled model per drawn world, each from a copy of ``model`` with that world's
    values (:func:`world_model`); an error notes the world it is about."""
    compiled: list[mujoco.MjModel] = []
    for world in draws.worlds:
        variant = world_model(model, draws, world)
        try:
            compiled.append(variant.compile())
        except CompileError as error:  # MuJoCo's message, with the element's path
            raise CompileError(f"{error}; drawn for world {world} (seed {draws.seed})",
                               error.path) from error
        except MjcfError as error:  # ValidationError: its findings name the elements
            error.add_note(f"drawn for world {world} (seed {draws.seed})")
            raise
    return compiled
