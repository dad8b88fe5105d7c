# Generated from src/typed_mjcf/_dmcompat/copier.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.copier``: ``Copier(source).copy_into(destination)`` copies a model's
contents into another, as ``include_copy`` does."""
from __future__ import annotations
from typed_mjcf._base import ModelRoot

class Copier:
    """Copies the contents of ``source`` (a model) into other models."""
    def __init__(self, source: ModelRoot) -> None: ...
    def copy_into(self, destination: ModelRoot, override_attributes: bool = False) -> None:
        """Merge a copy of the source's contents into ``destination``."""
        ...
