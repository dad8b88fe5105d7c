"""``dm_control.mjcf.debugging``: debug mode, which records where each element was made
and each attribute last set (``element.get_init_stack()``,
``element.get_last_modified_stacks_for_all_attributes()``).

Limits: the ``--pymjcf_debug`` flags are not defined (absl flags are not a dependency):
debug mode is turned on with :func:`enable_debug_mode`. Compile errors are typed-mjcf's
``CompileError``, which already names the element MuJoCo's message is about; the XML
instrumented with ``<!--pymjcfdebug:...-->`` comments and its full dump are not written.
"""

from __future__ import annotations

import contextlib
from collections.abc import Generator
from typing import NamedTuple

from typed_mjcf import _debuginfo
from typed_mjcf._debuginfo import StackTraceEntry

DEBUG_METADATA_PREFIX = "pymjcfdebug"
_FULL_DUMP_DIR: list[str] = [""]


class ElementDebugInfo(NamedTuple):
    element: object
    init_stack: list[StackTraceEntry]
    attribute_stacks: dict[str, list[StackTraceEntry]]


def debug_mode() -> bool:
    """Whether debug mode is on."""
    return _debuginfo.RECORDER[0] is not None


def enable_debug_mode() -> None:
    _debuginfo.set_recording(True)


def disable_debug_mode() -> None:
    _debuginfo.set_recording(False)


def get_full_dump_dir() -> str:
    return _FULL_DUMP_DIR[0]


def set_full_dump_dir(dump_path: str) -> None:
    """Kept for dm_control's API; nothing is dumped there (see the module docstring)."""
    _FULL_DUMP_DIR[0] = dump_path


def get_current_stack_trace() -> list[StackTraceEntry]:
    """The stack of the calling code, up to where it entered typed-mjcf."""
    return _debuginfo.current_stack()


@contextlib.contextmanager
def freeze_current_stack_trace() -> Generator[None]:
    """While the block runs, what is made or set is recorded with the stack of its start."""
    if not debug_mode():
        yield
        return
    before = _debuginfo.freeze(_debuginfo.current_stack())
    try:
        yield
    finally:
        _debuginfo.freeze(before)


__all__ = ["DEBUG_METADATA_PREFIX", "ElementDebugInfo", "StackTraceEntry", "debug_mode",
           "disable_debug_mode", "enable_debug_mode", "freeze_current_stack_trace",
           "get_current_stack_trace", "get_full_dump_dir", "set_full_dump_dir"]
