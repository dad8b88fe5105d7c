"""Reading and writing models: MJCF text and files, MuJoCo specs, files with their assets."""

from __future__ import annotations

import os
from typing import IO, TYPE_CHECKING

if TYPE_CHECKING:
    import mujoco

    from typed_mjcf._root import ModelRoot
    from typed_mjcf_generated.elements import RootElement


def _typed(model: ModelRoot) -> RootElement:
    from typed_mjcf_generated.elements import RootElement

    assert isinstance(model, RootElement)
    return model


def from_xml_string(xml: str | bytes, *, base_dir: str | os.PathLike[str] | None = None,
                    source: str | None = None) -> RootElement:
    """Parse MJCF text. ``base_dir`` is where relative files and includes are found."""
    from typed_mjcf._parse import parse_text

    return _typed(parse_text(xml, base_dir=None if base_dir is None else os.fspath(base_dir),
                             source=source))


def from_path(path: str | os.PathLike[str]) -> RootElement:
    """Parse an MJCF file; relative files and includes resolve against its folder."""
    from typed_mjcf._parse import parse_path

    return _typed(parse_path(os.fspath(path)))


def from_file(file: IO[str] | IO[bytes], *, base_dir: str | os.PathLike[str] | None = None
              ) -> RootElement:
    """Parse MJCF from an open file object."""
    name = getattr(file, "name", None)
    if base_dir is None and isinstance(name, str):
        base_dir = os.path.dirname(os.path.abspath(name))
    return from_xml_string(file.read(), base_dir=base_dir,
                           source=name if isinstance(name, str) else None)


def from_spec(spec: mujoco.MjSpec) -> RootElement:
    """Read a ``mujoco.MjSpec`` back into typed elements."""
    from typed_mjcf._bridge import spec_to_xml

    xml, assets = spec_to_xml(spec)
    # The spec's files are relative to the folder of the file it was read from (if any).
    folder: object = getattr(spec, "modelfiledir", None)
    model = from_xml_string(xml, base_dir=folder if isinstance(folder, str) and folder else None)
    del assets
    return model


def export_with_assets(model: ModelRoot, directory: str | os.PathLike[str],
                       model_filename: str | None = None) -> str:
    """Write the model's XML and every file it uses into ``directory``; return the XML's path."""
    from typed_mjcf._assets_io import export_with_assets as export

    return export(model, os.fspath(directory), model_filename)


__all__ = ["export_with_assets", "from_file", "from_path", "from_spec", "from_xml_string"]
