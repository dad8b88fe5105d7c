# Generated from src/typed_mjcf/warp/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Many worlds on MuJoCo Warp (the optional extra ``warp``: ``pip install typed-mjcf[warp]``).

:func:`put_worlds` makes a batched Warp model and data of ``nworld`` worlds from a typed model
and a draw (per-world values, as :mod:`typed_mjcf.parametric` takes them): the values go
into per-world copies of the compiled model (``mj_setConst`` deriving what depends on them),
and each Warp model field that then differs between worlds is batched
(``mujoco_warp.put_model(..., batch_sizes=...)``). ``worlds.bind(element)`` gives the arrays
``Physics.bind`` gives, by the same names (the same generated table), with a leading axis of
worlds::

    worlds = put_worlds(model, [(ball, "friction", frictions)], device="cpu")
    worlds.step(100)
    worlds.bind(ball).xpos        # shape (nworld, 3)
    worlds.bind(ball).friction    # shape (nworld, 3)

:func:`warp_refusals` (and ``typed-mjcf check --backend warp``) says what of a model the
installed MuJoCo Warp refuses, element by element.
"""
from __future__ import annotations
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Protocol, cast
import mujoco
from typed_mjcf._core.errors import BindingError, InvalidValueError, UnbatchedWarning
from typed_mjcf._generated.bindings import Bind
from typed_mjcf._sim.parametric import Draw, world_models
from typed_mjcf._sim.warp_refusals import Refusal, WarpMissingError, warp_modules, warp_refusals
from typed_mjcf.physics import Physics
from typed_mjcf.types import MuJoCoArray
from typed_mjcf._base import ModelRoot
__all__ = ["Refusal", "UnbatchedWarning", "WarpMissingError", "Worlds", "put_worlds",
           "warp_modules", "warp_refusals"]

class _WarpArray(Protocol):
    shape: tuple[int, ...]
    device: object
    dtype: object
    def numpy(self) -> MuJoCoArray: ...
    def assign(self, src: MuJoCoArray) -> None: ...

class Worlds(Bind):
    """A batched MuJoCo Warp model and data of ``nworld`` worlds, and the typed model and
    compiled ``MjModel`` they come from; :meth:`bind` as ``Physics.bind``, per world."""
    nworld: int
    warp_model: object
    warp_data: object
    batched: tuple[str, ...]
    device: str | None
    _physics: Physics
    def __init__(self, physics: Physics, warp_model: object, warp_data: object, nworld: int,
                 batched: Sequence[str], device: str | None = None) -> None: ...
    @property
    def model(self) -> mujoco.MjModel:
        """The compiled model every world was made from (world values not written)."""
        ...
    @property
    def data(self) -> mujoco.MjData: ...
    @property
    def is_dirty(self) -> bool: ...
    def mark_as_dirty(self) -> None:
        """Warp's data is derived by ``step``: nothing to mark."""
        ...
    def forward(self) -> None:
        """Run ``mujoco_warp.forward`` on every world."""
        ...
    def step(self, nstep: int = 1) -> None:
        """Step every world ``nstep`` times."""
        ...
    def write(self, draw: Draw) -> None:
        """Write a new draw's values into these worlds (an episode's randomisation), without
        putting the model again: every field the new values change must be one these worlds
        batch (:attr:`batched`; else put_worlds again with such a draw)."""
        ...
    def arrays(self, struct: str, field: str) -> tuple[_WarpArray, tuple[int, ...]]:
        """The Warp array of ``struct.field`` and its CPU array's shape."""
        ...

def put_worlds(model: ModelRoot | Physics, draw: Draw = (), *, nworld: int | None = None,
               device: str | None = None) -> Worlds:
    """A batched MuJoCo Warp model and data of ``nworld`` worlds of ``model`` (a typed model,
    or a ``Physics`` compiled from one), each world with its values of ``draw`` (which sets
    ``nworld`` when given); ``device``: Warp's (``"cpu"``, ``"cuda:0"``; Warp's default if
    ``None``)."""
    ...
