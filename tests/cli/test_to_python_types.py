"""``typed-mjcf to-python`` output passes ``mypy --strict`` and pyright's strict mode with no
ignores, and ruff's formatter and linter leave it as it is: the code for every corpus model
MuJoCo compiles (the biggest among them), checked in one run of each tool, the type checkers
with the repository's configuration."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf.cli.to_python import to_python

from ..typing.test_typecheck import Checker, Diagnostic, run_both
from .corpus import CORPUS, compiled, module_name
from .test_to_python import SEPARATORS

MINIMUM_SAMPLE = 20


@pytest.fixture(scope="module")
def modules(tmp_path_factory: pytest.TempPathFactory) -> list[Path]:
    folder = tmp_path_factory.mktemp("to_python")
    written: list[Path] = []
    for ident, path in CORPUS:
        if ident == SEPARATORS:
            continue
        try:
            compiled(ident, path)
        except pytest.skip.Exception:
            continue
        module = folder / module_name(ident)
        module.write_text(to_python(mjcf.from_path(path), str(folder)), encoding="utf-8")
        written.append(module)
    return written


@pytest.fixture(scope="module")
def reports(modules: list[Path],
            tmp_path_factory: pytest.TempPathFactory) -> dict[Checker, list[Diagnostic]]:
    return run_both(modules, tmp_path_factory.mktemp("mypy_cache"))


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
