"""Everything the typed-mjcf generator reads from the installed ``mujoco`` wheel, as plain data.

The wheel is the authority on what the installed parser accepts:

* ``mujoco.mj_printSchema(False, False)``: the grammar tree (rows, child cardinalities,
  attribute names), parsed by :func:`parse_print_schema`;
* ``mujoco.introspect``: C enums and the field types of the ``mjs*`` structs;
* ``mujoco/doc/XMLreference.rst``: anchors and the ``:at-val:`` text of attribute entries,
  parsed by :func:`parse_reference` and typed by :func:`parse_at_val`;
* ``MjSpec().default``: the default values of the ``mjs*`` objects (:func:`spec_defaults`);
* the parser itself (``MjSpec.from_string``), which :mod:`codegen.probe` asks what the rows
  printSchema omits (``frame``, ``replicate``, ``worldbody``) take.

The parsers are pure functions of text so tests can feed them small snippets; the ``read_*``
functions are thin adapters over the installed module. ``mujoco`` ships no type information,
so every value crosses into typed code through a runtime check in this module.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from types import ModuleType
from typing import Literal, SupportsInt, cast

from codegen import ir
from codegen.probe import MujocoParser, Parser, SpecParser

# ----------------------------------------------------------------------- printSchema tree


@dataclass(frozen=True)
class WheelRow:
    """One row of ``mj_printSchema``: ``tag (card)`` and its attribute names, children nested."""

    tag: str  # as printed; ``(world)body`` serves both <worldbody> and <body>
    card: ir.Cardinality
    attributes: tuple[str, ...] = ()
    children: tuple[WheelRow, ...] = ()

    @property
    def spellings(self) -> tuple[str, ...]:
        """The XML tags this row stands for: ``(world)body`` -> ``("worldbody", "body")``."""
        match = re.fullmatch(r"\((\w+)\)(\w+)", self.tag)
        if match is None:
            return (self.tag,)
        return (match.group(1) + match.group(2), match.group(2))

    def child(self, tag: str) -> WheelRow | None:
        """The child row spelled ``tag`` (any spelling), if any."""
        return next((c for c in self.children if tag in c.spellings), None)

    def walk(self) -> Iterator[WheelRow]:
        """This row and its descendants, depth first."""
        yield self
        for c in self.children:
            yield from c.walk()


class PrintSchemaError(ValueError):
    """Text that is not ``mj_printSchema`` output; ``str()`` names the line."""


_ROW_RE = re.compile(r"(?P<indent> *)(?P<tag>\S+) \((?P<card>[!?*R])\)(?P<rest>.*)")
_CARDS: dict[str, ir.Cardinality] = {"!": "!", "?": "?", "*": "*", "R": "R"}


@dataclass
class _RowBuilder:
    indent: int
    tag: str
    card: ir.Cardinality
    attributes: list[str]
    children: list[_RowBuilder]

    def freeze(self) -> WheelRow:
        return WheelRow(self.tag, self.card, tuple(self.attributes),
                        tuple(c.freeze() for c in self.children))


def parse_print_schema(text: str) -> WheelRow:
    """Parse ``mj_printSchema(False, False)``: indented ``tag (card) attr attr ...`` rows whose
    attribute lists wrap onto continuation lines (lines without a ``(card)`` marker)."""
    stack: list[_RowBuilder] = []
    root: _RowBuilder | None = None
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        match = _ROW_RE.fullmatch(line.rstrip())
        if match is None:
            if not stack:
                raise PrintSchemaError(f"line {number}: attributes before the first row")
            stack[-1].attributes.extend(line.split())
            continue
        row = _RowBuilder(len(match["indent"]), match["tag"], _CARDS[match["card"]],
                          match["rest"].split(), [])
        while stack and stack[-1].indent >= row.indent:
            stack.pop()
        if stack:
            stack[-1].children.append(row)
        elif root is None:
            root = row
        else:
            raise PrintSchemaError(f"line {number}: second root row {row.tag!r}")
        stack.append(row)
    if root is None:
        raise PrintSchemaError("no rows")
    return root.freeze()


# --------------------------------------------------------------------- XMLreference.rst


@dataclass(frozen=True)
class RstEntry:
    """The attribute entry following one or more anchors.

    ``at_val`` is the text inside ``:at-val:`...``` (None when the entry has none, e.g. a
    shared ``:at:`a`, :at:`b``` entry); ``same_as`` is the element anchor a substituted
    ``|x attrib list|`` entry defers to ("Same as in :ref:`spatial <tendon-spatial>`")."""

    at_val: str | None = None
    same_as: str | None = None


@dataclass(frozen=True)
class Reference:
    """The anchors of ``XMLreference.rst`` (in document order), their attribute entries, and
    every attribute name the text spells (``:at:`name```, in entries and in prose)."""

    anchors: tuple[str, ...]
    entries: Mapping[str, RstEntry]
    names: frozenset[str] = frozenset()

    def __contains__(self, anchor: str) -> bool:
        return anchor in self._positions

    @cached_property
    def _positions(self) -> dict[str, int]:
        return {a: i for i, a in enumerate(self.anchors)}

    def position(self, anchor: str) -> int:
        """Document order of ``anchor`` (``len(anchors)`` when absent)."""
        return self._positions.get(anchor, len(self.anchors))

    def at_val(self, anchor: str, _depth: int = 0) -> str | None:
        """The ``:at-val:`` text documenting ``anchor``, following ``same_as`` deferrals."""
        entry = self.entries.get(anchor)
        if entry is None or _depth > 4:
            return None
        if entry.at_val is not None or entry.same_as is None:
            return entry.at_val
        attribute = anchor.rsplit("-", 1)[-1]
        return self.at_val(f"{entry.same_as}-{attribute}", _depth + 1)


_ANCHOR_RE = re.compile(r"\.\. _([\w.-]+):\s*")
_AT_VAL_RE = re.compile(r":at-val:`([^`]*)`")
_AT_NAME_RE = re.compile(r":at:`([A-Za-z_]\w*)`")
_SUBST_DEF_RE = re.compile(r"\.\. \|[^|]+\| replace::")
_SUBST_USE_RE = re.compile(r"\|[^|]+ attrib list\|\s*")
_REF_TARGET_RE = re.compile(r":ref:`[^`<]*<([\w.-]+)>`")


class _ReferenceReader:
    """Line scanner: anchors accumulate until the next entry or prose line consumes them."""

    def __init__(self, lines: list[str]) -> None:
        self.lines = lines
        self.anchors: list[str] = []
        self.entries: dict[str, RstEntry] = {}
        self.pending: list[str] = []

    def read(self) -> Reference:
        index = 0
        while index < len(self.lines):
            index = self._line(index)
        names = {m for line in self.lines for m in _AT_NAME_RE.findall(line)}
        return Reference(tuple(self.anchors), self.entries, frozenset(names))

    def _line(self, index: int) -> int:
        line = self.lines[index]
        anchor = _ANCHOR_RE.fullmatch(line)
        if anchor is not None:
            self.anchors.append(anchor.group(1))
            self.pending.append(anchor.group(1))
        elif _SUBST_DEF_RE.match(line):
            return self._skip_indented(index + 1)  # the definition of a substitution
        elif line.startswith(":at:"):
            at_val = _AT_VAL_RE.search(line)
            self._consume(RstEntry(at_val=at_val.group(1) if at_val else None))
        elif _SUBST_USE_RE.fullmatch(line):
            self._consume(RstEntry(same_as=self._same_as(index + 1)))
        elif line.strip():
            self.pending = []  # a heading or prose: the anchors named an element
        return index + 1

    def _consume(self, entry: RstEntry) -> None:
        for anchor in self.pending:
            self.entries[anchor] = entry
        self.pending = []

    def _skip_indented(self, index: int) -> int:
        while index < len(self.lines) and self.lines[index].startswith((" ", "\t")):
            index += 1
        return index

    def _same_as(self, index: int) -> str | None:
        """The first ``:ref:`` target of the indented paragraph after a substitution use."""
        end = self._skip_indented(index)
        match = _REF_TARGET_RE.search(" ".join(self.lines[index:end]))
        return match.group(1) if match else None


def parse_reference(text: str) -> Reference:
    """Anchors and attribute entries of ``XMLreference.rst`` text."""
    return _ReferenceReader(text.splitlines()).read()


# ------------------------------------------------------------------------- :at-val: types

AtValKind = Literal["real", "int", "bool", "keyword", "string"]


@dataclass(frozen=True)
class AtVal:
    """A typed ``:at-val:`` text: ``real(3), "0 0 0"`` -> real, arity (3, 3), default."""

    kind: AtValKind
    arity: tuple[int, int | None] | None = None  # None: scalar; (0, None): any number
    keywords: tuple[str, ...] = ()  # keyword kind only, in documented order
    default: str | None = None
    required: bool = False


_TYPE_RE = re.compile(r"(?P<base>real|int|string|bool)(?:\((?P<count>[^()]*(?:\([^()]*\))?"
                      r"[^()]*)\))?")
_KEYWORDS_RE = re.compile(r"\[(?P<body>[^\]]*)\]")
_KEYWORD_RE = re.compile(r"\w*[A-Za-z]\w*")
_SYMBOLIC_COUNT_RE = re.compile(r"[\w.*+()\s]+")
_NUMBER_RE = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_INT_RE = re.compile(r"-?\d+")


def parse_at_val(text: str) -> AtVal | None:
    """Type an ``:at-val:`` text, or None when it is not one of the documented forms.

    Forms: ``real``/``int`` with an optional count ``(3)``, ``(1 or 3)`` or a symbolic
    ``(3*nvert)`` (any number of values); ``bool``; ``string``; a keyword list ``[a, b]``
    (``[false, true]`` is bool). Then optionally ``, "default"``, ``, optional``,
    ``, required`` or ``, default = <prose>`` (a computed default)."""
    parts = _split_at_val(text.strip())
    if parts is None:
        return None
    base = _keywords(parts[0]) or _scalar_type(parts[0])
    return None if base is None else _with_tail(base, parts[1])


def _split_at_val(text: str) -> tuple[str, str] | None:
    """``type, tail`` at the first comma outside a keyword list."""
    end = text.find("]") + 1 if text.startswith("[") else 0
    head, comma, tail = text[end:].partition(",")
    head = text[:end] + head
    if end and head.strip() != text[:end]:
        return None  # text after the closing bracket
    return head.strip(), tail.strip() if comma else ""


def _keywords(head: str) -> AtVal | None:
    match = _KEYWORDS_RE.fullmatch(head)
    if match is None:
        return None
    words = tuple(w.strip() for w in match["body"].split(","))
    if len(words) < 2 or not all(_KEYWORD_RE.fullmatch(w) for w in words):
        return None
    if len(set(words)) != len(words):
        return None
    if set(words) == {"false", "true"}:
        return AtVal("bool")
    return AtVal("keyword", keywords=words)


def _scalar_type(head: str) -> AtVal | None:
    match = _TYPE_RE.fullmatch(head)
    if match is None:
        return None
    base, count = match["base"], match["count"]
    if count is None:
        return AtVal(cast(AtValKind, base))
    if base not in ("real", "int"):
        return None
    arity = _arity(count.strip())
    if arity is None:
        return None
    return AtVal(cast(AtValKind, base), arity=None if arity == (1, 1) else arity)


def _arity(count: str) -> tuple[int, int | None] | None:
    if count.isdigit():
        n = int(count)
        return (n, n) if n > 0 else None
    pair = re.fullmatch(r"(\d+) or (\d+)", count)
    if pair is not None:
        low, high = sorted((int(pair[1]), int(pair[2])))
        return (low, high) if low > 0 and low < high else None
    if _SYMBOLIC_COUNT_RE.fullmatch(count) and re.search(r"[A-Za-z]", count):
        return (0, None)  # a count given by the model: any number of values
    return None


def _with_tail(base: AtVal, tail: str) -> AtVal | None:
    if tail in ("", "optional"):
        return base
    if tail == "required":
        return AtVal(base.kind, base.arity, base.keywords, None, required=True)
    if tail.startswith("default ="):
        return base  # computed from the model; no literal default
    quoted = re.fullmatch(r'"([^"]*)"', tail)
    if quoted is None:
        return None
    default = quoted.group(1)
    if not _default_fits(base, default):
        return None
    if "..." in default.split():
        return base  # "0 0 ...": filled to the model's count; no literal default
    return AtVal(base.kind, base.arity, base.keywords, default)


def _default_fits(base: AtVal, default: str) -> bool:
    if base.kind == "bool":
        return default in ("false", "true")
    if base.kind == "keyword":
        return default in base.keywords
    if base.kind == "string":
        return True
    values = [v for v in default.split() if v != "..."]
    number = _INT_RE if base.kind == "int" else _NUMBER_RE
    if not values or not all(number.fullmatch(v) for v in values):
        return False
    high = base.arity[1] if base.arity is not None else 1
    # a documented default may be shorter than the arity (the rest is filled), never longer
    return high is None or len(values) <= high


# ------------------------------------------------------------------------ installed wheel

SpecValue = bool | int | float | str | tuple[float, ...]


@dataclass(frozen=True)
class Wheel:
    """What sync needs from a mujoco wheel; tests build synthetic ones."""

    version: str
    schema: WheelRow
    enums: Mapping[str, Mapping[str, int]] = field(
        default_factory=dict[str, Mapping[str, int]])
    reference: Reference = field(default_factory=lambda: Reference((), {}))
    # mjs struct -> field -> C type ("float", "double", "int", "mjtGeom", ...)
    structs: Mapping[str, Mapping[str, str]] = field(
        default_factory=dict[str, Mapping[str, str]])
    # loads MJCF text: sync asks it which attributes rows without a printSchema row take
    parser: Parser | None = None
    # loads MJCF text telling refusals from models it cannot compile: the drift probe's
    drift_parser: Parser | None = None


def _module(name: str) -> ModuleType:
    return importlib.import_module(name)


def _get(obj: object, name: str) -> object:
    value: object = getattr(obj, name)
    return value


def _mapping(value: object, what: str) -> dict[object, object]:
    if not isinstance(value, dict):
        raise TypeError(f"{what}: expected a dict, got {type(value).__name__}")
    return cast("dict[object, object]", value)


def read_version() -> str:
    version = _get(_module("mujoco"), "__version__")
    if not isinstance(version, str):
        raise TypeError("mujoco.__version__ is not a string")
    return version


def read_print_schema_text() -> str:
    print_schema = cast(Callable[[bool, bool], object], _get(_module("mujoco"), "mj_printSchema"))
    text = print_schema(False, False)
    if not isinstance(text, str):
        raise TypeError("mj_printSchema did not return text")
    return text


def read_print_schema() -> WheelRow:
    """The installed parser's grammar tree."""
    return parse_print_schema(read_print_schema_text())


