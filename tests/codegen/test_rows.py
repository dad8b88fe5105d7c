"""An attribute's row has one declaration (``typed_mjcf._core.rows``): the generator renders
``A(...)`` and the releases' ``ReleaseType(...)`` from it, the runtime's AttributeSpec is one,
and the release table's rows are its named tuple (issue 37 item 5)."""

from __future__ import annotations

import dataclasses

import pytest

from codegen import ir, releases, rows
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.rows import AttributeRow, ReleaseType, release_fields, release_type
from typed_mjcf._generated.releases import TYPES


def test_the_release_row_is_the_attribute_row_s_release_fields() -> None:
    assert rows.mismatch() is None
    assert ReleaseType._fields == release_fields()
    assert [name for name, _ in rows.RELEASE] == [name for name, _ in rows.ROW
                                                  if name in ReleaseType._fields]


def test_a_call_follows_the_declaration() -> None:
    """Positional where the field has no default, keywords in the declaration's order,
    defaults left out, an expression given as it is; a field not declared is refused."""
    values: dict[str, object] = {"doc": "", "arity": (3, 3), "kind": "real", "name": "pos",
                                 "keywords": rows.Source("get_args(X)"), "required": False}
    assert rows.call("A", rows.ROW, values) == "A('pos', 'real', arity=(3, 3), " \
                                               "keywords=get_args(X))"
    assert rows.call("ReleaseType", rows.RELEASE, {"kind": "int", "default": "1"}) == \
        "ReleaseType('int', default='1')"
    with pytest.raises(ValueError, match="no field 'colour'"):
        rows.call("A", rows.ROW, {**values, "colour": "red"})


def test_an_attribute_spec_is_its_row() -> None:
    """The runtime's spec of an attribute holds every field of the row, and its release
    type is read from them by name."""
    spec = AttributeSpec("pos", "real", arity=(3, 3), default="0 0 0")
    assert isinstance(spec, AttributeRow)
    assert {f.name for f in dataclasses.fields(AttributeRow)} <= {
        f.name for f in dataclasses.fields(spec)}
    assert release_type(spec) == ReleaseType("real", "double", (3, 3), default="0 0 0")
    assert (spec.lo, spec.hi, spec.is_array, spec.py_name) == (3, 3, True, "pos")


def test_the_release_table_rows_are_named() -> None:
    newest = ir.load()
    for row, attributes in TYPES.items():
        for name, by_release in attributes.items():
            for typed in by_release.values():
                assert isinstance(typed, ReleaseType), (row, name, typed)
    headlight = newest.elements["headlight"].attribute("active")
    typed = releases.type_row(releases.type_fields(newest, headlight))
    assert (typed.kind, typed.default) == (headlight.kind, headlight.default)
