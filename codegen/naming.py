"""Python names for MJCF declarations and attributes."""

from __future__ import annotations

import keyword

# Runtime base API names: an attribute or child tag with one of these names would shadow it.
RESERVED = frozenset({
    "add", "insert", "remove", "parent", "root", "tag", "get_children", "find", "find_all",
    "get_attributes", "set_attributes", "to_xml", "to_xml_string", "compile", "to_spec",
    "get_assets", "validate", "path", "spec", "namescope", "full_identifier", "paste",
    "resolve", "attach_model", "detach", "iter_elements", "attached_model",
})


def py_name(xml_name: str) -> str:
    """The Python identifier of an MJCF attribute or child tag (``class`` -> ``class_``)."""
    name = xml_name.replace("-", "_")
    if keyword.iskeyword(name) or keyword.issoftkeyword(name):
        name += "_"
    if not name.isidentifier():
        raise ValueError(f"cannot name {xml_name!r} in Python")
    return name


def class_name(declaration: str, root: str = "mujoco") -> str:
    """The Python class of a grammar row: ``equality_joint`` -> ``EqualityJoint``."""
    if declaration == root:
        return "RootElement"
    return "".join(part[:1].upper() + part[1:] for part in declaration.split("_") if part)
