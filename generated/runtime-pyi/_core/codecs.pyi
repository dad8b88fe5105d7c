# Generated from src/typed_mjcf/_core/codecs.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import Final, SupportsFloat, SupportsIndex, cast
import numpy as np
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, MjcfError, did_you_mean
Array = np.ndarray[tuple[int, ...], np.dtype[np.generic]]
Float64Array = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
Float32Array = np.ndarray[tuple[int, ...], np.dtype[np.float32]]
INT32_MIN: Final = -(2**31)
INT32_MAX: Final = 2**31 - 1
DTYPES: Final[dict[str, type[np.generic]]] = ...
_DOUBLE = r"[-+]?(?:\d{1,200}(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d{1,2})?"
_FLOAT = r"[-+]?(?:\d{1,20}(?:\.\d*)?|\.\d+)(?:[eE](?:-\d{1,2}|\+?\d))?"
_INTEGER = r"[-+]?\d{1,9}"
FLOAT32_MAX: Final = float(np.finfo(np.float32).max)
FLOAT32_RANGE: Final = f"within the range of a float32 (magnitude at most {FLOAT32_MAX:.8g})"

def checked_texts() -> dict[str, str]:
    """A new, empty table of checked texts for a codec (each text to itself)."""
    ...

def remember(checked: dict[str, str], text: str) -> None:
    """Note that ``text`` passed a codec's check (if there is room, and it is short)."""
    ...

class Rejected(Exception):
    """A value the attribute cannot take, with what it expected."""
    def __init__(self, expected: str, error: type[MjcfError] = InvalidValueError) -> None:
        super().__init__(expected)
        self.expected = expected
        self.error = error
DEFAULT_PRECISION: int | None = None

def real_text(values: Sequence[float], single: bool = False, precision: int | None = None) -> str:
    """Real numbers as MJCF text, space-separated: the one spelling of a float every writer
    uses (one number is a sequence of one). With ``precision``, that many significant digits;
    else the shortest text that reads back exactly (as a float32 when ``single``), without a
    trailing ``.0``."""
    ...

class Format:
    """Export options, applied by every codec the same way. ``precision=None`` is the
    library's default (:data:`DEFAULT_PRECISION`), read when a number is written."""
    precision: int | None
    zero_threshold: float
    canonical: bool
    def __init__(self, precision: object = None, zero_threshold: object = 0.0,
                 canonical: bool = False) -> None: ...
    @property
    def digits(self) -> int | None:
        """The precision numbers are written with (``None``: shortest round-trip form)."""
        ...
    @property
    def keeps_source_text(self) -> bool:
        """Whether numbers read from a file are written as they were read: nothing asks
        for them to be reformatted."""
        ...
    def number(self, x: float, single: bool = False) -> str:
        """One number (of a float32 when ``single``), as :func:`real_text` spells it."""
        ...
    def numbers(self, values: Sequence[float], single: bool = False) -> str:
        """Numbers, space-separated, as :func:`real_text` spells them with these options."""
        ...
DEFAULT_FORMAT: Final = Format()

class Codec:
    """Text in, Python value in, text out, for one kind of attribute."""
    lazy: bool = False
    def accept(self, value: object) -> object:
        """A value given in Python, as stored; raises :class:`Rejected`."""
        ...
    def parse(self, text: str) -> object:
        """Text read from a file, as stored (possibly that text, checked); raises
        :class:`Rejected`."""
        ...
    def read(self, stored: object) -> object:
        """What a property returns for a stored value."""
        ...
    keeps_read_text: bool = True
    def write(self, stored: object, fmt: Format) -> str:
        """The stored value as attribute text; a text stored as read, as it was read when
        ``fmt.keeps_source_text`` and :attr:`keeps_read_text`."""
        ...

def check_xml_text(value: str, what: str = "text") -> None:
    """Refuse a string that XML cannot hold; ``what`` names what was expected."""
    ...

class StringCodec(Codec):
    def __init__(self, pattern: str | None) -> None:
        self.pattern = None if pattern is None else re.compile(pattern)
    def accept(self, value: object) -> object: ...

class CharsCodec(StringCodec):
    def __init__(self, pattern: str | None, lo: int, hi: int | None) -> None:
        super().__init__(pattern)
        self.lo, self.hi = lo, hi
    def accept(self, value: object) -> object: ...

