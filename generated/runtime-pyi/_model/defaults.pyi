# Generated from src/typed_mjcf/_model/defaults.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""What value MuJoCo uses for an attribute once default classes are applied.

The class of an element is its ``class``, else the ``childclass`` (or, for ``<frame>`` and
``<replicate>``, the ``class``) of its nearest ancestor that has one, else the model's root
class (``main``). A class's value comes from its own defaults row for the element's kind,
else from the class it is nested in, up to the root. Kinds that share one default per class
in MuJoCo (actuators: ``<general>``, ``<motor>``, ``<position>``...) take an attribute they
have in common from whichever of their rows sets it last.
"""
from __future__ import annotations
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts

def main_class(model: ModelBase) -> Element | None:
    """The model's top-level ``<default>`` (its class ``main``), if it has one."""
    ...

def class_of(element: Element) -> Element | None:
    """The default class that applies to ``element`` (``None``: no class says anything)."""
    ...

def resolve(element: Element, name: str, grammar_defaults: bool = True) -> object:
    """The value of attribute ``name`` that MuJoCo compiles for ``element``: its own, else
    its classes', else (with ``grammar_defaults``) the grammar's default. An array given
    shorter than it may be (``size="0.1"`` of up to 3) keeps the rest from where it would
    otherwise come, as MuJoCo reads it into the default's values."""
    ...

def resolve_all(element: Element, grammar_defaults: bool = True) -> dict[str, object]:
    """:func:`resolve` of every attribute of ``element``, by name, its classes found once
    (when an attribute first needs them)."""
    ...
