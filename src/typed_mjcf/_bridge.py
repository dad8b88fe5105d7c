"""The MuJoCo bridge: compiling, and converting to and from ``mujoco.MjSpec``.

``mujoco`` is imported when first needed: it is the heaviest import of the library, and
building, reading and writing models do not need it.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from lxml import etree

from typed_mjcf._export import iter_written
from typed_mjcf._parse import source_line
from typed_mjcf._tree import ModelBase
from typed_mjcf._validate import ensure_valid
from typed_mjcf._write import vfs_text
from typed_mjcf.errors import CompileError

if TYPE_CHECKING:
    import mujoco

# MuJoCo ends its messages with the element's line: "Element 'include', line 7" (XML
# errors) or "Element name 'arm', id 1, line 22" / "Element id 3, line 9" (compile errors).
_ELEMENT_LINE = re.compile(r"^Element\b.*\bline (\d+)", re.MULTILINE)


def _mujoco_error(model: ModelBase, error: Exception, xml: str) -> CompileError:
    """MuJoCo's message, with the path of the element it names where it can be found."""
    message = str(error).strip()
    match = _ELEMENT_LINE.search(message)
    if match:
        path = _path_at_line(model, xml, int(match.group(1)))
        if path:
            message += f"\n(the element is {path})"
    return CompileError(f"MuJoCo could not compile the model: {message}")


def _path_at_line(model: ModelBase, xml: str, line: int) -> str | None:
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


def compile_model(model: ModelBase) -> mujoco.MjModel:
    """Validate, then compile with MuJoCo (files passed through a virtual file system)."""
    import mujoco

    ensure_valid(model)
    xml, collected = vfs_text(model)
    try:
        return mujoco.MjModel.from_xml_string(xml, collected.files)
    except ValueError as error:
        raise _mujoco_error(model, error, xml) from None


def to_spec(model: ModelBase) -> mujoco.MjSpec:
    """The model as a ``mujoco.MjSpec``."""
    import mujoco

    xml, collected = vfs_text(model)
    try:
        return mujoco.MjSpec.from_string(xml, assets=collected.files)
    except ValueError as error:
        raise _mujoco_error(model, error, xml) from None


def spec_to_xml(spec: mujoco.MjSpec) -> str:
    """The MJCF text MuJoCo writes for a spec (compiling it first, as ``to_xml`` requires)."""
    spec.compile()
    return spec.to_xml()
