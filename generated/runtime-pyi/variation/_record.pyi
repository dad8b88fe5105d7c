# Generated from src/typed_mjcf/variation/_record.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Distributions stated on attributes through a recording proxy, and drawn per world.

``v.of(geom)`` is typed as the geom itself, so ``v.of(geom).friction = uniform(...)`` is
checked by the geom's own setter types; at run time the proxy records the distribution
instead of assigning it. World ``i``'s values depend only on ``(seed, i)``: each world has
its own generator (:func:`world_rng`), so how many worlds are drawn, or where, changes
nothing.
"""
from __future__ import annotations
from collections.abc import Iterator
from typing import TypeVar, cast
import numpy as np
from typed_mjcf._core.tree import Element
from typed_mjcf.variation._distributions import Choice, Distribution, as_distribution
from typed_mjcf.variation._drawn import Drawn, Draws, Values
E = TypeVar("E", bound=Element)
PARAMETRIC = 0
STRUCTURAL = 1

def world_rng(seed: int, world: int, stream: int = PARAMETRIC) -> np.random.Generator:
    """World ``world``'s generator for ``seed``: the same wherever and with whatever else
    it is made (a ``SeedSequence`` child keyed, as ``spawn`` keys them, by the world's index
    and the stream)."""
    ...

def check_worlds(seed: object, n: object, first: object) -> None:
    """Refuse a seed, count or first world that is no non-negative int."""
    ...

class Variation:
    """Distributions on attributes of elements, drawn per world.

        v = Variation()
        v.of(geom).friction = uniform((0.5, 0.005, 1e-4), (1.5, 0.01, 1e-3))
        draws = v.draw(seed=0, n=1000)   # one Drawn(element, attribute, values) per attribute
    """
    def __init__(self) -> None: ...
    def of(self, element: E) -> E:
        """A stand-in for ``element`` (typed as it) whose attribute assignments record
        distributions: ``v.of(geom).mass = uniform(0.5, 2.0)``."""
        ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[tuple[Element, str, Distribution]]:
        """``(element, attribute, distribution)`` for each varied attribute, in order."""
        ...
    def __repr__(self) -> str: ...
    def record(self, element: Element, name: str, value: object) -> None:
        """State ``value`` (a distribution) for attribute ``name`` of ``element`` (what an
        assignment through :meth:`of` does); a second one for it replaces the first."""
        ...
    def draw(self, seed: int, n: int, *, first: int = 0) -> Draws:
        """The values of worlds ``first`` to ``first + n - 1``, each from its own generator
        (``world_rng(seed, i)``, drawn from in the order the distributions were stated), checked as assignment checks them (the attribute's codec)
        and against the attribute's bounds (schema/facts.toml): a value out of them is an
        error naming the element, attribute, value and world, never clipped."""
        ...
