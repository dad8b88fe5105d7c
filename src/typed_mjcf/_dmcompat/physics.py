"""``dm_control.mjcf.physics``: its names are typed_mjcf's (``Physics`` and ``Binding``
once typed-mjcf has them)."""

from __future__ import annotations


def __getattr__(name: str) -> object:
    import typed_mjcf

    try:
        return getattr(typed_mjcf, name)
    except AttributeError:
        raise AttributeError(f"module 'dm_control.mjcf.physics' (typed-mjcf) has no "
                             f"attribute {name!r}") from None
