"""A minimal XML node, a chunk of text standing for a subtree, and their serialiser: what
the exporter builds for composed models instead of an lxml tree.

Building lxml elements costs more than the rest of an export; these nodes are plain Python
objects with the few operations composition needs, written out in one iterative pass (deep
models do not hit Python's recursion limit).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator

_SPECIAL = re.compile('[&<>"\n\r\t]')
_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;",
                          "\n": "&#10;", "\r": "&#13;", "\t": "&#9;"})


def has_markup(text: str) -> bool:
    """Whether escaping would change ``text`` other than in its double quotes. Six scans of
    one character each (memchr speed) cost a fraction of a regular expression's character
    class matched at every position: this check runs once per exported element."""
    return ("&" in text or "<" in text or ">" in text or "\n" in text or "\r" in text
            or "\t" in text)


class Chunk:
    """A subtree written straight to text when serialised, at the depth it lands at."""

    __slots__ = ("render",)

    def __init__(self, render: Callable[[int, bool], str]) -> None:
        self.render = render  # (depth, pretty_print) -> the subtree's text


class Node:
    """An XML element: tag, attributes in order, children (nodes, or chunks of text)."""

    __slots__ = ("attrib", "children", "tag")

    def __init__(self, tag: str, attrib: dict[str, str] | None = None) -> None:
        self.tag = tag
        self.attrib: dict[str, str] = {} if attrib is None else attrib
        self.children: list[Node | Chunk] = []

    def sub(self, tag: str, attrib: dict[str, str] | None = None) -> Node:
        """A new last child."""
        node = Node(tag, attrib)
        self.children.append(node)
        return node

    def get(self, key: str) -> str | None:
        return self.attrib.get(key)

    def set(self, key: str, value: str) -> None:
        self.attrib[key] = value

    def __iter__(self) -> Iterator[Node]:
        """The child nodes (sections and the other nodes merging looks into)."""
        return (child for child in self.children if isinstance(child, Node))

    def insert(self, index: int, node: Node | Chunk) -> None:
        self.children.insert(index, node)

    def remove(self, node: Node | Chunk) -> None:
        self.children.remove(node)


def escape(value: str) -> str:
    """``value`` as the text of an XML attribute."""
    return value.translate(_ESCAPES) if _SPECIAL.search(value) else value


MAX_INDENT = 60  # characters: deeper levels are indented no further, as libxml2 does


def indent(level: int) -> str:
    """Two spaces per level, up to :data:`MAX_INDENT` characters."""
    return "  " * level if 2 * level <= MAX_INDENT else " " * MAX_INDENT


def serialize(root: Node, pretty_print: bool = True) -> str:
    """The XML text, indented by two spaces per level like lxml's pretty printing (and,
    like libxml2, no deeper than :data:`MAX_INDENT` characters)."""
    parts: list[str] = []
    append = parts.append
    newline = "\n" if pretty_print else ""
    stack: list[tuple[Node | Chunk, int, bool]] = [(root, 0, False)]
    while stack:
        node, depth, closing = stack.pop()
        if isinstance(node, Chunk):
            append(node.render(depth, pretty_print))
            continue
        spaces = indent(depth) if pretty_print else ""
        if closing:
            append(f"{spaces}</{node.tag}>{newline}")
            continue
        attributes = "".join([f' {k}="{escape(v)}"' for k, v in node.attrib.items()])
        if node.children:
            append(f"{spaces}<{node.tag}{attributes}>{newline}")
            stack.append((node, depth, True))
            stack.extend([(child, depth + 1, False) for child in reversed(node.children)])
        else:
            append(f"{spaces}<{node.tag}{attributes}/>{newline}")
    return "".join(parts)
