# Generated from src/typed_mjcf/_text/export.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Writing elements as MJCF text, iteratively (depth is unlimited).

Every value is written by its attribute's codec with the export's :class:`Format`; names
and references are written as seen from the model being exported: an element's name takes
the prefix of its scope (``arm/`` for what an attached model ``arm`` holds), a reference the
scoped name its target has now.

A model with nothing attached is written straight to text in one pass. A composed model is
built as light nodes where composition joins the attached models' sections and bodies to
the parent's (the sections, the attachment frames and their ancestors), with every other
subtree a chunk of text written in place when the nodes are serialised. The keyframes of a
composed model are combined elsewhere (:mod:`typed_mjcf._model.keyframes`): the writer leaves them
out and reports their sections, and which model each joint, actuator and mocap body came
from.
"""
from __future__ import annotations
import functools
from collections import deque
from collections.abc import Callable, Iterator, Mapping
from typing import Final, cast
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import DEFAULT_FORMAT, Format
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec, WritePlan
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.xmltext import MAX_INDENT, Chunk, Node, escape, has_markup, indent
FileNamer = Callable[[Element, AttributeSpec], str]

def is_empty_single(parent: Element, child: Element) -> bool:
    """A once-only child with nothing to say: no attributes, no attached model, and only
    children like itself. Such sections are not written (reading them gives nothing back)."""
    ...

def written_children(element: Element) -> list[Element]:
    """The children an export writes: all but once-only sections with nothing to say."""
    ...

def iter_written(element: Element) -> Iterator[Element]:
    """The elements the writer writes for ``element``'s subtree, in document order
    (attached models not included)."""
    ...

def has_defaults(model: ModelBase) -> bool:
    """Whether the model's default classes say anything (its classes nest when attached)."""
    ...
_Task = tuple[Element, Node | None, bool]

