"""Composition: attaching models to each other, dm_control style.

An attached model stays a model of its own (its elements, names and defaults are untouched);
the parent holds it through an *attachment frame*, a ``<body>`` placed where it was attached.
At export the attached model is written inline under its scope: every identifier and
reference is prefixed ``<model name>/``, its default classes nest in a class named after the
scope, and its sections join the parent's (see ``ElementSpec.compose``).
"""

from __future__ import annotations

from typed_mjcf import _tree
from typed_mjcf._export import folder_attributes
from typed_mjcf._tree import Element, ModelBase, grammar_facts, same_value
from typed_mjcf.errors import ChildError, IllegalChildError, InvalidTypeError, InvalidValueError


def scope_name(model: ModelBase) -> str:
    """The model's name, which scopes its names where it is attached."""
    name = _tree.scope_of(model).name
    if name is None:
        raise InvalidValueError(
            "a model needs a name to be attached: its names are scoped '<model>/...'; "
            "set RootElement(model='...') or model.model = '...'")
    return name


def top_model(model: ModelBase) -> ModelBase:
    """The outermost model ``model`` is attached into (itself when not attached)."""
    return _tree.scope_model(_tree.scope_of(model).outermost())


def _host(site: Element) -> tuple[Element, dict[str, object]]:
    """Where the attachment frame goes, and the pose it takes."""
    if site.spec.holds_bodies:
        return site, {}
    root = _tree.model_of(site)
    if isinstance(site, ModelBase) and root is site:
        holder = next(tag for tag, child in site.spec.children.items()
                      if _tree.element_class(child.class_name).spec.holds_bodies)
        return getattr(site, site.spec.children[holder].py_name), {}
    parent = site.parent
    if parent is None or not parent.spec.holds_bodies:
        raise ChildError(f"{site.path}: a model can only be attached where bodies can go")
    body_spec = parent.spec.children[grammar_facts().body]
    body_attributes = _tree.element_class(body_spec.class_name).spec.by_name
    pose = {name: _tree.read_value(site, site.spec.by_name[name])
            for name in _tree.values(site)
            if name in body_attributes and body_attributes[name].kind == "real"}
    return parent, pose


def attach(site: Element, model: ModelBase) -> Element:
    """Attach ``model`` at ``site``; return the attachment frame."""
    if not isinstance(model, ModelBase):  # pyright: ignore[reportUnnecessaryIsInstance]
        raise InvalidTypeError(f"{site.path}: attach() expected a mjcf.RootElement (a model), "
                               f"got {model!r}")
    if not site.spec.attachable:
        raise IllegalChildError(f"{site.path}: a model cannot be attached to a <{site.tag}>")
    root = _tree.model_of(site)
    if root is None:
        raise ChildError(f"{site.path}: the element was removed from its model")
    frame = _tree.frame_of(model)
    if frame is not None:
        raise ChildError(f"model {scope_name(model)!r} is already attached elsewhere, at "
                         f"{frame.path}; detach() it first or attach a copy")
    if _tree.scope_of(root).is_within(_tree.scope_of(model)):
        raise ChildError(f"cannot attach model {scope_name(model)!r} into itself")
    host, pose = _host(site)
    _tree.child_scope(host).check_free(scope_name(model))
    check_compatible(top_model(root), model)
    frame = host.add(grammar_facts().body, **pose)
    _tree.attach_at(frame, model)
    return frame


def detach(model: ModelBase) -> None:
    """Undo ``attach``: remove the attachment frame (with anything added to it)."""
    frame = _tree.frame_of(model)
    if frame is None:
        raise ChildError(f"model {_tree.scope_of(model).name!r} is not attached")
    _tree.detach_model(model)
    _tree.remove_subtree(frame)


# ----------------------------------------------------------------------------- global sections


def _effective(section: Element | None, child: Element, name: str) -> object:
    """The value ``section`` has for ``name`` (its grammar default when unset or absent)."""
    attribute = child.spec.by_name[name]
    value = None if section is None else _tree.read_value(section, attribute)
    if value is None:
        return None if attribute.default is None else attribute.codec.read(
            attribute.codec.parse(attribute.default))
    return value


def conflicts(parent: Element | None, child: Element, where: str) -> list[str]:
    """Attributes set in ``child``'s section whose value differs from the parent's."""
    found: list[str] = []
    for name in _tree.values(child):
        if name in folder_attributes():
            continue  # folders resolve the attached model's own files
        mine, theirs = _effective(parent, child, name), _effective(child, child, name)
        if not same_value(mine, theirs):
            found.append(f"<{where}> {name}: {theirs!r} in the attached model, "
                         f"{mine!r} in the model it is attached to")
    for grandchild in _tree.children(child):
        if child.spec.children[grandchild.spec.tag].single:
            existing = None if parent is None else _tree.single_child(parent, grandchild.spec.tag)
            found += conflicts(existing, grandchild, f"{where}/{grandchild.spec.tag}")
    return found


def check_compatible(parent: ModelBase, model: ModelBase) -> None:
    """Refuse to attach a model whose global settings contradict the parent's."""
    problems: list[str] = []
    for section in _tree.children(model):
        if section.spec.compose != "attributes":
            continue
        mine = _tree.single_child(parent, section.spec.tag)
        problems += conflicts(mine, section, section.spec.tag)
    if problems:
        raise InvalidValueError(
            f"cannot attach model {scope_name(model)!r}: its global settings "
            "differ from the model it is attached to:\n  " + "\n  ".join(problems))
