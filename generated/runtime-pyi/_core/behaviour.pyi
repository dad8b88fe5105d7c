# Generated from src/typed_mjcf/_core/behaviour.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The one switch between the typed API's choices and dm_control's observable behaviour.

``install_as_dm_control_mjcf()`` turns it on (README "Coming from dm_control.mjcf" lists
what it changes); every module that behaves differently reads :func:`dm_control_behaviour`.
Off, the typed API keeps its own choices: read-only arrays, once-only children created on
first access, readable file names, unnamed elements without identifiers.
"""
from __future__ import annotations
from typing import Final
_STATE: Final[list[bool]] = ...

def dm_control_behaviour() -> bool:
    """Whether dm_control's behaviour is on (see the module docstring)."""
    ...

def set_dm_control_behaviour(on: bool) -> bool:
    """Turn dm_control's behaviour on or off; return the previous setting."""
    ...
STATE: Final = _STATE

def dm_control_namespace(namespace: str) -> str:
    """The name of ``namespace`` in dm_control's schema."""
    ...
