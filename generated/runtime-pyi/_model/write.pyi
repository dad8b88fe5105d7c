# Generated from src/typed_mjcf/_model/write.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""A whole model (or one element) as MJCF text: the writer, keyframes combined, and the
files renamed when the text is for a virtual file system or a folder of its own."""
from __future__ import annotations
from collections.abc import Callable
from typing import Final
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.names import NameScope
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._text.export import FileNamer, Writer
from typed_mjcf._text.files import CollectedFiles, collect_files
NO_ATTRIBUTES: Final[frozenset[str]] = ...

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
    ...

def collect(model: ModelBase) -> CollectedFiles:
    """Every file the model uses, by a flat unique name."""
    ...

def attribute_text(element: Element, name: str, fmt: Format,
                   names_from: NameScope | None = None) -> str | None:
    """The text the XML gives ``element``'s attribute ``name`` (an XML name), if set."""
    ...

def vfs_text(model: ModelBase, fmt: Format = DEFAULT_FORMAT, pretty_print: bool = True,
             namer: Callable[[Writer], None] | None = None,
             limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> tuple[str, CollectedFiles]:
    """The model's XML with every file by its flat name (and no folder attributes), and the
    files: what MuJoCo compiles from memory and what a folder export writes (``namer``,
    ``limits``: as for :func:`element_text`)."""
    ...

def rewrite_model_file(owner: ModelBase, path: str, contents: bytes, collected: CollectedFiles,
                       models: tuple[str, ...]) -> bytes | None:
    """An MJCF file the model uses (an ``<asset><model>``), rewritten to find its own files
    among ``collected``: MuJoCo resolves them against its own folder and ``<compiler>``, and
    in a virtual file system they get flat names like the main model's. It reads files as
    ``owner`` may (the same folders, the same files in memory). ``None`` when it is not MJCF
    the library reads (see :func:`~typed_mjcf._text.files.collect_files`)."""
    ...
