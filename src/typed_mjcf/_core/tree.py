"""The element tree: elements, their attributes and children, names and links.

This is the core every feature builds on. An element stores its attribute values by XML
name (each as its codec stores it, or the element a reference links to), its children in
document order, its parent, the model whose tree it is in (``root``) and the name scope its
name lives in (its model's, or for what is added to an attachment frame, the attached
model's). Every attribute is set by one path, :meth:`Element._assign` (Python values) and
:func:`assign_text` (text read from a file), and every element is made by :func:`_create`.

References are links: a reference attribute holds the element it names as soon as the name
resolves (at assignment, or when an element of that name appears later), so renaming the
target, renaming or attaching its model, or copying keeps the reference right; the text is
derived when the model is written. A reference to a removed element reads as ``None`` and is
reported by ``validate()``.

Features (parsing, export, composition, validation, ...) use the functions at the end of this
module (the internal API), not the elements' private slots.
"""

# The element's slots are private to the tree; this module's functions and descriptors are
# the tree, so they read them (pyright would otherwise allow only Element's own methods).
# pyright: reportPrivateUsage=false

from __future__ import annotations

import copy
import inspect
import os
from array import array as _array_of
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import (
    ClassVar,
    Final,
    Generic,
    NoReturn,
    Protocol,
    Self,
    SupportsIndex,
    TypeAlias,
    TypeVar,
    cast,
    overload,
)

import numpy as np

from typed_mjcf._build import mypyc_attr
from typed_mjcf._core.access import ANYWHERE, Confinement
from typed_mjcf._core.behaviour import FLAGS as _FLAGS
from typed_mjcf._core.codecs import ArrayCodec, Rejected
from typed_mjcf._core.debuginfo import RECORDER as _RECORDER
from typed_mjcf._core.doclines import DCLASS_DOC, adder_listing
from typed_mjcf._core.errors import (
    ChildError,
    DuplicateIdentifierError,
    IllegalChildError,
    InvalidReferenceError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    UnknownAttributeError,
    did_you_mean,
)
from typed_mjcf._core.grammar import AttributeSpec, ChildSpec, ElementSpec, RowClass
from typed_mjcf._core.language import GrammarFacts
from typed_mjcf._core.names import SEPARATOR, UNNAMED_MODEL, NameScope, NameTaken
from typed_mjcf._core.sourcelines import SourceText, file_start_line

E = TypeVar("E", bound="Element")
E_co = TypeVar("E_co", bound="Element", covariant=True)

_Slice: TypeAlias = "slice[int | None, int | None, int | None]"  # not subscriptable at run time

_CLASSES: dict[str, type[Element]] = {}
_FACTS: list[GrammarFacts] = []
DCLASS: Final = "dclass"  # dm_control's Python name of the class attribute (also ours)
_RESERVED_NAMES: set[str] = set()  # names a body may not take (the world body's)
_NO_CHILDREN: tuple[()] = ()
# What a refused value may say of itself (a stand-in for values, such as a distribution of
# typed_mjcf.variation, says where it goes): each gives a note or None; asked on refusal only.
_REJECTION_NOTES: list[Callable[[object], str | None]] = []
# object.__setattr__, called as a function (mypyc's own translation of object.__setattr__
# does not handle the slots of native classes)
_write_attribute: Final[Callable[[object, str, object], None]] = object.__setattr__
# object.__new__ of a _Blank (see _create)
_new_blank = cast("Callable[[type[_Blank]], _Blank]", object.__new__)


def element_class(class_name: str) -> type[Element]:
    """The generated class of that name."""
    return _CLASSES[class_name]


def element_classes() -> Mapping[str, type[Element]]:
    """Every generated class, by name."""
    return _CLASSES


def finish_grammar(facts: GrammarFacts,
                   adjust: Callable[[Mapping[str, type[Element]]], None] | None = None) -> None:
    """Called by the generated tables once every class exists: the language-wide facts,
    which rows hold bodies, and the signature and docstring of every ``add_<tag>()``.
    ``adjust`` is what a layer above changes in the tables first (the installed MuJoCo's
    release: what it lacks or types otherwise, ``typed_mjcf._releases``)."""
    _FACTS[:] = [facts]
    for cls in _CLASSES.values():  # dm_control's spelling of the class attribute
        dclass = cls.spec.by_name.get(facts.dclass)
        if dclass is not None:
            cls.spec.by_key.setdefault(DCLASS, dclass)
            setattr(cls, DCLASS, Attribute(dclass))
    _RESERVED_NAMES.clear()
    _RESERVED_NAMES.add(facts.world_body)
    for cls in _CLASSES.values():
        cls.spec.holds_bodies = facts.body in cls.spec.children
        for attribute in cls.spec.attributes.values():
            namespace = facts.name_lists.get(f"{cls.spec.tag}@{attribute.name}")
            if namespace is not None:
                attribute.mark_name_list(namespace)
        for child in cls.spec.children.values():
            child.cls = _CLASSES[child.class_name]
            child.holder = cls.spec
    if adjust is not None:
        adjust(_CLASSES)
    document_adders()


# Why a name or a value is refused when the reason lies outside the core's tables (the
# release in use lacks it): the layer that adjusts the tables registers how to say so.
NameNote = Callable[["ElementSpec", str], "str | None"]
ValueNote = Callable[["ElementSpec", "AttributeSpec", object], "str | None"]
_NOTES: list[tuple[NameNote, ValueNote]] = []


def explain_refusals(name_note: NameNote, value_note: ValueNote) -> None:
    """Register what says why a name (an attribute, a child, ``add_<tag>``) or a value is
    refused, beyond the row's own rules: "needs MuJoCo >= 4.0.0; installed 3.17.0"."""
    _NOTES[:] = [(name_note, value_note)]


def name_note(spec: ElementSpec, name: str) -> str | None:
    """Why ``name`` is not on ``spec``'s row, when a layer above knows (else None)."""
    return _NOTES[0][0](spec, name) if _NOTES else None


def value_note(spec: ElementSpec, attribute: AttributeSpec, value: object) -> str | None:
    """Why ``value`` is refused for ``attribute``, when a layer above knows (else None)."""
    return _NOTES[0][1](spec, attribute, value) if _NOTES else None


def grammar_facts() -> GrammarFacts:
    """The language facts of the loaded grammar (schema/facts.toml's ``[language]``)."""
    return _FACTS[0]


def _public_name(attribute: AttributeSpec) -> str:
    """An attribute's key in ``get_attributes()``: its Python name, and dm_control's
    ``dclass`` for ``class``."""
    return DCLASS if attribute.name == grammar_facts().dclass else attribute.py_name


