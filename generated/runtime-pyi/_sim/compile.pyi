# Generated from src/typed_mjcf/_sim/compile.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The one compile from memory: MJCF text and its files into a ``mujoco.MjModel``.

Every route that compiles text typed-mjcf wrote (``compile()``, ``Physics``, the keyframe
layout, pictures, the ids of unnamed elements) goes through :func:`compile_from_memory`, so
each release fact about compiling is applied once, here. The files go to ``MjSpec.assets``,
keyed by the path the text names, where two share a base name: unlike
``MjModel.from_xml_string(xml, assets)``, which refuses two keys with one base name, it keeps
``assets/torso/base_link.stl`` and ``assets/gripper/base_link.stl`` apart (measured with
MuJoCo 3.3.7, 3.17.0 and 4.0.0). Other files go through the dict, which finds a file by its
base name whatever folder the text names (MuJoCo 3.3.7's ``MjSpec`` needs the exact path).
"""
from __future__ import annotations
from collections.abc import Callable, Mapping
import mujoco

def spec_from_memory(text: str, files: Mapping[str, bytes]) -> mujoco.MjSpec:
    """A spec of ``text`` whose files (MJCF files it includes among them) are in memory."""
    ...

def compile_from_memory(text: str, files: Mapping[str, bytes],
                        edit: Callable[[mujoco.MjSpec], None] | None = None) -> mujoco.MjModel:
    """``text`` compiled with ``files`` (``edit``: what to change in the spec first).

    Raises MuJoCo's ``ValueError`` (and the ``RuntimeError`` of a C++ exception it did not
    expect) as MuJoCo gives it.
    """
    ...
