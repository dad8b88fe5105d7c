"""to-python's code of the corpus: a module per corpus model MuJoCo compiles, checked by the
session's one mypy and pyright run (``tests/conftest.py``'s ``typed_code_run``)."""

from __future__ import annotations

from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.support.corpus import CORPUS, SEPARATORS, compiled, module_name
from typed_mjcf.cli.to_python import to_python


def corpus_modules(folder: Path) -> list[Path]:
    """``to_python`` of every corpus model MuJoCo compiles, a module each in ``folder``."""
    written: list[Path] = []
    for ident, path in CORPUS:
        if ident == SEPARATORS:
            continue
        try:
            compiled(ident, path)
        except pytest.skip.Exception:
            continue
        module = folder / module_name(ident)
        module.write_text(to_python(mjcf.from_path(path), str(folder)), encoding="utf-8")
        written.append(module)
    return written
