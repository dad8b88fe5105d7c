# Generated from src/typed_mjcf/_dmcompat/attribute.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.attribute``: ``Asset`` (an in-memory file). dm_control's attribute
classes (``String``, ``Array``...) are its internals; typed-mjcf's codecs take their
place and are not served here."""
from __future__ import annotations
from typed_mjcf.assets import Asset
__all__ = ["Asset"]
