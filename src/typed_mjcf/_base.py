"""The public base classes of the generated classes: :class:`Element` and :class:`ModelRoot`.

They put the features (export, composition, defaults, validation, the MuJoCo bridge) on the
core tree as methods, so that users meet one object; each method is a thin call into its
feature module.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Final, Generic, Never, NoReturn, Self, TypeVar, cast

from lxml import etree

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.codecs import Format
from typed_mjcf._core.debuginfo import StackTraceEntry, attribute_stacks, init_stack
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, did_you_mean
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._core.tree import check_removable, grammar_facts
from typed_mjcf._model.assets_io import get_assets
from typed_mjcf._model.compose import attach, attached_children, detach, include_copy
from typed_mjcf._model.defaults import resolve
from typed_mjcf._model.resource_limits import (
    DEFAULT_COMPILE_LIMITS,
    DEFAULT_RENDER_LIMITS,
    CompileLimits,
    RenderLimits,
)
from typed_mjcf._model.traversal import commit_defaults
from typed_mjcf._model.validate import Finding, validate
from typed_mjcf._model.write import attribute_text
from typed_mjcf._sim.bridge import compile_model, to_spec
from typed_mjcf._sim.notebook import repr_mimebundle, repr_png
from typed_mjcf._sim.preview import FreeView, render, render_png
from typed_mjcf._sim.text import model_text
from typed_mjcf._text.files import copied_files, file_stem, rebase_files
from typed_mjcf.assets import Asset

if TYPE_CHECKING:
    import os

    import mujoco
    from typing_extensions import TypeVar as _TypeVar  # with a default (PEP 696)

    from typed_mjcf._generated import Namespace
    from typed_mjcf.types import RgbImage, XmlElement


class Element(_tree.Element):
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""

    __slots__ = _tree.WEAKREF_SLOTS  # (the compiled build's native base keeps none)

    # ------------------------------------------------------------------ unknown attributes
    # Here, not on typed_mjcf._core.tree.Element: that module may be compiled (mypyc drops code
    # under `if not TYPE_CHECKING` and keeps no such methods on classes it compiles).

    if not TYPE_CHECKING:  # run time only: checkers should see unknown attributes as errors

        def __getattr__(self, name: str) -> NoReturn:
            # Only reached when normal lookup fails: an attribute the grammar doesn't have.
            if name.startswith("__"):
                raise AttributeError(name)
            alias = _tree.mjcf_alias(self, name)
            if alias is not None:  # dm_control's spelling: getattr(visual, "global")
                return getattr(self, alias)
            raise self._unknown_attribute(name)

        def __setattr__(self, name: str, value: object) -> None:
            # Properties and slots are found by the normal route; anything else is a name
            # the grammar does not have. The tree writes its slots with _SLOTS' setters.
            try:
                object.__setattr__(self, name, value)
            except AttributeError:
                raise self._unknown_attribute(name, "can't set attribute") from None

        def __delattr__(self, name: str) -> None:
            try:
                object.__delattr__(self, name)
            except AttributeError:
                raise self._unknown_attribute(name) from None

        # dm_control's code also names the tag by keyword: add(element_name="geom", ...)
        def add(self, tag=None, /, **kwargs):
            """Add a child ``<tag>`` with the given attributes and return it."""
            return self._add_child(self._new_child_spec(_tree.tag_given(self, tag, kwargs)),
                                   None, kwargs)

        def insert(self, tag, /, position, **kwargs):
            """Add a child ``<tag>`` at ``position`` among this element's children."""
            return _tree.insert_child(self, tag, position, kwargs)

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
        body); a top-level section of a composed model, the attached models' sections'.

        With ``once_only_children_by_tag``, a once-only child's tag gives that child itself
        (``None`` if it does not exist), as dm_control's ``get_children`` does; with
        ``eager_children``, the once-only children that are not on demand are among all
        children (dm_control makes them with their parent)."""
        if tag is None and FLAGS.eager_children:
            for child_spec in self.spec.children.values():
                if child_spec.single and not child_spec.on_demand:
                    getattr(self, child_spec.py_name)
        elif tag is not None and FLAGS.once_only_children_by_tag:
            once = self.spec.children.get(tag)
            if once is not None and once.single:
                return cast("list[Element]", getattr(self, once.py_name))
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
        prefix and its name, ``arm/elbow``); ``None`` for an unnamed element (with
        ``Behaviour.unnamed_identifiers``, dm_control's name for it: ``//unnamed_geom_0``)."""
        return self.prefixed_identifier(None)

    def prefixed_identifier(self, prefix_root: NameScope | None) -> str | None:
        """The element's name as seen from the model of scope ``prefix_root`` (the
        outermost model when ``None``), as :attr:`full_identifier` gives it."""
        scope = _tree.scope_of(self)
        prefix = scope.prefix(prefix_root)
        if isinstance(self, _tree.ModelBase) and _tree.model_of(self) is self:
            return prefix
        attached = _tree.attached_at(self)
        if attached is not None:
            return f"{prefix}{_tree.scope_of(attached).name}/"
        if self.spec.holds_bodies and isinstance(self.parent, ModelRoot):  # the world body
            return prefix or grammar_facts().world_body
        name = _tree.element_name(self)
        if name is None and FLAGS.unnamed_identifiers:
            parent = self.parent
            if self.spec.compose == "nest" and isinstance(parent, _tree.ModelBase):
                return prefix or SEPARATOR  # the model's own default class: dm_control names it so
            if parent is not None and _tree.attached_at(parent) is not None and (
                    _tree.scope_of(parent) is not scope):  # a frame's own: the frame's name
                return parent.prefixed_identifier(prefix_root)
            unnamed = _tree.COMPAT.unnamed_identifier(self)
            return None if unnamed is None else (prefix or SEPARATOR) + unnamed
        if name is not None and FLAGS.frame_names_end_in_separator:
            parent = self.parent
            if parent is not None and _tree.attached_at(parent) is not None and (
                    _tree.scope_of(parent) is not scope):  # a frame's own: dm_control's name
                return f"{parent.prefixed_identifier(prefix_root)}{name}/"
        return None if name is None else prefix + name

    def get_attribute_xml_string(self, attribute_name: str,
                                 prefix_root: NameScope | None = None, *,
                                 precision: int | None = None,
                                 zero_threshold: float = 0.0) -> str | None:
        """One attribute's value as the XML text writes it (``None`` when unset); names
        as seen from ``prefix_root``'s model (dm_control's ``get_attribute_xml_string``)."""
        attribute = self.spec.by_key.get(attribute_name) or self.spec.by_name.get(
            attribute_name)
        if attribute is None:
            raise _tree.unknown_attribute(self, attribute_name)
        if attribute.name not in _tree.values(self):
            return None
        return attribute_text(self, attribute.name, Format(precision, zero_threshold, False),
                              prefix_root)

    @property
    def attached_model(self) -> ModelRoot | None:
        """On an attachment frame, the model attached there."""
        return cast("ModelRoot | None", _tree.attached_at(self))

    # ------------------------------------------------------------------ look-ups

    def find(self, namespace: Namespace, identifier: str) -> Element | None:
        """The element named ``identifier`` in ``namespace`` inside this element, or ``None``.
        O(1) per scope: ``find("joint", "arm/elbow")`` looks in the model attached as
        ``arm``."""
        if not isinstance(identifier, str):  # pyright: ignore[reportUnnecessaryIsInstance]
            raise InvalidTypeError(f"{self.path}: find() identifier must be a str, got "
                                   f"{identifier!r}")
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
        if isinstance(self, _tree.ModelBase) and _tree.model_of(self) is self:
            return found
        return found if _is_inside(found, self) else None

    def enter_model(self, scope: str) -> ModelRoot | None:
        """The model attached under ``scope`` (``"arm"``, or ``"arm/gripper/"`` for one
        attached inside it) in this element's scope, or ``None``."""
        current: NameScope | None = _tree.scope_of(self)
        for part in (p for p in scope.split(SEPARATOR) if p):
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

    def paste(self, element: _tree.E, position: int | None = None) -> _tree.E:
        """Add a deep copy of ``element`` (from this model or another) as a child; return it.

        References inside the copied subtree point into the copy; references to elements
        outside it are kept by name, to resolve in this model. Names must be free here. From a
        model kept to some folders, the copy takes its files along, read (or refused) now under
        that model's rules, as ``include_copy`` does.
        """
        # a detached element (a deepcopy, a removed one) keeps its model's scope: its rules
        source = _tree.model_of(element) or _tree.scope_model(_tree.scope_of(element))
        target = _tree.model_of(self)
        confined = _tree.file_access(source).roots is not None  # else: paths kept, as ever
        files = {} if target is None or not confined else copied_files(element, source, target)
        clone = super().paste(element, position)
        if target is not None:
            rebase_files(clone, element, files, target)
        return clone

    # ------------------------------------------------------------------ export

    def to_xml_string(self, prefix_root: NameScope | None = None, self_only: bool = False,
                      pretty_print: bool = True, debug_context: object = None, *,
                      precision: int | None = None, zero_threshold: float = 0.0,
                      canonical: bool = False) -> str:
        """This element as MJCF text (a top-level section of a composed model holds the
        attached models' sections too).

        Numbers read from a file are written as they were read; values set in Python in the
        shortest form that reads back exactly. ``precision`` (significant digits; ``None``:
        the library's default, ``typed_mjcf._core.codecs.DEFAULT_PRECISION``, the shortest form),
        ``zero_threshold`` (smaller magnitudes are written as 0) and ``canonical=True`` (every
        number in the canonical form, as if set in Python) reformat every number. Names are
        written as seen from the element's model, or from ``prefix_root`` (a name scope);
        ``self_only`` writes the element's own tag only. ``debug_context`` is accepted for
        dm_control's signature and unused.
        """
        del debug_context
        return model_text(self, Format(precision, zero_threshold, canonical), bool(pretty_print),
                          names_from=prefix_root, self_only=bool(self_only))

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

    # ------------------------------------------------------------------ debug mode

    def get_init_stack(self) -> list[StackTraceEntry]:
        """Where this element was made, in dm_control's debug mode (empty otherwise)."""
        return init_stack(self)

    def get_last_modified_stacks_for_all_attributes(self) -> dict[str, list[StackTraceEntry]]:
        """Where each attribute (by XML name) was last set, in dm_control's debug mode."""
        return attribute_stacks(self, tuple(self.spec.attributes))

    # ------------------------------------------------------------------ defaults

    def commit_defaults(self, attributes: Iterable[str] | None = None) -> None:
        """Write the values the default classes give this element into it (only
        ``attributes``, when given): it then says what MuJoCo uses without its classes."""
        commit_defaults(self, attributes)


