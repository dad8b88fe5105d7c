# Generated from src/typed_mjcf/cli/_common.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""What every command shares: exit codes, reading models, naming files and lines, progress."""
from __future__ import annotations
import sys
from collections.abc import Iterable, Iterator
from typing import Final, TextIO, TypeVar, cast
from typed_mjcf import RootElement, tooling
from typed_mjcf.errors import IgnoredAttributeWarning, MjcfError, ParseError
from typed_mjcf.io import FileAccess, from_path
from typed_mjcf.tooling import DEFAULT_ACCESS, Element, ParseOptions, Problem, parse_path
OK: Final = 0
FOUND: Final = 1
BAD_INPUT: Final = 2
T = TypeVar("T")

class BadInput(Exception):
    """A file the command cannot work with; the message is one line naming file and line."""

def shown(path: str | None) -> str:
    """A path as messages show it: relative to the current folder when inside it."""
    ...

def location(source: str | None, line: int | None) -> str:
    """``file:line`` (or ``file`` when the line is unknown)."""
    ...

def one_line(text: str) -> str: ...

def parse_error_text(error: ParseError) -> str:
    """A parse error as ``file:line: message``, the file as messages show it."""
    ...

def load(path: str, ignored: list[IgnoredAttributeWarning] | None = None,
         problems: list[Problem] | None = None,
         files: FileAccess | None = None) -> RootElement:
    """Parse an MJCF file; raise :class:`BadInput` with a one-line message if it cannot be.

    Attributes MuJoCo ignores (and the model drops) go to ``ignored`` when it is given, else
    to stderr as ``typed-mjcf: warning: FILE:LINE: ...``. With ``problems``, mistakes the
    parser can read past (a bad value, a misspelt attribute, ...) go there and are left out
    of the model, instead of making the file unreadable.
    """
    ...

def source_of(element: Element) -> tuple[str | None, int | None]:
    """The file and line the element was read from (the model's file, no line, if unknown)."""
    ...

def where(element: Element) -> str:
    """``file:line`` of the element."""
    ...

def error(command: str, message: str, stream: TextIO | None = None) -> None:
    """Report bad input on stderr: ``typed-mjcf <command>: <message>``."""
    ...

class Progress:
    """``[i/n] file`` on one stderr line, rewritten in place; shown when stderr is a terminal
    (or when asked), only for several files. Call :meth:`clear` before printing anything."""
    def __init__(self, total: int, enabled: bool | None = None,
                 stream: TextIO | None = None) -> None:
        self.stream = stream or sys.stderr
        if enabled is None:
            enabled = total > 1 and self.stream.isatty()
        self.enabled = enabled
        self.total = total
        self.shown = False
    def each(self, items: Iterable[T], label: str = "") -> Iterator[T]:
        """The items, showing progress as each one starts."""
        ...
    def update(self, done: int, text: str) -> None:
        if not self.enabled:
            return
        line = f"[{done}/{self.total}] {text}"
        width = _terminal_width()
        if len(line) > width - 1:
            line = line[: width - 4] + "..."
        self.stream.write(f"\r\x1b[K{line}")
        self.stream.flush()
        self.shown = True
    def clear(self) -> None:
        if self.shown:
            self.stream.write("\r\x1b[K")
            self.stream.flush()
            self.shown = False

def _terminal_width() -> int: ...
