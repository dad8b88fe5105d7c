"""Writing elements as MJCF text, iteratively (depth is unlimited).

A model with nothing attached is written straight to text in one pass. A composed model
is built as light nodes where composition joins the attached models' sections and bodies
to the parent's (the sections, the attachment frames and their ancestors), with every other
subtree a chunk of text written in place when the nodes are serialised. ``to_xml()`` parses
the text into lxml.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterator
from typing import TypeAlias, cast

import numpy as np
from lxml import etree

from typed_mjcf._compose import MAIN_CLASS, scope_name
from typed_mjcf._element import Element
from typed_mjcf._gc import collector_paused
from typed_mjcf._root import ModelRoot
from typed_mjcf._spec import AttributeSpec
from typed_mjcf._xmltext import Chunk, Node, escape, serialize
from typed_mjcf.assets import Asset
from typed_mjcf.errors import ExportError

XmlNode: TypeAlias = etree._Element  # pyright: ignore[reportPrivateUsage]  # lxml's element type
FileNamer = Callable[[Element, AttributeSpec, object], str]


def _shortest_double(x: float) -> str:
    text = repr(x)
    return text.removesuffix(".0")


def _shortest_doubles(values: list[float]) -> str:
    """Space-separated shortest forms: one C-level join, then drop each trailing ".0"."""
    text = " ".join(map(repr, values)).replace(".0 ", " ")
    return text.removesuffix(".0")


def _shortest_float32(x: np.float32) -> str:
    text = str(x)
    return text.removesuffix(".0")


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
            return _shortest_doubles(value.tolist())
        return " ".join(map(self.number, value.tolist()))

    def value(self, element: Element, attribute: AttributeSpec, value: object) -> str:
        kind = attribute.kind
        if kind == "file" and self.file_namer is not None:
            return self.file_namer(element, attribute, value)
        if type(value) is str:
            return value
        if type(value) is np.ndarray:
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


def reference_name(element: Element, attribute: AttributeSpec, target: Element,
                   same_model: bool = True) -> str:
    """The name a reference to ``target`` is written with (unscoped)."""
    id_attribute = target.spec.id_attribute
    name = None if id_attribute is None else target._attrs.get(id_attribute.name)  # pyright: ignore[reportPrivateUsage]
    if not isinstance(name, str):
        raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                          f"which has no name")
    if same_model and target._root is not element._root:  # pyright: ignore[reportPrivateUsage]
        raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                          f"which is not part of this model")
    return name


def _is_empty_single(parent: Element, child: Element) -> bool:
    """A once-only child with nothing to say: no attributes, no attached model, and only
    children like itself. Such sections are not written (reading them gives nothing back)."""
    if child._attrs or child._attached is not None:  # pyright: ignore[reportPrivateUsage]
        return False
    child_spec = parent._SPEC.children.get(child._SPEC.tag)  # pyright: ignore[reportPrivateUsage]
    if child_spec is None or not child_spec.single:
        return False
    return all(_is_empty_single(child, grandchild) for grandchild in child._children)  # pyright: ignore[reportPrivateUsage]


def written_children(element: Element) -> list[Element]:
    """The children an export writes: all but once-only sections with nothing to say."""
    child_specs = element._SPEC.children  # pyright: ignore[reportPrivateUsage]
    return [child for child in element._children  # pyright: ignore[reportPrivateUsage]
            if child._attrs or not child_specs[child._SPEC.tag].single  # pyright: ignore[reportPrivateUsage]
            or not _is_empty_single(element, child)]


def iter_written(element: Element) -> Iterator[Element]:
    """The elements :func:`build` writes for ``element``'s subtree, in document order."""
    stack: list[Element] = [element]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(written_children(current)))


