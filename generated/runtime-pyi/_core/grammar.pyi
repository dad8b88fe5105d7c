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
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Final, Literal
from typed_mjcf._core.codecs import Codec, make_codec
from typed_mjcf._core.tree import Element
DOCS_URL: Final = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"
Kind = Literal["string", "file", "chars", "bool", "int", "real", "keyword", "flags", "id", "ref"]
Compose = Literal["attributes", "nest", "keyframes"]

class AttributeSpec:
    """One attribute of one grammar row."""
    name: str
    py_name: str
    kind: Kind
    dtype: str | None
    lo: int
    hi: int | None
    is_array: bool
    keywords: tuple[str, ...]
    numbers: tuple[tuple[str, int], ...]
    alone: tuple[str, ...]
    ordered: bool
    namespace: str | None
    namespace_from: tuple[str, Mapping[str, str]] | None
    default: str | None
    computed: bool
    required: bool
    pattern: str | None
    bounds: tuple[tuple[str, float], ...]
    off: tuple[tuple[str, float], ...]
    directory: tuple[str, ...]
    anchor: str | None
    doc: str
    scope: bool
    index: int
    codec: Codec
    is_reference: bool
    direct: bool
    codec_only: bool
    bare: bool
    name_list: str | None
    as_is: bool
    def __init__(
        self,
        name: str,
        kind: Kind,
        *,
        py_name: str | None = None,
        dtype: str | None = None,
        arity: tuple[int, int | None] | None = None,
        keywords: Sequence[str] = (),
        numbers: Sequence[tuple[str, int]] = (),
        alone: Sequence[str] = (),
        ordered: bool = False,
        namespace: str | None = None,
        namespace_from: tuple[str, Mapping[str, str]] | None = None,
        default: str | None = None,
        computed: bool = False,
        required: bool = False,
        pattern: str | None = None,
        bounds: Sequence[tuple[str, float]] = (),
        off: Sequence[tuple[str, float]] = (),
        directory: Sequence[str] = (),
        anchor: str | None = None,
        doc: str = "",
        scope: bool = False,
    ) -> None: ...
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
    cls: type[Element]
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
