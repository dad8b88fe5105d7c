"""``typed-mjcf to-python`` output passes ``mypy --strict`` and pyright's strict mode with no
ignores, and ruff's formatter and linter leave it as it is: the code for every corpus model
MuJoCo compiles (the biggest among them), checked in one run of each tool, the type checkers
with the repository's configuration (the run of the typed code, ``tests/conftest.py``)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.typecheck import Checker, Diagnostic, TypedCodeRun

MINIMUM_SAMPLE = 20


@pytest.fixture(scope="module")
def modules(typed_code_run: TypedCodeRun) -> list[Path]:
    return typed_code_run.corpus_modules  # tests/conftest.py: checked with the typed code


@pytest.fixture(scope="module")
def reports(typed_code_run: TypedCodeRun) -> dict[Checker, list[Diagnostic]]:
    return typed_code_run.corpus_reports


def test_the_sample_is_big_enough(modules: list[Path]) -> None:
    assert len(modules) >= MINIMUM_SAMPLE
    biggest = max(modules, key=lambda m: m.stat().st_size)
    assert biggest.stat().st_size > 100_000, biggest  # dog.xml's code, a few thousand lines
    assert all("ignore" not in m.read_text(encoding="utf-8") for m in modules)


@pytest.mark.parametrize("checker", ["mypy", "pyright"])
def test_the_code_type_checks(checker: Checker, reports: dict[Checker, list[Diagnostic]]) -> None:
    found = [f"{d.file.name}:{d.line}: {d.code}: {d.message}" for d in reports[checker]]
    assert found == []


RUFF = [sys.executable, "-m", "ruff"]
RUFF_OPTIONS = ["--no-cache", "--isolated", "--line-length", "100"]


def test_ruff_format_leaves_the_code_as_it_is(modules: list[Path]) -> None:
    result = subprocess.run([*RUFF, "format", "--check", *RUFF_OPTIONS, *map(str, modules)],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stdout + result.stderr


def test_ruff_finds_nothing_to_lint(modules: list[Path]) -> None:
    result = subprocess.run([*RUFF, "check", *RUFF_OPTIONS, "--select", "E,F,W,I,B,UP",
                             *map(str, modules)], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stdout + result.stderr