class Attachable(_tree.Element):
    """What elements a model can be attached at have (bodies, the world, sites, the root)."""

    __slots__ = ()

    def attach(self, model: ModelRoot) -> Element:
        """Attach ``model`` here; return its attachment frame (a ``<body>``).

        Args:
            model: the model to attach; it stays its own object, its names scoped ``<its name>/...`` here (``find("joint", "arm/elbow")``) and in the exported XML; its ``detach()`` undoes the attachment.
        """
        return cast("Element", attach(self, model))  # the generated classes say: a Body

    def attach_model(self, model: ModelRoot) -> Element:
        """Another name for :meth:`attach`."""
        return self.attach(model)


# What a model's pictures take as its camera and its keyframe: the generated root class says
# (its Camera and Key). Taken, never given: a root is a bare ModelRoot, which takes them by
# name only.
if TYPE_CHECKING:
    _Camera_contra = _TypeVar("_Camera_contra", bound=_tree.Element, contravariant=True, default=Never)
    _Key_contra = _TypeVar("_Key_contra", bound=_tree.Element, contravariant=True, default=Never)
else:
    _Camera_contra = TypeVar("_Camera_contra", bound=_tree.Element, contravariant=True)
    _Key_contra = TypeVar("_Key_contra", bound=_tree.Element, contravariant=True)


