"""Writing elements as MJCF: an lxml tree built in one pass, then serialised."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TypeAlias

import numpy as np
from lxml import etree

from typed_mjcf._element import Element
from typed_mjcf._spec import AttributeSpec
from typed_mjcf.assets import Asset
from typed_mjcf.errors import ExportError

XmlNode: TypeAlias = etree._Element  # pyright: ignore[reportPrivateUsage]  # lxml's element type
FileNamer = Callable[[Element, AttributeSpec, object], str]


def _shortest_double(x: float) -> str:
    text = repr(x)
    return text[:-2] if text.endswith(".0") else text


def _shortest_float32(x: np.float32) -> str:
    text = str(x)
    return text[:-2] if text.endswith(".0") else text


class Formatter:
    """Turns stored attribute values into MJCF text."""

    def __init__(self, precision: int | None = None, zero_threshold: float = 0.0,
                 file_namer: FileNamer | None = None,
                 skip_attributes: frozenset[str] = frozenset()) -> None:
        self.precision = precision
        self.zero_threshold = zero_threshold
        self.file_namer = file_namer  # renames every file (paths and in-memory assets)
        self.skip_attributes = skip_attributes

    def number(self, x: float) -> str:
        if self.zero_threshold and abs(x) < self.zero_threshold:
            return "0"
        if self.precision is not None:
            return format(x, f".{self.precision}g")
        return _shortest_double(x)

    def array(self, attribute: AttributeSpec, value: np.ndarray[tuple[int, ...], np.dtype[np.generic]]) -> str:
        if attribute.kind == "int":
            return " ".join(map(str, value.tolist()))
        if self.precision is None and not self.zero_threshold:
            if attribute.dtype == "float":
                return " ".join(_shortest_float32(x) for x in value)  # pyright: ignore[reportArgumentType]
            return " ".join(map(_shortest_double, value.tolist()))
        return " ".join(map(self.number, value.tolist()))

    def value(self, element: Element, attribute: AttributeSpec, value: object) -> str:
        kind = attribute.kind
        if kind == "file" and self.file_namer is not None:
            return self.file_namer(element, attribute, value)
        if isinstance(value, str):
            return value
        if isinstance(value, np.ndarray):
            return self.array(attribute, value)  # pyright: ignore[reportUnknownArgumentType]
        if kind == "real":
            assert isinstance(value, float)
            return self.number(value)
        if kind == "bool":
            return "true" if value else "false"
        if kind == "int":
            return str(value)
        if kind == "flags":
            assert isinstance(value, tuple)
            return " ".join(value)  # pyright: ignore[reportUnknownArgumentType]
        if isinstance(value, Element):
            return reference_name(element, attribute, value)
        if isinstance(value, Asset):
            raise ExportError(
                f"{element.path}: {attribute.py_name} holds an in-memory asset; write the "
                f"model with export_with_assets() or compile() so the file gets a name"
            )
        raise ExportError(f"{element.path}: cannot write {attribute.py_name}={value!r}")


def reference_name(element: Element, attribute: AttributeSpec, target: Element) -> str:
    """The name a reference to ``target`` is written with."""
    id_attribute = target.spec.id_attribute
    name = None if id_attribute is None else target.get_attributes().get(id_attribute.py_name)
    if not isinstance(name, str):
        raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                          f"which has no name")
    if target._root is not element._root:  # pyright: ignore[reportPrivateUsage]
        raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                          f"which is not part of this model")
    return name


def _is_empty_single(parent: Element, child: Element) -> bool:
    if child._attrs or child._children:  # pyright: ignore[reportPrivateUsage]
        return False
    child_spec = parent.spec.children.get(child.tag)
    return child_spec is not None and child_spec.single


def iter_written(element: Element) -> Iterator[Element]:
    """The elements :func:`build` writes for ``element``'s subtree, in document order."""
    stack: list[Element] = [element]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(child for child in reversed(current._children)  # pyright: ignore[reportPrivateUsage]
                     if not _is_empty_single(current, child))


def build(element: Element, formatter: Formatter, parent: XmlNode | None = None) -> XmlNode:
    """The lxml element for ``element`` and its subtree."""
    attrs = element._attrs  # pyright: ignore[reportPrivateUsage]
    spec = element.spec
    attrib: dict[str, str] = {}
    skip = formatter.skip_attributes
    if attrs:
        if skip and any(name in skip for name in attrs):
            attrs = {k: v for k, v in attrs.items() if k not in skip}
        if len(attrs) == 1:
            key, value = next(iter(attrs.items()))
            attrib[key] = formatter.value(element, spec.by_key[key], value)
        else:
            for attribute in spec.attributes:
                value = attrs.get(attribute.name)
                if value is not None:
                    attrib[attribute.name] = formatter.value(element, attribute, value)
    if parent is None:
        node = etree.Element(spec.tag, attrib)
    else:
        node = etree.SubElement(parent, spec.tag, attrib)
    for child in element._children:  # pyright: ignore[reportPrivateUsage]
        if not _is_empty_single(element, child):
            build(child, formatter, node)
    return node


def to_xml(element: Element, *, precision: int | None = None, zero_threshold: float = 0.0,
           file_namer: FileNamer | None = None) -> XmlNode:
    return build(element, Formatter(precision, zero_threshold, file_namer))


def to_xml_string(element: Element, *, precision: int | None = None, zero_threshold: float = 0.0,
                  pretty_print: bool = True, file_namer: FileNamer | None = None) -> str:
    node = to_xml(element, precision=precision, zero_threshold=zero_threshold,
                  file_namer=file_namer)
    return etree.tostring(node, pretty_print=pretty_print, encoding="unicode")
