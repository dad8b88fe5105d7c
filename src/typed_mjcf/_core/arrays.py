"""The arrays an element's attributes read as: read-only views whose failed in-place edit
says what to do instead (numpy alone says only "assignment destination is read-only")."""

from __future__ import annotations

from collections.abc import Callable
from typing import Final, cast

import numpy as np

from typed_mjcf._core.errors import InvalidValueError

_ADVICE: Final = (
    "an array read from an element is read-only: assign a new value instead, e.g. "
    "`body.pos = (0, 0, 1)` or `body.pos = body.pos + delta` (the assignment is checked; "
    "install_as_dm_control_mjcf() makes arrays writable in place, as dm_control's are)")

_Base = np.ndarray[tuple[int, ...], np.dtype[np.generic]]
# numpy's own methods, called untyped (their overloads name every dtype)
_SETITEM = cast(Callable[[object, object, object], None], np.ndarray.__setitem__)
_WRAP = cast(Callable[..., object], np.ndarray.__array_wrap__)


class ReadOnlyArray(_Base):
    """An attribute's value as read from an element: a read-only ndarray. What arithmetic
    makes of it is a plain ndarray; writing into it raises the library's error."""

    def __setitem__(self, key: object, value: object, /) -> None:
        if not self.flags.writeable:
            raise InvalidValueError(_ADVICE)
        _SETITEM(self, key, value)  # a writable copy of one

    def __repr__(self) -> str:
        return repr(self.view(np.ndarray))


def _plain_result(self: ReadOnlyArray, array: object, *args: object, **kwargs: object) -> object:
    """What arithmetic makes of a read array: a plain ndarray, not a view of a value."""
    out = _WRAP(self, array, *args, **kwargs)
    return out.view(np.ndarray) if isinstance(out, np.ndarray) else out


def _in_place(name: str) -> object:
    def operator(self: ReadOnlyArray, other: object) -> object:
        if not self.flags.writeable:
            raise InvalidValueError(_ADVICE)
        return getattr(np.ndarray, name)(self, other)
    operator.__name__ = name
    return operator


def _install_operators() -> None:
    """``body.pos += 1`` too (numpy alone: "output array is read-only"), and plain results;
    set after the class so that the checkers keep numpy's own signatures."""
    for name in ("__iadd__", "__isub__", "__imul__", "__itruediv__", "__ifloordiv__",
                 "__imod__", "__ipow__", "__imatmul__", "__iand__", "__ior__", "__ixor__",
                 "__ilshift__", "__irshift__"):
        setattr(ReadOnlyArray, name, _in_place(name))
    setattr(ReadOnlyArray, "__array_wrap__", _plain_result)


_install_operators()


def read_only(array: _Base) -> _Base:
    """``array`` as a read-only :class:`ReadOnlyArray` view (no copy)."""
    view = array.view(ReadOnlyArray)
    view.flags.writeable = False
    return view
