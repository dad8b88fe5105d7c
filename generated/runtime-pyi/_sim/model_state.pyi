# Generated from src/typed_mjcf/_sim/model_state.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""A compiled model's pickled state (what ``mujoco.MjModel.__setstate__`` reads), written fast.

``Physics`` keeps its model as a :class:`typed_mjcf.physics.Model`, a subclass of
``mujoco.MjModel``; pybind11 makes an instance of a subclass only through ``__setstate__``, so
each compiled model is copied once through its state. ``MjModel.__getstate__`` takes about
three times as long as writing the same bytes with MuJoCo's own ``mj_saveModel`` (0.3 s
against 0.1 s for a model with 50 MB of textures, as dm_control's maze arenas have; reading
them back, ``__setstate__``, takes another 0.3 s): the state is a short header followed by
exactly what ``mj_saveModel`` writes. The header's rule is learnt from two small models of
the installed MuJoCo and checked against ``__getstate__``; where it does not hold (another
release's format), ``__getstate__`` is used.
"""
from __future__ import annotations
import mujoco

def model_state(model: mujoco.MjModel) -> bytes:
    """``model.__getstate__()``, the same bytes, written with ``mj_saveModel``."""
    ...
