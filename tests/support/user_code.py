"""A user's project of the documentation's code (``UserCode``): each block, the reference's
examples, ``examples/``, the negative cases, the README table's mistakes and a canary, a
module each, with strict configurations and none of this repository's settings; and the one
mypy and pyright run over it (``tests/conftest.py``'s ``user_code_reports``)."""

from __future__ import annotations

import shutil
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from tests.support.doc_blocks import BLOCKS, EXAMPLES, REFERENCE, ROOT, reference_examples
from tests.support.typecheck import (
    MYPY_OUTPUT,
    NEGATIVE_FILES,
    Checker,
    Diagnostic,
    run_checkers,
)

# The mistakes of the README's table "What the type checker catches", one per line in the
# table's order after the three set-up lines; what mypy says of each must be what the
# table's typed-mjcf column shows ("…" standing for the middle of a long list).
MISTAKES = [
    'body.add_geom(tpye="capsule")',
    'body.add_geom(type="capsul")',
    "body.add_geom(pos=(1, 2))",
    "body.add_geom(size=(1, 2, 3, 4))",
    'body.add_geom(mass="heavy")',
    "body.add_geom(condim=3.5)",
    'body.add_joint(limited="yes")',
    "model.worldbody.add_motor()",
    "joint.add_geom()",
    "model.sensor.add_jointpos(joint=body.add_geom())",
    'joint.tpye = "hinge"',
]
MISTAKES_MODULE = ("import typed_mjcf as mjcf\n\nmodel = mjcf.RootElement()\n"
                   "body = model.worldbody.add_body()\njoint = body.add_joint()\n"
                   + "".join(line + "\n" for line in MISTAKES))
MISTAKES_FIRST_LINE = 6


# A module with two mistakes, checked with the others: it proves that the runs see the
# library's and MuJoCo's types (an untyped import would make everything Any, and clean).
CANARY = """import mujoco

import typed_mjcf as mjcf

mjcf.RootElement().worldbody.add_geom(type="capsul")
mujoco.mj_step(mjcf.RootElement().compile())
"""
CANARY_LINES = [5, 6]


@dataclass(frozen=True)
class UserCode:
    """A user's project in ``folder``: the README's blocks, ``examples/``, the negative cases
    of ``tests/typing/negative/``, the README table's mistakes and the canary, each a module;
    strict configurations and nothing else (``deprecated`` for mypy, which the README asks
    for, so that the generic ``add()``'s misspelt keywords are reported); the ``mujoco`` stubs
    in ``typings/``, as ``typed-mjcf mujoco-stubs`` puts them."""

    folder: Path
    origin: Mapping[Path, tuple[Path, int]]  # module -> (file shown, line offset)
    canary: Path
    mistakes: Path

    @property
    def files(self) -> list[Path]:
        return list(self.origin)

    def describe(self, diagnostic: Diagnostic) -> str:
        shown, offset = self.origin.get(diagnostic.file, (diagnostic.file, 0))
        name = shown.relative_to(ROOT) if shown.is_relative_to(ROOT) else shown
        first = diagnostic.message.splitlines()[0]
        return f"{name}:{diagnostic.line + offset}: [{diagnostic.code}] {first}"


def user_project(folder: Path) -> UserCode:
    origin: dict[Path, tuple[Path, int]] = {}

    def module(name: str, text: str, shown: Path | None = None, offset: int = 0) -> Path:
        path = (folder / name).resolve()
        path.write_text(text, encoding="utf-8")
        origin[path] = (shown or path, offset)
        return path

    for number, block in enumerate(BLOCKS):
        module(f"doc_block{number}.py", block.code, block.source, block.line - 1)
    module("reference_examples.py", reference_examples(), REFERENCE / "index.md")
    for path in [*EXAMPLES, *NEGATIVE_FILES]:
        module(path.name, path.read_text(encoding="utf-8"), path)
    canary, mistakes = module("canary.py", CANARY), module("mistakes.py", MISTAKES_MODULE)
    shutil.copytree(ROOT / "generated" / "mujoco-stubs", folder / "typings" / "mujoco")
    (folder / "mypy.ini").write_text("[mypy]\nstrict = True\nenable_error_code = deprecated\n"
                                     "mypy_path = typings\n", encoding="utf-8")
    (folder / "pyrightconfig.json").write_text('{"typeCheckingMode": "strict"}\n',
                                               encoding="utf-8")
    return UserCode(folder, origin, canary, mistakes)


def check_user_code(code: UserCode, python: str, cache: Path
                    ) -> dict[Checker, list[Diagnostic]]:
    """mypy and pyright on ``code`` with ``python``'s packages, side by side."""
    paths = [str(f) for f in code.files]
    return run_checkers({
        "mypy": [sys.executable, "-m", "mypy", "--config-file", str(code.folder / "mypy.ini"),
                 "--python-executable", python, "--cache-dir", str(cache), *MYPY_OUTPUT,
                 *paths],
        "pyright": [sys.executable, "-m", "pyright", "--outputjson",
                    "--project", str(code.folder / "pyrightconfig.json"),
                    "--pythonpath", python, *paths],
    }, code.folder)
