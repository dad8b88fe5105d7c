"""``dm_control.mjcf.physics``: the names of typed-mjcf's ``typed_mjcf.physics`` (``Physics``,
``Binding``, ...), loaded when first used (it imports ``mujoco``)."""

from __future__ import annotations

import importlib
from typing import Final

# dm_control's private names that code built on it reads (dm_robotics.moma's types module
# annotates bindings as ``Union[mjcf.physics.Binding, mjcf.physics._EmptyBinding]``)
_DM_CONTROL_NAMES: Final = {"_EmptyBinding": "EmptyBinding"}


def __getattr__(name: str) -> object:
    module = importlib.import_module("typed_mjcf.physics")
    try:
        return getattr(module, _DM_CONTROL_NAMES.get(name, name))
    except AttributeError:
        raise AttributeError(f"module 'dm_control.mjcf.physics' (typed-mjcf) has no "
                             f"attribute {name!r}") from None
