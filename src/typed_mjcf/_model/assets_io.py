"""Writing a model with its files into a folder, and the files for MuJoCo's VFS.

:func:`export_with_assets` writes only into its folder, each file atomically, and refuses to
replace a different file of the same name unless asked to. File names are flat and unique
(see :mod:`typed_mjcf._text.files`).
"""

from __future__ import annotations

import os
import re
import stat
import tempfile
import time

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import ExportError
from typed_mjcf._core.names import UNNAMED_MODEL
from typed_mjcf._core.signals import HeldSignals
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._model.write import collect
from typed_mjcf._text.files import (
    CollectedFiles,
    is_plain_file_name,
    safe_file_name,
    split_name,
    unique_name,
)

# A model's text for a folder of its own and the files it uses, written before the export
# (typed_mjcf._sim.text.vfs_text: what writing it needs is resolved in a layer above)
Written = tuple[str, CollectedFiles]


def model_files(model: ModelBase, written: Written,
                model_filename: str | None = None) -> dict[str, bytes]:
    """The files a folder export writes: the model's XML (``written``, named
    ``model_filename``, else after the model) last, after every file it uses."""
    xml, collected = written
    data = xml.encode("utf-8")
    if model_filename is None:
        stem = _tree.scope_of(model).name or UNNAMED_MODEL
        name = unique_name(safe_file_name(stem, ".xml"), data, collected)
    else:
        name = model_filename
    return {**collected.files, name: data}


def get_assets(model: ModelBase, *, flat: bool = False) -> dict[str, bytes]:
    """The files the model uses, by the names its VFS export gives them: each file's own
    name, except where two different files share a base name (``torso/base_link.stl`` and
    ``gripper/base_link.stl``): those keep their folders (the path below the model's folder,
    ``assets/torso/base_link.stl`` under ``meshdir="assets"``), as ``mujoco.MjSpec``'s
    ``assets`` holds them apart. MuJoCo's dict route, ``MjModel.from_xml_string(xml,
    assets)``, finds files by base name alone and cannot hold both: ``flat=True`` asks for
    that form, base names only, and raises :class:`ExportError` naming both files where
    the model has such a pair."""
    files = collect(model).files
    if not flat:
        return files
    by_base: dict[str, str] = {}
    for name in files:
        base = name.rsplit("/", 1)[-1]
        other = by_base.setdefault(base.casefold(), name)
        if other != name:
            raise ExportError(
                f"get_assets(flat=True): {other!r} and {name!r} are different files with one "
                f"base name, which MuJoCo's MjModel.from_xml_string(xml, assets) cannot hold "
                f"apart (it finds files by base name); use get_assets() with "
                f"mujoco.MjSpec.from_string(xml, assets=...), or compile()")
    return {name.rsplit("/", 1)[-1]: data for name, data in files.items()}


def _source_file(model: ModelBase) -> str | None:
    """The name of the ``.xml`` file the model was read from, if it was read from one."""
    sources = _tree.source_map(model)
    main = None if sources is None else sources.main
    name = os.path.basename(main) if isinstance(main, str) else ""
    return name if name.lower().endswith(".xml") and len(name) > len(".xml") else None


def export_with_assets(model: ModelBase, written: Written, directory: str,
                       model_filename: str | None = None, *, overwrite: bool = False,
                       after_source: bool = True) -> str:
    """Write the XML and its files (``written``) into ``directory``; return the XML's path.

    Without ``model_filename`` the XML is named after the file the model was read from
    (``after_source``), else after the model (``model=``), as dm_control names it.

    Only plain file names inside ``directory`` are written (the collected names are safe by
    construction; ``model_filename`` must be plain). Every file is checked before any is
    written: one already there with other contents (or that is not a regular file) is an
    :class:`ExportError` unless ``overwrite``; identical files are left untouched. Each file
    is written to a temporary file in ``directory`` and renamed over its name, so a reader
    never sees half a file; the model's XML is written last.
    """
    xml, collected = written
    if model_filename is None:
        source = _source_file(model) if after_source else None
        stem = (source[: -len(".xml")] if source is not None
                else _tree.scope_of(model).name or UNNAMED_MODEL)
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
        if not is_plain_path(file_name):
            raise ExportError(_unwritable(file_name, collected))
    write_files(directory, outputs, overwrite, "export_with_assets")
    return os.path.join(directory, name)


def is_plain_path(name: str) -> bool:
    """Whether ``name`` is plain file names joined by ``/`` (a file the model keeps apart
    from another of its base name keeps its folders)."""
    return all(is_plain_file_name(part) for part in name.split("/"))


def _unwritable(name: str, collected: CollectedFiles) -> str:
    """Why ``name`` is not written: the source names a file so (the text names it as the
    source does, so it cannot be written under another name)."""
    for _, element, attribute, value, used, _ in collected.uses:
        if used == name:
            return (f"{element.path}: {attribute.py_name}={value!r}: cannot export a file "
                    f"named {name!r}: expected a name file systems take everywhere (no "
                    f"characters Windows refuses, no leading dot or space); the text names "
                    f"the file as its source does, so rename the file and the attribute")
    return f"refusing to write {name!r}: not a plain file name"  # pragma: no cover


def _make_folders(directory: str, outputs: list[tuple[str, bytes]]) -> None:
    """The folders of the outputs kept apart by theirs, inside ``directory``: never
    through a link or over a file."""
    for file_name, _ in outputs:
        parts = file_name.split("/")[:-1]
        for count in range(1, len(parts) + 1):
            path = os.path.join(directory, *parts[:count])
            try:
                mode = os.lstat(path).st_mode
            except FileNotFoundError:
                try:
                    os.mkdir(path)
                except OSError as error:
                    raise ExportError(f"cannot create the folder {path}: "
                                      f"{error.strerror or error}") from error
                continue
            if not stat.S_ISDIR(mode):
                raise ExportError(f"cannot write into {path}: not a folder (or a link)")


