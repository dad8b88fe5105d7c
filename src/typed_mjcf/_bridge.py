"""The MuJoCo bridge: compiling, and converting to and from ``mujoco.MjSpec``."""

from __future__ import annotations

import re

import mujoco

from typed_mjcf._assets_io import collect_assets, xml_with_assets
from typed_mjcf._root import ModelRoot
from typed_mjcf.errors import CompileError

_ELEMENT_LINE = re.compile(r"Element '(\w+)', line (\d+)")


def _mujoco_error(model: ModelRoot, error: Exception, xml: str) -> CompileError:
    """MuJoCo's message, with the path of the element it names where it can be found."""
    message = str(error).strip()
    match = _ELEMENT_LINE.search(message)
    if match:
        line = int(match.group(2))
        path = _path_at_line(model, xml, line)
        if path:
            message += f"\n(the element is {path})"
    return CompileError(f"MuJoCo could not compile the model: {message}")


def _path_at_line(model: ModelRoot, xml: str, line: int) -> str | None:
    """The element written on ``line`` of ``xml`` (the export is one element per line)."""
    elements = list(model.iter_elements())
    # Pretty-printed export writes each element's start tag on its own line, in document order;
    # skipped empty sections never precede a line MuJoCo reports, so count start tags.
    start_lines = [i + 1 for i, text in enumerate(xml.splitlines())
                   if text.lstrip().startswith("<") and not text.lstrip().startswith("</")]
    if line in start_lines:
        index = start_lines.index(line)
        if index < len(elements):
            return elements[index].path
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
