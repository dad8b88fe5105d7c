"""Which build runs: ``typed_mjcf.COMPILED`` names the modules mypyc compiled (none in the
pure-Python build), and in the compiled run (``nox -s tests_compiled``, which sets
``TYPED_MJCF_EXPECT_COMPILED=1``) they are exactly pyproject's list, loaded as extensions."""

from __future__ import annotations

import importlib
import os
import sys
import tomllib
from importlib.machinery import EXTENSION_SUFFIXES
from pathlib import Path

import typed_mjcf

PYPROJECT = Path(__file__).resolve().parents[2] / "pyproject.toml"


def _listed() -> set[str]:
    """The modules pyproject's build hook compiles, by their full names."""
    hook = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["tool"]["hatch"]["build"][
        "targets"]["wheel"]["hooks"]["custom"]
    return {f"typed_mjcf.{module}" for module in hook["modules"]}


def _is_extension(name: str) -> bool:
    return str(importlib.import_module(name).__file__).endswith(tuple(EXTENSION_SUFFIXES))


def test_compiled_names_the_loaded_extension_modules_and_no_others() -> None:
    loaded = [name for name in sys.modules if name.startswith("typed_mjcf.")]
    assert sorted(name for name in loaded if _is_extension(name)) == list(typed_mjcf.COMPILED)


def test_the_build_is_the_one_the_run_expects() -> None:
    if os.environ.get("TYPED_MJCF_EXPECT_COMPILED") == "1":
        assert set(typed_mjcf.COMPILED) == _listed()
        assert all(_is_extension(name) for name in _listed())
        # the pure-Python twin ships beside each compiled module (help(), tracebacks' source)
        assert all(Path(str(importlib.import_module(name).__file__)).with_name(
            name.rpartition(".")[2] + ".py").is_file() for name in _listed())
    else:
        assert typed_mjcf.COMPILED == ()
        assert not any(_is_extension(name) for name in _listed())
