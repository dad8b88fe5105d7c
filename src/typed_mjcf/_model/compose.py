"""Composition: attaching models to each other, dm_control style.

An attached model stays a model of its own (its elements, names and defaults are untouched);
the parent holds it through an *attachment frame*, a ``<body>`` placed where it was attached.
At export the attached model is written inline under its scope: every identifier and
reference is prefixed ``<model name>/``, its default classes nest in a class named after the
scope, and its sections join the parent's (see ``ElementSpec.compose``).
"""

from __future__ import annotations

from collections.abc import Mapping

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import (
    ChildError,
    IllegalChildError,
    InvalidReferenceError,
    InvalidValueError,
)
from typed_mjcf._core.names import UNNAMED_MODEL
from typed_mjcf._core.tree import Element, ModelBase, equal_read_values, grammar_facts
from typed_mjcf._text.export import folder_attributes
from typed_mjcf._text.files import copied_files, rebase_files
from typed_mjcf._text.merge import combine, rule_of


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
        raise InvalidReferenceError(f"{site.path}: attach() expected a mjcf.RootElement (a "
                                    f"model), got {model!r}")
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
        raise ChildError(f"cannot attach model {_tree.scope_of(model).name!r} into itself "
                         f"(a model cannot merge into itself)")
    host, pose = _host(site)
    scope = _tree.child_scope(host)
    name = free_name(scope.attached, _tree.scope_of(model).name)
    scope.check_free(name)
    if name != _tree.scope_of(model).name:
        scope_attribute = model.spec.scope_attribute
        if scope_attribute is not None:
            _tree.assign(model, scope_attribute, name)
    adopt_settings(root, model)
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


def _reconcile(parent: Element | None, child: Element, where: str, model: str,
               plan: list[tuple[list[str], str, object]], problems: list[str],
               route: list[str]) -> None:
    """What adopting ``child``'s settings into ``parent`` takes (``plan``), or why it can't."""
    for name in _tree.values(child):
        if name in folder_attributes():
            continue  # folders resolve the attached model's own files
        attribute = child.spec.by_name[name]
        theirs = _tree.read_value(child, attribute)
        mine = None if parent is None else _tree.read_value(parent, attribute)
        if mine is None:
            plan.append((route, name, theirs))  # the parent leaves it unset: adopt it
        elif not equal_read_values(mine, theirs):
            rule = rule_of(child, name)
            merged = None if rule is None else combine(rule, mine, theirs)
            if merged is None:
                problems.append(f"Conflicting values for attribute `{name}` of <{where}>: "
                                f"{theirs!r} in the attached model {model!r}, {mine!r} in "
                                f"the model it is attached to")
            elif not equal_read_values(merged, mine):
                plan.append((route, name, merged))
    for grandchild in _tree.children(child):
        if child.spec.children[grandchild.spec.tag].single:
            tag = grandchild.spec.tag
            existing = None if parent is None else _tree.single_child(parent, tag)
            _reconcile(existing, grandchild, f"{where}/{tag}", model, plan, problems,
                       [*route, tag])


def adopt_settings(parent: ModelBase, model: ModelBase) -> None:
    """Before ``model`` is attached to ``parent``: the global settings ``parent`` leaves unset
    take ``model``'s values, values both set are combined by their rule (``max`` for
    ``size`` memory, ...) or refused with both values named; nothing changes on refusal."""
    plan: list[tuple[list[str], str, object]] = []
    problems: list[str] = []
    name = scope_name(model)
    for section in _tree.children(model):
        if section.spec.compose == "attributes":
            tag = section.spec.tag
            _reconcile(_tree.single_child(parent, tag), section, tag, name, plan, problems,
                       [tag])
    if problems:
        raise InvalidValueError(f"cannot attach model {name!r}: " + "; ".join(problems))
    for route, attribute, value in plan:
        target: Element = parent
        for tag in route:
            found = _tree.single_child(target, tag)
            target = found if found is not None else _tree.new_child(
                target, target.spec.children[tag])
        _tree.assign(target, target.spec.by_name[attribute], value)


def free_name(scope_names: Mapping[str, object], name: str | None) -> str:
    """A scope name for an attached model: its own, else ``<name>_<n>`` with the first
    number free (dm_control's rule; an unnamed model is ``unnamed_model``)."""
    base = name or UNNAMED_MODEL
    if base not in scope_names:
        return base
    n = 1
    while f"{base}_{n}" in scope_names:
        n += 1
    return f"{base}_{n}"


# ----------------------------------------------------------------------------- views


def attached_children(element: Element) -> list[Element]:
    """What attached models add to ``element``'s children as users see them: an attachment
    frame shows the attached model's bodies (and the rest of its world body); a top-level
    section of a composed model, the same section of every model attached into it (default
    classes excepted: an attached model's classes stay its own)."""
    attached = _tree.attached_at(element)
    if attached is not None:
        return [child for section in _tree.children(attached) if section.spec.holds_bodies
                for child in _tree.children(section)]
    root = _tree.model_of(element)
    if root is None or element.parent is not root or element.spec.compose == "nest":
        return []
    found: list[Element] = []
    for model in _tree.attached_models(root):
        section = _tree.single_child(model, element.spec.tag)
        if section is not None:
            found += _tree.children(section)
            found += attached_children(section)
    return found


# ----------------------------------------------------------------------------- copies


def include_copy(model: ModelBase, other: ModelBase, override_attributes: bool) -> None:
    """Merge a copy of ``other``'s contents into ``model`` (see ``ModelRoot.include_copy``):
    dm_control's copier. Once-only children merge into this model's; an element with a name
    this model has under the same parent merges into it when ``override_attributes``; every
    other element is copied in. Attributes this model sets keep their value, unless
    ``override_attributes``; a global setting both give differently is an error."""
    if other is model:
        raise ChildError("cannot include a copy of a model into itself")
    files = copied_files(other, other, model)  # read (or refused) before anything changes
    _merge_into(model, other, override_attributes,
                (_tree.scope_of(other).name or UNNAMED_MODEL, files, model))


def _merge_into(target: Element, source: Element, override: bool,
                models: tuple[str, dict[tuple[int, str], bytes], ModelBase]) -> None:
    name, files, target_model = models  # the source's name, its files, the target
    stored = _tree.values(target)
    problems: list[str] = []
    for attribute_name in _tree.values(source):
        attribute = source.spec.by_name[attribute_name]
        if attribute.kind == "id" or attribute.scope or attribute_name in folder_attributes():
            continue
        theirs = _tree.read_value(source, attribute)
        mine = _tree.read_value(target, attribute) if attribute_name in stored else None
        if mine is None or override:
            _tree.assign(target, attribute, theirs)
        elif not equal_read_values(mine, theirs):
            problems.append(f"Conflicting values for attribute `{attribute_name}` of "
                            f"<{source.spec.tag}>: {theirs!r} in model {name!r}, {mine!r} here")
    if problems:
        raise InvalidValueError(f"{target.path}: cannot include a copy: " + "; ".join(problems))
    for child in _tree.children(source):
        child_spec = target.spec.children[child.spec.tag]
        existing: Element | None = None
        if child_spec.single:
            existing = _tree.single_child(target, child.spec.tag)
            if existing is None:
                existing = _tree.new_child(target, child_spec)
        elif override and (child_name := _tree.element_name(child)) is not None:
            existing = next((c for c in _tree.children(target) if c.spec.tag == child.spec.tag
                             and _tree.element_name(c) == child_name), None)
        if existing is None:
            rebase_files(_tree.Element.paste(target, child), child, files, target_model)
        else:
            _merge_into(existing, child, override, models)
