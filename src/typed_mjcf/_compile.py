"""The one compile from memory: MJCF text and its files into a ``mujoco.MjModel``.

Every route that compiles text typed-mjcf wrote (``compile()``, ``Physics``, the keyframe
layout, pictures, the ids of unnamed elements) goes through :func:`compile_from_memory`, so
each release fact about compiling is applied once, here. The files go to ``MjSpec.assets``,
keyed by the path the text names: unlike ``MjModel.from_xml_string(xml, assets)``, which
refuses two keys with one base name, it keeps ``torso/base_link.stl`` and
``gripper/base_link.stl`` apart (measured with MuJoCo 3.17.0 and 4.0.0).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

from typed_mjcf._release_facts import clears_asset_cache

if TYPE_CHECKING:
    import mujoco


def spec_from_memory(text: str, files: Mapping[str, bytes]) -> mujoco.MjSpec:
    """A spec of ``text`` whose files (MJCF files it includes among them) are in memory."""
    import mujoco

    includes = {name: data for name, data in files.items() if name.lower().endswith(".xml")}
    return mujoco.MjSpec.from_string(text, include=includes, assets=dict(files))


def compile_from_memory(text: str, files: Mapping[str, bytes],
                        edit: Callable[[mujoco.MjSpec], None] | None = None) -> mujoco.MjModel:
    """``text`` compiled with ``files`` (``edit``: what to change in the spec first).

    Raises MuJoCo's ``ValueError`` (and the ``RuntimeError`` of a C++ exception it did not
    expect) as MuJoCo gives it.
    """
    import mujoco

    if clears_asset_cache():  # else a file of an earlier model with the same name is used
        mujoco.mj_clearCache(mujoco.mj_getCache())
    spec = spec_from_memory(text, files)
    if edit is not None:
        edit(spec)
    return spec.compile()
