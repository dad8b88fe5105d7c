# Generated from src/typed_mjcf/variation/_apply.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The slow but general parametric route: a world's drawn values assigned to a copy of the
model, which is then compiled (each value checked again by assignment, and the model by
``validate()`` and MuJoCo's compiler, whose errors name the element and the world)."""
from __future__ import annotations
from typing import TYPE_CHECKING, TypeVar
from typed_mjcf._base import ModelRoot
from typed_mjcf.variation._drawn import Draws
import mujoco
M = TypeVar("M", bound=ModelRoot)

def world_model(model: M, draws: Draws, world: int) -> M:
    """A copy of ``model`` with world ``world``'s drawn values assigned (``model`` is left
    as it was). The draws' elements must be ``model``'s, or in models attached to it."""
    ...

def compile_worlds(model: ModelRoot, draws: Draws) -> list[mujoco.MjModel]:
    """One compiled model per drawn world, each from a copy of ``model`` with that world's
    values (:func:`world_model`); an error notes the world it is about."""
    ...
