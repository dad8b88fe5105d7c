"""Positive typing cases: what mypy and pyright infer for the public API.

Checked statically by ``test_typecheck.py`` (``mypy --strict --warn-unused-ignores`` and
pyright strict, zero errors expected) and also run by pytest, so every snippet is valid at
run time too: each ``assert_type`` states a type, the runtime ``isinstance`` beside some of
them checks the objects really are what the checkers are told.
"""

# pyright: reportUnnecessaryTypeIgnoreComment=true

from __future__ import annotations

import copy
import io
from pathlib import Path
from typing import Literal, assert_type

import mujoco
import numpy as np

import typed_mjcf as mjcf
from typed_mjcf.types import Float32Array, Float64Array, Int32Array

JointType = Literal["free", "ball", "slide", "hinge"]


def known_at_run_time(text: str) -> str:
    return text


def build() -> mjcf.RootElement:
    model = mjcf.RootElement(model="arm")
    assert_type(model, mjcf.RootElement)
    assert_type(model.model, str | None)

    # once-only children are properties, created on use
    assert_type(model.compiler, mjcf.Compiler)
    assert_type(model.compiler.angle, Literal["radian", "degree"] | None)
    model.compiler.angle = "radian"
    model.compiler.autolimits = True
    assert_type(model.option, mjcf.Option)
    assert_type(model.worldbody, mjcf.Worldbody)
    assert_type(model.default, mjcf.Default)
    assert_type(model.default.geom, mjcf.DefaultGeom)
    assert_type(model.asset, mjcf.AssetSection)
    assert_type(model.actuator, mjcf.Actuator)
    assert_type(model.sensor, mjcf.Sensor)

    # add_<tag> results
    arm = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1))
    assert_type(arm, mjcf.Body)
    geom = arm.add_geom(type="capsule", size=(0.04, 0.2), rgba=(1, 0, 0, 1), condim=3)
    assert_type(geom, mjcf.Geom)
    assert_type(arm.add_site(name="tip", pos=np.zeros(3)), mjcf.Site)
    assert_type(model.default.add_default(class_="big"), mjcf.Default)

    # the generic add()/insert(), typed by overloads on the tag
    shoulder = arm.add("joint", name="shoulder", type="hinge", axis=(0, 1, 0), limited=True,
                       range=(-1, 1))
    assert_type(shoulder, mjcf.Joint)
    assert isinstance(shoulder, mjcf.Joint)
    fore = arm.insert("body", 0, name="forearm", pos=(0, 0, -0.45))
    assert_type(fore, mjcf.Body)
    assert isinstance(fore, mjcf.Body)
    assert_type(fore.add("geom", type="sphere", size=0.05), mjcf.Geom)
    assert_type(model.worldbody.add("light", pos=(0, 0, 3)), mjcf.Light)
    assert_type(model.add("keyframe"), mjcf.Keyframe)
    # a tag only known at run time falls back to the untyped base class
    assert_type(fore.add(known_at_run_time("site")), mjcf.Element)
    assert_type(fore.insert(known_at_run_time("site"), 0, size=0.1), mjcf.Element)

    # child lists by tag: live views, indexed by position or name
    assert_type(arm.geom, mjcf.ElementList[mjcf.Geom])
    assert_type(arm.body, mjcf.ElementList[mjcf.Body])
    assert_type(arm.joint, mjcf.ElementList[mjcf.Joint])
    assert_type(model.worldbody.body, mjcf.ElementList[mjcf.Body])
    assert_type(model.actuator.motor, mjcf.ElementList[mjcf.Motor])
    assert_type(model.worldbody.body["upper_arm"], mjcf.Body)
    assert_type(arm.geom[0:1], list[mjcf.Geom])
    fore.geom[0].rgba = (1, 0, 0, 1)

    # property getters
    assert_type(shoulder.type, JointType | None)
    assert_type(shoulder.limited, Literal["false", "true", "auto"] | None)
    assert_type(shoulder.range, Float64Array | None)
    assert_type(shoulder.name, str | None)
    assert_type(geom.size, Float64Array | None)
    assert_type(geom.rgba, Float32Array | None)
    assert_type(geom.condim, int | None)
    assert_type(geom.mass, float | None)
    assert_type(geom.material, str | mjcf.Material | None)
    assert_type(geom.class_, str | mjcf.Default | None)
    assert_type(model.worldbody.add_body().mocap, bool | None)
    assert_type(model.compiler.meshdir, str | None)

    # property setters: sequences, numpy arrays, elements or names for references
    geom.size = (0.05,)
    geom.size = [0.1, 0.2, 0.3]
    geom.size = np.array([0.1, 0.2])
    geom.rgba = np.array([1, 0, 0, 1], dtype=np.float32)
    geom.rgba = None
    # ints and numpy scalars where reals are expected, alone and mixed with floats in a
    # list (mypy targeting 3.11, where int has no is_integer, once refused the mixed list)
    geom.mass = 1
    geom.mass = np.float32(0.5)
    geom.size = [1, 2.5, np.int64(3)]
    geom.pos = (0, 0, np.float64(0.5))
    model.keyframe.add_key(qpos=[0, 0, 0.5, 1, 0, 0, 0], ctrl=[0.5, 0])
    # a default class by name or element, spelt class_ or dclass (dm_control's)
    limb = model.default.add_default(dclass="limb")
    assert_type(limb, mjcf.Default)
    arm.add_geom(dclass=limb, size=[0.1])
    arm.add_geom(class_="limb", size=[0.1])
    assert_type(arm.add_geom(size=[0.1]).dclass, str | mjcf.Default | None)
    geom.dclass = limb
    geom.mass = 1.5
    shoulder.type = "slide"
    shoulder.limited = "auto"
    shoulder.limited = False
    geom.material = "steel"
    geom.material = model.asset.add_material(name="steel")

    # references: a name, or an element of the right namespace
    motor = model.actuator.add_motor(name="m", joint="shoulder", gear=(2,))
    assert_type(motor, mjcf.Motor)
    assert_type(motor.joint, str | mjcf.Freejoint | mjcf.Joint | None)
    sensor = model.sensor.add_jointpos(joint=shoulder)
    assert_type(sensor, mjcf.Jointpos)
    ball = model.worldbody.add_body(name="ball")
    ball.add_geom(type="sphere", size=(0.1,))
    free = ball.add_freejoint(name="free")
    assert_type(free, mjcf.Freejoint)
    model.sensor.add_framepos(objtype="body", objname="ball")
    model.actuator.add_general(joint=free, gear=(0, 0, 1, 0, 0, 0))
    model.sensor.add_framepos(objtype="site", objname="tip")
    return model


