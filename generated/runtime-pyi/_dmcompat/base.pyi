# Generated from src/typed_mjcf/_dmcompat/base.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.base``: the abstract ``Element`` is typed-mjcf's ``Element``."""
from __future__ import annotations
from typed_mjcf._base import Element
__all__ = ["Element"]
