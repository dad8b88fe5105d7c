"""Whole-model keyframes for composed models.

Each part of a composed model (the model and those attached to it) may define keyframes
for its own joints, actuators and mocap bodies. Keys with the same name combine into one key
of the whole model: each part's values go to the addresses its joints (actuators, mocap
bodies) have in the composed model, and what no part gives keeps MuJoCo's default (``qpos0``,
zero velocities and controls). The layout comes from compiling the composed model once
without keyframes.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from typed_mjcf._xmltext import Node, serialize
from typed_mjcf.errors import ExportError

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._element import Element
    from typed_mjcf._export import Writer
    from typed_mjcf._root import ModelRoot

Vector = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
# MuJoCo's joint types: free, ball, slide, hinge (mjtJoint); their qpos and dof sizes.
QPOS_SIZE = (7, 4, 1, 1)
DOF_SIZE = (6, 3, 1, 1)


def _layout(root: ModelRoot) -> mujoco.MjModel:
    import mujoco

    from typed_mjcf._assets_io import collect_assets
    from typed_mjcf._export import Formatter, Writer

    collected = collect_assets(root)
    formatter = Formatter(file_namer=collected.name_of,
                          skip_attributes=collected.directory_attributes)
    writer = Writer(formatter, root, keyframes=False)
    xml = serialize(writer.model(root), pretty_print=False)
    try:
        return mujoco.MjModel.from_xml_string(xml, collected.files)
    except ValueError as error:
        raise ExportError(f"combining the keyframes of the attached models needs the composed "
                          f"model to compile, and MuJoCo refused it: {error}") from None


def _key_name(key: Element, index: int) -> str:
    name = key._attrs.get("name")  # pyright: ignore[reportPrivateUsage]
    return name if isinstance(name, str) else f"#{index}"


class _Key:
    def __init__(self, m: mujoco.MjModel) -> None:
        self.m = m
        self.values: dict[str, Vector] = {}
        self.time: float | None = None

    def vector(self, name: str) -> Vector:
        if name not in self.values:
            m = self.m
            defaults: dict[str, Callable[[], Vector]] = {
                "qpos": lambda: np.array(m.qpos0, dtype=np.float64),
                "qvel": lambda: np.zeros(m.nv),
                "act": lambda: np.zeros(m.na),
                "ctrl": lambda: np.zeros(m.nu),
                "mpos": lambda: np.array(m.body_pos[m.body_mocapid >= 0], dtype=np.float64).ravel(),
                "mquat": lambda: np.array(m.body_quat[m.body_mocapid >= 0], dtype=np.float64).ravel(),
            }
            self.values[name] = defaults[name]()
        return self.values[name]


def _slots(m: mujoco.MjModel, owners: list[ModelRoot], part: ModelRoot,
           kind: str) -> list[tuple[int, int]]:
    """(address, size) in the composed vector ``kind`` of each of ``part``'s entries."""
    mine = [i for i, owner in enumerate(owners) if owner is part]
    if kind == "qpos":
        return [(int(m.jnt_qposadr[j]), QPOS_SIZE[int(m.jnt_type[j])]) for j in mine]
    if kind == "qvel":
        return [(int(m.jnt_dofadr[j]), DOF_SIZE[int(m.jnt_type[j])]) for j in mine]
    if kind == "ctrl":
        return [(a, 1) for a in mine]
    if kind == "act":
        return [(int(m.actuator_actadr[a]), int(m.actuator_actnum[a])) for a in mine
                if m.actuator_actnum[a] > 0]
    size = 3 if kind == "mpos" else 4
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


def combine_keyframes(writer: Writer, node: Node, root: ModelRoot,
                      parts: list[tuple[ModelRoot, Element]]) -> None:
    """Replace the keyframe section of ``node`` with whole-model keys."""
    m = _layout(root)
    owners = {"qpos": writer.joint_owners, "qvel": writer.joint_owners,
              "ctrl": writer.actuator_owners, "act": writer.actuator_owners,
              "mpos": writer.mocap_owners, "mquat": writer.mocap_owners}
    if len(writer.joint_owners) != m.njnt or len(writer.actuator_owners) != m.nu:
        raise ExportError("cannot combine the keyframes of attached models whose joints or "
                          "actuators MuJoCo expands (e.g. inside <replicate>)")
    keys: dict[str, _Key] = {}
    tag = parts[0][1].tag
    for part, section in parts:
        for index, key in enumerate(section._children):  # pyright: ignore[reportPrivateUsage]
            combined = keys.setdefault(_key_name(key, index), _Key(m))
            for kind, value in key._attrs.items():  # pyright: ignore[reportPrivateUsage]
                if kind == "time":
                    assert isinstance(value, float)
                    if combined.time is not None and combined.time != value:
                        raise ExportError(f"{key.path}: time {value} differs from {combined.time} "
                                          f"in a keyframe of the same name")
                    combined.time = value
                elif kind in owners:
                    assert isinstance(value, np.ndarray)
                    _place(combined, kind, _slots(m, owners[kind], part, kind),
                           np.asarray(value, dtype=np.float64), key.path)
    for old in [child for child in node if child.tag == tag]:
        node.remove(old)
    section_node = writer.section_node(node, tag)
    number = writer.formatter.number
    key_tag = next(iter(parts[0][1].spec.children))
    for name, combined in keys.items():
        attrib: dict[str, str] = {} if name.startswith("#") else {"name": name}
        if combined.time is not None:
            attrib["time"] = number(combined.time)
        for kind, vector in combined.values.items():
            attrib[kind] = " ".join(number(float(x)) for x in vector)
        section_node.sub(key_tag, attrib)
