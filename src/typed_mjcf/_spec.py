"""Run-time grammar tables: what the generated classes tell the runtime about each row.

An :class:`AttributeSpec` is also the descriptor that reads and writes its attribute on an
element, so each attribute costs one object and one dictionary lookup per access.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Final, Literal, overload

from typed_mjcf._convert import Converter, make_converter

if TYPE_CHECKING:
    from typed_mjcf._element import Element

DOCS_URL: Final = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"

Kind = Literal["string", "file", "chars", "bool", "int", "real", "keyword", "flags", "id", "ref"]


class AttributeSpec:
    """One attribute of one grammar row, and the descriptor that accesses it."""

    __slots__ = (
        "anchor",
        "convert",
        "default",
        "directory",
        "dtype",
        "hi",
        "index",
        "is_array",
        "keywords",
        "kind",
        "lo",
        "name",
        "namespace",
        "pattern",
        "py_name",
        "required",
        "text",
    )

    name: str
    py_name: str
    kind: Kind
    dtype: str | None
    lo: int
    hi: int | None
    is_array: bool
    keywords: tuple[str, ...]
    namespace: str | None
    default: str | None
    required: bool
    pattern: str | None
    directory: tuple[str, ...]
    anchor: str | None
    text: str
    convert: Converter
    index: int

    def __init__(
        self,
        name: str,
        py_name: str,
        kind: Kind,
        *,
        dtype: str | None = None,
        arity: tuple[int, int | None] | None = None,
        keywords: Sequence[str] = (),
        namespace: str | None = None,
        default: str | None = None,
        required: bool = False,
        pattern: str | None = None,
        directory: Sequence[str] = (),
        anchor: str | None = None,
        text: str = "",
    ) -> None:
        self.name = name
        self.py_name = py_name
        self.kind = kind
        self.dtype = dtype
        self.is_array = arity is not None and kind != "chars"  # chars: arity counts characters
        self.lo, self.hi = arity if arity is not None else (1, 1)

        self.keywords = tuple(keywords)
        self.namespace = namespace
        self.default = default
        self.required = required
        self.pattern = pattern
        self.directory = tuple(directory)  # <compiler> attributes naming the folder of files
        self.anchor = anchor
        self.text = text
        self.index = 0  # position in the row, set by ElementSpec
        self.convert: Converter = make_converter(self)

    @overload
    def __get__(self, obj: None, owner: type[object] | None = None) -> AttributeSpec: ...
    @overload
    def __get__(self, obj: Element, owner: type[object] | None = None) -> object: ...
    def __get__(self, obj: Element | None, owner: type[object] | None = None) -> object:
        if obj is None:
            return self
        return obj._attrs.get(self.name)  # pyright: ignore[reportPrivateUsage]

    def __set__(self, obj: Element, value: object) -> None:
        obj._set_attribute(self, value)  # pyright: ignore[reportPrivateUsage]

    def __delete__(self, obj: Element) -> None:
        obj._set_attribute(self, None)  # pyright: ignore[reportPrivateUsage]

    @property
    def url(self) -> str | None:
        return f"{DOCS_URL}#{self.anchor}" if self.anchor else None

    def describe(self) -> str:
        """The attribute's MJCF type in words, e.g. ``real[3]`` or ``keyword: hinge|slide``."""
        if self.kind in ("keyword", "flags"):
            return f"{self.kind}: {'|'.join(self.keywords)}"
        if self.kind in ("id", "ref"):
            return f"{self.kind}<{self.namespace}>"
        base = self.dtype if self.kind == "real" and self.dtype else self.kind
        if not self.is_array:
            return base
        if self.hi is None:
            return f"{base}[]" if self.lo == 0 else f"{base}[{self.lo}..]"
        return f"{base}[{self.lo}]" if self.lo == self.hi else f"{base}[{self.lo}..{self.hi}]"

    def __repr__(self) -> str:
        return f"<attribute {self.name!r}: {self.describe()}>"


class ChildSpec:
    """A legal child of a row: its tag, Python class name and whether it appears once."""

    __slots__ = ("card", "class_name", "cls", "index", "py_name", "single", "tag")

    tag: str
    py_name: str
    class_name: str
    single: bool
    card: str
    index: int
    cls: type[Element] | None  # the generated class, resolved on first use

    def __init__(self, tag: str, py_name: str, class_name: str, single: bool, card: str) -> None:
        self.tag = tag
        self.py_name = py_name
        self.class_name = class_name
        self.single = single
        self.card = card
        self.index = 0
        self.cls = None


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
        "id_attribute",
        "name",
        "namespace",
        "order",
        "tag",
        "text",
    )

    tag: str
    name: str
    attributes: tuple[AttributeSpec, ...]
    by_key: dict[str, AttributeSpec]
    by_name: dict[str, AttributeSpec]
    children: dict[str, ChildSpec]
    namespace: str | None
    constraints: tuple[tuple[str, tuple[tuple[str, ...], ...]], ...]
    anchor: str | None
    text: str
    compose: str | None
    attachable: bool
    defaults_tag: str | None
    order: dict[str, int]  # XML attribute name -> grammar position

    def __init__(
        self,
        tag: str,
        name: str,
        attributes: Sequence[AttributeSpec],
        children: Sequence[ChildSpec] = (),
        *,
        constraints: Sequence[tuple[str, tuple[tuple[str, ...], ...]]] = (),
        anchor: str | None = None,
        text: str = "",
        compose: str | None = None,
        attachable: bool = False,
        defaults_tag: str | None = None,
    ) -> None:
        self.tag = tag
        self.name = name
        self.compose = compose  # top-level sections: how an attached model's section joins
        self.attachable = attachable  # a model can be attached here
        self.defaults_tag = defaults_tag  # the child of a <default> class holding our defaults
        self.attributes = tuple(attributes)
        self.by_key = {}
        self.by_name = {a.name: a for a in self.attributes}
        self.order = {a.name: i for i, a in enumerate(self.attributes)}
        # annotated here: at class level mypy would read an AttributeSpec as a descriptor
        self.id_attribute: AttributeSpec | None = None
        for i, a in enumerate(self.attributes):
            a.index = i
            self.by_key[a.py_name] = a
            self.by_key.setdefault(a.name, a)
            if a.kind == "id":
                self.id_attribute = a
        if "class" in self.by_key:
            self.by_key.setdefault("dclass", self.by_key["class"])  # dm_control's spelling
        self.namespace = self.id_attribute.namespace if self.id_attribute else None
        self.children = {}
        for i, c in enumerate(children):
            c.index = i
            self.children[c.tag] = c
        self.constraints = tuple(constraints)
        self.anchor = anchor
        self.text = text

    @property
    def url(self) -> str | None:
        return f"{DOCS_URL}#{self.anchor}" if self.anchor else None

    def attribute_names(self) -> list[str]:
        return [a.py_name for a in self.attributes]
