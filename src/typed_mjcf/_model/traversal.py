"""dm_control's traversal helpers: committing defaults into elements, and finding the
frame, freejoint and joints of attachments."""

from __future__ import annotations

from collections.abc import Iterable

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._model.defaults import resolve


def commit_defaults(element: Element, attributes: Iterable[str] | None = None) -> None:
    """Write into ``element`` the value its default classes give each of its attributes
    (only ``attributes``, when given) that it does not set itself, and the rest of an array
    it sets shorter than its classes do: afterwards its own values say what MuJoCo uses,
    whatever the classes."""
    spec = element.spec
    if spec.defaults_tag is None:
        return
    names = ([a.py_name for a in spec.attributes.values()] if attributes is None
             else list(attributes))
    for name in names:
        attribute = spec.by_key[name]
        if attribute.kind == "id":
            continue
        own = _tree.read_value(element, attribute)
        value = resolve(element, name, grammar_defaults=False)
        if value is not None and value is not own:  # unset, or an array its classes fill up
            _tree.assign(element, attribute, value)


def get_attachment_frame(model: ModelBase) -> Element | None:
    """Where ``model`` is attached (its frame in the parent model), if it is."""
    return _tree.frame_of(model)


def get_freejoint(element: Element) -> Element | None:
    """The ``<freejoint>`` (or ``<joint type="free">``) directly in ``element``, if any."""
    facts = grammar_facts()
    for child in _tree.children(element):
        if child.spec.tag == facts.freejoint:
            return child
        joint_type = child.spec.by_name.get(facts.joint_type)
        if child.spec.row in facts.joints and joint_type is not None and (
                _tree.read_value(child, joint_type) == facts.free_type):
            return child
    return None


def get_frame_freejoint(model: Element) -> Element | None:
    """The free joint of an attached model's attachment frame (or of a frame), if any.

    As dm_control's, this takes the attached model; a frame itself is taken too."""
    frame = _frame(model)
    return None if frame is None else get_freejoint(frame)


def get_frame_joints(model: Element) -> list[Element]:
    """The joints of an attached model's attachment frame (or of a frame): what makes the
    attached model move. As dm_control's, this takes the attached model; a frame too."""
    frame = _frame(model)
    if frame is None:
        return []
    return [child for child in _tree.children(frame) if child.spec.row in grammar_facts().joints]


def _frame(element: Element) -> Element | None:
    """The attachment frame of a model (``None`` if it is not attached), or ``element``."""
    return _tree.frame_of(element) if isinstance(element, ModelBase) else element
