"""Which files a model may read, and reading one safely.

A model read from a file (or from text with a folder) may read the files it names (includes,
meshes, textures, skins, height fields, ``<model>`` assets) only inside its own folder, with
symbolic links resolved: a link inside the folder that points outside is outside. The caller
widens (or narrows) that with a :class:`FileAccess`. A model from a zip archive reads only
the archive's files. A model built in Python reads the files its author names.

Reading never blocks or runs away: only regular files are read (not a FIFO, a device such as
``/dev/zero``, a folder), and never more than the bytes the limit leaves.

The file opened is the file checked (:func:`open_confined`, the one way a model's file is
opened): the path is resolved and checked, then opened folder by folder from the allowed
folder's descriptor (``os.open`` with ``dir_fd``) without following any link, so a link swapped
into the path meanwhile is met, not followed; the path is then resolved and checked again.
Where ``os.open`` takes no ``dir_fd`` (Windows), the resolved path is opened without following
its last component only.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import BinaryIO, Final, cast

from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError

_HINT: Final = ("pass files=typed_mjcf.FileAccess(roots=[...]) to the loader to allow a folder, "
                "or FileAccess(anywhere=True) for a model you trust")


@dataclass(frozen=True, slots=True)
class FileAccess:
    """Where a model read from MJCF may read the files it names.

    ``roots``
        More folders whose files may be read (symbolic links in them resolved too).
    ``model_folder``
        Whether the model's own folder may be read (default ``True``): the folder of the file
        it was read from, else the ``model_dir`` given with its text, else the current folder.
        ``False`` with no ``roots``: only the files given in memory (``assets=``).
    ``anywhere``
        Read any file (``False`` by default): for a model whose source you trust.
    ``max_bytes``
        The most bytes the model's files may hold together, counted each time they are read
        (``get_assets()``, ``compile()``, an export, the includes of one load), and the most a
        zip archive's entries may inflate to (1 GiB).

    ``typed_mjcf.from_path(path, files=typed_mjcf.FileAccess(roots=["/data/meshes"]))`` reads
    the model's folder and ``/data/meshes``.
    """

    roots: Sequence[str | os.PathLike[str]] = field(default=())
    model_folder: bool = True
    anywhere: bool = False
    max_bytes: int = 1 << 30

    def __post_init__(self) -> None:
        roots = cast(object, self.roots)
        if isinstance(roots, str | bytes | os.PathLike) or not isinstance(roots, tuple | list):
            raise InvalidTypeError(f"FileAccess.roots must be a list of folders, got {roots!r}")
        folders: list[str] = []
        for root in cast("tuple[object, ...] | list[object]", roots):
            fspath: object = getattr(root, "__fspath__", None)
            folder: object = fspath() if callable(fspath) else root
            if not isinstance(folder, str) or not folder:
                raise InvalidTypeError(f"FileAccess.roots holds {root!r}, not a folder path")
            folders.append(os.path.abspath(folder))
        object.__setattr__(self, "roots", tuple(folders))  # frozen: normalised once, here
        for name in ("model_folder", "anywhere"):
            flag: object = getattr(self, name)
            if not isinstance(flag, bool):
                raise InvalidTypeError(f"FileAccess.{name} must be a bool, got {flag!r}")
        check_count("FileAccess.max_bytes", self.max_bytes)



def check_count(name: str, value: object) -> None:
    """A setting that is a whole number of at least 1 (a bool is not one): one error naming
    ``name`` otherwise."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise InvalidTypeError(f"{name} must be an int, got {value!r}")
    if value < 1:
        raise InvalidValueError(f"{name} must be at least 1, got {value!r}")

DEFAULT_ACCESS: Final = FileAccess()


