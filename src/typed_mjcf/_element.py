"""The element tree: children, validated attributes, identifiers and error paths.

The generated classes subclass :class:`Element` and declare a ``_SPEC``; everything else is
generic. Attribute descriptors, child properties and ``add_<tag>`` methods are installed here
from the spec when a generated class is created, so the generated code carries only tables
and static types.
"""

from __future__ import annotations

import copy as _copy
from collections.abc import Callable, Iterator, Mapping
from typing import TYPE_CHECKING, ClassVar, NoReturn, Protocol, Self, TypeVar, cast, overload

import numpy as np

from typed_mjcf._convert import Rejected
from typed_mjcf._spec import AttributeSpec, ChildSpec, ElementSpec
from typed_mjcf.errors import (
    ChildError,
    DuplicateIdentifierError,
    InvalidTypeError,
    InvalidValueError,
    UnknownAttributeError,
    did_you_mean,
)

if TYPE_CHECKING:
    from lxml import etree

    from typed_mjcf._root import ModelRoot

_REGISTRY: dict[str, type[Element]] = {}
_new_object = object.__new__
_set_slot = object.__setattr__  # elements' own __setattr__ validates; their slots bypass it
_NO_CHILDREN: tuple[()] = ()
E = TypeVar("E", bound="Element")


def element_class(class_name: str) -> type[Element]:
    """The generated class of that name."""
    return _REGISTRY[class_name]


