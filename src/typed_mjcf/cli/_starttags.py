"""Start tags as the author wrote them, for ``fmt``: each attribute's text as written (quotes,
entities, spelling, the spaces before it) and where the author broke the tag across lines,
and laying a start tag out within a width, keeping those breaks.

The XML parser gives values, not how they were written; a scan of the text gives the start
tags in document order, which is the order of the parsed tree's elements (comments,
processing instructions, CDATA, the DOCTYPE and end tags are skipped; MJCF declares no
entities, so none expands into elements).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Final

WIDTH: Final = 100  # the longest line fmt writes where it can break a start tag

_TOKEN: Final = re.compile(
    rb"<!--.*?-->|<\?.*?\?>|<!\[CDATA\[.*?\]\]>|<!DOCTYPE(?:[^\[>]|\[.*?\])*>|</[^>]*>"
    rb"|<([^\s/>!?]+)((?:[^>\"']|\"[^\"]*\"|'[^']*')*)>", re.DOTALL)
_ATTRIBUTE: Final = re.compile(rb"(\s*)([^\s=/>]+)\s*=\s*(\"[^\"]*\"|'[^']*')")


@dataclass(frozen=True)
class Written:
    """One attribute as written: its ``name="value"`` text, the spaces before it when it is
    on the line of the attribute before it, or the column the author's line starts at
    relative to the tag's ``<`` when the author put it on a new line."""

    text: str
    space: str = " "
    broken_at: int | None = None


@dataclass(frozen=True)
class StartTag:
    """One start tag as written: its column (``None`` when something else is before it on its
    line), its attributes, the spaces before ``>``."""

    column: int | None
    attributes: list[Written]
    closing_space: str = ""


def start_tags(data: bytes) -> list[StartTag]:
    """Every start tag of ``data``, in document order."""
    tags: list[StartTag] = []
    for match in _TOKEN.finditer(data):
        if match.group(1) is None:
            continue
        line_start = data.rfind(b"\n", 0, match.start()) + 1
        column = match.start() - line_start
        attributes: list[Written] = []
        inside = match.group(2)
        end = 0
        for attribute in _ATTRIBUTE.finditer(inside):
            space, name, value = attribute.groups()
            end = attribute.end()
            text = f"{name.decode('utf-8', 'replace')}={value.decode('utf-8', 'replace')}"
            if b"\n" in space:
                attributes.append(Written(text, broken_at=len(space) - space.rfind(b"\n")
                                          - 1 - column))
            else:
                attributes.append(Written(text, _spaces(space)))
        rest = inside[end:].rstrip(b"/")
        alone = not data[line_start:match.start()].strip()
        tags.append(StartTag(column if alone else None, attributes,
                             "" if b"\n" in rest else _spaces(rest, "")))
    return tags


def _spaces(space: bytes, least: str = " ") -> str:
    """Spaces as written between two things on one line (tabs and all), or ``least``."""
    text = space.decode("ascii", "replace")
    return text if text and not text.strip() else least


def indent_unit(tags: list[StartTag]) -> int:
    """The file's indentation step: the column of the root's first child (2 when it is
    not a plausible step: the child on the root's line, or indented by tabs)."""
    column = tags[1].column if len(tags) > 1 else None
    return column if column is not None and 1 <= column <= 8 else 2


def lay_out(indent: str, opening: str, attributes: list[Written], closing: str,
            width: int = WIDTH) -> list[str]:
    """The lines of a start tag: ``indent + opening`` (``<tag``), then each attribute, after
    the spaces written before it, or on a new line where the author broke the tag (at the
    author's column relative to the tag, at least two spaces in) or where the next one would
    pass ``width`` (aligned with the tag's first attribute, or four spaces in if that is
    far), then ``closing``."""
    align = len(opening) + 1 if len(indent) + len(opening) + 1 <= width // 2 else 4
    lines = [indent + opening]
    for written in attributes:
        text = written.text
        if written.broken_at is not None:
            lines.append(indent + " " * max(written.broken_at, 2) + text)
            continue
        line = lines[-1]
        current = line.rsplit("\n", 1)[-1]  # a value written across lines: its last line
        first = line == indent + opening  # the first attribute stays on the tag's line
        if first or len(current) + len(written.space) + len(text.split("\n", 1)[0]) <= width:
            lines[-1] = f"{line}{written.space}{text}"
        else:
            lines.append(indent + " " * align + text)
    lines[-1] += closing
    return lines
