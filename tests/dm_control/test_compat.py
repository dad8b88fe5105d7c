"""``install_as_dm_control_mjcf()`` and dm_control's observable behaviour behind its switch
(README "Coming from dm_control.mjcf"): each behaviour with the switch on, and the typed
API's own choice with it off."""

from __future__ import annotations

import copy
import hashlib
import subprocess
import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._dmcompat import debugging, installed

from . import harness, references


@pytest.fixture
def dm() -> Iterator[None]:
    """dm_control's behaviour on while the test runs (everything restored after)."""
    with installed():
        yield


def test_installed_is_undone() -> None:
    before = {name: sys.modules.get(name) for name in ("dm_control", "dm_control.mjcf")}
    with installed():
        assert mjcf.current_behaviour() == mjcf.Behaviour.dm_control()
        assert sys.modules["dm_control.mjcf"].RootElement is mjcf.RootElement
    assert mjcf.current_behaviour() == mjcf.Behaviour.typed()
    assert {name: sys.modules.get(name) for name in before} == before


@pytest.mark.skipif(harness.mjcf_folder() is None, reason="dm_control is not installed")
def test_dm_controls_own_code_runs_on_typed_mjcf_after_install() -> None:
    """In a fresh interpreter: the redirection is process-wide."""
    code = textwrap.dedent("""
        import typed_mjcf
        typed_mjcf.install_as_dm_control_mjcf()
        from dm_control import mjcf
        from dm_control.mjcf import debugging, element, traversal_utils
        from dm_control.manipulation import props
        box = props.Box()
        assert isinstance(box.mjcf_model, typed_mjcf.RootElement)
        assert isinstance(box.mjcf_model.worldbody, element._ElementImpl)
        assert isinstance(box.mjcf_model, mjcf.Element)
        assert mjcf.element.RootElement is typed_mjcf.RootElement
        assert traversal_utils.get_freejoint is typed_mjcf.get_freejoint
        assert callable(mjcf.export_with_assets) and not debugging.debug_mode()
        physics = getattr(typed_mjcf, "Physics", None)
        try:
            assert mjcf.Physics is physics
        except AttributeError:
            assert physics is None
        try:
            import dm_control.mjcf.schema
        except ImportError:
            pass
        else:
            raise AssertionError("dm_control.mjcf.schema is not served")
        print("ok")
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "ok"


def _model() -> mjcf.RootElement:
    model = mjcf.RootElement(model="m")
    body = model.worldbody.add_body(name="b", pos=(1, 2, 3))
    body.add_geom(name="g", size=(0.1,), rgba=(1, 1, 1, 1))
    return model


# ---------------------------------------------------------------------------- arrays


def test_arrays_are_edited_in_place(dm: None) -> None:
    model = _model()
    body, geom = model.worldbody.body[0], model.find("geom", "g")
    assert isinstance(geom, mjcf.Geom)
    body.pos *= 2
    rgba = geom.rgba
    assert rgba is not None
    rgba[3] = 0.1
    rgba[:3] = (0.5, 0.25, 0)
    assert body.pos is not None and body.pos.tolist() == [2, 4, 6]
    assert 'pos="2 4 6"' in model.to_xml_string()
    assert 'rgba="0.5 0.25 0 0.1"' in model.to_xml_string()


def test_typed_arrays_stay_read_only() -> None:
    geom = _model().find("geom", "g")
    assert isinstance(geom, mjcf.Geom) and geom.rgba is not None
    with pytest.raises(ValueError, match="read-only"):
        geom.rgba[3] = 0.1


def test_an_array_edited_in_place_is_checked_when_written(dm: None) -> None:
    model = _model()
    geom = model.find("geom", "g")
    assert isinstance(geom, mjcf.Geom) and geom.rgba is not None
    geom.rgba.resize(5, refcheck=False)  # numpy's one in-place change of length
    with pytest.raises(mjcf.InvalidValueError, match=r"geom\[g\].*rgba.*expected 4"):
        model.to_xml_string()
    with pytest.raises(mjcf.InvalidValueError, match="rgba"):
        model.get_assets()


def test_a_copy_does_not_share_arrays_edited_in_place(dm: None) -> None:
    model = _model()
    body = model.worldbody.body[0]
    assert body.pos is not None
    clone = copy.deepcopy(model)
    body.pos[0] = 7
    assert clone.worldbody.body[0].pos is not None
    assert clone.worldbody.body[0].pos.tolist() == [1, 2, 3]


# ---------------------------------------------------------------------------- children


def test_inertial_exists_once_added(dm: None) -> None:
    body = _model().worldbody.body[0]
    inertial = getattr(body, "inertial", None)
    assert inertial is None  # dm_control's walkers: `if inertial: inertial.mass *= f`
    if body.inertial is None:
        body.add("inertial", mass=1, pos=(0, 0, 0))
    assert body.inertial is not None and body.inertial.mass == 1


def test_typed_inertial_is_made_on_first_access() -> None:
    assert _model().worldbody.body[0].inertial is not None


def test_freejoint_is_one_element(dm: None) -> None:
    world = _model()
    arm = _model()
    frame = world.worldbody.attach(arm)
    assert getattr(frame, "freejoint") is None  # noqa: B009 - typed as a list, one here
    free = frame.add("freejoint")
    assert getattr(frame, "freejoint") is free  # noqa: B009 - as above
    assert mjcf.get_frame_freejoint(arm) is free  # dm_control's take the attached model
    assert mjcf.get_frame_joints(arm) == [free]


def test_frame_helpers_take_the_attached_model() -> None:
    world, arm = _model(), _model()
    arm.model = "arm"
    frame = world.worldbody.attach(arm)
    slide = frame.add_joint(type="slide")
    assert mjcf.get_frame_joints(arm) == [slide] == mjcf.get_frame_joints(frame)
    assert mjcf.get_frame_freejoint(arm) is None
    free = frame.add_freejoint()
    assert mjcf.get_frame_freejoint(arm) is free is mjcf.get_frame_freejoint(frame)
    assert mjcf.get_frame_freejoint(_model()) is None  # a model not attached


def test_global_is_spelt_as_in_mjcf(dm: None) -> None:
    model = _model()
    assert getattr(model.visual, "global") is model.visual.global_
    assert model.visual.get_children("global") is model.visual.global_


def test_element_lists_clear_and_remove() -> None:
    model = _model()
    body = model.worldbody.body[0]
    extra = body.add_geom(size=(0.2,))
    body.geom.remove(extra)
    assert extra.is_removed and len(body.geom) == 1
    with pytest.raises(mjcf.ChildError, match="not one of its"):
        body.geom.remove(extra)
    body.geom.clear()
    assert len(body.geom) == 0


# ---------------------------------------------------------------------------- names


def test_unnamed_elements_have_dm_controls_identifiers(dm: None) -> None:
    model = mjcf.RootElement(model="m")
    body = model.worldbody.add_body()
    joint = body.add_joint()
    body.add_geom(size=(0.1,))
    model.actuator.add_motor(joint=joint)
    assert (body.full_identifier, joint.full_identifier) == ("//unnamed_body_0",
                                                             "//unnamed_joint_0")
    other = mjcf.RootElement(model="other")
    inner = other.worldbody.add_body()
    inner.add_geom(size=(0.1,))
    frame = model.worldbody.attach(other)
    slide = frame.add_joint(type="slide")
    named = frame.add_joint(name="root_x", type="slide")
    model.actuator.add_position(joint=named)
    assert inner.full_identifier == "other//unnamed_body_0"
    assert slide.full_identifier == frame.full_identifier == "other/"
    assert named.full_identifier == "other/root_x/"
    compiled = mujoco.MjModel.from_xml_string(model.to_xml_string(), model.get_assets())
    for element, kind in ((body, mujoco.mjtObj.mjOBJ_BODY), (joint, mujoco.mjtObj.mjOBJ_JOINT),
                          (inner, mujoco.mjtObj.mjOBJ_BODY), (slide, mujoco.mjtObj.mjOBJ_JOINT),
                          (named, mujoco.mjtObj.mjOBJ_JOINT)):
        name = element.full_identifier
        assert name is not None and mujoco.mj_name2id(compiled, kind, name) >= 0, name
    assert compiled.actuator_trnid[1, 0] == mujoco.mj_name2id(
        compiled, mujoco.mjtObj.mjOBJ_JOINT, "other/root_x/")
    assert str(joint) == "<joint/>"  # its own tag makes no name up, as dm_control's str()


def test_typed_unnamed_elements_have_no_identifier() -> None:
    body = _model().worldbody.add_body()
    assert body.full_identifier is None
    assert "unnamed" not in body.root.to_xml_string()


def test_models_without_a_name(dm: None) -> None:
    assert mjcf.RootElement().model == "unnamed_model"


def test_prefixed_identifier_and_attribute_text() -> None:
    world, arm = _model(), _model()
    arm.model = "arm"
    world.worldbody.attach(arm)
    geom = arm.find("geom", "g")
    assert geom is not None
    assert geom.prefixed_identifier(world.namescope) == "arm/g"
    assert geom.prefixed_identifier(arm.namescope) == "g"
    site = world.worldbody.add_site(name="s")
    world.sensor.add_framepos(objtype="geom", objname=geom)
    sensor = world.sensor.framepos[0]
    assert sensor.get_attribute_xml_string("objname") == "arm/g"
    assert site.get_attribute_xml_string("pos") is None
    assert world.worldbody.body[0].get_attribute_xml_string("pos", precision=2) == "1 2 3"
    with pytest.raises(mjcf.UnknownAttributeError):
        site.get_attribute_xml_string("nonsense")


# ---------------------------------------------------------------------------- files


def test_files_are_named_by_their_contents(dm: None) -> None:
    model = mjcf.RootElement(model="m")
    contents = box_stl(0.1)
    mesh = model.asset.add_mesh(name="shape",
                                file=mjcf.Asset(contents, ".stl", name="shape"))
    model.worldbody.add_geom(type="mesh", mesh=mesh)
    digest = hashlib.sha1(contents, usedforsecurity=False).hexdigest()
    assert list(model.get_assets()) == [f"shape-{digest}.stl"]
    assert f'file="shape-{digest}.stl"' in model.to_xml_string()
    assert model.compile().nmesh == 1


def test_typed_files_keep_readable_names() -> None:
    model = mjcf.RootElement(model="m")
    model.asset.add_mesh(name="shape", file=mjcf.Asset(box_stl(0.1), ".stl", name="shape"))
    assert list(model.get_assets()) == ["shape.stl"]


def test_meshes_without_a_name_are_named_after_their_file(dm: None) -> None:
    xml = ('<mujoco><asset><mesh file="cube.stl"/></asset>'
           '<worldbody><geom type="mesh" mesh="cube"/></worldbody></mujoco>')
    model = mjcf.from_xml_string(xml, assets={"cube.stl": box_stl(0.1)})
    mesh = model.asset.mesh[0]
    assert mesh.name == "cube"
    assert model.worldbody.geom[0].mesh is mesh
    assert model.compile().nmesh == 1


# ---------------------------------------------------------------------------- references

# dm_control's semantics of references: tests/dm_control/references.py


def _references() -> list[object]:
    return references.references(mjcf)


def test_a_reference_given_by_name_reads_as_that_name(dm: None) -> None:
    assert _references() == references.DM_CONTROL


def test_typed_references_link_to_their_element() -> None:
    """Without the switch: a name given links (at once, or when its element appears),
    follows renames, and reads as None once the element is removed."""
    seen = _references()
    assert [type(seen[i]) for i in (0, 1, 5, 7, 8)] == [mjcf.Body] * 5
    assert seen[2:5] == [True, True, "b2"] and seen[6] == "c2"
    assert seen[9:] == [True, None, None, [True, True]]


@pytest.mark.skipif(harness.mjcf_folder() is None, reason="dm_control is not installed")
def test_dm_controls_own_references_read_alike() -> None:
    code = textwrap.dedent("""
        from dm_control import mjcf
        from tests.dm_control.references import references
        print(repr(references(mjcf)))
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=Path(__file__).resolve().parents[2], timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == repr(references.DM_CONTROL)


# ---------------------------------------------------------------------------- defaults


def test_a_frames_own_joint_takes_the_defaults_of_the_model_it_is_in() -> None:
    parent = mjcf.RootElement(model="parent")
    parent.default.joint.damping = 1.0
    probe = mjcf.RootElement(model="probe")
    probe.default.joint.damping = 5.0
    body = probe.worldbody.add_body()
    body.add_geom(size=(0.1,))
    body.add_joint(name="hinge")
    frame = parent.worldbody.attach(probe)
    frame.add_joint(name="slide", type="slide")
    frame.add_geom(size=(0.1,))  # mass for the frame to move
    compiled = parent.compile()
    damping = {mujoco.mj_id2name(compiled, mujoco.mjtObj.mjOBJ_JOINT, i):
               float(compiled.dof_damping[compiled.jnt_dofadr[i]])
               for i in range(compiled.njnt)}
    assert damping == {"probe/slide": 1.0, "probe/hinge": 5.0}


# ---------------------------------------------------------------------------- debug mode


def test_debug_mode_records_where_elements_were_made_and_set(dm: None) -> None:
    debugging.enable_debug_mode()
    try:
        model = mjcf.RootElement(model="m")
        body = model.worldbody.add_body(name="b")
        body.pos = (1, 2, 3)
    finally:
        debugging.disable_debug_mode()
    made = body.get_init_stack()[-1]
    assert made.filename == __file__ and made.text == 'body = model.worldbody.add_body(name="b")'
    stacks = body.get_last_modified_stacks_for_all_attributes()
    assert stacks["name"] == body.get_init_stack()
    assert stacks["pos"][-1].text == "body.pos = (1, 2, 3)"
    later = model.worldbody.add_body()
    assert later.get_init_stack() == [] and not debugging.debug_mode()
    assert np.all([not s for s in later.get_last_modified_stacks_for_all_attributes().values()])


_FLAG_PROBE = textwrap.dedent("""
    import sys
    import typed_mjcf
    typed_mjcf.install_as_dm_control_mjcf()
    from absl import flags
    from dm_control import mjcf
    flags.FLAGS(["prog", *sys.argv[1:]])  # as absl.app.run parses, after the imports
    model = mjcf.RootElement()
    body = model.worldbody.add("body", name="b")
    print(mjcf.debugging.debug_mode(), bool(body.get_init_stack()),
          repr(mjcf.debugging.get_full_dump_dir()))
""")


@pytest.mark.skipif(harness.mjcf_folder() is None, reason="dm_control is not installed")
@pytest.mark.parametrize(("arguments", "expected"), [
    ([], "False False ''"),
    (["--pymjcf_debug"], "True True ''"),
    (["--pymjcf_debug", "--pymjcf_debug_full_dump_dir=/x"], "True True '/x'"),
])
def test_debug_mode_follows_dm_controls_flags(arguments: list[str], expected: str) -> None:
    """dm_control defines --pymjcf_debug and reads it when the first element is made."""
    run = subprocess.run([sys.executable, "-c", _FLAG_PROBE, *arguments], capture_output=True,
                         text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == expected


def test_a_refused_model_names_where_its_element_was_made_and_set(dm: None) -> None:
    debugging.enable_debug_mode()
    try:
        model = mjcf.RootElement(model="m")
        model.worldbody.add_body(name="b").add_joint(name="j")
        motor = model.actuator.add_motor(name="drive", joint="j")
        motor.joint = "nowhere"
        with pytest.raises(mjcf.ValidationError) as caught:
            mjcf.Physics.from_mjcf_model(model)
    finally:
        debugging.disable_debug_mode()
    lines = str(caught.value).splitlines()
    where = f"`test_a_refused_model_names_where_its_element_was_made_and_set` at {__file__}"
    assert lines[-3:] == [
        f"  * Element object was created by {where}:{_line_of('motor = model.actuator.add')}",
        '  * name="drive" was set when the element was created',
        f'  * joint="nowhere" was set by {where}:{_line_of("motor.joint = ")}',
    ]
    assert caught.value.findings[0].element is motor  # the same error, findings kept
    debugging.disable_debug_mode()
    with pytest.raises(mjcf.ValidationError, match="run again with --pymjcf_debug"):
        mjcf.Physics.from_mjcf_model(model)


def test_without_dm_controls_behaviour_errors_are_unchanged() -> None:
    model = mjcf.RootElement(model="m")
    model.actuator.add_motor(name="drive", joint="nowhere")
    with pytest.raises(mjcf.ValidationError) as caught:
        mjcf.Physics.from_mjcf_model(model)
    assert "pymjcf" not in str(caught.value)


def _line_of(text: str) -> int:
    lines = Path(__file__).read_text(encoding="utf-8").splitlines()
    return next(i for i, line in enumerate(lines, 1) if text in line and "_line_of" not in line)


# ---------------------------------------------------------------------------- spec, add, copies


def test_element_spec_has_dm_controls_shape() -> None:
    model = mjcf.RootElement(model="m")
    geom = model.default.geom  # a <geom> in a default class: its own grammar row
    assert (geom.spec.name, geom.spec.row) == ("geom", "default_geom")
    body = model.worldbody.add_body(name="b")
    assert list(body.spec.attributes)[:2] == ["name", "childclass"]
    assert body.spec.attributes["pos"].kind == "real" and body.spec.identifier == "name"
    assert body.spec.namespace == "body" and model.default.spec.identifier == "class"
    children = body.spec.children
    assert children["geom"].repeated and not children["inertial"].repeated
    assert children["inertial"] == body.add_inertial(mass=1).spec
    assert children["inertial"] != body.add_geom(size=(1,)).spec
    assert children["geom"].attributes is body.geom[0].spec.attributes
    assert not children["inertial"].on_demand  # the typed API makes it on first access
    with installed():
        assert children["inertial"].on_demand and not model.spec.children["option"].on_demand


def test_get_children_lists_dm_controls_eager_children(dm: None) -> None:
    model = mjcf.RootElement(model="m")
    tags = [child.tag for child in model.get_children()]
    assert {"compiler", "option", "default", "worldbody", "actuator"} <= set(tags)
    assert model.worldbody.add_body().get_children() == []  # inertial is on demand
    with pytest.raises(mjcf.ChildError, match="a <compiler> child already exists"):
        model.add("compiler")


def test_typed_children_exist_once_used() -> None:
    model = mjcf.RootElement(model="m")
    assert model.get_children() == []
    assert model.add("compiler", angle="radian").angle == "radian"


def test_add_takes_dm_controls_keyword_for_the_tag(dm: None) -> None:
    body = mjcf.RootElement(model="m").worldbody.add("body")
    geom = body.add(element_name="geom", size=[0.1], name="g")
    assert geom.tag == "geom" and geom.name == "g"


def test_typed_add_takes_the_tag_first() -> None:
    body = mjcf.RootElement(model="m").worldbody.add_body()
    with pytest.raises(mjcf.InvalidTypeError, match="takes the child's tag first"):
        body.add(element_name="geom")  # type: ignore[call-arg]


def test_dir_lists_mjcf_spellings() -> None:
    visual = mjcf.RootElement(model="m").visual
    assert {"global", "global_"} <= set(dir(visual))
    assert "class" in dir(mjcf.RootElement(model="m").worldbody.add_geom(size=(1,)))


def test_the_models_own_default_class_is_named_by_its_prefix(dm: None) -> None:
    parent, child = mjcf.RootElement(model="p"), mjcf.RootElement(model="c")
    parent.attach(child)
    assert parent.default.full_identifier == "/"
    assert child.default.full_identifier == "c/"


def test_include_copy_keeps_the_files_of_the_copy(tmp_path: Path) -> None:
    source_folder = tmp_path / "source"
    (source_folder / "meshes").mkdir(parents=True)
    (source_folder / "meshes" / "box.stl").write_bytes(box_stl(0.2))
    (source_folder / "model.xml").write_text(
        '<mujoco><compiler meshdir="meshes"/><asset><mesh name="box" file="box.stl"/>'
        "</asset><worldbody><geom type='mesh' mesh='box'/></worldbody></mujoco>")
    source = mjcf.from_path(source_folder / "model.xml")
    target = mjcf.RootElement(model="t")
    target.include_copy(source)
    mesh = target.find("mesh", "box")
    assert mesh is not None and mesh.file == "box.stl"
    assert list(target.get_assets().values()) == [box_stl(0.2)]
    compiled = target.compile()
    assert compiled.nmesh == 1


def test_include_copy_of_a_file_named_alike_with_other_contents(tmp_path: Path) -> None:
    (tmp_path / "box.stl").write_bytes(box_stl(0.2))
    (tmp_path / "model.xml").write_text(
        '<mujoco><asset><mesh name="box" file="box.stl"/></asset></mujoco>')
    source = mjcf.from_path(tmp_path / "model.xml")
    target = mjcf.from_xml_string('<mujoco><asset><mesh name="other" file="box.stl"/>'
                                  "</asset></mujoco>", assets={"box.stl": box_stl(0.5)})
    target.include_copy(source)
    mesh = target.find("mesh", "box")
    assert mesh is not None and mesh.file == "box-2.stl"
    assert sorted(target.get_assets().values()) == sorted([box_stl(0.2), box_stl(0.5)])


@pytest.mark.skipif(harness.mjcf_folder() is None, reason="dm_control is not installed")
def test_dm_controls_private_binding_names(dm: None) -> None:
    from typed_mjcf.physics import EmptyBinding

    assert sys.modules["dm_control.mjcf.physics"]._EmptyBinding is EmptyBinding


def test_a_one_control_actuator_binds_as_its_row() -> None:
    model = mjcf.RootElement(model="m")
    joint = model.worldbody.add_body().add_joint(name="j")
    model.worldbody.body[0].add_geom(size=(0.1,))
    motor = model.actuator.add_motor(joint=joint, ctrlrange=(-1, 2), ctrllimited="true")
    physics = mjcf.Physics.from_mjcf_model(model)
    low, high = physics.bind(motor).ctrlrange
    assert (low, high) == (-1, 2) and physics.bind(motor).gear.shape == (6,)
    assert physics.bind([motor]).ctrlrange.shape == (1, 2)


def test_object_types_may_be_given_as_ints() -> None:
    """dm_control's enums (``mjbindings.enums.mjtObj``) are plain ints."""
    model = mjcf.RootElement(model="m")
    model.worldbody.add_site(name="s")
    physics = mjcf.Physics.from_mjcf_model(model)
    site = int(mujoco.mjtObj.mjOBJ_SITE)
    assert physics.model.name2id("s", site) == 0 and physics.model.id2name(0, site) == "s"
    with pytest.raises(mjcf.InvalidValueError, match="not a kind of MuJoCo object"):
        physics.model.name2id("s", 999)


def test_export_names_the_xml_after_the_model_as_dm_control_does(dm: None,
                                                                   tmp_path: Path) -> None:
    from dm_control import mjcf as dm_mjcf

    source = tmp_path / "humanoid.xml"
    source.write_text('<mujoco model="Humanoid"><worldbody><geom size="1"/></worldbody>'
                      "</mujoco>", encoding="utf-8")
    model = dm_mjcf.from_path(str(source))
    written = dm_mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert written == str(tmp_path / "out" / "Humanoid.xml")
    # the typed API's function names it after the file, switch or not
    assert mjcf.export_with_assets(model, tmp_path / "typed").endswith("humanoid.xml")