def _short(value: object, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


class Element:
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""

    __slots__ = (
        "__weakref__",
        "_attached",
        "_attrs",
        "_children",
        "_parent",
        "_root",
        "_singles",
    )
    _SPEC: ClassVar[ElementSpec]

    _attrs: dict[str, object]
    _children: list[Element] | tuple[()]  # () until the first child: fewer objects for the GC
    _parent: Element | None
    _root: ModelRoot | None
    _singles: dict[str, Element] | None
    _attached: ModelRoot | None  # on attachment frames: the model attached there

    # ------------------------------------------------------------------ class set-up

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        spec: ElementSpec | None = cls.__dict__.get("_SPEC")
        if spec is None:
            return
        _REGISTRY[cls.__name__] = cls
        for attribute in spec.attributes:
            setattr(cls, attribute.py_name, attribute)
        for child in spec.children.values():
            setattr(cls, child.py_name, SingleChild(child) if child.single else ChildList(child))
            setattr(cls, "add_" + child.tag, _adder(child))
        if spec.attachable and "attach" not in spec.children:
            setattr(cls, "attach", cls.attach_model)  # dm_control's name
    def __init__(self) -> None:
        raise TypeError(
            f"{type(self).__name__} elements are created by their parent, "
            f"e.g. parent.add_{self._SPEC.tag}(...) or parent.add({self._SPEC.tag!r}, ...)"
        )

    @classmethod
    def _blank(cls, parent: Element | None, root: ModelRoot | None) -> Self:
        element = _new_object(cls)
        _init_attrs(element, {})
        _init_children(element, _NO_CHILDREN)
        _init_parent(element, parent)
        _init_root(element, root)
        _init_singles(element, None)
        _init_attached(element, None)
        return element

    # ------------------------------------------------------------------ identity

    @property
    def tag(self) -> str:
        """The XML tag."""
        return self._SPEC.tag

    @property
    def spec(self) -> ElementSpec:
        """The grammar row of this element."""
        return self._SPEC

    @property
    def parent(self) -> Element | None:
        """The parent element; ``None`` for a model's root or a removed element."""
        return self._parent

    @property
    def root(self) -> ModelRoot:
        """The model this element belongs to."""
        root = self._root
        if root is None:
            raise ChildError(f"{self.path}: the element is not part of a model (it was removed)")
        return root

    @property
    def path(self) -> str:
        """Where the element is in its model, e.g. ``worldbody/body[upper_arm]/geom[0]``."""
        steps: list[str] = []
        element: Element = self
        while element._parent is not None:
            steps.append(element._step())
            element = element._parent
        if not steps:
            return "<root>" if element is self and self._root is self else f"<{self.tag}>"
        scope = self._root.namescope if self._root is not None else ""
        return scope + "/".join(reversed(steps))

    def _step(self) -> str:
        parent = self._parent
        assert parent is not None
        tag = self._SPEC.tag
        child_spec = parent._SPEC.children.get(tag)
        if child_spec is not None and child_spec.single:
            return tag
        id_attribute = self._SPEC.id_attribute
        if id_attribute is not None:
            name = self._attrs.get(id_attribute.name)
            if name is not None:
                return f"{tag}[{name}]"
        index = 0
        for sibling in parent._children:
            if sibling is self:
                return f"{tag}[{index}]"
            if sibling._SPEC.tag == tag:
                index += 1
        return f"{tag}[new]"

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.path}>"

    # ------------------------------------------------------------------ attributes

    if not TYPE_CHECKING:  # run time only: checkers should see unknown attributes as errors

        def __getattr__(self, name: str) -> NoReturn:
            # Only reached when normal lookup fails: an attribute the grammar doesn't have.
            if name.startswith("__"):
                raise AttributeError(name)
            raise self._unknown_attribute(name)

        def __setattr__(self, name: str, value: object) -> None:
            try:
                object.__setattr__(self, name, value)
            except AttributeError:
                raise self._unknown_attribute(name) from None

    def _unknown_attribute(self, name: str) -> UnknownAttributeError:
        spec = self._SPEC
        known = [a.py_name for a in spec.attributes]
        hint = did_you_mean(name, known + [c.py_name for c in spec.children.values()])
        return UnknownAttributeError(
            f"{self.path}: <{spec.tag}> has no attribute {name!r}{hint}; "
            f"its attributes are: {', '.join(known) or '(none)'}"
        )

    def _reject(self, attribute: AttributeSpec, value: object, rejected: Rejected) -> Exception:
        return rejected.error(
            f"{self.path}: invalid {attribute.py_name}={_short(value)} on <{self._SPEC.tag}>: "
            f"expected {rejected.expected}"
        )

    def _set_attribute(self, attribute: AttributeSpec, value: object) -> None:
        attrs = self._attrs
        if value is None:
            old = attrs.pop(attribute.name, None)
            if old is not None and attribute.kind == "id" and self._root is not None:
                self._root._forget_identifier(attribute.namespace, old, self)  # pyright: ignore[reportPrivateUsage]
            return
        try:
            converted = attribute.convert(value)
        except Rejected as rejected:
            raise self._reject(attribute, value, rejected) from None
        if attribute.kind == "id":
            self._claim_identifier(attribute, converted)
        elif attribute.kind == "ref" and not isinstance(converted, str):
            self._check_reference(attribute, converted)
        attrs[attribute.name] = converted

    def _claim_identifier(self, attribute: AttributeSpec, name: object) -> None:
        root = self._root
        if root is None:
            return
        assert isinstance(name, str) and attribute.namespace is not None
        tables = root._identifiers  # pyright: ignore[reportPrivateUsage]
        table = tables.get(attribute.namespace)
        if table is None:
            table = tables[attribute.namespace] = {}
        holder = table.get(name)
        if holder is not None and holder is not self:
            raise DuplicateIdentifierError(
                f"{self.path}: invalid {attribute.py_name}={name!r} on <{self._SPEC.tag}>: "
                f"expected a name unique in namespace {attribute.namespace!r}, "
                f"but {holder.path} has it"
            )
        old = self._attrs.get(attribute.name)
        if isinstance(old, str) and old != name and table.get(old) is self:
            del table[old]
        table[name] = self

    def _check_reference(self, attribute: AttributeSpec, target: object) -> None:
        assert isinstance(target, Element)
        id_attribute = target._SPEC.id_attribute
        if id_attribute is None or target._attrs.get(id_attribute.name) is None:
            raise InvalidValueError(
                f"{self.path}: invalid {attribute.py_name}={target!r} on <{self._SPEC.tag}>: "
                f"expected a named element (give {target.path} a name first)"
            )

    def resolve(self, name: str) -> object:
        """The value MuJoCo uses for attribute ``name``: set here, else from the default
        classes that apply (``class``, an ancestor's ``childclass``, the root class), else the
        grammar's default; ``None`` where MuJoCo computes it (e.g. from other attributes)."""
        from typed_mjcf._defaults import resolve

        return resolve(self, name)

    def get_attributes(self) -> dict[str, object]:
        """The attributes that are set, by Python name, in grammar order."""
        attrs = self._attrs
        spec = self._SPEC
        by_name = spec.by_name
        return {by_name[name].py_name: attrs[name]
                for name in sorted(attrs, key=spec.order.__getitem__)}

    def set_attributes(self, **kwargs: object) -> None:
        """Set several attributes at once; if any is refused, none is changed."""
        by_key = self._SPEC.by_key
        attributes: list[AttributeSpec] = []
        for key in kwargs:
            attribute = by_key.get(key)
            if attribute is None:
                raise self._unknown_attribute(key)
            attributes.append(attribute)
        saved = dict(self._attrs)
        try:
            for attribute, value in zip(attributes, kwargs.values(), strict=True):
                self._set_attribute(attribute, value)
        except Exception:
            self._restore_attributes(saved)
            raise

    def _restore_attributes(self, saved: dict[str, object]) -> None:
        id_attribute = self._SPEC.id_attribute
        if id_attribute is not None and self._root is not None:
            current = self._attrs.get(id_attribute.name)
            before = saved.get(id_attribute.name)
            if current != before:
                assert id_attribute.namespace is not None
                if current is not None:
                    self._root._forget_identifier(id_attribute.namespace, current, self)  # pyright: ignore[reportPrivateUsage]
                if isinstance(before, str):
                    self._root._remember_identifier(id_attribute.namespace, before, self)  # pyright: ignore[reportPrivateUsage]
        self._attrs.clear()
        self._attrs.update(saved)

    def _init_attributes(self, kwargs: Mapping[str, object]) -> None:
        """Set the attributes of a new element; the identifier is claimed last, so a
        refused value leaves the model untouched."""
        by_key = self._SPEC.by_key
        attrs = self._attrs
        identifier: AttributeSpec | None = None
        name: object = None
        for key, value in kwargs.items():
            attribute = by_key.get(key)
            if attribute is None:
                raise self._unknown_attribute(key)
            if value is None:
                continue
            try:
                converted = attribute.convert(value)
            except Rejected as rejected:
                raise self._reject(attribute, value, rejected) from None
            kind = attribute.kind
            if kind == "id":
                identifier, name = attribute, converted
                continue
            if kind == "ref" and type(converted) is not str:
                self._check_reference(attribute, converted)
            attrs[attribute.name] = converted
        if identifier is not None:
            claim_first_name(self, identifier, name)
            attrs[identifier.name] = name

    # ------------------------------------------------------------------ children

    def add(self, tag: str, /, **kwargs: object) -> Element:
        """Add a child ``<tag>`` with the given attributes and return it."""
        return self._add_child(tag, None, kwargs)

    def insert(self, tag: str, position: int, /, **kwargs: object) -> Element:
        """Add a child ``<tag>`` at ``position`` among this element's children."""
        return self._add_child(tag, position, kwargs)

    def _child_spec(self, tag: str) -> ChildSpec:
        child_spec = self._SPEC.children.get(tag)
        if child_spec is None:
            if not isinstance(tag, str):  # pyright: ignore[reportUnnecessaryIsInstance]
                raise InvalidTypeError(f"{self.path}: a child tag must be a string, got {tag!r}")
            legal = list(self._SPEC.children)
            raise ChildError(
                f"{self.path}: <{tag}> is not a legal child of <{self._SPEC.tag}>"
                f"{did_you_mean(tag, legal)}; legal children: {', '.join(legal) or '(none)'}"
            )
        return child_spec

    def _add_child(self, tag: str, position: int | None, kwargs: Mapping[str, object]) -> Element:
        child_spec = self._SPEC.children.get(tag)
        if child_spec is None:
            child_spec = self._child_spec(tag)  # raises, with a suggestion
        cls = child_spec.cls or child_class(child_spec)
        if child_spec.single:
            if self._single_child(tag) is not None:
                raise ChildError(
                    f"{self.path}: <{self._SPEC.tag}> already has a <{tag}> (it may appear once)")
            child = cls._blank(self, self._root)
            child._init_attributes(kwargs)
            self._place(child, child_spec, position)
            return child
        return append_child(self, cls, position, kwargs)

    def _mutable_children(self) -> list[Element]:
        children = self._children
        if isinstance(children, tuple):
            children = []
            _set_slot(self, "_children", children)
        return children

    def _place(self, child: Element, child_spec: ChildSpec, position: int | None) -> None:
        children = self._mutable_children()
        if child_spec.single:
            if self._singles is None:
                object.__setattr__(self, "_singles", {})
            assert self._singles is not None
            self._singles[child_spec.tag] = child
            if position is None:
                position = self._grammar_position(child_spec)
        if position is None:
            children.append(child)
        else:
            children.insert(position, child)

    def _grammar_position(self, child_spec: ChildSpec) -> int:
        """Where a once-only child goes: before the first child the grammar lists after it."""
        children_specs = self._SPEC.children
        for i, sibling in enumerate(self._children):
            sibling_spec = children_specs.get(sibling._SPEC.tag)
            if sibling_spec is not None and sibling_spec.index > child_spec.index:
                return i
        return len(self._children)

    def _single_child(self, tag: str) -> Element | None:
        singles = self._singles
        return None if singles is None else singles.get(tag)

    def _single_or_new(self, tag: str) -> Element:
        existing = self._single_child(tag)
        return existing if existing is not None else self._add_child(tag, None, {})

    def get_children(self, tag: str | None = None) -> list[Element]:
        """The children, in document order; only those with ``tag`` if given."""
        if tag is None:
            return list(self._children)
        self._child_spec(tag)
        return [c for c in self._children if c._SPEC.tag == tag]

    def iter_elements(self) -> Iterator[Element]:
        """This element and all its descendants, in document order."""
        stack: list[Element] = [self]
        while stack:
            element = stack.pop()
            yield element
            stack.extend(reversed(element._children))

    def remove(self) -> None:
        """Remove this element (and its subtree) from its parent."""
        parent = self._parent
        if parent is None:
            raise ChildError(f"{self.path}: a model's root (or a removed element) has no parent")
        parent._mutable_children().remove(self)
        if parent._singles is not None and parent._singles.get(self._SPEC.tag) is self:
            del parent._singles[self._SPEC.tag]
        root = self._root
        for element in self.iter_elements():
            if root is not None:
                root._forget_element(element)  # pyright: ignore[reportPrivateUsage]
            object.__setattr__(element, "_root", None)
        object.__setattr__(self, "_parent", None)

    def paste(self, element: E, position: int | None = None) -> E:
        """Add a deep copy of ``element`` (from this model or another) as a child; return it.

        References inside the copied subtree point into the copy; references to elements
        outside it are kept by name, to resolve in this model. Names must be free here.
        """
        child_spec = self._child_spec(element.tag)
        if type(element).__name__ != child_spec.class_name:
            raise ChildError(f"{self.path}: a {type(element).__name__} cannot be a child of "
                             f"<{self._SPEC.tag}> (its <{element.tag}> children are "
                             f"{child_spec.class_name})")
        if child_spec.single and self._single_child(element.tag) is not None:
            raise ChildError(f"{self.path}: <{self._SPEC.tag}> already has a <{element.tag}>")
        memo: dict[int, object] = {}
        clone = element._clone_tree(self, self._root, memo)
        clone._remap_references(memo)
        root = self._root
        for copied in clone.iter_elements():
            attrs = copied._attrs
            for key, value in attrs.items():
                if isinstance(value, Element) and value._root is not root:
                    name = value._attrs.get(value._SPEC.id_attribute.name) if (
                        value._SPEC.id_attribute) else None
                    attrs[key] = name  # kept by name: it must resolve in this model
            id_attribute = copied._SPEC.id_attribute
            name = None if id_attribute is None else attrs.get(id_attribute.name)
            if root is not None and id_attribute is not None and isinstance(name, str):
                assert id_attribute.namespace is not None
                holder = root._lookup_identifier(id_attribute.namespace, name)  # pyright: ignore[reportPrivateUsage]
                if holder is not None:
                    raise DuplicateIdentifierError(
                        f"{self.path}: cannot add a copy of {element.path}: its "
                        f"{id_attribute.namespace} name {name!r} is taken by {holder.path}")
        if root is not None:
            for copied in clone.iter_elements():
                attached = copied._attached
                if attached is not None:
                    from typed_mjcf._compose import scope_name

                    scope = scope_name(attached)
                    if scope in root._scopes:  # pyright: ignore[reportPrivateUsage]
                        raise ChildError(f"{self.path}: the copy holds an attached model named "
                                         f"{scope!r}, and one of that name is attached here")
                    root._scopes[scope] = attached  # pyright: ignore[reportPrivateUsage]
            for copied in clone.iter_elements():
                id_attribute = copied._SPEC.id_attribute
                name = None if id_attribute is None else copied._attrs.get(id_attribute.name)
                if id_attribute is not None and isinstance(name, str):
                    assert id_attribute.namespace is not None
                    root._remember_identifier(id_attribute.namespace, name, copied)  # pyright: ignore[reportPrivateUsage]
        self._place(clone, child_spec, position)
        return clone

    # ------------------------------------------------------------------ composition

    def attach_model(self, model: ModelRoot) -> Element:
        """Attach ``model`` here; return its attachment frame (a ``<body>``).

        The model stays its own object: its names are scoped ``<model name>/...`` in this
        model (``find("joint", "arm/elbow")``) and in the exported XML; ``model.detach()``
        undoes the attachment.
        """
        from typed_mjcf._compose import attach

        return attach(self, model)

    @property
    def attached_model(self) -> ModelRoot | None:
        """On an attachment frame, the model attached there."""
        return self._attached

    # ------------------------------------------------------------------ copies

    def __copy__(self) -> Self:
        return self.__deepcopy__({})

    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """A detached copy of the subtree; references inside it point into the copy."""
        clone = self._clone_tree(None, None, memo)
        clone._remap_references(memo)
        return clone

    def _clone_tree(self, parent: Element | None, root: ModelRoot | None,
                    memo: dict[int, object]) -> Self:
        """A copy of this subtree under ``parent`` (not added to its children); iterative."""
        top: Self | None = None
        stack: list[tuple[Element, Element | None]] = [(self, parent)]
        while stack:
            original, clone_parent = stack.pop()
            clone = type(original)._blank(clone_parent, root)
            memo[id(original)] = clone
            if original._attached is not None:
                attached = _copy.deepcopy(original._attached, memo)
                object.__setattr__(clone, "_attached", attached)
                object.__setattr__(attached, "_frame", clone)
            for key, value in original._attrs.items():
                # arrays are mutable in place: the copy gets its own
                clone._attrs[key] = cast(object, value.copy()) if isinstance(value, np.ndarray) else value
            if top is None:
                top = cast(Self, clone)
            elif clone_parent is not None:
                clone_parent._mutable_children().append(clone)
                if clone_parent._SPEC.children[clone._SPEC.tag].single:
                    if clone_parent._singles is None:
                        object.__setattr__(clone_parent, "_singles", {})
                    assert clone_parent._singles is not None
                    clone_parent._singles[clone._SPEC.tag] = clone
            stack.extend((child, clone) for child in reversed(original._children))
        assert top is not None
        return top

    def _remap_references(self, memo: Mapping[int, object]) -> None:
        """Point references to elements that were copied at their copies."""
        for element in self.iter_elements():
            attrs = element._attrs
            for key, value in attrs.items():
                if isinstance(value, Element):
                    attrs[key] = memo.get(id(value), value)

    # ------------------------------------------------------------------ export

    def to_xml(self, *, precision: int | None = None,
               zero_threshold: float = 0.0) -> etree._Element:  # pyright: ignore[reportPrivateUsage]
        """This element as an lxml element."""
        from typed_mjcf._export import to_xml

        return to_xml(self, precision=precision, zero_threshold=zero_threshold)

    def to_xml_string(self, precision: int | None = None, zero_threshold: float = 0.0,
                      pretty_print: bool = True) -> str:
        """This element as MJCF text.

        Floats are written in the shortest form that reads back exactly unless ``precision``
        (significant digits) is given; values smaller in magnitude than ``zero_threshold``
        are written as 0.
        """
        from typed_mjcf._export import to_xml_string

        return to_xml_string(self, precision=precision, zero_threshold=zero_threshold,
                             pretty_print=pretty_print)


