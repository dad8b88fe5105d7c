# Generated from src/typed_mjcf/variation/_distributions.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
T = TypeVar("T")
Numbers = np.ndarray[tuple[int, ...], np.dtype[np.float64]]

class Distribution:
    """A value drawn anew for each world (made by :func:`uniform`, :func:`normal`,
    :func:`log_uniform`, :func:`choice`, or a tuple holding some)."""
    def draw(self, rng: np.random.Generator) -> object:
        """One world's value, from that world's generator."""
        ...

class _Numeric(Distribution):
    """Two numbers or two vectors of one length (``a``, ``b``: low and high, or mean and std)."""
    a: Numbers
    b: Numbers
    scalar: bool
    integers: bool
    name: str = ""
    first: str = ""
    second: str = ""
    def __init__(self, a: object, b: object) -> None: ...
    def __repr__(self) -> str: ...

class Uniform(_Numeric):
    """Uniform between ``low`` and ``high`` (integers from both ends when both are ints)."""
    name, first, second = "uniform", "low", "high"
    def __init__(self, low: object, high: object) -> None: ...
    def draw(self, rng: np.random.Generator) -> object: ...

class Normal(_Numeric):
    """Normal with ``mean`` and standard deviation ``std``."""
    name, first, second = "normal", "mean", "std"
    def __init__(self, mean: object, std: object) -> None:
        super().__init__(mean, std)
        self.integers = False  # draws are real numbers
        if bool(np.any(self.b < 0)):
            raise InvalidValueError(f"normal(): std must be >= 0, got {std!r}")
    def draw(self, rng: np.random.Generator) -> object: ...

class LogUniform(_Numeric):
    """Uniform in the logarithm between ``low`` and ``high`` (both > 0)."""
    name, first, second = "log_uniform", "low", "high"
    def __init__(self, low: object, high: object) -> None:
        super().__init__(low, high)
        self.integers = False
        if bool(np.any(self.a <= 0)) or bool(np.any(self.a > self.b)):
            raise InvalidValueError(f"log_uniform(): expected 0 < low <= high, got {low!r} and "
                                    f"{high!r}")
    def draw(self, rng: np.random.Generator) -> object: ...

class Choice(Distribution):
    """One of ``options``, each as likely."""
    options: tuple[object, ...]
    def __init__(self, options: object) -> None: ...
    def draw(self, rng: np.random.Generator) -> object: ...
    def __repr__(self) -> str: ...

class Components(Distribution):
    """A vector some of whose components are distributions, each drawn in order."""
    items: tuple[object, ...]
    def __init__(self, items: Sequence[object]) -> None: ...
    def draw(self, rng: np.random.Generator) -> object: ...
    def __repr__(self) -> str: ...

def uniform(low: T, high: T) -> T:
    """Uniform between ``low`` and ``high``: numbers, or vectors of one length (per
    component); integers (both ends included) when both are ints. Typed as ``T``."""
    ...

def normal(mean: T, std: T) -> T:
    """Normal with ``mean`` and standard deviation ``std`` (numbers or vectors)."""
    ...

def log_uniform(low: T, high: T) -> T:
    """Uniform in the logarithm between ``low`` and ``high`` (> 0; numbers or vectors)."""
    ...

def choice(options: Sequence[T]) -> T:
    """One of ``options`` (keywords, numbers, vectors, names or elements), each as likely."""
    ...

def as_distribution(value: object) -> Distribution | None:
    """``value`` as a distribution: itself, or a tuple or list holding some (per
    component); ``None`` when it holds none."""
    ...
