"""The documentation's MuJoCo Warp examples run (``nox -s tests`` skips them without the
extra; tests/test_readme.py type-checks them there)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.doc_blocks import BLOCKS, Block, needs_warp, run_block

WARP_BLOCKS = [block for block in BLOCKS if needs_warp(block)]


def test_the_docs_have_warp_examples() -> None:
    assert len(WARP_BLOCKS) >= 1


@pytest.mark.parametrize("block", WARP_BLOCKS, ids=[b.name for b in WARP_BLOCKS])
def test_documented_warp_example_runs(block: Block, tmp_path: Path,
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    run_block(block, tmp_path, monkeypatch)
