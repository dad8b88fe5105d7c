"""Type stubs for MuJoCo's Python module ``mujoco``, generated from the installed wheel.

MuJoCo ships no type information. This package writes ``generated/mujoco-stubs/``, a PEP 561
stub-only package that types ``import mujoco`` for mypy and pyright: this repository's checks
find it on the path of an editable install; the typed-mjcf wheel carries it inside
``typed_mjcf`` (``_mujoco_stubs``, never as an installed ``mujoco-stubs/``) and ``typed-mjcf
mujoco-stubs`` copies it into a user's project. How:

1. ``sources``: draft stubs from two pinned tools run on the installed wheel. pybind11-stubgen
   reads the compiled modules (``_structs``, ``_functions``, ``_specs``, ``_enums``, ...): the
   signatures pybind11 writes into every docstring carry parameter names, defaults, array
   dtypes and which array arguments MuJoCo writes into, which is more than
   ``mujoco.introspect`` says about the Python bindings (it describes the C API: pointers,
   not the numpy arrays or the named-access views). mypy's stubgen reads the pure-Python
   modules (``rollout``, ``viewer``, ``renderer``, ...) from source, annotations as written.
2. ``spelling``: the C++ names pybind11 leaks (``mujoco::python::MjModelBodyViews``) mapped to
   the Python classes, by rule.
3. ``passes``: rules about the bindings that the drafts get wrong or leave loose (array inputs
   accept any array-like, C ints refuse floats, setters of array fields take any array-like,
   one base class for the enums, ``m.bind(...)`` overloads, ...). ``cdocs`` adds each struct
   field's C comment and shape (from ``mujoco.introspect``) as its docstring.
4. ``facts``: the hand-kept remainder (return types pybind11 cannot name, annotations the
   Python sources lack), each entry checked to still match a definition.
5. ``imports`` and ``build``: imports for the names the passes wrote, a completeness check
   (no parameter, return or attribute left untyped, no C++ name left), a header, the layout.

The output depends only on the installed ``mujoco`` and the pinned tools, so it is
deterministic; ``python -m codegen check`` regenerates and compares.
"""

from __future__ import annotations

from pathlib import Path

from codegen import folder
from codegen.mujoco_stubs.build import build

STUBS_DIR = Path(__file__).resolve().parents[2] / "generated" / "mujoco-stubs"


def render() -> dict[str, str]:
    """``{path inside mujoco-stubs/: text}`` for the installed ``mujoco``."""
    return build()


def stale(files: dict[str, str]) -> list[str]:
    """Paths under ``STUBS_DIR`` that differ from ``files``, are missing or are extra."""
    return folder.stale(files, STUBS_DIR)


def write(files: dict[str, str]) -> list[str]:
    """Make ``STUBS_DIR`` hold exactly ``files``; the paths that changed."""
    return folder.write(files, STUBS_DIR)
