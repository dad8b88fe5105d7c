"""``dm_control.mjcf.parser``."""

from __future__ import annotations

from typed_mjcf.io import from_file, from_path, from_xml_string, from_zip

__all__ = ["from_file", "from_path", "from_xml_string", "from_zip"]
