"""Developer tasks: ``nox -s tests``, ``nox -s demo``, ``nox -s generate``, ``nox -s bench``,
``nox -s pictures``, ``nox -s bench_editor``.

Every session runs on the first Python nox finds that the project supports (3.11 or newer);
``nox -P 3.13 -s tests`` (or ``-P`` with an interpreter's path) picks one. With none
installed, a session fails (it does not skip) and says which Python it looked for.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import nox
from nox.command import CommandFailed

# python="<version range>" (interpreter discovery by python-discovery) came in nox 2026.8.10;
# older versions would look for an interpreter literally named ">=3.11" and find none.
nox.needs_version = ">=2026.8.10"
nox.options.default_venv_backend = "venv"
nox.options.reuse_existing_virtualenvs = True
nox.options.sessions = ["tests"]
# A missing interpreter is a failure, not a skip that exits 0 and looks like a pass.
nox.options.error_on_missing_interpreters = True

PYTHON = ">=3.11"  # pyproject's requires-python: any installed version that satisfies it
# src holds the generated classes too (src/typed_mjcf/_generated links to generated/).
TYPED_PATHS = ["src", "codegen", "tests/typing", "examples"]
# Deliberately ill-typed code: tests/typing/test_typecheck.py checks that mypy and pyright
# reject it as its markers say. The plain runs below skip it: mypy via [tool.mypy] exclude;
# pyright by not being given it (a [tool.pyright] exclude would hide it from that test too).
NEGATIVE_CASES = Path("tests/typing/negative")


def _pyright_paths() -> list[str]:
    paths: list[str] = []
    for path in TYPED_PATHS:
        if NEGATIVE_CASES.is_relative_to(path):
            paths += sorted(str(p) for p in Path(path).rglob("*.py")
                            if not p.is_relative_to(NEGATIVE_CASES))
        else:
            paths.append(path)
    return paths


@nox.session(python=PYTHON)
def tests(session: nox.Session) -> None:
    """The test suite, then ruff, mypy --strict and pyright over the typed code."""
    session.install("-e", ".[dev]")
    session.run("python", "-m", "codegen", "check")
    # every core; a worker takes whole files, so a module's shared fixtures (a mypy run,
    # a language server) are built once
    session.run("pytest", "-n", "auto", "--dist", "loadfile", *session.posargs)
    session.run("ruff", "check", ".")
    session.run("mypy", *TYPED_PATHS)
    session.run("pyright", *_pyright_paths())


@nox.session(python=PYTHON)
def demo(session: nox.Session) -> None:
    """Build a small robot with the typed API, compile it, simulate one second."""
    session.install("-e", ".")
    session.run("python", "examples/demo.py", *session.posargs)


@nox.session(python=PYTHON)
def pictures(session: nox.Session) -> None:
    """Render the README's pictures of the examples into examples/pictures/ (offscreen: EGL or
    OSMesa, no display). tests/test_pictures.py checks the committed ones are current."""
    session.install("-e", ".[render]")
    session.run("python", "-m", "tests.pictures", *session.posargs)


# What schema/ describes: one place. `python -m codegen generate` writes it and moves
# pyproject.toml's pins with it (the dev extra's mujoco==X, the dependency range).
MUJOCO_VERSION = json.loads(Path("schema/mjcf.json").read_text(encoding="utf-8"))[
    "mujoco_version"]


@nox.session(python=PYTHON)
def generate(session: nox.Session) -> None:
    """Refresh schema/ from a mujoco wheel (and a grammar file) and render generated/.

    The session installs the MuJoCo it generates for, in its own environment: the pinned
    version (what schema/ describes) unless --mujoco-version names another.

    nox -s generate                                  # the pinned MuJoCo: expect no changes
    nox -s generate -- --mujoco-version 4.1.0        # bindings for another MuJoCo
    nox -s generate -- --grammar path/to/mujoco/src/xml/mjcf.schema
    """
    try:
        version, args = _generate_args(session.posargs)
    except ValueError as error:  # before installing anything: a mistake fails at once
        session.error(str(error))
    # The release generated for, whatever release the project depends on now (that is the
    # pin being moved): the project without its dependencies, the rest by hand.
    # `mujoco`, not `mujoco-core`: the package the dev extra pins (3.x has no mujoco-core)
    try:
        session.install(*_requirements("codegen"), f"mujoco=={version}")
    except CommandFailed:
        session.error(f"no `mujoco` {version} to install (pip says why above): the pins name "
                      "the package users and dm_control install, so a release published as "
                      "mujoco-core alone (4.0.1) is not one to move to; see CONTRIBUTING.md")
    session.install("--no-deps", "-e", ".")
    session.run("python", "-m", "codegen", "generate", *args)


def _requirements(extra: str) -> list[str]:
    """pyproject's runtime dependencies other than MuJoCo, and those of ``extra``."""
    project = tomllib.loads(Path("pyproject.toml").read_text(encoding="utf-8"))["project"]
    runtime = [r for r in project["dependencies"] if not r.startswith("mujoco")]
    return [*runtime, *project["optional-dependencies"][extra]]


def _generate_args(posargs: list[str]) -> tuple[str, list[str]]:
    """The MuJoCo version to install and the arguments for ``python -m codegen generate``;
    ``ValueError`` (one line) for a missing or malformed value."""
    args, version = list(posargs), MUJOCO_VERSION
    for at, arg in enumerate(args):
        if arg == "--mujoco-version" or arg.startswith("--mujoco-version="):
            value = arg.partition("=")[2] if "=" in arg else (
                args[at + 1] if at + 1 < len(args) else "")
            if not re.fullmatch(r"\d+(\.\d+)*", value):
                raise ValueError(f"--mujoco-version needs a release number such as 4.1.0, "
                                 f"got {value!r}")
            del args[at : at + (1 if "=" in arg else 2)]
            version = value
            break
    for at, arg in enumerate(args):  # the generator checks this too; here it saves an install
        if arg == "--grammar" or arg.startswith("--grammar="):
            value = arg.partition("=")[2] if "=" in arg else (
                args[at + 1] if at + 1 < len(args) else "")
            if value and not Path(value).expanduser().is_file():  # none: argparse says so
                raise ValueError(f"--grammar {value}: no such file; expected MuJoCo's "
                                 "grammar file (src/xml/mjcf.schema in its source tree)")
    return version, args


@nox.session(python=PYTHON)
def bench(session: nox.Session) -> None:
    """typed-mjcf side by side with dm_control.mjcf, mujoco.MjSpec and raw lxml (tests/bench).

    nox -s bench                          # the full suite: several minutes
    nox -s bench -- --quick               # tiny sizes, a few seconds
    nox -s bench -- --json bench.json     # also save the raw numbers
    nox -s bench -- --only W1,W3 --libs typed,lxml
    """
    session.install("-e", ".", f"mujoco=={MUJOCO_VERSION}", "dm_control>=1.0.50")
    session.run("python", "-m", "tests.bench", *session.posargs)


@nox.session(python=PYTHON)
def bench_editor(session: nox.Session) -> None:
    """What an editor costs: pyright's language server on authoring scripts, typed-mjcf beside
    dm_control.mjcf and mujoco.MjSpec (tests/bench/editor.py; CPU, memory, completion hits).

    nox -s bench_editor                          # 3 fresh servers per library: minutes
    nox -s bench_editor -- --rounds 1 --libs typed --misses
    """
    session.install("-e", ".[dev]")
    session.run("python", "-m", "tests.bench.editor", *session.posargs)
