"""The MuJoCo bridge: compiling, and converting to and from ``mujoco.MjSpec``."""

from __future__ import annotations

import re

import mujoco
from lxml import etree

from typed_mjcf._assets_io import collect_assets, xml_with_assets
from typed_mjcf._export import iter_written
from typed_mjcf._parse import source_line
from typed_mjcf._root import ModelRoot
from typed_mjcf.errors import CompileError

# MuJoCo ends its messages with the element's line: "Element 'include', line 7" (XML
# errors) or "Element name 'arm', id 1, line 22" / "Element id 3, line 9" (compile errors).
_ELEMENT_LINE = re.compile(r"^Element\b.*\bline (\d+)", re.MULTILINE)


def _mujoco_error(model: ModelRoot, error: Exception, xml: str) -> CompileError:
    """MuJoCo's message, with the path of the element it names where it can be found."""
    message = str(error).strip()
    match = _ELEMENT_LINE.search(message)
    if match:
        path = _path_at_line(model, xml, int(match.group(1)))
        if path:
            message += f"\n(the element is {path})"
    return CompileError(f"MuJoCo could not compile the model: {message}")


def _path_at_line(model: ModelRoot, xml: str, line: int) -> str | None:
    """The path of the element whose start tag is on ``line`` of ``xml``, the model's export.

    The export is read back to find each element's line, and its elements are paired in
    document order with the ones the writer wrote (empty once-only sections are left out).
    """
    try:
        nodes = etree.fromstring(xml.encode("utf-8")).iter()
    except etree.XMLSyntaxError:
        return None
    for node, element in zip(nodes, iter_written(model), strict=False):
        if source_line(node) == line:
            return element.path
    return None


def vfs_xml(model: ModelRoot) -> tuple[str, dict[str, bytes]]:
    """The model's XML for compiling from memory, and the files it uses."""
    collected = collect_assets(model)
    return xml_with_assets(model, collected), collected.files


def compile_model(model: ModelRoot) -> mujoco.MjModel:
    xml, files = vfs_xml(model)
    try:
        return mujoco.MjModel.from_xml_string(xml, files)
    except ValueError as error:
        raise _mujoco_error(model, error, xml) from None


def to_spec(model: ModelRoot) -> mujoco.MjSpec:
    xml, files = vfs_xml(model)
    try:
        spec = mujoco.MjSpec.from_string(xml, assets=files)
    except ValueError as error:
        raise _mujoco_error(model, error, xml) from None
    return spec


def spec_to_xml(spec: mujoco.MjSpec) -> tuple[str, dict[str, bytes]]:
    """The MJCF text MuJoCo writes for a spec (compiling it first, as ``to_xml`` requires)."""
    spec.compile()
    return spec.to_xml(), {}
