"""Python source text for ``to-python``: literals written the way a person types them, and
call statements laid out in lines of at most :data:`WIDTH` characters.

The layout is black's (and ruff's), so that either leaves the code as it is: a call on one line
if it fits; else its arguments together on an indented line; else one argument per line with a
trailing comma. The exception is bulk data: a tuple of many numbers too long for its line is
filled across lines, where black would put each number on a line of its own, and marked
``# fmt: off`` so that formatters keep it.
"""

from __future__ import annotations

import keyword
import math
import re
from dataclasses import dataclass
from typing import Final

from typed_mjcf import tooling

WIDTH: Final = 100
INDENT: Final = "    "
MAX_ONE_PER_LINE: Final = 12  # numbers: a longer tuple that must split is filled instead

_EXPONENT = re.compile(r"e([+-])0*(\d)")


@dataclass(frozen=True)
class Items:
    """A tuple literal: its items' text joined by ``", "`` (one string, not one per item:
    a mesh's million numbers cost their text, not a million objects), and how many."""

    text: str
    count: int

    @classmethod
    def of(cls, items: tuple[str, ...]) -> Items:
        """The literal of ``items`` (none holding ``", "``: numbers, keywords)."""
        return cls(", ".join(items), len(items))

    def inline(self) -> str:
        return f"({self.text},)" if self.count == 1 else f"({self.text})"


Value = str | Items  # an expression's text, or a tuple that may be filled across lines


def inline(value: Value) -> str:
    return value if isinstance(value, str) else value.inline()


def string(text: str) -> str:
    """A string literal, in double quotes where that needs no escapes."""
    literal = repr(text)
    if literal.startswith("'") and '"' not in text:
        return '"' + literal[1:-1].replace("\\'", "'") + '"'
    return literal


def number(x: float) -> str:
    """A float as a person would type it: MJCF's spelling (``real_text``: ``1`` for
    1.0, ``0.1``) with a short exponent (``2e-6``); ``-0.0`` keeps its sign; infinities and
    NaN as ``math.inf`` and ``math.nan``. The export's precision does not apply: the code
    builds the model exactly."""
    if math.isnan(x):
        return "math.nan"
    if math.isinf(x):
        return "math.inf" if x > 0 else "-math.inf"
    if x == 0 and math.copysign(1.0, x) < 0:
        return "-0.0"
    text = tooling.real_text((x,))  # looked up at each call: one spelling, the codec's
    return _EXPONENT.sub(lambda m: f"e{'-' if m.group(1) == '-' else ''}{m.group(2)}", text)


def identifier(text: str, fallback: str) -> str:
    """A Python name made from ``text`` (lower case, ``_`` for other characters); ``fallback``
    when nothing is left, and as a prefix when it would start with a digit."""
    name = re.sub(r"\W+", "_", text.lower(), flags=re.ASCII).strip("_")
    if not name:
        return fallback
    if name[0].isdigit():
        name = f"{fallback}_{name}"
    if keyword.iskeyword(name):
        name += "_"
    return name


def call(indent: str, target: str | None, callee: str,
         arguments: list[tuple[str | None, Value]]) -> list[str]:
    """``[target = ]callee(arguments)`` laid out in lines of at most :data:`WIDTH`
    characters (where the values allow: a long string cannot be split), as black and ruff
    lay it out; a tuple of more than :data:`MAX_ONE_PER_LINE` numbers is filled across lines
    instead, between ``# fmt: off`` and ``# fmt: on``."""
    head = f"{indent}{target} = {callee}(" if target else f"{indent}{callee}("
    texts = [_argument(name, inline(value)) for name, value in arguments]
    joined = ", ".join(texts)
    if len(head) + len(joined) + 1 <= WIDTH:
        return [f"{head}{joined})"]
    inner = indent + INDENT
    if len(inner) + len(joined) <= WIDTH:
        return [head, inner + joined, f"{indent})"]
    # one argument per line, with a trailing comma (but none after a sole argument)
    comma = "," if len(arguments) > 1 else ""
    lines = [head]
    filled = False
    for (name, value), text in zip(arguments, texts, strict=True):
        if len(inner) + len(text) + len(comma) <= WIDTH or not isinstance(value, Items):
            lines.append(f"{inner}{text}{comma}")
            continue
        lines.append(f"{inner}{_argument(name, '(')}")
        if value.count > MAX_ONE_PER_LINE:
            lines += fill(value.text, inner + INDENT)
            filled = True
        else:
            lines += [f"{inner}{INDENT}{item}," for item in value.text.split(", ")]
        lines.append(f"{inner}){comma}")
    lines.append(f"{indent})")
    if filled:
        return [f"{indent}# fmt: off", *lines, f"{indent}# fmt: on"]
    return lines


def assignment(indent: str, target: str, prefix: str, text: str) -> list[str]:
    """``target = prefix "text"``, the string split after ``/`` over lines when too long."""
    line = f"{indent}{target} = {prefix} {string(text)}"
    if len(line) <= WIDTH:
        return [line]
    inner = indent + INDENT
    parts: list[str] = []
    current = ""
    for piece in re.split(r"(?<=/)", text):
        if current and len(inner) + len(string(current + piece)) > WIDTH:
            parts.append(current)
            current = ""
        current += piece
    parts.append(current)
    return [f"{indent}{target} = {prefix} (", *(inner + string(p) for p in parts), f"{indent})"]


def _argument(name: str | None, text: str) -> str:
    return text if name is None else f"{name}={text}"


def fill(text: str, indent: str) -> list[str]:
    """Items (``text``: joined by ``", "``) as many to a line as fit, each line ending with
    a comma; an item longer than a line alone on its line."""
    lines: list[str] = []
    room = WIDTH - len(indent) - 1  # the line's items, before its comma
    start = 0
    while start < len(text):
        if len(text) - start <= room:
            end = len(text)
        else:  # the last separator that lets the line fit, else the item alone
            end = text.rfind(", ", start, start + room + 2)
            if end < 0:
                end = text.find(", ", start)
                end = len(text) if end < 0 else end
        lines.append(f"{indent}{text[start:end]},")
        start = end + 2
    return lines
