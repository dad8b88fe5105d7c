"""The corpus the CLI tests run over (the one tests/runtime/test_corpus.py finds: the MJCF
models packaged with dm_control and mujoco), MuJoCo's own compile of each, and a writable
mirror of the packages for commands that rewrite files."""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
from pathlib import Path

import pytest

from tests.runtime.test_corpus import CORPUS, CORPUS_PACKAGES, compiled

__all__ = ["CORPUS", "compiled", "corpus_params", "mirror", "module_name"]


def corpus_params() -> list[object]:
    return [pytest.param(ident, path, id=ident) for ident, path in CORPUS]


def module_name(ident: str) -> str:
    """A Python module file name for a corpus file (unique: the corpus path, flattened)."""
    return re.sub(r"\W", "_", ident.removesuffix(".xml")) + ".py"


def mirror(folder: Path) -> Path:
    """A copy of the corpus packages in ``folder``: the XML files copied (to be rewritten),
    every other file a link to the original. A corpus file ``ident`` is at ``folder/ident``."""
    for package in CORPUS_PACKAGES:
        spec = importlib.util.find_spec(package)
        assert spec is not None and spec.submodule_search_locations is not None
        base = Path(next(iter(spec.submodule_search_locations)))
        for here, _, files in os.walk(base):
            target = folder / package / Path(here).relative_to(base)
            target.mkdir(parents=True, exist_ok=True)
            for name in files:
                if name.endswith(".xml"):
                    shutil.copyfile(Path(here) / name, target / name)
                else:
                    (target / name).symlink_to(Path(here) / name)
    return folder
