"""``typed-mjcf fmt``: lay MJCF files out consistently, changing as little as it can.

By default fmt keeps what the author wrote: attributes in their order and spelling (numbers,
keywords, quotes aside: values are written in double quotes), start tags broken across lines
where the author broke them, elements where they are (repeated sections are not merged),
comments, processing instructions, stray text (MuJoCo ignores text) and ``<include>``
elements. It indents by two spaces per level, writes one element per line, keeps at most one
blank line in a row, and breaks a start tag longer than 100 characters before the attribute
that passes the width (aligned with its first attribute). ``--canonical`` writes instead what
typed-mjcf's exporter writes with ``canonical=True`` (attributes in grammar order, numbers in
the shortest text that reads back exactly, keywords in their grammar spelling, no empty
attributes or empty once-only sections, one line per start tag), keeping the same structure.
A model's included files are formatted with it, each in the context it is included in.
"""

from __future__ import annotations

import argparse
import difflib
import itertools
import os
import re
import shutil
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass

from lxml import etree

from typed_mjcf import tooling
from typed_mjcf.cli._common import (
    BAD_INPUT,
    FOUND,
    OK,
    BadInput,
    Progress,
    error,
    load,
    location,
    shown,
)
from typed_mjcf.cli._starttags import WIDTH, StartTag, indent_unit, lay_out, start_tags
from typed_mjcf.cli._values import canonical_text
from typed_mjcf.tooling import (
    INCLUDE,
    MAX_INDENT,
    ElementSpec,
    Rejected,
    escape,
    root_class,
    start_line,
)
from typed_mjcf.types import XmlElement

NAME = "fmt"
HELP = ("lay MJCF files out consistently, keeping what was written (comments, spelling, "
        "order); --canonical rewrites them in the exporter's canonical form")
DESCRIPTION = """\
Lay MJCF files out consistently: two-space indentation, one element per line, at most one
blank line in a row, start tags longer than 100 characters broken before the attribute that
passes the width. What the author wrote is kept: attribute order and spelling ("0.10" stays
"0.10"), where a start tag was broken across lines, element order, repeated sections,
comments, <include> elements, and text inside elements (MJCF has none and MuJoCo ignores
it, but fmt does not drop it).

--canonical writes the canonical form instead (what to_xml_string(canonical=True) writes):
attributes in MuJoCo's grammar order, numbers in the shortest form that reads back exactly
("0.10" -> "0.1", "1.0" -> "1"), keywords in their grammar spelling, one line per start tag;
empty attributes and empty once-only sections (<compiler/>) are dropped.

The files a model includes are formatted too, each in the place it is included. The result
compiles to the same model, and formatting it again changes nothing.

exit status: 0 formatted (or nothing to change), 1 with --check: some file would change,
2 a file cannot be read as MJCF (other files are still formatted)."""

_DECLARATION = re.compile(rb"<\?xml\s")
# a declaration fmt may keep as written: it says nothing of the encoding, or says UTF-8
_PLAIN_DECLARATION = re.compile(rb"<\?xml\s[^>]*?\?>")
_ENCODING = re.compile(rb"encoding\s*=\s*[\"']([^\"']*)[\"']")
_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                          remove_comments=False, remove_pis=False, huge_tree=True)


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("files", nargs="+", metavar="MODEL.xml", help="the models to format")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; list the files that would change (exit 1 if any)")
    parser.add_argument("--diff", action="store_true",
                        help="write nothing; show the changes as a unified diff")
    parser.add_argument("--width", type=int, default=WIDTH, metavar="N",
                        help=f"break start tags longer than N characters (default {WIDTH}; "
                             "0: never break a tag the author did not break)")
    parser.add_argument("--canonical", action="store_true",
                        help="write the canonical form: attributes in grammar order, numbers "
                             "in the shortest exact form, one line per start tag")
    parser.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                        help="show progress on stderr (default: for several files, on a "
                             "terminal)")
    parser.set_defaults(run=run)


