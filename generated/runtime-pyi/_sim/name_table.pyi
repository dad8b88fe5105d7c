# Generated from src/typed_mjcf/_sim/name_table.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Compiled ids by name for a whole kind of object at once, for a large ``bind``.

One ``mj_name2id`` call costs about as much as the rest of binding an element; reading a
kind's names out of ``MjModel.names`` in one pass is a tenth of that per object. MuJoCo
stores each object's name there followed by a NUL, kind after kind in id order; the table is
made only when the names are laid out so (checked against ``name_<kind>adr``).
"""
from __future__ import annotations
import mujoco

def name_ids(model: mujoco.MjModel, size: str) -> dict[str, int] | None:
    """Name -> compiled id of every named object of the kind counted by ``size``
    (``"njnt"``), the first of a repeated name as ``mj_name2id`` gives; ``None`` where the
    model does not lay the names out as expected (then ask ``mj_name2id``)."""
    ...
