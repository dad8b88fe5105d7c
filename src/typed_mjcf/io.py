"""Reading and writing models: MJCF text and files, MuJoCo specs, files with their assets.

Reading is safe for models from anywhere: see :class:`ParseLimits` for what it refuses and
how to raise its bounds, and :class:`FileAccess` for the files a model may read (by default
only those in its own folder). Every failure is a :class:`~typed_mjcf.ParseError`.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import IO, TYPE_CHECKING, cast

from typed_mjcf._core.access import ANYWHERE, DEFAULT_ACCESS, FileAccess, confine, only_given
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.errors import InvalidTypeError, ParseError
from typed_mjcf._core.tree import COMPAT, ModelBase
from typed_mjcf._model.assets_io import export_with_assets as export
from typed_mjcf._model.zip import read_zip, use_archive_files, write_zip
from typed_mjcf._sim.bridge import spec_to_xml
from typed_mjcf._sim.text import vfs_text
from typed_mjcf._text.parse import DEFAULT_LIMITS, ParseLimits, ParseOptions, parse_path, parse_text

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._generated.elements import RootElement


def _typed(model: ModelBase) -> RootElement:
    if FLAGS.named_after_files:
        COMPAT.name_after_files(model)  # dm_control names unnamed meshes... after their files
    return cast("RootElement", model)


def _folder(base_dir: object, what: str) -> str | None:
    if base_dir is None or isinstance(base_dir, str):
        return base_dir
    fspath = getattr(base_dir, "__fspath__", None)
    folder: object = fspath() if callable(fspath) else None
    if not isinstance(folder, str):
        raise InvalidTypeError(f"{what} must be a path (str or os.PathLike[str]), "
                               f"got {type(base_dir).__name__}")
    return folder


def _model(model: object) -> ModelBase:
    """``model`` if it is a model's root, else the library's error."""
    if not isinstance(model, ModelBase):
        raise InvalidTypeError(f"mjcf_model must be a model (typed_mjcf.RootElement), got "
                               f"{type(model).__name__}")
    return model


def _options(assets: Mapping[str, bytes] | None, escape_separators: bool,
             resolve_references: bool) -> ParseOptions:
    if assets is not None and not isinstance(assets, Mapping):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"assets must map file names to bytes, got {type(assets).__name__}")
    return ParseOptions(dict(assets or {}), bool(escape_separators), bool(resolve_references))


def from_xml_string(xml_string: str | bytes, escape_separators: bool = False,
                    model_dir: str | os.PathLike[str] | None = None,
                    resolve_references: bool = True,
                    assets: Mapping[str, bytes] | None = None, *,
                    base_dir: str | os.PathLike[str] | None = None, source: str | None = None,
                    limits: ParseLimits | None = None,
                    files: FileAccess | None = None) -> RootElement:
    """Parse MJCF text.

    ``model_dir`` (or ``base_dir``) is where relative files and includes are found (the
    current directory if not given); ``assets`` gives file contents by the path the model
    writes (or the file's name), used before the disk; ``escape_separators`` escapes ``/`` in
    names as dm_control does (by default names keep their ``/``); ``resolve_references=False``
    keeps references as names until ``model.resolve_references()``. ``source`` names the text
    in error messages; ``limits`` raises (or lowers) the bounds on size, depth and element
    count (see :class:`ParseLimits`); ``files`` says which files the model may read, its
    includes and the files ``get_assets()``, ``compile()`` and the exports read (by default
    only inside ``model_dir``, else the current folder; see :class:`FileAccess`).
    """
    folder = _folder(base_dir if base_dir is not None else model_dir, "model_dir")
    return _typed(parse_text(xml_string, base_dir=folder, source=source,
                             limits=_limits(limits),
                             options=_options(assets, escape_separators, resolve_references),
                             access=_access(files)))


def from_path(path: str | os.PathLike[str], escape_separators: bool = False,
              resolve_references: bool = True, assets: Mapping[str, bytes] | None = None, *,
              limits: ParseLimits | None = None,
              files: FileAccess | None = None) -> RootElement:
    """Parse an MJCF file; relative files and includes resolve against its folder, and by
    default the model reads files only inside it (see :func:`from_xml_string` for the other
    arguments)."""
    file = _folder(path, "path")
    if file is None:
        raise InvalidTypeError("path must be a path (str or os.PathLike), got None")
    return _typed(parse_path(file, limits=_limits(limits),
                             options=_options(assets, escape_separators, resolve_references),
                             access=_access(files)))


def from_file(file: IO[str] | IO[bytes] | str | os.PathLike[str],
              escape_separators: bool = False,
              model_dir: str | os.PathLike[str] | None = None, resolve_references: bool = True,
              assets: Mapping[str, bytes] | None = None, *,
              base_dir: str | os.PathLike[str] | None = None,
              limits: ParseLimits | None = None,
              files: FileAccess | None = None) -> RootElement:
    """Parse MJCF from an open file object (text or binary), or a path. Relative files and
    includes resolve against ``model_dir``, else the file's folder if it has a name (see
    :func:`from_xml_string` for the other arguments)."""
    if isinstance(file, str | os.PathLike):
        return from_path(file, escape_separators, resolve_references, assets, limits=limits,
                         files=files)
    limits = _limits(limits)
    name = getattr(file, "name", None)
    source = name if isinstance(name, str) else None
    folder = base_dir if base_dir is not None else model_dir
    if folder is None and source is not None:
        folder = os.path.dirname(os.path.abspath(source))
    read: object = getattr(file, "read", None)
    if not callable(read):
        raise InvalidTypeError(f"from_file needs an open file or a path, got "
                               f"{type(file).__name__}")
    try:
        data = _read_all(file, limits.max_bytes)
    except (OSError, ValueError) as error:  # UnicodeDecodeError is a ValueError
        if isinstance(error, InvalidTypeError):
            raise
        raise ParseError(f"cannot read the file: {error}", source) from None
    return from_xml_string(data, escape_separators, None, resolve_references, assets,
                           base_dir=folder, source=source, limits=limits, files=files)


def from_zip(path: str | os.PathLike[str] | IO[bytes], model_file: str = "model.xml",
             escape_separators: bool = False, resolve_references: bool = True, *,
             limits: ParseLimits | None = None,
             files: FileAccess | None = None) -> RootElement:
    """Parse a model and its files from a zip archive (one MJCF file, or the one named
    ``model_file`` among several).

    The model reads its includes and files only from the archive (``files`` may name folders
    on disk it may read too: its ``roots``, or ``anywhere``; an archive has no folder of its
    own). Entries are inflated only when the model reads them, and never past the limits:
    the model's text past ``limits.max_bytes``, its other files past ``files.max_bytes``.
    """
    access = _access(files)
    limits = _limits(limits)
    source = os.fspath(path) if isinstance(path, str | os.PathLike) else "<zip>"
    confinement = confine(FileAccess(access.roots, False, access.anywhere, access.max_bytes),
                          None)
    if not access.roots and not access.anywhere:
        confinement = only_given(f"the archive {source}", access.max_bytes)
    xml, archive, name = read_zip(path, model_file, limits, confinement)
    model = parse_text(xml, source=name, limits=limits, access=confinement,
                       options=ParseOptions(archive, bool(escape_separators),
                                            bool(resolve_references)))
    use_archive_files(model, archive)
    return _typed(model)


def _read_all(file: IO[str] | IO[bytes], limit: int) -> str | bytes:
    """The file's contents, read in chunks until its end or until more than ``limit``
    characters are read (the parser then refuses the text as too long)."""
    texts: list[str] = []
    blobs: list[bytes] = []
    total = 0
    while total <= limit:
        chunk = cast(object, file.read(1 << 20))  # a file-like object may return anything
        if isinstance(chunk, str):
            texts.append(chunk)
        elif isinstance(chunk, bytes):
            blobs.append(chunk)
        else:
            raise InvalidTypeError(f"the file's read() gave {type(chunk).__name__}, "
                                   f"expected str or bytes")
        if not chunk:
            break
        total += len(chunk)
    if texts and blobs:
        raise InvalidTypeError("the file's read() gave both str and bytes")
    return "".join(texts) if texts else b"".join(blobs)


def _access(files: object) -> FileAccess:
    if files is None:  # dm_control's "anywhere" is its facade's (_dmcompat.parser), not ours
        return DEFAULT_ACCESS
    if not isinstance(files, FileAccess):
        raise InvalidTypeError(f"files must be a typed_mjcf.FileAccess, got {type(files).__name__}")
    return files


def _limits(limits: object) -> ParseLimits:
    if limits is None:
        return DEFAULT_LIMITS
    if not isinstance(limits, ParseLimits):
        raise InvalidTypeError(f"limits must be a typed_mjcf.ParseLimits, "
                               f"got {type(limits).__name__}")
    return limits


def from_spec(spec: mujoco.MjSpec) -> RootElement:
    """Read a ``mujoco.MjSpec`` back into typed elements."""
    xml = spec_to_xml(spec)
    # The spec's files are relative to the folder of the file it was read from (if any).
    folder: object = getattr(spec, "modelfiledir", None)
    # A spec is the caller's own object (MuJoCo read any file it names): no confinement.
    return _typed(parse_text(xml, base_dir=folder if isinstance(folder, str) and folder else None,
                             access=ANYWHERE))


def export_with_assets(mjcf_model: ModelBase, out_dir: str | os.PathLike[str],
                       out_file_name: str | None = None, *, overwrite: bool = False) -> str:
    """Write the model's XML and every file it uses into ``out_dir``; return the XML's path.

    The XML is named ``out_file_name`` (which must end in ``.xml``), else after the file the
    model was read from (``humanoid.xml`` stays ``humanoid.xml``), else after the model
    (``model=``; dm_control's ``export_with_assets`` always names it so).
    Files are written only inside ``out_dir``, under flat names (names that would reach
    elsewhere, e.g. with ``..`` or a path separator, are made safe), each atomically (a
    temporary file, then a rename). A file already there with the same contents is left as
    it is; one with different contents is an :class:`~typed_mjcf.ExportError` unless
    ``overwrite=True``, and then nothing is written.
    """
    return exported(mjcf_model, out_dir, out_file_name, overwrite, after_source=True)


def exported(mjcf_model: object, out_dir: object, out_file_name: object, overwrite: object,
             *, after_source: bool) -> str:
    """:func:`export_with_assets`, the arguments checked; the XML named after the source file
    (``after_source``) or the model when no name is given."""
    folder = _folder(out_dir, "out_dir")
    if folder is None:
        raise InvalidTypeError("out_dir must be a path (str or os.PathLike), got None")
    if out_file_name is not None and not isinstance(out_file_name, str):
        raise InvalidTypeError(f"out_file_name must be a str, got {type(out_file_name).__name__}")
    if not isinstance(overwrite, bool):
        raise InvalidTypeError(f"overwrite must be a bool, got {type(overwrite).__name__}")
    model = _model(mjcf_model)
    return export(model, vfs_text(model), folder, out_file_name, overwrite=overwrite,
                  after_source=after_source)


def export_with_assets_as_zip(mjcf_model: ModelBase, out_dir: str | os.PathLike[str],
                              model_name: str | None = None, *, overwrite: bool = False) -> str:
    """Write the model and every file it uses into ``out_dir/<model_name>.zip`` (a folder
    ``<model_name>/`` inside, as dm_control writes it); return the archive's path.

    Written as :func:`export_with_assets` writes a file: atomically (a temporary file, then a
    rename), never through a link, and an archive already there with other contents is an
    :class:`~typed_mjcf.ExportError` unless ``overwrite=True``.
    """
    folder = _folder(out_dir, "out_dir")
    if folder is None:
        raise InvalidTypeError("out_dir must be a path (str or os.PathLike), got None")
    if model_name is not None and not isinstance(model_name, str):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"model_name must be a str, got {type(model_name).__name__}")
    if not isinstance(overwrite, bool):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"overwrite must be a bool, got {type(overwrite).__name__}")
    model = _model(mjcf_model)
    return write_zip(model, vfs_text(model), folder, model_name, overwrite=overwrite)


__all__ = ["FileAccess", "ParseLimits", "export_with_assets", "export_with_assets_as_zip", "from_file",
           "from_path", "from_spec", "from_xml_string", "from_zip"]
