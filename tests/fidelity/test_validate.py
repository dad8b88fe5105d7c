"""validate(): one test per kind of finding, each checking the path and rule it reports;
valid models have no findings; names MuJoCo defines itself are not reported."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf._model.validate import (
    RULES,
    Finding,
    ValidationError,
    ensure_valid,
    errors,
    validate,
)

from ..bench.scaling import chain
from ..operations import growth


def only(model: mjcf.RootElement) -> Finding:
    findings = validate(model)
    assert len(findings) == 1, findings
    return findings[0]


def assert_finding(finding: Finding, path: str, rule: str, *words: str) -> None:
    text = str(finding)
    assert text.startswith(f"{path}: {rule}: "), text
    assert finding.path == path and finding.rule == rule
    for word in words:
        assert word in finding.message, finding.message


def mujoco_error(model: mjcf.RootElement, *, compile: bool = False) -> str | None:
    """What MuJoCo says reading the model (``compile``: compiling it too, where some repeated
    names are found)."""
    try:
        if compile:
            mujoco.MjModel.from_xml_string(model.to_xml_string())
        else:
            mujoco.MjSpec.from_string(model.to_xml_string())
    except ValueError as error:
        return str(error)
    return None


# ----------------------------------------------------------------------------- valid models


def arm() -> mjcf.RootElement:
    """The README's arm, with a default class, a tendon, sensors and an equality."""
    model = mjcf.RootElement(model="arm")
    model.compiler.angle = "radian"
    model.default.add_default(class_="limb").add_geom(rgba=(0.5, 0.5, 0.5, 1))
    model.asset.add_material(name="steel", rgba=(0.7, 0.7, 0.7, 1))
    upper = model.worldbody.add_body(name="upper_arm", pos=(0, 0, 1), childclass="limb")
    upper.add_geom(type="capsule", size=(0.04, 0.2), material="steel")
    shoulder = upper.add_joint(name="shoulder", type="hinge", axis=(0, 1, 0))
    upper.add_site(name="tip", pos=(0, 0, -0.4))
    fore = upper.insert("body", 0, name="forearm", pos=(0, 0, -0.45))
    fore.add_geom(type="sphere", size=0.05)
    elbow = fore.add_joint(name="elbow")
    model.actuator.add_motor(name="m", joint="shoulder")
    model.actuator.add_position(name="p", joint=elbow, kp=10)
    model.sensor.add_jointpos(joint=shoulder)
    model.sensor.add_framepos(objtype="body", objname="forearm")
    model.sensor.add_accelerometer(site="tip")
    fixed = model.tendon.add_fixed(name="t")
    fixed.add_joint(joint=shoulder, coef=1.0)
    model.equality.add_connect(body1="forearm", anchor=(0, 0, 0))
    model.contact.add_exclude(body1="world", body2="upper_arm")
    return model


def test_a_valid_model_has_no_findings_and_mujoco_compiles_it() -> None:
    model = arm()
    assert validate(model) == []
    assert ensure_valid(model) == []
    assert model.compile().nbody == 3


def test_builtin_and_implicit_names_resolve() -> None:
    model = mjcf.RootElement()
    model.asset.add_mesh(file="meshes/link.v2.stl")            # named "link.v2"
    model.asset.add_texture(file="textures/wood.png", type="2d")  # named "wood"
    model.asset.add_material(name="m", texture="wood")
    model.worldbody.add_geom(type="mesh", mesh="link.v2", class_="main", material="m")
    model.contact.add_exclude(body1="world", body2="world")
    assert validate(model) == []


def test_child_model_names_are_left_to_mujoco() -> None:
    model = mjcf.RootElement()
    model.asset.add_model(name="gripper", file="gripper.xml")
    body = model.worldbody.add_body(name="b")
    body.add_attach(model="gripper", body="palm", prefix="g_")  # palm is in gripper.xml
    model.sensor.add_framepos(objtype="body", objname="g_palm")  # named by the prefix
    assert validate(model) == []


