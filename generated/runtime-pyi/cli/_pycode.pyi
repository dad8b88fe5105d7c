# Generated from src/typed_mjcf/cli/_pycode.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Python source text for ``to-python``: literals written the way a person types them, and
call statements laid out in lines of at most :data:`WIDTH` characters.

The layout is black's (and ruff's), so that either leaves the code as it is: a call on one line
if it fits; else its arguments together on an indented line; else one argument per line with a
trailing comma. The exception is bulk data: a tuple of many numbers too long for its line is
filled across lines, where black would put each number on a line of its own, and marked
``# fmt: off`` so that formatters keep it.
"""
from __future__ import annotations
from dataclasses import dataclass
from typing import Final
WIDTH: Final = 100
INDENT: Final = "    "
MAX_ONE_PER_LINE: Final = 12

@dataclass(frozen=True)
class Items:
    """A tuple literal: its items' text joined by ``", "`` (one string, not one per item:
    a mesh's million numbers cost their text, not a million objects), and how many."""
    text: str
    count: int
    @classmethod
    def of(cls, items: tuple[str, ...]) -> Items:
        """The literal of ``items`` (none holding ``", "``: numbers, keywords)."""
        ...
    def inline(self) -> str: ...
Value = str | Items

def inline(value: Value) -> str: ...

def string(text: str) -> str:
    """A string literal, in double quotes where that needs no escapes."""
    ...

def number(x: float) -> str:
    """A float as a person would type it: MJCF's spelling (``real_text``: ``1`` for
    1.0, ``0.1``) with a short exponent (``2e-6``); ``-0.0`` keeps its sign; infinities and
    NaN as ``math.inf`` and ``math.nan``. The export's precision does not apply: the code
    builds the model exactly."""
    ...

def identifier(text: str, fallback: str) -> str:
    """A Python name made from ``text`` (lower case, ``_`` for other characters); ``fallback``
    when nothing is left, and as a prefix when it would start with a digit."""
    ...

def call(indent: str, target: str | None, callee: str,
         arguments: list[tuple[str | None, Value]]) -> list[str]:
    """``[target = ]callee(arguments)`` laid out in lines of at most :data:`WIDTH`
    characters (where the values allow: a long string cannot be split), as black and ruff
    lay it out; a tuple of more than :data:`MAX_ONE_PER_LINE` numbers is filled across lines
    instead, between ``# fmt: off`` and ``# fmt: on``."""
    ...

def assignment(indent: str, target: str, prefix: str, text: str) -> list[str]:
    """``target = prefix "text"``, the string split after ``/`` over lines when too long."""
    ...

def fill(text: str, indent: str) -> list[str]:
    """Items (``text``: joined by ``", "``) as many to a line as fit, each line ending with
    a comma; an item longer than a line alone on its line."""
    ...
