"""Reading MJCF text into typed elements.

Parsing is safe by default (no DTDs, entities or network). ``<include>`` elements are
expanded in place, wherever they appear, so document order (and so qpos layout) is kept.
Repeated once-only sections (two ``<asset>`` blocks, say) merge, as they do in MuJoCo.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import cast

import numpy as np
from lxml import etree

from typed_mjcf._convert import Rejected
from typed_mjcf._element import _REGISTRY, Element  # pyright: ignore[reportPrivateUsage]
from typed_mjcf._export import XmlNode
from typed_mjcf._root import ModelRoot
from typed_mjcf.errors import MjcfError, ParseError, did_you_mean

INCLUDE = "include"

_Array = np.ndarray[tuple[int, ...], np.dtype[np.generic]]


def _xml_parser() -> etree.XMLParser:
    return etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                           remove_comments=True, remove_pis=True, huge_tree=False)


def source_line(node: XmlNode) -> int | None:
    """The line ``node`` starts on in the text it was read from, if known."""
    line: object = node.sourceline  # lxml-stubs types it loosely
    return line if isinstance(line, int) else None


def root_class() -> type[ModelRoot]:
    for cls in _REGISTRY.values():
        if issubclass(cls, ModelRoot):
            return cls
    raise RuntimeError("no generated root class is registered")  # pragma: no cover


@dataclass
class _Context:
    base_dir: str | None
    included: list[str] = field(default_factory=lambda: [])  # every file read, in order
    nesting: list[str] = field(default_factory=lambda: [])  # the files including the current one


def is_model_text(data: bytes) -> bool:
    """Whether ``data`` is MJCF text: XML whose root element is the model's root."""
    try:
        node = etree.fromstring(data, _xml_parser())
    except etree.XMLSyntaxError:
        return False
    return node.tag == root_class()._SPEC.tag  # pyright: ignore[reportPrivateUsage]


def _read_xml(data: str | bytes, source: str | None) -> XmlNode:
    if isinstance(data, str):
        data = data.encode("utf-8")
    try:
        return etree.fromstring(data, _xml_parser())
    except etree.XMLSyntaxError as error:
        line = error.lineno if error.lineno else None
        raise ParseError(f"malformed XML: {error.msg}", source, line) from None


def parse_text(data: str | bytes, *, base_dir: str | None = None,
               source: str | None = None) -> ModelRoot:
    """Parse MJCF text into a model."""
    node = _read_xml(data, source)
    return _build_model(node, _Context(base_dir), source)


def parse_path(path: str) -> ModelRoot:
    """Parse an MJCF file; its folder is the base of relative paths."""
    path = os.path.abspath(path)
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as error:
        raise ParseError(f"cannot read the file: {error.strerror}", path) from None
    node = _read_xml(data, path)
    return _build_model(node, _Context(os.path.dirname(path), [path], [path]), path)


def _build_model(node: XmlNode, context: _Context, source: str | None) -> ModelRoot:
    cls = root_class()
    if node.tag != cls._SPEC.tag:  # pyright: ignore[reportPrivateUsage]
        raise ParseError(f"the root element is <{node.tag!s}>, expected <{cls._SPEC.tag}>",  # pyright: ignore[reportPrivateUsage]
                         source, source_line(node))
    model = cls()
    object.__setattr__(model, "_base_dir", context.base_dir)
    _set_attributes(model, node, source)
    _add_children(model, node, context, source)
    return model


def _set_attributes(element: Element, node: XmlNode, source: str | None) -> None:
    by_name = element.spec.by_name
    for key, text in node.attrib.items():
        attribute = by_name.get(str(key))
        if attribute is None:
            known = list(by_name)
            raise ParseError(
                f"<{element.tag}> has no attribute {str(key)!r}{did_you_mean(str(key), known)}",
                source, source_line(node))
        try:
            element._set_attribute(attribute, str(text))  # pyright: ignore[reportPrivateUsage]
        except MjcfError as error:
            raise ParseError(str(error), source, source_line(node)) from None
        except Rejected as rejected:  # pragma: no cover - _set_attribute converts these
            raise ParseError(rejected.expected, source, source_line(node)) from None