class Writer:
    """Writes an element and its subtree, attached models inline under their scope."""

    def __init__(self, formatter: Formatter, top: Element, keyframes: bool = True) -> None:
        self.formatter = formatter
        self.top = top
        self.keyframes = keyframes  # False: leave keyframes out (to learn the composed layout)
        self.skip = formatter.skip_attributes
        # plain output: no precision, threshold or renamed files, so values format inline
        self.plain = (formatter.precision is None and not formatter.zero_threshold
                      and formatter.file_namer is None)
        root = top._root  # pyright: ignore[reportPrivateUsage]
        # which model each joint/actuator/mocap body came from: only composed models need it
        self.tracking = root is not None and bool(root._scopes)  # pyright: ignore[reportPrivateUsage]
        # elements with an attachment frame in their subtree: written as nodes, so attached
        # models' bodies can join them; everything else is written as chunks of text
        self.hosts: set[int] = _hosts(root) if self.tracking and root is not None else set()
        self.pending: deque[tuple[ModelRoot, str]] = deque()  # attached models whose sections follow
        self.joint_owners: list[ModelRoot] = []  # the model of each joint, in document order
        self.actuator_owners: list[ModelRoot] = []
        self.mocap_owners: list[ModelRoot] = []

    # --------------------------------------------------------------- attributes

    def attributes(self, element: Element, prefix: str, model: ModelRoot | None) -> dict[str, str]:
        """The attributes to write, as unescaped text, in grammar order."""
        by_name = element._SPEC.by_name  # pyright: ignore[reportPrivateUsage]
        attrs = element._attrs  # pyright: ignore[reportPrivateUsage]
        return {name: self.general(element, by_name[name], attrs[name], prefix, model)
                for name in self.names(element)}

    def names(self, element: Element) -> list[str]:
        """The names of the attributes to write, in grammar order."""
        attrs = element._attrs  # pyright: ignore[reportPrivateUsage]
        skip = self.skip
        names = [name for name in attrs if name not in skip] if skip else list(attrs)
        # sort the few attributes set rather than scan every attribute the grammar has
        if len(names) > 1:
            names.sort(key=element._SPEC.order.__getitem__)  # pyright: ignore[reportPrivateUsage]
        return names

    def attribute_text(self, element: Element, prefix: str = "",
                       model: ModelRoot | None = None) -> str:
        """`` name="value"`` for each attribute, escaped where text can need it. The common
        values are formatted inline (this loop is most of an export's time); the rest, and
        names and files a scope changes, as :meth:`general` formats them."""
        attrs = element._attrs  # pyright: ignore[reportPrivateUsage]
        by_name = element._SPEC.by_name  # pyright: ignore[reportPrivateUsage]
        plain = self.plain
        parts: list[str] = []
        for name in self.names(element):
            value = attrs[name]
            attribute = by_name[name]
            if plain and (not prefix or attribute.kind not in _SCOPED_KINDS):
                kind = type(value)
                if kind is str:
                    parts.append(f' {name}="{escape(cast(str, value))}"')
                    continue
                if kind is np.ndarray and attribute.dtype == "double":
                    doubles = cast("np.ndarray[tuple[int, ...], np.dtype[np.float64]]", value)
                    parts.append(f' {name}="{_shortest_doubles(doubles.tolist())}"')
                    continue
                if kind is float:
                    parts.append(f' {name}="{_shortest_double(cast(float, value))}"')
                    continue
            text = self.general(element, attribute, value, prefix, model)
            parts.append(f' {name}="{escape(text)}"')
        return "".join(parts)

    def general(self, element: Element, attribute: AttributeSpec, value: object, prefix: str,
                model: ModelRoot | None) -> str:
        if isinstance(value, Element):
            return self.reference(element, attribute, value)
        if prefix and isinstance(value, str) and attribute.kind in ("id", "ref"):
            if value == MAIN_CLASS and attribute.namespace == "default":
                return prefix
            return prefix + value
        if prefix and model is not None and attribute.kind == "file" and isinstance(
                value, str) and self.formatter.file_namer is None:
            return _absolute_file(model, attribute, value)
        return self.formatter.value(element, attribute, value)

    def reference(self, element: Element, attribute: AttributeSpec, target: Element) -> str:
        """A reference to ``target``, scoped as seen from the model being written."""
        name = reference_name(element, attribute, target, same_model=False)
        target_root = target._root  # pyright: ignore[reportPrivateUsage]
        top_root = self.top._root  # pyright: ignore[reportPrivateUsage]
        scopes: list[str] = []
        model = target_root
        while model is not top_root:
            frame = None if model is None else model._frame  # pyright: ignore[reportPrivateUsage]
            if model is None or frame is None:
                raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                                  f"which is not part of this model")
            scopes.append(scope_name(model))
            model = frame._root  # pyright: ignore[reportPrivateUsage]
        return "".join(s + "/" for s in reversed(scopes)) + name

    # --------------------------------------------------------------- elements

    def element(self, element: Element, parent: Node | None, prefix: str,
                model: ModelRoot | None) -> Node:
        """Write ``element``'s subtree under ``parent``; iterative, so depth is unlimited.

        Composition still adds to, or looks into, the model's sections, the attachment
        frames and their ancestors, and sections whose attributes merge (``<option>``...):
        those are nodes. Everything below them is written as chunks of text.
        """
        first: Node | None = None
        # (element, parent node, scope, model it belongs to, inside a merging section)
        stack: list[tuple[Element, Node | None, str, ModelRoot | None, bool]] = [
            (element, parent, prefix, model, False)]
        pop, push = stack.pop, stack.append
        tracking, keyframes = self.tracking, self.keyframes
        while stack:
            current, parent_node, scope, owner, merging = pop()
            if parent_node is not None and first is not None and not self.needs_node(
                    current, merging):
                parent_node.children.append(self.chunk(current, scope, owner))
                continue
            spec = current._SPEC  # pyright: ignore[reportPrivateUsage]
            attrib = self.attributes(current, scope, owner) if current._attrs else {}  # pyright: ignore[reportPrivateUsage]
            node = Node(spec.tag, attrib)
            if first is None:
                first = node
            if parent_node is not None:
                parent_node.children.append(node)
            if tracking and spec.namespace in _TRACKED:
                self._track(spec.namespace, current, owner)
            inner = merging or (spec.compose == "attributes" and isinstance(
                current._parent, ModelRoot))  # pyright: ignore[reportPrivateUsage]
            pending: list[tuple[Element, Node | None, str, ModelRoot | None, bool]] = [
                (child, node, scope, owner, inner) for child in written_children(current)
                if keyframes or child._SPEC.compose != "keyframes"]  # pyright: ignore[reportPrivateUsage]
            attached = current._attached  # pyright: ignore[reportPrivateUsage]
            if attached is not None:
                pending += self.attachment(node, attached, scope + scope_name(attached) + "/")
            for task in reversed(pending):
                push(task)
        assert first is not None
        return first

    def needs_node(self, element: Element, merging: bool) -> bool:
        """Whether composition may add to or look into ``element``: a model's section, an
        attachment frame or one of its ancestors, or part of a section whose attributes
        merge with the attached models'."""
        return (merging or id(element) in self.hosts
                or isinstance(element._parent, ModelRoot))  # pyright: ignore[reportPrivateUsage]

    def chunk(self, element: Element, prefix: str, model: ModelRoot | None,
              extra: dict[str, str] | None = None) -> Chunk:
        """``element``'s subtree, to be written as text where it lands (it holds no
        attachment frame); ``extra`` attributes follow the element's own."""
        if self.tracking:
            for written in iter_written(element):
                namespace = written._SPEC.namespace  # pyright: ignore[reportPrivateUsage]
                if namespace in _TRACKED:
                    self._track(namespace, written, model)
        return Chunk(lambda depth, pretty_print: self.write(
            element, prefix, model, depth, pretty_print, extra))

    def text(self, element: Element, pretty_print: bool) -> str:
        """``element``'s subtree as XML text, written in one pass without building nodes
        (for models with nothing attached: composition needs :meth:`element`'s nodes)."""
        return self.write(element, "", None, 0, pretty_print)

    def write(self, element: Element, prefix: str, model: ModelRoot | None, depth: int,
              pretty_print: bool, extra: dict[str, str] | None = None) -> str:
        """The text of ``element``'s subtree, indented from ``depth``."""
        parts: list[str] = []
        append = parts.append
        newline = "\n" if pretty_print else ""
        step = "  " if pretty_print else ""
        # an element to open, or the text that closes one
        stack: list[tuple[Element | str, int]] = [(element, depth)]
        pop, push = stack.pop, stack.append
        attribute_text = self.attribute_text
        while stack:
            current, level = pop()
            if isinstance(current, str):
                append(current)
                continue
            tag = current._SPEC.tag  # pyright: ignore[reportPrivateUsage]
            attrs = attribute_text(current, prefix, model) if current._attrs else ""  # pyright: ignore[reportPrivateUsage]
            if extra is not None and current is element:
                attrs += "".join([f' {k}="{escape(v)}"' for k, v in extra.items()])
            indent = step * level
            children = written_children(current) if current._children else None  # pyright: ignore[reportPrivateUsage]
            if children:
                append(f"{indent}<{tag}{attrs}>{newline}")
                push((f"{indent}</{tag}>{newline}", level))
                level += 1
                for child in reversed(children):
                    push((child, level))
            else:
                append(f"{indent}<{tag}{attrs}/>{newline}")
        return "".join(parts)

    def _track(self, namespace: str | None, element: Element, model: ModelRoot | None) -> None:
        if model is None:
            return
        if namespace == "joint":
            self.joint_owners.append(model)
        elif namespace == "actuator":
            self.actuator_owners.append(model)
        elif element._attrs.get("mocap") is True:  # pyright: ignore[reportPrivateUsage]
            self.mocap_owners.append(model)

    def attachment(self, frame: Node, model: ModelRoot, scope: str
                   ) -> list[tuple[Element, Node | None, str, ModelRoot | None, bool]]:
        """The attached model's bodies, to be written inside its frame; its other sections
        join the parent's later."""
        if _has_defaults(model) and frame.get("childclass") is None:
            frame.set("childclass", scope)
        self.pending.append((model, scope))
        return [(child, frame, scope, model, False)
                for section in model._children  # pyright: ignore[reportPrivateUsage]
                if "body" in section._SPEC.children  # pyright: ignore[reportPrivateUsage]
                for child in section._children]  # pyright: ignore[reportPrivateUsage]

    # --------------------------------------------------------------- models

    def model(self, root: ModelRoot) -> Node:
        node = self.element(root, None, "", root)
        if not root._scopes:  # pyright: ignore[reportPrivateUsage]
            return node
        keyframes: list[tuple[ModelRoot, Element]] = [
            (root, s) for s in root._children if s.spec.compose == "keyframes"]  # pyright: ignore[reportPrivateUsage]
        while self.pending:
            model, scope = self.pending.popleft()
            for section in model._children:  # pyright: ignore[reportPrivateUsage]
                if section.spec.compose == "keyframes":
                    keyframes.append((model, section))
                elif "body" not in section.spec.children and not _is_empty_single(model, section):
                    self.section(node, section, model, scope)
        if self.keyframes and any(section._children for _, section in keyframes):  # pyright: ignore[reportPrivateUsage]
            from typed_mjcf._keyframes import combine_keyframes

            combine_keyframes(self, node, root, keyframes)
        return node

    def section_node(self, root: Node, tag: str) -> Node:
        """The root's ``<tag>`` section, created at its grammar position if missing."""
        for child in root:
            if child.tag == tag:
                return child
        sections = self.top.spec.children
        rank = sections[tag].index
        node = Node(tag)
        index = next((i for i, child in enumerate(root.children)
                      if isinstance(child, Node) and sections[child.tag].index > rank),
                     len(root.children))
        root.insert(index, node)
        return node

    def section(self, root: Node, section: Element, model: ModelRoot, scope: str) -> None:
        """Join an attached model's section to the root's, as its grammar row says."""
        compose = section.spec.compose
        target = self.section_node(root, section.tag)
        if compose == "attributes":
            self.merge_attributes(target, section, model, scope)
        elif compose == "nest":
            nested = target.sub(section.tag, {"class": scope})
            nested.children += [self.chunk(child, scope, model)
                                for child in written_children(section)]
        else:
            classed = _has_defaults(model)
            for child in written_children(section):
                unclassed = "class" in child.spec.by_name and "class" not in child._attrs  # pyright: ignore[reportPrivateUsage]
                extra = {"class": scope} if classed and unclassed else None
                target.children.append(self.chunk(child, scope, model, extra))

    def merge_attributes(self, target: Node, section: Element, model: ModelRoot,
                         scope: str) -> None:
        for name, text in self.attributes(section, scope, model).items():
            if name in _folders():
                continue  # each model's files resolve in its own folders
            mine = target.get(name)
            if mine is None:
                target.set(name, text)
            elif mine != text:
                raise ExportError(
                    f"<{section.tag}> {name}: {text!r} in attached model "
                    f"{scope.rstrip('/')!r} differs from {mine!r} in the model it is attached to")
        for child in section._children:  # pyright: ignore[reportPrivateUsage]
            sub = next((c for c in target if c.tag == child.tag), None)
            if sub is None:
                sub = target.sub(child.tag)
            self.merge_attributes(sub, child, model, scope)