@dataclass
class Formatted:
    """One file: its path, its text now, and its canonical text."""

    path: str
    before: bytes
    after: str

    @property
    def changed(self) -> bool:
        return self.before != self.after.encode("utf-8")


def run(args: argparse.Namespace) -> int:
    files: list[str] = args.files
    write = not (args.check or args.diff)
    status = OK
    seen: set[str] = set()
    changed = unchanged = 0
    progress = Progress(len(files), args.progress)
    for file in progress.each(files, "formatting"):
        try:
            results = format_model(file, seen, canonical=args.canonical, width=args.width)
            for result in results:
                if result.changed and write:
                    _replace(result.path, result.after)
        except BadInput as problem:
            progress.clear()
            error("fmt", str(problem))
            status = BAD_INPUT
            continue
        except OSError as problem:
            progress.clear()
            error("fmt", f"{shown(problem.filename)}: cannot write: {problem.strerror}")
            status = BAD_INPUT
            continue
        for result in results:
            if not result.changed:
                unchanged += 1
                continue
            changed += 1
            progress.clear()
            if args.diff:
                sys.stdout.write(unified_diff(result))
            if args.check:
                print(f"would reformat {shown(result.path)}")
            elif write:
                print(f"reformatted {shown(result.path)}")
    if args.check and changed and status == OK:
        status = FOUND
    verb = "would be reformatted" if not write else "reformatted"
    summary = f"{_files(changed)} {verb}, {_files(unchanged)} already formatted"
    print(summary, file=sys.stderr if args.diff else sys.stdout)
    return status


def _files(n: int) -> str:
    return f"{n} file" if n == 1 else f"{n} files"


def unified_diff(result: Formatted) -> str:
    before = result.before.decode("utf-8", "replace").splitlines(keepends=True)
    after = result.after.splitlines(keepends=True)
    name = shown(result.path)
    lines = difflib.unified_diff(before, after, f"{name} (before)", f"{name} (formatted)")
    return "".join(line if line.endswith("\n") else line + "\n" for line in lines)


