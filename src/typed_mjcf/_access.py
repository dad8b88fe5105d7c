"""Which files a model may read, and reading one safely.

A model read from a file (or from text with a folder) may read the files it names (includes,
meshes, textures, skins, height fields, ``<model>`` assets) only inside its own folder, with
symbolic links resolved: a link inside the folder that points outside is outside. The caller
widens (or narrows) that with a :class:`FileAccess`. A model from a zip archive reads only
the archive's files. A model built in Python reads the files its author names.

Reading never blocks or runs away: only regular files are read (not a FIFO, a device such as
``/dev/zero``, a folder), through a descriptor opened without following a last-moment link,
and never more than the bytes the limit leaves.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import BinaryIO, Final, cast

from typed_mjcf.errors import InvalidTypeError, InvalidValueError

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

    def refusal(self, path: str) -> str | None:
        """Why ``path`` may not be read (``None``: it may)."""
        if self.roots is None:
            return None
        real = _real(path)
        if not self.roots:
            return f"not among {self.where}; {self.hint}"
        if real is None:
            return f"{path!r} is not a path a file can have (a NUL character?)"
        if any(_inside(real, root) for root in self.roots):
            return None
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
    reason = confinement.refusal(path)
    if reason is not None:
        raise Refused(reason)
    with open_regular(path) as file:
        size = os.fstat(file.fileno()).st_size
        if size > limit:
            raise Refused(too_large(size, limit))
        data = file.read(limit + 1)  # the file may grow while it is read
    if len(data) > limit:
        raise Refused(too_large(len(data), limit))
    return data


def open_regular(path: str) -> BinaryIO:
    """``path`` opened for reading if it is a regular file (``OSError`` otherwise): opening
    does not block (a FIFO), and a link put in place after ``path`` was resolved is not
    followed."""
    real = _real(path)
    if real is None:
        raise OSError(errno.EINVAL, "not a valid path")
    flags = (os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
             | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0))
    try:
        fd = os.open(real, flags)
    except OSError as error:
        if error.errno == errno.ELOOP:
            raise OSError(errno.ELOOP, "a symbolic link that leads in a loop") from None
        raise
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