_TRACKED = frozenset({"joint", "actuator", "body"})
_SCOPED_KINDS = frozenset({"id", "ref", "file"})  # values an attached model's scope changes


def _hosts(root: ModelRoot) -> set[int]:
    """The ids of the attachment frames of ``root`` and of the models attached to it,
    nested ones included, and of all their ancestors."""
    hosts: set[int] = set()
    models = [root]
    while models:
        for attached in models.pop()._scopes.values():  # pyright: ignore[reportPrivateUsage]
            models.append(attached)
            element = attached._frame  # pyright: ignore[reportPrivateUsage]
            while element is not None and id(element) not in hosts:
                hosts.add(id(element))
                element = element._parent  # pyright: ignore[reportPrivateUsage]
    return hosts


def _has_defaults(model: ModelRoot) -> bool:
    for section in model._children:  # pyright: ignore[reportPrivateUsage]
        if section.spec.compose == "nest":
            return bool(section._children or section._attrs)  # pyright: ignore[reportPrivateUsage]
    return False


def _folders() -> frozenset[str]:
    from typed_mjcf._compose import folder_attributes

    return folder_attributes()


def _absolute_file(model: ModelRoot, attribute: AttributeSpec, file: str) -> str:
    """An attached model's file, as a path that does not depend on the parent's folders."""
    from typed_mjcf._assets_io import compiler_folders, resolve_path

    return resolve_path(model, attribute, file, compiler_folders(model))


