"""A physics made from a model builds its named indexers (``physics.named``) when they are
first used, not at every load (a tenth to a fifth of Physics.from_mjcf_model's time)."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf import physics as physics_module
from typed_mjcf._sim.named import make_axes


def test_named_indexers_are_made_on_first_use(monkeypatch: pytest.MonkeyPatch) -> None:
    model = mjcf.RootElement(model="m")
    model.worldbody.add_body(name="b").add_joint(name="hinge", axis=(0, 1, 0))
    model.worldbody.body[0].add_geom(size=(0.1,))
    made: list[object] = []
    real = make_axes

    def counting(compiled: mujoco.MjModel) -> object:
        made.append(compiled)
        return real(compiled)

    monkeypatch.setattr(physics_module, "make_axes", counting)
    physics = mjcf.Physics.from_mjcf_model(model)
    assert made == []
    physics.named.data.qpos["hinge"] = 0.5
    np.testing.assert_array_equal(physics.data.qpos, [0.5])
    assert physics.named.model.jnt_axis["hinge"].tolist() == [0, 1, 0]
    assert len(made) == 1
    copy = physics.copy()
    assert copy.named.data.qpos["hinge"] == 0.5 and len(made) == 2
