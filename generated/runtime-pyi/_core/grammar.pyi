# Generated from src/typed_mjcf/_core/grammar.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
    index: int = field(init=False)
    codec: Codec = field(init=False)
    is_reference: bool = field(init=False)
    direct: bool = field(init=False)
    codec_only: bool = field(init=False)
    bare: bool = field(init=False)
    name_list: str | None = field(init=False)
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
        ...
    @property
    def url(self) -> str | None:
        """This attribute's entry in MuJoCo's XML reference."""
        ...
    def describe(self) -> str:
        """The attribute's MJCF type in words, e.g. ``real[3]`` or ``keyword: hinge|slide``."""
        ...
    def __repr__(self) -> str: ...
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
    tag: str
    py_name: str
    class_name: str
    single: bool
    card: str
    once: bool
    index: int
    cls: type[RowClass]
    holder: ElementSpec
    def __init__(self, tag: str, class_name: str, *, single: bool = False, card: str = "*",
                 py_name: str | None = None) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def repeated(self) -> bool:
        """Whether the parent holds a list of these (dm_control: ``repeated``)."""
        ...
    @property
    def on_demand(self) -> bool:
        """Whether this once-only child exists only once added (``on_demand_children``, as
        dm_control's schema marks them): those of the rows that hold bodies (``<inertial>``)."""
        ...
    @property
    def attributes(self) -> dict[str, AttributeSpec]: ...
    @property
    def children(self) -> dict[str, ChildSpec]: ...
    @property
    def namespace(self) -> str | None: ...
    @property
    def identifier(self) -> str | None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __repr__(self) -> str: ...
Constraint = tuple[str, tuple[tuple[str, ...], ...]]

class ElementSpec:
    """One grammar row: tag, attributes in grammar order, legal children, constraints.

    Shaped as dm_control's ``ElementSpec`` where they meet: ``name`` is the tag,
    ``attributes`` maps XML names to attributes, ``children`` tags to :class:`ChildSpec`
    (``repeated``, ``on_demand``), ``namespace`` and ``identifier``. ``row`` is the grammar
    row's own name (``default_geom`` for a ``<geom>`` in a default class).
    """
    tag: str
    name: str
    row: str
    attributes: dict[str, AttributeSpec]
    by_key: dict[str, AttributeSpec]
    by_name: dict[str, AttributeSpec]
    order: dict[str, int]
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
    ) -> None: ...
    @property
    def identifier(self) -> str | None:
        """The attribute that names elements of this row (dm_control: ``identifier``)."""
        ...
    @property
    def url(self) -> str | None:
        """This element's entry in MuJoCo's XML reference."""
        ...
    def __repr__(self) -> str: ...
