# Generated from src/typed_mjcf/_text/xmltext.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""A minimal XML node, a chunk of text standing for a subtree, and their serialiser: what
the exporter builds for composed models instead of an lxml tree.

Building lxml elements costs more than the rest of an export; these nodes are plain Python
objects with the few operations composition needs, written out in one iterative pass (deep
models do not hit Python's recursion limit).
"""
from __future__ import annotations
from collections.abc import Callable, Iterator

def has_markup(text: str) -> bool:
    """Whether escaping would change ``text`` other than in its double quotes. Six scans of
    one character each (memchr speed) cost a fraction of a regular expression's character
    class matched at every position: this check runs once per exported element."""
    ...

class Chunk:
    """A subtree written straight to text when serialised, at the depth it lands at."""
    def __init__(self, render: Callable[[int, bool], str]) -> None:
        self.render = render

class Node:
    """An XML element: tag, attributes in order, children (nodes, or chunks of text)."""
    def __init__(self, tag: str, attrib: dict[str, str] | None = None) -> None:
        self.tag = tag
        self.attrib: dict[str, str] = {} if attrib is None else attrib
        self.children: list[Node | Chunk] = []
    def sub(self, tag: str, attrib: dict[str, str] | None = None) -> Node:
        """A new last child."""
        ...
    def get(self, key: str) -> str | None: ...
    def set(self, key: str, value: str) -> None: ...
    def __iter__(self) -> Iterator[Node]:
        """The child nodes (sections and the other nodes merging looks into)."""
        ...
    def insert(self, index: int, node: Node | Chunk) -> None: ...
    def remove(self, node: Node | Chunk) -> None: ...

def escape(value: str) -> str:
    """``value`` as the text of an XML attribute."""
    ...
MAX_INDENT = 60

def indent(level: int) -> str:
    """Two spaces per level, up to :data:`MAX_INDENT` characters."""
    ...

def serialize(root: Node, pretty_print: bool = True) -> str:
    """The XML text, indented by two spaces per level like lxml's pretty printing (and,
    like libxml2, no deeper than :data:`MAX_INDENT` characters)."""
    ...
