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

import json
import re
import subprocess
import sys
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import pytest

Checker = Literal["mypy", "pyright"]
CHECKERS: tuple[Checker, ...] = ("mypy", "pyright")

ROOT = Path(__file__).resolve().parents[2]
TYPING_DIR = Path(__file__).resolve().parent
NEGATIVE_DIR = TYPING_DIR / "negative"
NEGATIVE_FILES = sorted(p for p in NEGATIVE_DIR.glob("*.py") if p.name != "__init__.py")
MUJOCO_NEGATIVE_FILES = sorted((NEGATIVE_DIR / "mujoco").glob("*.py"))
POSITIVE_FILES = sorted(p for p in TYPING_DIR.rglob("*.py") if NEGATIVE_DIR not in p.parents)
# The typed code, relative to ROOT: mypy --strict and pyright strict find no error in it.
TYPED_PATHS = ("src", "codegen", "tests/typing", "examples")

MARKER = re.compile(r"#\s*E:\s*(?P<body>.*)$")
MARKER_GROUP = re.compile(r"(?P<checker>\w+)\[(?P<codes>[^\]]*)\]")
MYPY_LINE = re.compile(
    r"^(?P<file>.+?):(?P<line>\d+)(?::\d+)?: (?P<severity>error|warning|note): "
    r"(?P<message>.*?)(?:  \[(?P<code>[a-z0-9-]+)\])?$"
)


@dataclass(frozen=True, order=True)
class Diagnostic:
    """One error (or warning) a checker reported."""

    file: Path
    line: int
    code: str
    message: str


Expected = dict[tuple[int, Checker], set[str]]


# ----------------------------------------------------------------------------- markers


def parse_markers(path: Path) -> Expected:
    """``{(line, checker): codes}`` from the ``# E: mypy[...] pyright[...]`` markers."""
    expected: Expected = {}
    for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        match = MARKER.search(text)
        if match is None:
            continue
        body = match["body"]
        groups = list(MARKER_GROUP.finditer(body))
        leftover = MARKER_GROUP.sub("", body).strip()
        if not groups or leftover:
            raise ValueError(f"{path}:{number}: malformed marker {match[0]!r}; "
                             f"expected e.g. '# E: mypy[arg-type] pyright[reportArgumentType]'")
        for group in groups:
            checker = group["checker"]
            if checker not in CHECKERS:
                raise ValueError(f"{path}:{number}: unknown checker {checker!r} in marker; "
                                 f"known: {', '.join(CHECKERS)}")
            codes = {code.strip() for code in group["codes"].split(",") if code.strip()}
            if not codes:
                raise ValueError(f"{path}:{number}: {checker}[] names no error code")
            name: Checker = "mypy" if checker == "mypy" else "pyright"
            expected.setdefault((number, name), set()).update(codes)
    return expected


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


# ----------------------------------------------------------------------------- checkers


# what parse_mypy reads: one line per diagnostic, absolute paths, error codes
MYPY_OUTPUT = ["--show-absolute-path", "--show-error-codes", "--no-pretty",
               "--no-error-summary", "--hide-error-context", "--no-color-output"]


def mypy_command(files: Iterable[Path], cache_dir: Path) -> list[str]:
    """mypy with the repository's configuration, as ``nox -s tests`` runs it."""
    return [
        sys.executable, "-m", "mypy",
        "--config-file", str(ROOT / "pyproject.toml"),
        "--warn-unused-ignores",
        "--cache-dir", str(cache_dir),
        *MYPY_OUTPUT,
        *(str(f) for f in files),
    ]


def parse_mypy(returncode: int, stdout: str, stderr: str) -> list[Diagnostic]:
    if returncode not in (0, 1):
        raise RuntimeError(f"mypy crashed (exit {returncode}):\n{stdout}\n{stderr}")
    diagnostics: list[Diagnostic] = []
    for text in stdout.splitlines():
        match = MYPY_LINE.match(text)
        if match is None:
            raise RuntimeError(f"unparsed mypy output line: {text!r}\n{stdout}")
        if match["severity"] == "note":
            continue
        diagnostics.append(Diagnostic(Path(match["file"]).resolve(), int(match["line"]),
                                      match["code"] or "(no code)", match["message"]))
    return diagnostics


def pyright_command(files: Iterable[Path]) -> list[str]:
    """pyright with the repository's (strict) configuration, JSON output."""
    return [
        sys.executable, "-m", "pyright", "--outputjson",
        "--project", str(ROOT / "pyproject.toml"),
        "--pythonpath", sys.executable,
        *(str(f) for f in files),
    ]