class ModelRoot(Element, _tree.ModelBase, Generic[_Camera_contra, _Key_contra]):
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
        unset; a setting both give differently is an error unless ``override_attributes``.
        The copies keep naming their files, which this model is given in memory; from a model
        kept to some folders, every one is read (or refused) now, under that model's rules."""
        include_copy(self, other, override_attributes)

    def iter_exported(self) -> Iterator[Element]:
        """Every element of the composed model, in the order the exported XML has them:
        attached models' bodies inside their frames, their other sections after ours."""
        return (cast(Element, e) for e in _tree.iter_composed(self, True))

    def get_assets(self, *, flat: bool = False) -> dict[str, bytes]:
        """The files the model uses, by the names its VFS export gives them: each file's own
        name, except where two different files share a base name (``torso/base_link.stl``
        and ``gripper/base_link.stl``): those keep their folders (``assets/torso/base_link.stl``
        under ``meshdir="assets"``), which ``mujoco.MjSpec.from_string(xml, assets=...)``
        holds apart. MuJoCo's dict route, ``MjModel.from_xml_string(xml, assets)``, finds
        files by base name alone and cannot hold both: ``flat=True`` gives that form and
        raises :class:`~typed_mjcf.errors.ExportError` naming both files of such a pair."""
        return get_assets(self, flat=flat)

    def validate(self) -> list[Finding]:
        """What MuJoCo's grammar forbids beyond single values: presence constraints, required
        attributes and children, references that name nothing, unused default classes, ...
        Each finding names the element path and the rule; warnings don't stop compile()."""
        return validate(self)

    def compile(self, limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjModel:
        """Validate, then compile with MuJoCo (assets passed through a virtual file system).

        Raises ``ValidationError`` listing every error ``validate()`` finds, or
        ``CompileError`` with MuJoCo's message and the path of the element it concerns, or
        naming the element that takes what MuJoCo would allocate past ``limits``."""
        return compile_model(self, limits)

    def to_spec(self, limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjSpec:
        """This model as a ``mujoco.MjSpec``; ``CompileError`` naming the element that takes
        what MuJoCo would allocate past ``limits`` (as :meth:`compile`)."""
        return to_spec(self, limits)

    # ------------------------------------------------------------------ pictures

    def render(self, camera: str | _Camera_contra | FreeView | None = None, *, width: int = 640,
               height: int = 480, time: float = 0.0, keyframe: str | int | _Key_contra | None = None,
               views: tuple[str, ...] | list[str] | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> RgbImage:
        """A picture of the model: a ``height`` x ``width`` x 3 array of ``uint8`` RGB.

        The size is given by keyword (``render(width=320, height=240)``): both are ``int``,
        so no checker would catch them swapped. (``Physics.render`` keeps dm_control's
        positional ``height, width``.)
        ``camera``: ``None`` frames the whole model as MuJoCo's viewer does (from the
        model's centre and extent); a camera of the model by name or element; or a
        ``FreeView`` (azimuth, elevation, distance, lookat). The pose is the model's
        ``qpos0``, or ``keyframe`` (a key's name, index or element), after ``time`` seconds
        of simulation from it. ``views`` (names of the presets ``front``, ``side``,
        ``top``, ``iso``, or of the model's cameras, which win) makes a contact sheet of
        labelled views instead, the whole ``width`` x ``height``. Renders offscreen
        (EGL, else OSMesa, unless ``MUJOCO_GL`` says otherwise); ``RenderError`` says what
        to install when no OpenGL back end works. ``limits`` bounds the simulation steps,
        the offscreen buffer and the compile (``RenderError``/``CompileError`` past them).
        """
        return cast("RgbImage", render(self, camera, width=width, height=height, time=time,
                                       keyframe=keyframe, views=views, limits=limits))

    def render_png(self, path: str | os.PathLike[str],
                   camera: str | _Camera_contra | FreeView | None = None, *, width: int = 640,
                   height: int = 480, time: float = 0.0, keyframe: str | int | _Key_contra | None = None,
                   views: tuple[str, ...] | list[str] | None = None,
                   limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> None:
        """Write ``render()``'s picture to ``path`` as a PNG file (the size by keyword)."""
        render_png(self, path, camera, width=width, height=height, time=time,
                   keyframe=keyframe, views=views, limits=limits)

    def _repr_png_(self) -> bytes | None:
        """The picture notebooks show (``None``, the text, if it cannot be made)."""
        return repr_png(self)

    def _repr_mimebundle_(self, include: object = None,
                          exclude: object = None) -> dict[str, str | bytes]:
        """IPython's display: the picture with the MJCF a click away, rendered once
        (``typed_mjcf.set_notebook_display("xml")`` shows the MJCF only)."""
        del include, exclude
        return repr_mimebundle(self)

    if TYPE_CHECKING:
        def __copy__(self) -> Self: ...


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
    if not isinstance(namespace, str):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"a namespace must be a str, got {namespace!r}; namespaces: "
                               f"{', '.join(sorted(known))}")
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
