"""An attribute's row, read from the IR and rendered from one declaration.

The declaration is :class:`typed_mjcf._core.rows.AttributeRow` (and its ``RELEASE`` fields,
:class:`~typed_mjcf._core.rows.ReleaseType`): its fields, their order and defaults are what
a generated ``A(...)`` or ``ReleaseType(...)`` call may say, and a call leaves a default out.
Nothing here lists the fields: :func:`call` renders any of them, and refuses a name the
declaration lacks. The module is loaded by its path (see ``codegen/runtime.py``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import TYPE_CHECKING

from codegen import ir
from codegen.runtime import core_module

if TYPE_CHECKING:
    from typed_mjcf._core import rows as declaration
else:  # the module alone, without the package's __init__ (see codegen/runtime.py)
    declaration = core_module("_core/rows")

AttributeRow = declaration.AttributeRow
ReleaseType = declaration.ReleaseType


def mismatch() -> str | None:
    """How ``ReleaseType`` differs from ``AttributeRow``'s ``RELEASE`` fields (their names,
    order and defaults), or None: the generator refuses to render while they differ."""
    release, defaults = declaration.release_fields(), declaration.defaults()
    if ReleaseType._fields != release:
        return f"ReleaseType's fields {ReleaseType._fields} are not AttributeRow's {release}"
    for name, default in ReleaseType._field_defaults.items():
        if defaults.get(name) != default:
            return (f"ReleaseType's default of {name} is {default!r}, AttributeRow's "
                    f"{defaults.get(name)!r}")
    return None


if (_MISMATCH := mismatch()) is not None:
    raise TypeError(f"typed_mjcf/_core/rows.py: {_MISMATCH}")


class Source(str):
    """A Python expression a call gives as it is (``get_args(Joint_type)``), not a value."""

    __slots__ = ()

    def __repr__(self) -> str:
        return str(self)


# Each shape's fields in order, each with its default (``MISSING``: none; given by position)
ROW: tuple[tuple[str, object], ...] = tuple(
    (f.name, f.default) for f in dataclasses.fields(AttributeRow) if f.init)
RELEASE: tuple[tuple[str, object], ...] = tuple(
    (name, ReleaseType._field_defaults.get(name, dataclasses.MISSING))
    for name in ReleaseType._fields)


def call(function: str, declared: tuple[tuple[str, object], ...],
         values: Mapping[str, object]) -> str:
    """``function(...)`` giving ``values`` as ``declared`` (:data:`ROW`, :data:`RELEASE`)
    says: a field without a default by position, the others by keyword unless equal to
    their default, in the declaration's order."""
    unknown = sorted(set(values) - {name for name, _ in declared})
    if unknown:
        raise ValueError(f"{function}(...) declares no field {unknown[0]!r}")
    args: list[str] = []
    for name, default in declared:
        if default is dataclasses.MISSING:
            args.append(repr(values[name]))
        elif name in values and values[name] != default:
            args.append(f"{name}={values[name]!r}")
    return f"{function}({', '.join(args)})"


def release_values(schema: ir.Schema, a: ir.AttributeDef) -> dict[str, object]:
    """``a``'s ``RELEASE`` fields as ``schema`` (one release's grammar) types it, those at
    their default left out: what a release may type otherwise."""
    values: dict[str, object] = {"kind": a.kind}
    if a.dtype is not None and a.dtype != ("int" if a.kind == "int" else "double"):
        values["dtype"] = a.dtype  # else the kind's (AttributeSpec fills it in)
    if a.arity is not None:
        values["arity"] = tuple(a.arity)
    words = keywords(schema, a)
    if words:
        values["keywords"] = words
    if a.numbers:
        values["numbers"] = tuple(a.numbers.items())
    if a.namespace is not None:
        values["namespace"] = a.namespace
    if a.default is not None:
        values["default"] = a.default
    assert set(values) <= set(ReleaseType._fields), sorted(values)
    return values


def keywords(schema: ir.Schema, a: ir.AttributeDef) -> tuple[str, ...]:
    """The keywords ``schema`` gives ``a`` (none for an attribute without an enum)."""
    if a.enum is None or a.enum not in schema.enums:
        return ()
    return tuple(schema.enums[a.enum].keywords)
