"""What value MuJoCo uses for an attribute once default classes are applied.

The class of an element is its ``class``, else the ``childclass`` (or, for ``<frame>`` and
``<replicate>``, the ``class``) of its nearest ancestor that has one, else the model's root
class (``main``). A class's value comes from its own defaults row for the element's kind,
else from the class it is nested in, up to the root. Kinds that share one default per class
in MuJoCo (actuators: ``<general>``, ``<motor>``, ``<position>``...) take an attribute they
have in common from whichever of their rows sets it last.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from typing import cast

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import Array, ArrayCodec, Codec
from typed_mjcf._core.errors import InvalidValueError, UnknownAttributeError, did_you_mean
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts


def main_class(model: ModelBase) -> Element | None:
    """The model's top-level ``<default>`` (its class ``main``), if it has one."""
    for section in _tree.children(model):
        if section.spec.compose == "nest":
            return section
    return None


def _named_class(element: Element, attribute: str, value: object) -> Element | None:
    """The default class a ``class``/``childclass`` value names (a link, or a name)."""
    if isinstance(value, Element):
        return None if value.is_removed else value
    assert isinstance(value, str)
    root = _tree.model_of(element)
    if value == grammar_facts().main_class:
        return None if root is None else main_class(root)
    namespace = element.spec.by_name[attribute].namespace or ""
    found = _tree.scope_of(element).find(namespace, value)
    if not isinstance(found, Element):
        raise InvalidValueError(f"{element.path}: default class {value!r} is not defined")
    return found


def class_of(element: Element) -> Element | None:
    """The default class that applies to ``element`` (``None``: no class says anything)."""
    facts = grammar_facts()
    value = _tree.values(element).get(facts.dclass)
    if value is not None:
        return _named_class(element, facts.dclass, value)
    ancestor = element.parent
    while ancestor is not None:
        stored = _tree.values(ancestor)
        childclass = stored.get(facts.childclass)
        if childclass is not None:
            return _named_class(ancestor, facts.childclass, childclass)
        own = stored.get(facts.dclass) if ancestor.spec.tag in facts.class_for_children else None
        if own is not None:
            return _named_class(ancestor, facts.dclass, own)
        ancestor = ancestor.parent
    root = _tree.model_of(element)
    return None if root is None else main_class(root)


@functools.cache
def _sharing_rows(defaults_tag: str) -> tuple[str, ...]:
    """The default rows that set the same default as ``defaults_tag``'s (all actuator kinds'
    for an actuator's), or just it."""
    facts = grammar_facts()
    for cls in _tree.element_classes().values():
        spec = cls.spec
        if spec.defaults_tag == defaults_tag and spec.namespace in facts.shared_defaults:
            return tuple(sorted({c.spec.defaults_tag for c in _tree.element_classes().values()
                                 if c.spec.namespace == spec.namespace
                                 and c.spec.defaults_tag is not None}))
    return (defaults_tag,)


def _class_value(default: Element, defaults_tag: str, attribute: AttributeSpec) -> object:
    """The value a class itself gives ``attribute`` (``None`` if it does not): the last of
    the rows sharing the default that sets it."""
    rows = _sharing_rows(defaults_tag)
    found: object = None
    if len(rows) == 1:
        row = _tree.single_child(default, defaults_tag)
        if row is not None and attribute.name in row.spec.by_name:
            found = _tree.read_value(row, row.spec.by_name[attribute.name])
        return found
    for child in _tree.children(default):  # document order: the last one written wins
        if child.spec.tag in rows and attribute.name in child.spec.by_name:
            value = _tree.read_value(child, child.spec.by_name[attribute.name])
            if value is not None:
                found = value
    return found


def resolve(element: Element, name: str, grammar_defaults: bool = True) -> object:
    """The value of attribute ``name`` that MuJoCo compiles for ``element``: its own, else
    its classes', else (with ``grammar_defaults``) the grammar's default. An array given
    shorter than it may be (``size="0.1"`` of up to 3) keeps the rest from where it would
    otherwise come, as MuJoCo reads it into the default's values."""
    spec = element.spec
    attribute = spec.by_key.get(name)
    if attribute is None:
        known = [a.py_name for a in spec.attributes.values()]
        raise UnknownAttributeError(f"{element.path}: <{spec.tag}> has no attribute {name!r}"
                                    f"{did_you_mean(name, known)}")
    return _resolved(element, attribute, lambda: _classes(element), grammar_defaults)


def resolve_all(element: Element, grammar_defaults: bool = True) -> dict[str, object]:
    """:func:`resolve` of every attribute of ``element``, by name, its classes found once
    (when an attribute first needs them)."""
    classes = functools.cache(lambda: _classes(element))
    return {attribute.name: _resolved(element, attribute, classes, grammar_defaults)
            for attribute in element.spec.attributes.values()}


def _classes(element: Element) -> tuple[Element, ...]:
    """The default classes whose values ``element`` takes, innermost first: its class and
    the classes that class is nested in (none for elements no default applies to)."""
    if element.spec.defaults_tag is None:
        return ()
    found: list[Element] = []
    default = class_of(element)
    while default is not None:
        found.append(default)
        parent = default.parent  # nested classes inherit from the class around them
        default = parent if parent is not None and parent.spec is default.spec else None
    return tuple(found)


def _resolved(element: Element, attribute: AttributeSpec,
              classes: Callable[[], tuple[Element, ...]], grammar_defaults: bool) -> object:
    """``classes`` is called only if the element's own value does not say it all: an
    element's own values are read even when its class is not defined."""
    own = _tree.read_value(element, attribute)
    length = _filled_length(element, attribute)
    found = own
    if found is not None and (length is None or _size(found) >= length):
        return found
    for value in _inherited(element, attribute, classes, grammar_defaults):
        found = value if found is None else _filled(found, value)
        if length is None or _size(found) >= length:
            break
    return found


def _filled_length(element: Element, attribute: AttributeSpec) -> int | None:
    """The length a shorter array of ``attribute`` is filled up to from defaults (None: it
    is not: scalars, fixed and unbounded lengths, elements no default applies to)."""
    codec = attribute.codec
    if element.spec.defaults_tag is None or not isinstance(codec, ArrayCodec):
        return None
    return codec.hi if codec.hi is not None and codec.lo < codec.hi else None


def _inherited(element: Element, attribute: AttributeSpec,
               classes: Callable[[], tuple[Element, ...]],
               grammar_defaults: bool) -> Iterator[object]:
    """What the element would have without its own value: its classes' values, innermost
    first, then (with ``grammar_defaults``) the grammar's default."""
    defaults_tag = element.spec.defaults_tag
    if defaults_tag is not None:
        for default in classes():
            value = _class_value(default, defaults_tag, attribute)
            if value is not None:
                yield value
    if attribute.default is not None and grammar_defaults:
        yield _grammar_default(attribute.codec, attribute.default)


@functools.cache
def _grammar_default(codec: Codec, text: str) -> object:
    """A grammar default's value, read once: values are immutable (arrays read-only). The
    codec, not the attribute, is the key: a release retypes an attribute in place."""
    return codec.read(codec.parse(text))


def _size(value: object) -> int:
    return len(cast(Array, value))


def _filled(own: object, fallback: object) -> object:
    """``own``, continued by the entries of ``fallback`` past its length (read-only)."""
    head, tail = cast(Array, own), cast(Array, fallback)
    if tail.shape[0] <= head.shape[0]:
        return head
    array = np.concatenate([head, tail[head.shape[0]:].astype(head.dtype)])
    array.flags.writeable = False
    return array
