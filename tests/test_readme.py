"""The documentation's Python examples and the scripts in ``examples/``, as a user meets them.

- every Python block of the README and of the pages in ``docs/`` runs and prints what the
  page says it prints (the generated MJCF reference's examples: tests/codegen/test_reference.py);
- those blocks (each written to a module of its own), the MJCF reference's examples (one
  module) and every file in ``examples/``
  are clean under ``mypy --strict`` and pyright strict: one mypy run and one pyright run over
  a user's project (``UserCode``: those modules, the negative cases, a canary; strict
  configurations and the ``mujoco`` stubs, none of this repository's settings) in a folder
  outside the repository, so that what is checked is what a user's own script would see.
  ``tests/typing/test_runtime_stubs.py`` compares the same run with one against the wheel's
  layout (``tests/conftest.py`` makes it once per session).

The examples' behaviour when run is tested in ``test_examples.py``.
"""

from __future__ import annotations

import contextlib
import importlib.util
import io
import re
import shutil
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.typing.test_typecheck import (
    CHECKERS,
    MYPY_OUTPUT,
    NEGATIVE_FILES,
    Checker,
    Diagnostic,
    run_checkers,
)

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
DOCS = ROOT / "docs"
# The pages written by hand; docs/reference/ is the generated reference copied by the build.
PAGES = [README, *sorted(p for p in DOCS.rglob("*.md")
                         if p.relative_to(DOCS).parts[0] not in ("reference", "_build"))]
REFERENCE = ROOT / "generated" / "mjcf-reference"
# The page whose table of mistakes shows what mypy says of each
MISTAKES_PAGE = DOCS / "guide" / "typing.md"
EXAMPLES = sorted((ROOT / "examples").glob("*.py"))


@dataclass(frozen=True)
class Block:
    """A fenced Python block of a page."""

    code: str
    source: Path
    line: int  # the page's line number of the block's first line of code

    @property
    def name(self) -> str:
        return f"{self.source.relative_to(ROOT).as_posix()}:{self.line}"


def page_blocks(path: Path) -> list[Block]:
    text = path.read_text(encoding="utf-8")
    return [Block(match[1], path, text.count("\n", 0, match.start(1)) + 1)
            for match in re.finditer(r"```python\n(.*?)```", text, re.DOTALL)]


BLOCKS = [block for page in PAGES for block in page_blocks(page)]


@pytest.mark.parametrize("block", BLOCKS, ids=[b.name for b in BLOCKS])
def test_documented_example_runs(block: Block, tmp_path: Path,
                                 monkeypatch: pytest.MonkeyPatch) -> None:
    if needs_warp(block) and importlib.util.find_spec("mujoco_warp") is None:
        pytest.skip("needs MuJoCo Warp (the warp extra): nox -s warp runs it "
                    "(tests/warp/test_docs.py)")
    run_block(block, tmp_path, monkeypatch)


def needs_warp(block: Block) -> bool:
    """Whether the block uses MuJoCo Warp (the ``warp`` extra)."""
    return "typed_mjcf.warp" in block.code


def run_block(block: Block, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Run the block; each of its ``# `` lines must be in what it prints."""
    monkeypatch.chdir(tmp_path)  # what an example writes (an image) lands there
    expected = [line[2:] for line in block.code.splitlines() if line.startswith("# ")]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile("\n" * (block.line - 1) + block.code, str(block.source), "exec"), {})
    for line in expected:
        assert line in out.getvalue()


def test_the_pages_have_examples() -> None:
    assert len(page_blocks(README)) >= 3
    assert {b.source for b in BLOCKS} > {README}
    assert len(EXAMPLES) >= 4


def reference_examples() -> str:
    """The MJCF reference's examples as one module, each a function."""
    functions: list[str] = ["import typed_mjcf as mjcf\n"]
    for page in sorted(REFERENCE.glob("*.md")):
        for block in page_blocks(page):
            body = [line for line in block.code.splitlines()
                    if line and line != "import typed_mjcf as mjcf"]
            made = "element" if any(line.startswith("element = ") for line in body) else "model"
            functions.append(f"\ndef example_{page.stem}() -> mjcf.Element:\n"
                             + "".join(f"    {line}\n" for line in body)
                             + f"    return {made}\n")
    return "\n".join(functions)


# ----------------------------------------------------------------------------- type checks


# The mistakes of the README's table "What the type checker catches", one per line in the
# table's order after the three set-up lines; what mypy says of each must be what the
# table's typed-mjcf column shows ("…" standing for the middle of a long list).
MISTAKES = [
    'body.add_geom(tpye="capsule")',
    'body.add_geom(type="capsul")',
    "body.add_geom(pos=(1, 2))",
    "body.add_geom(size=(1, 2, 3, 4))",
    'body.add_geom(mass="heavy")',
    "body.add_geom(condim=3.5)",
    'body.add_joint(limited="yes")',
    "model.worldbody.add_motor()",
    "joint.add_geom()",
    "model.sensor.add_jointpos(joint=body.add_geom())",
    'joint.tpye = "hinge"',
]
MISTAKES_MODULE = ("import typed_mjcf as mjcf\n\nmodel = mjcf.RootElement()\n"
                   "body = model.worldbody.add_body()\njoint = body.add_joint()\n"
                   + "".join(line + "\n" for line in MISTAKES))
MISTAKES_FIRST_LINE = 6


def readme_table_messages() -> list[str]:
    """The typed-mjcf column of the table of mistakes (``MISTAKES_PAGE``), in its order."""
    text = MISTAKES_PAGE.read_text(encoding="utf-8")
    section = text[text.index("| mistake | typed-mjcf |"):].split("\n\n", 1)[0]
    messages: list[str] = []
    for row in section.splitlines():
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", row)[1:-1]]
        if len(cells) == 4 and cells[1].startswith("`") and cells[1] != "typed-mjcf":
            messages.append(cells[1].strip("`").replace("\\|", "|"))
    return messages