def _replace(path: str, text: str) -> None:
    """Write ``text`` as the new contents of ``path``, keeping what the file is: through a
    symbolic link to the file it names (the link stays a link), and for a file with several
    hard links in place (as black does: every name sees the new text); any other file is
    replaced atomically (a temporary file renamed over it), keeping its permissions."""
    real = os.path.realpath(path)
    data = text.encode("utf-8")
    if os.stat(real).st_nlink > 1:
        with open(real, "r+b") as f:
            f.write(data)
            f.truncate()
            f.flush()
            os.fsync(f.fileno())
        return
    handle, temporary = tempfile.mkstemp(prefix=".fmt-", suffix=".xml",
                                         dir=os.path.dirname(real))
    try:
        with os.fdopen(handle, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        shutil.copymode(real, temporary)
        os.replace(temporary, real)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


# ---------------------------------------------------------------------------- formatting


def format_model(path: str, seen: set[str] | None = None, canonical: bool = False,
                 width: int = WIDTH) -> list[Formatted]:
    """The formatted text (the canonical text with ``canonical``) of a model's file and of
    every file it includes (each once, also across calls sharing ``seen``); raises
    :class:`BadInput` if one cannot be read."""
    model = load(path, ignored=[])  # fmt keeps what MuJoCo ignores, as written
    seen = set() if seen is None else seen
    sources = tooling.source_map(model)
    assert sources is not None
    main = os.path.abspath(path)
    # each file, and the row whose children its top-level elements are
    files: list[tuple[str, ElementSpec | None]] = [(main, None)]
    files += [(included, parent.spec) for included, (_, parent) in sources.includes.items()]
    results: list[Formatted] = []
    for file, context in files:
        real = os.path.realpath(file)  # two links to one file: formatted once
        if real in seen:
            continue
        seen.add(real)
        results.append(format_file(file, context, canonical, width))
    return results


def format_file(path: str, context: ElementSpec | None = None, canonical: bool = False,
                width: int = WIDTH) -> Formatted:
    """The formatted (or canonical) text of one file; ``context`` is the row its top-level
    elements belong to when it is included (its root ``<mujoco>`` then stands for the
    including element)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as problem:  # pragma: no cover - the model was read already
        raise BadInput(f"{shown(path)}: cannot read the file: {problem.strerror}") from None
    try:
        root = etree.fromstring(data, _PARSER)
    except etree.XMLSyntaxError as problem:  # pragma: no cover - the model was read already
        raise BadInput(f"{location(path, problem.lineno)}: malformed XML: {problem.msg}") from None
    head = data.removeprefix(b"\xef\xbb\xbf").lstrip()
    declared = _DECLARATION.match(head) is not None
    if canonical:
        return Formatted(path, data, _Printer(path, context).document(root, declared, text=data))
    tags = start_tags(data)
    printer = _Printer(path, context, iter(tags), indent_unit(tags), width)
    return Formatted(path, data, printer.document(root, declared, _as_written(head), data))


def _as_written(head: bytes) -> str | None:
    """The file's XML declaration as written, when fmt's UTF-8 output keeps it true."""
    match = _PLAIN_DECLARATION.match(head)
    if match is None:
        return None
    encoding = _ENCODING.search(match.group())
    if encoding is not None and encoding.group(1).lower().replace(b"_", b"-") not in (
            b"utf-8", b"utf8"):
        return None
    return match.group().decode("ascii", "replace")


class _Printer:
    """Writes one file's tree: as the author wrote its start tags (``written``, each
    element's in document order), or in the canonical form (``written`` is ``None``)."""

    def __init__(self, path: str, context: ElementSpec | None,
                 written: Iterator[StartTag] | None = None, unit: str = "  ",
                 width: int = WIDTH) -> None:
        self.path = path
        self.context = context
        self.written = written
        self.unit = unit  # the whitespace of one level
        self.width = width if width > 0 else sys.maxsize  # where start tags break

    def indent(self, level: int) -> str:
        depth = min(level, MAX_INDENT // len(self.unit.expandtabs(4)))  # as the exporter stops
        return self.unit * depth

    def start_tag(self, spaces: str, tag: str, closing: str) -> list[str]:
        """The next start tag as written, laid out at ``spaces``."""
        assert self.written is not None
        written = next(self.written)
        return lay_out(spaces, f"<{tag}", written.attributes, written.closing_space + closing,
                       self.width)

    def document(self, root: XmlElement, declared: bool, declaration: str | None = None,
                 text: bytes = b"") -> str:
        """The text of the file whose root element is ``root``; ``declared``: it starts with an
        XML declaration (``declaration``, as written, when it can stay so); ``text``: the
        file's, where the blank lines between what is outside the root are read."""
        tree = root.getroottree()
        info = tree.docinfo
        head: list[str] = []
        if declaration is not None:
            head.append(declaration)
        elif declared:
            head.append(f'<?xml version="{info.xml_version}" encoding="utf-8"?>')
        subset = info.internalDTD
        if subset is not None and (any(True for _ in subset.iterelements())
                                   or any(True for _ in subset.iterentities())):
            raise BadInput(f"{shown(self.path)}: the DOCTYPE declares an internal subset, which "
                           f"fmt would not keep; remove it (MJCF does not use DTDs)")
        if info.doctype:
            head.append(info.doctype)
        head += _outside([*reversed(list(root.itersiblings(preceding=True))), root], text)
        body = self.element(root, root_class().spec, 0, included_root=self.context is not None)
        tail = _outside(list(root.itersiblings()), text)
        return "".join(f"{line}\n" for line in [*head, *body, *tail])

    def element(self, node: XmlElement, spec: ElementSpec, depth: int,
                included_root: bool = False) -> list[str]:
        """The lines of ``node`` (a ``spec`` element) and its subtree; iterative, since
        models can nest deeper than Python recurses."""
        out: list[str] = []
        # (node, its row, depth, whether it is the included file's root): an element to open,
        # or a line to write as it is
        stack: list[tuple[XmlElement, ElementSpec, int, bool] | str] = [
            (node, spec, depth, included_root)]
        while stack:
            item = stack.pop()
            if isinstance(item, str):
                if item.startswith(_SAME_LINE):  # a comment the author wrote after a tag
                    out[-1] += " " + item[len(_SAME_LINE):]
                else:
                    out.append(item)
                continue
            current, row, level, is_included_root = item
            spaces = self.indent(level)
            tag = _tag(current)
            if tag == INCLUDE:  # as written (MuJoCo reads it before the grammar applies)
                if self.written is None:
                    out.append(f"{spaces}{_other(current)}")
                else:
                    out += self.start_tag(spaces, tag, "/>")
                continue
            children_row = self.context if is_included_root and self.context else row
            inside = _inside(current)
            kept = _blank_lines([child for child in inside if isinstance(child, str)
                                 or not self.is_empty(child, children_row)],
                                at_ends=self.written is not None)
            closing = ">" if kept else "/>"
            if self.written is None:
                start = f"<{tag}{self.attributes(current, row, is_included_root)}"
                out.append(f"{spaces}{start}{closing}")
            else:
                out += self.start_tag(spaces, tag, closing)
            if not kept:
                continue
            stack.append(f"{spaces}</{tag}>")
            inner = self.indent(level + 1)
            for child in reversed(kept):
                if child is _BLANK:
                    stack.append("")
                elif isinstance(child, str):
                    stack.append(f"{inner}{_text(child)}")
                elif not isinstance(child.tag, str):
                    same_line = self.written is not None and _after_on_its_line(child)
                    stack.append(f"{_SAME_LINE if same_line else inner}{_other(child)}")
                elif child.tag == INCLUDE:
                    stack.append((child, children_row, level + 1, False))
                else:
                    stack.append((child, _child_row(children_row, child.tag), level + 1, False))
        return out

    def attributes(self, node: XmlElement, row: ElementSpec, verbatim: bool) -> str:
        """`` name="value"`` in grammar order, canonical values (an included file's root:
        as written, MuJoCo does not read them)."""
        if verbatim:
            return "".join(f' {key}="{escape(str(value))}"' for key, value in node.attrib.items())
        texts: list[tuple[int, str, str]] = []
        for key, value in node.attrib.items():
            attribute = row.by_name.get(str(key))
            if attribute is None:  # one MuJoCo ignores on this row: kept, after the others
                texts.append((len(row.attributes) + len(texts), str(key), str(value)))
                continue
            try:
                text = canonical_text(attribute, str(value))
            except Rejected:  # pragma: no cover - the model was read already
                raise BadInput(f"{location(self.path, node.sourceline)}: invalid "
                               f"{attribute.name}={str(value)!r}") from None
            if text is not None:
                texts.append((attribute.index, attribute.name, text))
        texts.sort()
        return "".join(f' {name}="{escape(text)}"' for _, name, text in texts)

    def is_empty(self, node: XmlElement, parent_row: ElementSpec) -> bool:
        """A once-only section with nothing to say (what the exporter leaves out too; only
        the canonical form leaves it out)."""
        if self.written is not None or not isinstance(node.tag, str) or node.tag == INCLUDE:
            return False
        child = parent_row.children[node.tag]
        if not child.single or any(value for value in node.attrib.values()):
            return False
        row = _child_row(parent_row, node.tag)
        return all(inner is _BLANK or (not isinstance(inner, str) and self.is_empty(inner, row))
                   for inner in _inside(node))

def _child_row(row: ElementSpec, tag: str) -> ElementSpec:
    return tooling.element_class(row.children[tag].class_name).spec


_BLANK = "\n"  # a blank line the author left between two things (kept, one at most)


_SAME_LINE = "\0"  # before a comment to write on the line before (XML text has no NUL)


def _after_on_its_line(node: XmlElement) -> bool:
    """Whether the author wrote ``node`` (a comment) on the line of what comes before it:
    the end of the sibling before it, or its parent's start tag."""
    before = node.getprevious()
    parent = node.getparent()
    if before is not None:
        between = before.tail
    elif parent is not None:
        between = parent.text
    else:  # pragma: no cover - a comment outside the root is written on its own line
        return False
    return between is not None and "\n" not in between and not between.strip()


def _inside(node: XmlElement) -> list[XmlElement | str]:
    """What is inside an element, in order: child nodes, text that is not whitespace, and
    :data:`_BLANK` where whitespace holds an empty line."""
    inside: list[XmlElement | str] = []
    _add_text(inside, node.text)
    for child in node:
        inside.append(child)
        _add_text(inside, child.tail)
    return inside


def _add_text(inside: list[XmlElement | str], text: str | None) -> None:
    if not text:
        return
    content = text.strip()
    if not content:
        if text.count("\n") >= 2:
            inside.append(_BLANK)
        return
    before, _, after = text.partition(content)
    if before.count("\n") >= 2:
        inside.append(_BLANK)
    inside.append(content)
    if after.count("\n") >= 2:
        inside.append(_BLANK)


def _blank_lines(items: list[XmlElement | str],
                 at_ends: bool = False) -> list[XmlElement | str]:
    """At most one blank line in a row, none first or last (unless ``at_ends``)."""
    kept: list[XmlElement | str] = []
    for item in items:
        if item is _BLANK and ((not kept and not at_ends) or (kept and kept[-1] is _BLANK)):
            continue
        kept.append(item)
    while kept and kept[-1] is _BLANK and not at_ends:
        kept.pop()
    if kept and all(item is _BLANK for item in kept):  # nothing but a blank line inside
        kept = []
    return kept


def _text(text: str) -> str:
    """Text inside an element (MuJoCo ignores it), escaped, as written otherwise."""
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _other(node: XmlElement) -> str:
    """A comment, processing instruction or ``<include>``, as written (on a line of its own)."""
    tag: object = node.tag  # a comment's or instruction's is lxml's factory, not a string
    if not isinstance(tag, str):
        return etree.tostring(node, encoding="unicode", with_tail=False)
    attributes = "".join(f' {key}="{escape(str(value))}"' for key, value in node.attrib.items())
    return f"<{_tag(node)}{attributes}/>"


def _outside(nodes: list[XmlElement], text: bytes) -> list[str]:
    """The lines of what is outside the root (comments, instructions; the root itself last, if
    given, is not written), with a blank line where the author left one (lxml keeps no
    whitespace there: ``text`` says)."""
    lines: list[str] = []
    for node, after in itertools.pairwise(nodes):
        lines.append(_other(node))
        if _first_line(after, text) - _last_line(node) > 1:
            lines.append("")  # one at most
    if nodes and not isinstance(nodes[-1].tag, str):
        lines.append(_other(nodes[-1]))
    return lines


def _last_line(node: XmlElement) -> int:
    """The line a comment or processing instruction outside the root ends on."""
    return node.sourceline or 0


def _first_line(node: XmlElement, text: bytes) -> int:
    """The line a node outside the root (or the root's start tag) begins on (libxml2 gives
    the line it ends on); 0 without ``text``."""
    if not text or node.sourceline is None:
        return 0
    if isinstance(node.tag, str):
        return start_line(text, node.sourceline, node.tag)
    return node.sourceline - _other(node).count("\n")


def _tag(node: XmlElement) -> str:
    tag: object = node.tag  # an element's tag is text (lxml's types allow bytes and more)
    assert isinstance(tag, str)
    return tag
