"""Composition: attaching models to each other, dm_control style.

An attached model stays a model of its own (its elements, names and defaults are untouched);
the parent holds it through an *attachment frame*, a ``<body>`` placed where it was attached.
At export the attached model is written inline under its scope: every identifier and
reference is prefixed ``<model name>/``, its default classes nest in a class named after the
scope, and its sections join the parent's (see ``ElementSpec.compose``).
"""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING

from typed_mjcf.errors import ChildError, InvalidTypeError, InvalidValueError

if TYPE_CHECKING:
    from typed_mjcf._element import Element
    from typed_mjcf._root import ModelRoot

MAIN_CLASS = "main"  # MuJoCo's name for a model's root default class


def scope_name(model: ModelRoot) -> str:
    name = model.get_attributes().get("model")
    if not isinstance(name, str):
        raise InvalidValueError(
            "a model needs a name to be attached: its names are scoped '<model>/...'; "
            "set RootElement(model='...') or model.model = '...'")
    if "/" in name:
        raise InvalidValueError(f"model name {name!r}: '/' separates scopes")
    return name


def top_model(model: ModelRoot) -> ModelRoot:
    """The outermost model ``model`` is attached into (itself when not attached)."""
    while model._frame is not None:  # pyright: ignore[reportPrivateUsage]
        model = model._frame.root  # pyright: ignore[reportPrivateUsage]
    return model


def _host(site: Element) -> tuple[Element, dict[str, object]]:
    """Where the attachment frame goes, and the pose it takes."""
    if "body" in site.spec.children:
        return site, {}
    if site._SPEC.tag == site.root._SPEC.tag:  # pyright: ignore[reportPrivateUsage]
        return site.root._single_or_new(_body_holder_tag(site.root)), {}  # pyright: ignore[reportPrivateUsage]
    parent = site.parent
    if parent is None or "body" not in parent.spec.children:
        raise ChildError(f"{site.path}: a model can only be attached where bodies can go")
    body_spec = parent.spec.children["body"]
    from typed_mjcf._element import element_class

    body_attributes = element_class(body_spec.class_name)._SPEC.by_name  # pyright: ignore[reportPrivateUsage]
    pose = {name: value for name, value in site._attrs.items()  # pyright: ignore[reportPrivateUsage]
            if name in body_attributes and body_attributes[name].kind == "real"}
    return parent, pose


def _body_holder_tag(root: ModelRoot) -> str:
    for tag, child in root.spec.children.items():
        from typed_mjcf._element import element_class

        if "body" in element_class(child.class_name)._SPEC.children:  # pyright: ignore[reportPrivateUsage]
            return tag
    raise ChildError("the grammar has no section that holds bodies")  # pragma: no cover


def attach(site: Element, model: ModelRoot) -> Element:
    """Attach ``model`` at ``site``; return the attachment frame."""
    from typed_mjcf._root import ModelRoot

    if not site.spec.attachable:
        raise ChildError(f"{site.path}: a model cannot be attached to a <{site.tag}>")
    if not isinstance(model, ModelRoot):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"{site.path}: attach() takes a model (RootElement), got {model!r}")
    root = site.root
    if model._frame is not None:  # pyright: ignore[reportPrivateUsage]
        raise ChildError(f"model {scope_name(model)!r} is already attached at "
                         f"{model._frame.path}; detach() it first or attach a copy")  # pyright: ignore[reportPrivateUsage]
    outer: ModelRoot | None = root
    while outer is not None:
        if outer is model:
            raise ChildError(f"cannot attach model {model.get_attributes().get('model')!r} "
                             f"into itself")
        frame = outer._frame  # pyright: ignore[reportPrivateUsage]
        outer = None if frame is None else frame.root
    name = scope_name(model)
    if name in root._scopes:  # pyright: ignore[reportPrivateUsage]
        raise ChildError(
            f"another model named {name!r} is already attached to this model; names are "
            f"scoped by model name, so give each attached model its own (model.model = ...)")
    check_compatible(top_model(root), model)
    host, pose = _host(site)
    frame = host._add_child("body", None, pose)  # pyright: ignore[reportPrivateUsage]
    object.__setattr__(frame, "_attached", model)
    object.__setattr__(model, "_frame", frame)
    root._scopes[name] = model  # pyright: ignore[reportPrivateUsage]
    return frame


