"""One codec per attribute kind: MJCF text in, a Python value in, text out.

Every route that reads or writes a value goes through its attribute's codec: assignment and
``add()`` (:meth:`Codec.accept`), parsing (:meth:`Codec.parse`), reading a property
(:meth:`Codec.read`), and every export, keyframe composition included (:meth:`Codec.write`,
with the export's :class:`Format`).

Numbers read from a file are kept as the text they were read as, once a compiled pattern has
checked it (a value that fails the pattern is converted at once, so every error is still
raised at load): reading converts that text (each time; the array is read-only), and an export
with default options writes it back as it was read. Values set from Python are stored
converted and written canonically (floats in the shortest form that reads back exactly).

A codec raises :class:`Rejected` saying what it expected; the element turns that into an
error naming its path, the attribute and the value.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from fractions import Fraction
from typing import Final, SupportsFloat, SupportsIndex, cast

import numpy as np

from typed_mjcf._core.arrays import read_only
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, MjcfError, did_you_mean
from typed_mjcf.assets import Asset

Array = np.ndarray[tuple[int, ...], np.dtype[np.generic]]
Float64Array = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
Float32Array = np.ndarray[tuple[int, ...], np.dtype[np.float32]]

INT32_MIN: Final = -(2**31)
INT32_MAX: Final = 2**31 - 1
DTYPES: Final[dict[str, type[np.generic]]] = {
    "double": np.float64, "float": np.float32, "int": np.int32}

# Numbers as MJCF files spell them, kept as text once matched: few enough integer digits and
# a short enough exponent that no match can overflow (10^200 * 10^99 for a double, 10^20 *
# 10^9 for a float). Anything else (longer, hexadecimal, inf, nan) is converted to be checked.
_DOUBLE = r"[-+]?(?:\d{1,200}(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,2})?"
_FLOAT = r"[-+]?(?:\d{1,20}(?:\.\d*)?|\.\d+)(?:[eE](?:-\d{1,2}|\+?\d))?"
_INTEGER = r"[-+]?\d{1,9}"  # at most nine digits: always within 32 bits
FLOAT32_MAX: Final = float(np.finfo(np.float32).max)
# What a float attribute (dtype "float" in schema/) expects of each number: MuJoCo's reader
# refuses a finite one beyond it ("number is too large"), where numpy would make it inf.
FLOAT32_RANGE: Final = f"within the range of a float32 (magnitude at most {FLOAT32_MAX:.8g})"
# the smallest normal numbers: below them (zero aside) a number is subnormal
_TINY: Final = {False: float(np.finfo(np.float64).tiny), True: float(np.finfo(np.float32).tiny)}
# Why a number that underflows is refused, when the MuJoCo release in use refuses them (set
# once, at import, by typed_mjcf._releases.facts: schema/releases/behaviour.toml); None: read.
_UNDERFLOW: list[str | None] = [None]

# Texts a codec has checked, to accept again without checking: models repeat the same few
# values ("0 0 1") many times. Bounded, so that reading many distinct values costs no memory.
# Each maps to the first such text, which parse() returns: repeated values share one string
# (52+ bytes less per value read; the lookup is the one the check already made).
_CHECKED_TEXTS: Final = 2048  # per codec
_CHECKED_LENGTH: Final = 64  # characters; longer texts are checked each time


# every codec's set of checked texts: emptied when what is accepted changes (refuse_underflow)
_CHECKED_SETS: list[dict[str, str]] = []


def checked_texts() -> dict[str, str]:
    """A new, empty table of checked texts for a codec (each text to itself)."""
    checked: dict[str, str] = {}
    _CHECKED_SETS.append(checked)
    return checked


def remember(checked: dict[str, str], text: str) -> None:
    """Note that ``text`` passed a codec's check (if there is room, and it is short)."""
    if len(checked) < _CHECKED_TEXTS and len(text) <= _CHECKED_LENGTH:
        checked[text] = text


class Rejected(Exception):
    """A value the attribute cannot take, with what it expected."""

    def __init__(self, expected: str, error: type[MjcfError] = InvalidValueError) -> None:
        super().__init__(expected)
        self.expected = expected
        self.error = error


def _type_rejected(expected: str) -> Rejected:
    return Rejected(expected, InvalidTypeError)


# The precision of every MJCF writer when none is asked for (significant digits; ``None``:
# the shortest text that reads back exactly). The one place it is decided: :class:`Format`
# reads it whenever it writes, so every route (assignment, export, ``str()``, composed models,
# keyframes, the MjSpec bridge, the CLI) follows it.
DEFAULT_PRECISION: int | None = None


