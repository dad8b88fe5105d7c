"""Writing elements as MJCF text, iteratively (depth is unlimited).

Every value is written by its attribute's codec with the export's :class:`Format`; names
and references are written as seen from the model being exported: an element's name takes
the prefix of its scope (``arm/`` for what an attached model ``arm`` holds), a reference the
scoped name its target has now.

A model with nothing attached is written straight to text in one pass. A composed model is
built as light nodes where composition joins the attached models' sections and bodies to
the parent's (the sections, the attachment frames and their ancestors), with every other
subtree a chunk of text written in place when the nodes are serialised. The keyframes of a
composed model are combined elsewhere (:mod:`typed_mjcf._model.keyframes`): the writer leaves them
out and reports their sections, and which model each joint, actuator and mocap body came
from.
"""

from __future__ import annotations

import functools
from collections import deque
from collections.abc import Callable, Iterator, Mapping
from typing import Final, cast

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.errors import ExportError
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec, WritePlan
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.files import absolute_file, element_file_stem, is_skin_file, name_files
from typed_mjcf._text.merge import combine, rule_of
from typed_mjcf._text.xmltext import MAX_INDENT, Chunk, Node, escape, has_markup, indent
from typed_mjcf.assets import Asset

# The text of a file attribute when the files are renamed (for a virtual file system).
FileNamer = Callable[[Element, AttributeSpec], str]


def is_empty_single(parent: Element, child: Element) -> bool:
    """A once-only child with nothing to say: no attributes, no attached model, and only
    children like itself. Such sections are not written (reading them gives nothing back)."""
    if _tree.values(child) or _tree.attached_at(child) is not None:
        return False
    child_spec = parent.spec.children.get(child.spec.tag)
    if child_spec is None or not child_spec.single:
        return False
    return all(is_empty_single(child, grandchild) for grandchild in _tree.children(child))


def written_children(element: Element) -> list[Element]:
    """The children an export writes: all but once-only sections with nothing to say."""
    child_specs = type(element).spec.children
    return [child for child in _tree.children(element)
            if _tree.values(child) or not child_specs[type(child).spec.tag].single
            or not is_empty_single(element, child)]


def iter_written(element: Element) -> Iterator[Element]:
    """The elements the writer writes for ``element``'s subtree, in document order
    (attached models not included)."""
    stack: list[Element] = [element]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(written_children(current)))


def has_defaults(model: ModelBase) -> bool:
    """Whether the model's default classes say anything (its classes nest when attached)."""
    for section in _tree.children(model):
        if section.spec.compose == "nest":
            return bool(_tree.children(section) or _tree.values(section))
    return False


# (element, parent node, inside a section whose attributes merge)
_Task = tuple[Element, Node | None, bool]


