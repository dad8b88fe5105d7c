"""Size limits: bytes, depth and element count, counted over the assembled model, each
refused with a ParseError naming the limit, and each raisable with ParseLimits."""

from __future__ import annotations

import io
import os
import time
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf.io import ParseLimits


def nested_bodies(depth: int) -> str:
    return ("<mujoco><worldbody>" + "<body>" * depth + "<geom size='.1'/>" + "</body>" * depth
            + "</worldbody></mujoco>")


def test_defaults() -> None:
    limits = ParseLimits()
    assert (limits.max_bytes, limits.max_depth, limits.max_elements) == (
        64 * 1024 * 1024, 500, 1_000_000)


def test_5000_nested_bodies_are_refused_fast_naming_the_limit() -> None:
    start = time.perf_counter()
    with pytest.raises(mjcf.ParseError, match=r"line 1: .*nested.*ParseLimits\.max_depth") as info:
        mjcf.from_xml_string(nested_bodies(5000))
    assert time.perf_counter() - start < 1.0
    assert not isinstance(info.value.__cause__, RecursionError)
    # Raised above what the XML reader can do at all: still a clear refusal.
    with pytest.raises(mjcf.ParseError, match=r"more than 2048 deep"):
        mjcf.from_xml_string(nested_bodies(5000), limits=ParseLimits(max_depth=10_000))


def test_depth_limit_is_exact_and_raisable() -> None:
    # <mujoco> is 1 and <worldbody> 2: 497 bodies and their geom make 500.
    model = mjcf.from_xml_string(nested_bodies(497))
    xml = model.to_xml_string()  # deep models export (and read back) too
    assert mjcf.from_xml_string(xml).to_xml_string() == xml
    with pytest.raises(mjcf.ParseError, match=r"<geom> is nested 501 deep, more than the limit "
                                              r"of 500 \(ParseLimits.max_depth\)"):
        mjcf.from_xml_string(nested_bodies(498))
    assert len(mjcf.from_xml_string(nested_bodies(498), limits=ParseLimits(max_depth=501))
               .find_all("body")) == 498
    with pytest.raises(mjcf.ParseError, match=r"line 1: .*max_depth"):
        mjcf.from_xml_string(nested_bodies(10), limits=ParseLimits(max_depth=5))


def test_1500_nested_bodies_parse_when_the_limit_is_raised() -> None:
    """The tree is built without recursion."""
    model = mjcf.from_xml_string(nested_bodies(1500), limits=ParseLimits(max_depth=2000))
    assert len(model.worldbody.body) == 1
    element: mjcf.Element = model.worldbody.body[0]
    depth = 0
    while element.get_children("body"):
        element = element.get_children("body")[0]
        depth += 1
    assert depth == 1499


def test_1500_nested_bodies_export_and_read_back() -> None:
    limits = ParseLimits(max_depth=2000)
    xml = mjcf.from_xml_string(nested_bodies(1500), limits=limits).to_xml_string()
    assert mjcf.from_xml_string(xml, limits=limits).to_xml_string() == xml


def test_depth_counts_the_assembled_model(tmp_path: Path) -> None:
    (tmp_path / "deep.xml").write_text("<mujoco>" + "<body>" * 5 + "</body>" * 5 + "</mujoco>")
    (tmp_path / "main.xml").write_text(
        "<mujoco><worldbody><body><include file='deep.xml'/></body></worldbody></mujoco>")
    # mujoco, worldbody, body, then 5 included bodies: 8
    assert mjcf.from_path(tmp_path / "main.xml", limits=ParseLimits(max_depth=8))
    with pytest.raises(mjcf.ParseError, match=r"deep.xml:1: <body> is nested 8 deep.*"
                                              r"included from main.xml:1"):
        mjcf.from_path(tmp_path / "main.xml", limits=ParseLimits(max_depth=7))


def test_byte_limit(tmp_path: Path) -> None:
    xml = "<mujoco><worldbody>" + "<body/>" * 1000 + "</worldbody></mujoco>"
    with pytest.raises(mjcf.ParseError, match=r"ParseLimits.max_bytes"):
        mjcf.from_xml_string(xml, limits=ParseLimits(max_bytes=len(xml) - 1))
    assert mjcf.from_xml_string(xml, limits=ParseLimits(max_bytes=len(xml)))
    # Files are read no further than the limit, and includes count too.
    (tmp_path / "part.xml").write_text(xml)
    (tmp_path / "main.xml").write_text("<mujoco><include file='part.xml'/></mujoco>")
    main_size = os.path.getsize(tmp_path / "main.xml")
    with pytest.raises(mjcf.ParseError, match=r"part.xml.*max_bytes"):
        mjcf.from_path(tmp_path / "main.xml", limits=ParseLimits(max_bytes=len(xml)))
    assert mjcf.from_path(tmp_path / "main.xml",
                          limits=ParseLimits(max_bytes=len(xml) + main_size))
    with pytest.raises(mjcf.ParseError, match=r"max_bytes"):
        mjcf.from_file(io.StringIO(xml), limits=ParseLimits(max_bytes=100))


