# Generated from src/typed_mjcf/cli/_starttags.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Start tags as the author wrote them, for ``fmt``: each attribute's text as written (quotes,
entities, spelling, the spaces before it) and where the author broke the tag across lines,
and laying a start tag out within a width, keeping those breaks.

The XML parser gives values, not how they were written; a scan of the text gives the start
tags in document order, which is the order of the parsed tree's elements (comments,
processing instructions, CDATA, the DOCTYPE and end tags are skipped; MJCF declares no
entities, so none expands into elements).
"""
from __future__ import annotations
from dataclasses import dataclass
from typing import Final
WIDTH: Final = 100

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
    ...

def indent_unit(tags: list[StartTag]) -> str:
    """The file's indentation step: the whitespace before the root's first child (two spaces
    when it is not a plausible step: the child on the root's line, or deeper than 8)."""
    ...

def lay_out(indent: str, opening: str, attributes: list[Written], closing: str,
            width: int = WIDTH) -> list[str]:
    """The lines of a start tag: ``indent + opening`` (``<tag``), then each attribute, after
    the spaces written before it, or on a new line where the author broke the tag (with the
    author's whitespace beyond the tag's indentation) or where the next one would
    pass ``width`` (aligned with the tag's first attribute, or four spaces in if that is
    far), then ``closing``."""
    ...
