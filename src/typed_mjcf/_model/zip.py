"""Models in zip archives: reading one (the MJCF file and the files it uses) and writing a
model with its files, as dm_control's ``from_zip`` and ``export_with_assets_as_zip`` do.

An archive is read lazily: the model's text is inflated with the text limit checked while
inflating, and every other entry only when the model reads it (an include, a mesh), with
:attr:`FileAccess.max_bytes` checked while inflating. An archive's defects (a bad checksum,
an encrypted entry, an unknown compression) are :class:`~typed_mjcf.ParseError`\\ s naming the
archive and the entry.
"""

from __future__ import annotations

import io
import os
import zipfile
import zlib
from typing import IO, TypeVar, cast, overload

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.access import Confinement
from typed_mjcf._core.errors import FileAccessError, FileReadError, InvalidTypeError, ParseError
from typed_mjcf._core.names import UNNAMED_MODEL
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._model.assets_io import Written, model_files, write_files
from typed_mjcf._text.files import safe_file_name
from typed_mjcf._text.parse import ParseLimits, read_bounded

_T = TypeVar("_T")

# What zipfile and zlib raise for a damaged, encrypted or unsupported entry.
_ENTRY_ERRORS = (zipfile.BadZipFile, zipfile.LargeZipFile, RuntimeError, NotImplementedError,
                 zlib.error, EOFError, OSError, ValueError)


class ArchiveFiles(dict[str, bytes]):
    """An archive's files by their path relative to the model's, inflated when first read.

    Only entries read are held (the dict's own items); the archive itself is held compressed.
    Read entries through :meth:`get` (as the readers do); iterating gives those read so far.
    """

    def __init__(self, data: bytes, source: str, folder: str, skip: str, budget: int) -> None:
        super().__init__()
        self._data, self._source, self._budget = data, source, budget
        self._used = 0  # bytes inflated so far
        self._entries: dict[str, zipfile.ZipInfo] = {}
        with _open(data, source) as archive:
            for info in archive.infolist():  # a later duplicate of a name wins, as in zipfile
                if not info.is_dir() and info.filename != skip:
                    self._entries[os.path.relpath(info.filename, folder or ".")] = info

    @overload
    def get(self, key: str, default: None = None, /) -> bytes | None: ...
    @overload
    def get(self, key: str, default: bytes, /) -> bytes: ...
    @overload
    def get(self, key: str, default: _T, /) -> bytes | _T: ...

    def get(self, key: str, default: object = None, /) -> object:
        """The entry ``key``, inflated if it was not yet (``default`` if there is none)."""
        found = super().get(key)
        if found is not None:
            return found
        info = self._entries.get(key)
        if info is None:
            return default
        with _open(self._data, self._source) as archive:
            data = _inflate(archive, info, self._source, self._budget - self._used,
                            "FileAccess.max_bytes", "files=typed_mjcf.FileAccess(max_bytes=...)")
        self._used += len(data)
        self[key] = data
        return data

    def __copy__(self) -> ArchiveFiles:
        clone = ArchiveFiles.__new__(ArchiveFiles)
        clone.update(self)
        clone._data, clone._source, clone._budget = self._data, self._source, self._budget
        clone._used, clone._entries = self._used, self._entries
        return clone


def _open(data: bytes, source: str) -> zipfile.ZipFile:
    try:
        return zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, OSError, ValueError, EOFError) as error:
        raise ParseError(f"not a zip archive: {error}", source) from None


