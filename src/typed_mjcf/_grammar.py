"""The grammar tables: what the generated classes tell the runtime about each MJCF row.

Everything the runtime knows about particular tags comes from here: the generated tables
build an :class:`ElementSpec` per grammar row, with an :class:`AttributeSpec` per attribute
and a :class:`ChildSpec` per legal child, plus one :class:`GrammarFacts` for the facts that
concern the language as a whole (the name of the root default class, the world body, ...).
The specs are plain data; :mod:`typed_mjcf._codecs` gives each attribute the codec of its
kind.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Final, Literal

from typed_mjcf._codecs import Codec, make_codec

if TYPE_CHECKING:
    from typed_mjcf._tree import Element

DOCS_URL: Final = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"

Kind = Literal["string", "file", "chars", "bool", "int", "real", "keyword", "flags", "id", "ref"]
Compose = Literal["attributes", "nest", "keyframes"]


class AttributeSpec:
    """One attribute of one grammar row."""

    __slots__ = (
        "alone",
        "anchor",
        "as_is",
        "codec",
        "codec_only",
        "default",
        "direct",
        "directory",
        "doc",
        "dtype",
        "hi",
        "index",
        "is_array",
        "is_reference",
        "keywords",
        "kind",
        "lo",
        "name",
        "name_list",
        "namespace",
        "namespace_from",
        "ordered",
        "pattern",
        "py_name",
        "required",
        "scope",
    )

    name: str
    py_name: str
    kind: Kind
    dtype: str | None
    lo: int
    hi: int | None
    is_array: bool
    keywords: tuple[str, ...]
    alone: tuple[str, ...]  # flags: keywords also taken, one alone in place of the flags
    ordered: bool  # flags: read from files only in the order of ``keywords``
    namespace: str | None
    namespace_from: tuple[str, Mapping[str, str]] | None
    default: str | None
    required: bool
    pattern: str | None
    directory: tuple[str, ...]
    anchor: str | None
    doc: str
    scope: bool
    index: int
    codec: Codec
    is_reference: bool  # names another element (a fixed or an attribute-given namespace)
    direct: bool  # stored as its codec gives it: no name, link or scope bookkeeping
    codec_only: bool  # direct, and written by its codec alone (not a file, nor names)
    name_list: str | None  # a text listing names of this namespace (a <flex>'s bodies)
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
        alone: Sequence[str] = (),
        ordered: bool = False,
        namespace: str | None = None,
        namespace_from: tuple[str, Mapping[str, str]] | None = None,
        default: str | None = None,
        required: bool = False,
        pattern: str | None = None,
        directory: Sequence[str] = (),
        anchor: str | None = None,
        doc: str = "",
        scope: bool = False,
    ) -> None:
        self.name = name
        self.py_name = name if py_name is None else py_name
        self.kind = kind
        if dtype is None and kind in ("int", "real"):
            dtype = "int" if kind == "int" else "double"
        self.dtype = dtype
        self.is_array = arity is not None and kind != "chars"  # chars: arity counts characters
        self.lo, self.hi = arity if arity is not None else (1, 1)
        self.keywords = tuple(keywords)
        self.alone = tuple(alone)
        self.ordered = ordered
        self.namespace = namespace
        # objname-like references: the namespace is named by another attribute's keyword
        self.namespace_from = namespace_from
        self.default = default
        self.required = required
        self.pattern = pattern
        self.directory = tuple(directory)  # <compiler> attributes naming the folder of files
        self.anchor = anchor
        self.doc = doc
        self.scope = scope  # the root's model name: the scope of the model when attached
        self.index = 0  # position in the row, set by ElementSpec
        self.is_reference = kind == "ref" or namespace_from is not None
        self.direct = not self.is_reference and kind != "id" and not scope
        self.codec_only = self.direct and kind != "file"
        self.name_list = None  # set by the language's facts (see mark_name_list)
        # a text stored for it is written as it is (verbatim output, names of the model
        # written): what its codec writes for such a text then (see Codec.write)
        self.as_is = self.codec_only or kind == "id" or self.is_reference
        self.codec = make_codec(kind, dtype=dtype, is_array=self.is_array, lo=self.lo,
                                hi=self.hi, keywords=self.keywords, pattern=pattern,
                                alone=self.alone, ordered=ordered)

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


class ChildSpec:
    """A legal child of a row: its tag, Python class name and whether it appears once."""

    __slots__ = ("card", "class_name", "cls", "index", "once", "py_name", "single", "tag")

    tag: str
    py_name: str
    class_name: str
    single: bool
    card: str
    once: bool
    index: int
    cls: type[Element]  # the generated class, set once every class exists

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


Constraint = tuple[str, tuple[tuple[str, ...], ...]]


class ElementSpec:
    """One grammar row: tag, attributes in grammar order, legal children, constraints."""

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
        "scope_attribute",
        "tag",
    )

    tag: str
    name: str
    attributes: tuple[AttributeSpec, ...]
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
        self.name = tag if name is None else name
        self.compose = compose  # top-level sections: how an attached model's section joins
        self.attachable = attachable  # a model can be attached here
        # MuJoCo's reader ignores attributes it does not know on this row
        self.ignores_unknown = ignores_unknown
        self.defaults_tag = defaults  # the child of a <default> class holding our defaults
        self.attributes = tuple(attributes)
        self.by_key = {}
        self.by_name = {}
        self.order = {}
        self.plans = {}
        self.id_attribute = None
        self.scope_attribute = None
        for i, attribute in enumerate(self.attributes):
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
        for attribute in self.attributes:
            self.by_key.setdefault(attribute.name, attribute)
        self.references = tuple(a for a in self.attributes if a.is_reference)
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
    def url(self) -> str | None:
        """This element's entry in MuJoCo's XML reference."""
        return f"{DOCS_URL}#{self.anchor}" if self.anchor else None

    def __repr__(self) -> str:
        return f"<row {self.name!r}: <{self.tag}>>"


@dataclass(frozen=True)
class KeyframeFacts:
    """How a keyframe's vectors map onto the compiled model (for combining keyframes)."""

    qpos: str = "qpos"
    qvel: str = "qvel"
    act: str = "act"
    ctrl: str = "ctrl"
    mpos: str = "mpos"
    mquat: str = "mquat"
    time: str = "time"


