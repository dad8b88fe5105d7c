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


@nox.session(python=PYTHON)
def generate(session: nox.Session) -> None:
    """Refresh schema/ from the installed mujoco (and a grammar file) and render generated/.

    nox -s generate -- --grammar path/to/mujoco/src/xml/mjcf.schema
    """
    session.install("-e", ".[codegen]")
    session.run("python", "-m", "codegen", "generate", *session.posargs)
