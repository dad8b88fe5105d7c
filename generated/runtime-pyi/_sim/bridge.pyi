# Generated from src/typed_mjcf/_sim/bridge.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The MuJoCo bridge: compiling, and converting to and from ``mujoco.MjSpec``.

``mujoco`` is imported when first needed: it is the heaviest import of the library, and
building, reading and writing models do not need it. When MuJoCo refuses a model, the error
keeps MuJoCo's message and names the element it is about (:mod:`typed_mjcf._sim.locate`).
"""
from __future__ import annotations
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
import mujoco

def compile_model(model: ModelBase,
                  limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjModel:
    """Validate, check what MuJoCo would allocate against ``limits``, then compile with
    MuJoCo (files passed through a virtual file system)."""
    ...

def to_spec(model: ModelBase,
            limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjSpec:
    """The model as a ``mujoco.MjSpec``, checked against ``limits`` first (``MjSpec`` reads
    replicates and flexcomps out as it parses, and is made to be compiled)."""
    ...

def spec_to_xml(spec: mujoco.MjSpec) -> str:
    """The MJCF text MuJoCo writes for a spec (compiling it first, as ``to_xml`` requires)."""
    ...
