# Generated from src/typed_mjcf/_base.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The public base classes of the generated classes: :class:`Element` and :class:`ModelRoot`.

They put the features (export, composition, defaults, validation, the MuJoCo bridge) on the
core tree as methods, so that users meet one object; each method is a thin call into its
feature module.
"""
from __future__ import annotations
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING, Final, Generic, Never, NoReturn, Self, TypeVar, cast
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.debuginfo import StackTraceEntry, attribute_stacks, init_stack
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._model.resource_limits import (
    DEFAULT_COMPILE_LIMITS,
    DEFAULT_RENDER_LIMITS,
    CompileLimits,
    RenderLimits,
)
from typed_mjcf._model.validate import Finding, validate
from typed_mjcf._sim.preview import FreeView, render, render_png
import os
import mujoco
from typing_extensions import TypeVar as _TypeVar
from typed_mjcf._generated import Namespace
from typed_mjcf.types import RgbImage, XmlElement

class Element(_tree.Element):
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""
    @property
    def root(self) -> ModelRoot:
        """The model this element belongs to."""
        ...
    @property
    def parent(self) -> Element | None:
        """The parent element; ``None`` for a model's root or a removed element."""
        ...
    def get_children(self, tag: str | None = None) -> list[Element]:
        """The children, in document order (only those with ``tag`` if given). An
        attachment frame's include the attached model's bodies (and the rest of its world
        body); a top-level section of a composed model, the attached models' sections'.

        With ``once_only_children_by_tag``, a once-only child's tag gives that child itself
        (``None`` if it does not exist), as dm_control's ``get_children`` does; with
        ``eager_children``, the once-only children that are not on demand are among all
        children (dm_control makes them with their parent)."""
        ...
    def all_children(self) -> list[Element]:
        """dm_control's name for ``get_children()``."""
        ...
    def iter_elements(self) -> Iterator[Element]:
        """This element and all its descendants, in document order (attached models are
        not included: see ``find_all``)."""
        ...
    @property
    def namescope(self) -> NameScope:
        """The name scope this element's name lives in (its model's)."""
        ...
    @property
    def full_identifier(self) -> str | None:
        """The name this element has in the outermost model it is part of (its scope's
        prefix and its name, ``arm/elbow``); ``None`` for an unnamed element (with
        ``Behaviour.unnamed_identifiers``, dm_control's name for it: ``//unnamed_geom_0``)."""
        ...
    def prefixed_identifier(self, prefix_root: NameScope | None) -> str | None:
        """The element's name as seen from the model of scope ``prefix_root`` (the
        outermost model when ``None``), as :attr:`full_identifier` gives it."""
        ...
    def get_attribute_xml_string(self, attribute_name: str,
                                 prefix_root: NameScope | None = None, *,
                                 precision: int | None = None,
                                 zero_threshold: float = 0.0) -> str | None:
        """One attribute's value as the XML text writes it (``None`` when unset); names
        as seen from ``prefix_root``'s model (dm_control's ``get_attribute_xml_string``)."""
        ...
    @property
    def attached_model(self) -> ModelRoot | None:
        """On an attachment frame, the model attached there."""
        ...
    def find(self, namespace: Namespace, identifier: str) -> Element | None:
        """The element named ``identifier`` in ``namespace`` inside this element, or ``None``.
        O(1) per scope: ``find("joint", "arm/elbow")`` looks in the model attached as
        ``arm``."""
        ...
    def enter_model(self, scope: str) -> ModelRoot | None:
        """The model attached under ``scope`` (``"arm"``, or ``"arm/gripper/"`` for one
        attached inside it) in this element's scope, or ``None``."""
        ...
    def find_all(self, namespace: Namespace, immediate_children_only: bool = False,
                 exclude_attachments: bool = False) -> list[Element]:
        """Every element of ``namespace`` inside this element (named or not), attached
        models' included unless ``exclude_attachments``, in the order the exported XML has
        them; only this element's children with ``immediate_children_only``."""
        ...
    def remove(self, affect_attachments: bool = False) -> None:
        """Remove this element (and its subtree) from its parent; references to the removed
        elements read as ``None`` from now on. A section that attached models merge into
        (``<option>``, ``<contact>``, ...) is removed only with ``affect_attachments=True``,
        which removes it in every attached model too."""
        ...
    def paste(self, element: _tree.E, position: int | None = None) -> _tree.E:
        """Add a deep copy of ``element`` (from this model or another) as a child; return it.

        References inside the copied subtree point into the copy; references to elements
        outside it are kept by name, to resolve in this model. Names must be free here. From a
        model kept to some folders, the copy takes its files along, read (or refused) now under
        that model's rules, as ``include_copy`` does.
        """
        ...
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
        ...
    def to_xml(self, prefix_root: NameScope | None = None, debug_context: object = None, *,
               precision: int | None = None, zero_threshold: float = 0.0,
               canonical: bool = False) -> XmlElement:
        """This element as an lxml element."""
        ...
    def __str__(self) -> str:
        """The element's own tag, e.g. ``<joint type="hinge"/>`` (``...`` for children)."""
        ...
    def get_init_stack(self) -> list[StackTraceEntry]:
        """Where this element was made, in dm_control's debug mode (empty otherwise)."""
        ...
    def get_last_modified_stacks_for_all_attributes(self) -> dict[str, list[StackTraceEntry]]:
        """Where each attribute (by XML name) was last set, in dm_control's debug mode."""
        ...
    def commit_defaults(self, attributes: Iterable[str] | None = None) -> None:
        """Write the values the default classes give this element into it (only
        ``attributes``, when given): it then says what MuJoCo uses without its classes."""
        ...

