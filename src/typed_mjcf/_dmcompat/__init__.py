"""dm_control's ``mjcf`` package, served by typed-mjcf: ``install_as_dm_control_mjcf()``.

After ``install()``, ``from dm_control import mjcf`` and ``import dm_control.mjcf.element``
(and its other submodules) give these modules, whose names are typed-mjcf's objects, and
the preset ``Behaviour.dm_control()`` gives dm_control's observable behaviour (docs/guide/
dm-control.md); ``behaviours`` lends the tree what only dm_control does. Nothing of
dm_control.mjcf itself is imported.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
from collections.abc import Generator
from contextlib import contextmanager
from typing import Final

from typed_mjcf._core.behaviour import Behaviour, set_behaviour
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
# dm_control.mjcf's submodules, as served here
SUBMODULES: Final[dict[str, types.ModuleType]] = {
    "attribute": attribute, "base": base, "constants": constants, "copier": copier,
    "debugging": debugging, "element": element, "export_with_assets": export_with_assets,
    "export_with_assets_as_zip": export_with_assets_as_zip, "namescope": namescope,
    "parser": parser, "physics": physics, "skin": skin, "traversal_utils": traversal_utils,
}


def modules() -> dict[str, types.ModuleType]:
    """What ``sys.modules`` gets: ``dm_control.mjcf`` and each submodule."""
    found = {PACKAGE: mjcf}
    found.update((f"{PACKAGE}.{name}", module) for name, module in SUBMODULES.items())
    return found


def install() -> None:
    """Make ``dm_control.mjcf`` (and its submodules) typed-mjcf's, for this process, and
    select dm_control's behaviours (``Behaviour.dm_control()``). Call it before anything
    imports ``dm_control.mjcf``: a module that imported dm_control's own keeps it."""
    sys.modules.update(modules())
    parent = sys.modules.get("dm_control")
    if parent is None:
        parent = _dm_control_package()
        sys.modules["dm_control"] = parent
    setattr(parent, "mjcf", mjcf)
    set_behaviour(Behaviour.dm_control())
    debugging.arm()  # --pymjcf_debug, read when the first element is made


@contextmanager
def installed() -> Generator[None]:
    """``install()`` while the block runs; everything as it was afterwards (for tests that
    run dm_control's code beside code that uses dm_control's own mjcf)."""
    saved = {name: sys.modules.get(name) for name in modules()}
    saved_parent = sys.modules.get("dm_control")
    saved_attribute = getattr(saved_parent, "mjcf", None)
    previous = set_behaviour(Behaviour.dm_control())
    try:
        install()
        yield
    finally:
        set_behaviour(previous)
        for name, module in saved.items():
            if module is None:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = module
        parent = sys.modules.get("dm_control")
        if saved_parent is None:
            sys.modules.pop("dm_control", None)
        elif parent is not None:
            if saved_attribute is None:
                if hasattr(parent, "mjcf"):
                    delattr(parent, "mjcf")
            else:
                setattr(parent, "mjcf", saved_attribute)


def _dm_control_package() -> types.ModuleType:
    """The installed ``dm_control`` package, or an empty one when it is not installed
    (code that only uses ``dm_control.mjcf`` then runs without it)."""
    if importlib.util.find_spec("dm_control") is not None:
        return importlib.import_module("dm_control")
    package = types.ModuleType("dm_control")
    package.__path__ = []
    return package
