"""The ``typed-mjcf`` command: entry points, help, and bad input (a missing file, XML that is
not MJCF, malformed XML, a schema error) as one line naming file and line, exit code 2, no
traceback, for every command."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from typed_mjcf.cli import main

from .bad_inputs import BAD, EXPECTED

ROOT = Path(__file__).resolve().parents[2]

GOOD = "<mujoco>\n  <worldbody>\n    <geom size='1'/>\n  </worldbody>\n</mujoco>\n"


@pytest.fixture(autouse=True)
def _files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    for name, text in BAD.items():
        if text is not None:
            Path(name).write_text(text, encoding="utf-8")
    Path("good.xml").write_text(GOOD, encoding="utf-8")


# what check reads past and reports as a finding (exit 1), not as an unreadable file
CHECK_FINDS = {"schema.xml"}


def _commands(name: str) -> list[list[str]]:
    checks = [] if name in CHECK_FINDS else [["check", name], ["check", "--compile", name]]
    return [["to-python", name], *checks, ["fmt", name],
            ["fmt", "--check", name], ["diff", name, "good.xml"], ["diff", "good.xml", name]]


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_is_one_line_and_exit_2(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    for command in _commands(name):
        assert main(command) == 2, command
        err = capsys.readouterr().err
        assert err == f"typed-mjcf {command[0]}: {EXPECTED[name]}\n", command


def test_check_reports_a_schema_error_as_a_finding(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "schema.xml"]) == 1
    assert capsys.readouterr().out.splitlines() == [
        ("schema.xml:3: unknown-attribute: worldbody/geom[0]: <geom> has no attribute 'sise' "
         "(did you mean 'size'?)"), "checked 1 file: 1 error, 0 warnings"]


def test_other_files_are_still_processed(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "malformed.xml", "good.xml"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "checked 2 files: 0 errors, 0 warnings, 1 file not readable\n"
    assert main(["fmt", "--canonical", "schema.xml", "good.xml"]) == 2  # good.xml: to "1"
    assert capsys.readouterr().out.splitlines() == [
        "reformatted good.xml", "1 file reformatted, 0 files already formatted"]
    assert Path("schema.xml").read_text(encoding="utf-8") == BAD["schema.xml"]


def test_no_traceback_from_the_command_line() -> None:
    """The real process: ``python -m typed_mjcf`` prints the one line and exits 2."""
    result = subprocess.run([sys.executable, "-m", "typed_mjcf", "check", "malformed.xml"],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 2
    assert result.stderr == f"typed-mjcf check: {EXPECTED['malformed.xml']}\n"
    assert "Traceback" not in result.stdout + result.stderr


def test_help_names_every_command_and_the_exit_codes(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["--help"])
    assert exit_info.value.code == 0
    text = capsys.readouterr().out
    for command in ("to-python", "check", "fmt", "diff"):
        assert f"typed-mjcf {command}" in text
    assert "exit status: 0 ok; 1 findings" in text
    # fmt keeps what was written unless --canonical: the summary must not say it rewrites
    fmt_line = next(line for line in text.splitlines() if "typed-mjcf fmt" in line)
    assert "keeping what was written" in fmt_line and "canonical" not in fmt_line
    assert "--canonical rewrites" in " ".join(text.split())  # the command list's help
    for command in ("to-python", "check", "fmt", "diff"):
        with pytest.raises(SystemExit):
            main([command, "--help"])
        assert "exit status:" in capsys.readouterr().out


def test_usage_errors_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    for argv in ([], ["lint", "good.xml"], ["check"], ["diff", "good.xml"]):
        with pytest.raises(SystemExit) as exit_info:
            main(argv)
        assert exit_info.value.code == 2
        assert "usage: typed-mjcf" in capsys.readouterr().err


def test_the_console_script_is_declared() -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert project["project"]["scripts"]["typed-mjcf"] == "typed_mjcf.cli:main"