def test_build_compile_and_query(tmp_path: Path) -> None:
    model = build()

    # namespace look-ups
    assert_type(model.find("joint", "shoulder"), mjcf.Freejoint | mjcf.Joint | None)
    assert_type(model.find("body", "upper_arm"), mjcf.Body | None)
    assert_type(model.find("geom", "g"), mjcf.Geom | None)
    assert_type(model.find("tendon", "t"), mjcf.Fixed | mjcf.Spatial | None)
    assert_type(model.find_all("geom"), list[mjcf.Geom])
    assert_type(model.find_all("body"), list[mjcf.Body])
    assert_type(model.find_all("joint"), list[mjcf.Freejoint | mjcf.Joint])
    namespace: mjcf.Namespace = "site" if known_at_run_time("site") else "geom"
    found = model.find(namespace, "tip")  # a namespace known at run time: any element
    assert found is None or isinstance(found, mjcf.Element)
    assert all(isinstance(e, mjcf.Element) for e in model.find_all(namespace))
    joint = model.find("joint", "shoulder")
    assert joint is not None
    assert_type(joint.name, str | None)  # common to <joint> and <freejoint>
    assert isinstance(joint, mjcf.Joint)  # only <joint> has a type and a range
    assert_type(joint.type, JointType | None)
    assert_type(joint.range, Float64Array | None)

    # the runtime base
    body = model.worldbody.body[0]
    assert_type(body.parent, mjcf.Element | None)
    assert_type(body.root, mjcf.ModelRoot)
    assert_type(body.tag, str)
    assert_type(body.path, str)
    assert_type(body.get_children(), list[mjcf.Element])
    assert_type(body.get_attributes(), dict[str, object])
    assert_type(copy.deepcopy(body), mjcf.Body)
    assert_type(copy.deepcopy(model), mjcf.RootElement)

    # export, parse, compile
    xml = model.to_xml_string(precision=6)
    assert_type(xml, str)
    parsed = mjcf.from_xml_string(xml)
    assert_type(parsed, mjcf.RootElement)
    assert isinstance(parsed, mjcf.RootElement)
    assert_type(parsed.worldbody.body[0].geom, mjcf.ElementList[mjcf.Geom])
    path = tmp_path / "arm.xml"
    path.write_text(xml, encoding="utf-8")
    assert_type(mjcf.from_path(path), mjcf.RootElement)
    assert_type(mjcf.from_file(io.StringIO(xml)), mjcf.RootElement)
    assert_type(model.get_assets(), dict[str, bytes])
    assert_type(mjcf.export_with_assets(model, tmp_path / "out"), str)

    compiled = model.compile()
    assert_type(compiled, mujoco.MjModel)
    assert isinstance(compiled, mujoco.MjModel)
    assert_type(compiled.nbody, int)
    assert_type(model.to_spec(), mujoco.MjSpec)
    assert_type(mjcf.from_spec(model.to_spec()), mjcf.RootElement)


