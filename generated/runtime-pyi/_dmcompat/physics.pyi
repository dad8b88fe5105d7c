# Generated from src/typed_mjcf/_dmcompat/physics.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.physics``: the names of typed-mjcf's ``typed_mjcf.physics`` (``Physics``,
``Binding``, ...), loaded when first used (it imports ``mujoco``)."""
from __future__ import annotations

def __getattr__(name: str) -> object: ...
