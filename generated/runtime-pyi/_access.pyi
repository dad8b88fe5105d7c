# Generated from src/typed_mjcf/_access.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
    def refusal(self, path: str) -> str | None:
        """Why ``path`` may not be read (``None``: it may)."""
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

def open_regular(path: str) -> BinaryIO:
    """``path`` opened for reading if it is a regular file (``OSError`` otherwise): opening
    does not block (a FIFO), and a link put in place after ``path`` was resolved is not
    followed."""
    ...

def too_large(size: int, limit: int) -> str: ...
