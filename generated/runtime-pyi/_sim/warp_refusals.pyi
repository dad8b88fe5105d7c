# Generated from src/typed_mjcf/_sim/warp_refusals.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""MuJoCo Warp, imported on first use; what of a model it refuses, element by element.

No list of what Warp supports is kept here: ``mujoco_warp.put_model`` is asked. It stops at
its first refusal, so each refusal is traced differentially: the model is compiled again
without one element (or with one setting of a global element such as ``<option>`` or
``<flag>`` left to its default), and an element is blamed when that changes what Warp says
(and no element inside it is blamed). The blamed elements are then taken out and Warp asked
again, until it takes the model or nothing more can be traced (then the refusal is reported
for the model as a whole).
"""
from __future__ import annotations
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import TYPE_CHECKING, Final
from typed_mjcf._core.errors import MjcfError
from typed_mjcf._core.tree import Element, ModelBase
import mujoco
EXTRA: Final = "pip install 'typed-mjcf[warp]' (MuJoCo Warp, mujoco-warp==4.0.0)"

class WarpMissingError(MjcfError, ImportError):
    """MuJoCo Warp (the ``warp`` extra) is not installed."""

def warp_modules() -> tuple[ModuleType, ModuleType]:
    """``warp`` and ``mujoco_warp``, imported on first use (an optional extra)."""
    ...

@dataclass(frozen=True, slots=True)
class Refusal:
    """One thing MuJoCo Warp refuses: the element (``path``; ``attribute`` for a global
    setting, else ``None``) and what Warp said."""
    path: str
    attribute: str | None
    message: str
    def __str__(self) -> str: ...
Ask = Callable[["mujoco.MjModel"], "str | None"]

def warp_ask() -> Ask:
    """What the installed MuJoCo Warp says of a compiled model: its refusal, or ``None``."""
    ...

def warp_refusals(model: ModelBase, ask: Ask | None = None) -> list[Refusal]:
    """What of ``model`` MuJoCo Warp refuses (none: Warp takes it as it is). ``ask``: who
    is asked (the installed MuJoCo Warp by default)."""
    ...

def _elements(model: ModelBase) -> list[Element]: ...