def build(element: Element, formatter: Formatter, parent: Node | None = None) -> Node:
    """The nodes of ``element`` and its subtree (attached models included)."""
    writer = Writer(formatter, element)
    root = element._root  # pyright: ignore[reportPrivateUsage]
    if parent is None and root is not None and root is element:
        return writer.model(root)
    return writer.element(element, parent, "", root)


def to_xml(element: Element, *, precision: int | None = None, zero_threshold: float = 0.0,
           file_namer: FileNamer | None = None) -> XmlNode:
    text = to_xml_string(element, precision=precision, zero_threshold=zero_threshold,
                         pretty_print=False, file_namer=file_namer)
    return etree.fromstring(text)


def write_text(element: Element, formatter: Formatter, pretty_print: bool = True) -> str:
    """The XML text of ``element`` and its subtree (attached models included)."""
    root = element._root  # pyright: ignore[reportPrivateUsage]
    with collector_paused():  # an export makes no reference cycles, only short-lived text
        if root is not None and not root._scopes:  # pyright: ignore[reportPrivateUsage]
            return Writer(formatter, element).text(element, pretty_print)
        return serialize(build(element, formatter), pretty_print)


def to_xml_string(element: Element, *, precision: int | None = None, zero_threshold: float = 0.0,
                  pretty_print: bool = True, file_namer: FileNamer | None = None) -> str:
    return write_text(element, Formatter(precision, zero_threshold, file_namer), pretty_print)
