"""mypy and pyright over the typed code: clean, except the negative cases, which fail as marked.

One mypy run (the repository's configuration plus ``--warn-unused-ignores``) and one pyright
run (the repository's strict configuration) per session, side by side, over the typed code
(``TYPED_PATHS``: ``src/``, ``codegen/``, ``tests/typing/``, ``examples/``) and the negative
cases (``negative/``, ``negative/mujoco/``). ``nox -s tests`` runs no other mypy or pyright:
these runs are its type check, done in the test run's parallel workers. Then, per checker:

- every file outside the negative cases must have no error (``assert_type`` mismatches are
  errors);
- every line of ``negative/*.py`` must get exactly the error codes its trailing marker names
  (see ``negative/__init__.py``): a missing code and an unexpected one both fail
  (``negative/mujoco/`` is compared by ``test_mujoco_stubs.py``, from the same runs).

A plain ``mypy`` run leaves ``negative/`` out (``[tool.mypy] exclude``); give pyright the
files as ``typed_paths()`` does.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import pytest

from tests.support.typecheck import (
    CHECKERS,
    MUJOCO_NEGATIVE_FILES,
    NEGATIVE_FILES,
    POSITIVE_FILES,
    ROOT,
    TYPED_PATHS,
    Checker,
    Diagnostic,
    all_files,
    compare,
    parse_markers,
)


def test_marker_syntax(tmp_path: Path) -> None:
    sample = tmp_path / "sample.py"
    sample.write_text(
        "x = 1\n"
        "f(x)  # E: mypy[arg-type,call-arg] pyright[reportCallIssue]\n"
        "g()  # E: pyright[reportUndefinedVariable]\n",
        encoding="utf-8",
    )
    assert parse_markers(sample) == {
        (2, "mypy"): {"arg-type", "call-arg"},
        (2, "pyright"): {"reportCallIssue"},
        (3, "pyright"): {"reportUndefinedVariable"},
    }
    for bad in ("# E: mypy", "# E: mypy[]", "# E: flake8[E501]", "# E: mypy[x] and more"):
        sample.write_text(f"x = 1  {bad}\n", encoding="utf-8")
        with pytest.raises(ValueError):
            parse_markers(sample)


@pytest.fixture(scope="module")
def reports(typed_code_reports: dict[Checker, list[Diagnostic]]
            ) -> dict[Checker, list[Diagnostic]]:
    return typed_code_reports  # tests/conftest.py: one run per session


def test_packages_are_marked_typed() -> None:
    """Without ``py.typed`` mypy treats an installed package as untyped (everything Any); the
    generated classes are part of ``typed_mjcf`` (one package, one marker)."""
    import typed_mjcf
    import typed_mjcf._generated

    assert typed_mjcf.__file__ is not None and typed_mjcf._generated.__file__ is not None
    marker = Path(typed_mjcf.__file__).parent / "py.typed"
    assert marker.is_file(), f"{marker} is missing: type checkers will ignore the package"
    assert Path(typed_mjcf._generated.__file__).parent.parent == marker.parent


def test_there_are_cases() -> None:
    assert POSITIVE_FILES and NEGATIVE_FILES
    for path in NEGATIVE_FILES:
        assert parse_markers(path), f"{path} has no '# E:' marker"


@pytest.mark.parametrize("checker", CHECKERS)
def test_positive_files_are_clean(checker: Checker,
                                  reports: Mapping[Checker, list[Diagnostic]]) -> None:
    problems: list[str] = []
    for path in POSITIVE_FILES:
        problems += compare(checker, path, {}, reports[checker])
    assert not problems, f"{checker} on the positive cases:\n" + "\n".join(problems)


@pytest.mark.parametrize("checker", CHECKERS)
def test_the_typed_code_is_clean(checker: Checker,
                                 reports: Mapping[Checker, list[Diagnostic]]) -> None:
    """src/, codegen/, examples/ (and tests/typing/ outside the negative cases): what the
    plain ``mypy``/``pyright`` runs over TYPED_PATHS would report."""
    negative = set(NEGATIVE_FILES) | set(MUJOCO_NEGATIVE_FILES)
    found = [f"{d.file.relative_to(ROOT)}:{d.line}: [{d.code}] {d.message.splitlines()[0]}"
             for d in reports[checker] if d.file.is_relative_to(ROOT) and d.file not in negative]
    assert not found, f"{checker} (strict) on the typed code:\n" + "\n".join(found)


def test_the_runs_check_the_typed_code() -> None:
    """The folders hold the code (a moved folder would be checked as nothing)."""
    files = all_files()
    for path in TYPED_PATHS:
        assert any(f.is_relative_to(ROOT / path) for f in files), path
    assert set(POSITIVE_FILES) <= set(files) and set(NEGATIVE_FILES) <= set(files)


@pytest.mark.parametrize("path", NEGATIVE_FILES, ids=[p.stem for p in NEGATIVE_FILES])
@pytest.mark.parametrize("checker", CHECKERS)
def test_negative_files_fail_as_marked(checker: Checker, path: Path,
                                       reports: Mapping[Checker, list[Diagnostic]]) -> None:
    problems = compare(checker, path, parse_markers(path), reports[checker])
    assert not problems, (f"{checker} on {path.relative_to(ROOT)} differs from its markers:\n"
                          + "\n".join(problems))


def test_no_diagnostics_outside_the_checked_files(
        reports: Mapping[Checker, list[Diagnostic]]) -> None:
    """Errors in imported modules (src/, generated/) would go unnoticed otherwise."""
    checked = set(all_files())
    stray = [f"{checker}: {d.file}:{d.line}: [{d.code}] {d.message.splitlines()[0]}"
             for checker, diagnostics in reports.items()
             for d in diagnostics if d.file not in checked]
    assert not stray, "\n".join(stray)
