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
import threading
from collections.abc import Callable
from types import FrameType, TracebackType
from typing import Final, Self, TypeAlias

from typed_mjcf._core.errors import ExportError

_Handler: TypeAlias = Callable[[int, FrameType | None], object] | int
_HELD: Final = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM")
                     if hasattr(signal, name))


class Interrupted(ExportError):
    """A signal came while files were being changed; the change was undone."""


class HeldSignals:
    """``with HeldSignals() as held:`` records SIGINT and SIGTERM instead of acting on them."""

    def __init__(self) -> None:
        self.received: signal.Signals | None = None
        self._previous: dict[signal.Signals, _Handler] = {}

    def __enter__(self) -> Self:
        if threading.current_thread() is threading.main_thread():
            for number in _HELD:
                previous = signal.getsignal(number)
                if previous is signal.SIG_IGN or previous is None:  # ignored, or not Python's
                    continue
                self._previous[number] = previous
                signal.signal(number, self._record)
        return self

    def _record(self, number: int, frame: FrameType | None) -> None:
        del frame
        if self.received is None:
            self.received = signal.Signals(number)

    def check(self, what: str) -> None:
        """Raise :class:`Interrupted` if a signal came (between two steps of ``what``)."""
        if self.received is not None:
            raise Interrupted(f"{what} was interrupted by {self.received.name}; what it had "
                              f"changed was put back")

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 traceback: TracebackType | None) -> None:
        for number, previous in self._previous.items():
            signal.signal(number, previous)
        if self.received is not None and self.received in self._previous:
            # the previous handler acts now: SIGTERM's default ends the process, SIGINT's
            # raises KeyboardInterrupt; a handler that returns leaves Interrupted to propagate
            signal.raise_signal(self.received)
