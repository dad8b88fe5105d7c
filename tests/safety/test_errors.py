"""Every failure while reading is the library's own error, with a line where there is one:
never a raw lxml error, KeyError, IndexError, RecursionError, UnicodeDecodeError or OSError."""

from __future__ import annotations

import io
from collections.abc import Callable
from pathlib import Path
from typing import IO

import pytest

import typed_mjcf as mjcf
from tests.compiled import patches
from typed_mjcf._text import parse as _parse  # pyright: ignore[reportPrivateUsage]

from ..operations import growth

MALFORMED: list[tuple[str | bytes, str]] = [
    ("", r"line 1: malformed XML: Document is empty"),
    ("<mujoco>\n<worldbody>\n<body>\n</worldbody></mujoco>", r"line 4: malformed XML"),
    ("<mujoco>\n\n<worldbody a='1' a='2'/></mujoco>", r"line 3: malformed XML: Attribute a redefined"),
    ("<mujoco/>\n<mujoco/>", r"line 2: malformed XML: Extra content"),
    ("<mujoco model='\x01'/>", r"line 1: malformed XML"),
    ("\n\n<mujoco>\n<worldbody>\n&undefined;</worldbody></mujoco>", r"line 5: malformed XML: Entity 'undefined' not defined"),
    (b"<mujoco model='\xff\xfe'/>", r"line 1: malformed XML: Invalid bytes in character encoding"),
    (b"<?xml version='1.0' encoding='no-such-encoding'?><mujoco/>", r"line 1: malformed XML: Unsupported encoding"),
    ("<mujoco model='\udc80'/>", r"line 1: the text holds a character that is not valid Unicode"),
    ("<mujoco>\n<worldbody><bodyy/></worldbody></mujoco>", r"line 2: <bodyy> is not a legal child"),
    ("<mujoco>\n<x:worldbody xmlns:x='u'/></mujoco>", r"line 2: <\{u\}worldbody> is not a legal child"),
    ("<mujoco>\n<option timestep='fast'/></mujoco>", r"line 2: .*timestep"),
    ("<mujoco>\n<compiler angle='gradians'/></mujoco>", r"line 2: .*angle"),
    ("<mujoco>\n<worldbody><geom size='1 2 3 4'/></worldbody></mujoco>", r"line 2: .*expected 1 to 3 numbers"),
    ("<mujoco>\n<worldbody><joint range='1 2 3'/></worldbody></mujoco>", r"line 2: "),
    ("<mujoco>\n<worldbody/>\n<worldbody name='w'/></mujoco>", r"line 3: worldbody: <worldbody> has no attribute 'name'"),
    ("<robot/>", r"line 1: the root element is <robot>"),
    ("<mujoco\n>\x00</mujoco>", r"line 2: malformed XML"),
]


@pytest.mark.parametrize(("xml", "pattern"), MALFORMED)
def test_malformed_text_is_a_parse_error_with_a_line(xml: str | bytes, pattern: str) -> None:
    with pytest.raises(mjcf.ParseError, match=pattern) as info:
        mjcf.from_xml_string(xml)
    assert info.value.line is not None
    assert info.value.__cause__ is None


def test_parse_error_is_a_value_error_with_source_and_line() -> None:
    with pytest.raises(ValueError) as info:
        mjcf.from_xml_string("<mujoco>\n<bad/></mujoco>", source="robot.xml")
    assert isinstance(info.value, mjcf.ParseError)
    assert (info.value.source, info.value.line) == ("robot.xml", 2)
    assert str(info.value).startswith("robot.xml:2: <bad>")


def test_encodings_are_read_as_declared() -> None:
    text = '<?xml version="1.0" encoding="{}"?><mujoco model="\u00e9t\u00e9"/>'
    assert mjcf.from_xml_string(text.format("UTF-16").encode("utf-16")).model == "\u00e9t\u00e9"
    assert mjcf.from_xml_string(text.format("ISO-8859-1").encode("latin-1")).model == "\u00e9t\u00e9"
    # A str is text already: its declaration is not applied a second time.
    assert mjcf.from_xml_string(text.format("ISO-8859-1")).model == "\u00e9t\u00e9"
    assert mjcf.from_xml_string(b"\xef\xbb\xbf<mujoco model='bom'/>").model == "bom"


@pytest.mark.parametrize("value", [None, 12, ["<mujoco/>"]])
def test_text_of_the_wrong_type_is_a_type_error(value: object) -> None:
    with pytest.raises(mjcf.InvalidTypeError):
        mjcf.from_xml_string(value)  # type: ignore[arg-type]


def test_file_errors_are_parse_errors(tmp_path: Path) -> None:
    with pytest.raises(mjcf.ParseError, match=r"nope.xml: cannot read the file: No such file"):
        mjcf.from_path(tmp_path / "nope.xml")
    with pytest.raises(mjcf.ParseError, match=r"cannot read the file: it is a folder"):
        mjcf.from_path(tmp_path)
    # operating-system refusals that hold for every user, root included (CI runs as root)
    file = tmp_path / "file.xml"
    file.write_text("<mujoco/>")
    with pytest.raises(mjcf.FileReadError, match=r"child.xml: cannot read the file: Not a "
                                                 r"directory"):
        mjcf.from_path(file / "child.xml")
    with pytest.raises(mjcf.FileReadError, match=r"cannot read the file: File name too long"):
        mjcf.from_path(tmp_path / ("x" * 300 + ".xml"))


