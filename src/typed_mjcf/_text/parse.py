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

import inspect
import os
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Final, Protocol, TypeAlias, cast

import numpy as np
from lxml import etree

from typed_mjcf._build import mypyc_attr
from typed_mjcf._core import tree as _tree
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
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.codecs import Rejected
from typed_mjcf._core.debuginfo import PACKAGE_DIR
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
from typed_mjcf._core.gc import collector_paused
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.sourcelines import SourceText
from typed_mjcf._core.tree import Element, ModelBase, name_note
from typed_mjcf.types import XmlElement

INCLUDE = "include"

XmlNode: TypeAlias = XmlElement

_Array = np.ndarray[tuple[int, ...], np.dtype[np.generic]]

# The deepest nesting libxml2 reads at all (with XML_PARSE_HUGE; 256 without). MuJoCo's own
# XML reader (tinyxml2) stops at 500.
_XML_READER_DEPTH: Final = 2048
_CHUNK: Final = 1 << 16  # bytes fed to the streaming parser at a time
# lxml reads an element's attributes (items()) by looking each up by name: time quadratic in
# their number (100,000 took minutes). A text whose every stretch without "<" is shorter than
# this holds no start tag with more than a few hundred attributes (a "<" never appears in a
# tag); others are read through attributes_of().
_LONG_STRETCH: Final = 4096
_MANY_ATTRIBUTES: Final = 64
_SUGGESTED: Final = 100  # ignored attributes given a "did you mean" in one parse


# an ordinary Python class when compiled: its checks (__post_init__) say what a bad limit
# is, where a compiled __init__ would raise a bare TypeError first (ParseLimits(max_bytes=1.5))
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

    max_bytes: int = 64 * 1024 * 1024
    max_depth: int = 500
    max_elements: int = 1_000_000

    def __post_init__(self) -> None:
        for name in ("max_bytes", "max_depth", "max_elements"):
            check_count(f"ParseLimits.{name}", getattr(self, name))


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
        found = self.assets.get(file)
        if found is None:
            found = self.assets.get(os.path.basename(file.replace("\\", "/")))
        return found


DEFAULT_OPTIONS: Final = ParseOptions()


def source_line(node: XmlNode) -> int | None:
    """The line libxml2 gives ``node``: where its start tag ends, if known."""
    line: object = node.sourceline  # lxml-stubs types it loosely
    return line if isinstance(line, int) else None


def root_class() -> type[ModelBase]:
    """The generated class of the root row (``<mujoco>``)."""
    for cls in _tree.element_classes().values():
        if issubclass(cls, ModelBase):
            return cls
    raise RuntimeError("no generated root class is registered")  # pragma: no cover


# ----------------------------------------------------------------------------- context


@dataclass
class _Include:
    """One level of ``<include>``: the file read, and the include element that read it."""

    path: str
    by: str | None  # the including file (None: text given in memory)
    at: int | None  # the line libxml2 gives the <include> (where its start tag ends)
    text: SourceText | None = None  # the including file's text

    @property
    def line(self) -> int | None:
        """The line the ``<include>`` start tag begins on, found when a message asks (it
        indexes the including file's lines: work a model read without errors never needs)."""
        if self.at is None or self.text is None:
            return self.at
        return self.text.start_line(self.at, INCLUDE)


@dataclass
class _Context:
    base_dir: str | None
    limits: ParseLimits = DEFAULT_LIMITS
    main: str | None = None  # the main model file, if the model was read from one
    bytes_read: int = 0
    elements: int = 0
    included: dict[str, _Include] = field(default_factory=lambda: {})  # every file, how first read
    nesting: list[_Include] = field(default_factory=lambda: [])  # includes around the current one
    options: ParseOptions = field(default_factory=lambda: DEFAULT_OPTIONS)
    confinement: Confinement = ANYWHERE  # where included files may be read
    texts: dict[str | None, SourceText] = field(default_factory=lambda: {})  # each source read
    long_tags: bool = False  # a text read may hold a start tag with many attributes
    ignored: int = 0  # attributes dropped with an IgnoredAttributeWarning

    def shown(self, path: str | None) -> str:
        """A path as messages show it: relative to the main file's folder when inside it."""
        if path is None:
            return "<text>"
        if self.base_dir is not None:
            try:
                relative = os.path.relpath(path, self.base_dir)
            except ValueError:  # another drive (Windows)
                return path
            if not relative.startswith(os.pardir):
                return relative
        return path

    def line(self, node: XmlNode, source: str | None) -> int | None:
        """The line ``node``'s start tag begins on in ``source``, if known."""
        line = source_line(node)
        text = self.texts.get(source)
        tag: object = node.tag
        if line is None or text is None or not isinstance(tag, str):
            return line
        return text.start_line(line, tag)

    def leave_include(self) -> None:
        self.nesting.pop()

    def refuse(self, rule: str, path: str, error: ParseError) -> None:
        """Raise ``error``, or pass it on and go on when the parse collects problems."""
        on_problem = self.options.on_problem
        if on_problem is None:
            raise error from None
        on_problem(Problem(rule, path, error))

    def error(self, message: str, source: str | None, line: int | None,
              kind: type[ParseError] = ParseError) -> ParseError:
        """A ParseError at ``source:line``, saying which includes led there."""
        levels = [f"in {self.shown(level.path)}, included from {self.shown(level.by)}"
                  + (f":{level.line}" if level.line is not None else "")
                  for level in reversed(self.nesting)]
        if levels:
            message += f" ({'; '.join(levels)})"
        return kind(message, source, line)


