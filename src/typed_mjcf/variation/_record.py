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

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import Rejected
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element
from typed_mjcf._model.validate import expected_bounds, keeps
from typed_mjcf.variation._distributions import Choice, Distribution, as_distribution
from typed_mjcf.variation._drawn import Drawn, Draws, Values

E = TypeVar("E", bound=Element)

# Spawn keys of a world's generators: parametric draws and structural builds of one seed
# draw from unrelated streams.
PARAMETRIC = 0
STRUCTURAL = 1


def world_rng(seed: int, world: int, stream: int = PARAMETRIC) -> np.random.Generator:
    """World ``world``'s generator for ``seed``: the same wherever and with whatever else
    it is made (a ``SeedSequence`` child keyed, as ``spawn`` keys them, by the world's index
    and the stream)."""
    check_worlds(seed, 1, world)
    return np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(world, stream)))


def check_worlds(seed: object, n: object, first: object) -> None:
    """Refuse a seed, count or first world that is no non-negative int."""
    for name, value in (("seed", seed), ("n", n), ("first", first)):
        if not isinstance(value, int | np.integer) or isinstance(value, bool) or value < 0:
            raise InvalidValueError(f"{name} must be a non-negative int, got {value!r}")


class _Entry:
    __slots__ = ("attribute", "distribution", "element")

    def __init__(self, element: Element, attribute: AttributeSpec,
                 distribution: Distribution) -> None:
        self.element = element
        self.attribute = attribute
        self.distribution = distribution


class Variation:
    """Distributions on attributes of elements, drawn per world.

        v = Variation()
        v.of(geom).friction = uniform((0.5, 0.005, 1e-4), (1.5, 0.01, 1e-3))
        draws = v.draw(seed=0, n=1000)   # one Drawn(element, attribute, values) per attribute
    """

    __slots__ = ("_entries",)

    def __init__(self) -> None:
        self._entries: list[_Entry] = []

    def of(self, element: E) -> E:
        """A stand-in for ``element`` (typed as it) whose attribute assignments record
        distributions: ``v.of(geom).mass = uniform(0.5, 2.0)``."""
        if not isinstance(cast(object, element), Element):
            raise InvalidTypeError(f"Variation.of() takes an element, got {element!r}")
        return cast(E, _Recorder(self, element))

    def __len__(self) -> int:
        return len(self._entries)

    def __iter__(self) -> Iterator[tuple[Element, str, Distribution]]:
        """``(element, attribute, distribution)`` for each varied attribute, in order."""
        return iter([(e.element, e.attribute.py_name, e.distribution) for e in self._entries])

    def __repr__(self) -> str:
        listed = ", ".join(f"{e.element.path}.{e.attribute.py_name}={e.distribution!r}"
                           for e in self._entries)
        return f"Variation({listed})"

    def record(self, element: Element, name: str, value: object) -> None:
        """State ``value`` (a distribution) for attribute ``name`` of ``element`` (what an
        assignment through :meth:`of` does); a second one for it replaces the first."""
        attribute = element.spec.by_key.get(name)
        if attribute is None:
            raise _tree.unknown_attribute(element, name)
        distribution = as_distribution(value)
        if distribution is None:
            raise InvalidTypeError(
                f"{element.path}: Variation.of(...).{attribute.py_name}={_tree.short_repr(value)} "
                f"on <{element.spec.tag}>: expected a distribution (uniform(), normal(), "
                f"log_uniform(), choice(), or a tuple holding some); set a fixed value on the "
                f"element itself")
        # The kind and shape fit (a vector's length, a keyword, an int): one draw, checked
        # by the attribute's codec now rather than at the first draw.
        samples = (distribution.options if isinstance(distribution, Choice)
                   else (distribution.draw(np.random.default_rng(0)),))
        for sample in samples:
            _accept(element, attribute, sample, f"; a value {distribution!r} draws")
        entry = _Entry(element, attribute, distribution)
        for k, old in enumerate(self._entries):
            if old.element is element and old.attribute is attribute:
                self._entries[k] = entry
                return
        self._entries.append(entry)

    def draw(self, seed: int, n: int, *, first: int = 0) -> Draws:
        """The values of worlds ``first`` to ``first + n - 1``, each from its own generator
        (``world_rng(seed, i)``, drawn from in the order the distributions were stated), checked as assignment checks them (the attribute's codec)
        and against the attribute's bounds (schema/facts.toml): a value out of them is an
        error naming the element, attribute, value and world, never clipped."""
        check_worlds(seed, n, first)
        worlds = range(first, first + n)
        columns: list[list[object]] = [[] for _ in self._entries]
        for world in worlds:
            rng = world_rng(seed, world)
            for entry, column in zip(self._entries, columns, strict=True):
                value = entry.distribution.draw(rng)
                column.append(_checked(entry, value, f"; drawn for world {world} (seed {seed})"))
        return Draws(seed, worlds, [Drawn(e.element, e.attribute.py_name, _stacked(c, n))
                                    for e, c in zip(self._entries, columns, strict=True)])


def _accept(element: Element, attribute: AttributeSpec, value: object, where: str) -> object:
    """``value`` as its codec reads it back, or the error assignment would raise (plus
    ``where``). An element given to a reference is checked when it is assigned."""
    if attribute.is_reference and isinstance(value, Element):
        return value
    try:
        return attribute.codec.read(attribute.codec.accept(value))
    except Rejected as rejected:
        error = _tree.rejection(element, attribute, value, rejected)
    raise _with(error, where)


def _checked(entry: _Entry, value: object, where: str) -> object:
    element, attribute = entry.element, entry.attribute
    read = _accept(element, attribute, value, where)
    if attribute.bounds and not keeps(read, attribute.bounds):
        raise InvalidValueError(
            f"{element.path}: invalid {attribute.py_name}={_tree.short_repr(value)} on "
            f"<{element.spec.tag}>: expected {expected_bounds(attribute)}{where}")
    return read


def _with(error: Exception, where: str) -> Exception:
    """``error`` with ``where`` appended to its message (same class)."""
    if not where:
        return error
    return type(error)(f"{error}{where}")


def _stacked(values: list[object], n: int) -> Values:
    """One world's value per row: numbers and same-length vectors as a numeric array, names
    and keywords as strings, anything else (elements, ragged vectors) as objects."""
    if values and all(isinstance(v, np.ndarray) for v in values):
        arrays = cast(list[Values], values)
        if len({a.shape for a in arrays}) == 1:
            return np.stack(arrays)
    elif values and all(isinstance(v, int | float | str) and not isinstance(v, bool)
                        for v in values) and len({type(v) for v in values}) == 1:
        return np.asarray(values)
    column = np.empty(n, dtype=object)
    for k, value in enumerate(values):
        column[k] = value
    return column


class _Recorder:
    """What :meth:`Variation.of` returns: assignments record distributions."""

    __slots__ = ("_element", "_variation")

    _element: Element
    _variation: Variation

    def __init__(self, variation: Variation, element: Element) -> None:
        object.__setattr__(self, "_variation", variation)
        object.__setattr__(self, "_element", element)

    def __setattr__(self, name: str, value: object) -> None:
        self._variation.record(self._element, name, value)

    def __getattr__(self, name: str) -> object:
        if name.startswith("__"):
            raise AttributeError(name)
        element = self._element
        if name not in element.spec.by_key:  # a method or a child: use the element itself
            raise _tree.unknown_attribute(element, name)
        return getattr(element, name)  # reading gives the element's own value

    def __repr__(self) -> str:
        return f"<Variation.of {self._element!r}>"

