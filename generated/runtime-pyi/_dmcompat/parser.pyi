# Generated from src/typed_mjcf/_dmcompat/parser.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.parser``: typed-mjcf's loaders, which here read any file a model names, as
dm_control's do, unless given ``files=``. Only these (and ``dm_control.mjcf``'s, the same
functions) read anywhere: ``typed_mjcf.from_path`` and the other loaders of the typed API keep
a model to its folder, switch or not."""
from __future__ import annotations
from collections.abc import Callable
from typing import Final, ParamSpec, TypeVar
from typed_mjcf import io
_P = ParamSpec("_P")
_R = TypeVar("_R")

def _reading_anywhere(load: Callable[_P, _R]) -> Callable[_P, _R]:
    """``load`` with ``files=FileAccess(anywhere=True)`` unless another is given."""
    ...
from_file = _reading_anywhere(io.from_file)
from_path = _reading_anywhere(io.from_path)
from_xml_string = _reading_anywhere(io.from_xml_string)
from_zip = _reading_anywhere(io.from_zip)
__all__ = ["from_file", "from_path", "from_xml_string", "from_zip"]