# ----------------------------------------------------------------------------- reading XML


def _refuse_entity_declarations(data: bytes, source: str | None, context: _Context) -> None:
    """Refuse ``<!ENTITY`` in a DOCTYPE before the XML parser can expand anything.

    MuJoCo does not expand declared entities, and they are the means of entity-expansion
    bombs. NUL bytes are dropped first, so UTF-16 and UTF-32 text is checked too.
    """
    text = data.replace(b"\0", b"") if b"\0" in data else data
    doctype = text.find(b"<!DOCTYPE")
    if doctype >= 0 and text.find(b"<!ENTITY", doctype) >= 0:
        line = text.count(b"\n", 0, text.find(b"<!ENTITY", doctype)) + 1
        raise context.error(
            "entity declarations (<!ENTITY ...>) are not allowed: MJCF does not use them "
            "and MuJoCo does not expand them", source, line)


def has_long_stretch(data: bytes, length: int = _LONG_STRETCH) -> bool:
    """Whether a "<" in ``data`` is followed by ``length`` bytes without one. Each window
    after a "<" is searched from its end (the last "<" in it starts the next window), so a
    text is crossed in about ``len(data) / length`` searches: a regular expression tried
    every "<" (a tenth of the time of reading a small model)."""
    at = data.find(b"<")
    while 0 <= at and at + length < len(data):
        last = data.rfind(b"<", at + 1, at + 1 + length)
        if last < 0:
            return True
        at = last
    return False


def _name(name: object, limit: int = 60) -> str:
    """A tag or attribute name for a message, shortened if (absurdly) long."""
    text = str(name)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _limit_message(what: str, limit: int, name: str) -> str:
    return (f"{what}, more than the limit of {limit} (ParseLimits.{name}); to read it anyway, "
            f"pass limits=typed_mjcf.ParseLimits({name}=...) with a larger value")


def _syntax_error(error: etree.XMLSyntaxError, source: str | None, context: _Context,
                  depth_limit: int) -> ParseError:
    line = error.lineno if error.lineno else None
    message = str(error.msg)
    if "Excessive depth" in message:
        if depth_limit < _XML_READER_DEPTH:
            return context.error(_limit_message(
                "elements are nested too deep", context.limits.max_depth, "max_depth"),
                source, line)
        return context.error(f"elements are nested more than {_XML_READER_DEPTH} deep, the "
                             f"most the XML reader can read in one file", source, line)
    return context.error(f"malformed XML: {message}", source, line)