def _short(value: object, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def short_repr(value: object) -> str:
    """``repr(value)``, shortened as the messages of refused values shorten it."""
    return _short(value)


# The element classes are native classes when compiled (mypyc): their slots are C struct
# fields, so the compiled tree reads and writes them directly, past the Python-level
# lookups (and _base.Element's __getattr__ hook) an ordinary class costs on every access.
# Generated classes and users' subclasses are interpreted subclasses of them; compiled code
# checks an argument's class with isinstance (not `is`). What differs between the builds:
# a native class keeps no __slots__ (the fields are declared by the annotations) and no
# weak references of its own (_base.Element adds the slot: WEAKREF_SLOTS), and a native
# instance cannot change its class (_create makes elements another way).
_LAYOUT_SLOTS: Final = ("__weakref__", "_attached", "_children", "_parent", "_root", "_scope",
                        "_singles", "_values")
_MODEL_SLOTS: Final = ("_access", "_base_dir", "_files", "_frame", "_sources")


@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class _Layout:
    """What every element stores (see :class:`Element`), in a class of its own so that
    elements can be made as a :class:`_Blank` and given their class once filled in."""

    __slots__ = _LAYOUT_SLOTS

    _values: dict[str, object]
    _children: list[Element] | tuple[()]  # () until the first child: fewer objects for the GC
    _parent: Element | None
    _root: ModelBase | None  # the model whose tree holds this element; None once removed
    _scope: NameScope  # where this element's name lives and its references resolve
    _singles: dict[str, Element] | None
    _attached: ModelBase | None  # on attachment frames: the model attached there


@mypyc_attr(serializable=True)
class _Blank(_Layout):
    """An element being made (pure Python build): the same layout as every element class,
    without :class:`Element`'s ``__setattr__``, so its slots are written at full speed."""

    __slots__ = ()


# Whether the element classes are native (the compiled build): mypyc keeps no __slots__.
NATIVE_LAYOUT: Final = "__slots__" not in vars(_Layout)
# The slot _base.Element adds: weak references, which a native class does not support itself.
WEAKREF_SLOTS: Final[tuple[str, ...]] = ("__weakref__",) if NATIVE_LAYOUT else ()


class SiblingNumbers:
    """Each child's place among its parent's children of its tag, counted once per parent:
    the paths of many unnamed siblings in linear time (a path alone counts its siblings)."""

    def __init__(self) -> None:
        self._tables: dict[int, dict[int, int]] = {}

    def number(self, parent: Element, child: Element) -> int | None:
        table = self._tables.get(id(parent))
        if table is None:
            table = self._tables[id(parent)] = {}
            counts: dict[str, int] = {}
            for sibling in children(parent):
                tag = sibling.spec.tag
                table[id(sibling)] = counts.get(tag, 0)
                counts[tag] = table[id(sibling)] + 1
        return table.get(id(child))


def paths(elements: Iterable[Element]) -> list[str]:
    """The paths of ``elements`` (as :attr:`Element.path`), in time linear in their number."""
    numbers = SiblingNumbers()
    return [element._path(numbers) for element in elements]


@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class Element(_Layout):
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""

    __slots__ = ()
    spec: ClassVar[ElementSpec]

    # ------------------------------------------------------------------ class set-up

    def __init_subclass__(cls, **kwargs: object) -> None:
        super().__init_subclass__(**kwargs)
        spec: ElementSpec | None = vars(cls).get("spec")
        if spec is None:
            return
        _CLASSES[cls.__name__] = cls
        for attribute in spec.attributes.values():
            setattr(cls, attribute.py_name, Attribute(attribute))
        for child in spec.children.values():
            setattr(cls, child.py_name, SingleChild(child) if child.single else ChildList(child))
            setattr(cls, "add_" + child.tag, _adder(child))

    def __init__(self) -> None:
        raise TypeError(
            f"{type(self).__name__} elements are created by their parent, "
            f"e.g. parent.add_{self.spec.tag}(...) or parent.add({self.spec.tag!r}, ...)"
        )

    # ------------------------------------------------------------------ identity

    @property
    def tag(self) -> str:
        """The XML tag."""
        return self.spec.tag

    @property
    def parent(self) -> Element | None:
        """The parent element; ``None`` for a model's root or a removed element."""
        return self._parent

    @property
    def is_removed(self) -> bool:
        """Whether this element was removed from its model."""
        return self._root is None

    @property
    def path(self) -> str:
        """Where the element is in its model, e.g. ``worldbody/body[upper_arm]/geom[0]``."""
        return self._path(None)

    def _path(self, numbers: SiblingNumbers | None) -> str:
        steps: list[str] = []
        element: Element = self
        while element._parent is not None:
            steps.append(element._step(numbers))
            element = element._parent
        if not steps:
            return "<root>" if isinstance(element, ModelBase) and element is self._root else (
                f"<{self.spec.tag}>")
        scope = element._scope.prefix() if isinstance(element, ModelBase) else ""
        return scope + "/".join(reversed(steps))

    def _step(self, numbers: SiblingNumbers | None = None) -> str:
        parent = self._parent
        assert parent is not None
        tag = self.spec.tag
        child_spec = parent.spec.children.get(tag)
        if child_spec is not None and child_spec.single:
            return tag
        id_attribute = self.spec.id_attribute
        if id_attribute is not None:
            name = self._values.get(id_attribute.name)
            if isinstance(name, str):
                return f"{tag}[{name}]"
        if numbers is not None:
            number = numbers.number(parent, self)
            return f"{tag}[new]" if number is None else f"{tag}[{number}]"
        index = 0
        for sibling in parent._children:
            if sibling is self:
                return f"{tag}[{index}]"
            if sibling.spec.tag == tag:
                index += 1
        return f"{tag}[new]"

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.path}>"

    def __dir__(self) -> list[str]:
        """Also the MJCF spellings ``getattr`` takes where they differ (``global``)."""
        spec = self.spec
        spelled = [name for name in (*spec.children, *spec.by_name)
                   if _python_name(spec, name) is not None]
        return sorted({*super().__dir__(), *spelled})

    # ------------------------------------------------------------------ attributes

    # __getattr__, __setattr__ and __delattr__: on typed_mjcf._base.Element (interpreted,
    # since a compiled module cannot hide them from checkers behind `if not TYPE_CHECKING`)

    def _unknown_attribute(self, name: str, action: str | None = None) -> UnknownAttributeError:
        """``name`` is none of the row's attributes: the message says which are (reading,
        ``action`` says what was done, e.g. "can't set attribute")."""
        spec = self.spec
        missing = name_note(spec, name)
        if missing is not None:
            return UnknownAttributeError(f"{self.path}: {name!r} of <{spec.tag}> {missing}")
        known = [a.py_name for a in spec.attributes.values()]
        hint = did_you_mean(name, known + [c.py_name for c in spec.children.values()])
        what = f"{action} {name!r}" if action else (
            f"{type(self).__name__!r} object has no attribute {name!r}")
        return UnknownAttributeError(
            f"{self.path}: {what}{hint}: {name!r} is not a valid attribute of <{spec.tag}>; "
            f"its attributes are: {', '.join(known) or '(none)'}"
        )

    def _reject(self, attribute: AttributeSpec, value: object, rejected: Rejected) -> Exception:
        missing = value_note(self.spec, attribute, value)  # another release takes it?
        if missing is not None:
            return rejected.error(
                f"{self.path}: {_short(value)} for {attribute.py_name!r} of <{self.spec.tag}> "
                f"{missing}; expected {rejected.expected}")
        message = (f"{self.path}: invalid {attribute.py_name}={_short(value)} on "
                   f"<{self.spec.tag}>: expected {rejected.expected}")
        notes = [n for n in (note(value) for note in _REJECTION_NOTES) if n is not None]
        if notes:  # a stand-in for values, not a value: a type the attribute cannot take
            return InvalidTypeError("; ".join([message, *notes]))
        return rejected.error(message)

    def _assign(self, attribute: AttributeSpec, value: object) -> None:
        """Set one attribute from a Python value (``None`` or ``""`` unsets it)."""
        if _RECORDER[0] is not None:
            _RECORDER[0](self, (attribute.name,), False)
        if value is None or (type(value) is str and not value):
            self._unset(attribute)
            return
        _store(self, attribute, self._convert(attribute, value), True)

    def _convert(self, attribute: AttributeSpec, value: object) -> object:
        if attribute.is_reference and isinstance(value, Element):
            return self._link(attribute, value)
        try:
            stored = attribute.codec.accept(value)
        except Rejected as rejected:
            raise self._reject(attribute, value, rejected) from None
        if attribute.is_reference and isinstance(stored, str) and not _FLAGS.references_stay_names:
            return _resolve(self, attribute, stored)  # (else a name stays a name)
        return stored

    def _unset(self, attribute: AttributeSpec) -> None:
        old = self._values.pop(attribute.name, None)
        if old is None:
            return
        if attribute.kind == "id":
            self._scope.release(cast(str, attribute.namespace), cast(str, old), self)
        elif attribute.scope:
            try:
                _rename_model(self, None)
            except Exception:
                self._values[attribute.name] = old
                raise

    def _link(self, attribute: AttributeSpec, target: Element) -> Element:
        """Check that ``target`` may be what ``attribute`` refers to."""
        spec = target.spec
        namespace = spec.namespace
        if namespace != attribute.namespace and namespace not in (
                allowed := _reference_namespaces(self, attribute)):
            raise InvalidReferenceError(
                f"{self.path}: invalid {attribute.py_name}={target!r} on <{self.spec.tag}>: "
                f"expected a name or an element of namespace "
                f"{' or '.join(repr(n) for n in sorted(allowed))}, got a <{target.spec.tag}> "
                f"(namespace {namespace!r})")
        id_attribute = spec.id_attribute
        if id_attribute is None or id_attribute.name not in target._values:
            target._scope.unnamed_targets.append(target)  # an export will name it
        return target

    def get_attributes(self) -> dict[str, object]:
        """The attributes that are set, by Python name, in grammar order."""
        spec = self.spec
        by_name = spec.by_name
        return {_public_name(by_name[name]): _read(self, by_name[name])
                for name in sorted(self._values, key=spec.order.__getitem__)}

    def set_attributes(self, **kwargs: object) -> None:
        """Set several attributes at once; if any is refused, none is changed."""
        attributes = [self._attribute(key) for key in kwargs]
        snapshot = _Snapshot(self)
        try:
            for attribute, value in zip(attributes, kwargs.values(), strict=True):
                self._assign(attribute, value)
        except Exception:
            snapshot.restore()
            raise

    def _attribute(self, key: str) -> AttributeSpec:
        attribute = self.spec.by_key.get(key)
        if attribute is None:
            raise self._unknown_attribute(key)
        return attribute

    def _init_attributes(self, kwargs: Mapping[str, object]) -> None:
        """Set the attributes of a new element (not yet in its parent), each stored as
        :func:`_store` says: the values first, then, once every value is converted (so that
        a refused one leaves the model untouched), the name (which may be taken) and the
        references (those whose namespace another attribute names last)."""
        by_key = self.spec.by_key
        values = self._values
        store = _store
        identifier: AttributeSpec | None = None
        name: object = None
        references: list[tuple[AttributeSpec, object]] | None = None
        for key, value in kwargs.items():
            attribute = by_key.get(key)
            if attribute is None:
                raise self._unknown_attribute(key)
            if value is None or (type(value) is str and not value):
                continue
            if attribute.direct:
                try:
                    stored = attribute.codec.accept(value)
                except Rejected as rejected:
                    raise self._reject(attribute, value, rejected) from None
                if attribute.bare:  # storing it is this write (_store's first case)
                    values[attribute.name] = stored
                else:
                    store(self, attribute, stored, True)
            elif attribute.kind == "id":
                identifier, name = attribute, value
            else:  # converted once the values naming their namespace are stored
                if references is None:
                    references = []
                references.append((attribute, value))
        if identifier is not None:
            name = self._convert(identifier, name)
        if references is not None:
            if len(references) > 1:  # those whose namespace another attribute names last
                references.sort(key=_namespace_given)
            for i, (attribute, value) in enumerate(references):
                references[i] = attribute, self._convert(attribute, value)
        if identifier is not None:
            _store_name(self, identifier, name)
        if references is not None:
            for attribute, stored in references:
                store(self, attribute, stored, True)
        if _RECORDER[0] is not None:
            _RECORDER[0](self, tuple(by_key[key].name for key in kwargs), True)
        if _FLAGS.named_after_files:
            COMPAT.name_after_file(self)  # (when not named)

    # ------------------------------------------------------------------ children

    def add(self, tag: str, /, **kwargs: object) -> Element:
        """Add a child ``<tag>`` with the given attributes and return it."""
        # What runs is typed_mjcf._base.Element.add (interpreted): it also takes dm_control's
        # add(element_name="geom", ...), which checkers should not offer.
        return self._add_child(self._new_child_spec(tag_given(self, tag, kwargs)), None, kwargs)

    def insert(self, tag: str, /, position: int, **kwargs: object) -> Element:
        """Add a child ``<tag>`` at ``position`` among this element's children."""
        return insert_child(self, tag, position, kwargs)  # (run through _base.Element.insert)

    def _new_child_spec(self, tag: str) -> ChildSpec:
        """The child spec ``add(tag)`` adds; with ``eager_children`` a once-only child that
        is not on demand exists with its parent there, so adding another is refused."""
        child_spec = self._child_spec(tag)
        if _FLAGS.eager_children and child_spec.single and not child_spec.on_demand:
            getattr(self, child_spec.py_name)
        return child_spec

    def _child_spec(self, tag: str) -> ChildSpec:
        child_spec = self.spec.children.get(tag)
        if child_spec is None:
            if not isinstance(tag, str):  # pyright: ignore[reportUnnecessaryIsInstance]
                raise InvalidTypeError(f"{self.path}: a child tag must be a string, got {tag!r}")
            legal = list(self.spec.children)
            missing = name_note(self.spec, tag)
            if missing is not None:
                raise IllegalChildError(f"{self.path}: <{tag}> as a child of "
                                        f"<{self.spec.tag}> {missing}")
            raise IllegalChildError(
                f"{self.path}: <{tag}> is not a valid child of <{self.spec.tag}>"
                f"{did_you_mean(tag, legal)}; legal children: {', '.join(legal) or '(none)'}"
            )
        return child_spec

    def _add_child(self, child_spec: ChildSpec, position: int | None,
                   kwargs: Mapping[str, object]) -> Element:
        if child_spec.single and self._single(child_spec.tag) is not None:
            raise ChildError(f"{self.path}: a <{child_spec.tag}> child already exists "
                             f"(<{self.spec.tag}> has at most one)")
        if self._attached is not None:
            _check_frame_child(self, child_spec)
        child = _create(child_spec.cls, self)
        if kwargs:
            child._init_attributes(kwargs)
        if position is None and not child_spec.single:
            _append(self, child)
        else:
            _place(self, child, child_spec, position)
        return child

    def _single(self, tag: str) -> Element | None:
        singles = self._singles
        return None if singles is None else singles.get(tag)

    def iter_elements(self) -> Iterator[Element]:
        """This element and all its descendants, in document order (attached models are
        not included: see ``find_all``)."""
        stack: list[Element] = [self]
        while stack:
            element = stack.pop()
            yield element
            stack.extend(reversed(element._children))

    def remove(self) -> None:
        """Remove this element (and its subtree) from its parent; references to the
        removed elements read as ``None`` from now on."""
        parent = self._parent
        if parent is None:
            raise ChildError(f"{self.path}: a model's root (or a removed element) has no parent")
        if self._root is None:
            raise ChildError(f"{self.path}: the element is already removed")
        _unlink_child(parent, self)
        for element in self.iter_elements():
            _forget(element)
            if element._attached is not None:
                _detach_model(element._attached)
            element._root = None
        self._parent = None

    # ------------------------------------------------------------------ copies

    def __reduce_ex__(self, protocol: SupportsIndex) -> tuple[object, ...]:
        """Pickled without recursion, however deep the tree: an element's state leaves out
        its parent and children, and the top of its tree (the model, or a removed subtree)
        lists every element below it, with its parent, in document order."""
        names = _PICKLED_MODEL if isinstance(self, ModelBase) else _PICKLED
        state = {name: object.__getattribute__(self, name) for name in names}
        if self._parent is None:
            state[_TREE] = [(element, element._parent) for element in self.iter_elements()
                            if element is not self]
        elif self._root is None:  # in a removed subtree: its top holds the tree
            top = self._parent
            while top._parent is not None:
                top = top._parent
            state[_TOP] = top
        return _unpickled, (type(self),), state

    def __setstate__(self, state: dict[str, object]) -> None:
        tree = cast("list[tuple[Element, Element]]", state.pop(_TREE, []))
        state.pop(_TOP, None)
        for name, value in state.items():
            _write_attribute(self, name, value)
        for element, parent in tree:
            if not parent._children:
                _set_children(parent, [])
            cast(list[Element], parent._children).append(element)
            _set_parent(element, parent)

    def __copy__(self) -> Self:
        return self.__deepcopy__({})

    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """A detached copy of the subtree; references inside it point into the copy."""
        clone = _clone_tree(self, None, None, self._scope, memo)
        _remap_links(clone, memo)
        return clone

    def paste(self, element: E, position: int | None = None) -> E:
        """Add a deep copy of ``element`` (from this model or another) as a child; return it.

        References inside the copied subtree point into the copy; references to elements
        outside it are kept by name, to resolve in this model. Names must be free here.
        """
        child_spec = self._child_spec(element.spec.tag)
        if type(element).__name__ != child_spec.class_name:
            raise IllegalChildError(
                f"{self.path}: a {type(element).__name__} cannot be a child of "
                f"<{self.spec.tag}> (its <{element.spec.tag}> children are "
                f"{child_spec.class_name})")
        if child_spec.single and self._single(element.spec.tag) is not None:
            raise ChildError(f"{self.path}: a <{element.spec.tag}> child already exists")
        memo: dict[int, object] = {}
        clone = _clone_tree(element, self, self._root, _child_scope(self), memo)
        _remap_links(clone, memo)
        _adopt(self, clone, element)
        _place(self, clone, child_spec, position)
        return clone

    # ------------------------------------------------------------------ comparison

    def is_same_as(self, other: object) -> bool:
        """Whether ``other`` is an element of the same kind with the same attributes and,
        recursively, the same children: each kind of child in the same order (every child in
        the same order in a tendon's path), dm_control's ``is_same_as`` (models compare by
        their contents, whatever their names)."""
        if not isinstance(other, Element) or other.spec is not self.spec:
            return False
        pairs: list[tuple[Element, Element]] = [(self, other)]
        while pairs:
            a, b = pairs.pop()
            if a.spec is not b.spec:
                return False
            if not (isinstance(a, ModelBase) or _same_values(a, b)):  # a root's name differs
                return False
            ordered = a.spec.tag in grammar_facts().ordered_children
            if ordered and [c.spec.tag for c in a._children] != [c.spec.tag for c in b._children]:
                return False
            groups_a = _children_by_tag(a)
            groups_b = _children_by_tag(b)
            if groups_a.keys() != groups_b.keys():
                return False
            for tag, children in groups_a.items():
                others = groups_b[tag]
                if len(children) != len(others):
                    return False
                pairs += zip(children, others, strict=True)
        return True


