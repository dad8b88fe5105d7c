"""dm_control's Reference attribute (mjcf/attribute.py), as a user sees it: a name given
reads back as that name, links only on resolve_references() (a parse ends with one), and
stays that name when an element of it is renamed, removed or added later; an element given
reads back as the element, renamed or not, and as None once removed. ``test_compat.py`` runs
it on typed-mjcf (switch on and off) and, in a subprocess, on dm_control's own mjcf."""

from __future__ import annotations

from types import ModuleType


def references(mjcf: ModuleType) -> list[object]:
    """What each step reads back."""
    model = mjcf.RootElement()
    b = model.worldbody.add("body", name="b")
    exclude = model.contact.add("exclude", body1="b", body2="c")
    c = model.worldbody.add("body", name="c")
    seen = [exclude.body1, exclude.body2]
    exclude.body1 = b
    seen.append(exclude.body1 is b)
    b.name = "b2"
    seen += [exclude.body1 is b, exclude.get_attribute_xml_string("body1")]
    c.name = "c2"
    seen += [exclude.body2, exclude.get_attribute_xml_string("body2")]
    model.resolve_references()
    seen.append(exclude.body2)
    exclude.body2 = "c2"
    seen.append(exclude.body2)
    model.resolve_references()
    seen.append(exclude.body2 is c)
    by_name = model.worldbody.add("camera", target="c2")
    by_element = model.worldbody.add("camera", target=c)
    c.remove()
    seen += [by_name.target, by_element.target]
    parsed = mjcf.from_xml_string(
        '<mujoco><worldbody><body name="x"/></worldbody><contact><exclude body1="x" '
        'body2="y"/></contact><worldbody><body name="y"/></worldbody></mujoco>')
    exclude = parsed.contact.exclude[0]
    seen.append([exclude.body1 is parsed.worldbody.body[0],
                 exclude.body2 is parsed.worldbody.body[1]])
    return seen


# What dm_control.mjcf 1.0.50 reads back (the subprocess test checks it still does).
DM_CONTROL = ["b", "c", True, True, "b2", "c", "c", "c", "c2", True, "c2", None, [True, True]]
