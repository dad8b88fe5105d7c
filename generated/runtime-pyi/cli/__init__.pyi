# Generated from src/typed_mjcf/cli/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The ``typed-mjcf`` command: turn MJCF into typed Python, check, format, diff and render
models.

Each command is its own module (:mod:`.to_python`, :mod:`.check`, :mod:`.fmt`, :mod:`.diff`,
:mod:`.render`):
its ``NAME``, ``HELP`` and ``DESCRIPTION``, ``arguments()`` declaring its arguments, and a
``run()`` that returns the exit status:
0 all is well, 1 findings, differences or files that would change, 2 bad input (a one-line
error on stderr naming the file and line; never a traceback).
"""
from __future__ import annotations
import argparse
from collections.abc import Callable, Sequence
DESCRIPTION = """\
Tools for MuJoCo's MJCF models, typed against MuJoCo's own grammar.

  typed-mjcf to-python robot.xml -o robot.py   write Python that rebuilds the model
  typed-mjcf check robot.xml                   find what MuJoCo would refuse, file:line
  typed-mjcf fmt robot.xml                     lay it out, keeping what was written
  typed-mjcf diff a.xml b.xml                  what differs, element by element
  typed-mjcf render robot.xml -o robot.png     a picture of the model (offscreen)
  typed-mjcf mujoco-stubs                      the type stubs of `mujoco`, into typings/

Run "typed-mjcf COMMAND --help" for a command's options.

exit status: 0 ok; 1 findings, differences, or files that would change; 2 bad input (a
file that cannot be read as MJCF: a one-line error names the file and line)."""

def parser() -> argparse.ArgumentParser: ...

def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    ...