# ---------------------------------------------------------------------------- the model root


_TREE: Final = "tree"  # in a pickled top element's state: (element, parent) below it
_TOP: Final = "top"  # in a pickled removed element's state: the top of its subtree
# what a pickled element's state holds: every slot but the tree's links
_PICKLED: Final = tuple(sorted(set(_LAYOUT_SLOTS) - {"__weakref__", "_children", "_parent"}))


def _unpickled(cls: type[Element]) -> Element:
    """A blank element of ``cls``, for pickle to fill in (its links come from the top)."""
    element = cls.__new__(cls)
    _set_children(element, ())
    _set_parent(element, None)
    return element


@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class ModelBase(Element):
    """The root of a model: its name scope, the folder its files are relative to, where it
    is attached, the file contents it was given in memory, and where a parsed model's
    elements were read."""

    __slots__ = _MODEL_SLOTS

    _access: Confinement  # the files it may read (a model built in Python: any)
    _base_dir: str | None
    _frame: Element | None  # the attachment frame, in the model this one is attached to
    _files: dict[str, bytes]  # file contents given with the model (by path as written)
    _sources: SourceMap | None  # filled by the parser; None for models built in Python

    # (object: a compiled signature would refuse RootElement(model=3) with a bare TypeError
    # before the attribute's own check; elements.pyi gives checkers RootElement's signature)
    def __init__(self, model: object = None, *, model_dir: object = None,
                 assets: object = None, **kwargs: object) -> None:
        _init_model(self)
        if _RECORDER[0] is not None:
            _RECORDER[0](self, None, True)
        if model_dir is not None:
            self._base_dir = os.fspath(cast(str, model_dir))
        if assets is not None:
            self._files.update(cast("Mapping[str, bytes]", assets))
        scope_attribute = self.spec.scope_attribute
        if model is None and _FLAGS.unnamed_model_name and scope_attribute is not None and (
                not kwargs.get(scope_attribute.py_name)):
            model = UNNAMED_MODEL  # (the name an attached model without one is called)
        if model is not None and scope_attribute is not None:
            kwargs = {scope_attribute.py_name: model, **kwargs}
        self._init_attributes(kwargs)

    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """An independent copy, with copies of the models attached to it."""
        clone = cast(Self, _copy_model(self, memo))
        _remap_links(clone, memo)
        return clone


