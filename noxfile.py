"""Developer tasks: ``nox -s tests``, ``nox -s demo``, ``nox -s generate``, ``nox -s bench``."""

from __future__ import annotations

from pathlib import Path

import nox

nox.options.default_venv_backend = "venv"
nox.options.reuse_existing_virtualenvs = True
nox.options.sessions = ["tests"]

PYTHON = "3.11"
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
    session.run("pytest", *session.posargs)
    session.run("ruff", "check", ".")
    session.run("mypy", *TYPED_PATHS)
    session.run("pyright", *_pyright_paths())


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


@nox.session(python=PYTHON)
def bench(session: nox.Session) -> None:
    """typed-mjcf side by side with dm_control.mjcf, mujoco.MjSpec and raw lxml (tests/bench).

    nox -s bench                          # the full suite: several minutes
    nox -s bench -- --quick               # tiny sizes, a few seconds
    nox -s bench -- --json bench.json     # also save the raw numbers
    nox -s bench -- --only W1,W3 --libs typed,lxml
    """
    session.install("-e", ".", f"mujoco-core=={MUJOCO_VERSION}", "dm_control>=1.0.50")
    session.run("python", "-m", "tests.bench", *session.posargs)