def _read_xml(data: bytes, source: str | None, context: _Context, *,
              encoding: str | None = None) -> XmlNode:
    """Parse one document, counting its bytes, depth and elements against the limits."""
    limits = context.limits
    if context.bytes_read + len(data) > limits.max_bytes:
        raise context.error(_limit_message(
            f"the model text is at least {context.bytes_read + len(data)} bytes long",
            limits.max_bytes,
            "max_bytes"), source, None)
    context.bytes_read += len(data)
    context.texts[source] = SourceText(data)
    if not context.long_tags and has_long_stretch(data):
        context.long_tags = True
    _refuse_entity_declarations(data, source, context)
    depth_limit = min(limits.max_depth, _XML_READER_DEPTH)
    # Every element starts with "<" (entities are refused, so none expand into elements):
    # text with fewer "<" than the elements still allowed is read without watching each
    # element go by; the builder counts them, and checks the depth, exactly.
    watch = data.count(b"<") > limits.max_elements - context.elements
    parser: etree.XMLParser
    if watch:
        parser = etree.XMLPullParser(
            events=("start", "end"), encoding=encoding, resolve_entities=False,
            no_network=True, load_dtd=False, remove_comments=True, remove_pis=True,
            huge_tree=True)
    else:
        parser = etree.XMLParser(
            encoding=encoding, resolve_entities=False, no_network=True, load_dtd=False,
            remove_comments=True, remove_pis=True, huge_tree=True)
    depth, elements = 0, context.elements
    try:
        # libxml2's push parser does not recurse, however deep the nesting. Text watched
        # for its elements is fed in chunks, to stop as soon as a limit is passed; other text
        # in one call (a slice of all of a bytes object is that object: nothing is copied).
        chunk = _CHUNK if watch else max(len(data), 1)
        for start in range(0, max(len(data), 1), chunk):
            parser.feed(data[start:start + chunk])
            if not isinstance(parser, etree.XMLPullParser):
                continue
            for event, node in parser.read_events():  # stop as soon as a limit is passed
                if event == "end":
                    depth -= 1
                    continue
                depth += 1
                elements += 1
                if depth > depth_limit:
                    raise context.error(_limit_message(
                        f"<{_name(node.tag)}> is nested {depth} deep", limits.max_depth,
                        "max_depth"), source, context.line(node, source))
                if elements > limits.max_elements:
                    raise context.error(_limit_message(
                        f"the model has more than {elements - 1} elements",
                        limits.max_elements, "max_elements"), source, context.line(node, source))
        root = parser.close()
    except etree.XMLSyntaxError as error:
        if not error.lineno:
            error = _located(data, encoding) or error
        raise _syntax_error(error, source, context, depth_limit) from None
    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None and any(True for _ in dtd.iterentities()):  # an encoding not scanned
        raise context.error("entity declarations (<!ENTITY ...>) are not allowed: MJCF does "
                            "not use them and MuJoCo does not expand them", source, 1)
    return root


def _located(data: bytes, encoding: str | None) -> etree.XMLSyntaxError | None:
    """The error of a document the streaming parser gave up on without saying where (an
    undefined entity, say), from libxml2's ordinary parser, if it has a line.

    Only for the message: the limits were checked up to that point, entity declarations are
    refused already, and without ``huge_tree`` libxml2 stops at 256 levels of nesting.
    """
    parser = etree.XMLParser(encoding=encoding, resolve_entities=False, no_network=True,
                             load_dtd=False, huge_tree=False)
    try:
        etree.fromstring(data, parser)
    except etree.XMLSyntaxError as error:
        return error if error.lineno else None
    return None


def read_bounded(read: Callable[[int], bytes], limit: int, expected: int = 0) -> bytes:
    """Read until the end or until more than ``limit`` bytes are read (one more byte than
    allowed shows that the limit is passed), without allocating for the limit up front."""
    chunks: list[bytes] = []
    total = 0
    size = min(max(expected, 0), limit) + 1
    while total <= limit:
        chunk = read(min(size, limit + 1 - total))
        if not chunk:
            break
        chunks.append(chunk)
        total += len(chunk)
        size = 1 << 20
    return b"".join(chunks)


def _the_file() -> str:  # what a message calls the main file (see _read_file's ``what``)
    return "the file"


def _read_file(path: str, context: _Context, what: Callable[[], str], where: str | None,
               by: _Include | None, confinement: Confinement = ANYWHERE) -> bytes:
    """A file's bytes, refusing what ``confinement`` does not allow, what is not a regular
    file and what passes ``max_bytes``; a message names the line of the include ``by``."""
    try:
        remaining = max(context.limits.max_bytes - context.bytes_read, 0)
        with open_confined(path, confinement) as f:
            return read_bounded(f.read, remaining, os.fstat(f.fileno()).st_size)
    except Refused as refused:
        raise context.error(f"cannot read {what()}: {refused}", where,
                            None if by is None else by.line, FileAccessError) from None
    except OSError as error:
        reason = error.strerror or str(error)
        raise context.error(f"cannot read {what()}: {reason}", where,
                            None if by is None else by.line, FileReadError) from None


def _encode(text: str, source: str | None, context: _Context) -> bytes:
    try:
        return text.encode("utf-8")
    except UnicodeEncodeError as error:  # lone surrogates
        line = text.count("\n", 0, error.start) + 1
        raise context.error(f"the text holds a character that is not valid Unicode "
                            f"({text[error.start]!r} at offset {error.start})", source,
                            line) from None


def is_model_text(data: bytes) -> bool:
    """Whether ``data`` is MJCF text: XML whose root element is the model's root."""
    try:
        node = _read_xml(data, None, _Context(None))
    except ParseError:
        return False
    return node.tag == root_class().spec.tag


# ----------------------------------------------------------------------------- entry points