class Writer:
    """Writes an element and its subtree, attached models inline under their scope."""

    def __init__(self, top: Element, fmt: Format = DEFAULT_FORMAT,
                 file_namer: FileNamer | None = None,
                 skip_attributes: frozenset[str] = frozenset(),
                 names_from: NameScope | None = None) -> None:
        self.fmt = fmt
        self.top = top
        self.file_namer = file_namer  # renames every file (paths and in-memory assets)
        self.skip = skip_attributes
        root = _tree.model_of(top)
        own = _tree.scope_of(root) if root is not None else _tree.scope_of(top)
        # names are written as seen from this scope (dm_control's prefix_root)
        scope = own if names_from is None else names_from
        self.top_scope = scope
        self.prefixes: dict[int, str] = {id(scope): ""}
        self.composed = root is not None and bool(own.attached)
        # verbatim output: nothing renamed or reformatted, so texts stored as read are
        # written as they are (what their codecs write for them with such a format)
        self.verbatim = fmt.keeps_source_text and file_namer is None
        # elements with an attachment frame in their subtree: written as nodes, so attached
        # models' bodies can join them; everything else is written as chunks of text
        self.hosts: set[int] = _hosts(root) if self.composed and root is not None else set()
        self.pending: deque[ModelBase] = deque()  # attached models whose sections follow
        # the model of each joint, actuator and mocap body, in document order (composed)
        self.joint_owners: list[ModelBase] = []
        # the body each joint moves, by its place among the bodies written (MuJoCo numbers
        # joints body by body: a body's joints come before its children's, wherever written)
        self.joint_bodies: list[int] = []
        self.body_numbers: dict[int, int] = {}
        self.actuator_owners: list[ModelBase] = []
        self.mocap_owners: list[ModelBase] = []
        # composed models: each model's keyframe section, for combining (left out here)
        self.keyframe_sections: list[tuple[ModelBase, Element]] = []
        self._flat_names: dict[tuple[int, str], str] | None = None
        self.targets: dict[int, str] = {}  # the text of each element references link to
        # the scope whose elements' texts are written as stored (verbatim output; else none)
        self.verbatim_scope = scope if self.verbatim and not skip_attributes else None
        # names this export gives unnamed elements that references link to
        self.given_names: dict[int, str] = _names_to_give(top, scope)
        if self.composed:
            self.given_names.update(_file_names_of_attached(scope))

    # --------------------------------------------------------------- names

    def prefix(self, scope: NameScope) -> str:
        """The prefix of names in ``scope`` as seen from the model being written
        (:meth:`NameScope.prefix`, cached)."""
        found = self.prefixes.get(id(scope))
        if found is not None:
            return found
        current: NameScope | None = scope
        while current is not None and current is not self.top_scope:
            current = current.parent
        if current is None:
            raise ExportError(f"names of model {scope.name!r} cannot be written as part of "
                              f"this model: it is not attached into it")
        text = scope.prefix(self.top_scope)
        self.prefixes[id(scope)] = text
        return text

    def reference(self, element: Element, attribute: AttributeSpec, target: Element) -> str:
        """A reference to ``target``, scoped as seen from the model being written."""
        name = _tree.element_name(target)
        if _tree.model_of(target) is None:
            raise ExportError(f"{element.path}: {attribute.py_name} refers to a "
                              f"<{target.spec.tag}> that was removed from its model")
        scope = _tree.scope_of(target)
        if name is None:
            if _is_main_class(target):
                return self.main_class(scope)
            name = self.given_names.get(id(target))
            if name is None:
                raise ExportError(f"{element.path}: {attribute.py_name} refers to "
                                  f"{target.path}, which has no name and is not written here")
        else:  # the target's name, as a reference's codec writes a name
            name = attribute.codec.write(name, self.fmt)
        try:
            return self.prefix(scope) + name + _frame_child_suffix(target)
        except ExportError:
            raise ExportError(f"{element.path}: {attribute.py_name} refers to {target.path}, "
                              f"which is not part of this model") from None

    def main_class(self, scope: NameScope) -> str:
        """The name of a model's top-level default class: ``main``, or the scope of an
        attached model (its classes nest in a class named after it)."""
        prefix = self.prefix(scope)
        return prefix or grammar_facts().main_class

    # --------------------------------------------------------------- attributes

    def names(self, element: Element) -> list[str]:
        """The names of the attributes to write, in grammar order."""
        names = grammar_order(element.spec, _tree.values(element))
        skip = self.skip
        return [name for name in names if name not in skip] if skip else list(names)

    def given_name(self, element: Element) -> str:
        """`` name="..."`` for an unnamed element this export names."""
        id_attribute = element.spec.id_attribute
        assert id_attribute is not None
        name = self.prefix(_tree.scope_of(element)) + self.given_names[id(element)]
        return f'{id_attribute.name}="{escape(name)}"'

    def attributes(self, element: Element) -> dict[str, str]:
        """The attributes to write, as unescaped text, in grammar order."""
        by_name = element.spec.by_name
        stored = _tree.values(element)
        texts: dict[str, str] = {}
        if self.given_names and id(element) in self.given_names:
            id_attribute = element.spec.id_attribute
            assert id_attribute is not None
            texts[id_attribute.name] = (self.prefix(_tree.scope_of(element))
                                        + self.given_names[id(element)])
        for name in self.names(element):
            text = self.value(element, by_name[name], stored[name])
            if text is not None:
                texts[name] = text
        return texts

    def attribute_text(self, element: Element, stored: Mapping[str, object]) -> str:
        """`` name="value"`` for each of ``element``'s ``stored`` values (this loop is most
        of an export's time). In verbatim output, a text stored as read is written as it is
        where its codec says so (the plan's flag, from ``Codec.keeps_read_text``: what
        ``Codec.write`` does for it), into the template of the element's set of attributes,
        and escaped only if the result shows something to escape (one check per element
        rather than per value)."""
        spec = type(element).spec
        key = tuple(stored)
        plan = spec.plans.get(key)
        if plan is None:
            plan = write_plan(spec, key)
        if _tree.scope_of(element) is not self.verbatim_scope or (
                self.given_names and id(element) in self.given_names):
            return self.escaped_attribute_text(element, stored, plan)
        texts: list[str] = []
        append = texts.append
        fmt, targets = self.fmt, self.targets
        for name, attribute, as_is in plan[1]:
            value = stored[name]
            if as_is and type(value) is str:  # as its codec writes it (planned once)
                append(value)
            elif attribute.codec_only:
                append(attribute.codec.write(value, fmt))
            elif id(value) in targets:  # a link to an element already written to
                append(targets[id(value)])
            else:
                text = self.value(element, attribute, value)
                if text is None:  # not written (a link to a removed element)
                    return self.escaped_attribute_text(element, stored, plan)
                append(text)
        out = plan[2] % tuple(texts)
        if out.count('"') != 2 * len(texts) or has_markup(out):
            return self.escaped_attribute_text(element, stored, plan)
        return out

    def escaped_attribute_text(self, element: Element, stored: Mapping[str, object],
                               plan: WritePlan) -> str:
        """:meth:`attribute_text` value by value (``plan``: the write plan of ``stored``'s
        names), each text escaped: for output that is not verbatim, and values that need
        escaping."""
        verbatim = self.verbatim and _tree.scope_of(element) is self.top_scope
        parts: list[str] = []
        if self.given_names and id(element) in self.given_names:
            parts.append(f' {self.given_name(element)}')
        skip = self.skip
        fmt = self.fmt
        for name, attribute, as_is in plan[1]:
            if skip and name in skip:
                continue
            value = stored[name]
            if attribute.codec_only:
                if type(value) is str:  # text (or numbers as read: they may hold tabs)
                    text = attribute.codec.write(value, fmt)
                    parts.append(f' {name}="{escape(text)}"')
                else:  # numbers set in Python: nothing to escape
                    parts.append(f' {name}="{attribute.codec.write(value, fmt)}"')
                continue
            if verbatim and as_is and type(value) is str and attribute.kind == "id":
                parts.append(f' {name}="{escape(value)}"')  # (as its codec writes it)
                continue
            written = self.value(element, attribute, value)
            if written is not None:
                parts.append(f' {name}="{escape(written)}"')
        return "".join(parts)

    def value(self, element: Element, attribute: AttributeSpec, value: object) -> str | None:
        """One attribute's text (``None``: nothing to write, e.g. a link to a removed
        element, which ``validate()`` reports)."""
        kind = attribute.kind
        if isinstance(value, Element):
            if _tree.model_of(value) is None:
                return None
            # the same for every reference to that element: worked out once per export
            text = self.targets.get(id(value))
            if text is None:
                text = self.targets[id(value)] = self.reference(element, attribute, value)
            return text
        if kind == "file":
            if self.file_namer is not None:
                return self.file_namer(element, attribute)
            return self.file_text(element, attribute, value)
        if attribute.name_list is not None:  # names, each scoped like a reference
            text = attribute.codec.write(value, self.fmt)
            scope = _tree.scope_of(element)
            if scope is self.top_scope:
                return text
            prefix = self.prefix(scope)
            return " ".join(prefix + name for name in text.split())
        if kind == "id" or attribute.is_reference:
            text = attribute.codec.write(value, self.fmt)
            scope = _tree.scope_of(element)
            if scope is self.top_scope:
                return text
            if kind == "ref" and attribute.namespace == grammar_facts().class_namespace and (
                    text == grammar_facts().main_class):
                return self.main_class(scope)
            if kind == "id":
                return self.prefix(scope) + text + _frame_child_suffix(element)
            return self.prefix(scope) + text
        return attribute.codec.write(value, self.fmt)

    def file_text(self, element: Element, attribute: AttributeSpec, value: object) -> str:
        """A file path as the MJCF text writes it: as the source names it, so the text loads
        beside its source (an attached model's as an absolute path, which its parent's
        folders cannot change); in-memory contents (and an attached model's skin, whose bones
        are renamed) by the name ``get_assets()`` gives them."""
        if isinstance(value, Asset):
            return self.flat_file_names()[(id(element), attribute.name)]
        text = cast(str, value)
        scope = _tree.scope_of(element)
        if scope is not self.top_scope:
            if is_skin_file(element, attribute):
                return self.flat_file_names()[(id(element), attribute.name)]
            text = absolute_file(_tree.scope_model(scope), attribute, text)
        return text

    def flat_file_names(self) -> dict[tuple[int, str], str]:
        """The flat names of the files (named once per export, when the first is written)."""
        if self._flat_names is None:
            root = _tree.model_of(self.top)
            self._flat_names = {} if root is None else name_files(
                _tree.scope_model(self.top_scope)).names
        return self._flat_names

    # --------------------------------------------------------------- elements

    def element(self, element: Element, parent: Node | None) -> Node:
        """Write ``element``'s subtree under ``parent``; iterative, so depth is unlimited.

        Composition still adds to, or looks into, the model's sections, the attachment
        frames and their ancestors, and sections whose attributes merge (``<option>``...):
        those are nodes. Everything below them is written as chunks of text.
        """
        first: Node | None = None
        stack: list[_Task] = [(element, parent, False)]
        pop, push = stack.pop, stack.append
        while stack:
            current, parent_node, merging = pop()
            if parent_node is not None and first is not None and not self.needs_node(
                    current, merging):
                parent_node.children.append(self.chunk(current))
                continue
            spec = current.spec
            named = _tree.values(current) or id(current) in self.given_names
            attrib = self.attributes(current) if named else {}
            node = Node(spec.tag, attrib)
            if first is None:
                first = node
            if parent_node is not None:
                parent_node.children.append(node)
            if self.composed:
                self.track(current)
            inner = merging or (spec.compose == "attributes" and isinstance(
                current.parent, ModelBase))
            pending: list[_Task] = []
            attached = _tree.attached_at(current)
            frame_class = None if attached is None else self.frame_class(current, attached)
            for child in written_children(current):
                if self.composed and child.spec.compose == "keyframes" and isinstance(
                        current, ModelBase):
                    self.keyframe_sections.append((current, child))
                    continue
                if frame_class is not None and id(child) not in self.hosts:
                    node.children.append(self.chunk(child, frame_class(child)))
                    continue
                pending.append((child, node, inner))
            if attached is not None:
                pending += self.attachment(node, attached)
            for task in reversed(pending):
                push(task)
        assert first is not None
        return first

    def needs_node(self, element: Element, merging: bool) -> bool:
        """Whether composition may add to or look into ``element``: a model's section, an
        attachment frame or one of its ancestors, or part of a section whose attributes
        merge with the attached models'."""
        return merging or id(element) in self.hosts or isinstance(element.parent, ModelBase)

    def chunk(self, element: Element, extra: dict[str, str] | None = None) -> Chunk:
        """``element``'s subtree, to be written as text where it lands (it holds no
        attachment frame); ``extra`` attributes follow the element's own."""
        if self.composed:
            for written in iter_written(element):
                self.track(written)
        return Chunk(lambda depth, pretty_print: self.write(element, depth, pretty_print, extra))

    def start_tag(self, element: Element) -> str:
        """The element alone: its start tag, ``...`` for its children (dm_control's
        ``self_only``)."""
        stored = _tree.values(element)
        self.given_names.pop(id(element), None)  # as dm_control's str(): no name made up
        attrs = self.attribute_text(element, stored) if stored else ""
        tag = element.spec.tag
        if _tree.children(element) or _tree.attached_at(element) is not None:
            return f"<{tag}{attrs}>...</{tag}>"
        return f"<{tag}{attrs}/>"

    def text(self, element: Element, pretty_print: bool) -> str:
        """``element``'s subtree as XML text, written in one pass without building nodes
        (for models with nothing attached: composition needs :meth:`element`'s nodes)."""
        return self.write(element, 0, pretty_print)

    def write(self, element: Element, depth: int, pretty_print: bool,
              extra: dict[str, str] | None = None) -> str:
        """The text of ``element``'s subtree, indented from ``depth``."""
        parts: list[str] = []
        append = parts.append
        newline = "\n" if pretty_print else ""
        indents = INDENTS if pretty_print else _NO_INDENTS
        deepest = len(indents) - 1  # deeper levels are indented as much
        # the open elements: their children still to write, and their closing text
        stack: list[tuple[Iterator[Element], str]] = []
        # (direct calls, not local aliases: compiled, an alias is a Python-level call; the
        # spec read from the class: an element's own lookup passes its __getattr__ hook)
        given_names = self.given_names
        current, level = element, depth
        spaces = indents[min(deepest, level)]
        while True:
            tag = type(current).spec.tag
            stored = _tree.values(current)
            # (an element without attributes may still get a name from this export)
            named = stored or (given_names and id(current) in given_names)
            attrs = self.attribute_text(current, stored) if named else ""
            if extra is not None and current is element:
                attrs += "".join([f' {k}="{escape(v)}"' for k, v in extra.items()])
            children = written_children(current) if _tree.children(current) else None
            if children:
                append(f"{spaces}<{tag}{attrs}>{newline}")
                stack.append((iter(children), f"{spaces}</{tag}>{newline}"))
                level += 1
                spaces = indents[min(deepest, level)]
            else:
                append(f"{spaces}<{tag}{attrs}/>{newline}")
            # the next element: the next child of the innermost element still open
            while stack:
                following = next(stack[-1][0], None)
                if following is not None:
                    current = following
                    break
                append(stack.pop()[1])
                level -= 1
                spaces = indents[min(deepest, level)]
            else:
                return "".join(parts)

    def track(self, element: Element) -> None:
        """Note which model a joint, actuator or mocap body of a composed model came from."""
        namespace = element.spec.namespace
        model = _tree.model_of(element)  # the tree it is in: what the model's keys describe
        if namespace is None or model is None:
            return
        facts = grammar_facts()
        if element.spec.row in facts.joints:
            self.joint_owners.append(model)
            body = element.parent
            while body is not None and body.spec.tag != facts.body:  # frames are transparent
                body = body.parent
            self.joint_bodies.append(-1 if body is None else self.body_numbers.get(id(body), -1))
        elif namespace == facts.actuator_namespace:
            self.actuator_owners.append(model)
        elif element.spec.tag == facts.body:
            self.body_numbers[id(element)] = len(self.body_numbers)
            if _tree.values(element).get(facts.mocap) is True:
                self.mocap_owners.append(model)

    def frame_class(self, frame: Element,
                    model: ModelBase) -> Callable[[Element], dict[str, str] | None] | None:
        """For an attachment frame whose ``childclass`` gives the attached model's bodies
        their model's defaults: what each of the frame's own children (a joint added to the
        frame, say) must write to keep the defaults of the model the frame is in, as in
        dm_control: ``class`` naming the class that applies at the frame there."""
        if not has_defaults(model):
            return None
        facts = grammar_facts()
        text = self.main_class(_tree.scope_of(frame))
        ancestor = frame.parent
        while ancestor is not None:
            childclass = ancestor.spec.by_name.get(facts.childclass)
            stored = _tree.values(ancestor).get(facts.childclass)
            if childclass is not None and stored is not None:
                text = self.value(ancestor, childclass, stored) or text
                break
            ancestor = ancestor.parent

        def extra(child: Element) -> dict[str, str] | None:
            classed = facts.dclass in child.spec.by_name
            return {facts.dclass: text} if classed and facts.dclass not in _tree.values(
                child) else None
        return extra

    def attachment(self, frame: Node, model: ModelBase) -> list[_Task]:
        """The attached model's bodies, to be written inside its frame; its other sections
        join the parent's later."""
        if has_defaults(model) and frame.get(grammar_facts().childclass) is None:
            frame.set(grammar_facts().childclass, self.main_class(_tree.scope_of(model)))
        self.pending.append(model)
        return [(child, frame, False)
                for section in _tree.children(model) if section.spec.holds_bodies
                for child in _tree.children(section)]

    # --------------------------------------------------------------- models

    def model(self, root: ModelBase) -> Node:
        node = self.element(root, None)
        while self.pending:
            model = self.pending.popleft()
            for section in _tree.children(model):
                if section.spec.compose == "keyframes":
                    self.keyframe_sections.append((model, section))
                elif not section.spec.holds_bodies and not is_empty_single(model, section):
                    self.section(node, section, model)
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

    def section(self, root: Node, section: Element, model: ModelBase) -> None:
        """Join an attached model's section to the root's, as its grammar row says."""
        compose = section.spec.compose
        target = self.section_node(root, section.spec.tag)
        if compose == "attributes":
            self.merge_attributes(target, section)
        elif compose == "nest":
            scope_class = self.main_class(_tree.scope_of(model))
            nested = target.sub(section.spec.tag, {grammar_facts().dclass: scope_class})
            nested.children += [self.chunk(child) for child in written_children(section)]
        else:
            classed = has_defaults(model)
            dclass = grammar_facts().dclass
            scope_class = self.main_class(_tree.scope_of(model)) if classed else ""
            for child in written_children(section):
                unclassed = dclass in child.spec.by_name and dclass not in _tree.values(child)
                extra = {dclass: scope_class} if classed and unclassed else None
                target.children.append(self.chunk(child, extra))

    def merge_attributes(self, target: Node, section: Element) -> None:
        for name, text in self.attributes(section).items():
            if name in folder_attributes():
                continue  # each model's files resolve in its own folders
            mine = target.get(name)
            if mine is None:
                target.set(name, text)
            elif mine != text:
                attribute = section.spec.by_name[name]
                rule = rule_of(section, name)
                merged = None if rule is None else combine(
                    rule, attribute.codec.read(attribute.codec.parse(mine)),
                    attribute.codec.read(attribute.codec.parse(text)))
                if merged is None:
                    scope = self.prefix(_tree.scope_of(section)).rstrip(SEPARATOR)
                    raise ExportError(
                        f"Conflicting values for attribute `{name}` of <{section.spec.tag}>: "
                        f"{text!r} in attached model {scope!r}, {mine!r} in the model it is "
                        f"attached to")
                target.set(name, attribute.codec.write(attribute.codec.accept(merged),
                                                       self.fmt))
        for child in _tree.children(section):
            sub = next((c for c in target if c.tag == child.spec.tag), None)
            if sub is None:
                sub = target.sub(child.spec.tag)
            self.merge_attributes(sub, child)


