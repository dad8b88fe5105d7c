"""The shape of an attribute's row: the one declaration of what the generated tables say
about an attribute (``A(...)``) and what one release may type otherwise (``TYPES``).

:class:`AttributeRow`'s fields are the keyword arguments of a generated ``A(...)`` call, with
their types and defaults (a call leaves a default out); those marked ``RELEASE`` are also
the fields of :class:`ReleaseType`, one release's type of an attribute where it is not the
newest's. The generator reads this declaration to write both tables
(``codegen/rows.py``), the runtime's :class:`~typed_mjcf._core.grammar.AttributeSpec` is an
``AttributeRow`` with what it derives, and the release layer retypes an attribute by
replacing its ``RELEASE`` fields: a new fact is a field here, its value in the generator's
reading of the IR and its use in a feature. This module imports nothing from the package:
the generator loads it by its path (as ``_core/language.py``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import KW_ONLY, MISSING, dataclass, field, fields
from typing import Final, Literal, NamedTuple

Kind = Literal["string", "file", "chars", "bool", "int", "real", "keyword", "flags", "id", "ref"]
Arity = tuple[int, int | None]  # fixed (n, n), or a range (lo, hi; None: unbounded)
Bound = tuple[str, float]  # (">", 0.0), (">=", -1.0), ...
# A field with this metadata is one a release may type otherwise (a field of ReleaseType).
RELEASE: Final = {"release": True}


@dataclass(slots=True, eq=False, repr=False)
class AttributeRow:
    """One attribute of one grammar row, as the generated tables declare it."""

    name: str  # the XML name
    kind: Kind = field(metadata=RELEASE)
    _: KW_ONLY
    py_name: str = ""  # the Python name, where not the XML name
    dtype: str | None = field(default=None, metadata=RELEASE)  # numbers, if not the kind's
    # numbers: how many (None: one value); chars: how many characters
    arity: Arity | None = field(default=None, metadata=RELEASE)
    keywords: tuple[str, ...] = field(default=(), metadata=RELEASE)
    # keywords: the integer MuJoCo also reads for each
    numbers: tuple[tuple[str, int], ...] = field(default=(), metadata=RELEASE)
    alone: tuple[str, ...] = ()  # flags: keywords also taken, one alone in place of the flags
    ordered: bool = False  # flags: read from files only in the order of ``keywords``
    namespace: str | None = field(default=None, metadata=RELEASE)  # id, ref
    # objname-like references: the attribute whose keyword names the namespace, and the map
    # from its keywords to namespaces
    namespace_from: tuple[str, Mapping[str, str]] | None = None
    default: str | None = field(default=None, metadata=RELEASE)  # MJCF text
    required: bool = False
    computed: bool = False  # no default: MuJoCo computes the value when it is absent
    pattern: str | None = None  # a regex a string value must match
    # every value keeps these, or MuJoCo refuses the model (validate() checks them)
    bounds: tuple[Bound, ...] = ()
    off: tuple[Bound, ...] = ()  # a value keeping all of these counts as not set
    directory: tuple[str, ...] = ()  # <compiler> attributes naming the folder of files
    anchor: str | None = None  # XMLreference.rst's, where not the row's anchor + name
    doc: str = ""
    scope: bool = False  # the root's model name: the scope of the model when attached


class ReleaseType(NamedTuple):
    """One release's type of an attribute (the generated ``TYPES`` table's rows): the
    ``RELEASE`` fields of :class:`AttributeRow`, each with its type and default there."""

    kind: Kind
    dtype: str | None = None
    arity: Arity | None = None
    keywords: tuple[str, ...] = ()
    numbers: tuple[tuple[str, int], ...] = ()
    namespace: str | None = None
    default: str | None = None


def release_fields() -> tuple[str, ...]:
    """The fields of :class:`AttributeRow` a release may type otherwise, in order."""
    return tuple(f.name for f in fields(AttributeRow) if f.metadata.get("release"))


def defaults() -> dict[str, object]:
    """Each field of :class:`AttributeRow` with a default, and that default."""
    return {f.name: f.default for f in fields(AttributeRow) if f.default is not MISSING}


def release_type(row: AttributeRow) -> ReleaseType:
    """``row``'s ``RELEASE`` fields."""
    return ReleaseType._make(getattr(row, name) for name in ReleaseType._fields)