# ---------------------------------------------------------------------------- descriptors


class SingleChild:
    """A once-only child, created on first access."""

    __slots__ = ("child",)

    def __init__(self, child: ChildSpec) -> None:
        self.child = child

    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> SingleChild: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> Element: ...
    def __get__(self, obj: Element | None, owner: type[object] | None = None) -> object:
        if obj is None:
            return self
        return obj._single_or_new(self.child.tag)  # pyright: ignore[reportPrivateUsage]

    def __set__(self, obj: Element, value: object) -> None:
        raise ChildError(f"{obj.path}: {self.child.py_name} is a child element; "
                         f"set its attributes instead")

    def __delete__(self, obj: Element) -> None:
        existing = obj._single_child(self.child.tag)  # pyright: ignore[reportPrivateUsage]
        if existing is not None:
            existing.remove()


class ChildList:
    """The children with one tag, as a new list in document order."""

    __slots__ = ("child",)

    def __init__(self, child: ChildSpec) -> None:
        self.child = child

    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> ChildList: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> list[Element]: ...
    def __get__(self, obj: Element | None, owner: type[object] | None = None) -> object:
        if obj is None:
            return self
        tag = self.child.tag
        return [c for c in obj._children if c._SPEC.tag == tag]  # pyright: ignore[reportPrivateUsage]

    def __set__(self, obj: Element, value: object) -> None:
        raise ChildError(f"{obj.path}: {self.child.py_name} is the list of <{self.child.tag}> "
                         f"children; use add_{self.child.tag}() or remove()")


