"""Converters from user values (Python objects or MJCF text) to stored attribute values.

A converter either returns the value to store or raises :class:`Rejected` saying what was
expected; the element turns that into an error naming its path and the attribute.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Callable, Iterable
from fractions import Fraction
from typing import TYPE_CHECKING, Final, SupportsFloat, SupportsInt, cast

import numpy as np

from typed_mjcf.assets import Asset
from typed_mjcf.errors import InvalidTypeError, InvalidValueError, MjcfError, did_you_mean

if TYPE_CHECKING:
    from typed_mjcf._spec import AttributeSpec

Converter = Callable[[object], object]
AnyArray = np.ndarray[tuple[int, ...], np.dtype[np.generic]]

INT32_MIN: Final = -(2**31)
INT32_MAX: Final = 2**31 - 1
DTYPES: Final = {"double": np.float64, "float": np.float32, "int": np.int32}


class Rejected(Exception):
    """A value the attribute cannot take, with what it expected."""

    def __init__(self, expected: str, error: type[MjcfError] = InvalidValueError) -> None:
        super().__init__(expected)
        self.expected = expected
        self.error = error


def _type_rejected(expected: str) -> Rejected:
    return Rejected(expected, InvalidTypeError)


# ----------------------------------------------------------------------------- scalars


def _check_pattern(spec: AttributeSpec, text: str) -> None:
    if spec.pattern is not None and re.fullmatch(spec.pattern, text) is None:
        raise Rejected(f"text matching {spec.pattern!r}")


def string_converter(spec: AttributeSpec) -> Converter:
    def convert(value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a string")
        if not value:
            raise Rejected("a non-empty string")
        _check_pattern(spec, value)
        return value

    return convert


def chars_converter(spec: AttributeSpec) -> Converter:
    lo, hi = spec.lo, spec.hi

    def convert(value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a string")
        if not (lo <= len(value) and (hi is None or len(value) <= hi)):
            raise Rejected(f"{_count_text(lo, hi)} characters")
        _check_pattern(spec, value)
        return value

    return convert


def identifier_converter(spec: AttributeSpec) -> Converter:
    def convert(value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a name (string)")
        if not value:
            raise Rejected("a non-empty name")
        if "/" in value:
            raise Rejected("a name without '/' (it separates the scopes of attached models)")
        return value

    return convert


def file_converter(spec: AttributeSpec) -> Converter:
    def convert(value: object) -> object:
        if isinstance(value, Asset):
            return value
        if isinstance(value, os.PathLike):
            value = os.fspath(cast("os.PathLike[str]", value))
        if not isinstance(value, str):
            raise _type_rejected("a file path or a typed_mjcf.Asset")
        if not value:
            raise Rejected("a non-empty file path")
        return value

    return convert


_TRUE_FALSE: Final = {"true": True, "false": False}


def bool_converter(spec: AttributeSpec) -> Converter:
    def convert(value: object) -> object:
        if value is True or value is False:
            return value
        if isinstance(value, np.bool_):
            return bool(cast(object, value))
        if isinstance(value, str):
            found = _TRUE_FALSE.get(value.lower())
            if found is None:
                raise Rejected("true or false" + did_you_mean(value, _TRUE_FALSE))
            return found
        raise _type_rejected("a bool")

    return convert


def _to_int(value: object) -> int:
    if type(value) is int:
        result = value
    elif isinstance(value, bool | np.bool_):
        raise _type_rejected("an integer")
    elif isinstance(value, int | np.integer):
        result = int(cast(SupportsInt, value))
    elif isinstance(value, float | np.floating):
        f = float(cast(SupportsFloat, value))
        if not f.is_integer():
            raise Rejected("an integer (the value would be truncated)")
        result = int(f)
    elif isinstance(value, str):
        try:
            result = int(value)
        except ValueError:
            raise Rejected("an integer") from None
    else:
        raise _type_rejected("an integer")
    if not INT32_MIN <= result <= INT32_MAX:
        raise Rejected("an integer that fits in 32 bits")
    return result


def _to_float(value: object) -> float:
    if type(value) is float:
        return value
    if isinstance(value, bool | np.bool_):
        raise _type_rejected("a number")
    if isinstance(value, int | float | np.integer | np.floating):
        return float(cast(SupportsFloat, value))
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            raise Rejected("a number") from None
    raise _type_rejected("a number")


def _text_to_float32(text: str) -> np.float32:
    """MJCF text read as MuJoCo reads a float: rounded once, to the nearest float32.

    Going through a double rounds twice; that differs only when the double lands exactly
    halfway between two float32 values, so only then is the text compared exactly.
    """
    double = _to_float(text)
    single = np.float32(double)
    if float(single) == double or not math.isfinite(double):
        return single
    other = np.nextafter(single, np.float32(math.copysign(math.inf, double - float(single))))
    if double - float(single) != float(other) - double:
        return single
    exact, midpoint = Fraction(text.strip()), (Fraction(float(single)) + Fraction(float(other))) / 2
    if exact == midpoint:
        return single  # a true tie: round half to even, as the cast did
    return other if abs(exact - Fraction(float(other))) < abs(exact - Fraction(float(single))) else single


def _doubles_to_float32(doubles: np.ndarray[tuple[int, ...], np.dtype[np.float64]],
                        parts: list[str]) -> np.ndarray[tuple[int, ...], np.dtype[np.float32]]:
    """Round to float32 as MuJoCo does; only exact halfway doubles need the text again."""
    singles = doubles.astype(np.float32)
    back = singles.astype(np.float64)
    toward = np.nextafter(singles, np.where(doubles > back, np.float32(np.inf),
                                            np.float32(-np.inf)).astype(np.float32))
    ties = np.flatnonzero((back != doubles) & np.isfinite(doubles)
                          & (doubles - back == toward.astype(np.float64) - doubles))
    for i in ties.tolist():
        singles[i] = _text_to_float32(parts[i])
    return singles


def int_converter(spec: AttributeSpec) -> Converter:
    return _to_int


def real_converter(spec: AttributeSpec) -> Converter:
    return _to_float


# ----------------------------------------------------------------------------- arrays


def _count_text(lo: int, hi: int | None) -> str:
    if hi is None:
        return f"at least {lo}" if lo else "any number of"
    return f"{lo}" if lo == hi else f"{lo} to {hi}"


def array_converter(spec: AttributeSpec) -> Converter:
    lo, hi = spec.lo, spec.hi
    is_int = spec.kind == "int"
    dtype = DTYPES[spec.dtype or ("int" if is_int else "double")]
    noun = "integers" if is_int else "numbers"
    plain_types = frozenset({int}) if is_int else frozenset({int, float})
    expected = f"{_count_text(lo, hi)} {noun}"

    def from_text(text: str) -> AnyArray:
        parts = text.split()
        if hi is not None and len(parts) > hi:  # refuse before converting millions of numbers
            raise Rejected(f"{expected}, got {len(parts)}")
        try:  # C-level conversion; on any trouble, the per-item path says what was wrong
            if is_int:
                return np.array(list(map(int, parts)), dtype=dtype)
            doubles = np.fromiter(map(float, parts), np.float64, len(parts))
        except (ValueError, OverflowError):
            converter = _to_int if is_int else _to_float
            return np.array([converter(p) for p in parts], dtype=dtype)
        if dtype is np.float32:
            return _doubles_to_float32(doubles, parts)
        return doubles

    def convert(value: object) -> object:
        kind = type(value)
        if kind is tuple or kind is list:  # the common case: a few plain Python numbers
            items = cast("tuple[object, ...] | list[object]", value)
            n = len(items)
            if lo <= n and (hi is None or n <= hi) and plain_types.issuperset(map(type, items)):
                try:
                    return np.array(items, dtype)
                except OverflowError:
                    raise Rejected(f"{expected} that fit in 32 bits") from None
        try:
            array = from_text(cast(str, value)) if kind is str else to_array(value)
        except Rejected as rejected:
            if rejected.expected == expected or rejected.expected.startswith(expected):
                raise
            raise Rejected(expected, rejected.error) from None
        n = array.shape[0]
        if n < lo or (hi is not None and n > hi):
            raise Rejected(f"{expected}, got {n}")
        return array

    def to_array(value: object) -> AnyArray:
        if isinstance(value, str):
            return from_text(value)
        if isinstance(value, np.ndarray):
            return from_numpy(cast(AnyArray, value))
        if isinstance(value, int | float | np.integer | np.floating) and not isinstance(
                value, bool | np.bool_):
            return from_items([value])
        if isinstance(value, Iterable):
            return from_items(list(cast(Iterable[object], value)))
        raise _type_rejected(expected)

    def from_items(items: list[object]) -> AnyArray:
        if is_int:
            return np.array([_to_int(x) for x in items], dtype=dtype)
        return np.array([_to_float(x) for x in items], dtype=dtype)

    def from_numpy(value: AnyArray) -> AnyArray:
        if value.ndim != 1:
            raise Rejected(f"{expected} in a flat sequence")
        kind = value.dtype.kind
        if kind in "iu" or (kind == "f" and not is_int):
            return value.astype(dtype)
        if kind == "f":  # floats for an integer attribute: only if none would be truncated
            return from_items(cast(list[object], value.tolist()))
        raise _type_rejected(f"{expected} (got an array of dtype {value.dtype})")

    return convert


# ----------------------------------------------------------------------------- keywords


def keyword_converter(spec: AttributeSpec) -> Converter:
    keywords = spec.keywords
    lookup = {k.lower(): k for k in keywords}
    takes_bool = "true" in lookup and "false" in lookup
    listing = ", ".join(repr(k) for k in keywords)

    def convert(value: object) -> object:
        if takes_bool and (value is True or value is False):
            return "true" if value else "false"
        if not isinstance(value, str):
            raise _type_rejected(f"one of {listing}")
        found = lookup.get(value.lower())
        if found is None:
            raise Rejected(f"one of {listing}" + did_you_mean(value, keywords))
        return found

    return convert


def flags_converter(spec: AttributeSpec) -> Converter:
    keywords = spec.keywords
    lookup = {k.lower(): k for k in keywords}
    order = {k: i for i, k in enumerate(keywords)}
    listing = ", ".join(repr(k) for k in keywords)

    def convert(value: object) -> object:
        words: list[object]
        if isinstance(value, str):
            words = list(value.split())
        elif isinstance(value, Iterable):
            words = list(value)  # pyright: ignore[reportUnknownArgumentType]
        else:
            raise _type_rejected(f"keywords from {listing}")
        found: set[str] = set()
        for word in words:
            if not isinstance(word, str):
                raise _type_rejected(f"keywords from {listing}")
            canonical = lookup.get(word.lower())
            if canonical is None:
                raise Rejected(f"keywords from {listing}" + did_you_mean(word, keywords))
            found.add(canonical)
        if not found:
            raise Rejected(f"at least one keyword from {listing}")
        # MuJoCo reads some flag sets only in their canonical order.
        return tuple(sorted(found, key=order.__getitem__))

    return convert


def reference_converter(spec: AttributeSpec) -> Converter:
    namespace = spec.namespace

    def convert(value: object) -> object:
        if isinstance(value, str):
            if not value:
                raise Rejected("a non-empty name")
            return value
        element_spec = getattr(type(value), "_SPEC", None)
        if element_spec is None:
            raise _type_rejected(f"a name or an element of namespace {namespace!r}")
        if element_spec.namespace != namespace:
            raise _type_rejected(
                f"a name or an element of namespace {namespace!r}, "
                f"got a <{element_spec.tag}> (namespace {element_spec.namespace!r})"
            )
        return value

    return convert


CONVERTERS: Final[dict[str, Callable[[AttributeSpec], Converter]]] = {
    "string": string_converter,
    "chars": chars_converter,
    "file": file_converter,
    "bool": bool_converter,
    "int": int_converter,
    "real": real_converter,
    "keyword": keyword_converter,
    "flags": flags_converter,
    "id": identifier_converter,
    "ref": reference_converter,
}


def make_converter(spec: AttributeSpec) -> Converter:
    if spec.is_array:
        return array_converter(spec)
    return CONVERTERS[spec.kind](spec)

