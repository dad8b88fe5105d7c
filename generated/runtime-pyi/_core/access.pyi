# Generated from src/typed_mjcf/_core/access.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import BinaryIO, Final, cast
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
    max_bytes: int = ...
    def __post_init__(self) -> None: ...

def check_count(name: str, value: object) -> None:
    """A setting that is a whole number of at least 1 (a bool is not one): one error naming
    ``name`` otherwise."""
    ...
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
        ...
ANYWHERE: Final = Confinement(None, "anywhere")

def confine(access: FileAccess, folder: str | None) -> Confinement:
    """``access`` for a model whose own folder is ``folder`` (``None``: the current folder)."""
    ...

def only_given(what: str, max_bytes: int = DEFAULT_ACCESS.max_bytes) -> Confinement:
    """No file on disk: only what was given with the model (``what`` names it)."""
    ...

class Refused(Exception):
    """A file that may not be read (callers turn it into the library's error)."""

def read_file(path: str, confinement: Confinement, limit: int) -> bytes:
    """The bytes of the regular file at ``path``, if ``confinement`` allows it and it holds
    at most ``limit`` bytes. Raises :class:`Refused` (not allowed, too large) or ``OSError``."""
    ...
_NOFOLLOW: Final = getattr(os, "O_NOFOLLOW", 0)
WALKS: Final = (os.open in os.supports_dir_fd and bool(_NOFOLLOW)
                and hasattr(os, "O_DIRECTORY"))

def open_confined(path: str, confinement: Confinement) -> BinaryIO:
    """The regular file at ``path`` opened for reading, if ``confinement`` allows it:
    ``Refused`` if not, ``OSError`` if it cannot be read. The file opened is the one checked
    (see the module docstring); a path whose links keep changing is an ``OSError``."""
    ...

def _walk(root: str, relative: str) -> int | None:
    """``relative`` opened under the folder ``root`` one name at a time, following no link:
    a descriptor, or ``None`` when a symbolic link is met (the path changed)."""
    ...

def open_regular(path: str) -> BinaryIO:
    """``path`` opened for reading if it is a regular file (``OSError`` otherwise): opening
    does not block (a FIFO), and a link put in place of its last component after ``path``
    was resolved is not followed (for files read anywhere; see :func:`open_confined`)."""
    ...

def too_large(size: int, limit: int) -> str: ...
