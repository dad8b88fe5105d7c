# Generated from src/typed_mjcf/_dmcompat/export_with_assets.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.export_with_assets``: the XML named after the model, as dm_control names
it (the typed API's names it after the file the model was read from)."""
from __future__ import annotations
import os
from typed_mjcf._core.tree import ModelBase
__all__ = ["export_with_assets"]

def export_with_assets(mjcf_model: ModelBase, out_dir: str | os.PathLike[str],
                       out_file_name: str | None = None, *, overwrite: bool = False) -> str:
    """dm_control's ``export_with_assets``: the XML is ``out_file_name``, else
    ``<model>.xml``; otherwise :func:`typed_mjcf.export_with_assets`."""
    ...
