"""A pytest plugin that makes typed-mjcf follow another covered release's grammar than the
installed MuJoCo's, so the release tests run for every release on the newest MuJoCo:

    TYPED_MJCF_TEST_RELEASE=3.17.0 pytest -p tests.runtime.release_driver tests/runtime/...

The runtime reads the release from the ``*.dist-info`` beside the ``mujoco`` module
(``typed_mjcf._releases.gating.installed_mujoco``); while typed-mjcf is imported, that lookup is
pointed at a folder holding only ``mujoco-<release>.dist-info``. MuJoCo itself stays the
installed one (tests that compare with it check ``mujoco.__version__``).
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.util
import os
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

RELEASE_VARIABLE = "TYPED_MJCF_TEST_RELEASE"


def pretend(release: str) -> None:
    """Import typed-mjcf as if MuJoCo ``release`` were installed."""
    assert "typed_mjcf" not in sys.modules, "typed-mjcf is imported already: its release is set"
    folder = Path(tempfile.mkdtemp(prefix="typed-mjcf-release-"))
    (folder / f"mujoco-{release}.dist-info").mkdir()
    origin = str(folder / "mujoco" / "__init__.py")
    real: Callable[..., importlib.machinery.ModuleSpec | None] = importlib.util.find_spec

    def find_spec(name: str, package: str | None = None) -> importlib.machinery.ModuleSpec | None:
        if name == "mujoco":
            return importlib.machinery.ModuleSpec("mujoco", None, origin=origin)
        return real(name, package)

    setattr(importlib.util, "find_spec", find_spec)  # read once: at import
    try:
        importlib.import_module("typed_mjcf._releases.gating")  # reads the release
    finally:
        setattr(importlib.util, "find_spec", real)


_RELEASE = os.environ.get(RELEASE_VARIABLE)
if _RELEASE:
    pretend(_RELEASE)
