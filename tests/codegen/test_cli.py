"""``python -m codegen`` misused: one line on stderr, exit status 2, no traceback, nothing
written. (The noxfile checks ``nox -s generate``'s own arguments before installing.)"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import codegen
from codegen import __main__ as cli
from codegen import ir, render

ROOT = Path(__file__).resolve().parents[2]


def fails_in_one_line(args: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    assert cli.main(args) == 2
    out, err = capsys.readouterr()
    assert not out
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("python -m codegen: error: "), err
    return lines[0]


def test_missing_grammar_file(capsys: pytest.CaptureFixture[str]) -> None:
    line = fails_in_one_line(["generate", "--grammar", "missing/path"], capsys)
    assert "--grammar missing/path: no such file" in line


def test_grammar_is_a_directory(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "src" / "xml").mkdir(parents=True)
    (tmp_path / "src" / "xml" / "mjcf.schema").write_text("", encoding="utf-8")
    line = fails_in_one_line(["generate", "--grammar", str(tmp_path)], capsys)
    assert "is a directory" in line and "did you mean" in line


def test_malformed_grammar_names_file_and_line(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    grammar = tmp_path / "mjcf.schema"
    grammar.write_text("# a comment\n- not a grammar\n", encoding="utf-8")
    before = {p: p.read_bytes() for p in [ir.SCHEMA_PATH, *render.GENERATED_DIR.iterdir()]
              if p.is_file()}
    line = fails_in_one_line(["generate", "--grammar", str(grammar)], capsys)
    assert f"{grammar}:2: " in line
    assert {p: p.read_bytes() for p in before} == before  # nothing rewritten


def test_missing_dependency_is_named(monkeypatch: pytest.MonkeyPatch,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    """Without the codegen extra (jinja2 here), a hint instead of an import traceback."""
    monkeypatch.setitem(sys.modules, "jinja2", None)  # `import jinja2` now fails
    for module in ("commands", "render"):  # imported afresh, as in a new process
        monkeypatch.delitem(sys.modules, f"codegen.{module}", raising=False)
        monkeypatch.delattr(codegen, module, raising=False)
    line = fails_in_one_line(["check"], capsys)  # check writes nothing, even if it ran
    assert "jinja2 is not installed" in line and "nox -s generate" in line


def test_as_a_program() -> None:
    """The same through ``python -m`` (what ``nox -s generate`` runs)."""
    result = subprocess.run([sys.executable, "-m", "codegen", "generate", "--grammar",
                             "missing/path"], cwd=ROOT, capture_output=True, text=True,
                            check=False)
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
