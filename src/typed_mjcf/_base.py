"""The public base classes of the generated classes: :class:`Element` and :class:`ModelRoot`.

They put the features (export, composition, defaults, validation, the MuJoCo bridge) on the
core tree as methods, so that users meet one object; each method is a thin call into its
feature module.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Final, cast

from lxml import etree

from typed_mjcf import _tree
from typed_mjcf._bridge import compile_model, to_spec
from typed_mjcf._codecs import Format
from typed_mjcf._compose import attach, attached_children, detach, include_copy
from typed_mjcf._defaults import resolve
from typed_mjcf._files import file_stem
from typed_mjcf._names import NameScope
from typed_mjcf._traversal import commit_defaults
from typed_mjcf._tree import check_removable, grammar_facts
from typed_mjcf._validate import Finding, validate
from typed_mjcf._write import collect, element_text
from typed_mjcf.assets import Asset
from typed_mjcf.errors import InvalidValueError, did_you_mean

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._generated.elements import Body, Namespace, RootElement
    from typed_mjcf.types import XmlElement


class Element(_tree.Element):
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""

    __slots__ = ()

    # ------------------------------------------------------------------ where it is

    @property
    def root(self) -> ModelRoot:
        """The model this element belongs to."""
        root = _tree.model_of(self)
        if root is None:
            raise InvalidValueError(f"{self.path}: the element is not part of a model "
                                    f"(it was removed)")
        return cast(ModelRoot, root)

    @property
    def parent(self) -> Element | None:
        """The parent element; ``None`` for a model's root or a removed element."""
        return cast("Element | None", _tree.parent_of(self))

    def get_children(self, tag: str | None = None) -> list[Element]:
        """The children, in document order (only those with ``tag`` if given). An
        attachment frame's include the attached model's bodies (and the rest of its world
        body); a top-level section of a composed model, the attached models' sections'."""
        own = _tree.children_with_tag(self, tag)
        return cast("list[Element]", own + [e for e in attached_children(self)
                                            if tag is None or e.spec.tag == tag])

    def all_children(self) -> list[Element]:
        """dm_control's name for ``get_children()``."""
        return self.get_children()

    def iter_elements(self) -> Iterator[Element]:
        """This element and all its descendants, in document order (attached models are
        not included: see ``find_all``)."""
        return cast("Iterator[Element]", super().iter_elements())

    @property
    def namescope(self) -> NameScope:
        """The name scope this element's name lives in (its model's)."""
        return _tree.scope_of(self)

    @property
    def full_identifier(self) -> str | None:
        """The name this element has in the outermost model it is part of (its scope's
        prefix and its name, ``arm/elbow``); ``None`` for an unnamed element."""
        scope = _tree.scope_of(self)
        prefix = scope.prefix()
        if isinstance(self, ModelRoot) and _tree.model_of(self) is self:
            return prefix
        attached = _tree.attached_at(self)
        if attached is not None:
            return f"{_tree.scope_of(self).prefix()}{_tree.scope_of(attached).name}/"
        if self.spec.holds_bodies and isinstance(self.parent, ModelRoot):  # the world body
            return prefix or grammar_facts().world_body
        name = _tree.element_name(self)
        return None if name is None else prefix + name

    @property
    def attached_model(self) -> ModelRoot | None:
        """On an attachment frame, the model attached there."""
        return cast("ModelRoot | None", _tree.attached_at(self))

    # ------------------------------------------------------------------ look-ups

    def find(self, namespace: Namespace, identifier: str) -> Element | None:
        """The element named ``identifier`` in ``namespace`` inside this element, or ``None``.
        O(1) per scope: ``find("joint", "arm/elbow")`` looks in the model attached as
        ``arm``."""
        if namespace == ATTACHMENT_FRAME:
            attached = self.enter_model(identifier)
            found: object = None if attached is None else _tree.frame_of(attached)
        else:
            _check_namespace(namespace)
            found = _tree.scope_of(self).find(namespace, identifier)
            if found is None and namespace in grammar_facts().named_after_file:
                found = named_after_file(self, namespace, identifier)
        if not isinstance(found, Element) or found.is_removed:
            return None
        if isinstance(self, ModelRoot) and _tree.model_of(self) is self:
            return found
        return found if _is_inside(found, self) else None

    def enter_model(self, scope: str) -> ModelRoot | None:
        """The model attached under ``scope`` (``"arm"``, or ``"arm/gripper/"`` for one
        attached inside it) in this element's scope, or ``None``."""
        current: NameScope | None = _tree.scope_of(self)
        for part in (p for p in scope.split("/") if p):
            current = None if current is None else current.attached.get(part)
        if current is None or current is _tree.scope_of(self):
            return None
        return cast(ModelRoot, _tree.scope_model(current))

    def find_all(self, namespace: Namespace, immediate_children_only: bool = False,
                 exclude_attachments: bool = False) -> list[Element]:
        """Every element of ``namespace`` inside this element (named or not), attached
        models' included unless ``exclude_attachments``, in the order the exported XML has
        them; only this element's children with ``immediate_children_only``."""
        if namespace == ATTACHMENT_FRAME:
            def wanted(element: _tree.Element) -> bool:
                return _tree.attached_at(element) is not None
        else:
            _check_namespace(namespace)

            def wanted(element: _tree.Element) -> bool:
                return element.spec.namespace == namespace
        if immediate_children_only:
            return [cast(Element, c) for c in _tree.children(self) if wanted(c)]
        return [cast(Element, e) for e in _tree.iter_composed(self, not exclude_attachments)
                if wanted(e) and e is not self]

    # ------------------------------------------------------------------ values

    if not TYPE_CHECKING:  # typed per attribute by each generated class

        def resolve(self, name: str) -> object:
            """The value MuJoCo uses for attribute ``name``: set here, else from the default
            classes that apply (``class``, an ancestor's ``childclass``, the root class),
            else the grammar's default; ``None`` where MuJoCo computes it."""
            return resolve(self, name)

    # ------------------------------------------------------------------ composition

    def remove(self, affect_attachments: bool = False) -> None:
        """Remove this element (and its subtree) from its parent; references to the removed
        elements read as ``None`` from now on. A section that attached models merge into
        (``<option>``, ``<contact>``, ...) is removed only with ``affect_attachments=True``,
        which removes it in every attached model too."""
        if affect_attachments:
            root = _tree.model_of(self)
            if root is not None and _tree.parent_of(self) is root:
                for model in _tree.attached_models(root):
                    section = _tree.single_child(model, self.spec.tag)
                    if section is not None:
                        cast(Element, section).remove(affect_attachments=True)
        else:
            check_removable(self)
        _tree.remove_subtree(self)

    # ------------------------------------------------------------------ export

    def to_xml_string(self, prefix_root: NameScope | None = None, self_only: bool = False,
                      pretty_print: bool = True, debug_context: object = None, *,
                      precision: int | None = None, zero_threshold: float = 0.0,
                      canonical: bool = False) -> str:
        """This element as MJCF text (a top-level section of a composed model holds the
        attached models' sections too).

        Numbers read from a file are written as they were read; values set in Python in the
        shortest form that reads back exactly. ``precision`` (significant digits),
        ``zero_threshold`` (smaller magnitudes are written as 0) and ``canonical=True`` (every
        number in the canonical form, as if set in Python) reformat every number. Names are
        written as seen from the element's model, or from ``prefix_root`` (a name scope);
        ``self_only`` writes the element's own tag only. ``debug_context`` is accepted for
        dm_control's signature and unused.
        """
        del debug_context
        return element_text(self, Format(precision, zero_threshold, canonical), pretty_print,
                            names_from=prefix_root, self_only=self_only)

    def to_xml(self, prefix_root: NameScope | None = None, debug_context: object = None, *,
               precision: int | None = None, zero_threshold: float = 0.0,
               canonical: bool = False) -> XmlElement:
        """This element as an lxml element."""
        del debug_context
        return etree.fromstring(self.to_xml_string(
            prefix_root, pretty_print=False, precision=precision, zero_threshold=zero_threshold,
            canonical=canonical))

    def __str__(self) -> str:
        """The element's own tag, e.g. ``<joint type="hinge"/>`` (``...`` for children)."""
        return self.to_xml_string(self_only=True, pretty_print=False)

    # ------------------------------------------------------------------ defaults

    def commit_defaults(self, attributes: Iterable[str] | None = None) -> None:
        """Write the values the default classes give this element into it (only
        ``attributes``, when given): it then says what MuJoCo uses without its classes."""
        commit_defaults(self, attributes)


