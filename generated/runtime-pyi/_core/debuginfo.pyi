# Generated from src/typed_mjcf/_core/debuginfo.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Where each element was made and each of its attributes last set, in dm_control's debug
mode (``dm_control.mjcf.debugging`` after ``install_as_dm_control_mjcf()``).

Off by default, at the cost of one check when an element is made or an attribute set. On,
the tree reports every creation and assignment to the recorder, which keeps the Python
stack (the frames outside typed-mjcf) for each.
"""
from __future__ import annotations
import os
from collections.abc import Callable
from typing import Final, NamedTuple

class StackTraceEntry(NamedTuple):
    """One frame of a stack: dm_control's ``debugging.StackTraceEntry``."""
    filename: str
    line_number: int
    function_name: str
    text: str
Stack = list[StackTraceEntry]
Recorder = Callable[[object, tuple[str, ...] | None, bool], None]
PACKAGE_DIR: Final = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECORDER: Final[list[Recorder | None]] = ...

def current_stack() -> Stack:
    """The Python stack up to the first frame inside typed-mjcf (the caller's code), or the
    stack frozen by :func:`freeze`."""
    ...

def freeze(stack: Stack | None) -> Stack | None:
    """Make :func:`current_stack` give ``stack`` (``None``: the real one again); return the
    stack frozen before."""
    ...

def set_recording(on: bool) -> None:
    """Turn recording on or off (dm_control's debug mode)."""
    ...

def init_stack(element: object) -> Stack:
    """Where ``element`` was made (empty when debug mode was off)."""
    ...

def attribute_stacks(element: object, names: tuple[str, ...]) -> dict[str, Stack]:
    """Where each of ``names`` was last set on ``element`` (empty when unknown)."""
    ...
