"""``dm_control.mjcf.constants``: the ones that describe the language rather than
dm_control's implementation."""

from __future__ import annotations

from typing import Final

from typed_mjcf._core.names import SEPARATOR
from typed_mjcf._core.tree import DCLASS as _DCLASS
from typed_mjcf._core.tree import grammar_facts

_FACTS: Final = grammar_facts()

PREFIX_SEPARATOR: Final = SEPARATOR
PREFIX_SEPARATOR_ESCAPE: Final = "\\"
NAMESPACE_SEPARATOR: Final = "@"
DCLASS: Final = _DCLASS
CLASS: Final = _FACTS.dclass
CHILDCLASS: Final = _FACTS.childclass
BODY: Final = _FACTS.body
XML_DEFAULT_PRECISION: Final = 17
MAX_VFS_FILENAME_LENGTH: Final = 998