def read_enums() -> dict[str, dict[str, int]]:
    """``mujoco.introspect.enums.ENUMS`` as ``{mjtX: {C constant: value}}``."""
    raw = _mapping(_get(_module("mujoco.introspect.enums"), "ENUMS"), "introspect ENUMS")
    out: dict[str, dict[str, int]] = {}
    for name, decl in raw.items():
        values = _mapping(_get(decl, "values"), f"enum {name}")
        out[str(name)] = {str(k): v for k, v in values.items() if isinstance(v, int)}
    return out


def read_structs() -> dict[str, dict[str, str]]:
    """``mujoco.introspect.structs.STRUCTS`` as ``{mjsX: {field: C type}}``."""
    raw = _mapping(_get(_module("mujoco.introspect.structs"), "STRUCTS"), "introspect STRUCTS")
    out: dict[str, dict[str, str]] = {}
    for name, decl in raw.items():
        fields = _get(decl, "fields")
        if isinstance(fields, tuple):
            out[str(name)] = {str(_get(f, "name")): _c_type(_get(f, "type"))
                              for f in cast("tuple[object, ...]", fields)
                              if hasattr(f, "name") and hasattr(f, "type")}
    return out


def _c_type(decl: object) -> str:
    """The element type of an introspect type: ``float rgba[4]`` -> ``float``."""
    inner: object = decl
    for _ in range(4):
        if not hasattr(inner, "inner_type"):
            break
        inner = _get(inner, "inner_type")
    name = _get(inner, "name") if hasattr(inner, "name") else str(inner)
    return str(name)


