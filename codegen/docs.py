"""The documentation of attributes: one line per attribute, written once, read everywhere.

``attribute_doc()`` is the one source: the renderer puts its text in ``elements.py`` (the
``doc`` of each attribute, which ``help()`` lists at run time) and in ``elements.pyi`` (the
attributes' docstrings and the ``Args:`` of each ``add_<tag>()``, which editors show).

The line says, first, what a checker cannot: the MJCF type, the allowed values or the number
of values, the default (what MuJoCo uses when the attribute is absent), then MuJoCo's note.

Editors read an ``Args:`` block line by line: pyright shows, for keyword ``p``, the first line
of the whole docstring containing ``p: `` (or ``p (``), and only that line. So each entry is
one line, a note never contains ``word: ``, and an attribute comes before any attribute whose
name ends with its name (``range`` before ``ctrlrange``). The layout of an ``add_<tag>()``
docstring is ``typed_mjcf._core.doclines.adder_listing``, which the run time uses too.
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Mapping
from typing import TYPE_CHECKING

from codegen import ir
from codegen.runtime import core_module
from codegen.typing_names import Typer

if TYPE_CHECKING:
    from typed_mjcf._core import doclines
else:  # the module alone, without the package's __init__ (see codegen/runtime.py)
    doclines = core_module("_core/doclines")

DOCS_URL = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"

# Notes in MuJoCo's grammar file that describe how MuJoCo itself saves, checks or lowers an
# attribute: true, but about MuJoCo's code, not about what the attribute means to a user.
_INTERNAL = re.compile(
    r"\bsav(?:e|ed)\b|validated|\bchecks?\b|enforced|directive|stored on|seeded|reader"
    r"|deprecation|lowers to|fans out|pairwise|when defined|flipped|set even when absent"
    r"|compiled values|family is|suffixed byte|whole-attribute|transmission target"
    r"|object kinds|node positions|projects into|ordering|UNTYPED")


def note(a: ir.AttributeDef) -> str | None:
    """MuJoCo's note on the attribute as a sentence, or None when it is about MuJoCo's code."""
    if not a.doc or _INTERNAL.search(a.doc):
        return None
    text = a.doc.replace(": ", " - ")  # "word: " would read as another entry to an editor
    return text[:1].upper() + text[1:] + ("" if text.endswith(".") else ".")


def attribute_doc(typer: Typer, a: ir.AttributeDef, releases: str | None = None) -> str:
    """One line: type, allowed values or length, default or required, pattern, bounds, the
    releases that have it (``releases``, when not every release covered does), note."""
    facts = [typer.describe(a)]
    if a.default is not None:
        facts.append(f'default "{a.default}"')
    elif a.required:
        facts.append("required")
    elif a.computed is not None:
        facts.append("default computed by MuJoCo")
    else:
        facts.append("no default (unset when absent)")
    if a.pattern is not None:
        facts.append(f"must match ``{a.pattern}``")
    if a.bounds:
        each = "each value " if a.arity is not None else ""
        facts.append(f"{each}{' and '.join(a.bounds)}")
    if releases is not None:
        facts.append(f"in {releases}")
    line = "; ".join(facts) + "."
    text = note(a)
    return f"{line} {text}" if text else line


def attribute_url(el: ir.ElementDef, a: ir.AttributeDef) -> str | None:
    anchor = a.anchor if a.anchor is not None else None
    return f"{DOCS_URL}#{anchor}" if anchor is not None else None


def escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace('"""', "'''")


def property_doc(typer: Typer, el: ir.ElementDef, a: ir.AttributeDef,
                 releases: str | None = None) -> str:
    """An attribute's docstring in a class body: ``name``: the line, then the link."""
    parts = [f"``{a.name}``: {attribute_doc(typer, a, releases)}"]
    url = attribute_url(el, a)
    if url is not None:
        parts.append(url)
    return textwrap.indent(escape("\n\n".join(parts)), " " * 4).strip() + "\n    "


def adder_doc(typer: Typer, el: ir.ElementDef, entries: dict[str, str]) -> str:
    """``add_<tag>()``'s docstring: the element, its link, ``Args:`` (one line each)."""
    url = f"{DOCS_URL}#{el.anchor}" if el.anchor is not None else None
    text = doclines.adder_listing(el.tag, url, entries)
    return textwrap.indent(escape(text), " " * 8).strip() + "\n        "


def adder_entries(typer: Typer, el: ir.ElementDef, dclass: str,
                  releases: Mapping[str, str] | None = None) -> dict[str, str]:
    """Keyword -> its line, for the attributes of ``el`` (and dm_control's ``dclass``);
    ``releases``: attribute -> the releases that have it, where not all do."""
    releases = {} if releases is None else releases
    entries = {a.py_name: attribute_doc(typer, a, releases.get(a.name)) for a in el.attributes}
    if any(a.name == dclass for a in el.attributes):
        entries["dclass"] = doclines.DCLASS_DOC
    return entries