def parse_text(data: object, *, base_dir: str | None = None, source: str | None = None,
               limits: ParseLimits | None = None, options: ParseOptions = DEFAULT_OPTIONS,
               access: FileAccess | Confinement = DEFAULT_ACCESS) -> ModelBase:
    """Parse MJCF text into a model that reads files where ``access`` allows (by default in
    ``base_dir``, else the current folder)."""
    context = _Context(base_dir, limits or DEFAULT_LIMITS, options=options,
                       confinement=_confinement(access, base_dir))
    return _guarded(lambda: _parse_text(data, source, context), source)


def _parse_text(data: object, source: str | None, context: _Context) -> ModelBase:
    if isinstance(data, str):
        node = _read_xml(_encode(data, source, context), source, context, encoding="utf-8")
    elif isinstance(data, bytes):
        node = _read_xml(data, source, context)
    elif isinstance(data, bytearray):
        node = _read_xml(bytes(data), source, context)
    else:
        raise InvalidTypeError(f"MJCF text must be str or bytes, got {type(data).__name__}")
    return _build_model(node, context, source)


def parse_path(path: str, *, limits: ParseLimits | None = None,
               options: ParseOptions = DEFAULT_OPTIONS,
               access: FileAccess | Confinement = DEFAULT_ACCESS) -> ModelBase:
    """Parse an MJCF file; its folder is the base of relative paths and, by default, the
    only folder the model reads files from (see ``access``)."""
    path = os.path.abspath(path)
    folder = os.path.dirname(path)
    context = _Context(folder, limits or DEFAULT_LIMITS, main=path, options=options,
                       confinement=_confinement(access, folder))
    return _guarded(lambda: _parse_path(path, context), path)


def _confinement(access: FileAccess | Confinement, folder: str | None) -> Confinement:
    return access if isinstance(access, Confinement) else confine(access, folder)


def _parse_path(path: str, context: _Context) -> ModelBase:
    data = _read_file(path, context, _the_file, path, None)
    context.included[path] = _Include(path, None, None)
    node = _read_xml(data, path, context)
    return _build_model(node, context, path)


def _guarded(parse: Callable[[], ModelBase], source: str | None) -> ModelBase:
    """Run ``parse``; a failure that is not the library's own error becomes a ParseError.

    Such a failure is a bug in typed-mjcf; the original exception is kept as the cause.
    """
    try:
        return parse()
    except (MjcfError, Warning):  # a warning the caller's filters turned into an error
        raise
    except (RecursionError, MemoryError) as error:
        raise ParseError(f"the model is too large or too deeply nested to read "
                         f"({type(error).__name__})", source) from error
    except Exception as error:
        raise ParseError(f"internal error while reading the model: {type(error).__name__}: "
                         f"{error}", source) from error


# ----------------------------------------------------------------------------- building


def _build_model(node: XmlNode, context: _Context, source: str | None) -> ModelBase:
    cls = root_class()
    if node.tag != cls.spec.tag:
        raise context.error(f"the root element is <{_name(node.tag)}>, expected <{cls.spec.tag}>",
                            source, context.line(node, source))
    model = _tree.new_model(cls)
    _tree.set_base_dir(model, context.base_dir)
    _tree.set_file_access(model, context.confinement)
    _tree.memory_files(model).update(context.options.assets)
    sources = _tree.SourceMap(source)
    sources.add(model, source, node.sourceline)
    _tree.set_source_map(model, sources)
    with collector_paused():  # a parse creates only objects that live on
        _set_attributes(model, node, source, context)
        _Builder(context, sources).run(model, node, source)
        if FLAGS.named_after_files:  # as dm_control's parser: files name meshes..., then
            _tree.COMPAT.name_after_files(model)  # the references are resolved
        if FLAGS.references_stay_names and context.options.resolve_references:
            _tree.resolve_references(model)  # (nothing waits for a name)
    return model


def _set_attributes(element: Element, node: XmlNode, source: str | None,
                    context: _Context) -> None:
    """Read ``node``'s attributes into ``element``."""
    items = attributes_of(node) if context.long_tags else node.items()
    options = context.options
    rest = _tree.assign_texts(element, items, not options.escape_separators,
                              options.resolve_references)
    if rest is not None:
        _read_rest(element, rest, node, source, context)


def attributes_of(node: XmlNode) -> list[tuple[str, str]]:
    """``node.items()`` in time linear in their number (XPath lists them in one pass)."""
    if len(node.attrib) <= _MANY_ATTRIBUTES:
        return node.items()
    found = cast("list[_XPathAttribute]", node.xpath("@*"))
    return [(value.attrname, str(value)) for value in found]


