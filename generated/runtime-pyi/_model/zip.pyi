# Generated from src/typed_mjcf/_model/zip.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Models in zip archives: reading one (the MJCF file and the files it uses) and writing a
model with its files, as dm_control's ``from_zip`` and ``export_with_assets_as_zip`` do.

An archive is read lazily: the model's text is inflated with the text limit checked while
inflating, and every other entry only when the model reads it (an include, a mesh), with
:attr:`FileAccess.max_bytes` checked while inflating. An archive's defects (a bad checksum,
an encrypted entry, an unknown compression) are :class:`~typed_mjcf.ParseError`\\ s naming the
archive and the entry.
"""
from __future__ import annotations
import os
from typing import IO, TypeVar, cast, overload
from typed_mjcf._core.access import Confinement
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._model.assets_io import Written, model_files, write_files
from typed_mjcf._text.parse import ParseLimits, read_bounded
_T = TypeVar("_T")

class ArchiveFiles(dict[str, bytes]):
    """An archive's files by their path relative to the model's, inflated when first read.

    Only entries read are held (the dict's own items); the archive itself is held compressed.
    Read entries through :meth:`get` (as the readers do); iterating gives those read so far.
    """
    def __init__(self, data: bytes, source: str, folder: str, skip: str, budget: int) -> None: ...
    @overload
    def get(self, key: str, default: None = None, /) -> bytes | None:
        """The entry ``key``, inflated if it was not yet (``default`` if there is none)."""
        ...
    @overload
    def get(self, key: str, default: bytes, /) -> bytes:
        """The entry ``key``, inflated if it was not yet (``default`` if there is none)."""
        ...
    @overload
    def get(self, key: str, default: _T, /) -> bytes | _T:
        """The entry ``key``, inflated if it was not yet (``default`` if there is none)."""
        ...
    def __copy__(self) -> ArchiveFiles: ...

def read_zip(path: str | os.PathLike[str] | IO[bytes], model_file: str, limits: ParseLimits,
             confinement: Confinement) -> tuple[bytes, ArchiveFiles, str]:
    """The MJCF text in an archive, the other files (inflated when first read) by their path
    relative to it, and a name for messages. An archive with several MJCF files must name
    one ``model_file``."""
    ...

def use_archive_files(model: ModelBase, files: ArchiveFiles) -> None:
    """Let ``model`` read its files from the archive (on demand) rather than a copy."""
    ...

def write_zip(model: ModelBase, written: Written, directory: str,
              model_name: str | None = None, *, overwrite: bool = False) -> str:
    """Write ``model`` and its files (``written``) into ``directory/<name>.zip``, each under ``<name>/``
    (as dm_control writes it); return the archive's path. Written as the folder export
    writes a file: atomically, never through a link, never over a different file unless
    ``overwrite``."""
    ...
