# Generated from src/typed_mjcf/_core/arrays.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The arrays an element's attributes read as: read-only views whose failed in-place edit
says what to do instead (numpy alone says only "assignment destination is read-only")."""
from __future__ import annotations
import numpy as np
_Base = np.ndarray[tuple[int, ...], np.dtype[np.generic]]

class ReadOnlyArray(_Base):
    """An attribute's value as read from an element: a read-only ndarray. What arithmetic
    makes of it is a plain ndarray; writing into it raises the library's error."""
    def __setitem__(self, key: object, value: object, /) -> None: ...
    def __repr__(self) -> str: ...

def read_only(array: _Base) -> _Base:
    """``array`` as a read-only :class:`ReadOnlyArray` view (no copy)."""
    ...
