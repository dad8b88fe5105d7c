"""<include>: resolved as MuJoCo resolves it, each file once, cycles and missing files
reported with the files (and lines) involved."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf


def write(folder: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text)


def test_cycle_is_reported_with_the_chain_of_files(tmp_path: Path) -> None:
    write(tmp_path, {
        "main.xml": "<mujoco>\n<include file='a.xml'/></mujoco>",
        "a.xml": "<mujoco>\n\n<include file='b.xml'/></mujoco>",
        "b.xml": "<mujoco><include file='a.xml'/></mujoco>",
    })
    with pytest.raises(mjcf.ParseError) as info:
        mjcf.from_path(tmp_path / "main.xml")
    message = str(info.value)
    assert message.startswith(f"{tmp_path / 'b.xml'}:1: include cycle: b.xml includes 'a.xml'")
    assert "main.xml -> a.xml -> b.xml -> a.xml" in message
    assert info.value.source == str(tmp_path / "b.xml") and info.value.line == 1


def test_a_file_including_itself_or_the_main_file(tmp_path: Path) -> None:
    write(tmp_path, {
        "self.xml": "<mujoco><include file='self.xml'/></mujoco>",
        "main.xml": "<mujoco><include file='c.xml'/></mujoco>",
        "c.xml": "<mujoco><include file='main.xml'/></mujoco>",
    })
    with pytest.raises(mjcf.ParseError, match=r"include cycle: .*self.xml -> self.xml"):
        mjcf.from_path(tmp_path / "self.xml")
    with pytest.raises(mjcf.ParseError, match=r"include cycle: .*main.xml -> c.xml -> main.xml"):
        mjcf.from_path(tmp_path / "main.xml")


def test_a_second_include_of_a_file_is_refused_naming_the_first(tmp_path: Path) -> None:
    write(tmp_path, {
        "main.xml": "<mujoco>\n<include file='parts/a.xml'/>\n<include file='b.xml'/></mujoco>",
        "parts/a.xml": "<mujoco><worldbody/></mujoco>",
        "b.xml": "<mujoco>\n\n<include file='parts/a.xml'/></mujoco>",
    })
    with pytest.raises(mjcf.ParseError) as info:
        mjcf.from_path(tmp_path / "main.xml")
    message = str(info.value)
    assert f"{tmp_path / 'b.xml'}:3: " in message
    assert "was already included by main.xml:2; MuJoCo includes a file at most once" in message
    assert "(in b.xml, included from main.xml:3)" in message
    with pytest.raises(ValueError):  # MuJoCo refuses it too
        mujoco.MjSpec.from_file(str(tmp_path / "main.xml"))


def test_missing_file_names_the_including_file_and_line(tmp_path: Path) -> None:
    write(tmp_path, {
        "main.xml": "<mujoco>\n<include file='sub/a.xml'/></mujoco>",
        "sub/a.xml": "<mujoco>\n\n\n<include file='nope.xml'/></mujoco>",
    })
    with pytest.raises(mjcf.ParseError) as info:
        mjcf.from_path(tmp_path / "main.xml")
    assert (info.value.source, info.value.line) == (str(tmp_path / "sub" / "a.xml"), 4)
    assert "cannot read included file 'nope.xml' (nope.xml): No such file" in str(info.value)
    assert "included from main.xml:2" in str(info.value)


def test_paths_resolve_against_the_main_file_folder_as_in_mujoco(tmp_path: Path) -> None:
    """An include inside an included file is relative to the main file's folder, not to
    the including file's folder (XMLreference.rst, include/file)."""
    body = "<mujoco><body name='{0}'><geom size='.1'/></body></mujoco>"
    write(tmp_path, {
        "main.xml": "<mujoco><worldbody><include file='sub/b.xml'/></worldbody></mujoco>",
        "sub/b.xml": "<mujoco><body name='b'><geom size='.1'/></body>"
                     "<include file='sub/c.xml'/></mujoco>",
        "sub/c.xml": body.format("c"),
        "sub/sub/c.xml": body.format("wrong"),  # where a path relative to b.xml would lead
    })
    compiled = mujoco.MjModel.from_xml_path(str(tmp_path / "main.xml"))
    assert (compiled.nbody, compiled.body("b").id, compiled.body("c").id) == (3, 1, 2)
    model = mjcf.from_path(tmp_path / "main.xml")
    assert [b.name for b in model.find_all("body")] == ["b", "c"]
    # The same from text, with the folder given.
    text = (tmp_path / "main.xml").read_text()
    model = mjcf.from_xml_string(text, base_dir=tmp_path)
    assert [b.name for b in model.find_all("body")] == ["b", "c"]


def test_errors_inside_included_files_name_the_file_line_and_chain(tmp_path: Path) -> None:
    write(tmp_path, {
        "main.xml": "<mujoco>\n<worldbody>\n<include file='a.xml'/></worldbody></mujoco>",
        "a.xml": "<mujoco>\n<body poss='1 2 3'/></mujoco>",
        "broken.xml": "<mujoco>\n<body></mujoco>",
        "uses_broken.xml": "<mujoco><include file='broken.xml'/></mujoco>",
    })
    with pytest.raises(mjcf.ParseError, match=r"a.xml:2: worldbody/body\[0\]: <body> has no attribute 'poss'.*"
                                              r"\(in a.xml, included from main.xml:3\)"):
        mjcf.from_path(tmp_path / "main.xml")
    with pytest.raises(mjcf.ParseError, match=r"broken.xml:2: malformed XML"):
        mjcf.from_path(tmp_path / "uses_broken.xml")


def test_include_takes_only_a_file(tmp_path: Path) -> None:
    write(tmp_path, {"a.xml": "<mujoco/>"})
    for xml, pattern in [
        ("<mujoco>\n<include/></mujoco>", r"line 2: <include> needs a file attribute"),
        ("<mujoco><include file='a.xml' dir='x'/></mujoco>", r"not attribute 'dir'"),
        ("<mujoco><include file='a.xml'><body/></include></mujoco>", r"not children"),
        ("<mujoco><include file='.'/></mujoco>", r"cannot read included file '\.'.*folder"),
    ]:
        with pytest.raises(mjcf.ParseError, match=pattern):
            mjcf.from_xml_string(xml, base_dir=tmp_path)
