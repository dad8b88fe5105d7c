"""The grammar tables: what the generated classes tell the runtime about each MJCF row.

Everything the runtime knows about particular tags comes from here: the generated tables
build an :class:`ElementSpec` per grammar row, with an :class:`AttributeSpec` per attribute
and a :class:`ChildSpec` per legal child; the facts that concern the language as a whole
(the name of the root default class, the world body, ...) are declared in
:mod:`typed_mjcf._core.language`. The specs are plain data; :mod:`typed_mjcf._core.codecs` gives each
attribute the codec of its kind.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import ClassVar, Final, Literal, Protocol

from typed_mjcf._core.behaviour import FLAGS as _FLAGS
from typed_mjcf._core.codecs import Codec, make_codec
from typed_mjcf._core.rows import AttributeRow

DOCS_URL: Final = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"

Compose = Literal["attributes", "nest", "keyframes"]


@dataclass(slots=True, eq=False, repr=False)
class AttributeSpec(AttributeRow):
    """One attribute of one grammar row: its row (:class:`AttributeRow`, the generated
    ``A(...)`` call's fields) and what the runtime derives from it."""

    lo: int = field(init=False)
    hi: int | None = field(init=False)
    is_array: bool = field(init=False)
    index: int = field(init=False)  # position in the row, set by ElementSpec
    codec: Codec = field(init=False)
    # names another element (a fixed or an attribute-given namespace)
    is_reference: bool = field(init=False)
    # stored as its codec gives it: no name, link or scope bookkeeping
    direct: bool = field(init=False)
    codec_only: bool = field(init=False)  # direct, and written by its codec alone (not a
    # file, nor names)
    bare: bool = field(init=False)  # direct, and never empty (not a list that may hold no
    # numbers): storing it is the dict write alone (``_tree._store``'s first case; the loops
    # of add() and parsing test this flag, so what storing does is still decided there)
    # a text listing names of this namespace (a <flex>'s bodies; see mark_name_list)
    name_list: str | None = field(init=False)
    # a text stored for it is written unchanged by the exporter (verbatim output, names of
    # the model written), if its codec writes read texts as read (the write plan asks:
    # Codec.keeps_read_text)
    as_is: bool = field(init=False)

    def __post_init__(self) -> None:
        kind = self.kind
        if not self.py_name:
            self.py_name = self.name
        if self.dtype is None and kind in ("int", "real"):
            self.dtype = "int" if kind == "int" else "double"
        arity = self.arity
        self.is_array = arity is not None and kind != "chars"  # chars: arity counts characters
        self.lo, self.hi = arity if arity is not None else (1, 1)
        self.index = 0
        self.is_reference = kind == "ref" or self.namespace_from is not None
        self.direct = not self.is_reference and kind != "id" and not self.scope
        self.codec_only = self.direct and kind != "file"
        self.bare = self.direct and not (self.is_array and self.lo == 0)
        self.name_list = None  # set by the language's facts (see mark_name_list)
        self.as_is = self.codec_only or kind == "id" or self.is_reference
        self.codec = make_codec(kind, dtype=self.dtype, is_array=self.is_array, lo=self.lo,
                                hi=self.hi, keywords=self.keywords, pattern=self.pattern,
                                alone=self.alone, ordered=self.ordered, numbers=self.numbers)

    def mark_name_list(self, namespace: str) -> None:
        """This text lists names of ``namespace``: an attached model's are scoped when
        written, so it is not written by its codec alone."""
        self.name_list = namespace
        self.codec_only = False

    @property
    def url(self) -> str | None:
        """This attribute's entry in MuJoCo's XML reference."""
        return f"{DOCS_URL}#{self.anchor}" if self.anchor else None

    def describe(self) -> str:
        """The attribute's MJCF type in words, e.g. ``real[3]`` or ``keyword: hinge|slide``."""
        if self.kind in ("keyword", "flags"):
            alone = f", or alone: {'|'.join(self.alone)}" if self.alone else ""
            return f"{self.kind}: {'|'.join(self.keywords)}{alone}"
        if self.kind in ("id", "ref"):
            return f"{self.kind}<{self.namespace}>"
        if self.namespace_from is not None:
            return f"ref<{self.namespace_from[0]}>"
        base = self.dtype if self.kind == "real" and self.dtype else self.kind
        if not self.is_array:
            return base
        if self.hi is None:
            return f"{base}[]" if self.lo == 0 else f"{base}[{self.lo}..]"
        return f"{base}[{self.lo}]" if self.lo == self.hi else f"{base}[{self.lo}..{self.hi}]"

    def __repr__(self) -> str:
        return f"<attribute {self.name!r}: {self.describe()}>"


# How an export writes the attributes of an element that sets a given set of them: their
# names in grammar order; each name with its attribute and whether a text stored for it is
# written as it is (in verbatim output); the template of their `` name="%s"``.
WritePlan = tuple[tuple[str, ...], tuple[tuple[str, AttributeSpec, bool], ...], str]


class RowClass(Protocol):
    """A row's generated class, as the grammar sees it: its row (the tree's elements are
    such classes; the grammar, below the tree, knows them by this alone)."""

    spec: ClassVar[ElementSpec]


class ChildSpec:
    """A legal child of a row: its tag, Python class name and whether it appears once.

    It also reads as dm_control's spec of a child (``repeated``, ``on_demand``, and the
    child row's ``name``, ``attributes``, ``children``, ``namespace``, ``identifier``), and
    equals the child's row: ``child.spec == parent.spec.children[child.tag]``.
    """

    __slots__ = ("card", "class_name", "cls", "holder", "index", "once", "py_name", "single",
                 "tag")

    tag: str
    py_name: str
    class_name: str
    single: bool
    card: str
    once: bool
    index: int
    cls: type[RowClass]  # the generated class, set once every class exists
    holder: ElementSpec  # the row this is a child of, set once every class exists

    def __init__(self, tag: str, class_name: str, *, single: bool = False, card: str = "*",
                 py_name: str | None = None) -> None:
        self.tag = tag
        self.py_name = tag if py_name is None else py_name
        self.class_name = class_name
        self.single = single
        self.card = card
        # at most once in one XML element ("?" or "!"): MuJoCo refuses a second
        self.once = card in ("?", "!")
        self.index = 0

    # dm_control's ElementSpec of a child, read from the child's row
    @property
    def name(self) -> str:
        return self.tag

    @property
    def repeated(self) -> bool:
        """Whether the parent holds a list of these (dm_control: ``repeated``)."""
        return not self.single

    @property
    def on_demand(self) -> bool:
        """Whether this once-only child exists only once added (``on_demand_children``, as
        dm_control's schema marks them): those of the rows that hold bodies (``<inertial>``)."""
        return self.single and _FLAGS.on_demand_children and self.holder.holds_bodies

    @property
    def attributes(self) -> dict[str, AttributeSpec]:
        return self.cls.spec.attributes

    @property
    def children(self) -> dict[str, ChildSpec]:
        return self.cls.spec.children

    @property
    def namespace(self) -> str | None:
        return self.cls.spec.namespace

    @property
    def identifier(self) -> str | None:
        return self.cls.spec.identifier

    def __eq__(self, other: object) -> bool:
        if isinstance(other, ElementSpec):  # the child's own row
            return other is self.cls.spec
        return other is self

    def __hash__(self) -> int:
        return id(self)

    def __repr__(self) -> str:
        return f"<child <{self.tag}> of {self.holder!r}>"


Constraint = tuple[str, tuple[tuple[str, ...], ...]]


class ElementSpec:
    """One grammar row: tag, attributes in grammar order, legal children, constraints.

    Shaped as dm_control's ``ElementSpec`` where they meet: ``name`` is the tag,
    ``attributes`` maps XML names to attributes, ``children`` tags to :class:`ChildSpec`
    (``repeated``, ``on_demand``), ``namespace`` and ``identifier``. ``row`` is the grammar
    row's own name (``default_geom`` for a ``<geom>`` in a default class).
    """

    __slots__ = (
        "anchor",
        "attachable",
        "attributes",
        "by_key",
        "by_name",
        "children",
        "compose",
        "constraints",
        "defaults_tag",
        "doc",
        "holds_bodies",
        "id_attribute",
        "ignores_unknown",
        "name",
        "namespace",
        "order",
        "plans",
        "references",
        "row",
        "scope_attribute",
        "tag",
    )

    tag: str
    name: str  # the tag, as dm_control names it
    row: str
    attributes: dict[str, AttributeSpec]  # by XML name, in grammar order
    by_key: dict[str, AttributeSpec]
    by_name: dict[str, AttributeSpec]
    order: dict[str, int]  # XML attribute name -> grammar position
    # an element's attribute names as its values hold them -> how an export writes them
    plans: dict[tuple[str, ...], WritePlan]
    children: dict[str, ChildSpec]
    id_attribute: AttributeSpec | None
    scope_attribute: AttributeSpec | None
    references: tuple[AttributeSpec, ...]
    namespace: str | None
    constraints: tuple[Constraint, ...]
    anchor: str | None
    doc: str
    compose: Compose | None
    attachable: bool
    holds_bodies: bool
    ignores_unknown: bool
    defaults_tag: str | None

    def __init__(
        self,
        tag: str,
        name: str | None = None,
        *,
        attributes: Sequence[AttributeSpec] = (),
        children: Sequence[ChildSpec] = (),
        constraints: Sequence[Constraint] = (),
        anchor: str | None = None,
        doc: str = "",
        compose: Compose | None = None,
        attachable: bool = False,
        defaults: str | None = None,
        ignores_unknown: bool = False,
    ) -> None:
        self.tag = tag
        self.name = tag
        self.row = tag if name is None else name
        self.compose = compose  # top-level sections: how an attached model's section joins
        self.attachable = attachable  # a model can be attached here
        # MuJoCo's reader ignores attributes it does not know on this row
        self.ignores_unknown = ignores_unknown
        self.defaults_tag = defaults  # the child of a <default> class holding our defaults
        self.by_key = {}
        self.by_name = {}
        self.attributes = self.by_name
        self.order = {}
        self.plans = {}
        self.id_attribute = None
        self.scope_attribute = None
        for i, attribute in enumerate(attributes):
            attribute.index = i
            if attribute.anchor is None and anchor is not None:
                attribute.anchor = f"{anchor}-{attribute.name}"
            self.by_name[attribute.name] = attribute
            self.order[attribute.name] = i
            self.by_key[attribute.py_name] = attribute
            if attribute.kind == "id":
                self.id_attribute = attribute
            if attribute.scope:
                self.scope_attribute = attribute
        for attribute in attributes:
            self.by_key.setdefault(attribute.name, attribute)
        self.references = tuple(a for a in attributes if a.is_reference)
        self.namespace = self.id_attribute.namespace if self.id_attribute else None
        self.children = {}
        for i, child in enumerate(children):
            child.index = i
            self.children[child.tag] = child
        self.holds_bodies = False  # set by the grammar once every row is known
        self.constraints = tuple(constraints)
        self.anchor = anchor
        self.doc = doc

    @property
    def identifier(self) -> str | None:
        """The attribute that names elements of this row (dm_control: ``identifier``)."""
        return None if self.id_attribute is None else self.id_attribute.name

    @property
    def url(self) -> str | None:
        """This element's entry in MuJoCo's XML reference."""
        return f"{DOCS_URL}#{self.anchor}" if self.anchor else None

    def __repr__(self) -> str:
        return f"<row {self.row!r}: <{self.tag}>>"

