# Generated from src/typed_mjcf/_model/traversal.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""dm_control's traversal helpers: committing defaults into elements, and finding the
frame, freejoint and joints of attachments."""
from __future__ import annotations
from collections.abc import Iterable
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts

def commit_defaults(element: Element, attributes: Iterable[str] | None = None) -> None:
    """Write into ``element`` the value its default classes give each of its attributes
    (only ``attributes``, when given) that it does not set itself, and the rest of an array
    it sets shorter than its classes do: afterwards its own values say what MuJoCo uses,
    whatever the classes."""
    ...

def get_attachment_frame(model: ModelBase) -> Element | None:
    """Where ``model`` is attached (its frame in the parent model), if it is."""
    ...

def get_freejoint(element: Element) -> Element | None:
    """The ``<freejoint>`` (or ``<joint type="free">``) directly in ``element``, if any."""
    ...

def get_frame_freejoint(model: Element) -> Element | None:
    """The free joint of an attached model's attachment frame (or of a frame), if any.

    As dm_control's, this takes the attached model; a frame itself is taken too."""
    ...

def get_frame_joints(model: Element) -> list[Element]:
    """The joints of an attached model's attachment frame (or of a frame): what makes the
    attached model move. As dm_control's, this takes the attached model; a frame too."""
    ...
