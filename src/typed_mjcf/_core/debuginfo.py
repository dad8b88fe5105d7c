"""Where each element was made and each of its attributes last set, in dm_control's debug
mode (``dm_control.mjcf.debugging`` after ``install_as_dm_control_mjcf()``).

Off by default, at the cost of one check when an element is made or an attribute set. On,
the tree reports every creation and assignment to the recorder, which keeps the Python
stack (the frames outside typed-mjcf) for each.
"""

from __future__ import annotations

import os
import traceback
import weakref
from collections.abc import Callable
from typing import Final, NamedTuple


class StackTraceEntry(NamedTuple):
    """One frame of a stack: dm_control's ``debugging.StackTraceEntry``."""

    filename: str
    line_number: int
    function_name: str
    text: str


Stack = list[StackTraceEntry]
# what the tree calls: (element, None, True) when it is made, (element, names, True) for
# the values it is made with, (element, names, False) when set later
Recorder = Callable[[object, tuple[str, ...] | None, bool], None]

# the package folder (this module is in its _core/): frames inside it are the library's
PACKAGE_DIR: Final = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECORDER: Final[list[Recorder | None]] = [None]  # None: debug mode is off
_FROZEN: Final[list[Stack | None]] = [None]


class _Record:
    __slots__ = ("attributes", "init")

    def __init__(self, init: Stack) -> None:
        self.init = init
        self.attributes: dict[str, Stack] = {}


_RECORDS: weakref.WeakKeyDictionary[object, _Record] = weakref.WeakKeyDictionary()


def current_stack() -> Stack:
    """The Python stack up to the first frame inside typed-mjcf (the caller's code), or the
    stack frozen by :func:`freeze`."""
    frozen = _FROZEN[0]
    if frozen is not None:
        return list(frozen)
    stack: Stack = []
    for frame in traceback.extract_stack():
        if os.path.abspath(frame.filename).startswith(PACKAGE_DIR + os.sep):
            break
        stack.append(StackTraceEntry(frame.filename, frame.lineno or 0, frame.name,
                                     frame.line or ""))
    return stack


def freeze(stack: Stack | None) -> Stack | None:
    """Make :func:`current_stack` give ``stack`` (``None``: the real one again); return the
    stack frozen before."""
    before = _FROZEN[0]
    _FROZEN[0] = stack
    return before


def _record(element: object, names: tuple[str, ...] | None, creating: bool) -> None:
    record = _RECORDS.get(element)
    if names is None:  # made now
        _RECORDS[element] = _Record(current_stack())
        return
    if record is None:  # made before debug mode was on: where is unknown
        _RECORDS[element] = record = _Record([])
    stack = record.init if creating else current_stack()
    for name in names:
        record.attributes[name] = stack


def set_recording(on: bool) -> None:
    """Turn recording on or off (dm_control's debug mode)."""
    RECORDER[0] = _record if on else None


def init_stack(element: object) -> Stack:
    """Where ``element`` was made (empty when debug mode was off)."""
    record = _RECORDS.get(element)
    return [] if record is None else list(record.init)


def attribute_stacks(element: object, names: tuple[str, ...]) -> dict[str, Stack]:
    """Where each of ``names`` was last set on ``element`` (empty when unknown)."""
    record = _RECORDS.get(element)
    found = {} if record is None else record.attributes
    return {name: list(found.get(name, [])) for name in names}
