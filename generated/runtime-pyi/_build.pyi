# Generated from src/typed_mjcf/_build.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Which build runs: the pure-Python one, or the one whose hot modules mypyc compiled
(``TYPED_MJCF_COMPILE=1`` at wheel build; hatch_build.py). Both run the same source."""
from __future__ import annotations
from typing import TYPE_CHECKING, TypeVar
__all__ = ["compiled_modules", "describe", "mypyc_attr"]
_T = TypeVar("_T")
from mypy_extensions import mypyc_attr

def compiled_modules() -> tuple[str, ...]:
    """The loaded modules of typed_mjcf that are compiled extensions, sorted; ``()`` in the
    pure-Python build."""
    ...

def describe() -> str:
    """Which build runs, for ``typed-mjcf --version``: ``pure Python`` or ``compiled by
    mypyc: N modules``."""
    ...