@dataclass(frozen=True, slots=True)
class Confinement:
    """A :class:`FileAccess` made concrete for one model: the real folders it may read
    (``None``: anywhere), how messages name them, and the byte limit."""

    roots: tuple[str, ...] | None
    where: str
    max_bytes: int = DEFAULT_ACCESS.max_bytes
    hint: str = _HINT

    def resolve(self, path: str) -> tuple[str, str] | str | None:
        """``path`` resolved and the allowed folder holding it, or why it may not be read
        (``None``: anywhere)."""
        if self.roots is None:
            return None
        real = _real(path)
        if not self.roots:
            return f"not among {self.where}; {self.hint}"
        if real is None:
            return f"{path!r} is not a path a file can have (a NUL character?)"
        for root in self.roots:
            if _inside(real, root):
                return real, root
        shown = path if real == path else f"{path} (really {real})"
        return f"{shown} is outside {self.where}; {self.hint}"


ANYWHERE: Final = Confinement(None, "anywhere")


def confine(access: FileAccess, folder: str | None) -> Confinement:
    """``access`` for a model whose own folder is ``folder`` (``None``: the current folder)."""
    if access.anywhere:
        return Confinement(None, "anywhere", access.max_bytes)
    roots: list[str] = []
    names: list[str] = []
    if access.model_folder:
        own = os.path.abspath(folder or os.curdir)
        roots.append(_real(own) or own)
        names.append(f"the model's folder {own}")
    for given in access.roots:  # absolute str already (see FileAccess)
        root = os.fspath(given)
        roots.append(_real(root) or root)
        names.append(root)
    where = " and ".join(names) if names else "the files given with the model (it reads none from disk)"
    if len(names) > 1:
        where = "the folders the model may read: " + ", ".join(names)
    return Confinement(tuple(roots), where, access.max_bytes)


def only_given(what: str, max_bytes: int = DEFAULT_ACCESS.max_bytes) -> Confinement:
    """No file on disk: only what was given with the model (``what`` names it)."""
    return Confinement((), f"the files of {what}", max_bytes,
                       "a model read from an archive reads only the archive's files")


class Refused(Exception):
    """A file that may not be read (callers turn it into the library's error)."""


def read_file(path: str, confinement: Confinement, limit: int) -> bytes:
    """The bytes of the regular file at ``path``, if ``confinement`` allows it and it holds
    at most ``limit`` bytes. Raises :class:`Refused` (not allowed, too large) or ``OSError``."""
    with open_confined(path, confinement) as file:
        size = os.fstat(file.fileno()).st_size
        if size > limit:
            raise Refused(too_large(size, limit))
        data = file.read(limit + 1)  # the file may grow while it is read
    if len(data) > limit:
        raise Refused(too_large(len(data), limit))
    return data


_NOFOLLOW: Final = getattr(os, "O_NOFOLLOW", 0)
_CLOEXEC: Final = getattr(os, "O_CLOEXEC", 0)
_FILE_FLAGS: Final = (os.O_RDONLY | _NOFOLLOW | getattr(os, "O_NONBLOCK", 0) | _CLOEXEC
                      | getattr(os, "O_BINARY", 0))  # a FIFO must not block the open
_FOLDER_FLAGS: Final = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | _NOFOLLOW | _CLOEXEC
# Whether a path can be opened folder by folder without following links (POSIX; not Windows)
WALKS: Final = (os.open in os.supports_dir_fd and bool(_NOFOLLOW)
                and hasattr(os, "O_DIRECTORY"))
_RESOLUTIONS: Final = 8  # how often a path that changes while it is opened is resolved again


def open_confined(path: str, confinement: Confinement) -> BinaryIO:
    """The regular file at ``path`` opened for reading, if ``confinement`` allows it:
    ``Refused`` if not, ``OSError`` if it cannot be read. The file opened is the one checked
    (see the module docstring); a path whose links keep changing is an ``OSError``."""
    # A walk that meets no link opens the path's real file: no need to resolve it first
    # (a stat per folder); a link met is resolved and checked below.
    direct = _plainly_inside(path, confinement.roots) if WALKS else None
    if direct is not None:
        fd = _walk(*direct)
        if fd is not None:
            return _regular(fd)
    last: str | None = None
    for _ in range(_RESOLUTIONS):
        found = confinement.resolve(path)
        if isinstance(found, str):
            raise Refused(found)
        if found is None or not WALKS:
            return open_regular(path)
        real, root = found
        if real == last:  # resolved alike, yet a link is in the way: it leads in a loop
            raise OSError(errno.ELOOP, "a symbolic link that leads in a loop")
        fd = _walk(root, os.path.relpath(real, root))
        if fd is not None:
            return _regular(fd)
        last = real  # a link was met where the path had none: resolve and check again
    raise OSError(errno.ELOOP, "its folders or links kept changing while it was opened")


