"""Run dm_control.mjcf's own unit tests against typed_mjcf.

The tests are read from the installed dm_control package at test time (never copied here)
and executed with their ``dm_control.mjcf`` imports redirected to ``typed_mjcf``: ``from
dm_control import mjcf`` and ``from dm_control.mjcf import parser`` (and ``element``,
``namescope``, ...) all give ``typed_mjcf``. Everything else they import (absl, numpy,
``dm_control.mujoco``) is the real thing.
"""

from __future__ import annotations

import importlib.util
import sys
import types
import unittest
import unittest.mock
from collections.abc import Iterator
from contextlib import contextmanager
from functools import cache
from pathlib import Path

from typed_mjcf._dmcompat import installed

# dm_control.mjcf's test modules that exercise its public behaviour.
MODULES = ("element_test", "copier_test", "export_with_assets_test",
           "export_with_assets_as_zip_test", "traversal_utils_test", "xml_validation_test",
           "debugging_test", "skin_test", "physics_test")
# dm_control.mjcf's modules that hold test code its tests import (loaded from its folder).
HELPERS = ("code_for_debugging_test",)


def mjcf_folder() -> Path | None:
    """Where the installed dm_control.mjcf is (its tests and test assets), if installed."""
    spec = importlib.util.find_spec("dm_control")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations))) / "mjcf"


@contextmanager
def redirected() -> Iterator[None]:
    """``dm_control.mjcf`` (and its submodules) is typed_mjcf while the block runs, as
    ``typed_mjcf.install_as_dm_control_mjcf()`` makes it; dm_control's test helper modules
    (``code_for_debugging_test``) are loaded from dm_control's folder against it."""
    with installed():
        helpers = {f"dm_control.mjcf.{name}": _helper(name) for name in HELPERS}
        if importlib.util.find_spec("mock") is None:  # the backport physics_test imports
            helpers["mock"] = unittest.mock
        saved = {name: sys.modules.get(name) for name in helpers}
        sys.modules.update(helpers)
        package = sys.modules["dm_control.mjcf"]
        for name in HELPERS:  # for `from dm_control.mjcf import <helper>`
            setattr(package, name, helpers[f"dm_control.mjcf.{name}"])
        try:
            yield
        finally:
            for name in HELPERS:
                delattr(package, name)
            for name, module in saved.items():
                if module is None:
                    sys.modules.pop(name, None)
                else:
                    sys.modules[name] = module


@cache
def _helper(name: str) -> types.ModuleType:
    """One of dm_control.mjcf's test helper modules, run against typed_mjcf (once)."""
    folder = mjcf_folder()
    assert folder is not None
    path = folder / f"{name}.py"
    module = types.ModuleType(f"dm_control.mjcf.{name}")
    module.__file__ = str(path)
    code = compile(path.read_text(encoding="utf-8"), str(path), "exec")
    with installed():
        exec(code, module.__dict__)  # noqa: S102 - dm_control's own test code, as shipped
    return module


def load(module_name: str) -> types.ModuleType:
    """One of dm_control.mjcf's test modules, imported against typed_mjcf. Its
    ``__file__`` stays in dm_control's folder, so its test assets are found."""
    folder = mjcf_folder()
    assert folder is not None
    path = folder / f"{module_name}.py"
    module = types.ModuleType(f"dm_control_mjcf_tests.{module_name}")
    module.__file__ = str(path)
    sys.modules[module.__name__] = module  # its tests look themselves up there
    code = compile(path.read_text(encoding="utf-8"), str(path), "exec")
    with redirected():
        exec(code, module.__dict__)  # noqa: S102 - dm_control's own test code, as shipped
    return module


def test_ids(module: types.ModuleType) -> list[str]:
    """The ids (``Class.method``) of the tests in a loaded module."""
    suite = unittest.defaultTestLoader.loadTestsFromModule(module)
    return sorted(_ids(suite))


def _ids(suite: unittest.TestSuite) -> Iterator[str]:
    for test in suite:
        if isinstance(test, unittest.TestSuite):
            yield from _ids(test)
        else:
            # absl's parameterized tests append their parameters after a space
            yield test.id().split(" ")[0].removeprefix(f"{test.__class__.__module__}.")


def run(module: types.ModuleType, test_id: str) -> unittest.TestResult:
    """Run one test (``Class.method``) of a loaded module, imports redirected."""
    setup = getattr(module, "setUpModule", None)
    result = unittest.TestResult()
    with redirected():
        if callable(setup):
            setup()
        suite = unittest.defaultTestLoader.loadTestsFromName(test_id, module)
        suite.run(result)
    return result
