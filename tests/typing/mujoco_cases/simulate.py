"""Compile a model with an in-memory asset, simulate it, read results by name."""

from __future__ import annotations

from typing import assert_type

import mujoco
import numpy as np
import numpy.typing as npt

TETRAHEDRON = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
XML = """
<mujoco model="drop">
  <asset><mesh name="tet" file="tet.obj"/></asset>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 1">
      <freejoint name="free"/>
      <geom name="ball_geom" type="sphere" size="0.1" mass="1"/>
    </body>
    <body name="arm" pos="0.5 0 0.5">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <geom type="mesh" mesh="tet"/>
      <site name="tip" pos="0 0 0.2"/>
    </body>
  </worldbody>
  <actuator><motor name="motor" joint="hinge"/></actuator>
  <sensor><jointpos name="angle" joint="hinge"/></sensor>
  <keyframe><key name="home" qpos="0 0 1 1 0 0 0 0.5"/></keyframe>
</mujoco>
"""


def simulate() -> tuple[float, int]:
    m = mujoco.MjModel.from_xml_string(XML, assets={"tet.obj": TETRAHEDRON})
    d = mujoco.MjData(m)
    assert_type(m.nq, int)
    assert_type(m.opt.timestep, float)
    m.opt.timestep = 0.002
    m.opt.gravity = (0.0, 0.0, -9.81)
    mujoco.mj_resetDataKeyframe(m, d, 0)
    d.ctrl[:] = 0.1
    for _ in range(100):
        mujoco.mj_step(m, d)
    mujoco.mj_step(m, d, nstep=10)
    mujoco.mj_forward(m, d)

    # named access: model and data views
    ball = d.body("ball")
    assert_type(ball.xpos, npt.NDArray[np.float64])
    height = float(ball.xpos[2])
    qposadr = m.joint("hinge").qposadr
    assert_type(qposadr, npt.NDArray[np.int32])
    angle = float(d.qpos[int(qposadr[0])])
    assert abs(angle - float(d.sensor("angle").data[0])) < 1e-9
    assert m.body("ball").id == 1
    assert_type(d.joint("free").qvel, npt.NDArray[np.float64])
    tip: npt.NDArray[np.float64] = d.site("tip").xpos
    assert tip.shape == (3,)
    assert d.geom("ball_geom").xmat.shape == (9,)
    assert m.actuator("motor").gear[0] == 1.0

    # ids and names through mjtObj
    body_id = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "arm")
    assert_type(body_id, int)
    assert mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, body_id) == "arm"
    joint_id = mujoco.mj_name2id(m, int(mujoco.mjtObj.mjOBJ_JOINT), "hinge")
    assert m.jnt_type[joint_id] == mujoco.mjtJoint.mjJNT_HINGE
    assert_type(mujoco.mjtGeom.mjGEOM_SPHERE.value, int)
    assert mujoco.mjtGeom.mjGEOM_SPHERE.name == "mjGEOM_SPHERE"

    # functions writing into arrays, and arrays read from the structs
    jacp = np.zeros((3, m.nv))
    jacr = np.zeros((3, m.nv))
    mujoco.mj_jacBody(m, d, jacp, jacr, body_id)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, d.xmat[body_id])
    state = np.empty(mujoco.mj_stateSize(m, mujoco.mjtState.mjSTATE_FULLPHYSICS))
    mujoco.mj_getState(m, d, state, mujoco.mjtState.mjSTATE_FULLPHYSICS)
    for contact in d.contact:
        assert_type(contact.dist, float)
        assert_type(contact.geom, npt.NDArray[np.int32])
    total: float = mujoco.mj_getTotalmass(m)
    assert int(mujoco.mjtGeom.mjNGEOMTYPES) > 0 and mujoco.mjMINVAL > 0 and mujoco.mjNGROUP == 6
    assert_type(mujoco.__version__, str)
    copy = mujoco.MjData(m)
    mujoco.mj_copyData(copy, m, d)
    assert_type(d.time, float)
    return height + total * 0, d.ncon


if __name__ == "__main__":
    print(simulate())
