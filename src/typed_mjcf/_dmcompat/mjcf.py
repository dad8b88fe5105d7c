"""``dm_control.mjcf`` itself: its public names, each typed-mjcf's.

``mjcf.export_with_assets`` is the function, as in dm_control; any other name is looked up
in ``typed_mjcf`` when asked for, so ``mjcf.Physics`` is typed-mjcf's once it has one.
"""

from __future__ import annotations

import typed_mjcf._generated.elements as _elements
from typed_mjcf._base import Element
from typed_mjcf._dmcompat import (
    attribute,
    base,
    constants,
    copier,
    debugging,
    element,
    namescope,
    parser,
    physics,
    skin,
    traversal_utils,
)
from typed_mjcf._dmcompat.export_with_assets import export_with_assets
from typed_mjcf._dmcompat.parser import from_file, from_path, from_xml_string, from_zip
from typed_mjcf._model.traversal import (
    commit_defaults,
    get_attachment_frame,
    get_frame_freejoint,
    get_frame_joints,
    get_freejoint,
)
from typed_mjcf.assets import Asset
from typed_mjcf.io import export_with_assets_as_zip

PREFIX_SEPARATOR = constants.PREFIX_SEPARATOR
RootElement = _elements.RootElement

__all__ = [
    "PREFIX_SEPARATOR", "Asset", "Element", "RootElement", "attribute", "base", "commit_defaults",
    "constants", "copier", "debugging", "element", "export_with_assets",
    "export_with_assets_as_zip", "from_file", "from_path", "from_xml_string", "from_zip",
    "get_attachment_frame", "get_frame_freejoint", "get_frame_joints", "get_freejoint",
    "namescope", "parser", "physics", "skin", "traversal_utils",
]


def __getattr__(name: str) -> object:
    """Any other name is typed_mjcf's (``Physics`` once typed-mjcf has it)."""
    import typed_mjcf

    try:
        return getattr(typed_mjcf, name)
    except AttributeError:
        raise AttributeError(f"module 'dm_control.mjcf' (typed-mjcf) has no attribute "
                             f"{name!r}") from None
