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

from collections.abc import Sequence

import mujoco
import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import InvalidValueError
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._sim.bridge import compile_model
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
    triples = list(draw)
    root = _root_of([element for element, _, _ in triples])
    fresh = compile_model(root)
    if model is not None:
        base = model.model if isinstance(model, Physics) else model
        stale = changed_rows(fresh, base)
        if stale:
            raise InvalidValueError(
                f"the compiled model is not the draw's model as it is now (arrays that "
                f"differ: {', '.join(sorted(stale)[:5])}); compile it again (Physics."
                f"reload_from_mjcf_model) before writing values into it")
    columns, nworld = routes_for(root, fresh, triples, _route_cache(root, fresh))
    return root, fresh, columns, nworld


# the routes learnt for the last model, while it compiles to the same arrays: a new draw for
# the same model (an episode of training) costs one compile, not one per attribute
_ROUTES: list[tuple[ModelBase, mujoco.MjModel, dict[tuple[int, str, int], Route]]] = []


def _route_cache(root: ModelBase, fresh: mujoco.MjModel) -> dict[tuple[int, str, int], Route]:
    if _ROUTES:
        cached_root, cached_model, routes = _ROUTES[0]
        if cached_root is root and not changed_rows(cached_model, fresh) and not (
                changed_stats(cached_model, fresh)):
            return routes
    learnt: dict[tuple[int, str, int], Route] = {}
    _ROUTES[:] = [(root, fresh, learnt)]
    return learnt


def parametric_models(draw: Draw, model: mujoco.MjModel | Physics | None = None,
                      ) -> list[mujoco.MjModel]:
    """One ``MjModel`` per world: copies of ``model`` (of the draw's model compiled, if
    ``None``) with each world's values written in (no compile per world)."""
    _, fresh, columns, nworld = plan(draw, model)
    base = fresh if model is None else (model.model if isinstance(model, Physics) else model)
    return world_models(base, columns, nworld)


def parametric_physics(physics: Physics, draw: Draw) -> list[Physics]:
    """One :class:`Physics` per world: copies of ``physics`` (state included) with each
    world's values written into its model; every element ``physics`` binds, each binds."""
    _, _, columns, nworld = plan(draw, physics)
    routes = [route for route, _ in columns]
    out: list[Physics] = []
    for world in range(nworld):
        copy = physics.copy()
        for route, values in columns:
            write(copy.model, route, values[world])
        finish(copy.model, routes)
        copy.forward()
        out.append(copy)
    return out


def _root_of(elements: Sequence[Element]) -> ModelBase:
    roots = {id(root): root for root in (
        _tree.scope_model(_tree.scope_of(element).outermost()) for element in elements)}
    if not roots:
        raise InvalidValueError("the draw is empty: nothing says which model or how many "
                                "worlds")
    if len(roots) > 1:
        raise InvalidValueError(f"the draw's elements belong to {len(roots)} models; one "
                                f"draw writes into one model")
    return next(iter(roots.values()))