class _XPathAttribute(Protocol):
    """An attribute's value as XPath gives it: a string that knows its attribute's name."""

    attrname: str


def _read_rest(element: Element,
               rest: list[tuple[str, AttributeSpec | None, str, Exception | None]],
               node: XmlNode, source: str | None, context: _Context) -> None:
    """Read the attributes of ``node`` (into ``element``) that :func:`_tree.assign_texts`
    refused or left (references, empty texts, ones the row lacks); references whose
    namespace another attribute names (``objname`` by ``objtype``) last."""
    later: list[tuple[AttributeSpec, str]] | None = None
    for key, attribute, text, refused in rest:
        if attribute is not None and isinstance(refused, Rejected):
            context.refuse("invalid-value", element.path, _rejected(
                element, attribute, text, refused, node, source, context))
        elif refused is not None:
            _refuse_name(element, refused, node, source, context)
        else:
            later = _set_other(element, attribute, key, text, node, source, context, later)
    for attribute, text in later or ():
        _set_text(element, attribute, text, node, source, context)


def _refuse_name(element: Element, error: Exception, node: XmlNode, source: str | None,
                 context: _Context) -> None:
    rule = "duplicate-name" if isinstance(error, DuplicateIdentifierError) else "invalid-value"
    context.refuse(rule, element.path, context.error(str(error), source,
                                                     context.line(node, source)))


def _rejected(element: Element, attribute: AttributeSpec, text: str, rejected: Rejected,
              node: XmlNode, source: str | None, context: _Context) -> ParseError:
    error = _tree.rejection(element, attribute, text, rejected)
    return context.error(str(error), source, context.line(node, source))


def _set_other(element: Element, attribute: AttributeSpec | None, key: str, text: str,
               node: XmlNode, source: str | None, context: _Context,
               later: list[tuple[AttributeSpec, str]] | None,
               ) -> list[tuple[AttributeSpec, str]] | None:
    """Read an attribute that is not a plain value: a name, a reference, an empty value, one
    the row lacks; references whose namespace another attribute names are added to
    ``later``."""
    if attribute is None:
        known = list(element.spec.by_name)
        if element.spec.ignores_unknown:
            context.ignored += 1
            if context.ignored > _SUGGESTED:  # a suggestion costs ~0.1 ms: bound the total
                known = []
            _warn_ignored(element, _name(key), text, known, source, context.line(node, source))
            return later
        missing = name_note(element.spec, key)
        context.refuse("unknown-attribute", element.path, context.error(
            f"{element.path}: <{element.spec.tag}> has no attribute {_name(key)!r}"
            + (f": it {missing}" if missing else did_you_mean(_name(key), known)),
            source, context.line(node, source)))
        return later
    if attribute.kind == "id":
        name = text
        if context.options.escape_separators:
            name = escape_separators(name)
        try:
            _tree.assign_text(element, attribute, name)
        except Rejected as rejected:
            context.refuse("invalid-value", element.path,
                           _rejected(element, attribute, name, rejected, node, source, context))
        except MjcfError as error:
            _refuse_name(element, error, node, source, context)
        return later
    if attribute.namespace_from is not None:
        later = [] if later is None else later
        later.append((attribute, text))
        return later
    _set_text(element, attribute, text, node, source, context)
    return later


def _warn_ignored(element: Element, key: str, text: str, known: list[str],
                  source: str | None, line: int | None) -> None:
    path = element.path
    suggestion = did_you_mean(key, known) if known else ""
    warnings.warn(IgnoredAttributeWarning(
        f"<{element.spec.tag}> ({path}) has no attribute {key}={_name(repr(text))}"
        f"{suggestion}; MuJoCo ignores it, and so it is dropped",
        source, line, path), stacklevel=_outside_package())


_PACKAGE_DIR: Final = PACKAGE_DIR + os.sep


def _outside_package() -> int:
    """The ``stacklevel`` of the first caller outside typed-mjcf (the user's ``from_path``
    line), for :func:`warnings.warn`."""
    frame = inspect.currentframe()
    # Interpreted, this function's frame is first and stacklevel 1 is its caller; compiled,
    # typed-mjcf's compiled functions have no frames and stacklevel 1 is the first there is.
    level = 0 if frame is not None and frame.f_code.co_name == "_outside_package" else 1
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE_DIR):
        frame = frame.f_back
        level += 1
    return level


def escape_separators(name: str) -> str:
    """dm_control's escaping of the scope separator in a name read from a file."""
    return name.replace("/", "\\/")


