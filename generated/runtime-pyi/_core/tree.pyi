# Generated from src/typed_mjcf/_core/tree.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The element tree: elements, their attributes and children, names and links.

This is the core every feature builds on. An element stores its attribute values by XML
name (each as its codec stores it, or the element a reference links to), its children in
document order, its parent, the model whose tree it is in (``root``) and the name scope its
name lives in (its model's, or for what is added to an attachment frame, the attached
model's). Every attribute is set by one path, :meth:`Element._assign` (Python values) and
:func:`assign_text` (text read from a file), and every element is made by :func:`_create`.

References are links: a reference attribute holds the element it names as soon as the name
resolves (at assignment, or when an element of that name appears later), so renaming the
target, renaming or attaching its model, or copying keeps the reference right; the text is
derived when the model is written. A reference to a removed element reads as ``None`` and is
reported by ``validate()``.

Features (parsing, export, composition, validation, ...) use the functions at the end of this
module (the internal API), not the elements' private slots.
"""
from __future__ import annotations
from array import array as _array_of
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import (
    ClassVar,
    Final,
    Generic,
    NoReturn,
    Protocol,
    Self,
    SupportsIndex,
    TypeAlias,
    TypeVar,
    cast,
    overload,
)
from typed_mjcf._build import mypyc_attr
from typed_mjcf._core.access import ANYWHERE, Confinement
from typed_mjcf._core.codecs import ArrayCodec, Rejected
from typed_mjcf._core.errors import (
    ChildError,
    DuplicateIdentifierError,
    IllegalChildError,
    InvalidReferenceError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    UnknownAttributeError,
    did_you_mean,
)
from typed_mjcf._core.grammar import AttributeSpec, ChildSpec, ElementSpec, RowClass
from typed_mjcf._core.language import GrammarFacts
from typed_mjcf._core.names import SEPARATOR, UNNAMED_MODEL, NameScope, NameTaken
from typed_mjcf._core.sourcelines import SourceText, file_start_line
E = TypeVar("E", bound="Element")
E_co = TypeVar("E_co", bound="Element", covariant=True)
_Slice: TypeAlias = "slice[int | None, int | None, int | None]"
_FACTS: list[GrammarFacts] = ...
DCLASS: Final = "dclass"

def element_class(class_name: str) -> type[Element]:
    """The generated class of that name."""
    ...

def element_classes() -> Mapping[str, type[Element]]:
    """Every generated class, by name."""
    ...

def finish_grammar(facts: GrammarFacts,
                   adjust: Callable[[Mapping[str, type[Element]]], None] | None = None) -> None:
    """Called by the generated tables once every class exists: the language-wide facts,
    which rows hold bodies, and the signature and docstring of every ``add_<tag>()``.
    ``adjust`` is what a layer above changes in the tables first (the installed MuJoCo's
    release: what it lacks or types otherwise, ``typed_mjcf._releases``)."""
    ...
NameNote = Callable[["ElementSpec", str], "str | None"]
ValueNote = Callable[["ElementSpec", "AttributeSpec", object], "str | None"]

def explain_refusals(name_note: NameNote, value_note: ValueNote) -> None:
    """Register what says why a name (an attribute, a child, ``add_<tag>``) or a value is
    refused, beyond the row's own rules: "needs MuJoCo >= 4.0.0; installed 3.17.0"."""
    ...

def name_note(spec: ElementSpec, name: str) -> str | None:
    """Why ``name`` is not on ``spec``'s row, when a layer above knows (else None)."""
    ...

def value_note(spec: ElementSpec, attribute: AttributeSpec, value: object) -> str | None:
    """Why ``value`` is refused for ``attribute``, when a layer above knows (else None)."""
    ...

def grammar_facts() -> GrammarFacts:
    """The language facts of the loaded grammar (schema/facts.toml's ``[language]``)."""
    ...

def short_repr(value: object) -> str:
    """``repr(value)``, shortened as the messages of refused values shorten it."""
    ...

@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class _Layout:
    """What every element stores (see :class:`Element`), in a class of its own so that
    elements can be made as a :class:`_Blank` and given their class once filled in."""
    _values: dict[str, object]
    _children: list[Element] | tuple[()]
    _parent: Element | None
    _root: ModelBase | None
    _scope: NameScope
    _singles: dict[str, Element] | None
    _attached: ModelBase | None
NATIVE_LAYOUT: Final = "__slots__" not in vars(_Layout)
WEAKREF_SLOTS: Final[tuple[str, ...]] = ...

class SiblingNumbers:
    """Each child's place among its parent's children of its tag, counted once per parent:
    the paths of many unnamed siblings in linear time (a path alone counts its siblings)."""
    def __init__(self) -> None: ...
    def number(self, parent: Element, child: Element) -> int | None: ...

def paths(elements: Iterable[Element]) -> list[str]:
    """The paths of ``elements`` (as :attr:`Element.path`), in time linear in their number."""
    ...

@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class Element(_Layout):
    """An MJCF element. Use the generated subclasses (``typed_mjcf.Body``, ...)."""
    spec: ClassVar[ElementSpec]
    def __init_subclass__(cls, **kwargs: object) -> None: ...
    def __init__(self) -> None: ...
    @property
    def tag(self) -> str:
        """The XML tag."""
        ...
    @property
    def parent(self) -> Element | None:
        """The parent element; ``None`` for a model's root or a removed element."""
        ...
    @property
    def is_removed(self) -> bool:
        """Whether this element was removed from its model."""
        ...
    @property
    def path(self) -> str:
        """Where the element is in its model, e.g. ``worldbody/body[upper_arm]/geom[0]``."""
        ...
    def __repr__(self) -> str: ...
    def __dir__(self) -> list[str]:
        """Also the MJCF spellings ``getattr`` takes where they differ (``global``)."""
        ...
    def get_attributes(self) -> dict[str, object]:
        """The attributes that are set, by Python name, in grammar order."""
        ...
    def set_attributes(self, **kwargs: object) -> None:
        """Set several attributes at once; if any is refused, none is changed."""
        ...
    def add(self, tag: str, /, **kwargs: object) -> Element:
        """Add a child ``<tag>`` with the given attributes and return it."""
        ...
    def insert(self, tag: str, /, position: int, **kwargs: object) -> Element:
        """Add a child ``<tag>`` at ``position`` among this element's children."""
        ...
    def iter_elements(self) -> Iterator[Element]:
        """This element and all its descendants, in document order (attached models are
        not included: see ``find_all``)."""
        ...
    def remove(self) -> None:
        """Remove this element (and its subtree) from its parent; references to the
        removed elements read as ``None`` from now on."""
        ...
    def __reduce_ex__(self, protocol: SupportsIndex) -> tuple[object, ...]:
        """Pickled without recursion, however deep the tree: an element's state leaves out
        its parent and children, and the top of its tree (the model, or a removed subtree)
        lists every element below it, with its parent, in document order."""
        ...
    def __setstate__(self, state: dict[str, object]) -> None: ...
    def __copy__(self) -> Self: ...
    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """A detached copy of the subtree; references inside it point into the copy."""
        ...
    def paste(self, element: E, position: int | None = None) -> E:
        """Add a deep copy of ``element`` (from this model or another) as a child; return it.

        References inside the copied subtree point into the copy; references to elements
        outside it are kept by name, to resolve in this model. Names must be free here.
        """
        ...
    def is_same_as(self, other: object) -> bool:
        """Whether ``other`` is an element of the same kind with the same attributes and,
        recursively, the same children: each kind of child in the same order (every child in
        the same order in a tendon's path), dm_control's ``is_same_as`` (models compare by
        their contents, whatever their names)."""
        ...

@mypyc_attr(allow_interpreted_subclasses=True, serializable=True)
class ModelBase(Element):
    """The root of a model: its name scope, the folder its files are relative to, where it
    is attached, the file contents it was given in memory, and where a parsed model's
    elements were read."""
    _access: Confinement
    _base_dir: str | None
    _frame: Element | None
    _files: dict[str, bytes]
    _sources: SourceMap | None
    def __init__(self, model: object = None, *, model_dir: object = None,
                 assets: object = None, **kwargs: object) -> None: ...
    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """An independent copy, with copies of the models attached to it."""
        ...

@mypyc_attr(serializable=True)
class SourceMap:
    """Where a parsed model's elements were read (for messages that point into the files).

    ``lines`` maps each element to its file (``None`` for text given in memory) and the
    line libxml2 gave it (where its start tag ends), in the order the parser read them;
    ``includes`` maps each included file to the file that included it and the element its
    contents were read into.

    The map holds the elements in a list and their lines in an array beside it, and an
    element's file only if it is not the main one: no dict entry, int or (file, line) pair
    per element (about 50 bytes each); the index from element to place is made when first
    asked for (messages), not while reading.
    """
    def __init__(self, main: str | None = None) -> None:
        self.main = main  # the file (or text) the model was read from
        self.order: list[Element] = []  # every element, in reading order
        self.line_numbers = _array_of("q")  # the line of each (0: none given)
        self.files: dict[Element, str | None] = {}  # the elements read from another file
        self.includes: dict[str, tuple[str | None, Element]] = {}
        self.texts: dict[str, SourceText | None] = {}  # files read again for messages
        self._places: dict[Element, int] = {}
    def add(self, element: Element, source: str | None, line: int | None) -> None:
        """Record that ``element`` was read at ``source:line``."""
        ...
    def get(self, element: Element) -> tuple[str | None, int | None] | None:
        """Where ``element`` was read, if it was."""
        ...
    @property
    def lines(self) -> Mapping[Element, tuple[str | None, int | None]]:
        """Every element read, in reading order, with its file and line."""
        ...

def new_model(cls: type[ModelBase]) -> ModelBase:
    """An empty model of the generated root class (no attributes set)."""
    ...

@mypyc_attr(native_class=False)
class Attribute:
    """Reads and writes one attribute on elements of a generated class."""
    def __init__(self, spec: AttributeSpec) -> None:
        self.spec = spec
        self.name = spec.name
        self.codec = spec.codec
        self.lazy = spec.codec.lazy
        self.reference = spec.is_reference
        self.array = isinstance(spec.codec, ArrayCodec)
    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> Attribute: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> object: ...
    def __set__(self, obj: Element, value: object) -> None: ...
    def __delete__(self, obj: Element) -> None: ...
    def __repr__(self) -> str: ...

@mypyc_attr(native_class=False)
class SingleChild:
    """A once-only child, created on first access; ``del`` removes it."""
    def __init__(self, child: ChildSpec) -> None:
        self.child = child
    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> SingleChild: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> Element: ...
    def __set__(self, obj: Element, value: object) -> None: ...
    def __delete__(self, obj: Element) -> None: ...

@mypyc_attr(native_class=False)
class ChildList:
    """The children with one tag, as a live :class:`ElementList`."""
    def __init__(self, child: ChildSpec) -> None:
        self.child = child
    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> ChildList: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> ElementList[Element]: ...
    def __set__(self, obj: Element, value: object) -> None: ...

class ElementList(Sequence[E_co], Generic[E_co]):
    """The children of one element with one tag, in document order: a live view.

    Index by position or by name (``worldbody.body["arm"]``); ``del view[i]`` removes that
    child from the model.
    """
    def __init__(self, owner: Element, tag: str) -> None: ...
    @overload
    def __getitem__(self, index: int | str) -> E_co: ...
    @overload
    def __getitem__(self, index: _Slice) -> list[E_co]: ...
    def __delitem__(self, index: int | str | _Slice) -> None: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[E_co]: ...
    def __bool__(self) -> bool: ...
    def __eq__(self, other: object) -> bool:
        """Equal to a list, tuple or view of the same elements (hashing is off: it changes)."""
        ...
    def __repr__(self) -> str: ...
    def clear(self) -> None:
        """Remove every child of this list from the model (dm_control's ``clear()``)."""
        ...
    def remove(self, element: Element) -> None:
        """Remove ``element``, one of this list's children, from the model."""
        ...

def document_adders() -> None:
    """Give every ``add_<tag>()`` its signature and docstring (once all classes exist)."""
    ...

def attribute_listing(spec: ElementSpec) -> str:
    """``add_<tag>()``'s docstring, laid out by ``_doclines`` as ``elements.pyi``'s is, from
    each attribute's one line, written by the generator (``codegen/docs.py``) into its
    ``doc``."""
    ...

def check_removable(element: Element) -> None:
    """Refuse to remove a section of a model that attached models merge their own section
    into (dm_control's guard: ``remove(affect_attachments=True)`` says what is meant)."""
    ...

def element_name(element: Element) -> str | None:
    """The element's own name (not scoped), if it has one."""
    ...

def own_scoped_names(elements: Iterable[Element]) -> list[str | None]:
    """Each element's own name with its scope's prefix (``full_identifier``), each prefix
    computed once: ``None`` for an element without its own name, removed, or an attachment
    frame (asked one by one). For binding many elements at once."""
    ...

def reference_namespace(element: Element, attribute: AttributeSpec) -> str | None:
    """The one namespace a reference names now, if it is known."""
    ...

def resolve_references(model: Element) -> None:
    """Link every reference held as a name that names an element now."""
    ...

def equal_read_values(a: object, b: object) -> bool:
    """Whether two values as attributes read are equal: numbers by value, whatever holds
    them (an array equals a tuple of the same numbers)."""
    ...

def values(element: Element) -> Mapping[str, object]:
    """The stored values by XML name (read only, as its type says to type checkers: set
    through the element or the functions below). Lazy text and links are as stored;
    :func:`read_value` gives what users read."""
    ...

def children(element: Element) -> Sequence[Element]:
    """The children in document order (the tree's own list: do not modify)."""
    ...

def parent_of(element: Element) -> Element | None: ...

def children_with_tag(element: Element, tag: str | None) -> list[Element]:
    """The children (only those with ``tag`` if given; a tag the grammar does not allow
    here is an error)."""
    ...

def model_of(element: Element) -> ModelBase | None:
    """The model whose tree holds ``element`` (``None`` once removed)."""
    ...

def scope_of(element: Element) -> NameScope:
    """The name scope the element's name lives in."""
    ...

def attached_at(element: Element) -> ModelBase | None:
    """The model attached at ``element``, an attachment frame."""
    ...

def scope_model(scope: NameScope) -> ModelBase:
    """The model whose scope ``scope`` is."""
    ...

def attached_models(model: ModelBase) -> list[ModelBase]:
    """The models attached to ``model`` (not nested ones), in document order."""
    ...

def child_scope(parent: Element) -> NameScope:
    """The scope of what is added under ``parent``."""
    ...

def frame_of(model: ModelBase) -> Element | None:
    """Where ``model`` is attached, if it is."""
    ...

def base_dir(model: ModelBase) -> str | None: ...

def set_base_dir(model: ModelBase, folder: str | None) -> None: ...

def file_access(model: ModelBase) -> Confinement:
    """The files ``model`` may read (see :mod:`typed_mjcf._core.access`)."""
    ...

def set_file_access(model: ModelBase, access: Confinement) -> None: ...

def memory_files(model: ModelBase) -> dict[str, bytes]:
    """File contents the model was given in memory, by the path its attributes write."""
    ...

def set_memory_files(model: ModelBase, files: dict[str, bytes]) -> None:
    """Give ``model`` its in-memory files (a dict that may read entries on demand)."""
    ...

def source_map(model: ModelBase) -> SourceMap | None:
    """Where the parser read ``model``'s elements (``None`` for a model built in Python)."""
    ...

def set_source_map(model: ModelBase, sources: SourceMap | None) -> None: ...

def source_of(element: Element) -> tuple[str | None, int | None] | None:
    """The file and line ``element`` was read from (the line its start tag begins on, for
    elements read from a file), if it was parsed and is still in the model it was read into."""
    ...

def single_child(element: Element, tag: str) -> Element | None: ...

def read_value(element: Element, attribute: AttributeSpec) -> object:
    """The value users read for ``attribute`` (converted; a removed target reads None)."""
    ...

def new_child(parent: Element, child_spec: ChildSpec) -> Element:
    """A new child of ``parent``, last among its children, with no attributes."""
    ...

def rejection(element: Element, attribute: AttributeSpec, value: object,
              rejected: Rejected) -> Exception:
    """The error for a value ``attribute`` refused on ``element``, naming both."""
    ...

def assign(element: Element, attribute: AttributeSpec, value: object) -> None:
    """Set ``attribute`` from a Python value, as assignment does."""
    ...

def convert(element: Element, attribute: AttributeSpec, value: object) -> object:
    """``value`` as assigning it to ``attribute`` would store it (checked; nothing stored)."""
    ...

def attribute_of(element: Element, key: str) -> AttributeSpec:
    """The attribute ``key`` (Python or XML name) of ``element``; the element's error if
    it has none."""
    ...

def snapshot(element: Element) -> Callable[[], None]:
    """What puts ``element``'s values and name back as they are now."""
    ...

def assign_texts(element: Element, items: Iterable[tuple[str, str]], names: bool = True,
                 link: bool = True
                 ) -> list[tuple[str, AttributeSpec | None, str, Exception | None]] | None:
    """Set the attributes ``items`` (name, text) read from a file: most of a parse. Values,
    and if ``names`` (names taken as written) the element's name and its references of a
    fixed namespace (as :func:`assign_text` with ``link``). Return the others, in order,
    for the caller: each with its attribute (``None``: the row lacks it) and the refusal (a
    :class:`Rejected` or a library error), or ``None`` for one not set here (an empty text,
    a reference whose namespace another attribute names, names when not ``names``)."""
    ...

def assign_text(element: Element, attribute: AttributeSpec, text: str,
                link: bool = True) -> None:
    """Set ``attribute`` from text read from a file (numbers stay text once checked; names
    may hold '/'; references link when their target exists, unless ``link`` is false);
    raises :class:`Rejected`."""
    ...

def attach_at(frame: Element, model: ModelBase) -> None:
    """Record that ``model`` is attached at ``frame`` (placement is composition's job)."""
    ...

def detach_model(model: ModelBase) -> None:
    """Undo :func:`attach_at`; the frame stays where it is."""
    ...

def remove_subtree(element: Element) -> None:
    """``element.remove()`` without the guard on merged sections."""
    ...

def iter_composed(top: Element, attachments: bool) -> Iterator[Element]:
    """``top``'s subtree in the order the exported XML has it: attached models' bodies inside
    their frames, their other sections after ours (when ``attachments``)."""
    ...

def insert_child(parent: Element, tag: object, position: object,
                 kwargs: dict[str, object]) -> Element:
    """``insert()``: a child ``<tag>`` at ``position``, each checked (a bool is no int)."""
    ...

def mjcf_alias(element: Element, name: str) -> str | None:
    """The Python name of ``element``'s child or attribute that ``name`` spells as MJCF does
    (``global``: ``global_``); ``None`` where the two are the same or there is none."""
    ...

def add_rejection_note(note: Callable[[object], str | None]) -> None:
    """Have refusals of a value ask ``note`` what it says of that value (once per note)."""
    ...

def unknown_attribute(element: Element, name: str) -> UnknownAttributeError:
    """The error for ``name``, none of ``element``'s attributes."""
    ...

def _not_filled(*_: object) -> NoReturn: ...

def _nothing_handed_out(model: ModelBase) -> None:
    """No array is handed out for in-place edits until the compat room lends its own."""
    ...

class CompatHooks:
    """What the compat room lends the tree and the features, each called only while its
    flag is on (:func:`check_arrays` always: it has nothing to do while none is handed out)."""
    def __init__(self) -> None:
        # arrays_in_place: the stored array itself, writable; values copied for a copy; the
        # arrays handed out checked again before a model is written
        self.writable_array: Callable[[Element, AttributeSpec, object], object] = _not_filled
        self.copied_values: Callable[[Mapping[str, object]], dict[str, object]] = _not_filled
        self.check_arrays: Callable[[ModelBase], None] = _nothing_handed_out
        # named_after_files: one element (when unnamed), every element of a model
        self.name_after_file: Callable[[Element], None] = _not_filled
        self.name_after_files: Callable[[ModelBase], None] = _not_filled
        # element_name_keyword: the tag ``add()``'s keywords name (taken out of them)
        self.tag_by_keyword: Callable[[dict[str, object]], str | None] = _not_filled
        # unnamed_identifiers: one element's identifier; every unnamed one of a model
        self.unnamed_identifier: Callable[[Element], str | None] = _not_filled
        self.unnamed_names: Callable[[ModelBase], dict[int, str]] = _not_filled
        # compile_error_advice: a refusal of a model for a physics, with dm_control's advice
        self.explained: Callable[[ValueError, ModelBase], ValueError] = _not_filled
COMPAT: Final = CompatHooks()

def tag_given(parent: Element, tag: object, kwargs: dict[str, object]) -> str:
    """``add()``'s tag: the first argument, or (``element_name_keyword``) the keyword that
    names it (taken out of the attributes). Takes any object (here and in
    :func:`insert_child`: the compiled build checks an annotation before the body can)."""
    ...

def check_arrays(model: ModelBase) -> None:
    """Check again every array of ``model`` (and the models attached to it) handed out for
    in-place edits: an edit that made it invalid raises the error assigning it would."""
    ...

def keep_value(element: Element, attribute: AttributeSpec, value: object) -> None:
    """Keep ``value`` as ``attribute``'s stored value as it is (an array handed out for
    in-place edits, which is already the codec's)."""
    ...

def store_name(element: Element, attribute: AttributeSpec, name: str) -> None:
    """Give ``element`` the name ``name`` (``attribute`` its id), as storing does: a name
    given after a file."""
    ...
