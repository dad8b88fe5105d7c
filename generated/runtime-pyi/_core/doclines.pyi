# Generated from src/typed_mjcf/_core/doclines.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""How an ``add_<tag>()`` docstring is laid out: one function, for ``help()`` and editors.

The generator writes each attribute's one line (``codegen/docs.py``); this module lays the
lines out: the head, the reference, ``Args:`` in :func:`doc_order`. The run time uses it for
the docstrings ``help()`` shows, and the generator (which loads this module by its path) for
the ``Args:`` of ``elements.pyi`` that editors show, so the two cannot disagree. It imports
nothing from the package.
"""
from __future__ import annotations
from collections.abc import Mapping
from typing import Final
DCLASS_DOC: Final = "dm_control's name for ``class_``."

def doc_order(names: list[str]) -> list[str]:
    """``names`` in order, except that a name comes before every name ending with it: an
    editor shows keyword ``p`` the first line containing ``p: ``, which must be its own."""
    ...

def adder_listing(tag: str, url: str | None, entries: Mapping[str, str]) -> str:
    """``add_<tag>()``'s docstring: what it does, the reference, then ``Args:`` with each
    keyword's one line."""
    ...