def reference_path() -> Path:
    return Path(str(_get(_module("mujoco"), "__file__"))).parent / "doc" / "XMLreference.rst"


def read_reference() -> Reference:
    """The installed ``doc/XMLreference.rst`` (an empty reference if the wheel lacks it)."""
    path = reference_path()
    if not path.exists():
        return Reference((), {})
    return parse_reference(path.read_text(encoding="utf-8"))


def read_wheel() -> Wheel:
    """Everything sync reads, from the installed ``mujoco``."""
    return Wheel(read_version(), read_print_schema(), read_enums(), read_reference(),
                 read_structs(), MujocoParser(), SpecParser())


# -------------------------------------------------------------------- MjSpec default objects


def _spec_value(value: object) -> SpecValue | None:
    """A plain value for a default-object field; None for methods and nested objects."""
    if isinstance(value, bool | int | float | str):
        return value
    if hasattr(value, "tolist") and hasattr(value, "shape"):
        items = _get(value, "tolist")
        listed = cast(Callable[[], object], items)()
        if isinstance(listed, list) and all(
                isinstance(x, int | float) for x in cast("list[object]", listed)):
            return tuple(float(cast(float, x)) for x in cast("list[object]", listed))
        return None
    if isinstance(value, SupportsInt) and type(value).__module__.startswith("mujoco"):
        return int(value)  # a C enum value
    return None