class Attachable(_tree.Element):
    """What elements a model can be attached at have (bodies, the world, sites, the root)."""

    __slots__ = ()

    def attach(self, model: ModelRoot) -> Body:
        """Attach ``model`` here; return its attachment frame (a ``<body>``).

        Args:
            model: the model to attach; it stays its own object, its names scoped ``<its name>/...`` here (``find("joint", "arm/elbow")``) and in the exported XML; its ``detach()`` undoes the attachment.
        """
        return cast("Body", attach(self, model))

    def attach_model(self, model: ModelRoot) -> Body:
        """Another name for :meth:`attach`."""
        return self.attach(model)


class ModelRoot(Element, _tree.ModelBase):
    """Behaviour of ``<mujoco>``, the root of a model. Use ``typed_mjcf.RootElement``."""

    __slots__ = ()

    @property
    def namespaces(self) -> frozenset[str]:
        """The identifier namespaces of the grammar (``body``, ``joint``, ``geom``, ...)."""
        return _namespaces()

    @property
    def attachment_frame(self) -> Element | None:
        """Where this model is attached (its frame in the parent model), if it is."""
        return cast("Element | None", _tree.frame_of(self))

    @property
    def base_dir(self) -> str | None:
        """The directory relative file paths resolve against (the parsed file's folder)."""
        return _tree.base_dir(self)

    def detach(self) -> None:
        """Undo this model's attachment: its frame (and anything added to it) is removed."""
        detach(self)

    @property
    def parent_model(self) -> ModelRoot | None:
        """The model this one is attached to, if it is."""
        frame = _tree.frame_of(self)
        return None if frame is None else cast("ModelRoot | None", _tree.model_of(frame))

    @property
    def root_model(self) -> ModelRoot:
        """The outermost model this one is attached into (itself when not attached)."""
        return cast(ModelRoot, _tree.scope_model(_tree.scope_of(self).outermost()))

    def enter_scope(self, scope: str) -> ModelRoot | None:
        """The model attached under ``scope`` (``"arm"``, or ``"arm/gripper/"`` for one
        attached inside it), or ``None`` (dm_control's name for ``enter_model``)."""
        return self.enter_model(scope)

    def resolve_references(self) -> None:
        """Link every reference held as a name that names an element now (a model read
        with ``resolve_references=False``, say)."""
        _tree.resolve_references(self)

    def include_copy(self, other: ModelRoot, override_attributes: bool = False) -> None:
        """Merge a copy of ``other``'s contents into this model (dm_control's
        ``include_copy``): its sections' children are copied in (references among them point
        at the copies), and its global settings are adopted where this model leaves them
        unset; a setting both give differently is an error unless ``override_attributes``."""
        include_copy(self, other, override_attributes)

    def iter_exported(self) -> Iterator[Element]:
        """Every element of the composed model, in the order the exported XML has them:
        attached models' bodies inside their frames, their other sections after ours."""
        return (cast(Element, e) for e in _tree.iter_composed(self, True))

    def get_assets(self) -> dict[str, bytes]:
        """The files the model uses, by the names its VFS export gives them."""
        return collect(self).files

    def validate(self) -> list[Finding]:
        """What MuJoCo's grammar forbids beyond single values: presence constraints, required
        attributes and children, references that name nothing, unused default classes, ...
        Each finding names the element path and the rule; warnings don't stop compile()."""
        return validate(self)

    def compile(self) -> mujoco.MjModel:
        """Validate, then compile with MuJoCo (assets passed through a virtual file system).

        Raises ``ValidationError`` listing every error ``validate()`` finds, or
        ``CompileError`` with MuJoCo's message and the path of the element it concerns."""
        return compile_model(self)

    def to_spec(self) -> mujoco.MjSpec:
        """This model as a ``mujoco.MjSpec``."""
        return to_spec(self)

    if TYPE_CHECKING:
        def __copy__(self) -> RootElement: ...


