"""Developer tasks: ``nox -s tests``, ``nox -s demo``, ``nox -s generate``, ``nox -s bench``."""

from __future__ import annotations

import nox

nox.options.default_venv_backend = "venv"
nox.options.reuse_existing_virtualenvs = True
nox.options.sessions = ["tests"]

PYTHON = "3.11"
TYPED_PATHS = ["src", "generated", "codegen", "tests/typing", "examples"]


@nox.session(python=PYTHON)
def tests(session: nox.Session) -> None:
    """The test suite, then mypy --strict and pyright over the typed code."""
    session.install("-e", ".[dev]")
    session.run("python", "-m", "codegen", "check")
    session.run("pytest", *session.posargs)
    session.run("mypy", *TYPED_PATHS)
    session.run("pyright", *TYPED_PATHS)


@nox.session(python=PYTHON)
def demo(session: nox.Session) -> None:
    """Build a small robot with the typed API, compile it, simulate one second."""
    session.install("-e", ".")
    session.run("python", "examples/demo.py", *session.posargs)


MUJOCO_VERSION = "4.0.0"  # what schema/ describes; keep in step with the dev extra


@nox.session(python=PYTHON)
def generate(session: nox.Session) -> None:
    """Refresh schema/ from a mujoco wheel (and a grammar file) and render generated/.

    nox -s generate                                  # the pinned MuJoCo: expect no changes
    nox -s generate -- --mujoco-version 4.1.0        # bindings for another MuJoCo
    nox -s generate -- --grammar path/to/mujoco/src/xml/mjcf.schema
    """
    args = list(session.posargs)
    version = MUJOCO_VERSION
    if "--mujoco-version" in args:
        at = args.index("--mujoco-version")
        version = args[at + 1]
        del args[at : at + 2]
    session.install("-e", ".[codegen]", f"mujoco-core=={version}")
    session.run("python", "-m", "codegen", "generate", *args)
