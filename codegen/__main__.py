"""``python -m codegen``: refresh schema/ from MuJoCo's grammar and render generated/.

    python -m codegen generate [--grammar PATH/TO/mjcf.schema] [--allow-untyped]
    python -m codegen render      # schema/ -> generated/ only
    python -m codegen stubs       # the installed mujoco -> generated/mujoco-stubs/
    python -m codegen check       # exit 1 if generated/ differs from a fresh render

Misuse and broken inputs end in one line on stderr (``python -m codegen: error: ...``) and
exit status 2; a traceback means a bug in the generator.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from codegen.facts import FactsError
from codegen.grammar import GrammarError

PROG = "python -m codegen"
# What the commands import that a plain `pip install -e .` does not bring: the codegen extra
# (which `nox -s generate` installs, with the pinned MuJoCo).
EXTRA = {"jinja2", "mujoco", "pybind11_stubgen", "mypy"}


class UsageError(Exception):
    """A mistake in how the command was called, reported in one line."""


def grammar_file(text: str) -> Path:
    """``--grammar``: an existing file (MuJoCo's ``src/xml/mjcf.schema``)."""
    path = Path(text).expanduser()
    if path.is_dir():
        inside = path / "src" / "xml" / "mjcf.schema"
        hint = f" (did you mean {inside}?)" if inside.is_file() else ""
        raise UsageError(f"--grammar {text}: is a directory, not MuJoCo's grammar file "
                         f"src/xml/mjcf.schema{hint}")
    if not path.is_file():
        raise UsageError(f"--grammar {text}: no such file; expected MuJoCo's grammar file "
                         "(src/xml/mjcf.schema in its source tree)")
    return path


def parser() -> argparse.ArgumentParser:
    main_parser = argparse.ArgumentParser(prog=PROG, description=__doc__,
                                          formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = main_parser.add_subparsers(dest="command", required=True)
    gen = sub.add_parser("generate", help="sync schema/ with the installed mujoco and render")
    gen.add_argument("--grammar", help="MuJoCo's src/xml/mjcf.schema to read first")
    gen.add_argument("--allow-untyped", action="store_true",
                     help="write attributes that cannot be typed precisely as strings")
    sub.add_parser("render", help="render generated/ from schema/")
    sub.add_parser("stubs", help="write generated/mujoco-stubs/ from the installed mujoco")
    sub.add_parser("check", help="fail if generated/ differs from a fresh render")
    return main_parser


def run(args: argparse.Namespace) -> int:
    grammar = grammar_file(args.grammar) if getattr(args, "grammar", None) else None
    # Imported here, not at the top: a missing optional dependency then fails inside main()'s
    # error handling, as one line, instead of as an import traceback.
    from codegen import commands

    if args.command == "generate":
        return commands.generate(grammar, args.allow_untyped)
    if args.command == "render":
        return commands.render_only()
    if args.command == "stubs":
        return commands.stubs()
    return commands.check()


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)  # argparse reports its own errors (usage, exit 2)
    try:
        return run(args)
    except UsageError as error:
        problem = str(error)
    except (GrammarError, FactsError) as error:  # path:line: message
        problem = str(error)
    except ModuleNotFoundError as error:
        if error.name is None or error.name.partition(".")[0] not in EXTRA:
            raise
        problem = (f"{error.name} is not installed; `nox -s generate` installs what the "
                   "generator needs, or: pip install -e '.[codegen]' mujoco")
    except OSError as error:  # an input that cannot be read (the grammar, schema/, facts)
        problem = f"{error.filename or ''}: {error.strerror or error}".lstrip(": ")
    print(f"{PROG}: error: {problem}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
