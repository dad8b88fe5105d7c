# Generated from src/typed_mjcf/cli/fmt.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``typed-mjcf fmt``: lay MJCF files out consistently, changing as little as it can.

By default fmt keeps what the author wrote: attributes in their order and spelling (numbers,
keywords, quotes aside: values are written in double quotes), start tags broken across lines
where the author broke them, elements where they are (repeated sections are not merged),
comments, processing instructions, stray text (MuJoCo ignores text) and ``<include>``
elements. It indents by two spaces per level, writes one element per line, keeps at most one
blank line in a row, and breaks a start tag longer than 100 characters before the attribute
that passes the width (aligned with its first attribute). ``--canonical`` writes instead what
typed-mjcf's exporter writes with ``canonical=True`` (attributes in grammar order, numbers in
the shortest text that reads back exactly, keywords in their grammar spelling, no empty
attributes or empty once-only sections, one line per start tag), keeping the same structure.
A model's included files are formatted with it, each in the context it is included in.
"""
from __future__ import annotations
import argparse
from dataclasses import dataclass
from typed_mjcf.cli._starttags import WIDTH, StartTag, indent_unit, lay_out, start_tags
from typed_mjcf.tooling import (
    INCLUDE,
    MAX_INDENT,
    ElementSpec,
    Rejected,
    escape,
    root_class,
    start_line,
)
NAME = "fmt"
HELP = ("lay MJCF files out consistently, keeping what was written (comments, spelling, "
        "order); --canonical rewrites them in the exporter's canonical form")
DESCRIPTION = """\
Lay MJCF files out consistently: two-space indentation, one element per line, at most one
blank line in a row, start tags longer than 100 characters broken before the attribute that
passes the width. What the author wrote is kept: attribute order and spelling ("0.10" stays
"0.10"), where a start tag was broken across lines, element order, repeated sections,
comments, <include> elements, and text inside elements (MJCF has none and MuJoCo ignores
it, but fmt does not drop it).

--canonical writes the canonical form instead (what to_xml_string(canonical=True) writes):
attributes in MuJoCo's grammar order, numbers in the shortest form that reads back exactly
("0.10" -> "0.1", "1.0" -> "1"), keywords in their grammar spelling, one line per start tag;
empty attributes and empty once-only sections (<compiler/>) are dropped.

The files a model includes are formatted too, each in the place it is included. The result
compiles to the same model, and formatting it again changes nothing.

exit status: 0 formatted (or nothing to change), 1 with --check: some file would change,
2 a file cannot be read as MJCF (other files are still formatted)."""

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

@dataclass
class Formatted:
    """One file: its path, its text now, and its canonical text."""
    path: str
    before: bytes
    after: str
    @property
    def changed(self) -> bool: ...

def run(args: argparse.Namespace) -> int: ...

def unified_diff(result: Formatted) -> str: ...

def format_model(path: str, seen: set[str] | None = None, canonical: bool = False,
                 width: int = WIDTH) -> list[Formatted]:
    """The formatted text (the canonical text with ``canonical``) of a model's file and of
    every file it includes (each once, also across calls sharing ``seen``); raises
    :class:`BadInput` if one cannot be read."""
    ...

def format_file(path: str, context: ElementSpec | None = None, canonical: bool = False,
                width: int = WIDTH) -> Formatted:
    """The formatted (or canonical) text of one file; ``context`` is the row its top-level
    elements belong to when it is included (its root ``<mujoco>`` then stands for the
    including element)."""
    ...
