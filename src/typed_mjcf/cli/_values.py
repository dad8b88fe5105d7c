"""Attribute values as canonical text: what ``fmt`` writes and what ``diff`` compares.

The canonical form is the exporter's ``canonical=True`` form: each value through its
attribute's codec (numbers in the shortest text that reads back exactly, keywords in their
grammar spelling, flags in grammar order); names, references and file paths as written.
"""

from __future__ import annotations

from typing import Final

from typed_mjcf import tooling
from typed_mjcf.assets import Asset
from typed_mjcf.tooling import AttributeSpec, Element, Format, ModelBase, grammar_facts

CANONICAL: Final = Format(canonical=True)


def canonical_text(attribute: AttributeSpec, text: str) -> str | None:
    """Attribute text read from a file, in canonical form (``None`` for empty text, which
    MuJoCo reads as absent); raises :class:`~typed_mjcf.tooling.Rejected`."""
    if not text:
        return None
    if attribute.direct and attribute.kind != "file":
        return attribute.codec.write(attribute.codec.parse(text), CANONICAL)
    return text


def value_text(attribute: AttributeSpec, value: object) -> str | None:
    """A value as users read it (``element.attr``, ``resolve()``), as canonical text."""
    if value is None:
        return None
    if isinstance(value, Element):
        return reference_name(value)
    if isinstance(value, Asset):
        return f"<in-memory file {value.name or ''}{value.extension}>"
    if isinstance(value, str) and not attribute.direct or attribute.kind == "file":
        return str(value)
    return attribute.codec.write(attribute.codec.accept(value), CANONICAL)


def reference_name(target: Element) -> str:
    """The name a reference to ``target`` writes (a model's top default class: ``main``)."""
    name = tooling.element_name(target)
    if name is not None:
        return name
    if target.spec.compose == "nest" and isinstance(target.parent, ModelBase):
        return grammar_facts().main_class
    return f"<unnamed {target.spec.tag}>"


def stored_text(element: Element, attribute: AttributeSpec) -> str | None:
    """The canonical text of one attribute as set on ``element``."""
    return value_text(attribute, tooling.read_value(element, attribute))