def detach(model: ModelRoot) -> None:
    """Undo ``attach``: remove the attachment frame (with anything added to it)."""
    frame = model._frame  # pyright: ignore[reportPrivateUsage]
    if frame is None:
        raise ChildError(f"model {model.get_attributes().get('model')!r} is not attached")
    parent_root = frame.root
    object.__setattr__(frame, "_attached", None)
    frame.remove()
    del parent_root._scopes[scope_name(model)]  # pyright: ignore[reportPrivateUsage]
    object.__setattr__(model, "_frame", None)


def attachments(model: ModelRoot) -> list[tuple[Element, ModelRoot]]:
    """The attachment frames of ``model`` and their models, in document order."""
    scopes = model._scopes  # pyright: ignore[reportPrivateUsage]
    if not scopes:
        return []
    frames = {id(child._frame): child for child in scopes.values()}  # pyright: ignore[reportPrivateUsage]
    return [(e, frames[id(e)]) for e in model.iter_elements() if id(e) in frames]


# ----------------------------------------------------------------------------- global sections


def _effective(section: Element | None, child: Element, name: str) -> object:
    """The value ``section`` has for ``name`` (its grammar default when unset or absent)."""
    value = None if section is None else section._attrs.get(name)  # pyright: ignore[reportPrivateUsage]
    if value is None:
        attribute = child.spec.by_name[name]
        return None if attribute.default is None else attribute.convert(attribute.default)
    return value


def _same(a: object, b: object) -> bool:
    import numpy as np

    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return bool(np.array_equal(np.asarray(a), np.asarray(b)))
    return a == b


def conflicts(parent: Element | None, child: Element, where: str) -> list[str]:
    """Attributes set in ``child``'s section whose value differs from the parent's."""
    found: list[str] = []
    for name in child._attrs:  # pyright: ignore[reportPrivateUsage]
        if name in folder_attributes():
            continue  # folders resolve the attached model's own files
        mine, theirs = _effective(parent, child, name), _effective(child, child, name)
        if not _same(mine, theirs):
            found.append(f"<{where}> {name}: {theirs!r} in the attached model, "
                         f"{mine!r} in the model it is attached to")
    for grandchild in child.get_children():
        if child.spec.children[grandchild.tag].single:
            existing = None if parent is None else parent._single_child(grandchild.tag)  # pyright: ignore[reportPrivateUsage]
            found += conflicts(existing, grandchild, f"{where}/{grandchild.tag}")
    return found


@functools.cache
def folder_attributes() -> frozenset[str]:
    """The <compiler> attributes that name folders of files: each model keeps its own."""
    from typed_mjcf._element import _REGISTRY  # pyright: ignore[reportPrivateUsage]

    folders: set[str] = set()
    for cls in _REGISTRY.values():
        for attribute in cls._SPEC.attributes:  # pyright: ignore[reportPrivateUsage]
            folders.update(attribute.directory)
    return frozenset(folders)


def check_compatible(parent: ModelRoot, model: ModelRoot) -> None:
    """Refuse to attach a model whose global settings contradict the parent's."""
    problems: list[str] = []
    for section in model.get_children():
        if section.spec.compose != "attributes":
            continue
        mine = parent._single_child(section.tag)  # pyright: ignore[reportPrivateUsage]
        problems += conflicts(mine, section, section.tag)
    if problems:
        raise InvalidValueError(
            f"cannot attach model {model.get_attributes().get('model')!r}: its global settings "
            "differ from the model it is attached to:\n  " + "\n  ".join(problems))
