# Generated from src/typed_mjcf/parametric.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Many worlds of one compiled model: per-world values written into copies of it.

A *draw* is an iterable of ``(element, attribute, values)`` triples, ``values`` holding one
row per world (``(geom, "friction", array of shape (n, 3))``, ``(inertial, "mass", (n,))``).
Each attribute's compiled field is learnt from MuJoCo (the model compiled once more with the
attribute changed, see :mod:`typed_mjcf._sim.parametric`); an attribute the compiler derives more
from than ``mj_setConst`` derives again is refused with
:class:`~typed_mjcf.errors.NotParametricError` (compile one model per world instead)::

    physics = mjcf.Physics.from_mjcf_model(model)
    worlds = parametric_physics(physics, [(ball, "friction", frictions), (ball, "size", radii)])
    worlds[2].bind(ball).friction   # world 2's friction
"""
from __future__ import annotations
import mujoco
import numpy as np
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._sim.parametric import (
    Draw,
    Route,
    changed_rows,
    changed_stats,
    finish,
    routes_for,
    world_models,
    write,
)
from typed_mjcf.physics import Physics
from typed_mjcf.types import Array
__all__ = ["Draw", "parametric_models", "parametric_physics", "plan"]

def plan(draw: Draw, model: mujoco.MjModel | Physics | None = None,
         ) -> tuple[ModelBase, mujoco.MjModel, list[tuple[Route, Array[np.float64]]],
                    int]:
    """The draw checked and routed: its model, the compiled model the values go into (a
    fresh compile when ``model`` is ``None``), each triple's route and values, and the
    number of worlds."""
    ...

def parametric_models(draw: Draw, model: mujoco.MjModel | Physics | None = None,
                      ) -> list[mujoco.MjModel]:
    """One ``MjModel`` per world: copies of ``model`` (of the draw's model compiled, if
    ``None``) with each world's values written in (no compile per world)."""
    ...

def parametric_physics(physics: Physics, draw: Draw) -> list[Physics]:
    """One :class:`Physics` per world: copies of ``physics`` (state included) with each
    world's values written into its model; every element ``physics`` binds, each binds."""
    ...
