# Generated from src/typed_mjcf/_text/parse.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Reading MJCF text into typed elements.

Parsing is safe by default: no DTD or external entity is loaded, nothing is fetched from the
network, entity declarations are refused (MuJoCo's XML reader does not expand them; they are
how "billion laughs" documents multiply text), and :class:`ParseLimits` bounds the bytes
read, the nesting depth and the number of elements, all counted over the assembled model
(includes too). The document is read by a streaming parser that stops as soon as a limit is
passed, and the typed tree is built without recursion, so a deeply nested document gives a
:class:`~typed_mjcf.ParseError` naming the limit, never a ``RecursionError``.

``<include>`` elements are expanded in place, wherever they appear, so document order (and
so qpos layout) is kept. As in MuJoCo, an included file's path is relative to the folder of
the main model file (not of the file that includes it), and a file may be included once.
Repeated top-level sections (two ``<asset>`` blocks, say) merge, as they do in MuJoCo; a
once-only child repeated in one element (two ``<joint>`` in one ``<default>``) is refused, as
MuJoCo refuses it.

Every failure is a :class:`~typed_mjcf.ParseError` (a ``ValueError``) with the file and line
where it is known.
"""
from __future__ import annotations
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Final, Protocol, TypeAlias, cast
from typed_mjcf._build import mypyc_attr
from typed_mjcf._core.access import (
    ANYWHERE,
    DEFAULT_ACCESS,
    Confinement,
    FileAccess,
    Refused,
    check_count,
    confine,
    open_confined,
)
from typed_mjcf._core.errors import (
    DuplicateIdentifierError,
    FileAccessError,
    FileReadError,
    IgnoredAttributeWarning,
    InvalidTypeError,
    MjcfError,
    ParseError,
    did_you_mean,
)
from typed_mjcf._core.tree import Element, ModelBase, name_note
from typed_mjcf.types import XmlElement
INCLUDE = "include"
XmlNode: TypeAlias = XmlElement
_LONG_STRETCH: Final = 4096

@mypyc_attr(native_class=False)
@dataclass(frozen=True, slots=True)
class ParseLimits:
    """Bounds on what reading one model may consume; pass a raised copy to read more.

    Every limit counts the assembled model: the main text and every included file.

    ``max_bytes``
        Bytes of MJCF text read (64 MiB).
    ``max_depth``
        Nesting depth of elements, the root ``<mujoco>`` being 1 (500, the depth MuJoCo's
        own XML reader stops at). The XML reader cannot go past 2048 in one file.
    ``max_elements``
        XML elements read (1,000,000).

    ``typed_mjcf.from_path(path, limits=ParseLimits(max_bytes=1 << 30))`` reads a 1 GiB file.
    """
    max_bytes: int = ...
    max_depth: int = 500
    max_elements: int = 1_000_000
    def __post_init__(self) -> None: ...
DEFAULT_LIMITS: Final = ParseLimits()

@dataclass(frozen=True, slots=True)
class Problem:
    """A mistake a collecting parse read past (see ``ParseOptions.on_problem``): ``rule``
    says which kind (``unknown-attribute``, ``invalid-value``, ``duplicate-name``,
    ``illegal-child``), ``path`` is the element's, ``error`` the ParseError a strict parse
    raises, with its file and line."""
    rule: str
    path: str
    error: ParseError

@dataclass(frozen=True, slots=True)
class ParseOptions:
    """What a parse does besides reading the grammar (dm_control's parser arguments).

    ``assets``: file contents by the path the model writes (or the file's name), used for
    included MJCF files and every file attribute before the disk; ``escape_separators``: a
    ``/`` in a name read from the file becomes ``\\/`` (dm_control's escaping; by default
    names keep their ``/``); ``resolve_references``: link references to their elements
    (else they stay names until ``model.resolve_references()``); ``on_problem``: when
    given, a mistake in one attribute or element (a misspelt attribute, a value the grammar
    refuses, a name already taken, a child the parent cannot have) is passed to it as a
    :class:`Problem` and read past, the attribute (or the child and what is inside it) left
    out, instead of stopping the parse; what cannot be read past (malformed XML, a missing
    include, a limit) still raises.
    """
    assets: Mapping[str, bytes] = field(default_factory=lambda: {})
    escape_separators: bool = False
    resolve_references: bool = True
    on_problem: Callable[[Problem], None] | None = None
    def asset(self, file: str) -> bytes | None:
        """A file's contents from ``assets``: by the path as written, else by its name."""
        ...
DEFAULT_OPTIONS: Final = ParseOptions()

def source_line(node: XmlNode) -> int | None:
    """The line libxml2 gives ``node``: where its start tag ends, if known."""
    ...

def root_class() -> type[ModelBase]:
    """The generated class of the root row (``<mujoco>``)."""
    ...

def has_long_stretch(data: bytes, length: int = _LONG_STRETCH) -> bool:
    """Whether a "<" in ``data`` is followed by ``length`` bytes without one. Each window
    after a "<" is searched from its end (the last "<" in it starts the next window), so a
    text is crossed in about ``len(data) / length`` searches: a regular expression tried
    every "<" (a tenth of the time of reading a small model)."""
    ...

def read_bounded(read: Callable[[int], bytes], limit: int, expected: int = 0) -> bytes:
    """Read until the end or until more than ``limit`` bytes are read (one more byte than
    allowed shows that the limit is passed), without allocating for the limit up front."""
    ...

def is_model_text(data: bytes) -> bool:
    """Whether ``data`` is MJCF text: XML whose root element is the model's root."""
    ...

def parse_text(data: object, *, base_dir: str | None = None, source: str | None = None,
               limits: ParseLimits | None = None, options: ParseOptions = DEFAULT_OPTIONS,
               access: FileAccess | Confinement = DEFAULT_ACCESS) -> ModelBase:
    """Parse MJCF text into a model that reads files where ``access`` allows (by default in
    ``base_dir``, else the current folder)."""
    ...

def parse_path(path: str, *, limits: ParseLimits | None = None,
               options: ParseOptions = DEFAULT_OPTIONS,
               access: FileAccess | Confinement = DEFAULT_ACCESS) -> ModelBase:
    """Parse an MJCF file; its folder is the base of relative paths and, by default, the
    only folder the model reads files from (see ``access``)."""
    ...

def attributes_of(node: XmlNode) -> list[tuple[str, str]]:
    """``node.items()`` in time linear in their number (XPath lists them in one pass)."""
    ...

def escape_separators(name: str) -> str:
    """dm_control's escaping of the scope separator in a name read from a file."""
    ...
_Key = tuple[str, str]
