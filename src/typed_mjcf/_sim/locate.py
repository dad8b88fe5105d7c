"""Which element of our model a MuJoCo error is about.

MuJoCo ends an error with where it happened, on a line of its own (the last such line is
about the text it was given; earlier ones about files that text read):

- ``Element 'geom', line 4``: its XML reader, at a line of the text;
- ``Element name 'arm/l', id 3, line 7``: an object of the model being compiled (a body,
  joint, actuator, ...: MuJoCo does not say which kind), its name (``''`` if unnamed), its
  number among objects of its kind, and the line of the element it was read from;
- ``Element name 'k', id 0`` without a line: an object MuJoCo made itself (the bodies of a
  ``<flexcomp>``, the equality of its ``<edge equality>``) or compiles apart (keyframes).

The line is of the text typed-mjcf wrote, where an attached model's elements are written
inline and composition joins sections, so lines cannot be paired with our elements in
document order. Instead the model is written again with the same lines and a marker name on
every unnamed element that has a name attribute: the element at MuJoCo's line is then known
by its name, or by its position under the nearest element known by name. A line is trusted
only when the element there agrees with the name MuJoCo gives; otherwise (a line of a file an
``<attach>`` read) the name is looked up, among the names we write and those MuJoCo's compiler
makes (:mod:`typed_mjcf._model.compiled_names`). Where nothing identifies an element, the message
says so and which section the error concerns, never naming another element.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Final

from lxml import etree

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import DEFAULT_FORMAT
from typed_mjcf._core.grammar import ElementSpec
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.compiled_names import CompiledNames
from typed_mjcf._text.export import Writer, written_children
from typed_mjcf._text.files import CollectedFiles
from typed_mjcf._text.parse import source_line
from typed_mjcf._text.xmltext import serialize
from typed_mjcf.types import XmlElement as XmlNode

_OBJECT = re.compile(r"^Element name '(?P<name>.*)', id (?P<id>\d+)(?:, line (?P<line>\d+))?\s*$")
_XML = re.compile(r"^Element '(?P<tag>[^']*)', line (?P<line>\d+)\s*$")
_QUOTED = re.compile(r"'([^']+)'")
_MARK: Final = "typed-mjcf-element-"  # marker names: no model names its elements so
_MARKED = re.compile(re.escape(_MARK) + r"(\d+)$")


@dataclass(frozen=True, slots=True)
class Where:
    """What MuJoCo says about where an error happened."""

    tag: str | None = None  # XML reader errors: the element's tag
    name: str | None = None  # object errors: the object's name ('' if unnamed)
    number: int | None = None  # object errors: its number among objects of its kind
    line: int | None = None  # the element's line in the text MuJoCo was given


def where(message: str) -> Where | None:
    """The last ``Element ...`` line of MuJoCo's message, read."""
    found: Where | None = None
    for line in message.splitlines():
        if (match := _OBJECT.match(line)) is not None:
            text = match.group("line")
            found = Where(name=match.group("name"), number=int(match.group("id")),
                          line=int(text) if text else None)
        elif (match := _XML.match(line)) is not None:
            found = Where(tag=match.group("tag"), line=int(match.group("line")))
    return found


@dataclass(frozen=True, slots=True)
class Location:
    """What the error is about: an element's path (``None`` if not known) and a sentence."""

    path: str | None
    note: str


def locate(model: ModelBase, message: str, collected: CollectedFiles) -> Location | None:
    """The element (or section) of ``model`` that MuJoCo's ``message`` is about, for the text
    written with ``collected``'s file names (as :func:`typed_mjcf._model.write.vfs_text` writes)."""
    found = where(message)
    if found is None:
        return None
    return _Locator(model, collected).locate(found, message)


def written_nodes(model: ModelBase, collected: CollectedFiles,
                  ) -> tuple[XmlNode, list[tuple[XmlNode, Element]]]:
    """The model written as for MuJoCo (as :func:`locate` reads it, keyframes of composed
    models left out) and each node of it that is one of our elements, with that element, in
    document order (dm_control's debug dump)."""
    root, pairs = _Locator(model, collected).nodes()
    for node, element in pairs:  # the marker names are ours, not the model's
        id_attribute = element.spec.id_attribute
        value = node.get(id_attribute.name) if id_attribute is not None else None
        if id_attribute is not None and value is not None and _MARKED.search(value):
            del node.attrib[id_attribute.name]
    return root, pairs