_PICKLED_MODEL: Final = _PICKLED + _MODEL_SLOTS


def _init_model(model: ModelBase) -> None:
    model._values = {}
    model._children = []
    model._parent = None
    model._root = model
    model._scope = NameScope(model)
    model._singles = None
    model._attached = None
    model._base_dir = None
    model._access = ANYWHERE
    model._frame = None
    model._files = {}
    model._sources = None


@mypyc_attr(serializable=True)  # pickled and copied with its model (without __init__)
class SourceMap:
    """Where a parsed model's elements were read (for messages that point into the files).

    ``lines`` maps each element to its file (``None`` for text given in memory) and the
    line libxml2 gave it (where its start tag ends), in the order the parser read them;
    ``includes`` maps each included file to the file that included it and the element its
    contents were read into.

    The map holds the elements in a list and their lines in an array beside it, and an
    element's file only if it is not the main one: no dict entry, int or (file, line) pair
    per element (about 50 bytes each); the index from element to place is made when first
    asked for (messages), not while reading.
    """

    __slots__ = ("_places", "files", "includes", "line_numbers", "main", "order", "texts")

    def __init__(self, main: str | None = None) -> None:
        self.main = main  # the file (or text) the model was read from
        self.order: list[Element] = []  # every element, in reading order
        self.line_numbers = _array_of("q")  # the line of each (0: none given)
        self.files: dict[Element, str | None] = {}  # the elements read from another file
        self.includes: dict[str, tuple[str | None, Element]] = {}
        self.texts: dict[str, SourceText | None] = {}  # files read again for messages
        self._places: dict[Element, int] = {}  # element -> place in order, made on demand

    def add(self, element: Element, source: str | None, line: int | None) -> None:
        """Record that ``element`` was read at ``source:line``."""
        self.order.append(element)
        self.line_numbers.append(line or 0)
        if source is not self.main:
            self.files[element] = source

    def get(self, element: Element) -> tuple[str | None, int | None] | None:
        """Where ``element`` was read, if it was."""
        index, order = self._places, self.order
        for number in range(len(index), len(order)):  # the elements read since it was asked
            index[order[number]] = number
        place = index.get(element)
        if place is None:
            return None
        return self.files.get(element, self.main), self.line_numbers[place] or None

    @property
    def lines(self) -> Mapping[Element, tuple[str | None, int | None]]:
        """Every element read, in reading order, with its file and line."""
        return _Lines(self)


class _Lines(Mapping[Element, tuple[str | None, int | None]]):
    """A :class:`SourceMap`'s elements with their file and line, as a read-only mapping."""

    __slots__ = ("_sources",)

    def __init__(self, sources: SourceMap) -> None:
        self._sources = sources

    def __getitem__(self, element: Element) -> tuple[str | None, int | None]:
        found = self._sources.get(element)
        if found is None:
            raise KeyError(element)
        return found

    def __iter__(self) -> Iterator[Element]:
        return iter(self._sources.order)

    def __len__(self) -> int:
        return len(self._sources.order)


def new_model(cls: type[ModelBase]) -> ModelBase:
    """An empty model of the generated root class (no attributes set)."""
    model = cls.__new__(cls)  # (not object.__new__: a native class makes its own)
    _init_model(model)
    return model


# ---------------------------------------------------------------------------- descriptors


# data descriptors (__set__, __delete__): a native class would lose them (mypyc gives it
# __get__ only), and every assignment would then replace the descriptor
@mypyc_attr(native_class=False)
class Attribute:
    """Reads and writes one attribute on elements of a generated class."""

    __slots__ = ("array", "codec", "lazy", "name", "reference", "spec")

    def __init__(self, spec: AttributeSpec) -> None:
        self.spec = spec
        self.name = spec.name
        self.codec = spec.codec
        self.lazy = spec.codec.lazy
        self.reference = spec.is_reference
        self.array = isinstance(spec.codec, ArrayCodec)

    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> Attribute: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> object: ...
    def __get__(self, obj: Element | None, owner: type[object] | None = None) -> object:
        if obj is None:
            return self
        stored = obj._values.get(self.name)
        if stored is None:
            return None
        if self.lazy:  # numbers kept as read, arrays (read-only views)
            if self.array and _FLAGS.arrays_in_place:
                return COMPAT.writable_array(obj, self.spec, stored)
            return self.codec.read(stored)
        if self.reference:
            return _read_reference(obj, self.spec, stored)
        return stored

    def __set__(self, obj: Element, value: object) -> None:
        obj._assign(self.spec, value)

    def __delete__(self, obj: Element) -> None:
        obj._assign(self.spec, None)

    def __repr__(self) -> str:
        return repr(self.spec)


@mypyc_attr(native_class=False)
class SingleChild:
    """A once-only child, created on first access; ``del`` removes it."""

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
        existing = obj._single(self.child.tag)
        if existing is not None:
            return existing
        if _FLAGS.on_demand_children and self.child.on_demand:  # (the flag first: cheap)
            return None  # a body's <inertial> is None until added
        return obj._add_child(self.child, None, {})

    def __set__(self, obj: Element, value: object) -> None:
        raise IllegalChildError(f"{obj.path}: can't set attribute {self.child.py_name!r}: it "
                                f"is the <{self.child.tag}> child; set its attributes instead")

    def __delete__(self, obj: Element) -> None:
        existing = obj._single(self.child.tag)
        if existing is not None:
            check_removable(existing)
            existing.remove()


@mypyc_attr(native_class=False)
class ChildList:
    """The children with one tag, as a live :class:`ElementList`."""

    __slots__ = ("child",)

    def __init__(self, child: ChildSpec) -> None:
        self.child = child

    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> ChildList: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> ElementList[Element]: ...
    def __get__(self, obj: Element | None, owner: type[object] | None = None) -> object:
        if obj is None:
            return self
        tag = self.child.tag
        if _FLAGS.single_freejoint and tag == grammar_facts().freejoint:  # one, or None
            return next((c for c in obj._children if c.spec.tag == tag), None)
        return ElementList[Element](obj, tag)

    def __set__(self, obj: Element, value: object) -> None:
        raise IllegalChildError(
            f"{obj.path}: can't set attribute {self.child.py_name!r}: it is the list of "
            f"<{self.child.tag}> children; use add_{self.child.tag}() or remove()")


class ElementList(Sequence[E_co], Generic[E_co]):
    """The children of one element with one tag, in document order: a live view.

    Index by position or by name (``worldbody.body["arm"]``); ``del view[i]`` removes that
    child from the model.
    """

    __slots__ = ("_owner", "_tag")

    def __init__(self, owner: Element, tag: str) -> None:
        self._owner = owner
        self._tag = tag

    def _items(self) -> list[E_co]:
        tag = self._tag
        return [cast(E_co, c) for c in self._owner._children
                if c.spec.tag == tag]

    @overload
    def __getitem__(self, index: int | str) -> E_co: ...
    @overload
    def __getitem__(self, index: _Slice) -> list[E_co]: ...
    def __getitem__(self, index: int | str | _Slice) -> E_co | list[E_co]:
        if isinstance(index, str):
            for child in self._items():
                id_attribute = child.spec.id_attribute
                if id_attribute is not None and child._values.get(
                        id_attribute.name) == index:
                    return child
            raise KeyError(f"{self._owner.path}: no <{self._tag}> child named {index!r}")
        return self._items()[index]

    def __delitem__(self, index: int | str | _Slice) -> None:
        doomed = self[index]
        for child in doomed if isinstance(doomed, list) else [doomed]:
            child.remove()

    def __len__(self) -> int:
        tag = self._tag
        return sum(1 for c in self._owner._children if c.spec.tag == tag)

    def __iter__(self) -> Iterator[E_co]:
        return iter(self._items())

    def __bool__(self) -> bool:
        return len(self) > 0

    def __eq__(self, other: object) -> bool:
        """Equal to a list, tuple or view of the same elements (hashing is off: it changes)."""
        if isinstance(other, ElementList | list | tuple):
            return self._items() == list(cast(Iterable[object], other))
        return NotImplemented

    def __repr__(self) -> str:
        return repr(self._items())

    def clear(self) -> None:
        """Remove every child of this list from the model (dm_control's ``clear()``)."""
        for child in self._items():
            child.remove()

    def remove(self, element: Element) -> None:
        """Remove ``element``, one of this list's children, from the model."""
        if not any(child is element for child in self._items()):
            raise ChildError(f"{self._owner.path}: {element!r} is not one of its "
                             f"<{self._tag}> children")
        element.remove()


