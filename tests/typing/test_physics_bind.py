"""Positive typing cases for ``mjcf.Physics``: ``bind`` is typed per kind of element.

Checked statically by ``test_typecheck.py`` (mypy strict and pyright strict, no error) and
run by pytest: each ``assert_type`` states what the checkers infer, and the values are read
and written at run time too.
"""

from __future__ import annotations

from typing import assert_type

import mujoco
import numpy as np

import typed_mjcf as mjcf
from typed_mjcf.physics import (
    ActuatorBinding,
    Binding,
    BodyBinding,
    CameraBinding,
    GeomBinding,
    JointBinding,
    LightBinding,
    SensorBinding,
    SiteBinding,
    TendonBinding,
)
from typed_mjcf.types import Array


def scene() -> tuple[mjcf.RootElement, mjcf.Physics]:
    model = mjcf.RootElement(model="arm")
    model.worldbody.add_light(name="sun", pos=(0, 0, 3))
    model.worldbody.add_camera(name="overhead", pos=(0, 0, 3))
    arm = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1))
    arm.add_joint(name="shoulder", axis=(0, 1, 0))
    arm.add_geom(name="upper", type="capsule", size=(0.04, 0.2))
    arm.add_site(name="tip", pos=(0, 0, -0.2))
    model.tendon.add_fixed(name="t").add_joint(joint="shoulder", coef=1.0)
    model.actuator.add_motor(name="m", joint="shoulder")
    model.sensor.add_jointpos(name="angle", joint="shoulder")
    return model, mjcf.Physics.from_mjcf_model(model)


def test_bind_is_typed_per_kind() -> None:
    model, physics = scene()
    assert_type(physics, mjcf.Physics)
    assert_type(physics.model, mjcf.physics.Model)
    assert isinstance(physics.model, mujoco.MjModel)
    assert isinstance(physics.data, mujoco.MjData)

    joint = model.find("joint", "shoulder")
    assert joint is not None
    assert_type(physics.bind(joint), JointBinding)
    assert_type(physics.bind(joint).qpos, Array[np.float64])
    assert_type(physics.bind(joint).range, Array[np.float64])
    assert_type(physics.bind(joint).damping, Array[np.float64])
    physics.bind(joint).qpos = 0.5
    assert physics.data.qpos[0] == 0.5

    body = model.find("body", "upper_arm")
    assert body is not None
    assert_type(physics.bind(body), BodyBinding)
    assert_type(physics.bind(body).xpos, Array[np.float64])
    assert_type(physics.bind(model.worldbody), BodyBinding)

    geom = model.find("geom", "upper")
    assert geom is not None
    assert_type(physics.bind(geom), GeomBinding)
    assert_type(physics.bind(geom).rgba, Array[np.float32])
    assert_type(physics.bind(geom).contype, Array[np.int32])

    site = model.find("site", "tip")
    assert site is not None
    assert_type(physics.bind(site), SiteBinding)
    assert_type(physics.bind(site).xpos, Array[np.float64])

    motor = model.find("actuator", "m")
    assert motor is not None
    assert_type(physics.bind(motor), ActuatorBinding)
    assert_type(physics.bind(motor).ctrl, Array[np.float64])
    assert_type(physics.bind(motor).gear, Array[np.float64])

    sensor = model.find("sensor", "angle")
    assert sensor is not None
    assert_type(physics.bind(sensor), SensorBinding)
    assert_type(physics.bind(sensor).sensordata, Array[np.float64])

    tendon = model.find("tendon", "t")
    assert tendon is not None
    assert_type(physics.bind(tendon), TendonBinding)
    assert_type(physics.bind(tendon).length, Array[np.float64])

    camera = model.find("camera", "overhead")
    assert camera is not None
    assert_type(physics.bind(camera), CameraBinding)
    assert_type(physics.bind(camera).fovy, Array[np.float64])

    light = model.find("light", "sun")
    assert light is not None
    assert_type(physics.bind(light), LightBinding)
    assert_type(physics.bind(light).pos, Array[np.float64])
    physics.forward()
    assert physics.bind(sensor).sensordata[0] == 0.5


def test_bind_many_elements_of_one_kind() -> None:
    model, physics = scene()
    joints = physics.bind(model.find_all("joint"))
    assert_type(joints, JointBinding)
    assert_type(joints.qpos, Array[np.float64])
    joints.qpos += 0.25
    assert physics.data.qpos[0] == 0.25
    assert_type(physics.bind(model.find_all("geom")), GeomBinding)
    assert_type(physics.bind(model.worldbody.body), BodyBinding)  # an ElementList
    assert_type(physics.bind(model.find_all("actuator")).ctrl, Array[np.float64])
    # elements typed only as Element bind too, untyped: the binding of no particular kind
    elements: list[mjcf.Element] = list(model.find_all("site"))
    assert_type(physics.bind(elements), Binding)


def test_named_indexers_and_state() -> None:
    _, physics = scene()
    assert_type(physics.named.data.qpos["shoulder"], Array[np.float64])
    assert_type(physics.named.model.geom_rgba["upper", "a"], Array[np.float32])
    assert_type(physics.time(), float)
    assert_type(physics.timestep(), float)
    assert_type(physics.control(), Array[np.float64])
    with physics.reset_context() as reset:
        assert_type(reset, mjcf.Physics)
    physics.step(2)
    assert physics.time() == 2 * physics.timestep()
