"""Developer tasks: ``nox -s tests``, ``nox -s tests_compiled``, ``nox -s demo``, ``nox -s generate``, ``nox -s bench``,
``nox -s pictures``, ``nox -s bench_editor``, ``nox -s releases``, ``nox -s install_matrix``,
``nox -s docs``, ``nox -s ray``.

Every session runs on the first Python nox finds that the project supports (3.11 or newer);
``nox -P 3.13 -s tests`` (or ``-P`` with an interpreter's path) picks one. With none
installed, a session fails (it does not skip) and says which Python it looked for.
"""

from __future__ import annotations

import json
import re
import shutil
import tempfile
import tomllib
from pathlib import Path

import nox
from nox.command import CommandFailed

# python="<version range>" (interpreter discovery by python-discovery) came in nox 2026.8.10;
# older versions would look for an interpreter literally named ">=3.11" and find none.
nox.needs_version = ">=2026.8.10"
# uv (a tool, not a dependency of the project) when nox finds it (`pip install "nox[uv]"`,
# as .ci/run does): it creates the environment and installs .[dev] in ~15 s where pip
# takes minutes (measured: CONTRIBUTING.md "Keeping the suite fast"); venv and pip otherwise.
nox.options.default_venv_backend = "uv|venv"
nox.options.reuse_existing_virtualenvs = True
nox.options.sessions = ["tests"]
# A missing interpreter is a failure, not a skip that exits 0 and looks like a pass.
nox.options.error_on_missing_interpreters = True

PYTHON = ">=3.11"  # pyproject's requires-python: any installed version that satisfies it


@nox.session(python=PYTHON)
def tests(session: nox.Session) -> None:
    """The test suite on every core, type checks included, then ruff.

    mypy --strict and pyright strict over the typed code (src/ with the generated classes,
    codegen/, tests/typing/, examples/) run inside the test run, beside the other tests:
    tests/typing/test_typecheck.py (its TYPED_PATHS). pyproject's addopts make pytest-xdist
    keep each module's tests on one worker (its shared fixtures are built once) and start
    the longest first (tests/conftest.py).

    No separate ``python -m codegen check`` (17 s of one core before pytest starts): each of
    its comparisons is a test run here beside the others (the installed MuJoCo is the pinned
    one: test_drift; the pins: test_pins; generated/: test_generated_api; bindings.json:
    test_bindings; mujoco-stubs/: tests/typing/test_mujoco_stubs.py; runtime-pyi/:
    tests/codegen/test_runtime_stubs.py).
    """
    session.install("-e", ".[dev]")
    # Bytecode is written (a PYTHONDONTWRITEBYTECODE of the caller's is dropped for the run):
    # uv installs without .pyc files, and the run starts many Python processes (the two
    # workers, the subprocesses of the dm_control, safety, CLI and example tests) that import
    # the same modules; without .pyc each compiles them again (measured, CONTRIBUTING.md
    # "Keeping the suite fast": 25% of the CPU of the tests that start subprocesses).
    session.run("pytest", "-n", "auto", *session.posargs,
                env={"PYTHONDONTWRITEBYTECODE": None})
    session.run("ruff", "check", ".")


# The test modules the compiled build runs (tests_compiled): everything that exercises the
# runtime through the installed package. Left out: what checks the repository rather than
# the installed build (the type checks and stubs of src/, codegen/ and generated/ in sync,
# the docs, the install matrix, the benchmark's own smoke test).
COMPILED_TESTS = ["tests/runtime", "tests/composition", "tests/fidelity", "tests/safety",
                  "tests/dm_control", "tests/cli", "tests/physics", "tests/render",
                  "tests/test_generated_api.py", "tests/test_examples.py",
                  # the type check of to-python's output is the repository's mypy run
                  "--ignore", "tests/cli/test_to_python_types.py"]