def test_more_getters() -> None:
    scratch = mjcf.RootElement()  # a model that is never compiled
    assert_type(scratch.asset.add_mesh(name="m", vertex=(0, 0, 0)).vertex, Float32Array | None)
    assert_type(scratch.asset.add_texture(builtin="checker").builtin,
                Literal["none", "gradient", "checker", "flat"] | None)
    assert_type(scratch.asset.add_hfield(nrow=2, ncol=2, size=(1, 1, 1, 0.1)).size,
                Float64Array | None)
    assert_type(scratch.add("size").nuser_jnt, int | None)
    assert_type(scratch.add("custom").add_numeric(name="n", size=1).size, int | None)
    assert_type(scratch.keyframe.add_key().mpos, Float64Array | None)
    assert_type(scratch.visual.global_, mjcf.Global)


def test_flags_that_also_take_a_keyword_alone() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b").add_joint(name="j")
    pid = model.actuator.add_pid(joint="j", input="quat")
    assert_type(pid.input, tuple[mjcf.PidInput, ...] | mjcf.PidInputAlone | None)
    pid.input = ("ff", "pos")
    pid.input = "ff"
    general = model.actuator.add_general(joint="j", input="expmap")
    general.input = ("pos", "ff")
    general.input = "expmap"
    general.input = ["vel"]
    general.input = "pressure"  # what MuJoCo writes for a <cylinder>
    general.input = None
    model.default.add_dcmotor(input="quat")
    model.default.dcmotor.input = "voltage"
    chart: mjcf.DcmotorInputAlone = "quat"
    tokens: list[mjcf.DcmotorInput] = ["pos", "vel"]
    model.actuator.add_dcmotor(joint="j", motorconst=1, resistance=1, input=tokens).input = chart
    assert_type(general.resolve("input"), tuple[mjcf.Inputbit, ...] | mjcf.InputbitAlone | None)
    value = pid.input
    if isinstance(value, str):
        assert_type(value, Literal["expmap", "quat"])
    else:
        assert_type(value, tuple[Literal["pos", "vel", "ff"], ...] | None)
        assert value == ("ff",)


def test_int_arrays_and_assets() -> None:
    model = mjcf.RootElement()
    mesh = model.asset.add_mesh(name="tri", vertex=(0, 0, 0, 1, 0, 0, 0, 1, 0),
                                face=(0, 1, 2))
    assert_type(mesh.face, Int32Array | None)
    mesh.face = np.array([0, 2, 1], dtype=np.int64)
    texture = model.asset.add_texture(name="t", file=mjcf.Asset(b"\x89PNG", ".png"))
    assert_type(texture.file, str | mjcf.Asset | None)
    texture.file = Path("checker.png")


def test_errors_are_typed() -> None:
    model = mjcf.RootElement()
    geom = model.worldbody.add_body().add_geom()
    try:
        geom.size = (1, 2, 3, 4)  # type: ignore[assignment]  # deliberately wrong
    except mjcf.InvalidValueError as error:
        assert_type(error, mjcf.InvalidValueError)
        assert isinstance(error, ValueError)
    else:
        raise AssertionError("size=(1, 2, 3, 4) was accepted")
