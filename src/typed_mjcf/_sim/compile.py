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
from typing import TYPE_CHECKING

from typed_mjcf._releases.facts import clears_asset_cache

if TYPE_CHECKING:
    import mujoco


def spec_from_memory(text: str, files: Mapping[str, bytes]) -> mujoco.MjSpec:
    """A spec of ``text`` whose files (MJCF files it includes among them) are in memory."""
    import mujoco

    includes = {name: data for name, data in files.items() if name.lower().endswith(".xml")}
    return mujoco.MjSpec.from_string(text, include=includes, assets=dict(files))


def _flat(files: Mapping[str, bytes]) -> bool:
    """Whether MuJoCo's dict route holds ``files``: no two of one base name (case aside)."""
    bases = {name.replace("\\", "/").rsplit("/", 1)[-1].casefold() for name in files}
    return len(bases) == len(files)


def compile_from_memory(text: str, files: Mapping[str, bytes],
                        edit: Callable[[mujoco.MjSpec], None] | None = None) -> mujoco.MjModel:
    """``text`` compiled with ``files`` (``edit``: what to change in the spec first).

    Raises MuJoCo's ``ValueError`` (and the ``RuntimeError`` of a C++ exception it did not
    expect) as MuJoCo gives it.
    """
    import mujoco

    if clears_asset_cache():  # else a file of an earlier model with the same name is used
        mujoco.mj_clearCache(mujoco.mj_getCache())
    if edit is None and _flat(files):
        # the dict finds a file by its base name, whatever folder the text names (MjSpec's
        # assets need the path MuJoCo makes of the text's before 3.17.0)
        return mujoco.MjModel.from_xml_string(text, dict(files))
    spec = spec_from_memory(text, files)
    if edit is not None:
        edit(spec)
    return spec.compile()
