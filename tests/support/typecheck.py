"""mypy and pyright with the repository's configuration, and what they say: the session's
one run over the typed code (``tests/typing/test_typecheck.py`` explains it), the negative
cases' ``# E:`` markers, and the comparison of the two."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

Checker = Literal["mypy", "pyright"]
CHECKERS: tuple[Checker, ...] = ("mypy", "pyright")

ROOT = Path(__file__).resolve().parents[2]
TYPING_DIR = ROOT / "tests" / "typing"
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
