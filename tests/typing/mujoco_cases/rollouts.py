"""Batched rollouts with mujoco.rollout."""

from __future__ import annotations

from typing import assert_type

import mujoco
import numpy as np
import numpy.typing as npt
from mujoco import rollout

XML = """
<mujoco>
  <worldbody>
    <body><joint name="hinge" axis="0 1 0"/><geom type="capsule" size="0.05 0.2"/></body>
  </worldbody>
  <actuator><motor joint="hinge"/></actuator>
  <sensor><jointpos joint="hinge"/></sensor>
</mujoco>
"""


def run() -> tuple[int, ...]:
    m = mujoco.MjModel.from_xml_string(XML)
    d = mujoco.MjData(m)
    nstate = mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_FULLPHYSICS)
    initial = np.zeros((4, nstate))
    mujoco.mj_getState(m, d, initial[0], mujoco.mjtState.mjSTATE_FULLPHYSICS)
    control = np.random.default_rng(0).normal(size=(4, 50, m.nu))
    state, sensordata = rollout.rollout(m, d, initial, control)
    assert_type(state, npt.NDArray[np.float64])
    assert_type(sensordata, npt.NDArray[np.float64])
    with rollout.Rollout(nthread=2) as pool:
        assert_type(pool, rollout.Rollout)
        more, _ = pool.rollout([m] * 4, [mujoco.MjData(m) for _ in range(2)], initial,
                               control, nstep=50)
    assert more.shape == state.shape
    return state.shape


if __name__ == "__main__":
    print(run())
