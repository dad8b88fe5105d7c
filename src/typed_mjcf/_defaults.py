"""What value MuJoCo uses for an attribute once default classes are applied.

The class of an element is its ``class``, else the ``childclass`` of its nearest ancestor
that has one, else the model's root class (``main``). A class's value comes from its own
defaults row for the element's kind, else from the class it is nested in, up to the root.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from typed_mjcf._compose import MAIN_CLASS
from typed_mjcf.errors import InvalidValueError, UnknownAttributeError, did_you_mean

if TYPE_CHECKING:
    from typed_mjcf._element import Element
    from typed_mjcf._root import ModelRoot


def class_of(element: Element) -> str:
    """The default class that applies to ``element``."""
    value = element._attrs.get("class")  # pyright: ignore[reportPrivateUsage]
    if isinstance(value, str):
        return value
    ancestor = element.parent
    while ancestor is not None:
        childclass = ancestor._attrs.get("childclass")  # pyright: ignore[reportPrivateUsage]
        if isinstance(childclass, str):
            return childclass
        ancestor = ancestor.parent
    return MAIN_CLASS


def _class_element(model: ModelRoot, name: str) -> Element | None:
    if name == MAIN_CLASS:
        for section in model.get_children():
            if section.spec.compose == "nest":
                return section
        return None
    return model.find("default", name)


def resolve(element: Element, name: str) -> object:
    """The value of attribute ``name`` that MuJoCo compiles for ``element``."""
    spec = element.spec
    attribute = spec.by_key.get(name)
    if attribute is None:
        known = [a.py_name for a in spec.attributes]
        raise UnknownAttributeError(f"{element.path}: <{spec.tag}> has no attribute {name!r}"
                                    f"{did_you_mean(name, known)}")
    own = element._attrs.get(attribute.name)  # pyright: ignore[reportPrivateUsage]
    if own is not None:
        return own
    if spec.defaults_tag is not None:
        cls = class_of(element)
        default = _class_element(element.root, cls)
        if default is None and cls != MAIN_CLASS:
            raise InvalidValueError(f"{element.path}: default class {cls!r} is not defined")
        while default is not None:
            row = default._single_child(spec.defaults_tag)  # pyright: ignore[reportPrivateUsage]
            if row is not None:
                value = row._attrs.get(attribute.name)  # pyright: ignore[reportPrivateUsage]
                if value is not None:
                    return value
            parent = default.parent  # nested classes inherit from the class around them
            default = parent if parent is not None and parent.spec is default.spec else None
    if attribute.default is None:
        return None
    return attribute.convert(attribute.default)
