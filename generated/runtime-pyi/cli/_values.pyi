# Generated from src/typed_mjcf/cli/_values.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Attribute values as canonical text: what ``fmt`` writes and what ``diff`` compares.

The canonical form is the exporter's ``canonical=True`` form: each value through its
attribute's codec (numbers in the shortest text that reads back exactly, keywords in their
grammar spelling, flags in grammar order); names, references and file paths as written.
"""
from __future__ import annotations
from typing import Final
from typed_mjcf.tooling import AttributeSpec, Element, Format, ModelBase, grammar_facts
CANONICAL: Final = Format(canonical=True)

def canonical_text(attribute: AttributeSpec, text: str) -> str | None:
    """Attribute text read from a file, in canonical form (``None`` for empty text, which
    MuJoCo reads as absent); raises :class:`~typed_mjcf.tooling.Rejected`."""
    ...

def value_text(attribute: AttributeSpec, value: object) -> str | None:
    """A value as users read it (``element.attr``, ``resolve()``), as canonical text."""
    ...

def reference_name(target: Element) -> str:
    """The name a reference to ``target`` writes (a model's top default class: ``main``)."""
    ...

def stored_text(element: Element, attribute: AttributeSpec) -> str | None:
    """The canonical text of one attribute as set on ``element``."""
    ...
