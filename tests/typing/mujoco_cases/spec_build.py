"""Build a model with MjSpec, compile it, write it out and read it back."""

from __future__ import annotations

from typing import assert_type

import mujoco
import numpy as np
import numpy.typing as npt


def build_arm() -> mujoco.MjSpec:
    spec = mujoco.MjSpec()
    spec.modelname = "arm"
    spec.option.timestep = 0.005
    spec.worldbody.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[1, 1, 0.1])
    upper = spec.worldbody.add_body(name="upper", pos=[0, 0, 1])
    assert_type(upper, mujoco.MjsBody)
    shoulder = upper.add_joint(name="shoulder", type=mujoco.mjtJoint.mjJNT_HINGE,
                               axis=[0, 1, 0])
    assert_type(shoulder, mujoco.MjsJoint)
    upper.add_geom(type=mujoco.mjtGeom.mjGEOM_CAPSULE, fromto=[0, 0, 0, 0, 0, -0.4],
                   size=[0.04, 0, 0], rgba=[1, 0, 0, 1])
    fore = upper.add_body(name="fore", pos=[0, 0, -0.4])
    fore.add_joint(name="elbow", axis=[0, 1, 0], range=[-1.5, 1.5])
    geom = fore.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.05, 0, 0])
    geom.mass = 0.5
    site = fore.add_site(name="tip", pos=[0, 0, -0.3])
    motor = spec.add_actuator(name="motor", target="shoulder",
                              trntype=mujoco.mjtTrn.mjTRN_JOINT)
    motor.gear[0] = 2.0
    spec.add_sensor(name="tip_pos", type=mujoco.mjtSensor.mjSENS_FRAMEPOS,
                    objtype=mujoco.mjtObj.mjOBJ_SITE, objname=site.name)
    spec.add_key(name="home", qpos=[0.3, -0.2])
    return spec


def roundtrip() -> int:
    spec = build_arm()
    model = spec.compile()
    assert_type(model, mujoco.MjModel)
    assert (model.nbody, model.njnt, model.nu) == (3, 2, 1)
    xml = spec.to_xml()
    assert_type(xml, str)
    again = mujoco.MjSpec.from_string(xml, assets={"unused.txt": b"0"})
    body = again.body("fore")
    assert body is not None
    assert_type(body.pos, npt.NDArray[np.float64])
    body.pos = [0, 0, -0.5]
    for joint in again.joints:
        joint.armature = 0.1
        joint.damping = [0.1, 0.0, 0.0]  # 4.0: a polynomial, not a scalar
    data = mujoco.MjData(again.compile())
    mujoco.mj_step(data.model, data)
    bound = model.bind(spec.joint("elbow"))
    assert_type(bound.qposadr, npt.NDArray[np.int32])
    world = again.worldbody
    assert world.name == "world"
    copied = spec.copy()
    copied.delete(copied.body("fore"))
    return copied.compile().nbody


if __name__ == "__main__":
    print(roundtrip())
