"""A whole model (or one element) as MJCF text: the writer, keyframes combined, and the
files renamed when the text is for a virtual file system or a folder of its own."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Final

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.gc import collector_paused
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.keyframes import combine_keyframes, compile_layout, has_keyframes
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._model.validate import ensure_no_crash
from typed_mjcf._text.export import FileNamer, Writer
from typed_mjcf._text.files import CollectedFiles, collect_files
from typed_mjcf._text.parse import ParseOptions, is_model_text, parse_text
from typed_mjcf._text.xmltext import serialize

NO_ATTRIBUTES: Final[frozenset[str]] = frozenset()


def element_text(element: Element, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
                 collected: CollectedFiles | None = None, names_from: NameScope | None = None,
                 self_only: bool = False, namer: Callable[[Writer], None] | None = None,
                 limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> str:
    """The XML text of ``element`` and its subtree (attached models included: a top-level
    section of a composed model holds the attached models' too); with ``collected``, every
    file by its flat name and no folder attributes; names as seen from ``names_from``;
    only the element's own tag with ``self_only``; ``namer`` may give unnamed elements
    names for this text (in the writer's ``given_names``) before it is written; ``limits``
    bound the compile that lays out a composed model's keyframes."""
    root = _tree.model_of(element)
    if root is not None:
        _tree.check_arrays(root)  # arrays edited in place (dm_control's behaviour)
        if collected is None and not self_only and FLAGS.hashed_file_names:
            collected = collect(_tree.scope_model(_tree.scope_of(root).outermost()))
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
        root = _tree.model_of(element)
        if isinstance(element, ModelBase) and root is element:
            return _model_text(writer, element, collected, pretty_print, limits)
        if root is not None and element.parent is root:  # a section: attached ones join it
            node = Writer(root, fmt, file_namer, skip, names_from).model(root)
            section = next((n for n in node if n.tag == element.spec.tag), None)
            if section is not None:
                return serialize(section, pretty_print)
        return serialize(writer.element(element, None), pretty_print)


def _model_text(writer: Writer, element: ModelBase, collected: CollectedFiles | None,
                pretty_print: bool, limits: CompileLimits) -> str:
    """A composed model's text: attached models joined, keyframes combined."""
    with collector_paused():
        node = writer.model(element)
        if has_keyframes(writer):
            ensure_no_crash(element)  # MuJoCo compiles it below: nothing that crashes it,
            check_compile(element, limits)  # nor allocates past the limits
            if collected is None:  # the layout is compiled from memory: files by flat names
                collected = collect(element)
                layout = Writer(element, DEFAULT_FORMAT, collected.name_of,
                                collected.directory_attributes)
                layout_xml = serialize(layout.model(element), pretty_print=False)
            else:  # written as the text is, so MuJoCo's errors give the text's lines
                layout_xml = serialize(node, pretty_print)
            combine_keyframes(writer, node, compile_layout(layout_xml, collected.files))
        return serialize(node, pretty_print)


def collect(model: ModelBase) -> CollectedFiles:
    """Every file the model uses, by a flat unique name."""
    _tree.check_arrays(model)
    return collect_files(model, rewrite_model_file)


def attribute_text(element: Element, name: str, fmt: Format,
                   names_from: NameScope | None = None) -> str | None:
    """The text the XML gives ``element``'s attribute ``name`` (an XML name), if set."""
    return Writer(element, fmt, names_from=names_from).attributes(element).get(name)


def vfs_text(model: ModelBase, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
             namer: Callable[[Writer], None] | None = None,
             limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> tuple[str, CollectedFiles]:
    """The model's XML with every file by its flat name (and no folder attributes), and the
    files: what MuJoCo compiles from memory and what a folder export writes (``namer``,
    ``limits``: as for :func:`element_text`)."""
    collected = collect(model)
    return element_text(model, fmt, pretty_print, collected, namer=namer,
                        limits=limits), collected


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