# a fresh environment each run: a reused one would keep the last wheel (same version number)
@nox.session(python=PYTHON, reuse_venv=False)
def tests_compiled(session: nox.Session) -> None:
    """The suite on the compiled build: the wheel built with ``TYPED_MJCF_COMPILE=1`` (mypyc
    over pyproject's list of hot modules; a C compiler and minutes of CPU), installed (not
    editable) with the dev extra, then the runtime's tests against it
    (``tests/runtime/test_build.py`` checks the compiled modules are the ones loaded).

    nox -s tests_compiled                              # build, install, test
    nox -s tests_compiled -- tests/runtime -x          # other pytest arguments
    """
    # The wheel goes to a folder of its own outside the clone, not session.create_tmp(): that
    # sets TMPDIR to .nox/tests_compiled/tmp for every later command, so the tests' tmp_path
    # would lie inside the working directory, where the library names files relative to it
    # (fmt's messages, an attached model's files), unlike in `nox -s tests`.
    wheels = Path(tempfile.mkdtemp(prefix="typed-mjcf-wheels-"))
    try:
        session.install("build[uv]")
        session.run("python", "-m", "build", "--wheel", "--installer", "uv", "--outdir",
                    str(wheels), ".", env={"TYPED_MJCF_COMPILE": "1"})
        (wheel,) = wheels.glob("typed_mjcf-*.whl")
        session.install(f"{wheel}[dev]")
    finally:
        shutil.rmtree(wheels, ignore_errors=True)
    # the tests import typed_mjcf from site-packages (pytest puts the repository root on the
    # path, where no typed_mjcf is); TYPED_MJCF_EXPECT_COMPILED makes test_build insist
    session.run("pytest", "-n", "auto", *(session.posargs or COMPILED_TESTS),
                env={"PYTHONDONTWRITEBYTECODE": None, "TYPED_MJCF_EXPECT_COMPILED": "1"})


@nox.session(python=PYTHON)
def docs(session: nox.Session) -> None:
    """Build the documentation site from docs/ into docs/_build/html, strictly: a warning
    (a broken link, a missing page, an API name that does not resolve) fails the build. Then
    open it in headless Chromium (tests/docs: the home page, a guide page, an element page,
    the search; no console message; docs/_build/screenshot.png). The pages' code blocks run
    and type-check in ``nox -s tests`` (tests/test_readme.py)."""
    session.install("-e", ".[dev,docs]")
    session.run("sphinx-build", "-W", "--keep-going", "-n", "-q", "-b", "html", "docs",
                "docs/_build/html", env={"MUJOCO_GL": "egl"})
    session.run("pytest", "-p", "no:cacheprovider", "-q", "tests/docs", *session.posargs,
                env={"TYPED_MJCF_DOCS_SITE": "docs/_build/html"})


@nox.session(python=PYTHON)
def ray(session: nox.Session) -> None:
    """Structural variants on a local Ray cluster the tests start (tests/variation/
    test_ray.py; the optional ``ray`` extra, which ``nox -s tests`` does not install, so it
    skips them there). Slow: Ray takes tens of seconds to start on two cores."""
    session.install("-e", ".[dev,ray]")
    # Bytecode written (as in tests): each of Ray's processes (its node's agents, its
    # workers) would otherwise compile every module it imports at each start, and on a
    # loaded machine its node then misses its start deadlines (measured: 30 s, three tries)
    session.run("pytest", "-p", "no:cacheprovider", "-n", "0", "-q", "-rs",
                "tests/variation/test_ray.py", *session.posargs,
                env={"PYTHONDONTWRITEBYTECODE": None})


