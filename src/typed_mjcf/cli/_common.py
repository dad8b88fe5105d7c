"""What every command shares: exit codes, reading models, naming files and lines, progress."""

from __future__ import annotations

import os
import sys
import warnings
from collections.abc import Iterable, Iterator
from typing import Final, TextIO, TypeVar, cast

from typed_mjcf import RootElement, tooling
from typed_mjcf.errors import IgnoredAttributeWarning, MjcfError, ParseError
from typed_mjcf.io import FileAccess, from_path
from typed_mjcf.tooling import DEFAULT_ACCESS, Element, ParseOptions, Problem, parse_path

OK: Final = 0
FOUND: Final = 1  # findings, differences, files that would change
BAD_INPUT: Final = 2  # a file that cannot be read as MJCF (also argparse's usage errors)

T = TypeVar("T")


class BadInput(Exception):
    """A file the command cannot work with; the message is one line naming file and line."""


def shown(path: str | None) -> str:
    """A path as messages show it: relative to the current folder when inside it."""
    if path is None:
        return "<text>"
    try:
        relative = os.path.relpath(path)
    except ValueError:  # another drive (Windows)
        return path
    return path if relative.startswith(os.pardir) else relative


def location(source: str | None, line: int | None) -> str:
    """``file:line`` (or ``file`` when the line is unknown)."""
    return shown(source) if line is None else f"{shown(source)}:{line}"


def one_line(text: str) -> str:
    return " ".join(text.split())


def parse_error_text(error: ParseError) -> str:
    """A parse error as ``file:line: message``, the file as messages show it."""
    if error.source is not None:
        return f"{location(error.source, error.line)}: {one_line(error.detail)}"
    return one_line(str(error))


def load(path: str, ignored: list[IgnoredAttributeWarning] | None = None,
         problems: list[Problem] | None = None,
         files: FileAccess | None = None) -> RootElement:
    """Parse an MJCF file; raise :class:`BadInput` with a one-line message if it cannot be.

    Attributes MuJoCo ignores (and the model drops) go to ``ignored`` when it is given, else
    to stderr as ``typed-mjcf: warning: FILE:LINE: ...``. With ``problems``, mistakes the
    parser can read past (a bad value, a misspelt attribute, ...) go there and are left out
    of the model, instead of making the file unreadable.
    """
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", IgnoredAttributeWarning)
            if problems is None:
                model = from_path(path, files=files)
            else:
                options = ParseOptions(on_problem=problems.append)
                access = DEFAULT_ACCESS if files is None else files
                model = cast(RootElement, parse_path(path, options=options, access=access))
    except ParseError as error:
        raise BadInput(parse_error_text(error)) from None
    except MjcfError as error:  # pragma: no cover - from_path raises only ParseError
        raise BadInput(f"{shown(path)}: {one_line(str(error))}") from None
    for record in caught:
        if not isinstance(record.message, IgnoredAttributeWarning):  # pragma: no cover
            warnings.warn_explicit(record.message, record.category, record.filename,
                                   record.lineno)
        elif ignored is not None:
            ignored.append(record.message)
        else:
            found = record.message
            print(f"typed-mjcf: warning: {location(found.source, found.line)}: {found.detail}",
                  file=sys.stderr)
    return model


def source_of(element: Element) -> tuple[str | None, int | None]:
    """The file and line the element was read from (the model's file, no line, if unknown)."""
    found = tooling.source_of(element)
    if found is not None:
        return found
    model = tooling.model_of(element)
    root_source = None if model is None else tooling.source_of(model)
    return (root_source[0], None) if root_source is not None else (None, None)


def where(element: Element) -> str:
    """``file:line`` of the element."""
    return location(*source_of(element))


def error(command: str, message: str, stream: TextIO | None = None) -> None:
    """Report bad input on stderr: ``typed-mjcf <command>: <message>``."""
    print(f"typed-mjcf {command}: {message}", file=stream or sys.stderr)


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
        for i, item in enumerate(items, 1):
            self.update(i, f"{label} {item}".strip())
            yield item
        self.clear()

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


def _terminal_width() -> int:
    try:
        columns = os.get_terminal_size(sys.stderr.fileno()).columns
    except (OSError, ValueError):
        columns = 0
    return columns if columns >= 20 else 80  # a pseudo-terminal may report no size
