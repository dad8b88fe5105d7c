# Generated from src/typed_mjcf/_model/write.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""A whole model (or one element) as MJCF text: the writer, keyframes combined, and the
files renamed when the text is for a virtual file system or a folder of its own.

Writing is pure: what must be parsed or compiled first (the files a model uses, the
``<asset><model>`` files among them read and rewritten: :func:`files_to_collect`; the
compiled :func:`keyless_text` a composed model's keyframes are laid out by, when
:func:`needs_layout`) is resolved before the writer starts, in the simulation layer
(:mod:`typed_mjcf._sim.text`), and handed to :func:`element_text`.
"""
from __future__ import annotations
from collections.abc import Callable
from typing import TYPE_CHECKING, Final
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._text.export import FileNamer, Writer
from typed_mjcf._text.files import CollectedFiles, collect_files
import mujoco
NO_ATTRIBUTES: Final[frozenset[str]] = ...

def files_to_collect(element: Element, collected: CollectedFiles | None,
                     self_only: bool = False) -> CollectedFiles | None:
    """The files :func:`element_text` writes ``element`` with: ``collected``, else (under
    dm_control's behaviour, which writes every file by its flat name) the files of the
    outermost model, collected now (``<asset><model>`` files parsed)."""
    ...

def needs_layout(element: Element, self_only: bool = False) -> bool:
    """Whether writing ``element`` combines keyframes: it is a composed model (models are
    attached to it) and one of its parts has a keyframe."""
    ...

def keyless_text(model: ModelBase, fmt: Format, pretty_print: bool,
                 collected: CollectedFiles | None, names_from: NameScope | None = None) -> str:
    """A composed model's text without its keys, as :func:`element_text` writes it before
    combining them: what MuJoCo compiles to lay the keys out (files by the names of
    ``collected``, if given)."""
    ...

def element_text(element: Element, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
                 collected: CollectedFiles | None = None, names_from: NameScope | None = None,
                 self_only: bool = False, namer: Callable[[Writer], None] | None = None,
                 layout: mujoco.MjModel | None = None) -> str:
    """The XML text of ``element`` and its subtree (attached models included: a top-level
    section of a composed model holds the attached models' too); with ``collected``, every
    file by its flat name and no folder attributes; names as seen from ``names_from``;
    only the element's own tag with ``self_only``; ``namer`` may give unnamed elements
    names for this text (in the writer's ``given_names``) before it is written; ``layout``
    is the compiled :func:`keyless_text` of a composed model whose keyframes are combined
    (:func:`needs_layout`). Only writes: the files and the layout are resolved before."""
    ...

def collect(model: ModelBase) -> CollectedFiles:
    """Every file the model uses, by a flat unique name."""
    ...

def attribute_text(element: Element, name: str, fmt: Format,
                   names_from: NameScope | None = None) -> str | None:
    """The text the XML gives ``element``'s attribute ``name`` (an XML name), if set."""
    ...

def rewrite_model_file(owner: ModelBase, path: str, contents: bytes, collected: CollectedFiles,
                       models: tuple[str, ...]) -> bytes | None:
    """An MJCF file the model uses (an ``<asset><model>``), rewritten to find its own files
    among ``collected``: MuJoCo resolves them against its own folder and ``<compiler>``, and
    in a virtual file system they get flat names like the main model's. It reads files as
    ``owner`` may (the same folders, the same files in memory). ``None`` when it is not MJCF
    the library reads (see :func:`~typed_mjcf._text.files.collect_files`)."""
    ...
