"""Whole-model keyframes for composed models.

Each part of a composed model (the model and those attached to it) may define keyframes
for its own joints, actuators and mocap bodies. Keys with the same name combine into one key
of the whole model: each part's values go to the addresses its joints (actuators, mocap
bodies) have in the composed model, and what no part gives keeps MuJoCo's default (``qpos0``,
zero velocities and controls). The layout comes from compiling the composed model once
without keyframes, before it is written (:mod:`typed_mjcf._sim.text`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import ExportError
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.export import Writer
from typed_mjcf._text.xmltext import Node

if TYPE_CHECKING:
    import mujoco

Vector = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
# MuJoCo's joint types: free, ball, slide, hinge (mjtJoint); their qpos and dof sizes.
QPOS_SIZE = (7, 4, 1, 1)
DOF_SIZE = (6, 3, 1, 1)


def has_keyframes(writer: Writer) -> bool:
    """Whether any part of the model the writer wrote has a keyframe to combine."""
    return any(_tree.children(section) for _, section in writer.keyframe_sections)


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

    def vector(self, kind: str) -> Vector:
        if kind not in self.values:
            m = self.m
            keys = grammar_facts().keyframe
            defaults: dict[str, Callable[[], Vector]] = {
                keys.qpos: lambda: np.array(m.qpos0, dtype=np.float64),
                keys.qvel: lambda: np.zeros(m.nv),
                keys.act: lambda: np.zeros(m.na),
                keys.ctrl: lambda: np.zeros(m.nu),
                keys.mpos: lambda: np.array(m.body_pos[m.body_mocapid >= 0],
                                            dtype=np.float64).ravel(),
                keys.mquat: lambda: np.array(m.body_quat[m.body_mocapid >= 0],
                                             dtype=np.float64).ravel(),
            }
            self.values[kind] = defaults[kind]()
        return self.values[kind]


def _slots(m: mujoco.MjModel, owners: list[ModelBase], part: ModelBase,
           kind: str) -> list[tuple[int, int]]:
    """(address, size) in the composed vector ``kind`` of each of ``part``'s entries."""
    keys = grammar_facts().keyframe
    mine = [i for i, owner in enumerate(owners) if owner is part]
    if kind == keys.qpos:
        return [(int(m.jnt_qposadr[j]), QPOS_SIZE[int(m.jnt_type[j])]) for j in mine]
    if kind == keys.qvel:
        return [(int(m.jnt_dofadr[j]), DOF_SIZE[int(m.jnt_type[j])]) for j in mine]
    if kind == keys.ctrl:  # an actuator may take several controls (pid, orientation)
        return [(int(m.actuator_ctrladr[a]), int(m.actuator_ctrlnum[a])) for a in mine]
    if kind == keys.act:
        return [(int(m.actuator_actadr[a]), int(m.actuator_actnum[a])) for a in mine
                if m.actuator_actnum[a] > 0]
    size = 3 if kind == keys.mpos else 4
    mocap_bodies = [int(b) for b in np.flatnonzero(m.body_mocapid >= 0)]
    order = sorted(mocap_bodies, key=lambda b: int(m.body_mocapid[b]))
    return [(int(m.body_mocapid[order[i]]) * size, size) for i in mine]


def _place(key: _Key, kind: str, slots: list[tuple[int, int]], values: Vector,
           where: str) -> None:
    expected = sum(size for _, size in slots)
    if len(values) != expected:
        raise ExportError(f"{where}: {kind} has {len(values)} values, but the model's part "
                          f"has {expected}")
    vector = key.vector(kind)
    offset = 0
    for address, size in slots:
        vector[address:address + size] = values[offset:offset + size]
        offset += size


def combine_keyframes(writer: Writer, node: Node, m: mujoco.MjModel) -> None:
    """Add the whole-model keys to ``node``, the root the writer wrote (without keys)."""
    keys_facts = grammar_facts().keyframe
    # MuJoCo numbers joints body by body, bodies in document order (a stable sort)
    order = sorted(range(len(writer.joint_owners)), key=writer.joint_bodies.__getitem__)
    joint_owners = [writer.joint_owners[i] for i in order]
    owners = {keys_facts.qpos: joint_owners, keys_facts.qvel: joint_owners,
              keys_facts.ctrl: writer.actuator_owners, keys_facts.act: writer.actuator_owners,
              keys_facts.mpos: writer.mocap_owners, keys_facts.mquat: writer.mocap_owners}
    if len(writer.joint_owners) != m.njnt or len(writer.actuator_owners) != m.nactuator:
        raise ExportError(f"cannot combine the keyframes of attached models: MuJoCo makes "
                          f"{m.njnt} joints and {m.nactuator} actuators of the text, which "
                          f"has {len(writer.joint_owners)} and {len(writer.actuator_owners)} "
                          f"(joints or actuators MuJoCo adds itself, e.g. inside "
                          f"<replicate>, a <flexcomp> or an <attach> element)")
    keys: dict[str, _Key] = {}
    sections = writer.keyframe_sections
    for part, section in sections:
        for index, key in enumerate(_tree.children(section)):
            name = _tree.element_name(key)
            combined = keys.setdefault(f"#{index}" if name is None else name, _Key(m))
            _combine(key, part, combined, owners, m)
    section_node = writer.section_node(node, sections[0][1].spec.tag)
    key_tag = next(iter(sections[0][1].spec.children))
    key_attributes = sections[0][1].spec.children[key_tag].cls.spec.by_name
    fmt = writer.fmt

    def text(attribute: str, value: object) -> str:  # as every value: by its codec
        return key_attributes[attribute].codec.write(value, fmt)

    for name, combined in keys.items():
        attrib: dict[str, str] = {} if name.startswith("#") else {"name": name}
        if combined.time is not None:
            attrib[keys_facts.time] = text(keys_facts.time, combined.time)
        for kind, vector in combined.values.items():
            attrib[kind] = text(kind, vector)
        section_node.sub(key_tag, attrib)


def _combine(key: Element, part: ModelBase, combined: _Key,
             owners: dict[str, list[ModelBase]], m: mujoco.MjModel) -> None:
    time_name = grammar_facts().keyframe.time
    for name, attribute in key.spec.by_name.items():
        value = _tree.read_value(key, attribute)
        if value is None:
            continue
        if name == time_name:
            assert isinstance(value, float)
            if combined.time is not None and combined.time != value:
                raise ExportError(f"{key.path}: time {value} differs from {combined.time} "
                                  f"in a keyframe of the same name")
            combined.time = value
        elif name in owners:
            assert isinstance(value, np.ndarray)
            _place(combined, name, _slots(m, owners[name], part, name),
                   np.asarray(value, dtype=np.float64), key.path)
        elif attribute is not key.spec.id_attribute:  # a state vector not combined here
            raise ExportError(f"{key.path}: cannot combine {name} with the keyframes of the "
                              f"models attached to it (only "
                              f"{', '.join(sorted(owners))} and {time_name} combine); "
                              f"remove it from the key")
