# Generated from src/typed_mjcf/_dmcompat/debugging.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.debugging``: debug mode, which records where each element was made
and each attribute last set (``element.get_init_stack()``,
``element.get_last_modified_stacks_for_all_attributes()``), and says so when MuJoCo (or
``validate()`` before it) refuses a model given to ``mjcf.Physics``.

Debug mode is on by ``--pymjcf_debug`` (absl flags, defined by
``install_as_dm_control_mjcf()`` when absl is installed, as dm_control defines them, and read
when the first element is made) or :func:`enable_debug_mode`. With
``--pymjcf_debug_full_dump_dir`` (or :func:`set_full_dump_dir`), a refused model is written
there as ``model.xml``, every element's line ending in ``<!--pymjcfdebug:<id>-->``, with
``<id>.dump`` telling where that element was made and each attribute set.
"""
from __future__ import annotations
import contextlib
from collections.abc import Generator, Iterator
from typing import Final, NamedTuple, cast
from typed_mjcf._base import Element, ModelRoot
from typed_mjcf._core.debuginfo import StackTraceEntry
DEBUG_METADATA_PREFIX: Final = "pymjcfdebug"

class ElementDebugInfo(NamedTuple):
    element: object
    init_stack: list[StackTraceEntry]
    attribute_stacks: dict[str, list[StackTraceEntry]]

def debug_mode() -> bool:
    """Whether debug mode is on (first asked: ``--pymjcf_debug``)."""
    ...

def enable_debug_mode() -> None: ...

def disable_debug_mode() -> None: ...

def arm() -> None:
    """Define dm_control's flags and read ``--pymjcf_debug`` when the first element is made
    (``install()`` calls it: absl parses the command line after the imports, in
    ``app.run``)."""
    ...

def get_full_dump_dir() -> str:
    """Where a refused model's full debug information is written (``''``: nowhere)."""
    ...

def set_full_dump_dir(dump_path: str) -> None: ...

def get_current_stack_trace() -> list[StackTraceEntry]:
    """The stack of the calling code, up to where it entered typed-mjcf."""
    ...

@contextlib.contextmanager
def freeze_current_stack_trace() -> Generator[None]:
    """While the block runs, what is made or set is recorded with the stack of its start."""
    ...

def explained(error: ValueError, model: ModelRoot) -> ValueError:
    """``error`` (refusing ``model`` for a physics) with dm_control's advice appended: out
    of debug mode, how to turn it on; in it, where each element the error names was made
    and its attributes set (and the full dump written, when a folder is set)."""
    ...

def dump_full_debug_info(model: ModelRoot, dump_dir: str) -> None:
    """Write ``model.xml`` (each element's lines ending in ``<!--pymjcfdebug:<id>-->``) and
    one ``<id>.dump`` per element into ``dump_dir``, as dm_control's debug mode does."""
    ...
__all__ = ["DEBUG_METADATA_PREFIX", "ElementDebugInfo", "StackTraceEntry", "debug_mode",
           "disable_debug_mode", "dump_full_debug_info", "enable_debug_mode",
           "freeze_current_stack_trace", "get_current_stack_trace", "get_full_dump_dir",
           "set_full_dump_dir"]