def write_files(directory: str, outputs: list[tuple[str, bytes]], overwrite: bool,
                what: str) -> None:
    """Write ``outputs`` (plain file names, the last one the file that uses the others) into
    ``directory`` as one change: every file goes to a temporary file first, then each is
    renamed into place; if anything fails (or is interrupted) the files already renamed are
    put back as they were and no temporary file is left. Files already there with the same
    contents are left untouched; different ones (or links, or anything not a regular file)
    are refused unless ``overwrite``, and then replaced, never written through."""
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as error:
        raise ExportError(f"cannot create the folder {directory}: "
                          f"{error.strerror or error}") from error
    remove_stale_temporaries(directory)
    _make_folders(directory, outputs)
    pending = _changed_files(directory, outputs, overwrite, what)
    temporaries: list[str] = []
    done: list[tuple[str, str | None, bool]] = []  # (path, its old file kept as, existed)
    path = directory
    # SIGINT and SIGTERM are taken between files (a handler run just after a rename would
    # leave it unrecorded, and SIGTERM's default would leave the folder mixed): the export
    # is put back or finished whole, and the signal acts when the block ends.
    with HeldSignals() as held:
        try:
            for file_name, contents in pending:
                path = os.path.join(directory, file_name)
                temporaries.append(_write_temporary(directory, contents))
                held.check(what)
            for (file_name, contents), temporary in zip(pending, temporaries, strict=True):
                path = os.path.join(directory, file_name)
                existed = os.path.lexists(path)
                done.append((path, _put_in_place(temporary, path, contents, overwrite),
                             existed))
                held.check(what)
        except BaseException as error:
            _roll_back(done)
            if isinstance(error, FileExistsError):
                raise ExportError(f"{path} appeared while exporting and has other contents; "
                                  f"pass overwrite=True to replace it") from None
            if isinstance(error, OSError):
                raise ExportError(f"cannot write {path}: {error.strerror or error}") from error
            raise
        finally:
            for leftover in temporaries:
                _remove(leftover)
        for _, backup, _ in done:
            if backup is not None:
                _remove(backup)


_TEMPORARY = re.compile(r"\.typed-mjcf-(?:(\d+)-)?[^/\\]*\.tmp\Z")
_STALE_AFTER = 24 * 3600  # seconds; a temporary file of a process still running is this old


def remove_stale_temporaries(directory: str) -> None:
    """Remove the temporary files an export killed midway left in ``directory``: those of a
    process that is no longer running (their name holds its id), or older than a day."""
    try:
        names = os.listdir(directory)
    except OSError:
        return
    now = time.time()
    for name in names:
        match = _TEMPORARY.match(name)
        if match is None:
            continue
        path = os.path.join(directory, name)
        try:
            info = os.lstat(path)
        except OSError:
            continue
        if not stat.S_ISREG(info.st_mode):
            continue
        pid = match.group(1)
        if now - info.st_mtime > _STALE_AFTER or (pid is not None and not _running(int(pid))):
            _remove(path)


def _running(pid: int) -> bool:
    """Whether process ``pid`` runs (on Windows, where signal 0 would end it: assume so)."""
    if pid == os.getpid():
        return True
    if os.name == "nt":  # pragma: no cover
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, OSError):
        return True  # another user's process
    return True


def _remove(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def _changed_files(directory: str, outputs: list[tuple[str, bytes]], overwrite: bool,
                   what: str) -> list[tuple[str, bytes]]:
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
            f"{what} would replace {len(conflicts)} file(s) in {directory} that "
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


def _write_temporary(directory: str, contents: bytes) -> str:
    """``contents`` in a new temporary file in ``directory`` (named after this process, so a
    later export can tell it is stale), with a new file's usual permissions."""
    fd, temporary = tempfile.mkstemp(dir=directory, prefix=f".typed-mjcf-{os.getpid()}-",
                                     suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(contents)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, _file_mode())  # mkstemp makes it private (0o600)
    except BaseException:
        _remove(temporary)
        raise
    return temporary


def _put_in_place(temporary: str, path: str, contents: bytes, replace: bool) -> str | None:
    """Rename ``temporary`` to ``path``; return where the file it replaced is kept until the
    whole export is done (``None``: there was none, or it could not be kept).

    With ``replace=False`` a file that appeared meanwhile is not replaced
    (``FileExistsError``) unless it has the same contents.
    """
    if not replace:
        try:
            os.link(temporary, path)  # fails if the name is taken: no silent replacement
            return None
        except FileExistsError:
            if not _same_contents(path, contents):
                raise
            return None
        except OSError:  # no hard links on this file system
            if os.path.lexists(path) and not _same_contents(path, contents):
                raise FileExistsError(path) from None
    backup: str | None = None
    if os.path.lexists(path):
        backup = temporary.removesuffix(".tmp") + "-old.tmp"  # stale-looking if left
        try:
            os.link(path, backup, follow_symlinks=False)  # the old file, to put back on failure
        except OSError:
            backup = None
    try:
        os.replace(temporary, path)
    except BaseException:
        if backup is not None:
            _remove(backup)
        raise
    return backup


def _roll_back(done: list[tuple[str, str | None, bool]]) -> None:
    """Undo the renames of an export that failed: old files back, new ones removed."""
    for path, backup, existed in reversed(done):
        try:
            if backup is not None:
                os.replace(backup, path)
            elif not existed:
                os.unlink(path)
        except OSError:
            pass