def _add_children(parent: Element, node: XmlNode, context: _Context,
                  source: str | None) -> None:
    children_specs = parent.spec.children
    for child_node in node:
        tag: object = child_node.tag
        if not isinstance(tag, str):
            continue  # entity references (comments and processing instructions are dropped)
        if tag == INCLUDE:
            _expand_include(parent, child_node, context, source)
            continue
        child_spec = children_specs.get(tag)
        if child_spec is None:
            legal = list(children_specs)
            raise ParseError(
                f"<{tag}> is not a legal child of <{parent.tag}> ({parent.path})"
                f"{did_you_mean(tag, legal)}", source, source_line(child_node))
        existing = parent._single_child(tag) if child_spec.single else None  # pyright: ignore[reportPrivateUsage]
        if existing is not None:
            # A repeated section: merge into the first.
            _merge_section(existing, child_node, context, source)
            continue
        child = parent._add_child(tag, None, {})  # pyright: ignore[reportPrivateUsage]
        _set_attributes(child, child_node, source)
        _add_children(child, child_node, context, source)


def _merge_section(section: Element, node: XmlNode, context: _Context,
                   source: str | None) -> None:
    """Merge a repeated once-only section into the first one.

    MuJoCo reads repeated sections in order, so merging keeps their meaning, with one
    exception: a section that nests itself (``<default>``: classes in classes) is a class
    hierarchy, and MuJoCo gives a class a copy of its parent's defaults as they are when the
    class is read. Main defaults that a later ``<default>`` section sets or changes therefore
    do not reach the classes of earlier sections, but would after merging; such a model is
    refused rather than silently changed.
    """
    nests = section.spec.children.get(section.tag)
    earlier_classes = ([e for e in section.iter_elements() if e.tag == section.tag
                        and e is not section] if nests is not None else [])
    before = _element_defaults(section) if earlier_classes else {}
    _set_attributes(section, node, source)
    _add_children(section, node, context, source)
    if not earlier_classes:
        return
    after = _element_defaults(section)
    for key, value in after.items():
        if key in before and _same_value(before[key], value):
            continue
        element_tag, attribute = key
        for hierarchy_class in earlier_classes:
            if not _sets_in_chain(hierarchy_class, section, element_tag, attribute):
                id_attribute = hierarchy_class.spec.id_attribute
                name = (None if id_attribute is None
                        else hierarchy_class._attrs.get(id_attribute.name))  # pyright: ignore[reportPrivateUsage]
                label = repr(name) if isinstance(name, str) else hierarchy_class.path
                raise ParseError(
                    f"this repeated <{section.tag}> section sets <{element_tag} {attribute}> "
                    f"for the whole model, but MuJoCo does not apply it to {section.tag} class "
                    f"{label} of an earlier <{section.tag}> section (a class keeps the values "
                    f"it inherited when it was defined); set {attribute} in that class, or "
                    f"move it into the first <{section.tag}> section",
                    source, source_line(node))


def _element_defaults(section: Element) -> dict[tuple[str, str], object]:
    """The attributes a hierarchy level sets on its element children, by (tag, attribute)."""
    values: dict[tuple[str, str], object] = {}
    for child in section.get_children():
        if child.tag != section.tag:
            for name, value in child._attrs.items():  # pyright: ignore[reportPrivateUsage]
                values[(child.tag, name)] = value
    return values


def _sets_in_chain(level: Element, top: Element, tag: str, attribute: str) -> bool:
    """Whether ``level`` or one of its ancestors below ``top`` sets ``<tag attribute>``."""
    current: Element | None = level
    while current is not None and current is not top:
        if (tag, attribute) in _element_defaults(current):
            return True
        current = current.parent
    return False


def _same_value(a: object, b: object) -> bool:
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        return bool(np.array_equal(cast(_Array, a), cast(_Array, b)))
    return not isinstance(a, np.ndarray) and not isinstance(b, np.ndarray) and a == b


def _expand_include(parent: Element, node: XmlNode, context: _Context,
                    source: str | None) -> None:
    file = node.get("file")
    if not file:
        raise ParseError("<include> needs a file attribute", source, source_line(node))
    base = context.base_dir or os.getcwd()
    path = os.path.abspath(os.path.join(base, file))
    if path in context.nesting:
        chain = " -> ".join([*context.nesting, path])
        raise ParseError(f"{file!r} includes itself: {chain}", source, source_line(node))
    if path in context.included:
        raise ParseError(f"{file!r} ({path}) is already part of the model (MuJoCo includes a "
                         f"file once)", source, source_line(node))
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as error:
        raise ParseError(f"cannot read included file {file!r} ({path}): {error.strerror}",
                         source, source_line(node)) from None
    context.included.append(path)
    included_root = _read_xml(data, path)
    context.nesting.append(path)
    _add_children(parent, included_root, context, path)
    context.nesting.pop()
