"""Distributions that type as the value they stand for.

``uniform(0.5, 1.5)`` is a ``float`` to a type checker, as ``dataclasses.field()`` is the
field's type, so assigning it through :meth:`Variation.of` is checked by the element's own
setter types (a 2-vector for ``pos``, a number for a keyword: errors in mypy and pyright).
At run time each returns a :class:`Distribution`, drawn anew for every world.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Final, TypeVar, cast

import numpy as np

from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError
from typed_mjcf._core.tree import add_rejection_note

T = TypeVar("T")

Numbers = np.ndarray[tuple[int, ...], np.dtype[np.float64]]

# What the refusal of a distribution assigned to an element says (typed_mjcf._core.tree asks).
_NOTE: Final = ("a distribution is drawn per world: state it with "
                "typed_mjcf.variation.Variation().of(element).<attribute> = ..., "
                "then draw(seed, n)")


class Distribution:
    """A value drawn anew for each world (made by :func:`uniform`, :func:`normal`,
    :func:`log_uniform`, :func:`choice`, or a tuple holding some)."""

    __slots__ = ()

    def draw(self, rng: np.random.Generator) -> object:
        """One world's value, from that world's generator."""
        raise NotImplementedError


class _Numeric(Distribution):
    """Two numbers or two vectors of one length (``a``, ``b``: low and high, or mean and std)."""

    __slots__ = ("a", "b", "integers", "scalar")

    a: Numbers
    b: Numbers
    scalar: bool  # numbers given, not vectors
    integers: bool  # ints given to uniform(): ints drawn
    name: str = ""
    first: str = ""
    second: str = ""

    def __init__(self, a: object, b: object) -> None:
        self.a = _numeric_array(self.name, self.first, a)
        self.b = _numeric_array(self.name, self.second, b)
        if self.a.shape != self.b.shape:
            raise InvalidValueError(
                f"{self.name}(): {self.first} and {self.second} must have the same length, "
                f"got {a!r} and {b!r}")
        self.scalar = self.a.ndim == 0
        self.integers = _integers(a) and _integers(b)

    def _value(self, drawn: np.ndarray[tuple[int, ...], np.dtype[np.generic]] | float) -> object:
        """A number for scalar arguments, else a 1-D array."""
        if self.scalar:
            return int(cast(float, drawn)) if self.integers else float(cast(float, drawn))
        return np.asarray(drawn, dtype=np.int64 if self.integers else np.float64)

    def __repr__(self) -> str:
        return f"{self.name}({self.first}={_text(self.a)}, {self.second}={_text(self.b)})"


class Uniform(_Numeric):
    """Uniform between ``low`` and ``high`` (integers from both ends when both are ints)."""

    __slots__ = ()
    name, first, second = "uniform", "low", "high"

    def __init__(self, low: object, high: object) -> None:
        super().__init__(low, high)
        if bool(np.any(self.a > self.b)):
            raise InvalidValueError(f"uniform(): low must not exceed high, got {low!r} and "
                                    f"{high!r}")

    def draw(self, rng: np.random.Generator) -> object:
        if self.integers:
            return self._value(rng.integers(self.a.astype(np.int64), self.b.astype(np.int64),
                                            endpoint=True))
        return self._value(rng.uniform(self.a, self.b))


class Normal(_Numeric):
    """Normal with ``mean`` and standard deviation ``std``."""

    __slots__ = ()
    name, first, second = "normal", "mean", "std"

    def __init__(self, mean: object, std: object) -> None:
        super().__init__(mean, std)
        self.integers = False  # draws are real numbers
        if bool(np.any(self.b < 0)):
            raise InvalidValueError(f"normal(): std must be >= 0, got {std!r}")

    def draw(self, rng: np.random.Generator) -> object:
        return self._value(rng.normal(self.a, self.b))


class LogUniform(_Numeric):
    """Uniform in the logarithm between ``low`` and ``high`` (both > 0)."""

    __slots__ = ()
    name, first, second = "log_uniform", "low", "high"

    def __init__(self, low: object, high: object) -> None:
        super().__init__(low, high)
        self.integers = False
        if bool(np.any(self.a <= 0)) or bool(np.any(self.a > self.b)):
            raise InvalidValueError(f"log_uniform(): expected 0 < low <= high, got {low!r} and "
                                    f"{high!r}")

    def draw(self, rng: np.random.Generator) -> object:
        return self._value(np.exp(rng.uniform(np.log(self.a), np.log(self.b))))


class Choice(Distribution):
    """One of ``options``, each as likely."""

    __slots__ = ("options",)

    options: tuple[object, ...]

    def __init__(self, options: object) -> None:
        if isinstance(options, str | bytes) or not isinstance(options, Sequence):
            raise InvalidTypeError(f"choice(): expected a sequence of options (a list or "
                                   f"tuple), got {options!r}")
        if not options:
            raise InvalidValueError("choice(): expected at least one option, got none")
        self.options = tuple(cast(Sequence[object], options))

    def draw(self, rng: np.random.Generator) -> object:
        return self.options[int(rng.integers(len(self.options)))]

    def __repr__(self) -> str:
        return f"choice({list(self.options)!r})"


class Components(Distribution):
    """A vector some of whose components are distributions, each drawn in order."""

    __slots__ = ("items",)

    items: tuple[object, ...]

    def __init__(self, items: Sequence[object]) -> None:
        self.items = tuple(items)

    def draw(self, rng: np.random.Generator) -> object:
        return tuple(item.draw(rng) if isinstance(item, Distribution) else item
                     for item in self.items)

    def __repr__(self) -> str:
        return f"({', '.join(map(repr, self.items))})"


def uniform(low: T, high: T) -> T:
    """Uniform between ``low`` and ``high``: numbers, or vectors of one length (per
    component); integers (both ends included) when both are ints. Typed as ``T``."""
    return cast(T, Uniform(low, high))


def normal(mean: T, std: T) -> T:
    """Normal with ``mean`` and standard deviation ``std`` (numbers or vectors)."""
    return cast(T, Normal(mean, std))


def log_uniform(low: T, high: T) -> T:
    """Uniform in the logarithm between ``low`` and ``high`` (> 0; numbers or vectors)."""
    return cast(T, LogUniform(low, high))


def choice(options: Sequence[T]) -> T:
    """One of ``options`` (keywords, numbers, vectors, names or elements), each as likely."""
    return cast(T, Choice(options))


def as_distribution(value: object) -> Distribution | None:
    """``value`` as a distribution: itself, or a tuple or list holding some (per
    component); ``None`` when it holds none."""
    if isinstance(value, Distribution):
        return value
    if isinstance(value, tuple | list):
        items = cast(Sequence[object], value)
        if any(isinstance(item, Distribution) for item in items):
            return Components(items)
    return None


def _note(value: object) -> str | None:
    return _NOTE if as_distribution(value) is not None else None


add_rejection_note(_note)  # assigning a distribution to an element says where it goes


def _numeric_array(function: str, argument: str, value: object) -> Numbers:
    """A number or a flat sequence of numbers, finite, as floats."""
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        array = None
    if array is None or array.ndim > 1 or isinstance(value, str | bool) or (
            array.ndim == 1 and not len(array)):
        raise InvalidTypeError(f"{function}(): {argument} must be a number or a sequence of "
                               f"numbers, got {value!r}")
    if not bool(np.all(np.isfinite(array))):
        raise InvalidValueError(f"{function}(): {argument} must be finite, got {value!r}")
    return array


def _integers(value: object) -> bool:
    """Whether ``value`` is an int or a sequence of ints (not bools)."""
    items = cast(Sequence[object], value) if isinstance(value, tuple | list) else [value]
    return all(isinstance(x, int | np.integer) and not isinstance(x, bool) for x in items)


def _text(array: Numbers) -> str:
    return repr(array.item()) if array.ndim == 0 else repr(tuple(array.tolist()))