def parse_pyright(returncode: int, stdout: str, stderr: str) -> list[Diagnostic]:
    try:
        report = json.loads(stdout)
    except json.JSONDecodeError:
        raise RuntimeError(f"pyright gave no JSON (exit {returncode}):\n{stdout}\n{stderr}"
                           ) from None
    diagnostics: list[Diagnostic] = []
    for item in report["generalDiagnostics"]:
        if item["severity"] not in ("error", "warning"):
            continue
        diagnostics.append(Diagnostic(
            Path(item["file"]).resolve(), item["range"]["start"]["line"] + 1,
            item.get("rule", "(no rule)"), item["message"]))
    return diagnostics


def run_checkers(commands: Mapping[Checker, list[str]], cwd: Path,
                 ) -> dict[Checker, list[Diagnostic]]:
    """The mypy and pyright ``commands`` side by side (two processes: they take seconds
    each), then their diagnostics."""
    processes = {name: subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True)
                 for name, command in commands.items()}
    outputs = {name: process.communicate() for name, process in processes.items()}
    return {
        "mypy": parse_mypy(processes["mypy"].returncode, *outputs["mypy"]),
        "pyright": parse_pyright(processes["pyright"].returncode, *outputs["pyright"]),
    }


def run_both(files: list[Path], cache_dir: Path, pyright_files: list[Path] | None = None,
             ) -> dict[Checker, list[Diagnostic]]:
    """mypy and pyright with the repository's configuration, side by side; pyright over
    ``pyright_files`` if given."""
    return run_checkers({"mypy": mypy_command(files, cache_dir),
                         "pyright": pyright_command(
                             files if pyright_files is None else pyright_files)}, ROOT)


def all_files() -> list[Path]:
    """Every file the runs check (absolute paths)."""
    found = {p.resolve() for path in TYPED_PATHS for p in (ROOT / path).rglob("*.py")}
    return sorted(found | set(NEGATIVE_FILES) | set(MUJOCO_NEGATIVE_FILES))


def run_typed_code(cache_dir: Path, more: Sequence[Path] = ()
                   ) -> dict[Checker, list[Diagnostic]]:
    """Both checkers over the typed code and the negative cases (and ``more`` files, checked
    with the same configuration). mypy is given the folders (its configuration's exclude
    leaves ``negative/`` out of them) and the negative files; pyright the folders, which
    include them."""
    folders = [Path(p) for p in TYPED_PATHS]
    return run_both([*folders, *NEGATIVE_FILES, *MUJOCO_NEGATIVE_FILES, *more], cache_dir,
                    pyright_files=[*folders, *more])


@dataclass(frozen=True)
class TypedCodeRun:
    """The session's run of both checkers (``tests/conftest.py``): what they said of the
    typed code and the negative cases, and of to-python's code of the corpus checked with
    them (``tests/cli/test_to_python_types.py``)."""

    typed_reports: dict[Checker, list[Diagnostic]]
    corpus_modules: list[Path]
    corpus_reports: dict[Checker, list[Diagnostic]]

    @classmethod
    def split(cls, reports: Mapping[Checker, list[Diagnostic]], corpus_modules: list[Path],
              ) -> TypedCodeRun:
        corpus = {path.resolve() for path in corpus_modules}
        return cls({name: [d for d in found if d.file not in corpus]
                    for name, found in reports.items()},
                   corpus_modules,
                   {name: [d for d in found if d.file in corpus]
                    for name, found in reports.items()})


@pytest.fixture(scope="module")
def reports(typed_code_reports: dict[Checker, list[Diagnostic]]
            ) -> dict[Checker, list[Diagnostic]]:
    return typed_code_reports  # tests/conftest.py: one run per session


# ----------------------------------------------------------------------------- comparison


def source_line(path: Path, line: int) -> str:
    lines = path.read_text(encoding="utf-8").splitlines()
    return lines[line - 1].strip() if 0 < line <= len(lines) else ""


def compare(checker: Checker, path: Path, expected: Expected,
            diagnostics: Iterable[Diagnostic]) -> list[str]:
    """Readable differences between the markers of ``path`` and what ``checker`` said."""
    got: dict[int, dict[str, list[str]]] = {}
    for d in diagnostics:
        if d.file == path:
            got.setdefault(d.line, {}).setdefault(d.code, []).append(d.message)
    wanted = {line: codes for (line, name), codes in expected.items() if name == checker}
    problems: list[str] = []
    for line in sorted(set(got) | set(wanted)):
        reported = got.get(line, {})
        missing = sorted(wanted.get(line, set()) - set(reported))
        unexpected = sorted(set(reported) - wanted.get(line, set()))
        if not missing and not unexpected:
            continue
        text = [f"{path.relative_to(ROOT)}:{line}: {source_line(path, line)}"]
        if missing:
            text.append(f"    missing {checker} error(s): {', '.join(missing)}")
        for code in unexpected:
            messages = "; ".join(m.splitlines()[0] for m in reported[code])
            text.append(f"    unexpected {checker} error [{code}]: {messages}")
        problems.append("\n".join(text))
    return problems


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
