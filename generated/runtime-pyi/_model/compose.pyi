# Generated from src/typed_mjcf/_model/compose.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Composition: attaching models to each other, dm_control style.

An attached model stays a model of its own (its elements, names and defaults are untouched);
the parent holds it through an *attachment frame*, a ``<body>`` placed where it was attached.
At export the attached model is written inline under its scope: every identifier and
reference is prefixed ``<model name>/``, its default classes nest in a class named after the
scope, and its sections join the parent's (see ``ElementSpec.compose``).
"""
from __future__ import annotations
from collections.abc import Mapping
from typed_mjcf._core.tree import Element, ModelBase, equal_read_values, grammar_facts

def scope_name(model: ModelBase) -> str:
    """The model's name, which scopes its names where it is attached."""
    ...

def top_model(model: ModelBase) -> ModelBase:
    """The outermost model ``model`` is attached into (itself when not attached)."""
    ...

def attach(site: Element, model: ModelBase) -> Element:
    """Attach ``model`` at ``site``; return the attachment frame."""
    ...

def detach(model: ModelBase) -> None:
    """Undo ``attach``: remove the attachment frame (with anything added to it)."""
    ...

def adopt_settings(parent: ModelBase, model: ModelBase) -> None:
    """Before ``model`` is attached to ``parent``: the global settings ``parent`` leaves unset
    take ``model``'s values, values both set are combined by their rule (``max`` for
    ``size`` memory, ...) or refused with both values named; nothing changes on refusal."""
    ...

def free_name(scope_names: Mapping[str, object], name: str | None) -> str:
    """A scope name for an attached model: its own, else ``<name>_<n>`` with the first
    number free (dm_control's rule; an unnamed model is ``unnamed_model``)."""
    ...

def attached_children(element: Element) -> list[Element]:
    """What attached models add to ``element``'s children as users see them: an attachment
    frame shows the attached model's bodies (and the rest of its world body); a top-level
    section of a composed model, the same section of every model attached into it (default
    classes excepted: an attached model's classes stay its own)."""
    ...

def include_copy(model: ModelBase, other: ModelBase, override_attributes: bool) -> None:
    """Merge a copy of ``other``'s contents into ``model`` (see ``ModelRoot.include_copy``):
    dm_control's copier. Once-only children merge into this model's; an element with a name
    this model has under the same parent merges into it when ``override_attributes``; every
    other element is copied in. Attributes this model sets keep their value, unless
    ``override_attributes``; a global setting both give differently is an error."""
    ...
