"""The README's Python examples and the scripts in ``examples/``, as a user meets them.

- every Python block of the README runs and prints what the README says it prints;
- the README's blocks (each written to a module of its own) and every file in ``examples/``
  are clean under ``mypy --strict`` and pyright strict, with no configuration but that: one
  mypy run and one pyright run over all of them, from a folder outside the repository, so
  that what is checked is what a user's own script would see (the installed ``typed_mjcf``
  and its ``mujoco`` stubs, none of this repository's settings).

The examples' behaviour when run is tested in ``test_examples.py``.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.typing.test_typecheck import (
    CHECKERS,
    MYPY_OUTPUT,
    Checker,
    Diagnostic,
    run_checkers,
)

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
EXAMPLES = sorted((ROOT / "examples").glob("*.py"))


@dataclass(frozen=True)
class Block:
    """A fenced Python block of the README."""

    code: str
    line: int  # the README's line number of the block's first line of code


def readme_blocks() -> list[Block]:
    text = README.read_text(encoding="utf-8")
    return [Block(match[1], text.count("\n", 0, match.start(1)) + 1)
            for match in re.finditer(r"```python\n(.*?)```", text, re.DOTALL)]


BLOCKS = readme_blocks()


@pytest.mark.parametrize("block", BLOCKS, ids=[f"line{b.line}" for b in BLOCKS])
def test_readme_example_runs(block: Block, tmp_path: Path,
                             monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # what an example writes (an image) lands there
    expected = [line[2:] for line in block.code.splitlines() if line.startswith("# ")]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile("\n" * (block.line - 1) + block.code, str(README), "exec"), {})
    for line in expected:
        assert line in out.getvalue()


def test_readme_has_examples() -> None:
    assert len(BLOCKS) >= 3
    assert len(EXAMPLES) >= 4


# ----------------------------------------------------------------------------- type checks


@dataclass(frozen=True)
class Checked:
    """What the checkers said, and where each checked file's lines come from."""

    diagnostics: Mapping[Checker, list[Diagnostic]]
    origin: Mapping[Path, tuple[Path, int]]  # checked file -> (file shown, line offset)
    canary: Path
    mistakes: Path

    def describe(self, diagnostic: Diagnostic) -> str:
        shown, offset = self.origin.get(diagnostic.file, (diagnostic.file, 0))
        name = shown.relative_to(ROOT) if shown.is_relative_to(ROOT) else shown
        first = diagnostic.message.splitlines()[0]
        return f"{name}:{diagnostic.line + offset}: [{diagnostic.code}] {first}"


def commands(folder: Path, files: list[Path]) -> dict[Checker, list[str]]:
    """Each checker in its strict mode and otherwise its defaults (the configuration files
    in ``folder`` say only that), so that the repository's settings play no part."""
    (folder / "mypy.ini").write_text("[mypy]\n", encoding="utf-8")
    (folder / "pyrightconfig.json").write_text(json.dumps({"typeCheckingMode": "strict"}),
                                               encoding="utf-8")
    paths = [str(f) for f in files]
    return {
        "mypy": [sys.executable, "-m", "mypy", "--strict",
                 "--config-file", str(folder / "mypy.ini"),
                 "--cache-dir", str(folder / ".mypy_cache"), *MYPY_OUTPUT, *paths],
        "pyright": [sys.executable, "-m", "pyright", "--outputjson",
                    "--project", str(folder / "pyrightconfig.json"),
                    "--pythonpath", sys.executable, *paths],
    }


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
    """The typed-mjcf column of the README's table of mistakes, in its order."""
    text = README.read_text(encoding="utf-8")
    section = text.split("## What the type checker catches", 1)[1].split("\n#", 1)[0]
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


@pytest.fixture(scope="module")
def checked(tmp_path_factory: pytest.TempPathFactory) -> Checked:
    folder = tmp_path_factory.mktemp("user_code")
    origin: dict[Path, tuple[Path, int]] = {}
    for number, block in enumerate(BLOCKS):
        module = folder / f"readme_block{number}.py"
        module.write_text(block.code, encoding="utf-8")
        origin[module.resolve()] = (README, block.line - 1)
    for example in EXAMPLES:
        origin[example] = (example, 0)
    canary = folder / "canary.py"
    canary.write_text(CANARY, encoding="utf-8")
    origin[canary.resolve()] = (canary.resolve(), 0)
    mistakes = folder / "mistakes.py"
    mistakes.write_text(MISTAKES_MODULE, encoding="utf-8")
    origin[mistakes.resolve()] = (mistakes.resolve(), 0)
    return Checked(run_checkers(commands(folder, list(origin)), folder), origin,
                   canary.resolve(), mistakes.resolve())


@pytest.mark.parametrize("checker", CHECKERS)
def test_readme_and_examples_type_check(checker: Checker, checked: Checked) -> None:
    """No error and no warning (errors inside the library would count too)."""
    found = [checked.describe(d) for d in sorted(checked.diagnostics[checker])
             if d.file not in (checked.canary, checked.mistakes)]
    assert not found, f"{checker} (strict) on the README's code and examples/:\n" + "\n".join(
        found)


@pytest.mark.parametrize("checker", CHECKERS)
def test_the_type_check_sees_mistakes(checker: Checker, checked: Checked) -> None:
    lines = sorted({d.line for d in checked.diagnostics[checker] if d.file == checked.canary})
    assert lines == CANARY_LINES, [checked.describe(d) for d in checked.diagnostics[checker]]


def test_the_readme_table_shows_what_mypy_says(checked: Checked) -> None:
    said: dict[int, str] = {}
    for diagnostic in checked.diagnostics["mypy"]:
        if diagnostic.file == checked.mistakes and diagnostic.line not in said:
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
