"""``dm_control.mjcf.copier``: ``Copier(source).copy_into(destination)`` copies a model's
contents into another, as ``include_copy`` does."""

from __future__ import annotations

from typed_mjcf._base import ModelRoot


class Copier:
    """Copies the contents of ``source`` (a model) into other models."""

    def __init__(self, source: ModelRoot) -> None:
        self._source = source

    def copy_into(self, destination: ModelRoot, override_attributes: bool = False) -> None:
        """Merge a copy of the source's contents into ``destination``."""
        destination.include_copy(self._source, override_attributes)