def test_a_file_without_read_permission_is_a_parse_error(tmp_path: Path) -> None:
    unreadable = tmp_path / "locked.xml"
    unreadable.write_text("<mujoco/>")
    unreadable.chmod(0)
    try:
        if _can_read(unreadable):
            pytest.skip("this user reads files whatever their permissions (root): "
                        "test_file_errors_are_parse_errors covers refusals root gets too")
        with pytest.raises(mjcf.FileReadError, match=r"Permission denied"):
            mjcf.from_path(unreadable)
    finally:
        unreadable.chmod(0o644)


def _can_read(path: Path) -> bool:
    try:
        path.read_bytes()
    except OSError:
        return False
    return True


class _Broken(io.RawIOBase):
    name = "broken.xml"

    def read(self, size: int | None = -1) -> bytes:
        raise OSError(5, "Input/output error")


def test_from_file_errors_are_parse_errors() -> None:
    with pytest.raises(mjcf.ParseError, match=r"broken.xml: cannot read the file: .*Input/output"):
        mjcf.from_file(_Broken())  # type: ignore[arg-type]
    undecodable: IO[str] = io.TextIOWrapper(io.BytesIO(b"<mujoco model='\xff'/>"), encoding="utf-8")
    with pytest.raises(mjcf.ParseError, match=r"cannot read the file: 'utf-8' codec"):
        mjcf.from_file(undecodable)
    with pytest.raises(mjcf.InvalidTypeError):
        mjcf.from_file(object())  # type: ignore[arg-type]
    with pytest.raises(mjcf.InvalidTypeError):
        mjcf.from_path(3)  # type: ignore[arg-type]
    with pytest.raises(mjcf.InvalidTypeError):
        mjcf.from_xml_string("<mujoco/>", base_dir=3)  # type: ignore[arg-type]


@patches("_text.parse")
def test_unexpected_exceptions_become_parse_errors(monkeypatch: pytest.MonkeyPatch) -> None:
    """A bug (here a KeyError planted in the builder) still surfaces as the library's error,
    with the original exception as its cause."""
    def broken(*args: object) -> None:
        raise KeyError("planted")

    monkeypatch.setattr(_parse, "_set_attributes", broken)
    with pytest.raises(mjcf.ParseError, match=r"internal error .*KeyError") as info:
        mjcf.from_xml_string("<mujoco model='m'/>")
    assert isinstance(info.value.__cause__, KeyError)

    def recursive(*args: object) -> None:
        raise RecursionError("maximum recursion depth exceeded")

    monkeypatch.setattr(_parse, "_set_attributes", recursive)
    with pytest.raises(mjcf.ParseError, match=r"too deeply nested"):
        mjcf.from_xml_string("<mujoco model='m'/>")


def _defaults(n_classes: int, n_repeats: int, extra: str = "") -> str:
    classes = "".join(f"<default class='c{i}'><geom size='1'/></default>"
                      for i in range(n_classes))
    repeats = "".join(f"<default><geom size='{i % 2 + 2}'/></default>" for i in range(n_repeats))
    return f"<mujoco>\n<default>{classes}{extra}</default>\n{repeats}</mujoco>"


def test_repeated_default_sections_merge_or_are_refused_clearly() -> None:
    # Every class sets the size itself: the later main size does not matter to them.
    assert len(mjcf.from_xml_string(_defaults(2, 2)).default.default) == 2
    # Class 'z' would inherit the later main size after merging, but not in MuJoCo.
    with pytest.raises(mjcf.ParseError, match=r"line 3: this repeated <default> section sets "
                                              r"<geom size>.*class 'z'"):
        mjcf.from_xml_string(_defaults(2, 1, "<default class='z'/>"))
    # A nested class inherits its parent's size.
    nested = "<default class='p'><geom size='1'/><default class='q'/></default>"
    assert mjcf.from_xml_string(_defaults(0, 1, nested)).find("default", "q") is not None
    # Same value again: nothing changes.
    same = "<mujoco><default><geom size='2'/><default class='a'/></default>" \
           "<default><geom size='2'/></default></mujoco>"
    assert mjcf.from_xml_string(same).find("default", "a") is not None
    # Classes of a repeated section are earlier classes for the next one.
    later = "<mujoco><default/><default><default class='b'/></default>" \
            "<default><geom size='3'/></default></mujoco>"
    with pytest.raises(mjcf.ParseError, match=r"class 'b'"):
        mjcf.from_xml_string(later)


def test_repeated_default_sections_take_linear_work() -> None:
    """Was quadratic (30 s for 3000 classes and 3000 repeated sections): 8x the sections,
    about 8x the Python lines executed (counted, not timed: tests/bench/scaling.py reports
    the time)."""
    def parsing(n: int) -> Callable[[], object]:
        xml = _defaults(n, n)
        return lambda: mjcf.from_xml_string(xml)

    ratio = growth(parsing, 100, 800, counted=("_text.parse", "_core.tree"))
    assert ratio < 8 * 1.25, ratio
