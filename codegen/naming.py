"""Python names for MJCF declarations and attributes."""

from __future__ import annotations

import keyword

# The runtime's public names (typed_mjcf.Element, ModelRoot and Attachable; a test keeps this
# equal to them): a child tag with one of these names takes a trailing underscore (the list
# of <attach> children is ``body.attach_``), and an attribute may not have one.
RESERVED = frozenset({
    "add", "all_children", "attach", "attach_model", "attached_model", "attachment_frame",
    "base_dir", "commit_defaults", "compile", "detach", "enter_model", "enter_scope", "find", "find_all",
    "full_identifier", "get_assets", "get_attachment_frame", "get_attribute_xml_string",
    "get_attributes", "get_children", "get_frame_freejoint", "get_frame_joints",
    "get_freejoint", "get_init_stack", "get_last_modified_stacks_for_all_attributes",
    "include_copy", "insert", "is_removed", "is_same_as", "iter_elements", "iter_exported",
    "namescope", "namespaces", "parent", "parent_model", "paste", "path", "prefixed_identifier",
    "remove", "render", "render_png", "resolve",
    "resolve_references", "root", "root_model", "set_attributes", "spec", "tag", "to_spec",
    "to_xml", "to_xml_string", "validate",
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