def test_validate_sees_what_is_written_only() -> None:
    model = mjcf.RootElement()
    _ = model.compiler, model.option.flag  # empty once-only sections: never written
    assert validate(model) == []


# ----------------------------------------------------------------------------- presence


def test_exclusive() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b", quat=(1, 0, 0, 0), euler=(0, 0, 0))
    assert_finding(only(model), "worldbody/body[b]", "exclusive", "quat", "euler")
    assert mujoco_error(model) is not None


def test_exclusive_bundles_count_when_partly_set() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="a").add_site(name="s1")
    model.worldbody.add_site(name="s2")
    model.equality.add_connect(site1="s1", site2="s2", anchor=(0, 0, 0))
    finding = only(model)
    assert_finding(finding, "equality/connect[0]", "exclusive", "site1+site2",
                   "body1+body2+anchor")
    assert mujoco_error(model) is not None


def test_exclusive_applies_in_default_classes() -> None:
    # the grammar's projection rows lack the constraint; MuJoCo checks it in defaults too
    model = mjcf.RootElement()
    model.default.camera.set_attributes(fovy=45, sensorsize=(1, 1))
    assert_finding(only(model), "default/camera", "exclusive", "fovy", "sensorsize")
    assert mujoco_error(model) is not None


def test_together() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b")
    model.sensor.add_framepos(name="f", objtype="body", objname="b", reftype="body")
    assert_finding(only(model), "sensor/framepos[f]", "together", "reftype", "refname")
    assert mujoco_error(model) is not None


def test_requires(monkeypatch: pytest.MonkeyPatch) -> None:
    """The "requires" kind (the grammar format's, and facts.toml's [[constraint]]) on a rule
    MuJoCo 4.0.0 has: a camera's focal/principal require sensorsize. No row of the 4.0.0
    grammar states a requires constraint, and this rule is not in the tables (MuJoCo checks
    it after defaults apply, on cameras only: a default class may set focal alone), so the
    test gives <camera> the rule and checks the validator and MuJoCo agree on both models."""
    spec = mjcf.Camera.spec
    monkeypatch.setattr(spec, "constraints", (
        *spec.constraints, ("requires", (("focal",), ("sensorsize",)))))
    model = mjcf.RootElement()
    model.worldbody.add_camera(name="c", focal=(1, 1))
    assert_finding(only(model), "worldbody/camera[c]", "requires", "focal", "sensorsize")
    assert "require sensorsize" in (mujoco_error(model, compile=True) or "")
    model.worldbody.camera[0].sensorsize = (1, 1)
    assert validate(model) == []
    assert mujoco_error(model, compile=True) is None


def test_oneof() -> None:
    model = mjcf.RootElement()
    model.equality.add_connect(name="c", anchor=(0, 0, 0))
    assert_finding(only(model), "equality/connect[c]", "oneof", "site1+site2", "body1+anchor")
    assert mujoco_error(model) is not None


# ----------------------------------------------------------------------------- required


def test_required_attribute() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_replicate().add_geom(size=(0.1,))
    model.worldbody.add_body(name="b").add_inertial(pos=(0, 0, 0))
    model.sensor.add_framepos(name="f")
    findings = validate(model)
    assert [(f.path, f.rule) for f in findings] == [
        ("worldbody/replicate[0]", "required-attribute"),
        ("worldbody/body[b]/inertial", "required-attribute"),
        ("sensor/framepos[f]", "required-attribute"),
        ("sensor/framepos[f]", "required-attribute"),
    ]
    assert ["count" in findings[0].message, "mass" in findings[1].message,
            "objtype" in findings[2].message, "objname" in findings[3].message] == [True] * 4
    assert mujoco_error(model) is not None


