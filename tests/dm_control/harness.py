"""Run dm_control.mjcf's own unit tests against typed_mjcf.

The tests are read from the installed dm_control package at test time (never copied here)
and executed with their ``dm_control.mjcf`` imports redirected to ``typed_mjcf``: ``from
dm_control import mjcf`` and ``from dm_control.mjcf import parser`` (and ``element``,
``namescope``, ...) all give ``typed_mjcf``. Everything else they import (absl, numpy,
``dm_control.mujoco``) is the real thing.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
import unittest
import unittest.mock
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import typed_mjcf

# dm_control.mjcf's test modules that exercise its public behaviour.
MODULES = ("element_test", "copier_test", "export_with_assets_test",
           "export_with_assets_as_zip_test", "traversal_utils_test", "xml_validation_test",
           "physics_test")
# The submodules those tests import by name; each is typed_mjcf.
SUBMODULES = ("attribute", "base", "constants", "copier", "debugging", "element",
              "export_with_assets", "export_with_assets_as_zip", "namescope", "parser",
              "physics", "schema", "traversal_utils")


def mjcf_folder() -> Path | None:
    """Where the installed dm_control.mjcf is (its tests and test assets), if installed."""
    spec = importlib.util.find_spec("dm_control")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations))) / "mjcf"


@contextmanager
def redirected() -> Iterator[None]:
    """``dm_control.mjcf`` (and its submodules) is typed_mjcf while the block runs."""
    dm_control = importlib.import_module("dm_control")
    package = _forwarding("dm_control.mjcf")
    shims: dict[str, types.ModuleType] = {"dm_control.mjcf": package}
    if importlib.util.find_spec("mock") is None:  # the backport physics_test imports
        shims["mock"] = unittest.mock
    for name in SUBMODULES:
        own = getattr(typed_mjcf, name, None)
        if isinstance(own, types.ModuleType):  # typed_mjcf has the module (physics)
            shims[f"dm_control.mjcf.{name}"] = own
            continue
        shims[f"dm_control.mjcf.{name}"] = submodule = _forwarding(f"dm_control.mjcf.{name}")
        if not hasattr(typed_mjcf, name):  # mjcf.export_with_assets is the function
            setattr(package, name, submodule)
    saved = {name: sys.modules.get(name) for name in shims}
    had_attribute = hasattr(dm_control, "mjcf")
    saved_attribute = getattr(dm_control, "mjcf", None)
    try:
        sys.modules.update(shims)
        setattr(dm_control, "mjcf", package)
        yield
    finally:
        for name, module in saved.items():
            if module is None:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = module
        if had_attribute:
            setattr(dm_control, "mjcf", saved_attribute)
        else:
            delattr(dm_control, "mjcf")


def _forwarding(name: str) -> types.ModuleType:
    """A module named ``name`` whose every attribute is typed_mjcf's."""
    module = types.ModuleType(name)

    def forward(attribute: str) -> object:
        return getattr(typed_mjcf, attribute)

    module.__getattr__ = forward  # type: ignore[method-assign]
    return module


def load(module_name: str) -> types.ModuleType:
    """One of dm_control.mjcf's test modules, imported against typed_mjcf. Its
    ``__file__`` stays in dm_control's folder, so its test assets are found."""
    folder = mjcf_folder()
    assert folder is not None
    path = folder / f"{module_name}.py"
    module = types.ModuleType(f"dm_control_mjcf_tests.{module_name}")
    module.__file__ = str(path)
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
