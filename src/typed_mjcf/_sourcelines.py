"""The line an element starts on, from the line libxml2 gives it.

libxml2 records an element's line when it has read the whole start tag, so a tag written
over several lines is reported on its last line. Messages should point at the ``<``: this
module finds it in the file's text, only when a message needs it (reading stays as fast).
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Final

# A start tag from its name on, with quoted attribute values (which may hold ">").
_REST_OF_TAG: Final = re.compile(
    rb"""(?:\s+[^\s=/>]+\s*=\s*(?:"[^"]*"|'[^']*'))*\s*/?>""")


@lru_cache(maxsize=256)
def _tag_start(tag: str) -> re.Pattern[bytes]:
    return re.compile(b"<" + re.escape(tag.encode("utf-8")) + rb"(?=[\s/>])")


def start_line(text: bytes, line: int, tag: str) -> int:
    """The line where the start tag of a ``<tag>`` that libxml2 placed on ``line`` begins.

    Of the ``<tag`` start tags that end on ``line``, the first is taken (two tags of the same
    name ending on one line, the first spread over several lines, are told apart only by
    document order, which a message does not have). ``line`` is returned when no such tag is
    found (text in an encoding other than UTF-8 or ASCII, say).
    """
    if line < 1:
        return line
    begin = 0
    for _ in range(line - 1):
        begin = text.find(b"\n", begin) + 1
        if begin == 0:
            return line
    end = text.find(b"\n", begin)
    end = len(text) if end < 0 else end
    pattern = _tag_start(tag)
    found: int | None = None
    # A start tag holds no "<": the one sought begins at the last "<" before its end, so
    # the search stops at the first markup that begins before the line.
    position = text.rfind(b"<", 0, end)
    while position >= 0:
        comment = text.rfind(b"<!--", 0, position + 1)
        if comment >= 0 and text.find(b"-->", comment) > position:
            position = text.rfind(b"<", 0, comment)  # skip the whole comment
            continue
        if pattern.match(text, position):
            rest = _REST_OF_TAG.match(text, position + 1 + len(tag))
            if rest is not None and begin <= rest.end() - 1 <= end:
                found = position
        if position < begin:
            break
        position = text.rfind(b"<", 0, position)
    return line if found is None else text.count(b"\n", 0, found) + 1


def file_start_line(path: str, line: int, tag: str, cache: dict[str, bytes | None]) -> int:
    """:func:`start_line` in the file at ``path`` (read once per ``cache``); ``line`` if the
    file cannot be read any more."""
    if path not in cache:
        try:
            with open(path, "rb") as file:
                cache[path] = file.read()
        except OSError:
            cache[path] = None
    text = cache[path]
    return line if text is None else start_line(text, line, tag)