_VALUE_TYPES = frozenset({"double", "float", "int", "mjtNum", "mjtByte", "mjtBool", "mjtSize",
                          "mjDoubleVec", "mjFloatVec", "mjIntVec"})


def _value_field(c_type: str) -> bool:
    """A numeric or C-enum field (strings, pointers and nested structs are skipped: some of
    them are not readable on a detached default object)."""
    return c_type in _VALUE_TYPES or (c_type.startswith("mjt") and c_type not in _VALUE_TYPES)


def spec_defaults(structs: Mapping[str, Mapping[str, str]] | None = None,
                  ) -> dict[str, dict[str, SpecValue]]:
    """The numeric and enum fields of ``MjSpec().default.<kind>`` (joint, geom, ...), keyed by
    kind and C field name; enum values as their integers."""
    structs = read_structs() if structs is None else structs
    spec = cast(Callable[[], object], _get(_module("mujoco"), "MjSpec"))()
    default = _get(spec, "default")
    out: dict[str, dict[str, SpecValue]] = {}
    for kind in dir(default):
        fields = structs.get("mjs" + kind[:1].upper() + kind[1:])
        if kind.startswith("_") or fields is None:
            continue
        obj = _get(default, kind)
        values = {name: _spec_value(_get(obj, name)) for name, c_type in fields.items()
                  if _value_field(c_type) and hasattr(obj, name)}
        out[kind] = {k: v for k, v in values.items() if v is not None}
    del spec  # the default objects are views into the spec: keep it alive until here
    return out


def read_constants() -> dict[str, int]:
    """The integer ``mjN*`` size constants of the ``mujoco`` module (``mjNREF``: 2, ...)."""
    module = _module("mujoco")
    values = {name: _get(module, name) for name in dir(module) if name.startswith("mjN")}
    return {k: v for k, v in values.items() if isinstance(v, int) and not isinstance(v, bool)}