def test_element_limit(tmp_path: Path) -> None:
    xml = "<mujoco><worldbody>" + "<body/>" * 1000 + "</worldbody></mujoco>"
    with pytest.raises(mjcf.ParseError, match=r"line 1: .*more than the limit of 1001 "
                                              r"\(ParseLimits.max_elements\)"):
        mjcf.from_xml_string(xml, limits=ParseLimits(max_elements=1001))
    assert mjcf.from_xml_string(xml, limits=ParseLimits(max_elements=1002))
    (tmp_path / "part.xml").write_text(xml)
    (tmp_path / "main.xml").write_text("<mujoco><include file='part.xml'/></mujoco>")
    with pytest.raises(mjcf.ParseError, match=r"max_elements"):  # 2 + 1002
        mjcf.from_path(tmp_path / "main.xml", limits=ParseLimits(max_elements=1003))
    assert mjcf.from_path(tmp_path / "main.xml", limits=ParseLimits(max_elements=1004))
    # Each file alone is within the limit: the count over the assembled model is exact.
    bodies = "<body/>" * 600
    (tmp_path / "half.xml").write_text(f"<mujoco>{bodies}</mujoco>")
    (tmp_path / "both.xml").write_text(
        f"<mujoco><worldbody><include file='half.xml'/>{bodies}</worldbody></mujoco>")
    assert mjcf.from_path(tmp_path / "both.xml", limits=ParseLimits(max_elements=1204))
    with pytest.raises(mjcf.ParseError, match=r"both.xml:1: the model has more than 1203 "
                                              r"elements, more than the limit of 1203"):
        mjcf.from_path(tmp_path / "both.xml", limits=ParseLimits(max_elements=1203))


def test_special_files_are_not_read(tmp_path: Path) -> None:
    if not os.path.exists("/dev/zero"):
        pytest.skip("no /dev/zero")
    start = time.perf_counter()
    with pytest.raises(mjcf.ParseError, match="not a regular file"):
        mjcf.from_path("/dev/zero")
    anywhere = mjcf.FileAccess(anywhere=True)  # not refused as outside the folder first
    with pytest.raises(mjcf.ParseError, match="not a regular file"):
        mjcf.from_xml_string("<mujoco><include file='/dev/zero'/></mujoco>", files=anywhere)
    model = mjcf.from_xml_string("<mujoco><asset><mesh file='/dev/zero'/></asset></mujoco>",
                                 files=anywhere)
    with pytest.raises(mjcf.InvalidValueError, match="not a regular file"):
        model.get_assets()  # the files a model uses are read when it compiles or exports
    if hasattr(os, "mkfifo"):  # a FIFO would block a plain open()
        os.mkfifo(tmp_path / "fifo.xml")
        with pytest.raises(mjcf.ParseError, match="not a regular file"):
            mjcf.from_path(tmp_path / "fifo.xml")
        (tmp_path / "main.xml").write_text(
            "<mujoco><include file='fifo.xml'/><asset><mesh file='fifo.xml'/></asset></mujoco>")
        with pytest.raises(mjcf.ParseError, match="included file 'fifo.xml'.*not a regular"):
            mjcf.from_path(tmp_path / "main.xml")
        (tmp_path / "main.xml").write_text("<mujoco><asset><mesh file='fifo.xml'/></asset></mujoco>")
        with pytest.raises(mjcf.InvalidValueError, match="not a regular file"):
            mjcf.from_path(tmp_path / "main.xml").get_assets()
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize(("kwargs", "error"), [
    ({"max_depth": 0}, mjcf.InvalidValueError),
    ({"max_bytes": -1}, mjcf.InvalidValueError),
    ({"max_elements": 1.5}, mjcf.InvalidTypeError),
    ({"max_depth": True}, mjcf.InvalidTypeError),
])
def test_limits_are_validated(kwargs: dict[str, object], error: type[Exception]) -> None:
    with pytest.raises(error):
        ParseLimits(**kwargs)  # type: ignore[arg-type]


def test_limits_argument_is_checked() -> None:
    with pytest.raises(mjcf.InvalidTypeError, match="ParseLimits"):
        mjcf.from_xml_string("<mujoco/>", limits=1000)  # type: ignore[arg-type]