class Attachable(_tree.Element):
    """What elements a model can be attached at have (bodies, the world, sites, the root)."""
    def attach(self, model: ModelRoot) -> Element:
        """Attach ``model`` here; return its attachment frame (a ``<body>``).

        Args:
            model: the model to attach; it stays its own object, its names scoped ``<its name>/...`` here (``find("joint", "arm/elbow")``) and in the exported XML; its ``detach()`` undoes the attachment.
        """
        ...
    def attach_model(self, model: ModelRoot) -> Element:
        """Another name for :meth:`attach`."""
        ...
_Camera_contra = _TypeVar("_Camera_contra", bound=_tree.Element, contravariant=True, default=Never)
_Key_contra = _TypeVar("_Key_contra", bound=_tree.Element, contravariant=True, default=Never)

class ModelRoot(Element, _tree.ModelBase, Generic[_Camera_contra, _Key_contra]):
    """Behaviour of ``<mujoco>``, the root of a model. Use ``typed_mjcf.RootElement``."""
    @property
    def namespaces(self) -> frozenset[str]:
        """The identifier namespaces of the grammar (``body``, ``joint``, ``geom``, ...)."""
        ...
    @property
    def attachment_frame(self) -> Element | None:
        """Where this model is attached (its frame in the parent model), if it is."""
        ...
    @property
    def base_dir(self) -> str | None:
        """The directory relative file paths resolve against (the parsed file's folder)."""
        ...
    def detach(self) -> None:
        """Undo this model's attachment: its frame (and anything added to it) is removed."""
        ...
    @property
    def parent_model(self) -> ModelRoot | None:
        """The model this one is attached to, if it is."""
        ...
    @property
    def root_model(self) -> ModelRoot:
        """The outermost model this one is attached into (itself when not attached)."""
        ...
    def enter_scope(self, scope: str) -> ModelRoot | None:
        """The model attached under ``scope`` (``"arm"``, or ``"arm/gripper/"`` for one
        attached inside it), or ``None`` (dm_control's name for ``enter_model``)."""
        ...
    def resolve_references(self) -> None:
        """Link every reference held as a name that names an element now (a model read
        with ``resolve_references=False``, say)."""
        ...
    def include_copy(self, other: ModelRoot, override_attributes: bool = False) -> None:
        """Merge a copy of ``other``'s contents into this model (dm_control's
        ``include_copy``): its sections' children are copied in (references among them point
        at the copies), and its global settings are adopted where this model leaves them
        unset; a setting both give differently is an error unless ``override_attributes``.
        The copies keep naming their files, which this model is given in memory; from a model
        kept to some folders, every one is read (or refused) now, under that model's rules."""
        ...
    def iter_exported(self) -> Iterator[Element]:
        """Every element of the composed model, in the order the exported XML has them:
        attached models' bodies inside their frames, their other sections after ours."""
        ...
    def get_assets(self, *, flat: bool = False) -> dict[str, bytes]:
        """The files the model uses, by the names its VFS export gives them: each file's own
        name, except where two different files share a base name (``torso/base_link.stl``
        and ``gripper/base_link.stl``): those keep their folders (``assets/torso/base_link.stl``
        under ``meshdir="assets"``), which ``mujoco.MjSpec.from_string(xml, assets=...)``
        holds apart. MuJoCo's dict route, ``MjModel.from_xml_string(xml, assets)``, finds
        files by base name alone and cannot hold both: ``flat=True`` gives that form and
        raises :class:`~typed_mjcf.errors.ExportError` naming both files of such a pair."""
        ...
    def validate(self) -> list[Finding]:
        """What MuJoCo's grammar forbids beyond single values: presence constraints, required
        attributes and children, references that name nothing, unused default classes, ...
        Each finding names the element path and the rule; warnings don't stop compile()."""
        ...
    def compile(self, limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjModel:
        """Validate, then compile with MuJoCo (assets passed through a virtual file system).

        Raises ``ValidationError`` listing every error ``validate()`` finds, or
        ``CompileError`` with MuJoCo's message and the path of the element it concerns, or
        naming the element that takes what MuJoCo would allocate past ``limits``."""
        ...
    def to_spec(self, limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjSpec:
        """This model as a ``mujoco.MjSpec``; ``CompileError`` naming the element that takes
        what MuJoCo would allocate past ``limits`` (as :meth:`compile`)."""
        ...
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
        ...
    def render_png(self, path: str | os.PathLike[str],
                   camera: str | _Camera_contra | FreeView | None = None, *, width: int = 640,
                   height: int = 480, time: float = 0.0, keyframe: str | int | _Key_contra | None = None,
                   views: tuple[str, ...] | list[str] | None = None,
                   limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> None:
        """Write ``render()``'s picture to ``path`` as a PNG file (the size by keyword)."""
        ...
    def __copy__(self) -> Self: ...
ATTACHMENT_FRAME: Final = "attachment_frame"

def named_after_file(element: _tree.Element, namespace: str, name: str) -> _tree.Element | None:
    """An unnamed element of ``namespace`` (a mesh, a texture...) that MuJoCo names after the
    stem of its file, if one is named ``name`` that way."""
    ...