def test_required_attributes_are_not_required_in_default_classes(
        monkeypatch: pytest.MonkeyPatch) -> None:
    # no projection row keeps a required attribute in 4.0.0: make joint@type required
    monkeypatch.setattr(mjcf.Joint.spec.by_name["type"], "required", True)
    monkeypatch.setattr(mjcf.DefaultJoint.spec.by_name["type"], "required", True)
    model = mjcf.RootElement()
    model.default.joint.damping = (1.0,)
    model.worldbody.add_body(name="b").add_joint(name="j")
    assert_finding(only(model), "worldbody/body[b]/joint[j]", "required-attribute", "type")


def test_required_child(monkeypatch: pytest.MonkeyPatch) -> None:
    # no row of MuJoCo 4.0.0's grammar has a required child: require <inertial> in <body>
    monkeypatch.setattr(mjcf.Body.spec.children["inertial"], "card", "!")
    model = mjcf.RootElement()
    model.worldbody.add_body(name="with").add_inertial(pos=(0, 0, 0), mass=1)
    bare = model.worldbody.add_body(name="without")
    _ = bare.inertial  # created empty on access: not written, so it does not count
    assert_finding(only(model), "worldbody/body[without]", "required-child", "<inertial>")


# ----------------------------------------------------------------------------- references


def test_reference_by_name_that_names_nothing() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b").add_joint(name="shoulder")
    model.actuator.add_motor(name="m", joint="sholder")
    finding = only(model)
    assert_finding(finding, "actuator/motor[m]", "unresolved-reference", "joint='sholder'",
                   "did you mean 'shoulder'")


def test_reference_to_a_removed_element() -> None:
    model = mjcf.RootElement()
    joint = model.worldbody.add_body(name="b").add_joint(name="j")
    model.actuator.add_motor(name="m", joint=joint)
    joint.remove()
    assert_finding(only(model), "actuator/motor[m]", "unresolved-reference", "removed")


def test_reference_to_an_element_of_another_model() -> None:
    other = mjcf.RootElement()
    joint = other.worldbody.add_body(name="b").add_joint(name="j")
    model = mjcf.RootElement()
    model.actuator.add_motor(name="m", joint=joint)
    assert_finding(only(model), "actuator/motor[m]", "unresolved-reference",
                   "another model", "worldbody/body[b]/joint[j]")


def test_undefined_class_and_childclass() -> None:
    model = mjcf.RootElement()
    model.default.add_default(class_="used")
    body = model.worldbody.add_body(name="b", childclass="limbs")
    body.add_geom(name="g", class_="usd", size=(0.1,))
    findings = validate(model)
    assert [(f.path, f.rule) for f in findings] == [
        ("default/default[used]", "unused-default"),
        ("worldbody/body[b]", "unresolved-reference"),
        ("worldbody/body[b]/geom[g]", "unresolved-reference"),
    ]
    assert "childclass='limbs' names no default class" in findings[1].message
    assert "did you mean 'used'" in findings[2].message
    assert mujoco_error(model) is not None


def test_unresolved_reference_in_a_default_class_is_a_warning() -> None:
    # MuJoCo resolves it only for elements that use the class (dm_control's fruit fly
    # defaults name materials that only the full model defines)
    model = mjcf.RootElement()
    model.default.add_default(class_="c").geom.material = "paint"
    model.worldbody.add_geom(class_="c", size=(0.1,), material="paint")
    findings = validate(model)
    assert [(f.path, f.rule, f.severity) for f in findings] == [
        ("default/default[c]/geom", "unresolved-reference", "warning"),
        ("worldbody/geom[0]", "unresolved-reference", "error")]


def test_object_names_of_frame_sensors_are_references() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_site(name="s")
    model.sensor.add_framepos(name="f", objtype="xbody", objname="s")
    assert_finding(only(model), "sensor/framepos[f]", "unresolved-reference",
                   "objname='s' names no body")


