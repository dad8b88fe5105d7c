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

import re
from array import array
from bisect import bisect_right
from typing import Final

# A start tag from its name on, with quoted attribute values (which may hold ">"); possessive,
# so that a tag with many attributes costs no memory per attribute.
_REST_OF_TAG: Final = re.compile(
    rb"""(?:\s+[^\s=/>]+\s*=\s*(?:"[^"]*"|'[^']*'))*+\s*/?>""")
_TAG_NAME: Final = re.compile(rb"<([^\s/>!?<]+)")


class SourceText:
    """One file's text, and an index of its lines, comments and start tags built as messages
    ask for them."""

    __slots__ = ("_comment_ends", "_comment_starts", "_lines", "_newlines", "text")

    def __init__(self, text: bytes) -> None:
        self.text = text
        self._newlines: array[int] | None = None  # offset of every "\n"
        self._comment_starts: array[int] | None = None  # "<!--" of every comment, in order
        self._comment_ends: array[int] = array("q")  # just past its "-->" (or the end)
        self._lines: dict[int, dict[str, int]] = {}  # line -> tag -> its first start tag

    def start_line(self, line: int, tag: str) -> int:
        """The line where the start tag of a ``<tag>`` that libxml2 placed on ``line`` begins.

        Of the ``<tag`` start tags that end on ``line``, the first is taken (two tags of the
        same name ending on one line, the first spread over several lines, are told apart only
        by document order, which a message does not have). ``line`` is returned when no such
        tag is found (text in an encoding other than UTF-8 or ASCII, say).
        """
        if line < 1:
            return line
        tags = self._lines.get(line)
        if tags is None:
            tags = self._lines[line] = self._start_tags(line)
        found = tags.get(tag)
        return line if found is None else self._line_of(found)

    def _line_bounds(self, line: int) -> tuple[int, int] | None:
        """The offsets where ``line`` begins and ends (its "\\n" or the end of the text)."""
        newlines = self._newline_offsets()
        if line - 1 > len(newlines):
            return None
        begin = 0 if line == 1 else newlines[line - 2] + 1
        end = newlines[line - 1] if line - 1 < len(newlines) else len(self.text)
        return begin, end

    def _line_of(self, offset: int) -> int:
        return bisect_right(self._newline_offsets(), offset - 1) + 1

    def _newline_offsets(self) -> array[int]:
        if self._newlines is None:
            found: array[int] = array("q")
            text, at = self.text, self.text.find(b"\n")
            while at >= 0:
                found.append(at)
                at = text.find(b"\n", at + 1)
            self._newlines = found
        return self._newlines

    def _comment_at(self, offset: int) -> tuple[int, int] | None:
        """Where the comment holding ``offset`` begins and ends, if one does."""
        starts = self._comment_starts
        if starts is None:
            starts = self._comment_starts = array("q")
            text, at = self.text, self.text.find(b"<!--")
            while at >= 0:
                end = text.find(b"-->", at + 4)
                end = len(text) if end < 0 else end + 3
                starts.append(at)
                self._comment_ends.append(end)
                at = text.find(b"<!--", end)
        i = bisect_right(starts, offset) - 1
        if i >= 0 and offset < self._comment_ends[i]:
            return starts[i], self._comment_ends[i]
        return None

    def _start_tags(self, line: int) -> dict[str, int]:
        """The first start tag of each name that ends on ``line``, by where it begins."""
        bounds = self._line_bounds(line)
        if bounds is None:
            return {}
        begin, end = bounds
        text = self.text
        # A start tag holds no "<": one ending on the line begins at the last "<" (outside
        # comments) before the line, or on it.
        position = text.rfind(b"<", 0, begin)
        while position >= 0:
            comment = self._comment_at(position)
            if comment is None:
                break
            position = text.rfind(b"<", 0, comment[0])
        position = text.find(b"<", max(position, 0), end)
        found: dict[str, int] = {}
        while 0 <= position < end:
            comment = self._comment_at(position)
            if comment is not None:
                position = text.find(b"<", comment[1], end)
                continue
            name = _TAG_NAME.match(text, position)
            if name is not None:
                rest = _REST_OF_TAG.match(text, name.end())
                if rest is not None and begin <= rest.end() - 1 <= end:
                    try:
                        found.setdefault(name.group(1).decode("utf-8"), position)
                    except UnicodeDecodeError:
                        pass
            position = text.find(b"<", position + 1, end)
        return found


def start_line(text: bytes, line: int, tag: str) -> int:
    """:meth:`SourceText.start_line` for one question about ``text``."""
    return SourceText(text).start_line(line, tag)


def file_start_line(path: str, line: int, tag: str, cache: dict[str, SourceText | None]) -> int:
    """:meth:`SourceText.start_line` in the file at ``path`` (read and indexed once per
    ``cache``); ``line`` if the file cannot be read any more."""
    if path not in cache:
        try:
            with open(path, "rb") as file:
                cache[path] = SourceText(file.read())
        except OSError:
            cache[path] = None
    source = cache[path]
    return line if source is None else source.start_line(line, tag)
