"""The documentation's Python blocks (the README's and the hand-written pages of ``docs/``),
the generated MJCF reference's examples as one module, and the scripts of ``examples/``;
running a block as a test does."""

from __future__ import annotations

import contextlib
import io
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
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
