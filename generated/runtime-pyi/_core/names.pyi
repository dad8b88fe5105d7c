# Generated from src/typed_mjcf/_core/names.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Name scopes: the identifiers of one model, and the models attached to it by scope name.

Every model has one :class:`NameScope`: per namespace (``body``, ``joint``, ``default``, ...)
a table from name to element, and the scopes of the models attached to it, by the attached
model's name. A scoped name ``arm/elbow`` looks ``elbow`` up in the scope attached as ``arm``.

Names read from files may themselves contain ``/`` (MuJoCo accepts it, and bimanual robots
use ``left/base_link``): a name is looked up literally first, and a model may not be attached
under a scope name that such a literal name starts with (the exported names would collide).
"""
from __future__ import annotations
from collections.abc import Iterator
from typing import Protocol, TypeAlias
from typed_mjcf._build import mypyc_attr
from typed_mjcf._core.errors import ChildError, DuplicateIdentifierError
SEPARATOR = "/"
UNNAMED_MODEL = "unnamed_model"

class Named(Protocol):
    """What a scope needs of the elements it names (for messages)."""
    @property
    def path(self) -> str: ...
_Model: TypeAlias = object

@mypyc_attr(native_class=False)
class NameScope:
    """The identifiers of one model and the scopes attached to it."""
    model: _Model
    name: str | None
    parent: NameScope | None
    tables: dict[str, dict[str, Named]]
    attached: dict[str, NameScope]
    slash_heads: dict[str, int]
    waiting: dict[tuple[str, str], list[tuple[object, object]]]
    unnamed_targets: list[Named]
    def __init__(self, model: object, name: str | None = None) -> None: ...
    def lookup(self, namespace: str, name: str) -> Named | None:
        """The element of ``namespace`` named ``name`` here (a literal name), or ``None``."""
        ...
    def get(self, namespace: str, name: str) -> Named:
        """The element of ``namespace`` named ``name`` here; ``KeyError`` if there is none
        (dm_control's ``NameScope.get``)."""
        ...
    def has_identifier(self, namespace: str, name: str) -> bool: ...
    def claim(self, namespace: str, name: str, element: Named) -> None:
        """Give ``name`` to ``element``; refused with :class:`NameTaken`, whose message
        starts with the element's path (callers may say more: see ``detail``)."""
        ...
    def release(self, namespace: str, name: str, element: Named) -> None:
        """Forget ``name`` if ``element`` holds it."""
        ...
    def find(self, namespace: str, name: str) -> Named | None:
        """The element a possibly scoped name names: literally here first, then through the
        scopes of attached models (``arm/elbow``)."""
        ...
    def enter(self, name: str) -> tuple[NameScope | None, str]:
        """The attached scope a scoped name starts with, and the rest of the name."""
        ...
    def scopes(self) -> Iterator[NameScope]:
        """This scope and every scope attached under it."""
        ...
    def names(self, namespace: str) -> Iterator[str]: ...
    def attach(self, child: NameScope) -> None:
        """Make ``child`` (a model's scope, named) attached here."""
        ...
    def detach(self, child: NameScope) -> None: ...
    def rename(self, new_name: str | None) -> None:
        """This scope's model is renamed: keep its entry in the parent's scope right."""
        ...
    def check_free(self, name: str, holder: NameScope | None = None) -> None:
        """Refuse ``name`` for a model attached here (other than ``holder``) if it is taken."""
        ...
    @property
    def root(self) -> NameScope:
        """The scope of the outermost model this one is attached into (itself if none)."""
        ...
    def full_prefix(self, prefix_root: NameScope | None = None) -> str:
        """dm_control's name for :meth:`prefix`."""
        ...
    def prefix(self, top: NameScope | None = None) -> str:
        """The prefix this scope's names take in the model of scope ``top`` (the outermost
        when not given): ``""`` for ``top`` itself, ``"arm/"`` for a model attached as arm."""
        ...
    def outermost(self) -> NameScope: ...
    def is_within(self, other: NameScope) -> bool:
        """Whether this scope is ``other`` or attached (at any depth) under it."""
        ...
    def __repr__(self) -> str: ...

class NameTaken(DuplicateIdentifierError):
    """A name its scope refuses; ``detail`` is the reason without the element's path."""
    def __init__(self, element: Named, detail: str) -> None:
        super().__init__(f"{element.path}: {detail}")
        self.detail = detail
