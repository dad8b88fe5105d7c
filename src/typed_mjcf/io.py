"""Reading and writing models: MJCF text and files, MuJoCo specs, files with their assets.

Reading is safe for models from anywhere: see :class:`ParseLimits` for what it refuses and
how to raise its bounds. Every failure is a :class:`~typed_mjcf.ParseError`.
"""

from __future__ import annotations

import os
from typing import IO, TYPE_CHECKING, cast

from typed_mjcf._assets_io import export_with_assets as export
from typed_mjcf._bridge import spec_to_xml
from typed_mjcf._parse import DEFAULT_LIMITS, ParseLimits, parse_path, parse_text
from typed_mjcf._tree import ModelBase
from typed_mjcf.errors import InvalidTypeError, ParseError

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._generated.elements import RootElement


def _typed(model: ModelBase) -> RootElement:
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


def from_xml_string(xml: str | bytes, *, base_dir: str | os.PathLike[str] | None = None,
                    source: str | None = None, limits: ParseLimits | None = None) -> RootElement:
    """Parse MJCF text. ``base_dir`` is where relative files and includes are found (the
    current directory if not given); ``source`` names the text in error messages; ``limits``
    raises (or lowers) the bounds on size, depth and element count (see :class:`ParseLimits`).
    """
    folder = _folder(base_dir, "base_dir")
    return _typed(parse_text(xml, base_dir=folder, source=source, limits=_limits(limits)))


def from_path(path: str | os.PathLike[str], *, limits: ParseLimits | None = None) -> RootElement:
    """Parse an MJCF file; relative files and includes resolve against its folder."""
    file = _folder(path, "path")
    if file is None:
        raise InvalidTypeError("path must be a path (str or os.PathLike), got None")
    return _typed(parse_path(file, limits=_limits(limits)))


def from_file(file: IO[str] | IO[bytes], *, base_dir: str | os.PathLike[str] | None = None,
              limits: ParseLimits | None = None) -> RootElement:
    """Parse MJCF from an open file object (text or binary). Relative files and includes
    resolve against ``base_dir``, else the file's folder if it has a name."""
    limits = _limits(limits)
    name = getattr(file, "name", None)
    source = name if isinstance(name, str) else None
    if base_dir is None and source is not None:
        base_dir = os.path.dirname(os.path.abspath(source))
    read: object = getattr(file, "read", None)
    if not callable(read):
        raise InvalidTypeError(f"from_file needs an open file, got {type(file).__name__}")
    try:
        data = _read_all(file, limits.max_bytes)
    except (OSError, ValueError) as error:  # UnicodeDecodeError is a ValueError
        if isinstance(error, InvalidTypeError):
            raise
        raise ParseError(f"cannot read the file: {error}", source) from None
    return from_xml_string(data, base_dir=base_dir, source=source, limits=limits)


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
    return from_xml_string(xml, base_dir=folder if isinstance(folder, str) and folder else None)


def export_with_assets(model: ModelBase, directory: str | os.PathLike[str],
                       model_filename: str | None = None, *, overwrite: bool = False) -> str:
    """Write the model's XML and every file it uses into ``directory``; return the XML's path.

    Files are written only inside ``directory``, under flat names (names that would reach
    elsewhere, e.g. with ``..`` or a path separator, are made safe), each atomically
    (a temporary file, then a rename). A file already there with the same contents is left
    as it is; one with different contents is an :class:`~typed_mjcf.ExportError` unless
    ``overwrite=True``, and then nothing is written.
    """
    folder = _folder(directory, "directory")
    if folder is None:
        raise InvalidTypeError("directory must be a path (str or os.PathLike), got None")
    if model_filename is not None and not isinstance(model_filename, str):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"model_filename must be a str, got {type(model_filename).__name__}")
    if not isinstance(overwrite, bool):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"overwrite must be a bool, got {type(overwrite).__name__}")
    return export(model, folder, model_filename, overwrite=overwrite)


__all__ = ["ParseLimits", "export_with_assets", "from_file", "from_path", "from_spec",
           "from_xml_string"]
