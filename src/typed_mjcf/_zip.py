"""Models in zip archives: reading one (the MJCF file and the files it uses) and writing a
model with its files, as dm_control's ``from_zip`` and ``export_with_assets_as_zip`` do."""

from __future__ import annotations

import io
import os
import zipfile
from typing import IO

from typed_mjcf import _tree
from typed_mjcf._assets_io import model_files
from typed_mjcf._files import safe_file_name
from typed_mjcf._names import UNNAMED_MODEL
from typed_mjcf._tree import ModelBase
from typed_mjcf.errors import ExportError, FileReadError, ParseError


def read_zip(path: str | os.PathLike[str] | IO[bytes],
             model_file: str = "model.xml") -> tuple[bytes, dict[str, bytes], str]:
    """The MJCF text in an archive, the other files by their path relative to it, and a
    name for messages. An archive with several MJCF files must name one ``model_file``."""
    source = os.fspath(path) if isinstance(path, str | os.PathLike) else "<zip>"
    try:
        archive = zipfile.ZipFile(path if not isinstance(path, os.PathLike) else os.fspath(path))
    except FileNotFoundError as error:
        raise FileReadError(f"cannot read the archive: {error.strerror}", source) from None
    except (zipfile.BadZipFile, OSError) as error:
        raise ParseError(f"not a zip archive: {error}", source) from None
    with archive:
        names = [n for n in archive.namelist() if not n.endswith("/")]
        models = [n for n in names if n.lower().endswith(".xml")]
        if not models:
            raise ParseError("the archive holds no MJCF (.xml) file", source)
        if len(models) > 1:
            chosen = [n for n in models if os.path.basename(n) == model_file]
            if not chosen:
                raise ParseError(f"the archive holds several .xml files ({', '.join(models)}) "
                                 f"and none named {model_file!r}", source)
            models = chosen
        main = models[0]
        folder = os.path.dirname(main)
        files = {os.path.relpath(n, folder or "."): archive.read(n) for n in names if n != main}
        return archive.read(main), files, f"{source}:{main}"


def write_zip(model: ModelBase, directory: str, model_name: str | None = None) -> str:
    """Write ``model`` and its files into ``directory/<name>.zip``, each under ``<name>/``
    (as dm_control writes it); return the archive's path."""
    name = model_name or _tree.scope_of(model).name or UNNAMED_MODEL
    stem = safe_file_name(name)
    files = model_files(model, f"{stem}.xml")
    try:
        os.makedirs(directory, exist_ok=True)
        path = os.path.join(directory, f"{stem}.zip")
        buffer = io.BytesIO()
        with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
            for file_name, contents in files.items():
                archive.writestr(f"{stem}/{file_name}", contents)
        with open(path, "wb") as out:
            out.write(buffer.getvalue())
    except OSError as error:
        raise ExportError(f"cannot write the archive into {directory}: "
                          f"{error.strerror or error}") from error
    return path
