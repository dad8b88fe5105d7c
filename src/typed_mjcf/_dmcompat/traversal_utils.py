"""``dm_control.mjcf.traversal_utils``."""

from __future__ import annotations

from typed_mjcf._model.traversal import (
    commit_defaults,
    get_attachment_frame,
    get_frame_freejoint,
    get_frame_joints,
    get_freejoint,
)

__all__ = ["commit_defaults", "get_attachment_frame", "get_frame_freejoint",
           "get_frame_joints", "get_freejoint"]