def child_class(child_spec: ChildSpec) -> type[Element]:
    """The generated class of a child (resolved on first use: classes refer to classes
    defined after them)."""
    cls = child_spec.cls = _REGISTRY[child_spec.class_name]
    return cls


def claim_first_name(element: Element, attribute: AttributeSpec, name: object) -> None:
    """``element._claim_identifier`` for an element that has no name yet: the common case
    (a new name in a namespace that has names) without a method call or old-name check."""
    root, namespace = element._root, attribute.namespace  # pyright: ignore[reportPrivateUsage]
    table = None if root is None or namespace is None else root._identifiers.get(namespace)  # pyright: ignore[reportPrivateUsage]
    if table is not None and isinstance(name, str) and name not in table:
        table[name] = element
    else:
        element._claim_identifier(attribute, name)  # pyright: ignore[reportPrivateUsage]  # creates the table, or refuses


def _slot_writer(name: str) -> Callable[[Element, object], None]:
    """The setter of one of Element's slots: writes it without Element.__setattr__, and
    faster than object.__setattr__ (no lookup of the slot by name)."""
    slot = cast("_SlotDescriptor", Element.__dict__[name])
    return slot.__set__


class _SlotDescriptor(Protocol):
    def __set__(self, obj: Element, value: object, /) -> None: ...