def _set_text(element: Element, attribute: AttributeSpec, text: str, node: XmlNode,
              source: str | None, context: _Context) -> None:
    options = context.options
    if options.escape_separators and attribute.is_reference:
        text = escape_separators(text)
    try:
        _tree.assign_text(element, attribute, text, link=options.resolve_references)
    except Rejected as rejected:
        context.refuse("invalid-value", element.path,
                       _rejected(element, attribute, text, rejected, node, source, context))
    except MjcfError as error:
        context.refuse("invalid-value", element.path,
                       context.error(str(error), source, context.line(node, source)))


# Children still to read into an element: (element, its remaining XML children, the file
# they are in, the element's depth in the assembled model (the root is 1), where the chain of
# same-tag ancestors of the element starts (or the element), what to run once all are read).
_Frame = tuple[Element, Iterator[XmlNode], str | None, int, Element, Callable[[], None] | None]


class _Builder:
    """Builds the typed tree from XML with an explicit stack (no recursion)."""

    def __init__(self, context: _Context, sources: _tree.SourceMap) -> None:
        self.context = context
        self.sources = sources
        self.stack: list[_Frame] = []
        self.nested: list[tuple[Element, Element]] = []  # (class, its section), not counted
        self.hierarchies: dict[int, _Hierarchy] = {}  # by id(section): repeated hierarchies
        # Once-only children may repeat only in a repeated section (MuJoCo reads each on its
        # own): how many times each element was merged into, and that count for its parent
        # when a child was read (missing: 0).
        self.merged: dict[Element, int] = {}
        self.read_in: dict[Element, int] = {}

    def run(self, root: Element, node: XmlNode, source: str | None) -> None:
        context, stack = self.context, self.stack
        # where each element was read (SourceMap.add, inline: it is per element)
        # (direct calls, not local aliases of functions and bound methods: compiled, an
        # alias is a Python-level call where a direct call is a C call)
        sources = self.sources
        order, line_numbers = sources.order, sources.line_numbers
        files, main = sources.files, sources.main
        max_depth, max_elements = context.limits.max_depth, context.limits.max_elements
        names = not context.options.escape_separators  # the tree claims names as read
        link = context.options.resolve_references  # (and links references)
        long_tags = context.long_tags  # (read again after an include)
        merged = self.merged
        self.count(node, source, 1)  # the root
        stack.append((root, iter(node), source, 1, root, None))
        # the frame on top of the stack, unpacked: reloaded whenever the stack changes
        parent, nodes, source, depth, top, on_exit = stack[-1]
        parent_spec = type(parent).spec
        child_specs, parent_tag = parent_spec.children, parent_spec.tag
        while True:
            child_node = next(nodes, None)
            if child_node is None:
                stack.pop()
                if on_exit is not None:
                    on_exit()
                if not stack:
                    return
                parent, nodes, source, depth, top, on_exit = stack[-1]
                parent_spec = type(parent).spec
                child_specs, parent_tag = parent_spec.children, parent_spec.tag
                continue
            tag: object = child_node.tag
            if not isinstance(tag, str):
                continue  # entity references (comments and processing instructions are dropped)
            context.elements += 1
            if context.elements > max_elements:
                self.count(child_node, source)
            if tag == INCLUDE:
                self.include(stack[-1], child_node)
                long_tags = context.long_tags
                parent, nodes, source, depth, top, on_exit = stack[-1]
                parent_spec = type(parent).spec
                child_specs, parent_tag = parent_spec.children, parent_spec.tag
                continue
            child_spec = child_specs.get(tag)
            if child_spec is None:
                legal = list(child_specs)
                missing = name_note(parent.spec, tag)
                context.refuse("illegal-child", parent.path, context.error(
                    f"<{_name(tag)}> is not a legal child of <{parent.spec.tag}> ({parent.path})"
                    + (f": it {missing}" if missing else did_you_mean(_name(tag), legal)),
                    source, context.line(child_node, source)))
                continue  # read past: the child and what is inside it are left out
            if depth >= max_depth:
                raise context.error(_limit_message(
                    f"<{tag}> is nested {depth + 1} deep", max_depth, "max_depth"),
                    source, context.line(child_node, source))
            if child_spec.single:
                existing = _tree.single_child(parent, tag)
                if existing is not None:
                    if child_spec.once:
                        self.repeat(parent, existing, child_node, source)
                    # A repeated section: merge into the first.
                    check = self.merge(existing, child_node, source)
                    stack.append((existing, iter(child_node), source, depth + 1, existing,
                                  check))
                    parent, nodes, source, depth, top, on_exit = stack[-1]
                    parent_spec = type(parent).spec
                    child_specs, parent_tag = parent_spec.children, parent_spec.tag
                    continue
            child = _tree.new_child(parent, child_spec)
            if merged and parent in merged:
                self.read_in[child] = merged[parent]
            order.append(child)
            line_numbers.append(child_node.sourceline or 0)
            if source is not main:
                files[child] = source
            items = attributes_of(child_node) if long_tags else child_node.items()
            if items:  # values and names by the tree, the rest here
                rest = _tree.assign_texts(child, items, names, link)
                if rest is not None:
                    _read_rest(child, rest, child_node, source, context)
            child_top = child
            if tag == parent_tag:
                child_top = top
                above = _tree.parent_of(top)
                if above is not None and above.spec.children[top.spec.tag].single:
                    self.nested.append((child, top))  # a class of a section that may repeat
            if len(child_node):
                stack.append((child, iter(child_node), source, depth + 1, child_top, None))
                parent, nodes, source, depth, top, on_exit = stack[-1]
                parent_spec = type(parent).spec
                child_specs, parent_tag = parent_spec.children, parent_spec.tag

    def count(self, node: XmlNode, source: str | None, elements: int = 0) -> None:
        """Count ``elements`` more (or check the count); refuse past ``max_elements``."""
        context = self.context
        context.elements += elements
        if context.elements > context.limits.max_elements:
            raise context.error(_limit_message(
                f"the model has more than {context.elements - 1} elements",
                context.limits.max_elements, "max_elements"), source, context.line(node, source))

    def repeat(self, parent: Element, existing: Element, node: XmlNode,
               source: str | None) -> None:
        """Refuse a second once-only child ``node`` of ``parent`` in one XML element (MuJoCo
        refuses it: "unique element found 2 times"); one in a repeated section is read."""
        occurrence = self.merged.get(parent, 0)
        if self.read_in.get(existing, 0) != occurrence:
            self.read_in[existing] = occurrence
            return
        context, tag = self.context, existing.spec.tag
        first, line = self.sources.get(existing) or (None, None)
        text = context.texts.get(first)
        if text is not None and line is not None:
            line = text.start_line(line, tag)
        where = ("" if line is None else
                 f" (the first is at {context.shown(first)}:{line})" if first != source else
                 f" (the first is on line {line})")
        raise context.error(
            f"a second <{tag}> in {parent.path}{where}: MuJoCo allows one <{tag}> in "
            f"<{parent.spec.tag}> and refuses the file", source, context.line(node, source))

    def merge(self, section: Element, node: XmlNode,
              source: str | None) -> Callable[[], None] | None:
        """Merge a repeated once-only section's attributes into the first one; return the
        check to run once its children are read too (see :class:`_Hierarchy`)."""
        context = self.context
        self.merged[section] = self.merged.get(section, 0) + 1
        if section.spec.tag not in section.spec.children:
            _set_attributes(section, node, source, context)
            return None
        hierarchy = self.hierarchies.get(id(section))
        if hierarchy is None:
            hierarchy = self.hierarchies[id(section)] = _Hierarchy(section)
        remaining: list[tuple[Element, Element]] = []
        for nested, top in self.nested:  # the classes read since the last repeat
            if top is section:
                hierarchy.add(nested)
            else:
                remaining.append((nested, top))
        self.nested = remaining
        count = len(hierarchy.classes)
        before = _section_defaults(section) if count else {}
        _set_attributes(section, node, source, context)
        if not count:
            return None
        nesting = list(context.nesting)

        def check() -> None:
            for key, value in _section_defaults(section).items():
                if key in before and _same_stored_value(before[key], value):
                    continue
                hierarchy_class = hierarchy.uncovered(key)
                if hierarchy_class is None:
                    continue
                element_tag, attribute = key
                name = _tree.element_name(hierarchy_class)
                label = repr(name) if name is not None else hierarchy_class.path
                saved, context.nesting = context.nesting, nesting
                error = context.error(
                    f"this repeated <{section.tag}> section sets <{element_tag} {attribute}> "
                    f"for the whole model, but MuJoCo does not apply it to {section.tag} class "
                    f"{label} of an earlier <{section.tag}> section (a class keeps the values "
                    f"it inherited when it was defined); set {attribute} in that class, or "
                    f"move it into the first <{section.tag}> section", source,
                    context.line(node, source))
                context.nesting = saved
                raise error

        return check

    def include(self, frame: _Frame, node: XmlNode) -> None:
        parent, _, source, depth, top, _ = frame
        context = self.context
        file = node.get("file")
        if not file:
            raise context.error("<include> needs a file attribute", source,
                                context.line(node, source))
        unexpected = [str(key) for key in node.attrib if key != "file"]
        if unexpected or len(node):
            what = f"attribute {_name(unexpected[0])!r}" if unexpected else "children"
            raise context.error(f"<include> takes only a file attribute, not {what}",
                                source, context.line(node, source))
        base = context.base_dir or os.getcwd()  # MuJoCo: relative to the main file's folder
        path = os.path.abspath(os.path.join(base, file))
        level = _Include(path, source, source_line(node), context.texts.get(source))
        chain = [level.path for level in context.nesting]
        if context.main is not None:
            chain.insert(0, context.main)
        if path in chain:
            shown = " -> ".join(context.shown(p) for p in [*chain, path])
            raise context.error(f"include cycle: {context.shown(source)} includes {file!r}, "
                                f"which is already being read: {shown}", source, level.line)
        first = context.included.get(path)
        if first is not None:
            where = ("is the main model file" if first.by is None else
                     f"was already included by {context.shown(first.by)}"
                     + (f":{first.line}" if first.line is not None else ""))
            raise context.error(f"{file!r} ({context.shown(path)}) {where}; MuJoCo includes "
                                f"a file at most once per model", source, level.line)
        given = context.options.asset(file)
        data = given if given is not None else _read_file(
            path, context, lambda: f"included file {file!r} ({context.shown(path)})", source, level,
            context.confinement)
        context.included[path] = level
        self.sources.includes[path] = (source, parent)
        context.nesting.append(level)
        included_root = _read_xml(data, path, context)
        self.count(included_root, path, 1)
        self.stack.append((parent, iter(included_root), path, depth, top,
                           context.leave_include))


