# Generated from src/typed_mjcf/_model/assets_io.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Writing a model with its files into a folder, and the files for MuJoCo's VFS.

:func:`export_with_assets` writes only into its folder, each file atomically, and refuses to
replace a different file of the same name unless asked to. File names are flat and unique
(see :mod:`typed_mjcf._text.files`).
"""
from __future__ import annotations
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._text.files import (
    CollectedFiles,
    is_plain_file_name,
    safe_file_name,
    split_name,
    unique_name,
)
Written = tuple[str, CollectedFiles]

def model_files(model: ModelBase, written: Written,
                model_filename: str | None = None) -> dict[str, bytes]:
    """The files a folder export writes: the model's XML (``written``, named
    ``model_filename``, else after the model) last, after every file it uses."""
    ...

def get_assets(model: ModelBase, *, flat: bool = False) -> dict[str, bytes]:
    """The files the model uses, by the names its VFS export gives them: each file's own
    name, except where two different files share a base name (``torso/base_link.stl`` and
    ``gripper/base_link.stl``): those keep their folders (the path below the model's folder,
    ``assets/torso/base_link.stl`` under ``meshdir="assets"``), as ``mujoco.MjSpec``'s
    ``assets`` holds them apart. MuJoCo's dict route, ``MjModel.from_xml_string(xml,
    assets)``, finds files by base name alone and cannot hold both: ``flat=True`` asks for
    that form, base names only, and raises :class:`ExportError` naming both files where
    the model has such a pair."""
    ...

def export_with_assets(model: ModelBase, written: Written, directory: str,
                       model_filename: str | None = None, *, overwrite: bool = False,
                       after_source: bool = True) -> str:
    """Write the XML and its files (``written``) into ``directory``; return the XML's path.

    Without ``model_filename`` the XML is named after the file the model was read from
    (``after_source``), else after the model (``model=``), as dm_control names it.

    Only plain file names inside ``directory`` are written (the collected names are safe by
    construction; ``model_filename`` must be plain). Every file is checked before any is
    written: one already there with other contents (or that is not a regular file) is an
    :class:`ExportError` unless ``overwrite``; identical files are left untouched. Each file
    is written to a temporary file in ``directory`` and renamed over its name, so a reader
    never sees half a file; the model's XML is written last.
    """
    ...

def is_plain_path(name: str) -> bool:
    """Whether ``name`` is plain file names joined by ``/`` (a file the model keeps apart
    from another of its base name keeps its folders)."""
    ...

def write_files(directory: str, outputs: list[tuple[str, bytes]], overwrite: bool,
                what: str) -> None:
    """Write ``outputs`` (plain file names, the last one the file that uses the others) into
    ``directory`` as one change: every file goes to a temporary file first, then each is
    renamed into place; if anything fails (or is interrupted) the files already renamed are
    put back as they were and no temporary file is left. Files already there with the same
    contents are left untouched; different ones (or links, or anything not a regular file)
    are refused unless ``overwrite``, and then replaced, never written through."""
    ...

def remove_stale_temporaries(directory: str) -> None:
    """Remove the temporary files an export killed midway left in ``directory``: those of a
    process that is no longer running (their name holds its id), or older than a day."""
    ...
