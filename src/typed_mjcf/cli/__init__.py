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
import os
import sys
from collections.abc import Callable, Sequence

from typed_mjcf import __version__
from typed_mjcf.cli import check, diff, fmt, mujoco_stubs, render, to_python
from typed_mjcf.cli._common import BAD_INPUT
from typed_mjcf.errors import MjcfError
from typed_mjcf.tooling import describe_build, describe_releases

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


def parser() -> argparse.ArgumentParser:
    main_parser = argparse.ArgumentParser(
        prog="typed-mjcf", description=DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    main_parser.add_argument("--version", action="version",
                             version=f"typed-mjcf {__version__} ({describe_build()})\n"
                                     f"{describe_releases()}")
    commands = main_parser.add_subparsers(title="commands", metavar="COMMAND", required=True)
    for module in (to_python, check, fmt, diff, render, mujoco_stubs):
        command = commands.add_parser(module.NAME, help=module.HELP,
                                      description=module.DESCRIPTION,
                                      formatter_class=argparse.RawDescriptionHelpFormatter)
        module.arguments(command)
        command.set_defaults(command_name=module.NAME)
    return main_parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    args = parser().parse_args(argv)
    run: Callable[[argparse.Namespace], int] = args.run
    try:
        return run(args)
    except KeyboardInterrupt:
        return 130
    except MjcfError as problem:  # a command let bad input through: still one line, not a
        print(f"typed-mjcf {args.command_name}: {' '.join(str(problem).split())}",  # trace
              file=sys.stderr)
        return BAD_INPUT
    except BrokenPipeError:  # the reader went away (| head): stop quietly
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141  # as a shell reports a process that SIGPIPE stopped
