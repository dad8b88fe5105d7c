"""``dm_control.mjcf.namescope``."""

from __future__ import annotations

from typed_mjcf._core.names import NameScope

__all__ = ["NameScope"]
