"""What value MuJoCo uses for an attribute once default classes are applied.

The class of an element is its ``class``, else the ``childclass`` of its nearest ancestor
that has one, else the model's root class (``main``). A class's value comes from its own
defaults row for the element's kind, else from the class it is nested in, up to the root.
"""

from __future__ import annotations

from typed_mjcf import _tree
from typed_mjcf._tree import Element, ModelBase, grammar_facts
from typed_mjcf.errors import InvalidValueError, UnknownAttributeError, did_you_mean


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
        childclass = _tree.values(ancestor).get(facts.childclass)
        if childclass is not None:
            return _named_class(ancestor, facts.childclass, childclass)
        ancestor = ancestor.parent
    root = _tree.model_of(element)
    return None if root is None else main_class(root)


def resolve(element: Element, name: str) -> object:
    """The value of attribute ``name`` that MuJoCo compiles for ``element``."""
    spec = element.spec
    attribute = spec.by_key.get(name)
    if attribute is None:
        known = [a.py_name for a in spec.attributes]
        raise UnknownAttributeError(f"{element.path}: <{spec.tag}> has no attribute {name!r}"
                                    f"{did_you_mean(name, known)}")
    own = _tree.read_value(element, attribute)
    if own is not None:
        return own
    defaults_tag = spec.defaults_tag
    if defaults_tag is not None:
        default = class_of(element)
        while default is not None:
            row = _tree.single_child(default, defaults_tag)
            if row is not None:
                value = _tree.read_value(row, row.spec.by_name[attribute.name]) if (
                    attribute.name in row.spec.by_name) else None
                if value is not None:
                    return value
            parent = default.parent  # nested classes inherit from the class around them
            default = parent if parent is not None and parent.spec is default.spec else None
    if attribute.default is None:
        return None
    return attribute.codec.read(attribute.codec.parse(attribute.default))
