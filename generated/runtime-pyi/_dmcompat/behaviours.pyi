# Generated from src/typed_mjcf/_dmcompat/behaviours.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""What only dm_control does, lent to the tree and the features (``_tree.COMPAT``), each
called only while its flag of :class:`typed_mjcf._core.behaviour.Behaviour` is on.

The one home of dm_control's naming rules: its count of unnamed elements
(:func:`unnamed_names`) and its kinds of names (:func:`dm_control_namespace`). An unnamed
asset is named after its file by the rule the file namer and the compiled names share
(:func:`typed_mjcf._text.files.element_file_stem`); a model given no name is
``names.UNNAMED_MODEL``, as an attached model without one is called.
"""
from __future__ import annotations
from collections.abc import Mapping
from typing import Final, TypeAlias, cast
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
ELEMENT_NAME: Final = "element_name"

def dm_control_namespace(namespace: str) -> str:
    """The name of ``namespace`` in dm_control's schema."""
    ...

def writable_array(element: Element, attribute: AttributeSpec, stored: object) -> object:
    """The stored array itself, writable: changes made in place are the element's."""
    ...

def copied_values(values: Mapping[str, object]) -> dict[str, object]:
    """An element's values for its copy: arrays copied, since they may be edited in place."""
    ...

def check_arrays(model: ModelBase) -> None:
    """Check again every array of ``model`` (and the models attached to it) handed out for
    in-place edits: an edit that made it invalid raises the error assigning it would."""
    ...

def unnamed_names(model: ModelBase) -> dict[int, str]:
    """dm_control's names of ``model``'s unnamed elements (attached models' left out), by
    ``id``: ``/unnamed_<kind>_<i>``, ``i`` the element's position among the model's elements
    of that kind (named or not, attachment frames included; the sections and a frame's own
    children are not counted), to follow its scope's prefix (``/`` for the outermost model);
    ``""`` for a frame's own unnamed child, which takes the frame's name."""
    ...

def unnamed_identifier(element: Element) -> str | None:
    """dm_control's name for an unnamed element of a namespace (see :func:`unnamed_names`);
    ``None`` for one it does not name so."""
    ...

def name_after_file(element: Element) -> None:
    """dm_control names an unnamed mesh (texture, ...) after its file's stem, as MuJoCo
    does: the name is the element's, so references find it and ``mesh.name`` reads it."""
    ...

def name_after_files(model: ModelBase) -> None:
    """Name every unnamed element of ``model`` that MuJoCo names after its file (see
    :func:`name_after_file`): dm_control's parser does."""
    ...

def tag_by_keyword(kwargs: dict[str, object]) -> str | None:
    """The tag ``add(element_name=...)`` names (taken out of the attributes)."""
    ...