# ---------------------------------------------------------------------------- add_<tag>


_ADDERS: dict[str, Callable[..., Element]] = {}


def _adder(child_spec: ChildSpec) -> Callable[..., Element]:
    """``add_<tag>()``: one function per child class, with a real signature and docstring
    (``help()``, ``inspect.signature``, Jupyter) made from the child's row."""
    key = f"{child_spec.tag}:{child_spec.class_name}:{child_spec.single}"
    found = _ADDERS.get(key)
    if found is not None:
        return found
    if child_spec.single:
        def add_child(self: Element, **kwargs: object) -> Element:
            return self._add_child(child_spec, None, kwargs)
    else:
        def add_child(self: Element, **kwargs: object) -> Element:  # the hot path of a build
            if self._attached is not None:
                _check_frame_child(self, child_spec)
            child = _create(child_spec.cls, self)
            if kwargs:
                child._init_attributes(kwargs)
            _append(self, child)
            return child
    add_child.__name__ = add_child.__qualname__ = f"add_{child_spec.tag}"
    _ADDERS[key] = add_child
    _PENDING_DOCS.append((add_child, child_spec))
    return add_child


_PENDING_DOCS: list[tuple[Callable[..., Element], ChildSpec]] = []


def document_adders() -> None:
    """Give every ``add_<tag>()`` its signature and docstring (once all classes exist)."""
    while _PENDING_DOCS:
        function, child_spec = _PENDING_DOCS.pop()
        spec = element_class(child_spec.class_name).spec
        parameters = [inspect.Parameter("self", inspect.Parameter.POSITIONAL_OR_KEYWORD)]
        parameters += [inspect.Parameter(a.py_name, inspect.Parameter.KEYWORD_ONLY,
                                         default=None, annotation=_annotation(a))
                       for a in spec.attributes.values()]
        setattr(function, "__signature__", inspect.Signature(
            parameters, return_annotation=child_spec.class_name))
        function.__doc__ = attribute_listing(spec)


def _annotation(attribute: AttributeSpec) -> str:
    return attribute.describe()


def attribute_listing(spec: ElementSpec) -> str:
    """``add_<tag>()``'s docstring, laid out by ``_doclines`` as ``elements.pyi``'s is, from
    each attribute's one line, written by the generator (``codegen/docs.py``) into its
    ``doc``."""
    entries = {a.py_name: a.doc for a in spec.attributes.values()}
    if DCLASS in spec.by_key:
        entries[DCLASS] = DCLASS_DOC
    return adder_listing(spec.tag, spec.url, entries)


# ---------------------------------------------------------------------------- creation


class _Slot(Protocol):
    def __set__(self, obj: Element, value: object, /) -> None: ...


def _slot_writer(name: str) -> Callable[[Element, object], None]:
    """Writes one of Element's slots past Element.__setattr__ (which exists to turn unknown
    names into helpful errors, and would slow every write of the tree)."""
    return cast(_Slot, vars(_Layout)[name]).__set__


_set_values = _slot_writer("_values")
_set_children = _slot_writer("_children")
_set_parent = _slot_writer("_parent")
_set_root = _slot_writer("_root")
_set_scope = _slot_writer("_scope")
_set_singles = _slot_writer("_singles")
_set_attached = _slot_writer("_attached")


def _create(cls: type[RowClass], parent: Element) -> Element:
    """A new element of ``cls`` (a generated class) under ``parent`` (not yet among its
    children), with no values."""
    attached = parent._attached
    # The seven writes are spelled out in both branches: a function shared by them cost the
    # pure build 0.5% of a build's instructions (python -m tests.bench.instructions).
    if NATIVE_LAYOUT:  # compiled: the fields are written directly
        element = cast(Element, cls.__new__(cls))
        element._values = {}
        element._children = _NO_CHILDREN
        element._parent = parent
        element._root = parent._root
        element._scope = parent._scope if attached is None else attached._scope
        element._singles = None
        element._attached = None
    else:
        # made as a _Blank (its slots written directly, past Element.__setattr__), then given
        # its class: about three times faster than writing each slot through its descriptor
        blank = _new_blank(_Blank)
        blank._values = {}
        blank._children = _NO_CHILDREN
        blank._parent = parent
        blank._root = parent._root
        blank._scope = parent._scope if attached is None else attached._scope
        blank._singles = None
        blank._attached = None
        _write_attribute(blank, "__class__", cls)
        # an Element now (typed so only from here: compiled code checks what a name holds)
        element = cast(Element, blank)
    if _RECORDER[0] is not None:
        _RECORDER[0](element, None, True)
    return element


def _child_scope(parent: Element) -> NameScope:
    """The scope of what is added under ``parent``: an attachment frame's children belong to
    the attached model's scope (two frames can each hold a joint ``root_x``)."""
    attached = parent._attached
    return parent._scope if attached is None else attached._scope


def _append(parent: Element, child: Element) -> None:
    """Put ``child`` last among ``parent``'s children (the one place that does)."""
    children = parent._children
    if type(children) is list:  # (narrowed by the test: no typing.cast, a call per child)
        children.append(child)
    else:  # () until the first child
        _set_children(parent, [child])


def _mutable_children(parent: Element) -> list[Element]:
    children = parent._children
    if type(children) is tuple:
        fresh: list[Element] = []
        _set_children(parent, fresh)
        return fresh
    return cast(list[Element], children)


def _place(parent: Element, child: Element, child_spec: ChildSpec, position: int | None) -> None:
    children = _mutable_children(parent)
    if child_spec.single:
        if parent._singles is None:
            parent._singles = {}
        parent._singles[child_spec.tag] = child
        if position is None:
            position = _grammar_position(parent, child_spec)
    if position is None:
        children.append(child)
    else:  # clamped as list.insert clamps, also past what a C index holds (10**30)
        n = len(children)
        children.insert(max(-n - 1, min(position, n)), child)


def _grammar_position(parent: Element, child_spec: ChildSpec) -> int:
    """Where a once-only child goes: before the first child the grammar lists after it."""
    children_specs = parent.spec.children
    for i, sibling in enumerate(parent._children):
        sibling_spec = children_specs.get(sibling.spec.tag)
        if sibling_spec is not None and sibling_spec.index > child_spec.index:
            return i
    return len(parent._children)


def _unlink_child(parent: Element, child: Element) -> None:
    _mutable_children(parent).remove(child)
    singles = parent._singles
    if singles is not None and singles.get(child.spec.tag) is child:
        del singles[child.spec.tag]


def _check_frame_child(frame: Element, child_spec: ChildSpec) -> None:
    """MuJoCo allows free joints only in top-level bodies: an attachment frame nested in a
    body may not have one (refused when added, as dm_control does)."""
    facts = grammar_facts()
    parent = frame._parent
    if child_spec.tag == facts.freejoint and parent is not None and not (
            parent.spec.holds_bodies and isinstance(parent._parent, ModelBase)):
        raise IllegalChildError(
            f"{frame.path}: <{child_spec.tag}> is not a valid child of this attachment frame: "
            f"MuJoCo allows free joints only in top-level bodies, and the frame is inside "
            f"{parent.path}")


def check_removable(element: Element) -> None:
    """Refuse to remove a section of a model that attached models merge their own section
    into (dm_control's guard: ``remove(affect_attachments=True)`` says what is meant)."""
    root = element._root
    if root is not None and element._parent is root and root._scope.attached:
        raise ChildError(f"{element.path}: the models attached to this one merge their "
                         f"<{element.spec.tag}> into it; use remove(affect_attachments=True) "
                         f"to clear it in every attached model too")


def _detach_model(model: ModelBase) -> None:
    """Undo an attachment whose frame leaves its model."""
    frame = model._frame
    if frame is not None:
        frame._attached = None
    model._frame = None
    parent = model._scope.parent
    if parent is not None:
        parent.detach(model._scope)


# ---------------------------------------------------------------------------- storing


def _store(element: Element, attribute: AttributeSpec, stored: object, link: bool) -> None:
    """Keep ``stored`` (what the codec gave, or the element a reference links to) as the
    attribute's value, with what comes with it: the name claimed and the old one released
    (:func:`_store_name`), the model renamed, a name that names no element yet waited for
    (if ``link``). An empty list of numbers is stored as absent, as MuJoCo reads it.

    The one place a value is stored: every route calls it, or, where a loop already knows
    the case, the case's own code (a call per value costs about 3% of a build, counted by
    ``python -m tests.bench.instructions``): a ``bare`` attribute's storing is the dict
    write alone (``AttributeSpec.bare``: direct, and never empty), which the loops of
    ``add()`` and parsing write themselves, and they store a name by :func:`_store_name`."""
    values = element._values
    if attribute.bare:  # nothing comes with it, and it is never empty
        values[attribute.name] = stored
    elif attribute.kind == "id":
        _store_name(element, attribute, stored)
    elif attribute.is_reference:
        values[attribute.name] = stored
        if link and type(stored) is str:  # a name (not an element)
            _wait(element, attribute, stored)
    elif attribute.direct:  # a list of numbers that may hold none
        if _is_empty_array(stored):
            element._unset(attribute)
        else:
            values[attribute.name] = stored
    else:  # the model's name: its scope's name too
        if isinstance(stored, str):
            _rename_model(element, stored)
        values[attribute.name] = stored