def _inflate(archive: zipfile.ZipFile, info: zipfile.ZipInfo, source: str, limit: int,
             name: str, hint: str) -> bytes:
    """An entry's bytes, inflated in chunks and refused as soon as they pass ``limit``."""
    if info.file_size > limit:
        raise FileAccessError(f"{info.filename}: the entry inflates to {info.file_size} bytes, "
                              f"more than the {max(limit, 0)} allowed ({name}); pass {hint} to "
                              f"read more", source)
    try:
        with archive.open(info) as entry:
            data = read_bounded(entry.read, max(limit, 0))
    except _ENTRY_ERRORS as error:
        raise ParseError(f"{info.filename}: cannot read the entry: "
                         f"{type(error).__name__}: {error}", source) from None
    if len(data) > limit:  # the header's size was wrong
        raise FileAccessError(f"{info.filename}: the entry inflates to more than the {limit} "
                              f"bytes allowed ({name}); pass {hint} to read more", source)
    return data


def read_zip(path: str | os.PathLike[str] | IO[bytes], model_file: str, limits: ParseLimits,
             confinement: Confinement) -> tuple[bytes, ArchiveFiles, str]:
    """The MJCF text in an archive, the other files (inflated when first read) by their path
    relative to it, and a name for messages. An archive with several MJCF files must name
    one ``model_file``."""
    source = os.fspath(path) if isinstance(path, str | os.PathLike) else "<zip>"
    if not isinstance(path, str | os.PathLike) and not callable(getattr(path, "read", None)):
        raise InvalidTypeError(f"from_zip needs a path or an open binary file, got "
                               f"{type(path).__name__}")
    try:
        if isinstance(path, str | os.PathLike):
            with open(os.fspath(path), "rb") as f:
                data = f.read()
        else:
            read = cast(object, path.read())  # a file-like object may return anything
            if not isinstance(read, bytes):
                raise ParseError(f"the archive's read() gave {type(read).__name__}, not bytes",
                                 source)
            data = read
    except FileNotFoundError as error:
        raise FileReadError(f"cannot read the archive: {error.strerror}", source) from None
    except (OSError, ValueError) as error:
        raise FileReadError(f"cannot read the archive: {error}", source) from None
    with _open(data, source) as archive:
        names = [i.filename for i in archive.infolist() if not i.is_dir()]
        models = list(dict.fromkeys(n for n in names if n.lower().endswith(".xml")))
        if not models:
            raise ParseError("the archive holds no MJCF (.xml) file", source)
        if len(models) > 1:
            chosen = [n for n in models if os.path.basename(n) == model_file]
            if not chosen:
                raise ParseError(f"the archive holds several .xml files ({', '.join(models)}) "
                                 f"and none named {model_file!r}", source)
            models = chosen
        main = models[0]
        text = _inflate(archive, archive.getinfo(main), source, limits.max_bytes,
                        "ParseLimits.max_bytes", "limits=typed_mjcf.ParseLimits(max_bytes=...)")
    files = ArchiveFiles(data, source, os.path.dirname(main), main, confinement.max_bytes)
    return text, files, f"{source}:{main}"


def use_archive_files(model: ModelBase, files: ArchiveFiles) -> None:
    """Let ``model`` read its files from the archive (on demand) rather than a copy."""
    _tree.set_memory_files(model, files)


def write_zip(model: ModelBase, written: Written, directory: str,
              model_name: str | None = None, *, overwrite: bool = False) -> str:
    """Write ``model`` and its files (``written``) into ``directory/<name>.zip``, each under ``<name>/``
    (as dm_control writes it); return the archive's path. Written as the folder export
    writes a file: atomically, never through a link, never over a different file unless
    ``overwrite``."""
    name = model_name or _tree.scope_of(model).name or UNNAMED_MODEL
    stem = safe_file_name(name)
    files = model_files(model, written, f"{stem}.xml")
    buffer = io.BytesIO()
    # Fixed dates, so the same model makes the same archive (and an export can tell).
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for file_name, contents in files.items():
            info = zipfile.ZipInfo(f"{stem}/{file_name}", date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            archive.writestr(info, contents)
    write_files(directory, [(f"{stem}.zip", buffer.getvalue())], overwrite,
                "export_with_assets_as_zip")
    return os.path.join(directory, f"{stem}.zip")