# ----------------------------------------------------------------------------- repeated sections

_Key = tuple[str, str]  # (element tag, attribute) of a default


class _Hierarchy:
    """The classes of a section that nests itself (``<default>``), for merging repeats.

    MuJoCo reads repeated sections in order, so merging keeps their meaning, with one
    exception: a section that nests itself is a class hierarchy, and MuJoCo gives a class a
    copy of its parent's defaults as they are when the class is read. Main defaults that a
    later ``<default>`` section sets or changes therefore do not reach the classes of earlier
    sections, but would after merging; such a model is refused rather than silently changed.

    To check that in time linear in the model, the classes read so far are counted, and so
    are, for each ``(tag, attribute)``, the classes that set it themselves or through a
    parent class (those keep their own value whatever the main default is).
    """

    def __init__(self, section: Element) -> None:
        self.section = section
        self.classes: list[Element] = []  # every class of the section, in document order
        self.covered: dict[_Key, int] = {}  # classes whose chain sets the key
        self.chains: dict[int, frozenset[_Key]] = {}  # by id(class): the keys its chain sets

    def add(self, hierarchy_class: Element) -> None:
        """Count a class that is completely read."""
        parent = hierarchy_class.parent
        none: frozenset[_Key] = frozenset()
        inherited = (self.chains.get(id(parent), none)
                     if parent is not None and parent is not self.section else none)
        chain = inherited.union(_element_defaults(hierarchy_class).keys())  # a frozenset
        self.chains[id(hierarchy_class)] = chain
        self.classes.append(hierarchy_class)
        for key in chain:
            self.covered[key] = self.covered.get(key, 0) + 1

    def uncovered(self, key: _Key) -> Element | None:
        """The first class that takes ``key`` from the main defaults, if one does."""
        if self.covered.get(key, 0) == len(self.classes):
            return None
        for hierarchy_class in self.classes:
            if key not in self.chains[id(hierarchy_class)]:
                return hierarchy_class
        return None


def _section_defaults(section: Element) -> dict[_Key, object]:
    """The attributes a section sets on its element children (not on nested classes)."""
    return _element_defaults(section)


def _element_defaults(level: Element) -> dict[_Key, object]:
    """The attributes a hierarchy level sets on its element children, by (tag, attribute)."""
    found: dict[_Key, object] = {}
    own_tag = level.spec.tag
    for tag, child_spec in level.spec.children.items():
        if tag == own_tag:
            continue  # nested classes: not walked (a level holds any number of them)
        if child_spec.single:  # by tag, in constant time
            child = _tree.single_child(level, tag)
            children: Sequence[Element] = () if child is None else (child,)
        else:
            children = _tree.children_with_tag(level, tag)
        for child in children:
            for name, value in _tree.values(child).items():
                found[(tag, name)] = value
    return found


def _same_stored_value(a: object, b: object) -> bool:
    """Whether two values as the tree stores them are the same (an array equals only an
    array of the same numbers: a value stored otherwise was set otherwise)."""
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        return bool(np.array_equal(cast(_Array, a), cast(_Array, b)))
    return not isinstance(a, np.ndarray) and not isinstance(b, np.ndarray) and a == b