class _Locator:
    def __init__(self, model: ModelBase, collected: CollectedFiles) -> None:
        self.model = model
        self.writer = Writer(model, DEFAULT_FORMAT, collected.name_of,
                             collected.directory_attributes)
        self.marks: list[Element] = []
        self.marked: set[int] = set()  # ids of the marks
        self.root: XmlNode | None = None  # of the marked text
        self.compiled: CompiledNames | None = None
        self.exported: dict[str, list[Element]] | None = None

    def nodes(self) -> tuple[XmlNode, list[tuple[XmlNode, Element]]]:
        """The marked text's root and each node that is one of our elements, with it."""
        root = self._marked_root()
        pairs: list[tuple[XmlNode, Element]] = []
        for node in root.iter():
            if not isinstance(node.tag, str) or node is root:
                continue
            element = self._element_of(node)
            if element is not None:
                pairs.append((node, element))
        return root, pairs

    # ------------------------------------------------------------------ finding

    def locate(self, found: Where, message: str) -> Location:
        element = self._at_line(found) if found.line is not None else None
        if element is not None:
            return Location(element.path, f"the element is {element.path}")
        if found.name:
            by_name = self._by_name(found.name)
            if by_name is not None:
                return by_name
        return self._unknown(found, message)

    def _at_line(self, found: Where) -> Element | None:
        """The element at MuJoCo's line, if it agrees with what MuJoCo says is there."""
        assert found.line is not None
        node = self._node_at(found.line)
        if node is None or (found.tag is not None and node.tag != found.tag):
            return None
        element = self._element_of(node)
        if element is None or found.name is None:
            return element
        if found.name == (self._written_name(element) or ""):
            return element
        # a copy MuJoCo made of the element (a <replicate>'s) carries its line too
        namespace = element.spec.namespace
        compiled = self._compiled()
        if namespace is not None and compiled.origin(
                _tree.scope_of(self.model), namespace, found.name) is element:
            return element
        return None  # the line of another file (a model an <attach> read)

    def _by_name(self, name: str) -> Location | None:
        """The element of that exported name, or the one MuJoCo's compiler made it from."""
        exported = self._exported().get(name, [])
        if len(exported) == 1:
            return Location(exported[0].path, f"the element is {exported[0].path}")
        if exported:
            paths = " or ".join(e.path for e in exported)
            return Location(None, f"MuJoCo names {name!r}, which is {paths}")
        origin = self._origin(name)
        if origin is None:
            return None
        return Location(origin.path, f"the element is {origin.path}, which MuJoCo's {name!r} "
                                     f"is made from")

    def _unknown(self, found: Where, message: str) -> Location:
        """No element: say which section the error concerns, and what its message names."""
        section = self._section(message)
        keys = self._key(section, found)
        if keys is not None:
            return keys
        if found.line is None and not found.name:
            what = (f"MuJoCo names no element: its object {found.number} has no name and no "
                    f"line (MuJoCo made it, or compiles it apart)")
        else:
            what = "no element of the model has the name and line MuJoCo gives"
        parts = [what]
        if section is not None:
            parts.append(f"the error concerns the <{section.tag}> section")
        parts += [f"{text!r} in its message is {elements[0].path}"
                  for text in dict.fromkeys(_QUOTED.findall(message))
                  if len(elements := self._exported().get(text, [])) == 1]
        return Location(None, "; ".join(parts))

    def _key(self, section: ElementSpec | None, found: Where) -> Location | None:
        """A keyframe, by its number: keys compile in document order (when no attached
        models' keys are combined into them)."""
        if (section is None or section.compose != "keyframes" or found.number is None
                or _tree.scope_of(self.model).attached):
            return None
        keys = [key for sec in _tree.children(self.model) if sec.spec is section
                for key in written_children(sec)]
        if found.number >= len(keys):
            return None
        path = keys[found.number].path
        return Location(path, f"the element is {path}")

    def _section(self, message: str) -> ElementSpec | None:
        """The root section whose tag MuJoCo's message uses first (``keyframe 0``, ``in
        equality constraint 0``)."""
        words = re.findall(r"[A-Za-z_]+", message.split("\n", 1)[0])
        sections = {child.tag: child for child in self.model.spec.children.values()}
        for word in words:
            child = sections.get(word)
            if child is not None:
                return _tree.element_class(child.class_name).spec
        return None

    # ------------------------------------------------------------------ the marked text

    def _node_at(self, line: int) -> XmlNode | None:
        if self.root is None:
            self.root = self._marked_root()
        return next((node for node in self.root.iter() if source_line(node) == line), None)

    def _marked_root(self) -> XmlNode:
        """The model written as for MuJoCo, with a marker name on every unnamed element that
        has a name attribute (same lines: names go on the element's own line). Keyframes of
        composed models are combined last, after every other section, and are left out."""
        writer = self.writer
        for element in _tree.iter_composed(self.model, True):
            if (element.spec.id_attribute is not None and _tree.element_name(element) is None
                    and id(element) not in writer.given_names):
                writer.given_names[id(element)] = f"{_MARK}{len(self.marks)}"
                self.marks.append(element)
                self.marked.add(id(element))
        if writer.composed:
            text = serialize(writer.model(self.model), pretty_print=True)
        else:
            text = writer.text(self.model, pretty_print=True)
        parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=True)
        return etree.fromstring(text.encode("utf-8"), parser)

    def _element_of(self, node: XmlNode) -> Element | None:
        """Our element for a node of the marked text: known by name, or by its position
        among the children of the same tag of the nearest node known by name."""
        steps: list[tuple[str, int]] = []
        current = node
        while (known := self._named(current)) is None:
            parent = current.getparent()
            if parent is None:  # the root: the model itself
                return _descend(self.model, steps)
            same = [n for n in parent if n.tag == current.tag]
            steps.append((str(current.tag), same.index(current)))
            current = parent
        return _descend(known, steps)

    def _named(self, node: XmlNode) -> Element | None:
        spec = self._row(node)
        if spec is None or spec.id_attribute is None:
            return None
        value = node.get(spec.id_attribute.name)
        if value is None:
            return None
        mark = _MARKED.search(value)
        if mark is not None:
            return self.marks[int(mark.group(1))]
        matches = [e for e in self._exported().get(value, []) if e.spec.namespace == spec.namespace]
        return matches[0] if len(matches) == 1 else None

    def _row(self, node: XmlNode) -> ElementSpec | None:
        """The grammar row of a node, from the root down."""
        chain = [node, *node.iterancestors()]
        spec: ElementSpec = self.model.spec
        for current in reversed(chain[:-1]):
            child = spec.children.get(str(current.tag))
            if child is None:
                return None
            spec = _tree.element_class(child.class_name).spec
        return spec

    # ------------------------------------------------------------------ names

    def _written_name(self, element: Element) -> str | None:
        """The name the text MuJoCo read gives ``element`` (``None``: it has none there):
        its own, one the export gives it, or a default class's for the top-level one."""
        name = _tree.element_name(element)
        if name is None and id(element) not in self.marked:
            name = self.writer.given_names.get(id(element))
        scope = _tree.scope_of(element)
        if name is None:
            return self.writer.main_class(scope) if _is_main_class(element) else None
        return self.writer.prefix(scope) + name

    def _exported(self) -> dict[str, list[Element]]:
        """Every element named in the text, by that name."""
        if self.exported is None:
            self.exported = {}
            for element in _tree.iter_composed(self.model, True):
                name = None if element.spec.namespace is None else self._written_name(element)
                if name is not None:
                    self.exported.setdefault(name, []).append(element)
        return self.exported

    def _compiled(self) -> CompiledNames:
        if self.compiled is None:
            self.compiled = CompiledNames(self.model)
        return self.compiled

    def _origin(self, name: str) -> Element | None:
        """The element a compiled object of that name is made from, in any namespace."""
        compiled = self._compiled()
        scope = _tree.scope_of(self.model)
        for namespace in _namespaces():
            origin = compiled.origin(scope, namespace, name)
            if origin is not None:
                return origin
        return None


def _descend(element: Element, steps: list[tuple[str, int]]) -> Element | None:
    """Follow ``steps`` (tag, index among children of that tag), innermost last, down from
    ``element``. What composition adds to a node (an attached model's bodies in its frame,
    its actuators in our section) follows the element's own children, so an index past them
    is not ours: ``None``."""
    current = element
    for tag, index in reversed(steps):
        same = [child for child in written_children(current) if child.spec.tag == tag]
        if index >= len(same):
            return None
        current = same[index]
    return current


def _is_main_class(element: Element) -> bool:
    return element.spec.compose == "nest" and isinstance(element.parent, ModelBase)


def _namespaces() -> Iterator[str]:
    seen: set[str] = set()
    for cls in _tree.element_classes().values():
        namespace = cls.spec.namespace
        if namespace is not None and namespace not in seen:
            seen.add(namespace)
            yield namespace
