# Generated from src/typed_mjcf/_model/keyframes.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Whole-model keyframes for composed models.

Each part of a composed model (the model and those attached to it) may define keyframes
for its own joints, actuators and mocap bodies. Keys with the same name combine into one key
of the whole model: each part's values go to the addresses its joints (actuators, mocap
bodies) have in the composed model, and what no part gives keeps MuJoCo's default (``qpos0``,
zero velocities and controls). The layout comes from compiling the composed model once
without keyframes, before it is written (:mod:`typed_mjcf._sim.text`).
"""
from __future__ import annotations
import numpy as np
from typed_mjcf._core.errors import ExportError
from typed_mjcf._text.export import Writer
from typed_mjcf._text.xmltext import Node
import mujoco
Vector = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
QPOS_SIZE = (7, 4, 1, 1)
DOF_SIZE = (6, 3, 1, 1)

def has_keyframes(writer: Writer) -> bool:
    """Whether any part of the model the writer wrote has a keyframe to combine."""
    ...

class LayoutError(ExportError):
    """MuJoCo refused the composed model without its keyframes; ``mujoco_message`` is what
    it said (about the text given to it: the model's text less its keyframes)."""
    def __init__(self, mujoco_message: str) -> None:
        super().__init__(f"combining the keyframes of the attached models needs the composed "
                         f"model to compile, and MuJoCo refused it: {mujoco_message}")
        self.mujoco_message = mujoco_message

class _Key:
    def __init__(self, m: mujoco.MjModel) -> None:
        self.m = m
        self.values: dict[str, Vector] = {}
        self.time: float | None = None
    def vector(self, kind: str) -> Vector: ...

def combine_keyframes(writer: Writer, node: Node, m: mujoco.MjModel) -> None:
    """Add the whole-model keys to ``node``, the root the writer wrote (without keys)."""
    ...
