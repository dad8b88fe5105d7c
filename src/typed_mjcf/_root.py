"""The model root: identifier namespaces, look-ups, and the model-wide operations."""

from __future__ import annotations

import functools
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING, Self

from typed_mjcf._element import Element
from typed_mjcf.errors import InvalidValueError, did_you_mean

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._validate import Finding


class ModelRoot(Element):
    """Behaviour of ``<mujoco>``, the root of a model. Use ``typed_mjcf.RootElement``."""

    __slots__ = ("_base_dir", "_frame", "_identifiers", "_scopes")

    _identifiers: dict[str, dict[str, Element]]
    _base_dir: str | None
    _frame: Element | None  # where this model is attached, if it is
    _scopes: dict[str, ModelRoot]  # models attached to this one, by scope name

    def __init__(self, **kwargs: object) -> None:
        initial: dict[str, object] = {
            "_attrs": {}, "_children": [], "_parent": None, "_root": self, "_singles": None,
            "_attached": None, "_identifiers": {}, "_base_dir": None, "_frame": None,
            "_scopes": {},
        }
        for name, value in initial.items():
            object.__setattr__(self, name, value)
        self._init_attributes(kwargs)

    @classmethod
    def _blank(cls, parent: Element | None, root: ModelRoot | None) -> Self:
        model = super()._blank(parent, root)
        object.__setattr__(model, "_root", model)
        object.__setattr__(model, "_identifiers", {})
        object.__setattr__(model, "_base_dir", None)
        object.__setattr__(model, "_frame", None)
        object.__setattr__(model, "_scopes", {})
        return model

    # ------------------------------------------------------------------ namespaces

    def _lookup_identifier(self, namespace: str, name: str) -> Element | None:
        table = self._identifiers.get(namespace)
        return None if table is None else table.get(name)

    def _remember_identifier(self, namespace: str, name: str, element: Element) -> None:
        table = self._identifiers.get(namespace)
        if table is None:
            table = self._identifiers[namespace] = {}
        table[name] = element

    def _forget_identifier(self, namespace: str | None, name: object, element: Element) -> None:
        assert namespace is not None and isinstance(name, str)
        table = self._identifiers.get(namespace)
        if table is not None and table.get(name) is element:
            del table[name]

    def _forget_element(self, element: Element) -> None:
        id_attribute = element._SPEC.id_attribute  # pyright: ignore[reportPrivateUsage]
        if id_attribute is not None:
            name = element._attrs.get(id_attribute.name)  # pyright: ignore[reportPrivateUsage]
            if name is not None:
                self._forget_identifier(id_attribute.namespace, name, element)

    def _rebuild_identifiers(self) -> None:
        self._identifiers.clear()
        for element in self.iter_elements():
            id_attribute = element._SPEC.id_attribute  # pyright: ignore[reportPrivateUsage]
            if id_attribute is None or id_attribute.namespace is None:
                continue
            name = element._attrs.get(id_attribute.name)  # pyright: ignore[reportPrivateUsage]
            if isinstance(name, str):
                self._remember_identifier(id_attribute.namespace, name, element)

    @property
    def namespaces(self) -> frozenset[str]:
        """The identifier namespaces of the grammar (``body``, ``joint``, ``geom``, ...)."""
        return _namespaces()

    def _check_namespace(self, namespace: str) -> None:
        known = _namespaces()
        if namespace not in known:
            raise InvalidValueError(
                f"unknown namespace {namespace!r}{did_you_mean(namespace, known)}; "
                f"namespaces: {', '.join(sorted(known))}"
            )

    def find(self, namespace: str, identifier: str) -> Element | None:
        """The element named ``identifier`` in ``namespace``, or ``None``. O(1) per scope:
        ``find("joint", "arm/elbow")`` looks in the model attached as ``arm``."""
        self._check_namespace(namespace)
        model: ModelRoot = self
        while "/" in identifier:
            scope, identifier = identifier.split("/", 1)
            attached = model._scopes.get(scope)
            if attached is None:
                return None
            model = attached
        return model._lookup_identifier(namespace, identifier)

    def detach(self) -> None:
        """Undo this model's attachment: its frame (and anything added to it) is removed."""
        from typed_mjcf._compose import detach

        detach(self)

    @property
    def attachment_frame(self) -> Element | None:
        """Where this model is attached (its frame in the parent model), if it is."""
        return self._frame

    @property
    def namescope(self) -> str:
        """This model's scope prefix in the outermost model it is attached into ("" if none)."""
        parts: list[str] = []
        model: ModelRoot = self
        while model._frame is not None:
            parts.append(str(model.get_attributes().get("model")))
            model = model._frame.root
        return "".join(p + "/" for p in reversed(parts))

    def find_all(self, namespace: str) -> Sequence[Element]:
        """Every element of ``namespace`` (named or not), attached models' included, in the
        order the exported XML has them."""
        self._check_namespace(namespace)
        return [e for e in self.iter_exported()
                if e._SPEC.namespace == namespace and e is not self]  # pyright: ignore[reportPrivateUsage]

    def iter_exported(self) -> Iterator[Element]:
        """Every element of the composed model, in the order the exported XML has them:
        attached models' bodies inside their frames, their other sections after ours."""
        pending: list[ModelRoot] = []

        def walk(elements: list[Element]) -> Iterator[Element]:
            stack = list(reversed(elements))
            while stack:
                element = stack.pop()
                yield element
                inside = list(element._children)  # pyright: ignore[reportPrivateUsage]
                attached = element._attached  # pyright: ignore[reportPrivateUsage]
                if attached is not None:
                    for section in attached._children:  # pyright: ignore[reportPrivateUsage]
                        if "body" in section._SPEC.children:  # pyright: ignore[reportPrivateUsage]
                            inside += section._children  # pyright: ignore[reportPrivateUsage]
                    pending.append(attached)
                stack.extend(reversed(inside))

        yield from walk([self])
        while pending:
            model = pending.pop(0)
            for section in model._children:  # pyright: ignore[reportPrivateUsage]
                if "body" not in section._SPEC.children:  # pyright: ignore[reportPrivateUsage]
                    yield from walk(list(section._children))  # pyright: ignore[reportPrivateUsage]

    # ------------------------------------------------------------------ copies

    def __deepcopy__(self, memo: dict[int, object]) -> Self:
        """An independent copy, with copies of the models attached to it."""
        clone = self._clone_tree(None, None, memo)
        object.__setattr__(clone, "_identifiers", {})
        object.__setattr__(clone, "_base_dir", self._base_dir)
        object.__setattr__(clone, "_frame", None)
        object.__setattr__(clone, "_scopes", {
            name: memo.get(id(model), model) for name, model in self._scopes.items()})
        for element in clone.iter_elements():
            object.__setattr__(element, "_root", clone)
        object.__setattr__(clone, "_root", clone)
        clone._remap_references(memo)
        clone._rebuild_identifiers()
        return clone

    # ------------------------------------------------------------------ MuJoCo

    @property
    def base_dir(self) -> str | None:
        """The directory relative file paths resolve against (the parsed file's folder)."""
        return self._base_dir

    def get_assets(self) -> dict[str, bytes]:
        """The files the model uses, by the names its exported XML gives them (for a VFS)."""
        from typed_mjcf._assets_io import collect_assets

        return collect_assets(self).files

    def validate(self) -> list[Finding]:
        """What MuJoCo's grammar forbids beyond single values: presence constraints, required
        attributes and children, references that name nothing, unused default classes, ...
        Each finding names the element path and the rule; warnings don't stop compile()."""
        from typed_mjcf._validate import validate

        return validate(self)

    def compile(self) -> mujoco.MjModel:
        """Validate, then compile with MuJoCo (assets passed through a virtual file system).

        Raises ``ValidationError`` listing every error ``validate()`` finds, or
        ``CompileError`` with MuJoCo's message and the path of the element it concerns."""
        from typed_mjcf._bridge import compile_model
        from typed_mjcf._validate import ensure_valid

        ensure_valid(self)
        return compile_model(self)

    def to_spec(self) -> mujoco.MjSpec:
        """This model as a ``mujoco.MjSpec``."""
        from typed_mjcf._bridge import to_spec

        return to_spec(self)


@functools.cache
def _namespaces() -> frozenset[str]:
    from typed_mjcf._element import _REGISTRY  # pyright: ignore[reportPrivateUsage]

    return frozenset(
        cls._SPEC.namespace for cls in _REGISTRY.values()  # pyright: ignore[reportPrivateUsage]
        if cls._SPEC.namespace is not None  # pyright: ignore[reportPrivateUsage]
    )
