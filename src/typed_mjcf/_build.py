"""Which build runs: the pure-Python one, or the one whose hot modules mypyc compiled
(``TYPED_MJCF_COMPILE=1`` at wheel build; hatch_build.py). Both run the same source."""

from __future__ import annotations

import sys
from collections.abc import Callable
from importlib.machinery import EXTENSION_SUFFIXES
from typing import TYPE_CHECKING, TypeVar

__all__ = ["compiled_modules", "describe", "mypyc_attr"]

_T = TypeVar("_T")

if TYPE_CHECKING:
    # mypyc reads the decorator by its name in mypy_extensions; at run time it is the no-op
    # below, so neither build needs mypy_extensions installed
    from mypy_extensions import mypyc_attr
else:

    def mypyc_attr(*attrs: str, **kwattrs: object) -> Callable[[_T], _T]:
        """mypyc's class options (``native_class=False``: an ordinary Python class whose
        methods are compiled); nothing to do when interpreted."""
        return lambda cls: cls


def compiled_modules() -> tuple[str, ...]:
    """The loaded modules of typed_mjcf that are compiled extensions, sorted; ``()`` in the
    pure-Python build."""
    return tuple(sorted(
        name for name, module in list(sys.modules.items())
        if (name == "typed_mjcf" or name.startswith("typed_mjcf."))
        and not name.endswith("__mypyc")  # mypyc's shared library (one per module, if separate)
        and str(getattr(module, "__file__", None) or "").endswith(tuple(EXTENSION_SUFFIXES))))


def describe() -> str:
    """Which build runs, for ``typed-mjcf --version``: ``pure Python`` or ``compiled by
    mypyc: N modules``."""
    compiled = compiled_modules()
    return f"compiled by mypyc: {len(compiled)} modules" if compiled else "pure Python"