# A module with two mistakes, checked with the others: it proves that the runs see the
# library's and MuJoCo's types (an untyped import would make everything Any, and clean).
CANARY = """import mujoco

import typed_mjcf as mjcf

mjcf.RootElement().worldbody.add_geom(type="capsul")
mujoco.mj_step(mjcf.RootElement().compile())
"""
CANARY_LINES = [5, 6]


@dataclass(frozen=True)
class UserCode:
    """A user's project in ``folder``: the README's blocks, ``examples/``, the negative cases
    of ``tests/typing/negative/``, the README table's mistakes and the canary, each a module;
    strict configurations and nothing else (``deprecated`` for mypy, which the README asks
    for, so that the generic ``add()``'s misspelt keywords are reported); the ``mujoco`` stubs
    in ``typings/``, as ``typed-mjcf mujoco-stubs`` puts them."""

    folder: Path
    origin: Mapping[Path, tuple[Path, int]]  # module -> (file shown, line offset)
    canary: Path
    mistakes: Path

    @property
    def files(self) -> list[Path]:
        return list(self.origin)

    def describe(self, diagnostic: Diagnostic) -> str:
        shown, offset = self.origin.get(diagnostic.file, (diagnostic.file, 0))
        name = shown.relative_to(ROOT) if shown.is_relative_to(ROOT) else shown
        first = diagnostic.message.splitlines()[0]
        return f"{name}:{diagnostic.line + offset}: [{diagnostic.code}] {first}"


def user_project(folder: Path) -> UserCode:
    origin: dict[Path, tuple[Path, int]] = {}

    def module(name: str, text: str, shown: Path | None = None, offset: int = 0) -> Path:
        path = (folder / name).resolve()
        path.write_text(text, encoding="utf-8")
        origin[path] = (shown or path, offset)
        return path

    for number, block in enumerate(BLOCKS):
        module(f"doc_block{number}.py", block.code, block.source, block.line - 1)
    module("reference_examples.py", reference_examples(), REFERENCE / "index.md")
    for path in [*EXAMPLES, *NEGATIVE_FILES]:
        module(path.name, path.read_text(encoding="utf-8"), path)
    canary, mistakes = module("canary.py", CANARY), module("mistakes.py", MISTAKES_MODULE)
    shutil.copytree(ROOT / "generated" / "mujoco-stubs", folder / "typings" / "mujoco")
    (folder / "mypy.ini").write_text("[mypy]\nstrict = True\nenable_error_code = deprecated\n"
                                     "mypy_path = typings\n", encoding="utf-8")
    (folder / "pyrightconfig.json").write_text('{"typeCheckingMode": "strict"}\n',
                                               encoding="utf-8")
    return UserCode(folder, origin, canary, mistakes)


def check_user_code(code: UserCode, python: str, cache: Path
                    ) -> dict[Checker, list[Diagnostic]]:
    """mypy and pyright on ``code`` with ``python``'s packages, side by side."""
    paths = [str(f) for f in code.files]
    return run_checkers({
        "mypy": [sys.executable, "-m", "mypy", "--config-file", str(code.folder / "mypy.ini"),
                 "--python-executable", python, "--cache-dir", str(cache), *MYPY_OUTPUT,
                 *paths],
        "pyright": [sys.executable, "-m", "pyright", "--outputjson",
                    "--project", str(code.folder / "pyrightconfig.json"),
                    "--pythonpath", python, *paths],
    }, code.folder)


def outside_negative_cases(code: UserCode, diagnostics: list[Diagnostic]) -> list[Diagnostic]:
    negative = {path.resolve() for path in NEGATIVE_FILES}
    return [d for d in diagnostics if code.origin.get(d.file, (d.file, 0))[0] not in negative]


@pytest.mark.parametrize("checker", CHECKERS)
def test_readme_and_examples_type_check(
        checker: Checker, user_code: UserCode,
        user_code_reports: Mapping[Checker, list[Diagnostic]]) -> None:
    """No error and no warning (errors inside the library would count too)."""
    found = [user_code.describe(d) for d in sorted(
                 outside_negative_cases(user_code, user_code_reports[checker]))
             if d.file not in (user_code.canary, user_code.mistakes)]
    assert not found, f"{checker} (strict) on the docs' code and examples/:\n" + "\n".join(
        found)


@pytest.mark.parametrize("checker", CHECKERS)
def test_the_type_check_sees_mistakes(
        checker: Checker, user_code: UserCode,
        user_code_reports: Mapping[Checker, list[Diagnostic]]) -> None:
    said = user_code_reports[checker]
    lines = sorted({d.line for d in said if d.file == user_code.canary})
    assert lines == CANARY_LINES, [user_code.describe(d) for d in said]


def test_the_readme_table_shows_what_mypy_says(
        user_code: UserCode, user_code_reports: Mapping[Checker, list[Diagnostic]]) -> None:
    said: dict[int, str] = {}
    for diagnostic in user_code_reports["mypy"]:
        if diagnostic.file == user_code.mistakes and diagnostic.line not in said:
            said[diagnostic.line] = f"{diagnostic.message}  [{diagnostic.code}]"
    table = readme_table_messages()
    assert len(table) == len(MISTAKES)
    for number, (code, shown) in enumerate(zip(MISTAKES, table, strict=True)):
        actual = said.get(MISTAKES_FIRST_LINE + number)
        assert actual is not None, f"mypy says nothing of {code}"
        head, _, tail = shown.partition("…")
        if tail:
            assert actual.startswith(head) and actual.endswith(tail), (code, actual)
        else:
            assert actual == shown, (code, actual)
