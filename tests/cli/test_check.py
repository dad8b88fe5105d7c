"""``typed-mjcf check``: every finding at the file and line of its element, as text or JSON,
with exit codes CI can use."""

from __future__ import annotations

import io
import json
from pathlib import Path
from typing import cast

import pytest
from pytest import approx

import typed_mjcf as mjcf
from tests.support.ignored_attributes import MODEL as IGNORED
from typed_mjcf._text.parse import ParseOptions, Problem, parse_path
from typed_mjcf.cli import main
from typed_mjcf.cli._common import Progress

MODEL = """\
<mujoco>
  <include file="parts.xml"/>
  <default>
    <default class="unused"><geom size="1"/></default>
  </default>
  <worldbody>
    <geom size="1" material="rde"/>
    <body name="b">
      <joint name="j"/>
      <geom size="1"/>
    </body>
  </worldbody>
  <asset><material name="red"/></asset>
</mujoco>
"""
PARTS = """\
<mujoco>
  <actuator>

    <motor joint="jj"/>
  </actuator>
</mujoco>
"""


@pytest.fixture(autouse=True)
def _in_tmp_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # files are shown relative to the current folder


def _model(text: str = MODEL) -> str:
    Path("parts.xml").write_text(PARTS, encoding="utf-8")
    Path("m.xml").write_text(text, encoding="utf-8")
    return "m.xml"


