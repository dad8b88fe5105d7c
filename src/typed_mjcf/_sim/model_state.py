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

import functools

import mujoco
import numpy as np

# two models of different sizes: the header's rule is learnt from one, checked on the other
_PROBES = ("<mujoco/>", '<mujoco><worldbody><geom size="1"/></worldbody></mujoco>')


def _mjb(model: mujoco.MjModel, prefix: bytes) -> bytearray:
    size = mujoco.mj_sizeModel(model)
    buffer = bytearray(len(prefix) + size)
    buffer[: len(prefix)] = prefix
    mujoco.mj_saveModel(model, None, np.frombuffer(buffer, np.uint8)[len(prefix):])
    return buffer


def _header(size: int, template: bytes, template_size: int) -> bytes:
    """``template`` (the header of a model of ``template_size`` bytes) for ``size`` bytes."""
    return template.replace(template_size.to_bytes(8, "little"), size.to_bytes(8, "little"))


@functools.cache
def _template() -> tuple[bytes, int] | None:
    """The header of a small model's state and that model's size, if the rule holds."""
    first, second = (mujoco.MjModel.from_xml_string(xml) for xml in _PROBES)
    size = mujoco.mj_sizeModel(first)
    state = first.__getstate__()
    template = state[: len(state) - size]
    if (state[len(template):] != bytes(_mjb(first, b""))
            or size.to_bytes(8, "little") not in template):
        return None
    other = mujoco.mj_sizeModel(second)
    if bytes(_mjb(second, _header(other, template, size))) != second.__getstate__():
        return None
    return template, size


def model_state(model: mujoco.MjModel) -> bytes:
    """``model.__getstate__()``, the same bytes, written with ``mj_saveModel``."""
    found = _template()
    if found is None:
        return model.__getstate__()
    template, template_size = found
    return bytes(_mjb(model, _header(mujoco.mj_sizeModel(model), template, template_size)))
