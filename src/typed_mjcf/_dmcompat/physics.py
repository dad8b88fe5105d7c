"""``dm_control.mjcf.physics``: the names of typed-mjcf's ``typed_mjcf.physics`` (``Physics``,
``Binding``, ...), loaded when first used (it imports ``mujoco``)."""

from __future__ import annotations

import importlib


def __getattr__(name: str) -> object:
    module = importlib.import_module("typed_mjcf.physics")
    try:
        return getattr(module, name)
    except AttributeError:
        raise AttributeError(f"module 'dm_control.mjcf.physics' (typed-mjcf) has no "
                             f"attribute {name!r}") from None
