"""The raw material: draft stubs from the two pinned tools, one text per module.

* pybind11-stubgen imports each compiled module and reads the signatures pybind11 writes into
  its docstrings (``mj_step(m: MjModel, d: MjData, nstep: SupportsInt = 1) -> None``), the
  property getters and setters of every struct and the members of every enum.
* mypy's stubgen reads the source of the pure-Python modules (``rollout.py``, ``viewer.py``,
  ...), so their annotations arrive as written rather than as evaluated at run time (which
  loses ``Optional`` and type aliases).

Both run in a subprocess of the current interpreter with a fixed environment: the tools import
``mujoco``, and what ``mujoco.GLContext`` is depends on ``MUJOCO_GL``; fixing it (and
``PYTHONHASHSEED``) keeps the drafts the same on every machine.
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
import tempfile
from pathlib import Path

# The compiled extension modules; ``mujoco/__init__.py`` star-imports most of them.
PYBIND_MODULES = (
    "mujoco._batch",
    "mujoco._callbacks",
    "mujoco._constants",
    "mujoco._enums",
    "mujoco._errors",
    "mujoco._functions",
    "mujoco._render",
    "mujoco._rollout",
    "mujoco._simulate",
    "mujoco._specs",
    "mujoco._structs",
)

# The pure-Python modules a user script imports. Left out, and so untyped for a checker
# (the stub package is marked partial): the GL platform back ends (importing them has side
# effects that depend on the machine's GL), ``mujoco.usd`` (needs ``pxr``), ``mujoco.sysid``
# (ships its own inline types and ``py.typed``), ``mujoco.introspect`` and the tests.
PYTHON_MODULES = (
    "mujoco",
    "mujoco.batch",
    "mujoco.gl_context",
    "mujoco.glfw",
    "mujoco.minimize",
    "mujoco.renderer",
    "mujoco.rendering",
    "mujoco.rendering.classic",
    "mujoco.rendering.classic.gl_context",
    "mujoco.rendering.classic.renderer",
    "mujoco.rollout",
    "mujoco.viewer",
)


def _environment() -> dict[str, str]:
    env = {key: value for key, value in os.environ.items()
           if key not in ("MUJOCO_GL", "PYOPENGL_PLATFORM")}
    env["PYTHONHASHSEED"] = "0"
    env["MUJOCO_GL"] = "glfw"  # the default on Linux; only decides what GLContext is at run time
    return env


# mypy is compiled with mypyc, so ``python -m mypy.stubgen`` finds no code object: call main().
_PYBIND11_STUBGEN = ["-m", "pybind11_stubgen"]
_MYPY_STUBGEN = ["-c", "from mypy.stubgen import main; main()"]


def _run(tool: list[str], args: list[str], cwd: Path) -> None:
    result = subprocess.run([sys.executable, *tool, *args], cwd=cwd, env=_environment(),
                            capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(tool)} failed (exit {result.returncode}):\n"
                           f"{result.stdout}\n{result.stderr}")


def _site_packages() -> str:
    """The directory holding the installed ``mujoco`` package."""
    spec = importlib.util.find_spec("mujoco")
    if spec is None or spec.origin is None:
        raise RuntimeError("mujoco is not installed")
    return str(Path(spec.origin).parents[1])


def _stub_file(root: Path, module: str) -> Path:
    """Where a tool wrote ``module``: ``a/b.pyi``, or ``a/b/__init__.pyi`` for a package."""
    parts = module.split(".")
    for path in (root.joinpath(*parts[:-1], parts[-1] + ".pyi"),
                 root.joinpath(*parts, "__init__.pyi")):
        if path.is_file():
            return path
    raise RuntimeError(f"no stub was written for {module} under {root}")


def draft_stubs() -> dict[str, str]:
    """``{module name: draft stub text}`` for every module in the two lists."""
    with tempfile.TemporaryDirectory(prefix="mujoco-stubs-") as tmp:
        root = Path(tmp)
        # --print-invalid-expressions-as-is: keep C++ spellings pybind11 leaks
        # (``mujoco::python::MjModelBodyViews``) so spelling.py can map them, instead of ``...``.
        _run(_PYBIND11_STUBGEN, ["--print-invalid-expressions-as-is", "--output-dir",
              str(root / "pybind"), *PYBIND_MODULES], root)
        # --no-import: read the source without importing it, so the drafts do not depend on
        # the optional packages viewer.py and the GL modules import (glfw, PyOpenGL)
        _run(_MYPY_STUBGEN, ["--include-docstrings", "--no-import", "--search-path",
                             _site_packages(), "--output", str(root / "mypy"),
              *(arg for module in PYTHON_MODULES for arg in ("-m", module))], root)
        drafts: dict[str, str] = {}
        for sub, modules in (("pybind", PYBIND_MODULES), ("mypy", PYTHON_MODULES)):
            for module in modules:
                drafts[module] = _stub_file(root / sub, module).read_text(encoding="utf-8")
        return drafts
