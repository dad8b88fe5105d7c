# Generated from src/typed_mjcf/_dmcompat/namescope.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.namescope``."""
from __future__ import annotations
from typed_mjcf._core.names import NameScope
__all__ = ["NameScope"]
