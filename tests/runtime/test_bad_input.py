"""Bad input on the public routes raises the library's own error (what was expected, with the
element's path) in both builds: never a bare TypeError from a compiled signature, and a bool
is no int (the compiled build unboxes an ``int`` argument, so the check must see it first)."""

from __future__ import annotations

import re
from collections.abc import Callable

import pytest

import typed_mjcf as mjcf


def _body() -> mjcf.Body:
    return mjcf.RootElement(model="m").worldbody.add_body(name="b")


ROUTES: dict[str, tuple[Callable[[], object], type[mjcf.MjcfError], str]] = {
    "from_xml_string(None)": (lambda: mjcf.from_xml_string(None),  # type: ignore[arg-type]
                              mjcf.InvalidTypeError, "MJCF text must be str or bytes"),
    "ParseLimits(max_elements=1.5)": (lambda: mjcf.ParseLimits(max_elements=1.5),  # type: ignore[arg-type]
                                      mjcf.InvalidTypeError, "max_elements must be an int"),
    "ParseLimits(max_depth=True)": (lambda: mjcf.ParseLimits(max_depth=True),
                                    mjcf.InvalidTypeError, "max_depth must be an int"),
    "insert(position=1.5)": (lambda: _body().insert("geom", 1.5),  # type: ignore[call-overload]
                             mjcf.InvalidTypeError, "body[b]: insert() position must be an int"),
    "insert(position=True)": (lambda: _body().insert("geom", True),
                              mjcf.InvalidTypeError, "body[b]: insert() position must be an int"),
    "insert(3)": (lambda: _body().insert(3, 0),  # type: ignore[call-overload]
                  mjcf.InvalidTypeError, "body[b]: a child tag must be a string, got 3"),
    "add(3)": (lambda: _body().add(3),  # type: ignore[call-overload]
               mjcf.InvalidTypeError, "body[b]: a child tag must be a string, got 3"),
    "to_xml_string(precision='x')": (
        lambda: _body().to_xml_string(precision="x"),  # type: ignore[arg-type]
        mjcf.InvalidValueError, "precision must be a positive int"),
    "to_xml_string(zero_threshold='x')": (
        lambda: _body().to_xml_string(zero_threshold="x"),  # type: ignore[arg-type]
        mjcf.InvalidValueError, "zero_threshold must be a non-negative number"),
    "RootElement(model=3)": (lambda: mjcf.RootElement(model=3),  # type: ignore[arg-type]
                             mjcf.InvalidTypeError, "<root>: invalid model=3 on <mujoco>"),
}


@pytest.mark.parametrize("route", list(ROUTES))
def test_bad_input_raises_the_librarys_error(route: str) -> None:
    call, error, message = ROUTES[route]
    with pytest.raises(error, match=re.escape(message)):
        call()


def test_a_truthy_pretty_print_is_taken_as_in_python() -> None:
    body = _body()
    assert body.to_xml_string(pretty_print=1) == body.to_xml_string(pretty_print=True)  # type: ignore[arg-type]
