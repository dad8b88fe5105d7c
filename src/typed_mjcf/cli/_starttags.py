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
    on the line of the attribute before it, or, when the author put it on a new line, the
    whitespace that line starts with beyond the tag's own indentation (``broken_at``)."""

    text: str
    space: str = " "
    broken_at: str | None = None


@dataclass(frozen=True)
class StartTag:
    """One start tag as written: the whitespace before it on its line (``None`` when
    something else is before it there), its attributes, the spaces before ``>``."""

    lead: str | None
    attributes: list[Written]
    closing_space: str = ""


def start_tags(data: bytes) -> list[StartTag]:
    """Every start tag of ``data``, in document order."""
    tags: list[StartTag] = []
    # Each byte is looked at once (a scan back to the line's start per tag, and a copy of
    # the line before it, were quadratic on a line of many tags): where the current line
    # starts and where the token before ends are carried along.
    line_start = searched = previous_end = 0
    for match in _TOKEN.finditer(data):
        start = match.start()
        newline = data.rfind(b"\n", searched, start)
        if newline >= 0:
            line_start = newline + 1
        searched, end_before = start, previous_end
        previous_end = match.end()
        if match.group(1) is None:
            continue
        if end_before > line_start:  # a token before it on its line
            lead = None
        else:  # only text between tokens: each byte copied once
            before = data[line_start:start]
            lead = _spaces(before, "") if not before.strip() else None
        attributes: list[Written] = []
        inside = match.group(2)
        end = 0
        for attribute in _ATTRIBUTE.finditer(inside):
            space, name, value = attribute.groups()
            end = attribute.end()
            text = f"{name.decode('utf-8', 'replace')}={value.decode('utf-8', 'replace')}"
            if b"\n" in space:
                attributes.append(Written(text, broken_at=_beyond(
                    _spaces(space[space.rfind(b"\n") + 1:], ""), lead or "")))
            else:
                attributes.append(Written(text, _spaces(space)))
        rest = inside[end:].rstrip(b"/")
        tags.append(StartTag(lead, attributes, "" if b"\n" in rest else _spaces(rest, "")))
    return tags


def _beyond(line_lead: str, tag_lead: str) -> str:
    """A continuation line's whitespace beyond the tag's (as written when it starts with the
    tag's; else as spaces past the tag's width, tabs counted as one), at least two spaces."""
    if line_lead.startswith(tag_lead) and len(line_lead) > len(tag_lead):
        extra = line_lead[len(tag_lead):]
    else:
        extra = " " * (len(line_lead) - len(tag_lead))
    return extra if len(extra.expandtabs(4)) >= 2 else "  "


def _spaces(space: bytes, least: str = " ") -> str:
    """Spaces as written between two things on one line (tabs and all), or ``least``."""
    text = space.decode("ascii", "replace")
    return text if text and not text.strip() else least


def indent_unit(tags: list[StartTag]) -> str:
    """The file's indentation step: the whitespace before the root's first child (two spaces
    when it is not a plausible step: the child on the root's line, or deeper than 8)."""
    lead = tags[1].lead if len(tags) > 1 else None
    if lead and (set(lead) == {"\t"} and len(lead) <= 2 or set(lead) == {" "} and len(lead) <= 8):
        return lead
    return "  "


def lay_out(indent: str, opening: str, attributes: list[Written], closing: str,
            width: int = WIDTH) -> list[str]:
    """The lines of a start tag: ``indent + opening`` (``<tag``), then each attribute, after
    the spaces written before it, or on a new line where the author broke the tag (with the
    author's whitespace beyond the tag's indentation) or where the next one would
    pass ``width`` (aligned with the tag's first attribute, or four spaces in if that is
    far), then ``closing``."""
    align = len(opening) + 1 if len(indent) + len(opening) + 1 <= width // 2 else 4
    lines = [indent + opening]
    for written in attributes:
        text = written.text
        if written.broken_at is not None:
            lines.append(indent + written.broken_at + text)
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
