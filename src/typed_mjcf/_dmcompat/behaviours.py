"""What only dm_control does, lent to the tree and the features (``_tree.COMPAT``), each
called only while its flag of :class:`typed_mjcf._core.behaviour.Behaviour` is on.

The one home of dm_control's naming rules: its count of unnamed elements
(:func:`unnamed_names`) and its kinds of names (:func:`dm_control_namespace`). An unnamed
asset is named after its file by the rule the file namer and the compiled names share
(:func:`typed_mjcf._text.files.element_file_stem`); a model given no name is
``names.UNNAMED_MODEL``, as an attached model without one is called.
"""

from __future__ import annotations

import weakref
from collections.abc import Mapping
from typing import Final, TypeAlias, cast

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import Rejected
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.names import SEPARATOR
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.files import element_file_stem

ELEMENT_NAME: Final = "element_name"  # the keyword dm_control's add() names the tag by

# dm_control's schema puts some kinds in one namespace of its own (its names for unnamed
# elements count them together: //unnamed_contact_0 for a <pair> or an <exclude>)
_DM_CONTROL_NAMESPACES: Final = {"pair": "contact", "exclude": "contact", "flex": "deformable",
                                 "skin": "deformable"}


def dm_control_namespace(namespace: str) -> str:
    """The name of ``namespace`` in dm_control's schema."""
    return _DM_CONTROL_NAMESPACES.get(namespace, namespace)


# ---------------------------------------------------------------------------- arrays_in_place
# Arrays read as writable arrays, edited in place as dm_control's are, and checked again
# whenever the model is written (check_arrays), so an invalid value never goes unnoticed.

# the arrays handed out for in-place edits: element -> {XML name: the stored array}
_Array: TypeAlias = np.ndarray[tuple[int], np.dtype[np.generic]]
_HANDED_OUT: weakref.WeakKeyDictionary[Element, dict[str, _Array]] = weakref.WeakKeyDictionary()


def writable_array(element: Element, attribute: AttributeSpec, stored: object) -> object:
    """The stored array itself, writable: changes made in place are the element's."""
    owned = _HANDED_OUT.get(element)
    if owned is not None and owned.get(attribute.name) is stored:
        return stored
    array = np.array(attribute.codec.read(stored))  # a copy of its own, writable
    _tree.keep_value(element, attribute, array)
    if owned is None:
        _HANDED_OUT[element] = owned = {}
    owned[attribute.name] = array
    return array


def copied_values(values: Mapping[str, object]) -> dict[str, object]:
    """An element's values for its copy: arrays copied, since they may be edited in place."""
    return {key: value.copy() if type(value) is np.ndarray else value
            for key, value in values.items()}


def check_arrays(model: ModelBase) -> None:
    """Check again every array of ``model`` (and the models attached to it) handed out for
    in-place edits: an edit that made it invalid raises the error assigning it would."""
    if not _HANDED_OUT:
        return
    models: set[int] = set()
    pending: list[ModelBase] = [model]
    while pending:
        current = pending.pop()
        models.add(id(current))
        pending += _tree.attached_models(current)
    for element, arrays in list(_HANDED_OUT.items()):
        root = _tree.model_of(element)
        if root is None or id(root) not in models:
            continue
        stored = _tree.values(element)
        for name, array in arrays.items():
            if stored.get(name) is not array:
                continue
            attribute = element.spec.by_name[name]
            try:
                attribute.codec.accept(array)
            except Rejected as rejected:
                raise _tree.rejection(element, attribute, array, rejected) from None


# ---------------------------------------------------------------------------- names


def unnamed_names(model: ModelBase) -> dict[int, str]:
    """dm_control's names of ``model``'s unnamed elements (attached models' left out), by
    ``id``: ``/unnamed_<kind>_<i>``, ``i`` the element's position among the model's elements
    of that kind (named or not, attachment frames included; the sections and a frame's own
    children are not counted), to follow its scope's prefix (``/`` for the outermost model);
    ``""`` for a frame's own unnamed child, which takes the frame's name."""
    counts: dict[str, int] = {}
    names: dict[int, str] = {}
    for element in _tree.iter_composed(model, False):
        namespace = element.spec.namespace
        parent = _tree.parent_of(element)
        if namespace is None or parent is None or isinstance(parent, ModelBase):
            continue
        unnamed = element.spec.id_attribute is not None and _tree.element_name(element) is None
        if _tree.attached_at(parent) is not None and (
                _tree.scope_of(element) is not _tree.scope_of(parent)):
            if unnamed:
                names[id(element)] = ""
            continue
        kind = dm_control_namespace(namespace)
        index = counts.get(kind, 0)
        counts[kind] = index + 1
        if unnamed:
            names[id(element)] = f"{SEPARATOR}unnamed_{kind}_{index}"
    return names


def unnamed_identifier(element: Element) -> str | None:
    """dm_control's name for an unnamed element of a namespace (see :func:`unnamed_names`);
    ``None`` for one it does not name so."""
    model = _tree.model_of(element)
    return None if model is None else unnamed_names(model).get(id(element)) or None


def name_after_file(element: Element) -> None:
    """dm_control names an unnamed mesh (texture, ...) after its file's stem, as MuJoCo
    does: the name is the element's, so references find it and ``mesh.name`` reads it."""
    id_attribute = element.spec.id_attribute
    attribute = grammar_facts().named_after_file.get(element.spec.namespace or "")
    if attribute is None or id_attribute is None or id_attribute.name in _tree.values(element):
        return
    stem = element_file_stem(element, attribute)  # the name MuJoCo gives it
    if stem and _tree.model_of(element) is not None and _tree.scope_of(element).lookup(
            cast(str, id_attribute.namespace), stem) is None:
        _tree.store_name(element, id_attribute, stem)


def name_after_files(model: ModelBase) -> None:
    """Name every unnamed element of ``model`` that MuJoCo names after its file (see
    :func:`name_after_file`): dm_control's parser does."""
    named_after_file = grammar_facts().named_after_file
    for element in model.iter_elements():
        if element.spec.namespace in named_after_file:
            name_after_file(element)


def tag_by_keyword(kwargs: dict[str, object]) -> str | None:
    """The tag ``add(element_name=...)`` names (taken out of the attributes)."""
    return cast("str | None", kwargs.pop(ELEMENT_NAME, None))


def _lend() -> None:
    hooks = _tree.COMPAT
    hooks.writable_array = writable_array
    hooks.copied_values = copied_values
    hooks.check_arrays = check_arrays
    hooks.name_after_file = name_after_file
    hooks.name_after_files = name_after_files
    hooks.tag_by_keyword = tag_by_keyword
    hooks.unnamed_identifier = unnamed_identifier
    hooks.unnamed_names = unnamed_names


_lend()
