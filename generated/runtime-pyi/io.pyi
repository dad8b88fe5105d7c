# Generated from src/typed_mjcf/io.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
from typed_mjcf._core.tree import COMPAT, ModelBase
from typed_mjcf._text.parse import DEFAULT_LIMITS, ParseLimits, ParseOptions, parse_path, parse_text
import mujoco
from typed_mjcf._generated.elements import RootElement

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
    ...

def from_path(path: str | os.PathLike[str], escape_separators: bool = False,
              resolve_references: bool = True, assets: Mapping[str, bytes] | None = None, *,
              limits: ParseLimits | None = None,
              files: FileAccess | None = None) -> RootElement:
    """Parse an MJCF file; relative files and includes resolve against its folder, and by
    default the model reads files only inside it (see :func:`from_xml_string` for the other
    arguments)."""
    ...

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
    ...

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
    ...

def from_spec(spec: mujoco.MjSpec) -> RootElement:
    """Read a ``mujoco.MjSpec`` back into typed elements."""
    ...

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
    ...

def exported(mjcf_model: object, out_dir: object, out_file_name: object, overwrite: object,
             *, after_source: bool) -> str:
    """:func:`export_with_assets`, the arguments checked; the XML named after the source file
    (``after_source``) or the model when no name is given."""
    ...

def export_with_assets_as_zip(mjcf_model: ModelBase, out_dir: str | os.PathLike[str],
                              model_name: str | None = None, *, overwrite: bool = False) -> str:
    """Write the model and every file it uses into ``out_dir/<model_name>.zip`` (a folder
    ``<model_name>/`` inside, as dm_control writes it); return the archive's path.

    Written as :func:`export_with_assets` writes a file: atomically (a temporary file, then a
    rename), never through a link, and an archive already there with other contents is an
    :class:`~typed_mjcf.ExportError` unless ``overwrite=True``.
    """
    ...
__all__ = ["FileAccess", "ParseLimits", "export_with_assets", "export_with_assets_as_zip", "from_file",
           "from_path", "from_spec", "from_xml_string", "from_zip"]
