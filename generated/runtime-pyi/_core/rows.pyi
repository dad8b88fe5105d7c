# Generated from src/typed_mjcf/_core/rows.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
Arity = tuple[int, int | None]
Bound = tuple[str, float]
RELEASE: Final = {"release": True}

@dataclass(slots=True, eq=False, repr=False)
class AttributeRow:
    """One attribute of one grammar row, as the generated tables declare it."""
    name: str
    kind: Kind = field(metadata=RELEASE)
    _: KW_ONLY
    py_name: str = ""
    dtype: str | None = field(default=None, metadata=RELEASE)
    arity: Arity | None = field(default=None, metadata=RELEASE)
    keywords: tuple[str, ...] = field(default=(), metadata=RELEASE)
    numbers: tuple[tuple[str, int], ...] = field(default=(), metadata=RELEASE)
    alone: tuple[str, ...] = ...
    ordered: bool = False
    namespace: str | None = field(default=None, metadata=RELEASE)
    namespace_from: tuple[str, Mapping[str, str]] | None = None
    default: str | None = field(default=None, metadata=RELEASE)
    required: bool = False
    computed: bool = False
    pattern: str | None = None
    bounds: tuple[Bound, ...] = ...
    off: tuple[Bound, ...] = ...
    directory: tuple[str, ...] = ...
    anchor: str | None = None
    doc: str = ""
    scope: bool = False

class ReleaseType(NamedTuple):
    """One release's type of an attribute (the generated ``TYPES`` table's rows): the
    ``RELEASE`` fields of :class:`AttributeRow`, each with its type and default there."""
    kind: Kind
    dtype: str | None = None
    arity: Arity | None = None
    keywords: tuple[str, ...] = ...
    numbers: tuple[tuple[str, int], ...] = ...
    namespace: str | None = None
    default: str | None = None

def release_fields() -> tuple[str, ...]:
    """The fields of :class:`AttributeRow` a release may type otherwise, in order."""
    ...

def defaults() -> dict[str, object]:
    """Each field of :class:`AttributeRow` with a default, and that default."""
    ...

def release_type(row: AttributeRow) -> ReleaseType:
    """``row``'s ``RELEASE`` fields."""
    ...