def _store_name(element: Element, attribute: AttributeSpec, name: object) -> None:
    """:func:`_store`'s case for the element's name (``attribute`` is its id): claimed in
    the element's scope (a refusal names the assignment and changes nothing), the old one
    released, what waited for it linked."""
    values = element._values
    old = values.get(attribute.name)
    if isinstance(name, str) and (old is None or old != name):  # (narrowed: no cast, a call)
        scope = element._scope
        namespace = attribute.namespace or ""  # ids have one
        table = scope.tables.get(namespace)
        if (table is not None and name not in table and not scope.waiting
                and SEPARATOR not in name and name not in _RESERVED_NAMES
                and element._root is not None):
            # a new name nothing waits for (most names): scope.claim's effect, without its
            table[name] = element  # checks, which cannot fail here
        else:
            _claim(element, attribute, namespace, name)
        if old is not None and isinstance(old, str):  # (most names are the first)
            scope.release(namespace, old, element)
    values[attribute.name] = name


def _namespace_given(pair: tuple[AttributeSpec, object]) -> bool:
    """Whether another attribute names the namespace of this reference (a sort key)."""
    return pair[0].namespace_from is not None


# ---------------------------------------------------------------------------- names


def _claim(element: Element, attribute: AttributeSpec, namespace: str, name: str) -> None:
    """Give ``element`` its name in its scope, checked (a refusal names the assignment):
    :func:`_store_name`'s case for a name that may be refused or that something waits for."""
    if element._root is None:  # not in a model (yet): no scope to claim in
        return
    scope = element._scope
    if name in _RESERVED_NAMES:
        facts = grammar_facts()
        if element.spec.tag == facts.body:
            raise InvalidValueError(
                f"{element.path}: invalid {attribute.py_name}={name!r} on "
                f"<{element.spec.tag}>: {name!r} is the name MuJoCo gives the world body")
    try:
        scope.claim(namespace, name, element)
    except NameTaken as taken:
        raise DuplicateIdentifierError(
            f"{element.path}: invalid {attribute.py_name}={name!r} on <{element.spec.tag}>: "
            f"{taken.detail}") from None
    if scope.waiting:
        _link_waiting(scope, namespace, name, element)


def _forget(element: Element) -> None:
    """Release the name of an element leaving its model."""
    id_attribute = element.spec.id_attribute
    if id_attribute is not None:
        name = element._values.get(id_attribute.name)
        if isinstance(name, str):
            element._scope.release(cast(str, id_attribute.namespace), name, element)


def _rename_model(element: Element, name: str | None) -> None:
    if isinstance(element, ModelBase):
        element._scope.rename(name)


def element_name(element: Element) -> str | None:
    """The element's own name (not scoped), if it has one."""
    id_attribute = element.spec.id_attribute
    if id_attribute is None:
        return None
    name = element._values.get(id_attribute.name)
    return name if isinstance(name, str) else None


def own_scoped_names(elements: Iterable[Element]) -> list[str | None]:
    """Each element's own name with its scope's prefix (``full_identifier``), each prefix
    computed once: ``None`` for an element without its own name, removed, or an attachment
    frame (asked one by one). For binding many elements at once."""
    prefixes: dict[int, str] = {}
    out: list[str | None] = []
    last: NameScope | None = None  # the scope of the element before, and its prefix
    prefix = ""
    for element in elements:
        attribute = element.spec.id_attribute
        name = (None if attribute is None or element._root is None
                or element._attached is not None else element._values.get(attribute.name))
        if not isinstance(name, str):
            out.append(None)
            continue
        scope = element._scope
        if scope is not last:
            found = prefixes.get(id(scope))
            if found is None:
                found = prefixes[id(scope)] = scope.prefix()
            last, prefix = scope, found
        out.append(prefix + name)
    return out


# ---------------------------------------------------------------------------- links


def _reference_namespaces(element: Element, attribute: AttributeSpec) -> frozenset[str]:
    """The namespaces a reference may name: its own, or the one its type attribute says."""
    if attribute.namespace is not None:
        return frozenset({attribute.namespace})
    assert attribute.namespace_from is not None
    type_attribute, namespaces = attribute.namespace_from
    word = element._values.get(type_attribute)
    if isinstance(word, str):
        found = namespaces.get(word.lower())
        return frozenset() if found is None else frozenset({found})
    return frozenset(namespaces.values())


def reference_namespace(element: Element, attribute: AttributeSpec) -> str | None:
    """The one namespace a reference names now, if it is known."""
    if attribute.namespace is not None:
        return attribute.namespace
    namespaces = _reference_namespaces(element, attribute)
    return next(iter(namespaces)) if len(namespaces) == 1 else None


def _resolve(element: Element, attribute: AttributeSpec, name: str) -> object:
    """The element ``name`` names for ``attribute``, or the name while it names nothing."""
    namespace = reference_namespace(element, attribute)
    if namespace is None:
        return name
    found = element._scope.find(namespace, name)
    return found if isinstance(found, Element) else name


def _wait(element: Element, attribute: AttributeSpec, name: str) -> None:
    """Link ``attribute`` when an element named ``name`` appears in the element's scope
    (with ``references_stay_names`` a name given stays that name: it links only on
    ``resolve_references()``, which a parse ends with)."""
    if _FLAGS.references_stay_names:
        return
    namespace = reference_namespace(element, attribute)
    if namespace is not None:
        element._scope.waiting.setdefault((namespace, name), []).append((element, attribute))


def _link_waiting(scope: NameScope, namespace: str, name: str, target: Element) -> None:
    waiting = scope.waiting
    if not waiting:
        return
    entries = waiting.pop((namespace, name), None)
    if entries is None:
        return
    for element, attribute in entries:
        assert isinstance(element, Element) and isinstance(attribute, AttributeSpec)
        values = element._values
        if values.get(attribute.name) == name and element._root is not None:
            values[attribute.name] = target


def _read_reference(element: Element, attribute: AttributeSpec, stored: object) -> object:
    """A link reads as its element (``None`` once the element is removed), a name as the
    name (it links when an element of that name appears, or on ``resolve_references()``;
    with ``references_stay_names`` only on ``resolve_references()``)."""
    if isinstance(stored, Element):
        return None if stored._root is None else stored
    return stored


def _read(element: Element, attribute: AttributeSpec) -> object:
    stored = element._values.get(attribute.name)
    if stored is None:
        return None
    if attribute.codec.lazy:
        return attribute.codec.read(stored)
    if attribute.is_reference:
        return _read_reference(element, attribute, stored)
    return stored


def resolve_references(model: Element) -> None:
    """Link every reference held as a name that names an element now."""
    for element in model.iter_elements():
        values = element._values
        for attribute in element.spec.references:
            stored = values.get(attribute.name)
            if type(stored) is str:
                found = _resolve(element, attribute, stored)
                if found is not stored:
                    values[attribute.name] = found


# ---------------------------------------------------------------------------- rollback


class _Snapshot:
    """An element's values and name, to put back when a group of assignments fails."""

    __slots__ = ("element", "name", "values")

    def __init__(self, element: Element) -> None:
        self.element = element
        self.values = dict(element._values)
        self.name = element_name(element)

    def restore(self) -> None:
        element = self.element
        id_attribute = element.spec.id_attribute
        current = element_name(element)
        if id_attribute is not None and current != self.name and element._root is not None:
            namespace = cast(str, id_attribute.namespace)
            scope = element._scope
            if current is not None:
                scope.release(namespace, current, element)
            if self.name is not None:
                scope.claim(namespace, self.name, element)
        scope_attribute = element.spec.scope_attribute
        if scope_attribute is not None:
            before = self.values.get(scope_attribute.name)
            if before != element._values.get(scope_attribute.name):
                _rename_model(element, before if isinstance(before, str) else None)
        element._values.clear()
        element._values.update(self.values)


# ---------------------------------------------------------------------------- copies


def _clone_tree(top: E, parent: Element | None, root: ModelBase | None, scope: NameScope,
                memo: dict[int, object]) -> E:
    """A copy of ``top``'s subtree under ``parent`` (not added to its children); iterative.
    Models attached inside it are copied too."""
    first: Element | None = None
    stack: list[tuple[Element, Element | None, NameScope]] = [(top, parent, scope)]
    while stack:
        original, clone_parent, clone_scope = stack.pop()
        cls = type(original)
        clone = cls.__new__(cls)
        _set_values(clone, {key: value for key, value in original._values.items()}
                    if not _FLAGS.arrays_in_place else COMPAT.copied_values(original._values))
        _set_children(clone, _NO_CHILDREN)
        _set_parent(clone, clone_parent)
        _set_root(clone, root)
        _set_scope(clone, clone_scope)
        _set_singles(clone, None)
        _set_attached(clone, None)
        memo[id(original)] = clone
        inner_scope = clone_scope
        if original._attached is not None:
            attached = _copy_model(original._attached, memo)
            clone._attached = attached
            attached._frame = clone
            inner_scope = attached._scope
        if first is None:
            first = clone
        elif clone_parent is not None:
            _append(clone_parent, clone)
            if clone_parent.spec.children[clone.spec.tag].single:
                if clone_parent._singles is None:
                    clone_parent._singles = {}
                clone_parent._singles[clone.spec.tag] = clone
        stack.extend((child, clone, inner_scope)
                     for child in reversed(original._children))
    assert first is not None
    return cast(E, first)


