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

import importlib.util
import re
from collections.abc import Mapping
from pathlib import Path

import pytest

from tests.support.doc_blocks import (
    BLOCKS,
    EXAMPLES,
    MISTAKES_PAGE,
    README,
    Block,
    needs_warp,
    page_blocks,
    run_block,
)
from tests.support.typecheck import CHECKERS, NEGATIVE_FILES, Checker, Diagnostic
from tests.support.user_code import CANARY_LINES, MISTAKES, MISTAKES_FIRST_LINE, UserCode


@pytest.mark.parametrize("block", BLOCKS, ids=[b.name for b in BLOCKS])
def test_documented_example_runs(block: Block, tmp_path: Path,
                                 monkeypatch: pytest.MonkeyPatch) -> None:
    if needs_warp(block) and importlib.util.find_spec("mujoco_warp") is None:
        pytest.skip("needs MuJoCo Warp (the warp extra): nox -s warp runs it "
                    "(tests/warp/test_docs.py)")
    run_block(block, tmp_path, monkeypatch)


def test_the_pages_have_examples() -> None:
    assert len(page_blocks(README)) >= 3
    assert {b.source for b in BLOCKS} > {README}
    assert len(EXAMPLES) >= 4


# ----------------------------------------------------------------------------- type checks


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
