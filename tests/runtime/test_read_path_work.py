"""What reading a model costs beyond the XML: work that only a message needs is left for
the message (issue 38: parse + export of humanoid_CMU.xml got slower by doing it eagerly)."""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf._text.parse import has_long_stretch

from ..operations import lines_executed

BODY = "<mujoco><worldbody><body name='{name}'/></worldbody></mujoco>"


def _model(folder: Path, includes: int, blank_lines: int = 0) -> Path:
    """``main.xml`` in ``folder`` including ``includes`` files, after ``blank_lines`` lines."""
    folder.mkdir(parents=True, exist_ok=True)
    for k in range(includes):
        (folder / f"inc{k}.xml").write_text(BODY.format(name=f"b{k}"))
    main = folder / "main.xml"
    main.write_text("<mujoco>" + "\n" * blank_lines
                    + "".join(f"<include file='inc{k}.xml'/>\n" for k in range(includes))
                    + "</mujoco>")
    return main


def test_an_include_read_without_errors_does_not_index_the_lines_of_its_file(
        tmp_path: Path) -> None:
    """The line an <include> starts on is found when a message asks, not for every include
    (that indexed every line of the including file)."""
    short, long = _model(tmp_path / "short", 3, 10), _model(tmp_path / "long", 3, 5_000)
    for path in (short, long):
        mjcf.from_path(path)  # warm-up
    counted = ("_text.parse", "_core.tree", "_core.access", "_core.sourcelines", "_base", "io")
    more = lines_executed(lambda: mjcf.from_path(long), counted) - lines_executed(
        lambda: mjcf.from_path(short), counted)
    assert more < 100  # indexing was a few lines per line of main.xml: 15,000 more


def test_the_line_of_an_include_is_still_where_its_tag_starts(tmp_path: Path) -> None:
    main = tmp_path / "main.xml"
    main.write_text("<mujoco>\n\n<include\n  file='missing.xml'/>\n</mujoco>")
    with pytest.raises(mjcf.FileReadError, match=r"main.xml:3"):
        mjcf.from_path(main)
    (tmp_path / "inc.xml").write_text(BODY.format(name="a"))
    main.write_text("<mujoco>\n<include file='inc.xml'/>\n\n<include\n file='inc.xml'/>"
                    "</mujoco>")
    with pytest.raises(mjcf.ParseError, match=r"main.xml:4: .*already included by main.xml:2;"):
        mjcf.from_path(main)


def test_included_files_inside_the_model_folder_are_opened_without_resolving_links(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A path written inside the allowed folder is opened folder by folder refusing links;
    resolving it first (a stat per folder of the path, for every file) is needed only when a
    link is met."""
    deep = tmp_path.joinpath(*"abcdefgh")
    one, ten = _model(deep / "one", 1), _model(deep / "ten", 10)
    real_lstat = os.lstat
    stats: list[object] = []

    def counting_lstat(path: object, *args: object, **kwargs: object) -> os.stat_result:
        stats.append(path)
        return real_lstat(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(os, "lstat", counting_lstat)
    counts: list[int] = []
    for path in (one, ten):
        stats.clear()
        mjcf.from_path(path)
        counts.append(len(stats))
    assert counts[1] == counts[0], counts


def test_a_link_inside_the_model_folder_is_still_resolved_and_followed(tmp_path: Path) -> None:
    _model(tmp_path / "real", 1)
    (tmp_path / "alias").symlink_to(tmp_path / "real")
    (tmp_path / "main.xml").write_text("<mujoco><include file='alias/inc0.xml'/></mujoco>")
    assert mjcf.from_path(tmp_path / "main.xml").find("body", "b0") is not None


@pytest.mark.parametrize("text", [
    b"", b"<", b"a" * 5_000, b"<" * 5_000, b"<" + b"a" * 4_095, b"<" + b"a" * 4_096,
    b"a<" + b"a" * 4_096 + b"<", b"<" + b"a" * 4_095 + b"<" + b"a" * 4_096,
    b"<a/>" * 3_000 + b"<" + b"b" * 4_096 + b"<a/>" * 3_000,
    (b"<" + b"c" * 4_095) * 5, (b"<" + b"c" * 4_094) * 5 + b"<" + b"c" * 4_096,
])
def test_a_long_stretch_without_a_tag_start_is_found_as_the_pattern_finds_it(
        text: bytes) -> None:
    assert has_long_stretch(text) is (re.search(rb"<[^<]{4096}", text) is not None)