def _copy_model(model: ModelBase, memo: dict[int, object]) -> ModelBase:
    """A copy of ``model`` and the models attached to it, names registered, links to the
    originals not yet remapped (see :func:`_remap_links`)."""
    scope = NameScope(None, model._scope.name)
    clone = _clone_tree(model, None, None, scope, memo)
    scope.model = clone
    clone._base_dir = model._base_dir
    clone._access = model._access
    clone._files = copy.copy(model._files)  # files read on demand stay so
    clone._frame = None
    clone._sources = None  # a copy was not read from anywhere
    stack: list[Element] = [clone]
    while stack:
        element = stack.pop()
        _set_root(element, clone)
        name = element_name(element)
        id_attribute = element.spec.id_attribute
        if name is not None and id_attribute is not None:
            element._scope.claim(cast(str, id_attribute.namespace), name, element)
        attached = element._attached
        if attached is not None:
            scope.attach(attached._scope)
        stack.extend(element._children)
    return clone


def _remap_links(top: Element, memo: Mapping[int, object]) -> None:
    """Point links to elements that were copied at their copies (attached models' too)."""
    stack: list[Element] = [top]
    while stack:
        element = stack.pop()
        values = element._values
        for attribute in element.spec.references:
            value = values.get(attribute.name)
            if isinstance(value, Element):
                target = cast(Element, memo.get(id(value), value))
                values[attribute.name] = target
                if element_name(target) is None:
                    target._scope.unnamed_targets.append(target)
        stack.extend(element._children)
        attached = element._attached
        if attached is not None:
            stack.append(attached)


def _adopt(parent: Element, clone: Element, original: Element) -> None:
    """Register a pasted copy's names and attached models in ``parent``'s model: links to
    elements outside the copy that are not in this model become names again."""
    root = parent._root
    for copied in clone.iter_elements():
        values = copied._values
        for attribute in copied.spec.references:
            value = values.get(attribute.name)
            if isinstance(value, Element) and value._root is not root:
                name = element_name(value)
                if name is None:
                    del values[attribute.name]
                else:
                    values[attribute.name] = _resolve(copied, attribute, name)
        name = element_name(copied)
        id_attribute = copied.spec.id_attribute
        if root is not None and id_attribute is not None and name is not None:
            holder = copied._scope.lookup(cast(str, id_attribute.namespace), name)
            if holder is not None:
                raise DuplicateIdentifierError(
                    f"{parent.path}: cannot add a copy of {original.path}: its "
                    f"{id_attribute.namespace} name {name!r} is taken by {holder.path}")
    if root is None:
        return
    for copied in clone.iter_elements():
        attached = copied._attached
        if attached is not None:
            copied._scope.attach(attached._scope)
        name = element_name(copied)
        id_attribute = copied.spec.id_attribute
        if id_attribute is not None and name is not None:
            copied._scope.claim(cast(str, id_attribute.namespace), name, copied)


# ---------------------------------------------------------------------------- comparison


def _same_values(a: Element, b: Element) -> bool:
    values_a, values_b = a._values, b._values
    if values_a.keys() != values_b.keys():
        return False
    spec = a.spec
    for name in values_a:
        attribute = spec.by_name[name]
        x, y = _read(a, attribute), _read(b, attribute)
        if isinstance(x, Element) or isinstance(y, Element):
            x = element_name(x) if isinstance(x, Element) else x
            y = element_name(y) if isinstance(y, Element) else y
        if not equal_read_values(x, y):
            return False
    return True


def _is_empty_array(stored: object) -> bool:
    return type(stored) is np.ndarray and not stored.size  # (narrowed: no typing.cast, a call)


