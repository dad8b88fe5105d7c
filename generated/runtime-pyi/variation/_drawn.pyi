# Generated from src/typed_mjcf/variation/_drawn.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
    attribute: str
    values: Values

class Draws(Sequence[Drawn]):
    """The result of :meth:`Variation.draw`: one :class:`Drawn` per varied attribute, in
    the order they were stated, for the worlds ``worlds`` of seed ``seed``."""
    seed: int
    worlds: range
    def __init__(self, seed: int, worlds: range, drawn: Sequence[Drawn]) -> None: ...
    @overload
    def __getitem__(self, index: int) -> Drawn: ...
    @overload
    def __getitem__(self, index: slice) -> Sequence[Drawn]: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[Drawn]: ...
    def world(self, world: int) -> list[tuple[Element, str, object]]:
        """World ``world``'s values: ``(element, attribute, value)`` for each attribute."""
        ...
    def __repr__(self) -> str: ...
