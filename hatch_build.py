"""The compiled build: with ``TYPED_MJCF_COMPILE=1`` the wheel carries the runtime's hot modules
compiled by mypyc (pyproject's ``[tool.hatch.build.targets.wheel.hooks.custom]`` lists them),
beside their ``.py`` twins. Without it (the default, the sdist, an editable install) the hook
does nothing: the wheel is pure Python and installs without a compiler.

A hook of our own rather than hatch-mypyc (last released 2023): the hook asks for mypy and
setuptools only when compiling (``dependencies()``), so the default build needs nothing more
than hatchling, and the module list stays one pyproject key.
"""

from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any

from hatchling.builders.hooks.plugin.interface import BuildHookInterface

SWITCH = "TYPED_MJCF_COMPILE"


class CompileHook(BuildHookInterface):
    PLUGIN_NAME = "custom"

    def _compiling(self) -> bool:
        return self.target_name == "wheel" and os.environ.get(SWITCH, "") == "1"

    def dependencies(self) -> list[str]:
        return list(self.config.get("compile-requires", [])) if self._compiling() else []

    def initialize(self, version: str, build_data: dict[str, Any]) -> None:
        if version == "editable" or not self._compiling():
            return
        package = self.config.get("package", "src/typed_mjcf")
        modules: list[str] = list(self.config["modules"])
        root = Path(self.root)
        sources = [f"{package}/{module.replace('.', '/')}.py" for module in modules]
        missing = [source for source in sources if not (root / source).is_file()]
        if missing:  # a module moved (issue 37) but the list did not: say so, never skip it
            raise RuntimeError(f"{SWITCH}=1: no such module to compile: {', '.join(missing)} "
                               "(pyproject [tool.hatch.build.targets.wheel.hooks.custom] modules)")
        self._built = Path(tempfile.mkdtemp(prefix="typed-mjcf-mypyc-"))
        for built, inside in _compile(root, sources, self._built):
            build_data["force_include"][str(built)] = inside
        build_data["pure_python"] = False
        build_data["infer_tag"] = True

    def finalize(self, version: str, build_data: dict[str, Any], artifact_path: str) -> None:
        built = getattr(self, "_built", None)
        if built is not None:
            shutil.rmtree(built, ignore_errors=True)


# What the compiled copy of a module changes, in every compiled module: mypyc gives a class
# a fixed layout of its own and refuses a dataclass's ``slots=True``, which the pure build
# keeps (an attribute row without it carries a __dict__: 2.3 MB more at import).
_COMPILED_EDITS: tuple[tuple[str, str], ...] = (("@dataclass(slots=True, ", "@dataclass("),)


def _stage(root: Path, sources: list[str], stage: Path) -> Path:
    """A copy of ``src/`` (links followed) and pyproject.toml under ``stage``, with
    ``_COMPILED_EDITS`` made in the ``sources``: what mypyc compiles."""
    shutil.copytree(root / "src", stage / "src", symlinks=False, dirs_exist_ok=True)
    shutil.copy2(root / "pyproject.toml", stage / "pyproject.toml")
    for source in sources:
        path = stage / source
        text = path.read_text(encoding="utf-8")
        for old, new in _COMPILED_EDITS:
            text = text.replace(old, new)
        path.write_text(text, encoding="utf-8")
    return stage


def _compile(root: Path, sources: list[str], out: Path, *, separate: bool = False,
             ) -> list[tuple[Path, str]]:
    """mypyc over ``sources`` (paths under ``root``) into extension modules under ``out``:
    each built file and its path in the wheel. ``separate``: one C file per module (a
    rebuild compiles only what changed; the wheel compiles them as one)."""
    from mypyc.build import mypycify
    from setuptools import Distribution

    # mypy checks the modules as the repository's checks do (pyproject's [tool.mypy], strict):
    # numpy, lxml and types-lxml are build requirements when compiling, and MuJoCo's stubs
    # (which the editable install puts on the path) are given as a `mujoco` stub folder.
    stubs = out / "stubs"
    shutil.copytree(root / "generated" / "mujoco-stubs", stubs / "mujoco", dirs_exist_ok=True)
    stage = _stage(root, sources, out / "stage")
    here, mypypath = Path.cwd(), os.environ.get("MYPYPATH")
    os.chdir(stage)  # mypy names a module from its path: src/typed_mjcf/_core/tree.py -> typed_mjcf._core.tree
    os.environ["MYPYPATH"] = str(stubs)
    try:
        version = f"{sys.version_info.major}.{sys.version_info.minor}"  # the wheel's Python
        # One shared library for all (a group), named as a separate build: mypyc then
        # makes no whole-program assumption that a class's subclasses are all compiled (with
        # separate=False it checks `type(x) is ModelBase` where a generated subclass comes).
        groups = True if separate else [(sources, "typed_mjcf")]
        extensions = mypycify(["--python-version", version, *sources], opt_level="3",
                              separate=groups, target_dir=str(out / "c"))
        dist = Distribution({"name": "typed-mjcf", "ext_modules": extensions})
        command = dist.get_command_obj("build_ext")
        command.build_lib = str(out / "lib")
        command.build_temp = str(out / "temp")
        command.parallel = os.cpu_count() or 1
        dist.run_command("build_ext")
    finally:
        os.chdir(here)
        if mypypath is None:
            os.environ.pop("MYPYPATH", None)
        else:
            os.environ["MYPYPATH"] = mypypath
    lib = out / "lib"
    built = sorted(path for path in lib.rglob("*") if path.is_file())
    if not built:
        raise RuntimeError(f"{SWITCH}=1: mypyc built nothing (Python {sys.version})")
    return [(path, path.relative_to(lib).as_posix()) for path in built]