class Writer:
    """Writes an element and its subtree, attached models inline under their scope."""
    def __init__(self, top: Element, fmt: Format = DEFAULT_FORMAT,
                 file_namer: FileNamer | None = None,
                 skip_attributes: frozenset[str] = frozenset(),
                 names_from: NameScope | None = None) -> None:
        self.fmt = fmt
        self.top = top
        self.file_namer = file_namer  # renames every file (paths and in-memory assets)
        self.skip = skip_attributes
        root = _tree.model_of(top)
        own = _tree.scope_of(root) if root is not None else _tree.scope_of(top)
        # names are written as seen from this scope (dm_control's prefix_root)
        scope = own if names_from is None else names_from
        self.top_scope = scope
        self.prefixes: dict[int, str] = {id(scope): ""}
        self.composed = root is not None and bool(own.attached)
        # verbatim output: nothing renamed or reformatted, so texts stored as read are
        # written as they are (what their codecs write for them with such a format)
        self.verbatim = fmt.keeps_source_text and file_namer is None
        # elements with an attachment frame in their subtree: written as nodes, so attached
        # models' bodies can join them; everything else is written as chunks of text
        self.hosts: set[int] = _hosts(root) if self.composed and root is not None else set()
        self.pending: deque[ModelBase] = deque()  # attached models whose sections follow
        # the model of each joint, actuator and mocap body, in document order (composed)
        self.joint_owners: list[ModelBase] = []
        # the body each joint moves, by its place among the bodies written (MuJoCo numbers
        # joints body by body: a body's joints come before its children's, wherever written)
        self.joint_bodies: list[int] = []
        self.body_numbers: dict[int, int] = {}
        self.actuator_owners: list[ModelBase] = []
        self.mocap_owners: list[ModelBase] = []
        # composed models: each model's keyframe section, for combining (left out here)
        self.keyframe_sections: list[tuple[ModelBase, Element]] = []
        self._flat_names: dict[tuple[int, str], str] | None = None
        self.targets: dict[int, str] = {}  # the text of each element references link to
        # the scope whose elements' texts are written as stored (verbatim output; else none)
        self.verbatim_scope = scope if self.verbatim and not skip_attributes else None
        # names this export gives unnamed elements that references link to
        self.given_names: dict[int, str] = _names_to_give(top, scope)
        if self.composed:
            self.given_names.update(_file_names_of_attached(scope))
    def prefix(self, scope: NameScope) -> str:
        """The prefix of names in ``scope`` as seen from the model being written
        (:meth:`NameScope.prefix`, cached)."""
        ...
    def reference(self, element: Element, attribute: AttributeSpec, target: Element) -> str:
        """A reference to ``target``, scoped as seen from the model being written."""
        ...
    def main_class(self, scope: NameScope) -> str:
        """The name of a model's top-level default class: ``main``, or the scope of an
        attached model (its classes nest in a class named after it)."""
        ...
    def names(self, element: Element) -> list[str]:
        """The names of the attributes to write, in grammar order."""
        ...
    def given_name(self, element: Element) -> str:
        """`` name="..."`` for an unnamed element this export names."""
        ...
    def attributes(self, element: Element) -> dict[str, str]:
        """The attributes to write, as unescaped text, in grammar order."""
        ...
    def attribute_text(self, element: Element, stored: Mapping[str, object]) -> str:
        """`` name="value"`` for each of ``element``'s ``stored`` values (this loop is most
        of an export's time). In verbatim output, a text stored as read is written as it is
        where its codec says so (the plan's flag, from ``Codec.keeps_read_text``: what
        ``Codec.write`` does for it), into the template of the element's set of attributes,
        and escaped only if the result shows something to escape (one check per element
        rather than per value)."""
        ...
    def escaped_attribute_text(self, element: Element, stored: Mapping[str, object],
                               plan: WritePlan) -> str:
        """:meth:`attribute_text` value by value (``plan``: the write plan of ``stored``'s
        names), each text escaped: for output that is not verbatim, and values that need
        escaping."""
        ...
    def value(self, element: Element, attribute: AttributeSpec, value: object) -> str | None:
        """One attribute's text (``None``: nothing to write, e.g. a link to a removed
        element, which ``validate()`` reports)."""
        ...
    def file_text(self, element: Element, attribute: AttributeSpec, value: object) -> str:
        """A file path as the MJCF text writes it: as the source names it, so the text loads
        beside its source (an attached model's as an absolute path, which its parent's
        folders cannot change); in-memory contents (and an attached model's skin, whose bones
        are renamed) by the name ``get_assets()`` gives them."""
        ...
    def flat_file_names(self) -> dict[tuple[int, str], str]:
        """The flat names of the files (named once per export, when the first is written)."""
        ...
    def element(self, element: Element, parent: Node | None) -> Node:
        """Write ``element``'s subtree under ``parent``; iterative, so depth is unlimited.

        Composition still adds to, or looks into, the model's sections, the attachment
        frames and their ancestors, and sections whose attributes merge (``<option>``...):
        those are nodes. Everything below them is written as chunks of text.
        """
        ...
    def needs_node(self, element: Element, merging: bool) -> bool:
        """Whether composition may add to or look into ``element``: a model's section, an
        attachment frame or one of its ancestors, or part of a section whose attributes
        merge with the attached models'."""
        ...
    def chunk(self, element: Element, extra: dict[str, str] | None = None) -> Chunk:
        """``element``'s subtree, to be written as text where it lands (it holds no
        attachment frame); ``extra`` attributes follow the element's own."""
        ...
    def start_tag(self, element: Element) -> str:
        """The element alone: its start tag, ``...`` for its children (dm_control's
        ``self_only``)."""
        ...
    def text(self, element: Element, pretty_print: bool) -> str:
        """``element``'s subtree as XML text, written in one pass without building nodes
        (for models with nothing attached: composition needs :meth:`element`'s nodes)."""
        ...
    def write(self, element: Element, depth: int, pretty_print: bool,
              extra: dict[str, str] | None = None) -> str:
        """The text of ``element``'s subtree, indented from ``depth``."""
        ...
    def track(self, element: Element) -> None:
        """Note which model a joint, actuator or mocap body of a composed model came from."""
        ...
    def frame_class(self, frame: Element,
                    model: ModelBase) -> Callable[[Element], dict[str, str] | None] | None:
        """For an attachment frame whose ``childclass`` gives the attached model's bodies
        their model's defaults: what each of the frame's own children (a joint added to the
        frame, say) must write to keep the defaults of the model the frame is in, as in
        dm_control: ``class`` naming the class that applies at the frame there."""
        ...
    def attachment(self, frame: Node, model: ModelBase) -> list[_Task]:
        """The attached model's bodies, to be written inside its frame; its other sections
        join the parent's later."""
        ...
    def model(self, root: ModelBase) -> Node: ...
    def section_node(self, root: Node, tag: str) -> Node:
        """The root's ``<tag>`` section, created at its grammar position if missing."""
        ...
    def section(self, root: Node, section: Element, model: ModelBase) -> None:
        """Join an attached model's section to the root's, as its grammar row says."""
        ...
    def merge_attributes(self, target: Node, section: Element) -> None: ...
INDENTS: Final = tuple(indent(level) for level in range(MAX_INDENT // 2 + 2))

def write_plan(spec: ElementSpec, key: tuple[str, ...]) -> WritePlan:
    """How to write an element of ``spec`` whose values have the names ``key`` (in their
    order). The elements of a row mostly set one of a few sets of attributes: each set's
    plan is kept (for that many sets) rather than sorted for each element."""
    ...

def grammar_order(spec: ElementSpec, stored: Mapping[str, object]) -> tuple[str, ...]:
    """The names of ``stored`` (an element's values) in the order of ``spec``'s grammar."""
    ...

@functools.cache
def folder_attributes() -> frozenset[str]:
    """The <compiler> attributes that name folders of files: each model keeps its own."""
    ...

def _names_to_give(top: Element, top_scope: NameScope) -> dict[int, str]:
    """Names for unnamed elements MJCF must name: every attachment frame, named after its
    model (``arm/``, as dm_control names it), and whatever a reference links to, named
    ``unnamed_<kind>_<n>`` with the first number free in its scope (MJCF refers by name).
    Nothing is stored on the elements."""
    ...

def _file_names_of_attached(top_scope: NameScope) -> dict[int, str]:
    """The unnamed assets of attached models that MuJoCo names after their file: written
    with that name, so that it takes the model's prefix as the references to it do."""
    ...

def _hosts(root: ModelBase) -> set[int]:
    """The ids of the attachment frames of ``root`` and of the models attached to it,
    nested ones included, and of all their ancestors."""
    ...
