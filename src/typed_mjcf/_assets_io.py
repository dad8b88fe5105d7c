"""Writing a model with its files into a folder, and the files for MuJoCo's VFS.

:func:`export_with_assets` writes only into its folder, each file atomically, and refuses to
replace a different file of the same name unless asked to. File names are flat and unique
(see :mod:`typed_mjcf._files`).
"""

from __future__ import annotations

import os
import stat
import tempfile

from typed_mjcf import _tree
from typed_mjcf._files import is_plain_file_name, safe_file_name, split_name, unique_name
from typed_mjcf._names import UNNAMED_MODEL
from typed_mjcf._tree import ModelBase
from typed_mjcf._write import collect, vfs_text
from typed_mjcf.errors import ExportError


def model_files(model: ModelBase, model_filename: str | None = None) -> dict[str, bytes]:
    """The files a folder export writes: the model's XML (named ``model_filename``, else
    after the model) last, after every file it uses."""
    xml, collected = vfs_text(model)
    data = xml.encode("utf-8")
    if model_filename is None:
        stem = _tree.scope_of(model).name or UNNAMED_MODEL
        name = unique_name(safe_file_name(stem, ".xml"), data, collected)
    else:
        name = model_filename
    return {**collected.files, name: data}


def get_assets(model: ModelBase) -> dict[str, bytes]:
    """The files the model uses, by the names its VFS export gives them."""
    return collect(model).files


def export_with_assets(model: ModelBase, directory: str, model_filename: str | None = None,
                       *, overwrite: bool = False) -> str:
    """Write the XML and its files into ``directory``; return the XML's path.

    Only plain file names inside ``directory`` are written (the collected names are safe by
    construction; ``model_filename`` must be plain). Every file is checked before any is
    written: one already there with other contents (or that is not a regular file) is an
    :class:`ExportError` unless ``overwrite``; identical files are left untouched. Each file
    is written to a temporary file in ``directory`` and renamed over its name, so a reader
    never sees half a file; the model's XML is written last.
    """
    xml, collected = vfs_text(model)
    if model_filename is None:
        stem = _tree.scope_of(model).name or UNNAMED_MODEL
        name = unique_name(safe_file_name(stem, ".xml"), xml.encode("utf-8"), collected)
    else:
        name = model_filename
        if not name.lower().endswith(".xml"):
            raise ExportError(f"the model's file name must end with '.xml', got {name!r}")
        if not is_plain_file_name(name):
            raise ExportError(f"model_filename must be a plain file name (no folders, no "
                              f"leading dot, no characters file systems refuse), got {name!r}; "
                              f"e.g. {safe_file_name(*split_name(name))!r}")
        if name.casefold() in collected.folded:
            raise ExportError(f"model_filename {name!r} is also the name of a file the model "
                              f"uses ({collected.folded[name.casefold()]!r}); choose another")
    outputs = [*collected.files.items(), (name, xml.encode("utf-8"))]
    for file_name, _ in outputs:
        if not is_plain_file_name(file_name):  # pragma: no cover - names are made safe
            raise ExportError(f"refusing to write {file_name!r}: not a plain file name")
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as error:
        raise ExportError(f"cannot create the folder {directory}: "
                          f"{error.strerror or error}") from error
    pending = _changed_files(directory, outputs, overwrite)
    for file_name, contents in pending:
        path = os.path.join(directory, file_name)
        try:
            _write_atomically(path, contents, replace=overwrite)
        except FileExistsError:
            raise ExportError(f"{path} appeared while exporting and has other contents; "
                              f"pass overwrite=True to replace it") from None
        except OSError as error:
            raise ExportError(f"cannot write {path}: {error.strerror or error}") from error
    return os.path.join(directory, name)


def _changed_files(directory: str, outputs: list[tuple[str, bytes]],
                   overwrite: bool) -> list[tuple[str, bytes]]:
    """The outputs whose file is missing or differs; refuses replacing files that differ
    (unless ``overwrite``) and anything that is not a regular file."""
    pending: list[tuple[str, bytes]] = []
    conflicts: list[str] = []
    for file_name, contents in outputs:
        path = os.path.join(directory, file_name)
        try:
            mode = os.lstat(path).st_mode
        except FileNotFoundError:
            pending.append((file_name, contents))
            continue
        except OSError as error:
            raise ExportError(f"cannot check {path}: {error.strerror or error}") from error
        if stat.S_ISDIR(mode):
            raise ExportError(f"cannot write {path}: a folder of that name is in the way")
        if stat.S_ISREG(mode) and _same_contents(path, contents):
            continue
        if not overwrite:
            kind = "" if stat.S_ISREG(mode) else (
                " (a symbolic link)" if stat.S_ISLNK(mode) else " (not a regular file)")
            conflicts.append(file_name + kind)
        pending.append((file_name, contents))
    if conflicts:
        raise ExportError(
            f"export_with_assets would replace {len(conflicts)} file(s) in {directory} that "
            f"differ from what the model needs: {', '.join(conflicts)}; nothing was written. "
            f"Pass overwrite=True to replace them, or export into another folder")
    return pending


def _same_contents(path: str, contents: bytes) -> bool:
    try:
        if os.path.getsize(path) != len(contents):
            return False
        with open(path, "rb") as f:
            return f.read() == contents
    except OSError:
        return False


def _file_mode() -> int:
    """The permissions ``open()`` would give a new file (``0o666`` less the umask)."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("Umask:"):
                    return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    return 0o644


def _write_atomically(path: str, contents: bytes, *, replace: bool = True) -> None:
    """Write ``path`` through a temporary file in its folder, renamed into place.

    With ``replace=False`` the rename does not replace a file that appeared meanwhile
    (``FileExistsError``) unless it has the same contents.
    """
    folder = os.path.dirname(path)
    fd, temporary = tempfile.mkstemp(dir=folder, prefix=".typed-mjcf-", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(contents)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, _file_mode())  # mkstemp makes it private (0o600)
        if replace:
            os.replace(temporary, path)
            return
        try:
            os.link(temporary, path)  # fails if the name is taken: no silent replacement
        except FileExistsError:
            if not _same_contents(path, contents):
                raise
        except OSError:  # no hard links on this file system
            if os.path.lexists(path) and not _same_contents(path, contents):
                raise FileExistsError(path) from None
            os.replace(temporary, path)
    finally:
        if os.path.lexists(temporary):
            os.unlink(temporary)