# Every element's slots, written once when it is created (the hot path of every add).
_init_attrs = _slot_writer("_attrs")
_init_children = _slot_writer("_children")
_init_parent = _slot_writer("_parent")
_init_root = _slot_writer("_root")
_init_singles = _slot_writer("_singles")
_init_attached = _slot_writer("_attached")


def append_child(parent: Element, cls: type[E], position: int | None,
                  kwargs: Mapping[str, object]) -> E:
    """A new repeated child of ``parent`` (the hot path of every add, ``_blank`` inlined)."""
    child = _new_object(cls)
    _init_attrs(child, {})
    _init_children(child, _NO_CHILDREN)
    _init_parent(child, parent)
    _init_root(child, parent._root)  # pyright: ignore[reportPrivateUsage]
    _init_singles(child, None)
    _init_attached(child, None)
    if kwargs:
        child._init_attributes(kwargs)  # pyright: ignore[reportPrivateUsage]
    children = parent._children  # pyright: ignore[reportPrivateUsage]
    if isinstance(children, tuple):
        first: list[Element] = []
        _init_children(parent, first)
        children = first
    if position is None:
        children.append(child)
    else:
        children.insert(position, child)
    return child


def _adder(child_spec: ChildSpec) -> Callable[..., Element]:
    tag = child_spec.tag
    if child_spec.single:
        def add_child(self: Element, **kwargs: object) -> Element:
            return self._add_child(tag, None, kwargs)  # pyright: ignore[reportPrivateUsage]
    else:
        def add_child(self: Element, **kwargs: object) -> Element:
            return append_child(self, child_spec.cls or child_class(child_spec), None, kwargs)

    add_child.__name__ = add_child.__qualname__ = f"add_{tag}"
    add_child.__doc__ = f"Add a <{tag}> child with the given attributes and return it."
    return add_child


def deep_copy(element: E) -> E:
    """A detached deep copy (same as ``copy.deepcopy``)."""
    return _copy.deepcopy(element)
