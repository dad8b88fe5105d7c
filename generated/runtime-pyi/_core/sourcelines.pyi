# Generated from src/typed_mjcf/_core/sourcelines.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The line an element starts on, from the line libxml2 gives it.

libxml2 records an element's line when it has read the whole start tag, so a tag written
over several lines is reported on its last line. Messages should point at the ``<``: this
module finds it in the file's text, only when a message needs it (reading stays as fast).

What it needs of a text (where lines begin, where comments are, the start tags ending on a
line) is found once per text and line (:class:`SourceText`), so the time for any number of
messages stays linear in the text: a line holding 10,000 ``<include>`` elements, each asking
for its line, took minutes when each question scanned the line again.
"""
from __future__ import annotations
from array import array

class SourceText:
    """One file's text, and an index of its lines, comments and start tags built as messages
    ask for them."""
    def __init__(self, text: bytes) -> None:
        self.text = text
        self._newlines: array[int] | None = None  # offset of every "\n"
        self._comment_starts: array[int] | None = None  # "<!--" of every comment, in order
        self._comment_ends: array[int] = array("q")  # just past its "-->" (or the end)
        self._lines: dict[int, dict[str, int]] = {}
    def start_line(self, line: int, tag: str) -> int:
        """The line where the start tag of a ``<tag>`` that libxml2 placed on ``line`` begins.

        Of the ``<tag`` start tags that end on ``line``, the first is taken (two tags of the
        same name ending on one line, the first spread over several lines, are told apart only
        by document order, which a message does not have). ``line`` is returned when no such
        tag is found (text in an encoding other than UTF-8 or ASCII, say).
        """
        ...

def start_line(text: bytes, line: int, tag: str) -> int:
    """:meth:`SourceText.start_line` for one question about ``text``."""
    ...

def file_start_line(path: str, line: int, tag: str, cache: dict[str, SourceText | None]) -> int:
    """:meth:`SourceText.start_line` in the file at ``path`` (read and indexed once per
    ``cache``); ``line`` if the file cannot be read any more."""
    ...
