# Generated from src/typed_mjcf/assets.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""In-memory assets: file contents given as bytes rather than as a path on disk."""
from __future__ import annotations
import os

class Asset:
    """File contents held in memory, usable wherever MJCF takes a file.

    ``extension`` (e.g. ``".stl"``) tells MuJoCo the format; ``name`` (optional) is the file
    name stem used when the model is exported with its assets.
    """
    contents: bytes
    extension: str
    name: str | None
    digest: str
    def __init__(self, contents: bytes | str, extension: str, name: str | None = None) -> None: ...
    @classmethod
    def from_path(cls, path: str | os.PathLike[str]) -> Asset:
        """Load a file's contents into memory (:class:`~typed_mjcf.FileReadError` if it
        cannot be read)."""
        ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __repr__(self) -> str: ...
