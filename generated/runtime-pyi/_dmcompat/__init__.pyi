# Generated from src/typed_mjcf/_dmcompat/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""dm_control's ``mjcf`` package, served by typed-mjcf: ``install_as_dm_control_mjcf()``.

After ``install()``, ``from dm_control import mjcf`` and ``import dm_control.mjcf.element``
(and its other submodules) give these modules, whose names are typed-mjcf's objects, and
the preset ``Behaviour.dm_control()`` gives dm_control's observable behaviour (docs/guide/
dm-control.md); ``behaviours`` lends the tree what only dm_control does. Nothing of
dm_control.mjcf itself is imported.
"""
from __future__ import annotations
import types
from collections.abc import Generator
from contextlib import contextmanager
from typing import Final
from typed_mjcf._dmcompat import (
    attribute,
    base,
    constants,
    copier,
    debugging,
    element,
    export_with_assets,
    export_with_assets_as_zip,
    mjcf,
    namescope,
    parser,
    physics,
    skin,
    traversal_utils,
)
from typed_mjcf._dmcompat import (
    behaviours as behaviours,  # lends the tree what only dm_control does
)
PACKAGE: Final = "dm_control.mjcf"
SUBMODULES: Final[dict[str, types.ModuleType]] = ...

def modules() -> dict[str, types.ModuleType]:
    """What ``sys.modules`` gets: ``dm_control.mjcf`` and each submodule."""
    ...

def install() -> None:
    """Make ``dm_control.mjcf`` (and its submodules) typed-mjcf's, for this process, and
    select dm_control's behaviours (``Behaviour.dm_control()``). Call it before anything
    imports ``dm_control.mjcf``: a module that imported dm_control's own keeps it."""
    ...

@contextmanager
def installed() -> Generator[None]:
    """``install()`` while the block runs; everything as it was afterwards (for tests that
    run dm_control's code beside code that uses dm_control's own mjcf)."""
    ...