def equal_read_values(a: object, b: object) -> bool:
    """Whether two values as attributes read are equal: numbers by value, whatever holds
    them (an array equals a tuple of the same numbers)."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        try:
            return bool(np.array_equal(np.asarray(a), np.asarray(b)))
        except (TypeError, ValueError):
            return False
    return a == b


def _children_by_tag(element: Element) -> dict[str, list[Element]]:
    groups: dict[str, list[Element]] = {}
    for child in element._children:
        groups.setdefault(child.spec.tag, []).append(child)
    return groups


# ---------------------------------------------------------------------------- internal API
# What the features (parse, export, composition, validation, ...) use of the tree.


def values(element: Element) -> Mapping[str, object]:
    """The stored values by XML name (read only, as its type says to type checkers: set
    through the element or the functions below). Lazy text and links are as stored;
    :func:`read_value` gives what users read."""
    return element._values


def children(element: Element) -> Sequence[Element]:
    """The children in document order (the tree's own list: do not modify)."""
    return element._children


def parent_of(element: Element) -> Element | None:
    return element._parent


def children_with_tag(element: Element, tag: str | None) -> list[Element]:
    """The children (only those with ``tag`` if given; a tag the grammar does not allow
    here is an error)."""
    if tag is None:
        return list(element._children)
    element._child_spec(tag)
    return [c for c in element._children if c.spec.tag == tag]


def model_of(element: Element) -> ModelBase | None:
    """The model whose tree holds ``element`` (``None`` once removed)."""
    return element._root


def scope_of(element: Element) -> NameScope:
    """The name scope the element's name lives in."""
    return element._scope


def attached_at(element: Element) -> ModelBase | None:
    """The model attached at ``element``, an attachment frame."""
    return element._attached


def scope_model(scope: NameScope) -> ModelBase:
    """The model whose scope ``scope`` is."""
    return cast(ModelBase, scope.model)


def attached_models(model: ModelBase) -> list[ModelBase]:
    """The models attached to ``model`` (not nested ones), in document order."""
    if not model._scope.attached:
        return []
    return [e._attached for e in model.iter_elements() if e._attached is not None]


def child_scope(parent: Element) -> NameScope:
    """The scope of what is added under ``parent``."""
    return _child_scope(parent)


def frame_of(model: ModelBase) -> Element | None:
    """Where ``model`` is attached, if it is."""
    return model._frame


def base_dir(model: ModelBase) -> str | None:
    return model._base_dir


def set_base_dir(model: ModelBase, folder: str | None) -> None:
    model._base_dir = folder


def file_access(model: ModelBase) -> Confinement:
    """The files ``model`` may read (see :mod:`typed_mjcf._core.access`)."""
    return model._access


def set_file_access(model: ModelBase, access: Confinement) -> None:
    model._access = access


def memory_files(model: ModelBase) -> dict[str, bytes]:
    """File contents the model was given in memory, by the path its attributes write."""
    return model._files


def set_memory_files(model: ModelBase, files: dict[str, bytes]) -> None:
    """Give ``model`` its in-memory files (a dict that may read entries on demand)."""
    model._files = files


def source_map(model: ModelBase) -> SourceMap | None:
    """Where the parser read ``model``'s elements (``None`` for a model built in Python)."""
    return model._sources


def set_source_map(model: ModelBase, sources: SourceMap | None) -> None:
    model._sources = sources


def source_of(element: Element) -> tuple[str | None, int | None] | None:
    """The file and line ``element`` was read from (the line its start tag begins on, for
    elements read from a file), if it was parsed and is still in the model it was read into."""
    root = element._root
    sources = None if root is None else root._sources
    found = None if sources is None else sources.get(element)
    if sources is None or found is None:
        return found
    source, line = found
    if source is None or line is None:
        return found
    return source, file_start_line(source, line, element.spec.tag, sources.texts)


def single_child(element: Element, tag: str) -> Element | None:
    return element._single(tag)


def read_value(element: Element, attribute: AttributeSpec) -> object:
    """The value users read for ``attribute`` (converted; a removed target reads None)."""
    return _read(element, attribute)


def new_child(parent: Element, child_spec: ChildSpec) -> Element:
    """A new child of ``parent``, last among its children, with no attributes."""
    child = _create(child_spec.cls, parent)
    if child_spec.single:
        _place(parent, child, child_spec, None)
        return child
    _append(parent, child)
    return child


def rejection(element: Element, attribute: AttributeSpec, value: object,
              rejected: Rejected) -> Exception:
    """The error for a value ``attribute`` refused on ``element``, naming both."""
    return element._reject(attribute, value, rejected)


def assign(element: Element, attribute: AttributeSpec, value: object) -> None:
    """Set ``attribute`` from a Python value, as assignment does."""
    element._assign(attribute, value)


def convert(element: Element, attribute: AttributeSpec, value: object) -> object:
    """``value`` as assigning it to ``attribute`` would store it (checked; nothing stored)."""
    return element._convert(attribute, value)


def attribute_of(element: Element, key: str) -> AttributeSpec:
    """The attribute ``key`` (Python or XML name) of ``element``; the element's error if
    it has none."""
    return element._attribute(key)


def snapshot(element: Element) -> Callable[[], None]:
    """What puts ``element``'s values and name back as they are now."""
    return _Snapshot(element).restore


def assign_texts(element: Element, items: Iterable[tuple[str, str]], names: bool = True,
                 link: bool = True
                 ) -> list[tuple[str, AttributeSpec | None, str, Exception | None]] | None:
    """Set the attributes ``items`` (name, text) read from a file: most of a parse. Values,
    and if ``names`` (names taken as written) the element's name and its references of a
    fixed namespace (as :func:`assign_text` with ``link``). Return the others, in order,
    for the caller: each with its attribute (``None``: the row lacks it) and the refusal (a
    :class:`Rejected` or a library error), or ``None`` for one not set here (an empty text,
    a reference whose namespace another attribute names, names when not ``names``)."""
    by_name = type(element).spec.by_name
    values = element._values
    rest: list[tuple[str, AttributeSpec | None, str, Exception | None]] | None = None
    refused: Exception | None = None
    for key, text in items:
        attribute = by_name.get(key)
        if attribute is not None and text:
            try:
                if attribute.bare:  # storing it is this write (_store's first case)
                    values[attribute.name] = attribute.codec.parse(text)
                    continue
                if names and attribute.kind == "id":
                    _store_name(element, attribute, attribute.codec.parse(text))
                    continue
                if attribute.direct:
                    _store(element, attribute, attribute.codec.parse(text), True)
                    continue
                if names and attribute.kind == "ref":
                    assign_text(element, attribute, text, link)
                    continue
            except (Rejected, MjcfError) as error:
                refused = error
        if rest is None:
            rest = []
        rest.append((key, attribute, text, refused))
        refused = None
    return rest


def assign_text(element: Element, attribute: AttributeSpec, text: str,
                link: bool = True) -> None:
    """Set ``attribute`` from text read from a file (numbers stay text once checked; names
    may hold '/'; references link when their target exists, unless ``link`` is false);
    raises :class:`Rejected`."""
    if not text:
        element._unset(attribute)  # an empty value: MuJoCo reads it as absent
        return
    namespace = attribute.namespace
    if link and namespace is not None and attribute.kind == "ref":
        table = element._scope.tables.get(namespace)
        found = None if table is None else table.get(text)
        if isinstance(found, Element):  # names an element already (a name in a table
            _store(element, attribute, found, True)  # is one the codec takes): linked at once
            return
    stored = attribute.codec.parse(text)
    if link and attribute.is_reference:
        stored = _resolve(element, attribute, text)
    _store(element, attribute, stored, link)


def attach_at(frame: Element, model: ModelBase) -> None:
    """Record that ``model`` is attached at ``frame`` (placement is composition's job)."""
    frame._scope.attach(model._scope)
    frame._attached = model
    model._frame = frame


def detach_model(model: ModelBase) -> None:
    """Undo :func:`attach_at`; the frame stays where it is."""
    _detach_model(model)


def remove_subtree(element: Element) -> None:
    """``element.remove()`` without the guard on merged sections."""
    Element.remove(element)


def iter_composed(top: Element, attachments: bool) -> Iterator[Element]:
    """``top``'s subtree in the order the exported XML has it: attached models' bodies inside
    their frames, their other sections after ours (when ``attachments``)."""
    pending: list[ModelBase] = []

    def walk(elements: list[Element]) -> Iterator[Element]:
        stack = list(reversed(elements))
        while stack:
            element = stack.pop()
            yield element
            attached = element._attached if attachments else None
            if attached is None:  # (extend reads the children at once: no copy needed)
                stack.extend(reversed(element._children))
                continue
            inside = list(element._children)
            for section in attached._children:
                if section.spec.holds_bodies:
                    inside += section._children
            pending.append(attached)
            stack.extend(reversed(inside))

    yield from walk([top])
    while pending:
        model = pending.pop(0)
        for section in children(model):
            if not section.spec.holds_bodies:
                yield from walk(list(children(section)))


# ---------------------------------------------------------------------------- spellings


def insert_child(parent: Element, tag: object, position: object,
                 kwargs: dict[str, object]) -> Element:
    """``insert()``: a child ``<tag>`` at ``position``, each checked (a bool is no int)."""
    if isinstance(position, bool) or not isinstance(position, int):
        raise InvalidTypeError(f"{parent.path}: insert() position must be an int, "
                               f"got {position!r}")
    if not isinstance(tag, str):
        raise InvalidTypeError(f"{parent.path}: a child tag must be a string, got {tag!r}")
    return parent._add_child(parent._new_child_spec(tag), position, kwargs)


def _python_name(spec: ElementSpec, name: str) -> str | None:
    """The Python name of a child or attribute that ``name`` spells as MJCF does, where the
    two differ (``global`` is ``global_``)."""
    child = spec.children.get(name)
    if child is not None and child.py_name != name:
        return child.py_name
    attribute = spec.by_name.get(name)
    if attribute is not None and attribute.py_name != name:
        return attribute.py_name
    return None


def mjcf_alias(element: Element, name: str) -> str | None:
    """The Python name of ``element``'s child or attribute that ``name`` spells as MJCF does
    (``global``: ``global_``); ``None`` where the two are the same or there is none."""
    return _python_name(element.spec, name)


def add_rejection_note(note: Callable[[object], str | None]) -> None:
    """Have refusals of a value ask ``note`` what it says of that value (once per note)."""
    if note not in _REJECTION_NOTES:
        _REJECTION_NOTES.append(note)


def unknown_attribute(element: Element, name: str) -> UnknownAttributeError:
    """The error for ``name``, none of ``element``'s attributes."""
    return element._unknown_attribute(name)


# ---------------------------------------------------------------------------- dm_control's behaviours
# What the tree does differently under a flag of typed_mjcf._core.behaviour is read there
# (``_FLAGS.<name>``); what only dm_control does lives in the compat room
# (typed_mjcf._dmcompat.behaviours), which fills these hooks when the package is imported.


def _not_filled(*_: object) -> NoReturn:
    raise MjcfError("dm_control's behaviours come from typed_mjcf._dmcompat, which is not "
                    "imported (import typed_mjcf)")


def _nothing_handed_out(model: ModelBase) -> None:
    """No array is handed out for in-place edits until the compat room lends its own."""


class CompatHooks:
    """What the compat room lends the tree and the features, each called only while its
    flag is on (:func:`check_arrays` always: it has nothing to do while none is handed out)."""

    __slots__ = ("check_arrays", "copied_values", "explained", "name_after_file", "name_after_files",
                 "tag_by_keyword", "unnamed_identifier", "unnamed_names",
                 "writable_array")

    def __init__(self) -> None:
        # arrays_in_place: the stored array itself, writable; values copied for a copy; the
        # arrays handed out checked again before a model is written
        self.writable_array: Callable[[Element, AttributeSpec, object], object] = _not_filled
        self.copied_values: Callable[[Mapping[str, object]], dict[str, object]] = _not_filled
        self.check_arrays: Callable[[ModelBase], None] = _nothing_handed_out
        # named_after_files: one element (when unnamed), every element of a model
        self.name_after_file: Callable[[Element], None] = _not_filled
        self.name_after_files: Callable[[ModelBase], None] = _not_filled
        # element_name_keyword: the tag ``add()``'s keywords name (taken out of them)
        self.tag_by_keyword: Callable[[dict[str, object]], str | None] = _not_filled
        # unnamed_identifiers: one element's identifier; every unnamed one of a model
        self.unnamed_identifier: Callable[[Element], str | None] = _not_filled
        self.unnamed_names: Callable[[ModelBase], dict[int, str]] = _not_filled
        # compile_error_advice: a refusal of a model for a physics, with dm_control's advice
        self.explained: Callable[[ValueError, ModelBase], ValueError] = _not_filled


COMPAT: Final = CompatHooks()


def tag_given(parent: Element, tag: object, kwargs: dict[str, object]) -> str:
    """``add()``'s tag: the first argument, or (``element_name_keyword``) the keyword that
    names it (taken out of the attributes). Takes any object (here and in
    :func:`insert_child`: the compiled build checks an annotation before the body can)."""
    if tag is None and _FLAGS.element_name_keyword:
        tag = COMPAT.tag_by_keyword(kwargs)
    if tag is None:
        raise InvalidTypeError(f"{parent.path}: add() takes the child's tag first, e.g. "
                               f"add('<tag>', ...)")
    if not isinstance(tag, str):
        raise InvalidTypeError(f"{parent.path}: a child tag must be a string, got {tag!r}")
    return tag


def check_arrays(model: ModelBase) -> None:
    """Check again every array of ``model`` (and the models attached to it) handed out for
    in-place edits: an edit that made it invalid raises the error assigning it would."""
    COMPAT.check_arrays(model)


def keep_value(element: Element, attribute: AttributeSpec, value: object) -> None:
    """Keep ``value`` as ``attribute``'s stored value as it is (an array handed out for
    in-place edits, which is already the codec's)."""
    element._values[attribute.name] = value


def store_name(element: Element, attribute: AttributeSpec, name: str) -> None:
    """Give ``element`` the name ``name`` (``attribute`` its id), as storing does: a name
    given after a file."""
    _store(element, attribute, name, True)
