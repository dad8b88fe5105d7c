# Generated from src/typed_mjcf/_core/signals.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Signals held while a change of several files runs, so that it is undone or finished whole.

A Python signal handler runs between two bytecodes: a ``KeyboardInterrupt`` or a ``SIGTERM``
taken just after a rename and before it is recorded would leave a file its undo does not know
of (and ``SIGTERM``'s default action ends the process with no undo at all). While
:class:`HeldSignals` is active (in the main thread only: Python runs handlers there),
``SIGINT`` and ``SIGTERM`` are recorded instead; :meth:`HeldSignals.check` raises
:class:`Interrupted` at a step boundary, and leaving the block restores the previous handlers
and delivers the signal to them, as if it came then.
"""
from __future__ import annotations
import signal
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import Final, Self, TypeAlias
from typed_mjcf._core.errors import ExportError
_Handler: TypeAlias = Callable[[int, FrameType | None], object] | int

class Interrupted(ExportError):
    """A signal came while files were being changed; the change was undone."""

class HeldSignals:
    """``with HeldSignals() as held:`` records SIGINT and SIGTERM instead of acting on them."""
    def __init__(self) -> None:
        self.received: signal.Signals | None = None
        self._previous: dict[signal.Signals, _Handler] = {}
    def __enter__(self) -> Self: ...
    def check(self, what: str) -> None:
        """Raise :class:`Interrupted` if a signal came (between two steps of ``what``)."""
        ...
    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 traceback: TracebackType | None) -> None: ...