# The indentation of each level, up to the deepest (see _xmltext.indent).
INDENTS: Final = tuple(indent(level) for level in range(MAX_INDENT // 2 + 2))
_NO_INDENTS: Final = ("",)


_PLANS_PER_ROW: Final = 256  # sets of attributes whose plan a row keeps (see below)


def write_plan(spec: ElementSpec, key: tuple[str, ...]) -> WritePlan:
    """How to write an element of ``spec`` whose values have the names ``key`` (in their
    order). The elements of a row mostly set one of a few sets of attributes: each set's
    plan is kept (for that many sets) rather than sorted for each element."""
    plan = spec.plans.get(key)
    if plan is not None:
        return plan
    by_name = spec.by_name
    # the grammar's own strings (values are stored under them): looked up by identity
    names = tuple(sorted((by_name[name].name for name in key), key=spec.order.__getitem__))
    # whether a text stored as read is written as it is: the attribute's (texts written
    # unchanged by the exporter: not files, nor names of attached models) and its codec's
    plan = (names, tuple((name, by_name[name],
                          by_name[name].as_is and by_name[name].codec.keeps_read_text)
                         for name in names),
            "".join(f' {name}="%s"' for name in names))
    if len(spec.plans) < _PLANS_PER_ROW:
        spec.plans[key] = plan
    return plan


def grammar_order(spec: ElementSpec, stored: Mapping[str, object]) -> tuple[str, ...]:
    """The names of ``stored`` (an element's values) in the order of ``spec``'s grammar."""
    return write_plan(spec, tuple(stored))[0]


@functools.cache
def folder_attributes() -> frozenset[str]:
    """The <compiler> attributes that name folders of files: each model keeps its own."""
    names: set[str] = set()
    for cls in _tree.element_classes().values():
        for attribute in cls.spec.attributes.values():
            names.update(attribute.directory)
    return frozenset(names)


def _is_main_class(element: Element) -> bool:
    """Whether ``element`` is a model's top-level default class (named by its model)."""
    return element.spec.compose == "nest" and isinstance(element.parent, ModelBase)


def _names_to_give(top: Element, top_scope: NameScope) -> dict[int, str]:
    """Names for unnamed elements MJCF must name: every attachment frame, named after its
    model (``arm/``, as dm_control names it), and whatever a reference links to, named
    ``unnamed_<kind>_<n>`` with the first number free in its scope (MJCF refers by name).
    Nothing is stored on the elements."""
    given: dict[int, str] = {}
    candidates: dict[int, Element] = {}
    for scope in top_scope.scopes():
        if scope is not top_scope and scope.name is not None:
            frame = _tree.frame_of(_tree.scope_model(scope))
            if frame is not None and _tree.element_name(frame) is None:
                given[id(frame)] = f"{scope.name}/"
    if FLAGS.unnamed_identifiers:
        _dm_control_names(top_scope, given)
        return given
    for scope in top_scope.scopes():
        for target in scope.unnamed_targets:
            assert isinstance(target, Element)
            if _tree.element_name(target) is None and not target.is_removed:
                candidates[id(target)] = target
    if not candidates:
        return given
    linked: set[int] = set()
    for element in _tree.iter_composed(top, True):
        stored = _tree.values(element)
        for attribute in element.spec.references:
            value = stored.get(attribute.name)
            if isinstance(value, Element) and id(value) in candidates:
                linked.add(id(value))
    taken: set[tuple[int, str, str]] = set()
    for key in sorted(linked, key=list(candidates).index):
        if key in given:
            continue
        target = candidates[key]
        scope = _tree.scope_of(target)
        namespace = target.spec.namespace or target.spec.tag
        n = 0
        while (scope.lookup(namespace, f"unnamed_{namespace}_{n}") is not None
               or (id(scope), namespace, f"unnamed_{namespace}_{n}") in taken):
            n += 1
        name = f"unnamed_{namespace}_{n}"
        taken.add((id(scope), namespace, name))
        given[key] = name
    return given


def _frame_child_suffix(element: Element) -> str:
    """dm_control's names of an attachment frame's own children end in ``/``
    (``arm/root_x/``): with ``frame_names_end_in_separator``, ``/`` for them, else nothing."""
    if not FLAGS.frame_names_end_in_separator:
        return ""
    parent = element.parent
    if parent is None or _tree.attached_at(parent) is None or (
            _tree.scope_of(parent) is _tree.scope_of(element)):
        return ""
    return SEPARATOR


def _dm_control_names(top_scope: NameScope, given: dict[int, str]) -> None:
    """dm_control's names for every unnamed element of a namespace (the compat room's
    count): ``unnamed_<kind>_<i>`` after ``/`` (``//`` in the model written); an attachment
    frame's own children take the frame's name, and a frame keeps its own (``arm/``)."""
    for scope in top_scope.scopes():
        lead = SEPARATOR if scope is top_scope else ""
        for key, name in _tree.COMPAT.unnamed_names(_tree.scope_model(scope)).items():
            given.setdefault(key, lead + name if name else "")


def _file_names_of_attached(top_scope: NameScope) -> dict[int, str]:
    """The unnamed assets of attached models that MuJoCo names after their file: written
    with that name, so that it takes the model's prefix as the references to it do."""
    named_after_file = grammar_facts().named_after_file
    given: dict[int, str] = {}
    for scope in top_scope.scopes():
        if scope is top_scope:
            continue
        for section in _tree.children(_tree.scope_model(scope)):
            for element in _tree.children(section):
                attribute = named_after_file.get(element.spec.namespace or "")
                if attribute is not None and _tree.element_name(element) is None:
                    stem = element_file_stem(element, attribute)
                    if stem:
                        given[id(element)] = stem
    return given


def _hosts(root: ModelBase) -> set[int]:
    """The ids of the attachment frames of ``root`` and of the models attached to it,
    nested ones included, and of all their ancestors."""
    hosts: set[int] = set()
    models = [root]
    while models:
        for attached in _tree.attached_models(models.pop()):
            models.append(attached)
            element = _tree.frame_of(attached)
            while element is not None and id(element) not in hosts:
                hosts.add(id(element))
                element = element.parent
    return hosts