@nox.session(python=PYTHON)
def warp(session: nox.Session) -> None:
    """The MuJoCo Warp tests (the ``warp`` extra; tests/warp, which ``nox -s tests`` does not
    collect): batched worlds on Warp's CPU device against MuJoCo, and what Warp refuses. The
    first run builds Warp's kernels (minutes of CPU; cached in ~/.cache/warp after)."""
    session.install("-e", ".[dev,warp]")
    session.run("pytest", "-n", "0", "-p", "no:cacheprovider", "tests/warp", *session.posargs,
                env={"WARP_TEST_SESSION": "1"})


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
    # pin being moved): the project without its dependencies, the rest by hand. A release
    # older than schema/mjcf.json's becomes schema/releases/<version>.json (codegen/releases.py).
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
    nox -s bench -- --build compiled=PATH/bin/python   # a compiled build's rows beside these
    """
    # Ray for the variation workload's structural variants on a local cluster; bytecode
    # written, so that Ray's processes start in time (see the ray session)
    session.install("-e", ".[ray]", f"mujoco=={MUJOCO_VERSION}", "dm_control>=1.0.50")
    session.run("python", "-m", "tests.bench", *session.posargs,
                env={"PYTHONDONTWRITEBYTECODE": None})


@nox.session(python=PYTHON)
def bench_editor(session: nox.Session) -> None:
    """What an editor costs: pyright's language server on authoring scripts, typed-mjcf beside
    dm_control.mjcf and mujoco.MjSpec (tests/bench/editor.py; CPU, memory, completion hits).

    nox -s bench_editor                          # 3 fresh servers per library: minutes
    nox -s bench_editor -- --rounds 1 --libs typed --misses
    """
    session.install("-e", ".[dev]")
    session.run("python", "-m", "tests.bench.editor", *session.posargs)


# The older MuJoCo releases schema/releases/ covers, each with the dm_control release that
# pairs with it (dm_control pins MuJoCo exactly; its models are part of the corpus).
OLDER_RELEASES = {"3.3.7": "dm_control==1.0.34", "3.17.0": "dm_control==1.0.49"}
# The corpus tests: round trip, validate and compile every model the installed packages ship.
CORPUS_TESTS = [
    "tests/fidelity/test_round_trip.py",
    "tests/fidelity/test_corpus_validate.py",
    "tests/fidelity/test_defaults_corpus.py",
    "tests/runtime/test_corpus.py",
    "tests/runtime/test_corpus_asset_routes.py",
    "tests/runtime/test_release_gates.py",
    "tests/runtime/test_release_types.py",
    "tests/runtime/test_release_facts.py",
    "tests/runtime/test_compile_routes.py",
]


@nox.session(python=PYTHON)
@nox.parametrize("mujoco", list(OLDER_RELEASES))
def releases(session: nox.Session, mujoco: str) -> None:
    """The corpus tests on an older MuJoCo (its grammar from schema/releases/), with the
    dm_control that pairs with it. Not in ``nox -s tests`` (which runs the newest MuJoCo).

    nox -s releases                       # every older release covered
    nox -s "releases(mujoco='3.17.0')"    # one
    """
    # the dev extra less its MuJoCo and dm_control pins (the newest's)
    dev = [r for r in _requirements("dev") if not r.startswith(("mujoco", "dm_control"))]
    session.install(*dev, f"mujoco=={mujoco}", OLDER_RELEASES[mujoco])
    session.install("--no-deps", "-e", ".")
    session.run("pytest", "-n", "auto", "--dist", "loadfile", *CORPUS_TESTS, *session.posargs,
                env={"MUJOCO_GL": "egl"})


@nox.session(python=PYTHON)
def install_matrix(session: nox.Session) -> None:
    """Build the wheel and install it into fresh environments holding MuJoCo 3.3.7, 3.17.0,
    4.0.0, mujoco-core 4.0.1 and an unsupported 3.2.7: ``import mujoco`` must keep working and
    typed-mjcf must compile a model (tests/install; minutes, from the package registry)."""
    session.install("pytest")
    session.run("pytest", "-p", "no:cacheprovider", "-rA", "tests/install", *session.posargs,
                env={"TYPED_MJCF_INSTALL_MATRIX": "1"})
