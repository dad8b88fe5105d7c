# Generated from src/typed_mjcf/_dmcompat/parser.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``dm_control.mjcf.parser``."""
from __future__ import annotations
from typed_mjcf.io import from_file, from_path, from_xml_string, from_zip
__all__ = ["from_file", "from_path", "from_xml_string", "from_zip"]
