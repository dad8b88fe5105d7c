"""``dm_control.mjcf.export_with_assets``."""

from __future__ import annotations

from typed_mjcf.io import export_with_assets

__all__ = ["export_with_assets"]
