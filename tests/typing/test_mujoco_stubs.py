"""The generated ``mujoco`` stubs (generated/mujoco-stubs): in sync, precise, and strict.

- drift: the committed stubs equal a fresh generation from the installed wheel;
- positive: realistic scripts in ``mujoco_cases/`` are clean under mypy --strict and pyright
  strict (their ``assert_type`` lines pin the precise types), and run;
- negative: each marked line of ``negative/mujoco/`` gets exactly the errors its marker names
  (markers as in ``negative/__init__.py``), from both checkers.

The diagnostics come from ``test_typecheck.py``'s mypy and pyright runs over the typed code
(which holds both the positive and the negative files): one run of each per session.
"""

from __future__ import annotations

import importlib.util
import runpy
from collections.abc import Mapping
from pathlib import Path

import pytest

from codegen import mujoco_stubs
from tests.support.typecheck import (
    CHECKERS,
    ROOT,
    Checker,
    Diagnostic,
    all_files,
    compare,
    parse_markers,
)

CASES = Path(__file__).resolve().parent / "mujoco_cases"
POSITIVE = sorted(CASES.glob("*.py"))
NEGATIVE = sorted((Path(__file__).resolve().parent / "negative" / "mujoco").glob("*.py"))

Reports = dict[Checker, list[Diagnostic]]


STUBS = ROOT / "generated" / "mujoco-stubs"


@pytest.fixture(scope="module")
def positive(typed_code_reports: Reports) -> Reports:
    return typed_code_reports  # tests/conftest.py


@pytest.fixture(scope="module")
def negative(typed_code_reports: Reports) -> Reports:
    return typed_code_reports


def test_the_runs_check_the_cases() -> None:
    checked = set(all_files())
    assert set(POSITIVE) <= checked and set(NEGATIVE) <= checked


def test_there_are_cases() -> None:
    assert len(POSITIVE) >= 5 and NEGATIVE
    for path in NEGATIVE:
        assert parse_markers(path), f"{path} has no '# E:' marker"


def test_stubs_match_a_fresh_generation() -> None:
    if importlib.util.find_spec("pybind11_stubgen") is None:
        pytest.skip("pybind11-stubgen (the dev extra) is not installed: cannot regenerate")
    stale = mujoco_stubs.stale(mujoco_stubs.render())
    assert not stale, (f"generated/mujoco-stubs/ differs from a fresh generation: {stale}; "
                       "run `python -m codegen stubs`")


@pytest.mark.parametrize("checker", CHECKERS)
def test_positive_cases_are_clean(checker: Checker, positive: Mapping[Checker, list[Diagnostic]]
                                  ) -> None:
    problems: list[str] = []
    for path in POSITIVE:
        problems += compare(checker, path, {}, positive[checker])
    stray = [f"{d.file}:{d.line}: [{d.code}] {d.message}" for d in positive[checker]
             if d.file.is_relative_to(STUBS)]  # errors inside the stubs themselves
    assert not problems and not stray, (f"{checker} on the mujoco cases:\n"
                                        + "\n".join(problems + stray))


@pytest.mark.parametrize("path", NEGATIVE, ids=[p.stem for p in NEGATIVE])
@pytest.mark.parametrize("checker", CHECKERS)
def test_negative_cases_fail_as_marked(checker: Checker, path: Path,
                                       negative: Mapping[Checker, list[Diagnostic]]) -> None:
    problems = compare(checker, path, parse_markers(path), negative[checker])
    assert not problems, (f"{checker} on {path.relative_to(ROOT)} differs from its markers:\n"
                          + "\n".join(problems))


@pytest.mark.parametrize("path", POSITIVE, ids=[p.stem for p in POSITIVE])
def test_positive_cases_run(path: Path) -> None:
    """What the stubs promise holds at run time for what the cases do (no GL needed)."""
    runpy.run_path(str(path), run_name="__main__")
