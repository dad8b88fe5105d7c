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

# The line of dm_control's keyword for the class attribute (``dclass``, beside ``class_``).
DCLASS_DOC: Final = "dm_control's name for ``class_``."


def doc_order(names: list[str]) -> list[str]:
    """``names`` in order, except that a name comes before every name ending with it: an
    editor shows keyword ``p`` the first line containing ``p: ``, which must be its own."""
    placed: list[str] = []
    for name in names:
        at = next((i for i, other in enumerate(placed)
                   if other != name and other.endswith(name)), len(placed))
        placed.insert(at, name)
    return placed


def adder_listing(tag: str, url: str | None, entries: Mapping[str, str]) -> str:
    """``add_<tag>()``'s docstring: what it does, the reference, then ``Args:`` with each
    keyword's one line."""
    lines = [f"Add a ``<{tag}>`` child and return it."]
    if url:
        lines += ["", f"Reference: {url}"]
    if entries:
        lines += ["", "Args:", *(f"    {name}: {entries[name]}"
                                 for name in doc_order(list(entries)))]
    return "\n".join(lines)