def test_scoped_names_resolve_through_find() -> None:
    # attachments make model.find resolve "child/..." names; until then they name nothing
    model = mjcf.RootElement()
    model.sensor.add_jointpos(name="s", joint="arm/shoulder")
    assert_finding(only(model), "sensor/jointpos[s]", "unresolved-reference",
                   "'arm/shoulder'", "no attached model")


# ----------------------------------------------------------------------------- default classes


def test_default_class_names() -> None:
    model = mjcf.RootElement()
    model.default.class_ = "base"
    model.default.add_default().add_geom(rgba=(1, 0, 0, 1))
    findings = validate(model)
    assert [(f.path, f.rule) for f in findings] == [
        ("default", "default-class"), ("default/default[0]", "default-class")]
    assert "'main'" in findings[0].message and "needs a class name" in findings[1].message
    assert mujoco_error(model) is not None
    model.default.class_ = "main"
    assert [f.path for f in validate(model)] == ["default/default[0]"]


def test_unused_default_is_a_warning() -> None:
    model = mjcf.RootElement()
    top = model.default.add_default(class_="robot")
    top.add_default(class_="finger").add_geom(rgba=(1, 0, 0, 1))
    model.default.add_default(class_="spare")
    model.worldbody.add_geom(class_="finger", size=(0.1,))  # uses finger, and robot above it
    finding = only(model)
    assert_finding(finding, "default/default[spare]", "unused-default", "'spare'")
    assert finding.severity == "warning"
    assert errors([finding]) == []
    assert ensure_valid(model) == [finding]  # warnings do not stop compile()
    assert mujoco_error(model) is None


def test_childclass_uses_a_class() -> None:
    model = mjcf.RootElement()
    model.default.add_default(class_="limb")
    model.worldbody.add_frame(childclass="limb")
    assert validate(model) == []


# ----------------------------------------------------------------------------- kinematic tree


def test_world_body_has_no_joints_or_inertia() -> None:
    model = mjcf.RootElement()
    frame = model.worldbody.add_frame(name="f")
    frame.add_joint(name="j")
    frame.add_inertial(pos=(0, 0, 0), mass=1)
    model.worldbody.add_body(name="b").add_frame().add_joint(name="fine")
    findings = validate(model)
    assert [(f.path, f.rule) for f in findings] == [  # <inertial> is placed first
        ("worldbody/frame[f]/inertial", "world-body"),
        ("worldbody/frame[f]/joint[j]", "world-body")]
    assert mujoco_error(model) is not None


def test_joints_are_not_direct_children_of_replicate() -> None:
    model = mjcf.RootElement()
    replicate = model.worldbody.add_body(name="b").add_replicate(count=2)
    replicate.add_frame().add_joint(name="j")
    replicate.add_body(name="c").add_joint(name="fine")
    assert_finding(only(model), "worldbody/body[b]/replicate[0]/frame[0]/joint[j]",
                   "replicate-joint", "wrap it in a <body>")
    assert mujoco_error(model) is not None


def test_self_attach_names_a_body_or_frame() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b").add_attach(prefix="copy")
    assert_finding(only(model), "worldbody/body[b]/attach[0]", "self-attach", "body=")
    assert mujoco_error(model) is not None


def test_named_objectless_sensor_with_two_replicates() -> None:
    # found by test_properties: MuJoCo copies a clock sensor per replicate, same name each time
    model = mjcf.RootElement()
    model.worldbody.add_replicate(count=1)
    model.worldbody.add_replicate(count=1)
    model.sensor.add_clock(name="c")
    model.sensor.add_clock()
    model.sensor.add_subtreecom(name="fine", body="world")
    assert_finding(only(model), "sensor/clock[c]", "replicate-names", "'c'")
    assert mujoco_error(model) is not None
    model.worldbody.replicate[1].remove()
    assert validate(model) == [] and mujoco_error(model) is None


