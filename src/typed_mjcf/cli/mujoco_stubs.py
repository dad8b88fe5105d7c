"""``typed-mjcf mujoco-stubs``: copy the ``mujoco`` type stubs into a project's stub folder.

The stubs (generated/mujoco-stubs in the repository, generated from the ``mujoco`` wheel the
bindings describe) ship inside the typed-mjcf wheel as ``typed_mjcf/_mujoco_stubs``, not as an
installed ``mujoco-stubs/`` package: that folder name belongs to whichever distribution owns
it (the unofficial ``mujoco-stubs`` on PyPI does), and two owners overwrite each other
silently. Copied into a folder of the user's project, they are the project's own files.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from pathlib import Path
from typing import Final

import typed_mjcf
from typed_mjcf.cli._common import BAD_INPUT, OK, error
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

# Marks a folder this command wrote (type checkers read only .pyi files).
MARKER: Final = "WRITTEN_BY_TYPED_MJCF"


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("directory", nargs="?", default="typings", metavar="DIRECTORY",
                        help="the project's stub folder (default typings, pyright's default)")
    parser.set_defaults(run=run)


def source() -> Path:
    """The shipped stubs: inside the installed wheel, or generated/ of a checkout (an
    editable install puts generated/ on the path)."""
    shipped = Path(typed_mjcf.__file__).resolve().parent / "_mujoco_stubs"
    if (shipped / "__init__.pyi").is_file():
        return shipped
    for entry in sys.path:
        candidate = Path(entry or ".") / "mujoco-stubs"
        ours = (candidate.parent / "typed_mjcf_generated").is_dir()  # generated/, not another
        if ours and (candidate / "__init__.pyi").is_file():
            return candidate
    raise FileNotFoundError("the mujoco stubs are not installed with this typed-mjcf")


def run(args: argparse.Namespace) -> int:
    target = Path(args.directory) / "mujoco"
    if target.exists() and not (target / MARKER).is_file():
        error(NAME, f"{target}: exists and was not written by typed-mjcf; remove it or name "
                    "another directory")
        return BAD_INPUT
    stubs = source()
    if target.exists():
        shutil.rmtree(target)
    shutil.copytree(stubs, target, ignore=shutil.ignore_patterns("py.typed", "__pycache__"))
    (target / MARKER).write_text(f"mujoco {MUJOCO_VERSION} stubs, from typed-mjcf "
                                 f"{typed_mjcf.__version__}\n", encoding="utf-8")
    count = sum(1 for _ in target.rglob("*.pyi"))
    print(f"{target}: {count} stub files for mujoco {MUJOCO_VERSION}. pyright and Pylance "
          f"read {args.directory}/ if it is their stubPath (typings/ by default); for mypy, "
          f'set mypy_path = "{args.directory}".')
    return OK