class IdentifierCodec(Codec):
    """A name: from Python without ``/`` (it separates the scopes of attached models); from
    files as written (MuJoCo accepts ``/`` in names and real models use it)."""
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...

class ReferenceCodec(Codec):
    """A name of another element, as text (the tree stores element links itself)."""
    def accept(self, value: object) -> object: ...

class FileCodec(Codec):
    def accept(self, value: object) -> object: ...

class BoolCodec(Codec):
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...
    def write(self, stored: object, fmt: Format) -> str: ...

def to_int(value: object) -> int:
    """An integer attribute's value, refusing what would be truncated or overflow."""
    ...

def to_float(value: object) -> float:
    """A real attribute's value."""
    ...

def text_to_float(text: str) -> float:
    """A number spelled as MuJoCo reads one (C's strtod): hexadecimal too, but no '_'
    separators or non-ASCII digits (which Python's float takes), and nothing too large for a
    double."""
    ...

def check_float32(value: float) -> None:
    """Refuse a finite number too large for a float32 (MuJoCo: "number is too large"); an
    infinity reaches here only spelled as one (:func:`text_to_float`), and is kept."""
    ...

def refuse_underflow(note: str | None) -> None:
    """Refuse numbers that underflow, saying ``note`` (why), or read them (``None``)."""
    ...

def underflows(text: str | None, value: float, single: bool) -> bool:
    """Whether ``value`` (read from ``text``, or given in Python: None) underflows its type:
    subnormal, or zero though the text is not. MuJoCo's strtod/strtof refuse such a text
    unless it is exact (0x1p-1074): those are refused too, since an export writes the value
    in decimal (5e-324), which the releases refusing underflow do not read."""
    ...

def check_underflow(what: str, texts: Sequence[str] | None, values: Sequence[float],
                    single: bool) -> None:
    """Refuse ``values`` (read from ``texts``, or given in Python) if one underflows and the
    release in use refuses that; ``what`` is what the codec expects."""
    ...

class IntCodec(Codec):
    def accept(self, value: object) -> object: ...
    def write(self, stored: object, fmt: Format) -> str: ...

class RealCodec(Codec):
    """One number. Text from a file is checked by converting it, and kept."""
    lazy = True
    def __init__(self, single: bool) -> None:
        self.single = single
        self.checked = checked_texts()
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...
    def read(self, stored: object) -> object: ...
    def write(self, stored: object, fmt: Format) -> str: ...

def count_text(lo: int, hi: int | None) -> str: ...

class ArrayCodec(Codec):
    """A list of numbers of a fixed or bounded length, stored as a read-only numpy array."""
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
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...
    def read(self, stored: object) -> object:
        """A read-only array: changes go through assignment (and its checks)."""
        ...
    def write(self, stored: object, fmt: Format) -> str: ...
    def from_text(self, text: str) -> Array: ...

class KeywordCodec(Codec):
    """One keyword, stored as the grammar spells it. Where MuJoCo's reader also takes a
    keyword's integer (``numbers``: ``<headlight active="1">``), so do parsing and assignment,
    and the keyword is stored: export writes that canonical spelling, which MuJoCo reads
    the same."""
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
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...

class FlagsCodec(Codec):
    """Keywords combined, stored as a tuple in the grammar's order; where the grammar allows,
    one keyword taken alone in place of them (``input="none"``), stored as that string.

    Python assignment takes any case and order (as dm_control does) and repeats; a file is
    read as MuJoCo reads it: as spelt, each keyword once, in the grammar's order if
    ``ordered``.
    """
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
    def accept(self, value: object) -> object: ...
    def parse(self, text: str) -> object: ...
    def write(self, stored: object, fmt: Format) -> str: ...

def make_codec(kind: str, *, dtype: str | None, is_array: bool, lo: int, hi: int | None,
               keywords: tuple[str, ...], pattern: str | None, alone: tuple[str, ...] = (),
               ordered: bool = False, numbers: tuple[tuple[str, int], ...] = ()) -> Codec:
    """The codec of an attribute (one object per distinct signature). ``alone`` and
    ``ordered`` concern flags: keywords also taken alone, and a file's order enforced;
    ``numbers``, keywords: the integer MuJoCo also reads for a keyword."""
    ...