def real_text(values: Sequence[float], single: bool = False, precision: int | None = None) -> str:
    """Real numbers as MJCF text, space-separated: the one spelling of a float every writer
    uses (one number is a sequence of one). With ``precision``, that many significant digits;
    else the shortest text that reads back exactly (as a float32 when ``single``), without a
    trailing ``.0``."""
    if precision is not None:
        spec = f".{precision}g"
        return " ".join([format(x, spec) for x in values])
    if single:
        text = " ".join([str(np.float32(x)) for x in values])
    else:
        text = " ".join(map(repr, values))  # one C-level join
    return text.replace(".0 ", " ").removesuffix(".0")


class Format:
    """Export options, applied by every codec the same way. ``precision=None`` is the
    library's default (:data:`DEFAULT_PRECISION`), read when a number is written."""

    __slots__ = ("canonical", "precision", "zero_threshold")

    precision: int | None  # as asked for; None: DEFAULT_PRECISION
    zero_threshold: float
    canonical: bool

    # (object: users pass these through to_xml_string(); the checks say what is expected,
    # where a compiled signature would raise a bare TypeError first)
    def __init__(self, precision: object = None, zero_threshold: object = 0.0,
                 canonical: bool = False) -> None:
        _check_option("precision", precision, lambda x: isinstance(x, int) and x >= 1,
                      "a positive int", allow_none=True)
        _check_option("zero_threshold", zero_threshold,
                      lambda x: isinstance(x, int | float) and x >= 0, "a non-negative number")
        self.precision = cast("int | None", precision)
        self.zero_threshold = float(cast(float, zero_threshold))
        self.canonical = canonical

    @property
    def digits(self) -> int | None:
        """The precision numbers are written with (``None``: shortest round-trip form)."""
        return DEFAULT_PRECISION if self.precision is None else self.precision

    @property
    def keeps_source_text(self) -> bool:
        """Whether numbers read from a file are written as they were read: nothing asks
        for them to be reformatted."""
        return self.digits is None and not self.zero_threshold and not self.canonical

    def number(self, x: float, single: bool = False) -> str:
        """One number (of a float32 when ``single``), as :func:`real_text` spells it."""
        return self.numbers((x,), single)

    def numbers(self, values: Sequence[float], single: bool = False) -> str:
        """Numbers, space-separated, as :func:`real_text` spells them with these options."""
        threshold = self.zero_threshold
        if threshold:
            values = [0.0 if abs(x) < threshold else x for x in values]
        precision = self.precision  # (not self.digits: a property costs a call per value)
        return real_text(values, single, DEFAULT_PRECISION if precision is None else precision)


def _check_option(name: str, value: object, valid: Callable[[object], bool], expected: str,
                  allow_none: bool = False) -> None:
    if (value is None and allow_none) or (not isinstance(value, bool) and valid(value)):
        return
    raise InvalidValueError(f"{name} must be {expected}, got {value!r}")


# The default options (the precision is read from DEFAULT_PRECISION as each number is written)
DEFAULT_FORMAT: Final = Format()


# ---------------------------------------------------------------------------- the interface


class Codec:
    """Text in, Python value in, text out, for one kind of attribute."""

    __slots__ = ()

    lazy: bool = False  # stores checked text from files, converted when read

    def accept(self, value: object) -> object:
        """A value given in Python, as stored; raises :class:`Rejected`."""
        raise NotImplementedError

    def parse(self, text: str) -> object:
        """Text read from a file, as stored (possibly that text, checked); raises
        :class:`Rejected`."""
        return self.accept(text)

    def read(self, stored: object) -> object:
        """What a property returns for a stored value."""
        return stored

    # Whether a text stored as read from a file is written as it was read when the output
    # keeps source text (``Format.keeps_source_text``): the one place that is decided. Every
    # codec's :meth:`write` follows it (a test holds each to it), and the exporter plans from
    # it (once per row, see ``_export.write_plan``) to write such texts without the call. A
    # codec that rewrites what it read (say, to normalise its spelling) sets it false, and
    # every route follows.
    keeps_read_text: bool = True

    def write(self, stored: object, fmt: Format) -> str:
        """The stored value as attribute text; a text stored as read, as it was read when
        ``fmt.keeps_source_text`` and :attr:`keeps_read_text`."""
        return stored if type(stored) is str else str(stored)  # (typing.cast is a call)


# What XML 1.0 can hold (its Char production): a string with anything else (NUL, most control
# characters, U+FFFE, U+FFFF, a lone surrogate) could not be written to a file and read back.
_NOT_XML: Final = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def check_xml_text(value: str, what: str = "text") -> None:
    """Refuse a string that XML cannot hold; ``what`` names what was expected."""
    bad = _NOT_XML.search(value)
    if bad is not None:
        raise Rejected(f"{what} that XML can hold (U+{ord(bad.group()):04X} at offset "
                       f"{bad.start()} is not an XML character)")


