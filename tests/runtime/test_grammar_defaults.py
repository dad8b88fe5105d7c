"""The defaults MuJoCo fills, as the grammar gives them (schema/mjcf.json, probed from the
installed MuJoCo by codegen/drift.py; tests/codegen/test_drift.py holds every one against
the reader): ``resolve()`` of an attribute left out is MuJoCo's value, and an attribute
whose value MuJoCo computes says so in its documentation."""

from __future__ import annotations

import mujoco
import numpy as np

import typed_mjcf as mjcf
from typed_mjcf._core.tree import element_classes
from typed_mjcf._model.defaults import resolve

# MJCF name -> MjsJoint field (MuJoCo's C name where it differs)
NAMES = {"damping": "damping", "armature": "armature", "frictionloss": "frictionloss",
         "stiffness": "stiffness", "group": "group", "ref": "ref", "margin": "margin",
         "springref": "springref", "range": "range", "actuatorfrcrange": "actfrcrange",
         "springdamper": "springdamper", "pos": "pos"}


def test_a_new_joint_resolves_to_what_mujoco_fills() -> None:
    model = mjcf.RootElement()
    joint = model.worldbody.add_body(name="b").add_joint(name="j")
    theirs = mujoco.MjSpec().worldbody.add_body().add_joint()
    for name, field in NAMES.items():
        ours = np.asarray(resolve(joint, name), dtype=float).ravel()  # (None: nan, unequal)
        expected = np.asarray(getattr(theirs, field), dtype=float).ravel()
        assert np.array_equal(ours, expected[:ours.size]), name


def test_a_motor_and_a_sensor_resolve_to_what_mujoco_fills() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b").add_joint(name="j")
    motor = model.actuator.add_motor(joint="j")
    assert list(motor.resolve("ctrlrange")) == [0.0, 0.0]
    assert motor.resolve("group") == 0
    sensor = model.sensor.add_jointpos(joint="j")
    assert sensor.resolve("noise") == 0.0


def test_computed_values_resolve_to_none_and_their_docs_say_so() -> None:
    geom = element_classes()["Geom"].spec.by_name["mass"]
    assert geom.default is None and geom.computed
    assert "default computed by MuJoCo" in geom.doc and "no default" not in geom.doc
    model = mjcf.RootElement()
    assert model.worldbody.add_body().add_geom(size=(1,)).resolve("mass") is None
    statistic = element_classes()["Statistic"].spec.by_name["extent"]
    assert statistic.computed and "computed by MuJoCo" in statistic.doc
    joint = element_classes()["Joint"].spec.by_name["damping"]
    assert not joint.computed and 'default "0 0 0"' in joint.doc