@dataclass(frozen=True)
class AttachFacts:
    """``<attach>``: the attribute naming the child model (a model asset), the prefix it
    scopes the child's names with, and the attributes naming a body or frame of the child
    (or, without a model, of this model: self-attachment needs one of them)."""

    tag: str
    model: str
    prefix: str
    references: tuple[str, ...]


@dataclass(frozen=True)
class FlexcompFacts:
    """``<flexcomp>``: the bodies MuJoCo's compiler makes for it, named after it by a
    template: ``{name}`` the flexcomp's name, ``{vertex}`` a vertex's index, ``{i}``,
    ``{j}``, ``{k}`` a grid node's indices along each axis."""

    tag: str
    namespace: str  # of the bodies it makes
    dof: str  # the attribute choosing vertex bodies or grid-node bodies
    rigid: str  # the attribute that, true, makes no bodies
    vertex_body: str
    node_body: str
    nodes: Mapping[str, int]  # dof keyword -> grid nodes per axis (the dofs with node bodies)


@dataclass(frozen=True)
class GrammarFacts:
    """Facts about the language as a whole, from ``schema/facts.toml``."""

    root: str  # the declaration name of the root row
    main_class: str  # the name of the top-level default class
    world_body: str  # the name MuJoCo gives the world body
    body: str  # the tag of bodies (attachment frames are bodies)
    frame: str  # the tag of <frame>, transparent in the kinematic tree
    replicate: str  # the tag of <replicate>
    joints: frozenset[str]  # rows (declaration names) of joints: what adds to qpos
    freejoint: str  # the tag of a free joint (so is a joint whose type is free_type)
    free_type: str
    joint_type: str  # the joint attribute naming its kind
    shared_defaults: frozenset[str]  # namespaces whose kinds share one default per class
    ordered_children: frozenset[str]  # tags whose children's order matters across tags
    class_for_children: frozenset[str]  # tags whose class= applies to their children too
    inertia: str  # the tag of a body's <inertial>
    sensor_section: str  # the tag of the root's <sensor> section
    mocap: str  # the body attribute that makes a body a mocap body
    childclass: str  # the attribute naming the default class of a subtree
    dclass: str  # the attribute naming an element's default class
    class_namespace: str  # the namespace of default classes
    actuator_namespace: str  # its elements are the model's controls
    named_after_file: Mapping[str, str] = field(default_factory=lambda: {})  # namespace -> attribute
    named_from_contents: frozenset[str] = frozenset()  # namespaces named by the file they read
    attach: AttachFacts | None = None
    replicate_separator: str = "sep"  # <replicate>'s attribute suffixing copies' names
    # global settings combined on attach rather than refused: "tag@attribute" -> rule
    merge_rules: Mapping[str, str] = field(default_factory=lambda: {})
    skin_file: str = ""  # "row@attribute" of binary skin files (bone names to scope)
    replicate_count: str = "count"  # <replicate>'s attribute counting its copies
    # a copy's name: {name} the original's, {sep} the separator, {index} the copy's index
    replicate_copy: str = "{name}{sep}{index}"
    copied_with_replicate: frozenset[str] = frozenset()  # root sections copied with targets
    # string attributes listing names: "tag@attribute" -> the namespace of the names
    name_lists: Mapping[str, str] = field(default_factory=lambda: {})
    flexcomp: FlexcompFacts | None = None
    keyframe: KeyframeFacts = KeyframeFacts()
