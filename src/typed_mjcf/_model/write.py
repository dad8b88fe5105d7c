"""A whole model (or one element) as MJCF text: the writer, keyframes combined, and the
files renamed when the text is for a virtual file system or a folder of its own.

Writing is pure: what must be parsed or compiled first (the files a model uses, the
``<asset><model>`` files among them read and rewritten: :func:`files_to_collect`; the
compiled :func:`keyless_text` a composed model's keyframes are laid out by, when
:func:`needs_layout`) is resolved before the writer starts, in the simulation layer
(:mod:`typed_mjcf._sim.text`), and handed to :func:`element_text`.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import TYPE_CHECKING, Final

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.gc import collector_paused
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.keyframes import combine_keyframes, has_keyframes
from typed_mjcf._text.export import FileNamer, Writer
from typed_mjcf._text.files import CollectedFiles, collect_files
from typed_mjcf._text.parse import ParseOptions, is_model_text, parse_text
from typed_mjcf._text.xmltext import serialize

if TYPE_CHECKING:
    import mujoco

NO_ATTRIBUTES: Final[frozenset[str]] = frozenset()


def files_to_collect(element: Element, collected: CollectedFiles | None,
                     self_only: bool = False) -> CollectedFiles | None:
    """The files :func:`element_text` writes ``element`` with: ``collected``, else (under
    dm_control's behaviour, which writes every file by its flat name) the files of the
    outermost model, collected now (``<asset><model>`` files parsed)."""
    root = _tree.model_of(element)
    if root is not None:
        _tree.check_arrays(root)  # arrays edited in place (dm_control's behaviour)
        if collected is None and not self_only and FLAGS.hashed_file_names:
            collected = collect(_tree.scope_model(_tree.scope_of(root).outermost()))
    return collected


def needs_layout(element: Element, self_only: bool = False) -> bool:
    """Whether writing ``element`` combines keyframes: it is a composed model (models are
    attached to it) and one of its parts has a keyframe."""
    if self_only or not isinstance(element, ModelBase) or _tree.model_of(element) is not element:
        return False
    parts = _tree.attached_models(element)
    if not parts:
        return False
    pending = [element, *parts]
    while pending:
        part = pending.pop()
        pending += _tree.attached_models(part)
        if any(section.spec.compose == "keyframes" and _tree.children(section)
               for section in _tree.children(part)):
            return True
    return False


def keyless_text(model: ModelBase, fmt: Format, pretty_print: bool,
                 collected: CollectedFiles | None, names_from: NameScope | None = None) -> str:
    """A composed model's text without its keys, as :func:`element_text` writes it before
    combining them: what MuJoCo compiles to lay the keys out (files by the names of
    ``collected``, if given)."""
    file_namer = None if collected is None else collected.name_of
    skip = NO_ATTRIBUTES if collected is None else collected.directory_attributes
    with collector_paused():
        return serialize(Writer(model, fmt, file_namer, skip, names_from).model(model),
                         pretty_print)


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
    root = _tree.model_of(element)
    if root is not None:
        _tree.check_arrays(root)  # arrays edited in place (dm_control's behaviour)
    file_namer: FileNamer | None = None if collected is None else collected.name_of
    skip = NO_ATTRIBUTES if collected is None else collected.directory_attributes
    with collector_paused():  # an export makes no reference cycles, only short-lived text
        writer = Writer(element, fmt, file_namer, skip, names_from)
        if namer is not None:
            namer(writer)
        if self_only:
            return writer.start_tag(element)
        if not writer.composed:
            return writer.text(element, pretty_print)
        if isinstance(element, ModelBase) and root is element:
            node = writer.model(element)  # a composed model: attached models joined
            if has_keyframes(writer):
                if layout is None:
                    raise AssertionError(f"{element.path}: combining keyframes needs the "
                                         f"compiled layout (see needs_layout)")
                combine_keyframes(writer, node, layout)
            return serialize(node, pretty_print)
        if root is not None and element.parent is root:  # a section: attached ones join it
            node = Writer(root, fmt, file_namer, skip, names_from).model(root)
            section = next((n for n in node if n.tag == element.spec.tag), None)
            if section is not None:
                return serialize(section, pretty_print)
        return serialize(writer.element(element, None), pretty_print)


def collect(model: ModelBase) -> CollectedFiles:
    """Every file the model uses, by a flat unique name."""
    _tree.check_arrays(model)
    return collect_files(model, rewrite_model_file)


def attribute_text(element: Element, name: str, fmt: Format,
                   names_from: NameScope | None = None) -> str | None:
    """The text the XML gives ``element``'s attribute ``name`` (an XML name), if set."""
    return Writer(element, fmt, names_from=names_from).attributes(element).get(name)


def rewrite_model_file(owner: ModelBase, path: str, contents: bytes, collected: CollectedFiles,
                       models: tuple[str, ...]) -> bytes | None:
    """An MJCF file the model uses (an ``<asset><model>``), rewritten to find its own files
    among ``collected``: MuJoCo resolves them against its own folder and ``<compiler>``, and
    in a virtual file system they get flat names like the main model's. It reads files as
    ``owner`` may (the same folders, the same files in memory). ``None`` when it is not MJCF
    the library reads (see :func:`~typed_mjcf._text.files.collect_files`)."""
    if not is_model_text(contents):
        return None
    memory = _tree.memory_files(owner)
    submodel = parse_text(contents, base_dir=os.path.dirname(path), source=path,
                          options=ParseOptions(memory), access=_tree.file_access(owner))
    _tree.set_memory_files(submodel, memory)
    sub_collected = CollectedFiles(files=collected.files, folded=collected.folded,
                                   keys=collected.keys, readers=collected.readers,
                                   digests=collected.digests,
                                   bytes_read=collected.bytes_read)
    collect_files(submodel, rewrite_model_file, sub_collected, models)
    collected.bytes_read = sub_collected.bytes_read
    return element_text(submodel, DEFAULT_FORMAT, True, sub_collected).encode("utf-8")
