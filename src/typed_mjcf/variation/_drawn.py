"""What a draw gives: per attribute, the values of every world (the contract with the
routes that write them into compiled models)."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import NamedTuple, cast, overload

import numpy as np

from typed_mjcf._core.tree import Element

Values = np.ndarray[tuple[int, ...], np.dtype[np.generic]]


class Drawn(NamedTuple):
    """The values drawn for one attribute of one element: ``values[k]`` is world
    ``worlds[k]``'s (leading axis: the worlds; then the attribute's numbers, if several)."""

    element: Element
    attribute: str  # the Python name (``friction``, ``class_``)
    values: Values


class Draws(Sequence[Drawn]):
    """The result of :meth:`Variation.draw`: one :class:`Drawn` per varied attribute, in
    the order they were stated, for the worlds ``worlds`` of seed ``seed``."""

    __slots__ = ("_drawn", "seed", "worlds")

    seed: int
    worlds: range

    def __init__(self, seed: int, worlds: range, drawn: Sequence[Drawn]) -> None:
        self.seed = seed
        self.worlds = worlds
        self._drawn = tuple(drawn)

    @overload
    def __getitem__(self, index: int) -> Drawn: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[Drawn]: ...
    def __getitem__(self, index: int | slice) -> Drawn | Sequence[Drawn]:
        return self._drawn[index]

    def __len__(self) -> int:
        return len(self._drawn)

    def __iter__(self) -> Iterator[Drawn]:
        return iter(self._drawn)

    def world(self, world: int) -> list[tuple[Element, str, object]]:
        """World ``world``'s values: ``(element, attribute, value)`` for each attribute."""
        if world not in self.worlds:
            raise IndexError(f"world {world} was not drawn: these draws hold worlds "
                             f"{self.worlds.start} to {self.worlds.stop - 1} of seed {self.seed}")
        k = world - self.worlds.start
        return [(d.element, d.attribute, _plain(d.values[k])) for d in self._drawn]

    def __repr__(self) -> str:
        return (f"<Draws of {len(self._drawn)} attributes for worlds {self.worlds.start}.."
                f"{self.worlds.stop - 1} of seed {self.seed}>")


def _plain(value: object) -> object:
    """A numpy scalar as the Python value it holds; arrays and other values as they are."""
    if isinstance(value, np.generic):
        scalar = cast("np.generic[object]", value)
        return scalar.item()
    return value