# ---------------------------------------------------------------------------- helpers


def _namespaces() -> frozenset[str]:
    found = _NAMESPACES
    if not found:
        found.update(cls.spec.namespace for cls in _tree.element_classes().values()
                     if cls.spec.namespace is not None)
    return frozenset(found)


_NAMESPACES: Final[set[str]] = set()


# dm_control's name for looking up attachment frames by their model's name in find().
ATTACHMENT_FRAME: Final = "attachment_frame"


def named_after_file(element: _tree.Element, namespace: str, name: str) -> _tree.Element | None:
    """An unnamed element of ``namespace`` (a mesh, a texture...) that MuJoCo names after the
    stem of its file, if one is named ``name`` that way."""
    attribute = grammar_facts().named_after_file[namespace]
    root = _tree.model_of(element)
    if root is None:
        return None
    for candidate in _tree.iter_composed(root, False):
        if candidate.spec.namespace != namespace or _tree.element_name(candidate) is not None:
            continue
        file = _tree.values(candidate).get(attribute)
        if isinstance(file, str) and file_stem(file) == name:
            return candidate
        if isinstance(file, Asset) and file.name == name:
            return candidate
    return None


def _check_namespace(namespace: str) -> None:
    known = _namespaces()
    if namespace not in known:
        raise InvalidValueError(
            f"{namespace!r} is not a valid namespace{did_you_mean(namespace, known)}; "
            f"namespaces: {', '.join(sorted(known))}")


def _is_inside(element: _tree.Element, ancestor: _tree.Element) -> bool:
    """Whether ``element`` is ``ancestor`` or below it, attachment frames included."""
    current: _tree.Element | None = element
    while current is not None:
        if current is ancestor:
            return True
        parent = current.parent
        if parent is None and isinstance(current, _tree.ModelBase):
            parent = _tree.frame_of(current)
        current = parent
    return False
