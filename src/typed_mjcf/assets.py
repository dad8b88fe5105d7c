"""In-memory assets: file contents given as bytes rather than as a path on disk."""

from __future__ import annotations

import hashlib
import os

from typed_mjcf._core.errors import FileReadError, InvalidTypeError, InvalidValueError


class Asset:
    """File contents held in memory, usable wherever MJCF takes a file.

    ``extension`` (e.g. ``".stl"``) tells MuJoCo the format; ``name`` (optional) is the file
    name stem used when the model is exported with its assets.
    """

    __slots__ = ("contents", "digest", "extension", "name")

    contents: bytes
    extension: str
    name: str | None
    digest: str  # SHA-1 of the contents

    def __init__(self, contents: bytes | str, extension: str, name: str | None = None) -> None:
        if isinstance(contents, str):
            try:
                contents = contents.encode("utf-8")
            except UnicodeEncodeError as error:  # a lone surrogate
                raise InvalidValueError(f"Asset contents: {error}") from None
        elif isinstance(contents, bytearray | memoryview):
            contents = bytes(contents)
        if not isinstance(contents, bytes):  # pyright: ignore[reportUnnecessaryIsInstance]
            raise InvalidTypeError(
                f"Asset contents must be bytes or str, got {type(contents).__name__}")
        _check_part("extension", extension, allow_none=False)
        _check_part("name", name, allow_none=True)
        if not extension.startswith("."):
            extension = "." + extension
        self.contents = contents
        self.extension = extension
        self.name = name
        self.digest = hashlib.sha1(contents).hexdigest()

    @classmethod
    def from_path(cls, path: str | os.PathLike[str]) -> Asset:
        """Load a file's contents into memory (:class:`~typed_mjcf.FileReadError` if it
        cannot be read)."""
        fspath = getattr(path, "__fspath__", None)  # whatever the static type said
        name: object = path if isinstance(path, str) else fspath() if callable(fspath) else None
        if not isinstance(name, str):
            raise InvalidTypeError(f"Asset.from_path needs a path (str or os.PathLike[str]), "
                                   f"got {type(path).__name__}")
        path = name
        stem, extension = os.path.splitext(os.path.basename(path))
        try:
            with open(path, "rb") as f:
                return cls(f.read(), extension, stem)
        except OSError as error:
            raise FileReadError(f"cannot read the file: {error.strerror or error}",
                                path) from None

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, Asset) and other.digest == self.digest
                and other.extension == self.extension)

    def __hash__(self) -> int:
        return hash((self.digest, self.extension))

    def __repr__(self) -> str:
        label = f"{self.name}{self.extension}" if self.name else self.extension
        return f"Asset({label!r}, {len(self.contents)} bytes, sha1={self.digest[:10]})"


def _check_part(what: str, value: object, *, allow_none: bool) -> None:
    """Refuse an extension or name that is not a string (the export makes any string a safe
    file name)."""
    if value is None and allow_none:
        return
    if not isinstance(value, str):
        expected = "a str or None" if allow_none else "a str"
        raise InvalidTypeError(f"Asset {what} must be {expected}, got {value!r}")