def test_findings_point_into_the_files(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", _model()]) == 1
    assert capsys.readouterr().out.splitlines() == [
        ("m.xml:4: unused-default (warning): default/default[unused]: default class 'unused' is "
         "defined but no element uses it (class= or childclass=)"),
        ("m.xml:7: unresolved-reference: worldbody/geom[0]: material='rde' names no material in "
         "the model (did you mean 'red'?)"),
        ("parts.xml:4: unresolved-reference: actuator/motor[0]: joint='jj' names no joint in the "
         "model (did you mean 'j'?) (in the model m.xml reads)"),
        "checked 1 file: 2 errors, 1 warning",
    ]


def test_warnings_alone_pass_unless_strict(capsys: pytest.CaptureFixture[str]) -> None:
    model = _model(MODEL.replace('material="rde"', 'material="red"').replace(
        '<include file="parts.xml"/>', ""))
    assert main(["check", model]) == 0
    assert capsys.readouterr().out.endswith("checked 1 file: 0 errors, 1 warning\n")
    assert main(["check", "--strict", model]) == 1


def test_json(capsys: pytest.CaptureFixture[str]) -> None:
    Path("broken.xml").write_text("<mujoco><worldbody><geom sise='1'/></worldbody></mujoco>",
                                  encoding="utf-8")
    Path("malformed.xml").write_text("<mujoco>\n<worldbody>\n</mujoco>\n", encoding="utf-8")
    assert main(["check", "--format", "json", _model(), "broken.xml", "malformed.xml"]) == 2
    document = json.loads(capsys.readouterr().out)
    assert document["summary"] == {"files": 3, "errors": 3, "warnings": 1, "unreadable": 1}
    assert document["findings"][1] == {
        "file": "m.xml", "line": 7, "rule": "unresolved-reference", "severity": "error",
        "path": "worldbody/geom[0]",
        "message": "material='rde' names no material in the model (did you mean 'red'?)"}
    assert document["findings"][3] == {
        "file": "broken.xml", "line": 1, "rule": "unknown-attribute", "severity": "error",
        "path": "worldbody/geom[0]",
        "message": "<geom> has no attribute 'sise' (did you mean 'size'?)"}
    assert document["unreadable"] == [
        ("malformed.xml:3: malformed XML: Opening and ending tag mismatch: worldbody line 2 and "
         "mujoco, line 3, column 10")]


MISTAKES = """\
<mujoco>
  <worldbody>
    <body name="arm">
      <geom name="upper" szie="0.1"/>
      <geom name="fore" size="0.1 0.2 0.3 0.4"/>
      <geom name="upper" size="0.1"/>
      <site type="plane"/>
      <body name="hand"><gem size="1"/><geom size="1" rgba="1 0 0 1"/></body>
      <geom size="0.1" material="stel"/>
    </body>
  </worldbody>
  <asset><material name="steel"/></asset>
</mujoco>
"""


def test_every_mistake_of_a_file_is_found_at_its_line(
        capsys: pytest.CaptureFixture[str]) -> None:
    """A misspelt attribute, a wrong array length, a duplicate name, a keyword the tag does
    not take, a child the parent cannot have and a reference to nothing: six findings, not
    one unreadable file."""
    Path("mistakes.xml").write_text(MISTAKES, encoding="utf-8")
    assert main(["check", "mistakes.xml"]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert [line.split(": ")[:3] for line in lines[:-1]] == [
        ["mistakes.xml:4", "unknown-attribute", "worldbody/body[arm]/geom[upper]"],
        ["mistakes.xml:5", "invalid-value", "worldbody/body[arm]/geom[fore]"],
        ["mistakes.xml:6", "duplicate-name", "worldbody/body[arm]/geom[2]"],
        ["mistakes.xml:7", "invalid-value", "worldbody/body[arm]/site[0]"],
        ["mistakes.xml:8", "illegal-child", "worldbody/body[arm]/body[hand]"],
        ["mistakes.xml:9", "unresolved-reference", "worldbody/body[arm]/geom[3]"],
    ]
    assert "'szie' (did you mean 'size'?)" in lines[0]
    assert "expected 1 to 3 numbers, got 4" in lines[1]
    assert "unique in namespace 'geom'" in lines[2]
    assert "invalid type='plane' on <site>" in lines[3]
    assert "<gem> is not a legal child of <body>" in lines[4]
    assert lines[-1] == "checked 1 file: 6 errors, 0 warnings"


def test_a_collecting_parse_leaves_out_only_what_is_wrong() -> None:
    """The parse check uses keeps the rest of the element: the misspelt attribute and the
    refused values are left out, the element and its other values stay; the strict parse
    (``from_path``) still stops at the first mistake."""
    Path("mistakes.xml").write_text(MISTAKES, encoding="utf-8")
    problems: list[Problem] = []
    model = cast(mjcf.RootElement,
                 parse_path("mistakes.xml", options=ParseOptions(on_problem=problems.append)))
    assert [p.rule for p in problems] == ["unknown-attribute", "invalid-value",
                                          "duplicate-name", "invalid-value", "illegal-child"]
    arm = model.worldbody.body[0]
    assert [(g.name, g.size) for g in arm.geom][:3] == [("upper", None), ("fore", None),
                                                       (None, approx([0.1]))]
    assert arm.site[0].type is None and [g.rgba for g in arm.body[0].geom] == [
        approx([1, 0, 0, 1])]
    with pytest.raises(mjcf.ParseError, match="has no attribute 'szie'"):
        mjcf.from_path("mistakes.xml")


def test_compile_reports_mujocos_error_at_the_element(capsys: pytest.CaptureFixture[str]) -> None:
    model = _model("<mujoco>\n<worldbody>\n<body name='b'>\n<joint/>\n</body>\n</worldbody>\n"
                   "</mujoco>\n")
    assert main(["check", model]) == 0
    capsys.readouterr()
    assert main(["check", "--compile", model]) == 1
    assert capsys.readouterr().out.splitlines() == [
        ("m.xml:3: compile: worldbody/body[b]: MuJoCo: mass and inertia of moving bodies must be "
         "larger than mjMINVAL"),
        "checked 1 file: 1 error, 0 warnings"]


def test_compile_reports_a_missing_file_at_its_element(capsys: pytest.CaptureFixture[str]) -> None:
    model = _model("<mujoco>\n<asset>\n<mesh name='m' file='gone.stl'/>\n</asset>\n</mujoco>\n")
    assert main(["check", "--compile", model]) == 1
    first = capsys.readouterr().out.splitlines()[0]
    assert first.startswith("m.xml:3: compile: asset/mesh[m]: file='gone.stl': cannot read ")


def test_several_files_and_progress(capsys: pytest.CaptureFixture[str]) -> None:
    model = _model()
    assert main(["check", "--progress", model, model]) == 1
    captured = capsys.readouterr()
    assert captured.out.endswith("checked 2 files: 4 errors, 2 warnings\n")
    assert "\r\x1b[K[1/2] checking m.xml" in captured.err
    assert "\r\x1b[K[2/2] checking m.xml" in captured.err
    assert captured.err.endswith("\r\x1b[K")  # the line is cleared at the end
    assert main(["check", model, model]) == 1
    assert capsys.readouterr().err == ""  # not a terminal: no progress unless asked


def test_progress_shows_only_on_a_terminal_for_several_files() -> None:
    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    assert Progress(2, stream=Terminal()).enabled
    assert not Progress(1, stream=Terminal()).enabled
    assert not Progress(2, stream=io.StringIO()).enabled
    assert Progress(1, enabled=True, stream=io.StringIO()).enabled



def test_an_attribute_mujoco_ignores_is_a_warning(capsys: pytest.CaptureFixture[str]) -> None:
    Path("m.xml").write_text(IGNORED, encoding="utf-8")
    assert main(["check", "m.xml"]) == 0
    dropped = "MuJoCo ignores it, and so it is dropped"
    assert capsys.readouterr().out.splitlines() == [
        ("m.xml:3: ignored-attribute (warning): worldbody/replicate[0]: <replicate> "
         f"(worldbody/replicate[0]) has no attribute prefix='p_'; {dropped}"),
        ("m.xml:7: ignored-attribute (warning): worldbody/frame[0]: <frame> "
         f"(worldbody/frame[0]) has no attribute bogus='x'; {dropped}"),
        "checked 1 file: 0 errors, 2 warnings",
    ]
    assert main(["check", "--strict", "m.xml"]) == 1


def test_other_commands_say_what_they_drop_on_stderr(capsys: pytest.CaptureFixture[str]) -> None:
    Path("m.xml").write_text(IGNORED, encoding="utf-8")
    assert main(["to-python", "m.xml"]) == 0
    captured = capsys.readouterr()
    assert "prefix" not in captured.out and "bogus" not in captured.out
    dropped = "MuJoCo ignores it, and so it is dropped"
    assert captured.err.splitlines() == [
        ("typed-mjcf: warning: m.xml:3: <replicate> (worldbody/replicate[0]) has no attribute "
         f"prefix='p_'; {dropped}"),
        ("typed-mjcf: warning: m.xml:7: <frame> (worldbody/frame[0]) has no attribute "
         f"bogus='x'; {dropped}"),
    ]
