"""``dm_control.mjcf.parser``: typed-mjcf's loaders, which here read any file a model names, as
dm_control's do, unless given ``files=``. Only these (and ``dm_control.mjcf``'s, the same
functions) read anywhere: ``typed_mjcf.from_path`` and the other loaders of the typed API keep
a model to its folder, switch or not."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Final, ParamSpec, TypeVar

from typed_mjcf import io
from typed_mjcf._core.access import FileAccess

_P = ParamSpec("_P")
_R = TypeVar("_R")
_ANYWHERE: Final = FileAccess(anywhere=True)


def _reading_anywhere(load: Callable[_P, _R]) -> Callable[_P, _R]:
    """``load`` with ``files=FileAccess(anywhere=True)`` unless another is given."""

    @functools.wraps(load)
    def loader(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        if kwargs.get("files") is None:
            kwargs["files"] = _ANYWHERE
        return load(*args, **kwargs)

    return loader


from_file = _reading_anywhere(io.from_file)
from_path = _reading_anywhere(io.from_path)
from_xml_string = _reading_anywhere(io.from_xml_string)
from_zip = _reading_anywhere(io.from_zip)

__all__ = ["from_file", "from_path", "from_xml_string", "from_zip"]