def test_a_replicate_copy_named_like_another_body() -> None:
    # found by test_properties: copies of body1 in a replicate of 2 are body10 and body11
    model = mjcf.RootElement()
    model.worldbody.add_replicate(count=2, offset=(1, 0, 0)).add_body(name="body1").add_geom(
        size=(0.1,))
    model.worldbody.add_body(name="body10").add_geom(size=(0.1,))
    assert_finding(only(model), "worldbody/replicate[0]/body[body1]", "repeated-name",
                   "'body10'", "the name of worldbody/body[body10]")
    assert "repeated name 'body10'" in (mujoco_error(model, compile=True) or "")
    model.worldbody.body["body10"].name = "body2"
    assert validate(model) == [] and mujoco_error(model, compile=True) is None


def test_two_replicates_making_one_name() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_replicate(count=2, offset=(1, 0, 0)).add_site(name="s1")  # s10 s11
    model.worldbody.add_replicate(count=12, offset=(0, 1, 0)).add_site(name="s")  # s00-s11
    finding = only(model)
    assert finding.rule == "repeated-name" and "'s10'" in finding.message, finding
    assert "repeated name 's10'" in (mujoco_error(model, compile=True) or "")
    model.worldbody.replicate[1].count = 10  # s0-s9
    assert validate(model) == [] and mujoco_error(model, compile=True) is None


def test_a_mesh_named_after_its_file_and_a_mesh_named_so(tmp_path: Path) -> None:
    (tmp_path / "foo.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n")
    model = mjcf.RootElement()
    model.compiler.meshdir = str(tmp_path)
    model.asset.add_mesh(file="foo.obj")
    model.asset.add_mesh(name="foo", file="foo.obj")
    assert_finding(only(model), "asset/mesh[0]", "repeated-name", "'foo'",
                   "the name of asset/mesh[foo]")
    assert "repeated name 'foo'" in (mujoco_error(model) or "")
    model.asset.mesh[1].name = "bar"
    assert validate(model) == [] and mujoco_error(model) is None


def test_a_body_named_like_a_flexcomp_body_is_no_repeated_name() -> None:
    # MuJoCo 4.0.0 compiles it: the bodies a <flexcomp> makes claim no names
    model = mjcf.from_xml_string(
        '<mujoco><worldbody><body name="flag_0"><geom size=".1"/></body>'
        '<flexcomp name="flag" type="grid" count="3 3 1" spacing=".1 .1 .1" radius=".01" '
        'dim="2"/></worldbody></mujoco>')
    assert validate(model) == [] and mujoco_error(model, compile=True) is None


# ----------------------------------------------------------------------------- reporting


def test_findings_are_in_document_order_and_the_error_lists_them_all() -> None:
    model = mjcf.RootElement()
    model.default.add_default(class_="spare")
    model.actuator.add_motor(name="m", joint="nothing")
    model.worldbody.add_body(name="b", quat=(1, 0, 0, 0), euler=(0, 0, 0))
    findings = validate(model)
    assert [f.rule for f in findings] == ["unused-default", "exclusive", "unresolved-reference"]
    with pytest.raises(ValidationError) as caught:
        ensure_valid(model)
    error = caught.value
    assert isinstance(error, mjcf.InvalidValueError)
    assert error.findings == tuple(findings)
    assert error.errors == tuple(findings[1:])
    text = str(error)
    assert "2 errors" in text and "1 warning" in text
    assert all(str(f) in text for f in findings)
    assert set(RULES) >= {f.rule for f in findings}


def test_validate_is_linear_in_the_number_of_elements() -> None:
    def validating(n: int) -> Callable[[], object]:
        model = chain(n)
        return lambda: validate(model)

    assert validate(chain(50)) == []
    # 8x the elements: about 8x the Python lines executed, far from 64x (counted, not timed:
    # tests/bench/scaling.py reports the time)
    ratio = growth(validating, 250, 2000,
                   counted=("_model.validate", "_core.tree", "_core.names", "_text.export"))
    assert ratio < 8 * 1.25, ratio