def _plainly_inside(path: str, roots: tuple[str, ...] | None) -> tuple[str, str] | None:
    """The allowed folder ``path`` is written inside of and the rest of ``path``, when
    ``path`` is absolute and normal (no ``..``, ``.`` or NUL): then ``path`` is its own real
    path if no link is on the way (the roots are real paths already)."""
    if (not roots or "\0" in path or not os.path.isabs(path)
            or os.path.normpath(path) != path):
        return None
    for root in roots:
        folder = root if root.endswith(os.sep) else root + os.sep
        if path.startswith(folder):
            return root, path[len(folder):]
    return None


def _walk(root: str, relative: str) -> int | None:
    """``relative`` opened under the folder ``root`` one name at a time, following no link:
    a descriptor, or ``None`` when a symbolic link is met (the path changed)."""
    parts = [part for part in relative.split(os.sep) if part not in ("", os.curdir)]
    if not parts:  # the allowed folder itself
        raise OSError(errno.EISDIR, "it is a folder")
    folder = os.open(root, _FOLDER_FLAGS)
    try:
        for index, part in enumerate(parts):
            last = index == len(parts) - 1
            try:
                fd = os.open(part, _FILE_FLAGS if last else _FOLDER_FLAGS, dir_fd=folder)
            except OSError as error:
                if error.errno in (errno.ELOOP, errno.ENOTDIR, errno.EMLINK) and _is_link(
                        part, folder):
                    return None
                raise
            os.close(folder)
            folder = fd
        return folder
    except BaseException:
        os.close(folder)
        raise


def _is_link(name: str, folder: int) -> bool:
    try:
        return stat.S_ISLNK(os.stat(name, dir_fd=folder, follow_symlinks=False).st_mode)
    except OSError:
        return False


def open_regular(path: str) -> BinaryIO:
    """``path`` opened for reading if it is a regular file (``OSError`` otherwise): opening
    does not block (a FIFO), and a link put in place of its last component after ``path``
    was resolved is not followed (for files read anywhere; see :func:`open_confined`)."""
    # Most paths end in no link: opened as given (the kernel resolves the folders as
    # realpath would, without a stat per folder); a link at the end is resolved first.
    try:
        return _regular(os.open(path, _FILE_FLAGS))
    except OSError as error:
        if error.errno != errno.ELOOP:
            raise
    except ValueError:  # an embedded NUL
        raise OSError(errno.EINVAL, "not a valid path") from None
    real = _real(path)
    if real is None:
        raise OSError(errno.EINVAL, "not a valid path")
    try:
        fd = os.open(real, _FILE_FLAGS)
    except OSError as error:
        if error.errno == errno.ELOOP:
            raise OSError(errno.ELOOP, "a symbolic link that leads in a loop") from None
        raise
    return _regular(fd)


def _regular(fd: int) -> BinaryIO:
    """The open file ``fd`` if it is a regular file (closed, ``OSError`` otherwise)."""
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):  # a FIFO or /dev/zero would never end
            raise OSError(errno.EISDIR if stat.S_ISDIR(mode) else errno.EINVAL,
                          "it is a folder" if stat.S_ISDIR(mode) else "not a regular file")
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def too_large(size: int, limit: int) -> str:
    return (f"{size} bytes, more than the {limit} left of the limit on the bytes of a model's "
            f"files (FileAccess.max_bytes); pass files=typed_mjcf.FileAccess(max_bytes=...) to "
            f"the loader to read more")


def _real(path: str) -> str | None:
    """``path`` absolute with every symbolic link resolved (``None``: not a path at all)."""
    try:
        return os.path.realpath(path)
    except (ValueError, OSError):  # an embedded NUL; a link loop on some platforms
        return None


def _inside(path: str, folder: str) -> bool:
    try:
        return os.path.commonpath([path, folder]) == folder
    except ValueError:  # another drive (Windows), or relative and absolute mixed
        return False
