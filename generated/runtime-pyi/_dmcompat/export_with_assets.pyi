# Generated from src/typed_mjcf/_dmcompat/export_with_assets.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.export_with_assets``."""
from __future__ import annotations
from typed_mjcf.io import export_with_assets
__all__ = ["export_with_assets"]
