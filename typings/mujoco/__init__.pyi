# Minimal type stubs for the part of `mujoco` that typed-mjcf's typed code uses.
# mujoco ships no type information; these are ours, and cover only what we call.
from collections.abc import Mapping
from typing import TypeAlias

import numpy as np

_F64: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.float64]]
_I32: TypeAlias = np.ndarray[tuple[int, ...], np.dtype[np.int32]]

__version__: str

class _NamedView:
    @property
    def data(self) -> _F64: ...
    @property
    def id(self) -> int: ...

class MjModel:
    @staticmethod
    def from_xml_string(xml: str, assets: Mapping[str, bytes] | None = ...) -> MjModel: ...
    @staticmethod
    def from_xml_path(filename: str, assets: Mapping[str, bytes] | None = ...) -> MjModel: ...
    nq: int
    nv: int
    nu: int
    na: int
    nbody: int
    njnt: int
    ngeom: int
    nsite: int
    nsensor: int
    nkey: int
    ntendon: int
    neq: int
    nmesh: int
    nmocap: int
    qpos0: _F64
    jnt_type: _I32
    jnt_qposadr: _I32
    jnt_dofadr: _I32
    actuator_actadr: _I32
    actuator_actnum: _I32
    body_mocapid: _I32
    body_pos: _F64
    body_quat: _F64
    key_qpos: _F64
    key_ctrl: _F64
    def body(self, name: str | int) -> _NamedView: ...
    def joint(self, name: str | int) -> _NamedView: ...
    def geom(self, name: str | int) -> _NamedView: ...

class MjData:
    def __init__(self, model: MjModel) -> None: ...
    time: float
    qpos: _F64
    qvel: _F64
    ctrl: _F64
    sensordata: _F64
    def sensor(self, name: str | int) -> _NamedView: ...
    def body(self, name: str | int) -> _NamedView: ...

class MjSpec:
    def __init__(self) -> None: ...
    @staticmethod
    def from_string(xml: str, include: Mapping[str, bytes] | None = ...,
                    assets: Mapping[str, bytes] | None = ...) -> MjSpec: ...
    @staticmethod
    def from_file(filename: str, include: Mapping[str, bytes] | None = ...,
                  assets: Mapping[str, bytes] | None = ...) -> MjSpec: ...
    def compile(self) -> MjModel: ...
    def to_xml(self) -> str: ...
    @property
    def assets(self) -> dict[str, bytes]: ...

def mj_step(m: MjModel, d: MjData, nstep: int = ...) -> None: ...
def mj_forward(m: MjModel, d: MjData) -> None: ...
def mj_resetDataKeyframe(m: MjModel, d: MjData, key: int) -> None: ...
