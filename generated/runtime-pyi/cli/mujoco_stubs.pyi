# Generated from src/typed_mjcf/cli/mujoco_stubs.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``typed-mjcf mujoco-stubs``: copy the ``mujoco`` type stubs into a project's stub folder.

The stubs (generated/mujoco-stubs in the repository, generated from the ``mujoco`` wheel the
bindings describe) ship inside the typed-mjcf wheel as ``typed_mjcf/_mujoco_stubs``, not as an
installed ``mujoco-stubs/`` package: that folder name belongs to whichever distribution owns
it (the unofficial ``mujoco-stubs`` on PyPI does), and two owners overwrite each other
silently. Copied into a folder of the user's project, they are the project's own files.
"""
from __future__ import annotations
import argparse
from pathlib import Path
from typing import Final
from typed_mjcf.tooling import MUJOCO_VERSION
NAME = "mujoco-stubs"
HELP = "copy the type stubs of `mujoco` into a project's stub folder (default typings/)"
DESCRIPTION = f"""\
Copy the type stubs of MuJoCo's `mujoco` package (generated from mujoco {MUJOCO_VERSION}, the
release typed-mjcf's bindings describe) into DIRECTORY/mujoco, so that type checkers see
`mujoco.MjModel`, `mujoco.mj_step(...)` and typed-mjcf's Physics precisely. pyright and
Pylance read typings/ by default; for mypy, set mypy_path = "typings". Run it again after
upgrading typed-mjcf: it replaces the stubs it wrote before, and leaves a folder it did not
write alone.

  typed-mjcf mujoco-stubs
  typed-mjcf mujoco-stubs stubs/

exit status: 0 the stubs are written, 2 DIRECTORY/mujoco exists and holds files typed-mjcf
did not write (a one-line error)."""
MARKER: Final = "WRITTEN_BY_TYPED_MJCF"

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

def source() -> Path:
    """The shipped stubs: inside the installed wheel, or generated/ of a checkout (an
    editable install puts generated/ on the path)."""
    ...

def run(args: argparse.Namespace) -> int: ...
