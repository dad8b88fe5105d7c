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
UNNAMED_MODEL = "unnamed_model"  # what an attached model without a name is called


class Named(Protocol):
    """What a scope needs of the elements it names (for messages)."""

    @property
    def path(self) -> str: ...


# a name, not `object`: a compiled class's annotations are loaded by name, and mypyc
# finds no builtins.object among its names
_Model: TypeAlias = object


@mypyc_attr(native_class=False)  # keeps __weakref__ (a native class has none)
class NameScope:
    """The identifiers of one model and the scopes attached to it."""

    __slots__ = ("__weakref__", "attached", "model", "name", "parent", "slash_heads", "tables",
                 "unnamed_targets", "waiting")

    model: _Model  # the model whose scope this is
    name: str | None  # the model's name: its scope in the model it is attached to
    parent: NameScope | None  # the scope of the model this one is attached to
    tables: dict[str, dict[str, Named]]
    attached: dict[str, NameScope]  # scopes of attached models, by name
    slash_heads: dict[str, int]  # literal names with '/': their first part -> how many
    # references by a name nothing has yet: (namespace, name) -> (element, attribute) pairs,
    # linked when the name is claimed (entries are checked then, so none needs removing)
    waiting: dict[tuple[str, str], list[tuple[object, object]]]
    # elements of this scope that a reference links to while they have no name: an export
    # names them (entries are checked then, so none needs removing)
    unnamed_targets: list[Named]

    def __init__(self, model: object, name: str | None = None) -> None:
        self.model = model
        self.name = name
        self.parent = None
        self.tables = {}
        self.attached = {}
        self.slash_heads = {}
        self.waiting = {}
        self.unnamed_targets = []

    # ------------------------------------------------------------------ identifiers

    def lookup(self, namespace: str, name: str) -> Named | None:
        """The element of ``namespace`` named ``name`` here (a literal name), or ``None``."""
        table = self.tables.get(namespace)
        return None if table is None else table.get(name)

    def get(self, namespace: str, name: str) -> Named:
        """The element of ``namespace`` named ``name`` here; ``KeyError`` if there is none
        (dm_control's ``NameScope.get``)."""
        found = self.lookup(namespace, name)
        if found is None:
            raise KeyError(f"no {namespace} named {name!r} in scope {self.name!r}")
        return found

    def has_identifier(self, namespace: str, name: str) -> bool:
        return self.lookup(namespace, name) is not None

    def claim(self, namespace: str, name: str, element: Named) -> None:
        """Give ``name`` to ``element``; refused with :class:`NameTaken`, whose message
        starts with the element's path (callers may say more: see ``detail``)."""
        table = self.tables.get(namespace)
        if table is None:
            table = self.tables[namespace] = {}
        holder = table.get(name)
        if holder is not None and holder is not element:
            raise NameTaken(element, f"expected a name unique in namespace {namespace!r}, "
                                     f"but {holder.path} has it")
        if holder is None and SEPARATOR in name:
            head = name.split(SEPARATOR, 1)[0]
            if head in self.attached:
                raise NameTaken(
                    element, f"the name {name!r} would collide with the names of the model "
                    f"attached as {head!r} (its names are written {head}/...)")
            self.slash_heads[head] = self.slash_heads.get(head, 0) + 1
        table[name] = element

    def release(self, namespace: str, name: str, element: Named) -> None:
        """Forget ``name`` if ``element`` holds it."""
        table = self.tables.get(namespace)
        if table is not None and table.get(name) is element:
            del table[name]
            if SEPARATOR in name:
                head = name.split(SEPARATOR, 1)[0]
                left = self.slash_heads.get(head, 0) - 1
                if left > 0:
                    self.slash_heads[head] = left
                else:
                    self.slash_heads.pop(head, None)

    def find(self, namespace: str, name: str) -> Named | None:
        """The element a possibly scoped name names: literally here first, then through the
        scopes of attached models (``arm/elbow``)."""
        found = self.lookup(namespace, name)
        if found is not None or SEPARATOR not in name:
            return found
        scope, rest = self.enter(name)
        if scope is None or scope is self:
            return None
        return scope.find(namespace, rest)

    def enter(self, name: str) -> tuple[NameScope | None, str]:
        """The attached scope a scoped name starts with, and the rest of the name."""
        head, _, rest = name.partition(SEPARATOR)
        return self.attached.get(head), rest

    def scopes(self) -> Iterator[NameScope]:
        """This scope and every scope attached under it."""
        stack: list[NameScope] = [self]
        while stack:
            scope = stack.pop()
            yield scope
            stack.extend(scope.attached.values())

    def names(self, namespace: str) -> Iterator[str]:
        table = self.tables.get(namespace)
        return iter(()) if table is None else iter(list(table))

    # ------------------------------------------------------------------ attached scopes

    def attach(self, child: NameScope) -> None:
        """Make ``child`` (a model's scope, named) attached here."""
        name = child.name
        if name is None:
            raise ChildError("a model needs a name to be attached: its names are scoped "
                             "'<model>/...'; set RootElement(model='...') or model.model = '...'")
        self.check_free(name, None)
        self.attached[name] = child
        child.parent = self

    def detach(self, child: NameScope) -> None:
        if child.name is not None and self.attached.get(child.name) is child:
            del self.attached[child.name]
        child.parent = None

    def rename(self, new_name: str | None) -> None:
        """This scope's model is renamed: keep its entry in the parent's scope right."""
        parent = self.parent
        if parent is not None:
            if new_name is None:
                raise ChildError(f"model {self.name!r} is attached: it keeps a name while it "
                                 f"is (detach() it first)")
            parent.check_free(new_name, self)
            if self.name is not None and parent.attached.get(self.name) is self:
                del parent.attached[self.name]
            parent.attached[new_name] = self
        self.name = new_name

    def check_free(self, name: str, holder: NameScope | None = None) -> None:
        """Refuse ``name`` for a model attached here (other than ``holder``) if it is taken."""
        taken = self.attached.get(name)
        if taken is not None and taken is not holder:
            raise ChildError(
                f"another model named {name!r} is already attached to this model; names are "
                f"scoped by model name, so give each attached model its own (model.model = ...)")
        if name in self.slash_heads:
            raise ChildError(
                f"the model has names that start with {name + SEPARATOR!r} (read from a file); "
                f"a model attached as {name!r} would write names that collide with them: "
                f"give the attached model another name")

    @property
    def root(self) -> NameScope:
        """The scope of the outermost model this one is attached into (itself if none)."""
        return self.outermost()

    def full_prefix(self, prefix_root: NameScope | None = None) -> str:
        """dm_control's name for :meth:`prefix`."""
        return self.prefix(prefix_root)

    def prefix(self, top: NameScope | None = None) -> str:
        """The prefix this scope's names take in the model of scope ``top`` (the outermost
        when not given): ``""`` for ``top`` itself, ``"arm/"`` for a model attached as arm."""
        parts: list[str] = []
        scope = self
        while scope is not top and scope.parent is not None:
            parts.append(scope.name or "")
            scope = scope.parent
        return "".join(part + SEPARATOR for part in reversed(parts))

    def outermost(self) -> NameScope:
        scope = self
        while scope.parent is not None:
            scope = scope.parent
        return scope

    def is_within(self, other: NameScope) -> bool:
        """Whether this scope is ``other`` or attached (at any depth) under it."""
        scope: NameScope | None = self
        while scope is not None:
            if scope is other:
                return True
            scope = scope.parent
        return False

    def __repr__(self) -> str:
        return f"<NameScope {self.name!r}>"


class NameTaken(DuplicateIdentifierError):
    """A name its scope refuses; ``detail`` is the reason without the element's path."""

    def __init__(self, element: Named, detail: str) -> None:
        super().__init__(f"{element.path}: {detail}")
        self.detail = detail
