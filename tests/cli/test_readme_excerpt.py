"""The ``to-python`` excerpt of docs/guide/cli.md is real: what the command writes for dm_control's
``suite/cartpole.xml``, line for line (``...`` stands for lines left out)."""

from __future__ import annotations

import re
from pathlib import Path

import typed_mjcf as mjcf
from tests.support.corpus import CORPUS
from typed_mjcf.cli.to_python import to_python

PAGE = Path(__file__).resolve().parents[2] / "docs" / "guide" / "cli.md"


def _excerpt() -> list[list[str]]:
    """The excerpt's runs of lines (split where ``...`` leaves lines out)."""
    section = PAGE.read_text(encoding="utf-8")
    block = re.search(r"```console\n\$ typed-mjcf to-python cartpole.xml.*?\n\$ sed[^\n]*\n"
                      r"(.*?)```", section, re.DOTALL)
    assert block is not None
    runs: list[list[str]] = [[]]
    for line in block.group(1).splitlines():
        if line == "...":
            runs.append([])
        else:
            runs[-1].append(line)
    return runs


def test_the_excerpt_is_what_to_python_writes() -> None:
    path = next(p for ident, p in CORPUS if ident == "dm_control/suite/cartpole.xml")
    written = to_python(mjcf.from_path(path), str(path.parent)).splitlines()
    runs = _excerpt()
    assert sum(len(run) for run in runs) > 20
    start = 0
    for run in runs:
        found = next((i for i in range(start, len(written)) if written[i:i + len(run)] == run),
                     None)
        assert found is not None, run
        start = found + len(run)