class StringCodec(Codec):
    __slots__ = ("pattern",)

    def __init__(self, pattern: str | None) -> None:
        self.pattern = None if pattern is None else re.compile(pattern)

    def accept(self, value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a string")
        if not value:
            raise Rejected("a non-empty string")
        check_xml_text(value)
        if self.pattern is not None and self.pattern.fullmatch(value) is None:
            raise Rejected(f"text matching {self.pattern.pattern!r}")
        return value


class CharsCodec(StringCodec):
    __slots__ = ("hi", "lo")

    def __init__(self, pattern: str | None, lo: int, hi: int | None) -> None:
        super().__init__(pattern)
        self.lo, self.hi = lo, hi

    def accept(self, value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a string")
        if not (self.lo <= len(value) and (self.hi is None or len(value) <= self.hi)):
            raise Rejected(f"{count_text(self.lo, self.hi)} characters")
        check_xml_text(value)
        if self.pattern is not None and self.pattern.fullmatch(value) is None:
            raise Rejected(f"text matching {self.pattern.pattern!r}")
        return value


class IdentifierCodec(Codec):
    """A name: from Python without ``/`` (it separates the scopes of attached models); from
    files as written (MuJoCo accepts ``/`` in names and real models use it)."""

    __slots__ = ()

    def accept(self, value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a name (string)")
        if not value:
            raise Rejected("a non-empty name")
        if "/" in value:
            raise Rejected("a name without '/' (it separates the scopes of attached models; "
                           "names read from files may have one)")
        check_xml_text(value, "a name")
        return value

    def parse(self, text: str) -> object:
        return text


class ReferenceCodec(Codec):
    """A name of another element, as text (the tree stores element links itself)."""

    __slots__ = ()

    def accept(self, value: object) -> object:
        if not isinstance(value, str):
            raise _type_rejected("a name or an element")
        if not value:
            raise Rejected("a non-empty name")
        check_xml_text(value, "a name")
        return value


class FileCodec(Codec):
    __slots__ = ()

    def accept(self, value: object) -> object:
        if isinstance(value, Asset):
            return value
        if isinstance(value, os.PathLike):
            value = os.fspath(cast("os.PathLike[str]", value))
        if not isinstance(value, str):
            raise _type_rejected("a file path or a typed_mjcf.Asset")
        if not value:
            raise Rejected("a non-empty file path")
        check_xml_text(value, "a file path")
        return value


_TRUE_FALSE: Final = {"true": True, "false": False}


class BoolCodec(Codec):
    __slots__ = ()

    def accept(self, value: object) -> object:
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

    def parse(self, text: str) -> object:
        exact = _TRUE_FALSE.get(text)  # spelt exactly as MuJoCo reads it: the common case
        if exact is not None:
            return exact
        found = self.accept(text)
        _check_spelling(text, "true" if found else "false")
        return found

    def write(self, stored: object, fmt: Format) -> str:
        return "true" if stored else "false"


def to_int(value: object) -> int:
    """An integer attribute's value, refusing what would be truncated or overflow."""
    if type(value) is int:
        result = value
    elif isinstance(value, bool | np.bool_):
        raise _type_rejected("an integer")
    elif isinstance(value, int | np.integer):
        result = int(cast(SupportsIndex, value))
    elif isinstance(value, float | np.floating):
        f = float(cast(SupportsFloat, value))
        if not f.is_integer():
            raise Rejected("an integer (the value would be truncated)")
        result = int(f)
    elif isinstance(value, str):
        if not value.isascii() or "_" in value:  # Python's int takes them; MuJoCo does not
            raise Rejected("an integer")
        try:
            result = int(value)
        except ValueError:
            raise Rejected("an integer") from None
    else:
        raise _type_rejected("an integer")
    if not INT32_MIN <= result <= INT32_MAX:
        raise Rejected("an integer that fits in 32 bits")
    return result


def to_float(value: object) -> float:
    """A real attribute's value."""
    if type(value) is float:
        return value
    if isinstance(value, bool | np.bool_):
        raise _type_rejected("a number")
    if isinstance(value, int | float | np.integer | np.floating):
        return float(cast(SupportsFloat, value))
    if isinstance(value, str):
        return text_to_float(value)
    raise _type_rejected("a number")


def text_to_float(text: str) -> float:
    """A number spelled as MuJoCo reads one (C's strtod): hexadecimal too, but no '_'
    separators or non-ASCII digits (which Python's float takes), and nothing too large for a
    double."""
    if not text.isascii() or "_" in text:
        raise Rejected("a number")
    try:
        value = float(text)
    except ValueError:
        if "x" not in text.lower():
            raise Rejected("a number") from None
        try:
            value = float.fromhex(text)
        except (ValueError, OverflowError):
            raise Rejected("a number") from None
    if math.isinf(value) and "inf" not in text.lower():
        raise Rejected("a number within the range of a double")
    return value


def check_float32(value: float) -> None:
    """Refuse a finite number too large for a float32 (MuJoCo: "number is too large"); an
    infinity reaches here only spelled as one (:func:`text_to_float`), and is kept."""
    if _beyond_float32(value):
        raise Rejected(f"a number {FLOAT32_RANGE}")


def _beyond_float32(value: float) -> bool:
    """Whether a Python number is finite and too large for a float32 (an infinity or NaN
    is kept, as MuJoCo reads one spelled so; a huge int is compared exactly)."""
    if -FLOAT32_MAX <= value <= FLOAT32_MAX:
        return False
    return not (type(value) is float and not math.isfinite(value))


def refuse_underflow(note: str | None) -> None:
    """Refuse numbers that underflow, saying ``note`` (why), or read them (``None``)."""
    _UNDERFLOW[0] = note
    for checked in _CHECKED_SETS:  # texts accepted before may be refused now
        checked.clear()


def _mantissa_is_zero(text: str) -> bool:
    bare = text.strip().lower().lstrip("+-")
    mantissa = bare[2:].partition("p")[0] if bare.startswith("0x") else bare.partition("e")[0]
    return re.search(r"[1-9a-f]", mantissa) is None


def underflows(text: str | None, value: float, single: bool) -> bool:
    """Whether ``value`` (read from ``text``, or given in Python: None) underflows its type:
    subnormal, or zero though the text is not. MuJoCo's strtod/strtof refuse such a text
    unless it is exact (0x1p-1074): those are refused too, since an export writes the value
    in decimal (5e-324), which the releases refusing underflow do not read."""
    if not abs(value) < _TINY[single]:
        return False
    return value != 0.0 or (text is not None and not _mantissa_is_zero(text))


def check_underflow(what: str, texts: Sequence[str] | None, values: Sequence[float],
                    single: bool) -> None:
    """Refuse ``values`` (read from ``texts``, or given in Python) if one underflows and the
    release in use refuses that; ``what`` is what the codec expects."""
    note = _UNDERFLOW[0]
    if note is None:
        return
    tiny = _TINY[single]
    for i, value in enumerate(values):
        if abs(value) < tiny and underflows(None if texts is None else texts[i], value, single):
            shown = repr(value) if texts is None else texts[i]
            kind = "float32" if single else "double"
            raise Rejected(f"{what} not underflowing a {kind} ({shown} does: {note})")


class IntCodec(Codec):
    __slots__ = ()

    def accept(self, value: object) -> object:
        return to_int(value)

    def write(self, stored: object, fmt: Format) -> str:
        return str(stored)


class RealCodec(Codec):
    """One number. Text from a file is checked by converting it, and kept."""

    __slots__ = ("checked", "single")
    lazy = True

    def __init__(self, single: bool) -> None:
        self.single = single
        self.checked = checked_texts()

    def accept(self, value: object) -> object:
        result = to_float(value)
        if self.single:
            check_float32(result)
        if _UNDERFLOW[0] is not None:
            self._check_underflow(value if isinstance(value, str) else None, result)
        return result

    def parse(self, text: str) -> object:
        shared = self.checked.get(text)
        if shared is not None:
            return shared
        value = text_to_float(text)
        if self.single:
            check_float32(value)
        if _UNDERFLOW[0] is not None:
            self._check_underflow(text, value)
        remember(self.checked, text)
        return text

    def read(self, stored: object) -> object:
        return to_float(stored) if type(stored) is str else stored

    def _check_underflow(self, text: str | None, value: float) -> None:
        """Refuse ``value`` (read from ``text``, or given in Python) if it underflows, the
        release in use refusing that (a float attribute's text read as a float32 does)."""
        read = float(_text_to_float32(text)) if self.single and text else value
        check_underflow("a number", None if text is None else [text], [read], self.single)

    def write(self, stored: object, fmt: Format) -> str:
        if type(stored) is str:
            if fmt.keeps_source_text and self.keeps_read_text:
                return stored
            stored = to_float(stored)
        return fmt.numbers((cast(float, stored),), self.single)


# ---------------------------------------------------------------------------- arrays


def count_text(lo: int, hi: int | None) -> str:
    if hi is None:
        return f"at least {lo}" if lo else "any number of"
    return f"{lo}" if lo == hi else f"{lo} to {hi}"


def _text_to_float32(text: str) -> np.float32:
    """MJCF text read as MuJoCo reads a float: rounded once, to the nearest float32.

    Going through a double rounds twice; that differs only when the double lands exactly
    halfway between two float32 values, so only then is the text compared exactly.
    """
    double = to_float(text)
    single = np.float32(double)
    if float(single) == double or not math.isfinite(double):
        return single
    other = np.nextafter(single, np.float32(math.copysign(math.inf, double - float(single))))
    if double - float(single) != float(other) - double:
        return single
    # (a hexadecimal spelling is exact in a double: the double is its value)
    exact = Fraction(double) if "x" in text.lower() else Fraction(text.strip())
    midpoint = (Fraction(float(single)) + Fraction(float(other))) / 2
    if exact == midpoint:
        return single  # a true tie: round half to even, as the cast did
    closer = abs(exact - Fraction(float(other))) < abs(exact - Fraction(float(single)))
    return other if closer else single


def _doubles_to_float32(doubles: Float64Array, parts: list[str]) -> Float32Array:
    """Round to float32 as MuJoCo does; only exact halfway doubles need the text again."""
    singles = doubles.astype(np.float32)
    back = singles.astype(np.float64)
    toward = np.nextafter(singles, np.where(doubles > back, np.float32(np.inf),
                                            np.float32(-np.inf)).astype(np.float32))
    with np.errstate(invalid="ignore"):  # inf - inf: infinities are no ties
        ties = np.flatnonzero((back != doubles) & np.isfinite(doubles)
                              & (doubles - back == toward.astype(np.float64) - doubles))
    for i in ties.tolist():
        singles[i] = _text_to_float32(parts[i])
    return singles


_PIECE: Final = 1 << 20  # characters of a long number list converted at a time
_PIECE_NUMBERS: Final = 1 << 16  # numbers of a long array written at a time


def _pieces(text: str) -> Iterator[str]:
    """``text`` in pieces of about :data:`_PIECE` characters, each cut after whitespace."""
    start, length = 0, len(text)
    while start < length:
        end = start + _PIECE
        if end < length:
            cut = _SPACE.search(text, end)  # the words are kept whole
            end = length if cut is None else cut.end()
        yield text[start:end]
        start = end


_SPACE: Final = re.compile(r"\s", re.ASCII)


class ArrayCodec(Codec):
    """A list of numbers of a fixed or bounded length, stored as a read-only numpy array."""

    __slots__ = ("checked", "dtype", "exact_types", "expected", "hi", "in_range", "is_int", "lo",
                 "pattern", "single")
    lazy = True

    def __init__(self, kind: str, dtype: str, lo: int, hi: int | None) -> None:
        self.lo, self.hi = lo, hi
        self.is_int = kind == "int"
        self.dtype = DTYPES[dtype]
        self.single = dtype == "float"
        self.exact_types = frozenset({int}) if self.is_int else frozenset({int, float})
        self.expected = f"{count_text(lo, hi)} {'integers' if self.is_int else 'numbers'}"
        self.in_range = f"{self.expected}, each {FLOAT32_RANGE}"
        number = _INTEGER if self.is_int else _FLOAT if self.single else _DOUBLE
        low, high = max(lo - 1, 0), "" if hi is None else str(max(hi - 1, 0))
        # Possessive ("}+"): the engine keeps no backtracking state per number (an ordinary
        # repeat costs ~600 bytes a number: 14 GB for a 60 MB list). It accepts the same
        # texts: a number never ends inside a word, so giving one back cannot help a match.
        repeat = f"(?:\\s+{number}){{{low},{high}}}+"
        self.pattern = re.compile(f"\\s*{number}{repeat}\\s*" if hi != 0 else r"\s*", re.ASCII)
        self.checked = checked_texts()

    def accept(self, value: object) -> object:
        kind = type(value)
        if kind is tuple or kind is list:  # the common case: a few Python ints and floats
            items = cast("tuple[object, ...] | list[object]", value)
            n = len(items)
            hi = self.hi
            if self.lo <= n and (hi is None or n <= hi):
                exact_types = self.exact_types
                for item in items:
                    if type(item) not in exact_types:
                        break
                else:
                    if self.single:
                        self._check_single(cast("Sequence[float]", items))
                    try:
                        array = np.array(items, self.dtype)
                    except OverflowError:
                        raise Rejected(f"{self.expected} that fit in 32 bits") from None
                    if _UNDERFLOW[0] is not None:
                        self._check_underflow(None, array)
                    return array
        try:
            array = self.from_text(cast(str, value)) if kind is str else self._to_array(value)
        except Rejected as rejected:
            if rejected.expected.startswith(self.expected):
                raise
            raise Rejected(self.expected, rejected.error) from None
        self._check_length(array.shape[0])
        if _UNDERFLOW[0] is not None and kind is not str:
            self._check_underflow(None, array)
        return array

    def _check_underflow(self, parts: list[str] | None, array: Array) -> None:
        """Refuse a number that underflows, the release in use refusing them (few are tiny:
        only those are looked at)."""
        if self.is_int:
            return
        values = array.astype(np.float64)
        tiny = np.flatnonzero(np.abs(values) < _TINY[self.single]).tolist()
        if tiny:
            check_underflow(self.expected, None if parts is None else [parts[i] for i in tiny],
                            [float(values[i]) for i in tiny], self.single)

    def parse(self, text: str) -> object:
        shared = self.checked.get(text)
        if shared is not None:
            return shared
        if self.pattern.fullmatch(text) is not None:
            if _UNDERFLOW[0] is not None and not self.is_int:
                self.from_text(text)  # the pattern lets tiny numbers by: convert to check
            remember(self.checked, text)
            return text
        array = self.from_text(text)
        self._check_length(array.shape[0])
        return array

    def read(self, stored: object) -> object:
        """A read-only array: changes go through assignment (and its checks)."""
        if type(stored) is str:
            return read_only(self.from_text(stored))
        return read_only(cast(Array, stored))

    def write(self, stored: object, fmt: Format) -> str:
        if type(stored) is str:
            if fmt.keeps_source_text and self.keeps_read_text:
                return stored
            stored = self.from_text(stored)
        array = cast(Array, stored)
        if array.shape[0] <= _PIECE_NUMBERS:
            return self._write_numbers(array, fmt)
        # a piece at a time: a number as a Python float and then as text costs ~100 bytes
        return " ".join([self._write_numbers(array[i:i + _PIECE_NUMBERS], fmt)
                         for i in range(0, array.shape[0], _PIECE_NUMBERS)])

    def _write_numbers(self, array: Array, fmt: Format) -> str:
        if self.is_int:
            return " ".join(map(str, array.tolist()))
        return fmt.numbers(cast(list[float], array.tolist()), self.single)

    def _check_length(self, n: int) -> None:
        if n < self.lo or (self.hi is not None and n > self.hi):
            raise Rejected(f"{self.expected}, got {n}")

    def from_text(self, text: str) -> Array:
        if len(text) <= _PIECE:
            return self._from_parts(text.split(), text)
        # A long list is converted a piece at a time: a word of text as a Python string
        # costs ten times its characters, a number in an array eight bytes.
        arrays: list[Array] = []
        count = 0
        for piece in _pieces(text):
            parts = piece.split()
            count += len(parts)
            if self.hi is not None and count > self.hi:
                raise Rejected(f"{self.expected}, got at least {count}")
            arrays.append(self._from_parts(parts, piece))
        return np.concatenate(arrays) if arrays else self._from_parts([], "")

    def _from_parts(self, parts: list[str], text: str) -> Array:
        """The numbers ``parts``, the words of ``text``."""
        if self.hi is not None and len(parts) > self.hi:  # refuse before converting millions
            raise Rejected(f"{self.expected}, got {len(parts)}")
        try:  # C-level conversion; on any trouble, the per-item path says what was wrong
            if not text.isascii() or "_" in text:
                raise ValueError(text)  # Python takes them; MuJoCo does not
            if self.is_int:
                return np.array(list(map(int, parts)), dtype=self.dtype)
            doubles = np.fromiter(map(float, parts), np.float64, len(parts))
            if not np.isfinite(doubles).all():
                raise ValueError(text)  # inf, nan or too large: the per-item path decides
        except (ValueError, OverflowError):
            if self.is_int:
                return np.array([to_int(p) for p in parts], dtype=self.dtype)
            doubles = np.array([text_to_float(p) for p in parts], dtype=np.float64)
        if self.single:
            if not np.isfinite(doubles).all() or np.abs(doubles).max(initial=0.0) > FLOAT32_MAX:
                self._check_single(cast(list[float], doubles.tolist()))
            singles = _doubles_to_float32(doubles, parts)
            if _UNDERFLOW[0] is not None:
                self._check_underflow(parts, singles)
            return singles
        if _UNDERFLOW[0] is not None:
            self._check_underflow(parts, doubles)
        return doubles

    def _to_array(self, value: object) -> Array:
        if isinstance(value, np.ndarray):
            return self._from_numpy(cast(Array, value))
        if isinstance(value, int | float | np.integer | np.floating) and not isinstance(
                value, bool | np.bool_):
            return self._from_items([value])
        if isinstance(value, Iterable):
            return self._from_items(list(cast(Iterable[object], value)))
        raise _type_rejected(self.expected)

    def _from_items(self, items: list[object]) -> Array:
        if self.is_int:
            return np.array([to_int(x) for x in items], dtype=self.dtype)
        floats = [to_float(x) for x in items]
        if self.single:
            self._check_single(floats)
        return np.array(floats, dtype=self.dtype)

    def _check_single(self, values: Sequence[float]) -> None:
        """Refuse numbers a float32 cannot hold (numpy would make them inf, silently)."""
        for value in values:  # (a compare per number: this is on the path of every build)
            if not -FLOAT32_MAX <= value <= FLOAT32_MAX and _beyond_float32(value):
                raise Rejected(self.in_range)

    def _from_numpy(self, value: Array) -> Array:
        if value.ndim == 0:
            return self._from_items([value.item()])
        if value.ndim != 1:
            raise Rejected(f"{self.expected} in a flat sequence")
        kind = value.dtype.kind
        if kind in "iu" or (kind == "f" and not self.is_int):
            if self.is_int and value.size and (value.min() < INT32_MIN or value.max() > INT32_MAX):
                raise Rejected(f"{self.expected} that fit in 32 bits")
            if self.single and kind == "f" and value.dtype.itemsize > 4:
                finite = value[np.isfinite(value)]
                if finite.size and float(np.abs(finite).max()) > FLOAT32_MAX:
                    raise Rejected(self.in_range)
            return value.astype(self.dtype)
        if kind == "f":  # floats for an integer attribute: only if none would be truncated
            return self._from_items(cast(list[object], value.tolist()))
        raise _type_rejected(f"{self.expected} (got an array of dtype {value.dtype})")


# ---------------------------------------------------------------------------- keywords


def _check_spelling(text: str, keyword: str) -> None:
    """Refuse a keyword read from a file in another case: Python assignment accepts any case
    (as dm_control does), but MuJoCo reads files exactly as written."""
    if text != keyword:
        raise Rejected(f"{keyword!r} (MuJoCo reads keywords only as its grammar spells them)")


class KeywordCodec(Codec):
    """One keyword, stored as the grammar spells it. Where MuJoCo's reader also takes a
    keyword's integer (``numbers``: ``<headlight active="1">``), so do parsing and assignment,
    and the keyword is stored: export writes that canonical spelling, which MuJoCo reads
    the same."""

    __slots__ = ("by_number", "exact", "keywords", "listing", "lookup", "takes_bool")

    def __init__(self, keywords: tuple[str, ...],
                 numbers: tuple[tuple[str, int], ...] = ()) -> None:
        self.keywords = keywords
        self.lookup = {k.lower(): k for k in keywords}
        # what parse() takes as it is, to the grammar's own string (shared by every value)
        self.exact = {word: word for word in self.lookup.values()}
        self.takes_bool = "true" in self.lookup and "false" in self.lookup
        self.by_number = {n: k for k, n in numbers}
        also = f" (or {', '.join(str(n) for _, n in numbers)})" if numbers else ""
        self.listing = ", ".join(repr(k) for k in keywords) + also

    def accept(self, value: object) -> object:
        if self.takes_bool and (value is True or value is False):
            return "true" if value else "false"
        if self.by_number and isinstance(value, int | np.integer) \
                and not isinstance(value, bool | np.bool_):
            return self._numbered(cast(object, value))
        if not isinstance(value, str):
            raise _type_rejected(f"one of {self.listing}")
        found = self.lookup.get(value.lower())
        if found is None:
            if self.by_number and value.strip():
                return self._numbered(value)
            raise Rejected(f"one of {self.listing}" + did_you_mean(value, self.keywords))
        return found

    def _numbered(self, value: object) -> str:
        """The keyword whose integer ``value`` is (an int, or text MuJoCo reads as one)."""
        try:
            found = self.by_number.get(to_int(value))
        except Rejected:
            found = None
        if found is None:
            raise Rejected(f"one of {self.listing}" + (
                did_you_mean(value, self.keywords) if isinstance(value, str) else ""))
        return found

    def parse(self, text: str) -> object:
        shared = self.exact.get(text)
        if shared is not None:  # spelt as the grammar spells it: the common case
            return shared
        found = cast(str, self.accept(text))
        if text.lower() != found.lower():  # a number MuJoCo reads as the keyword
            return found
        _check_spelling(text, found)
        return found


class FlagsCodec(Codec):
    """Keywords combined, stored as a tuple in the grammar's order; where the grammar allows,
    one keyword taken alone in place of them (``input="none"``), stored as that string.

    Python assignment takes any case and order (as dm_control does) and repeats; a file is
    read as MuJoCo reads it: as spelt, each keyword once, in the grammar's order if
    ``ordered``.
    """

    __slots__ = (
        "alone",
        "alone_lookup",
        "expected",
        "keywords",
        "listing",
        "lookup",
        "or_alone",
        "order",
        "ordered",
    )

    def __init__(self, keywords: tuple[str, ...], alone: tuple[str, ...] = (),
                 ordered: bool = False) -> None:
        self.keywords = keywords
        self.lookup = {k.lower(): k for k in keywords}
        self.order = {k: i for i, k in enumerate(keywords)}
        self.listing = ", ".join(repr(k) for k in keywords)
        self.alone = alone
        self.alone_lookup = {k.lower(): k for k in alone}
        self.ordered = ordered
        self.or_alone = f", or one of {', '.join(repr(k) for k in alone)} alone" if alone else ""
        self.expected = f"keywords from {self.listing}{self.or_alone}"

    def accept(self, value: object) -> object:
        words: list[object]
        if isinstance(value, str):
            words = list(value.split())
        elif isinstance(value, Iterable):
            words = list(cast(Iterable[object], value))
        else:
            raise _type_rejected(self.expected)
        found: set[str] = set()
        for word in words:
            if not isinstance(word, str):
                raise _type_rejected(self.expected)
            canonical = self.lookup.get(word.lower())
            if canonical is None:
                return self._alone(word, len(words))
            found.add(canonical)
        if not found:
            raise Rejected(f"at least one keyword from {self.listing}{self.or_alone}")
        # MuJoCo reads some flag sets only in their canonical order.
        return tuple(sorted(found, key=self.order.__getitem__))

    def _alone(self, word: str, count: int) -> str:
        """``word``, a keyword taken alone, as the whole value; else what was expected."""
        lone = self.alone_lookup.get(word.lower())
        if lone is None:
            raise Rejected(self.expected + did_you_mean(word, (*self.keywords, *self.alone)))
        if count > 1:
            raise Rejected(f"{lone!r} alone (it cannot be combined with other keywords), or "
                           f"keywords from {self.listing}")
        return lone

    def parse(self, text: str) -> object:
        found = self.accept(text)
        words = text.split()
        for word in words:
            key = word.lower()
            _check_spelling(word, self.lookup.get(key) or self.alone_lookup[key])
        if type(found) is str:
            return found
        flags = cast(tuple[str, ...], found)
        if len(words) != len(flags):
            repeated = next(w for i, w in enumerate(words) if w in words[:i])
            raise Rejected(f"each keyword once ({repeated!r} is repeated; MuJoCo refuses that)")
        if self.ordered and tuple(words) != flags:
            raise Rejected(f"{' '.join(flags)!r} (MuJoCo reads these keywords only in the order "
                           f"{', '.join(self.keywords)})")
        return flags

    def write(self, stored: object, fmt: Format) -> str:
        if type(stored) is str:  # a keyword alone
            return stored
        return " ".join(cast(tuple[str, ...], stored))


_SHARED: dict[tuple[object, ...], Codec] = {}


def make_codec(kind: str, *, dtype: str | None, is_array: bool, lo: int, hi: int | None,
               keywords: tuple[str, ...], pattern: str | None, alone: tuple[str, ...] = (),
               ordered: bool = False, numbers: tuple[tuple[str, int], ...] = ()) -> Codec:
    """The codec of an attribute (one object per distinct signature). ``alone`` and
    ``ordered`` concern flags: keywords also taken alone, and a file's order enforced;
    ``numbers``, keywords: the integer MuJoCo also reads for a keyword."""
    key = (kind, dtype, is_array, lo, hi, keywords, pattern, alone, ordered, numbers)
    codec = _SHARED.get(key)
    if codec is None:
        codec = _SHARED[key] = _new_codec(kind, dtype, is_array, lo, hi, keywords, pattern,
                                          alone, ordered, numbers)
    return codec


def _new_codec(kind: str, dtype: str | None, is_array: bool, lo: int, hi: int | None,
               keywords: tuple[str, ...], pattern: str | None, alone: tuple[str, ...],
               ordered: bool, numbers: tuple[tuple[str, int], ...] = ()) -> Codec:
    if is_array and kind in ("int", "real"):
        return ArrayCodec(kind, dtype or "double", lo, hi)
    if kind == "int":
        return IntCodec()
    if kind == "real":
        return RealCodec(dtype == "float")
    if kind == "bool":
        return BoolCodec()
    if kind == "keyword":
        return KeywordCodec(keywords, numbers)
    if kind == "flags":
        return FlagsCodec(keywords, alone, ordered)
    if kind == "id":
        return IdentifierCodec()
    if kind == "ref":
        return ReferenceCodec()
    if kind == "file":
        return FileCodec()
    if kind == "chars":
        return CharsCodec(pattern, lo, hi)
    return StringCodec(pattern)
