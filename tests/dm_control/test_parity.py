"""What a dm_control.mjcf user relies on, gap by gap (issue 13), checked against typed_mjcf;
where dm_control is installed, the same code is run against it too (its public API is the
reference)."""

from __future__ import annotations

import copy
import io
import os
import zipfile
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl

from . import harness

ASSETS = harness.mjcf_folder()
TEST_MODEL = None if ASSETS is None else ASSETS / "test_assets" / "test_model.xml"
needs_assets = pytest.mark.skipif(ASSETS is None, reason="dm_control is not installed")


def mesh_model(name: str, contents: bytes) -> mjcf.RootElement:
    model = mjcf.RootElement(name)
    mesh = model.asset.add_mesh(name="shape", file=mjcf.Asset(contents, ".stl", name="shape"))
    model.worldbody.add_body(name="b").add_geom(type="mesh", mesh=mesh)
    return model


# 1. assets with the XML text


def test_in_memory_assets_and_the_text_pair_are_safe() -> None:
    world = mjcf.RootElement("world")
    world.attach(mesh_model("small", box_stl(0.1)))
    world.attach(mesh_model("large", box_stl(0.3)))
    text, assets = world.to_xml_string(), world.get_assets()
    assert sorted(assets) == ["shape-2.stl", "shape.stl"]
    m = mujoco.MjModel.from_xml_string(text, assets)
    extents = sorted(round(float(np.ptp(m.mesh_vert[m.mesh_vertadr[i]:m.mesh_vertadr[i]
                                                    + m.mesh_vertnum[i]], axis=0)[0]), 6)
                     for i in range(m.nmesh))
    assert extents == [0.2, 0.6]
    assert world.compile().nmesh == 2


# 2. in-memory loading and zips


@needs_assets
def test_loading_from_memory_and_zips(tmp_path: Path) -> None:
    assert TEST_MODEL is not None
    texture = (TEST_MODEL.parent / "textures" / "deepmind.png").read_bytes()
    xml = TEST_MODEL.read_text(encoding="utf-8")
    elsewhere = tmp_path / "elsewhere"  # where the texture file is not
    elsewhere.mkdir()
    model = mjcf.from_xml_string(xml, model_dir=str(elsewhere),
                                 assets={"textures/deepmind.png": texture})
    assert list(model.get_assets().values()) == [texture]
    with open(TEST_MODEL, encoding="utf-8") as handle:
        assert mjcf.from_file(handle).is_same_as(model)
    archive = mjcf.export_with_assets_as_zip(model, tmp_path, "packed")
    with zipfile.ZipFile(archive) as zf:
        assert sorted(zf.namelist()) == ["packed/deepmind.png", "packed/packed.xml"]
    for source in (archive, io.BytesIO(Path(archive).read_bytes())):
        unzipped = mjcf.from_zip(source)
        assert unzipped.worldbody.is_same_as(model.worldbody)
        assert list(unzipped.get_assets().values()) == [texture]
    with pytest.raises(OSError, match="cannot read"):  # dm_control's IOError
        mjcf.from_xml_string('<mujoco><include file="missing.xml"/></mujoco>')


# 3. attachment scoping


def test_frame_joints_are_scoped_to_their_attached_model() -> None:
    world = mjcf.RootElement("world")
    frames = [world.attach(mjcf.RootElement(f"s{i}")) for i in (1, 2)]
    for frame in frames:
        frame.add_joint(name="root_x", type="slide", axis=(1, 0, 0))
    text = world.to_xml_string()
    assert 'name="s1/root_x"' in text and 'name="s2/root_x"' in text
    assert world.find("joint", "s2/root_x") is frames[1].joint[0]
    inner = mjcf.RootElement("inner")
    nested = frames[0].attach(inner)
    with pytest.raises(AttributeError, match="not a valid child"):
        nested.add_freejoint()


@needs_assets
def test_skins_of_attached_models_have_their_bones_scoped() -> None:
    assert ASSETS is not None
    rodent = ASSETS.parent / "locomotion" / "walkers" / "assets" / "rodent.xml"
    world = mjcf.RootElement("world")
    world.worldbody.add_geom(type="plane", size=(1, 1, 1))
    walker = mjcf.from_path(rodent)
    world.attach(walker)
    for m in (world.compile(),
              mujoco.MjModel.from_xml_string(world.to_xml_string(), world.get_assets())):
        bone = int(m.skin_bonebodyid[0])
        assert mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, bone).startswith(
            f"{walker.model}/")


def test_polymorphic_references_of_attached_models_are_scoped() -> None:
    arm = mjcf.RootElement("arm")
    link = arm.worldbody.add_body(name="link")
    link.add_geom(size=(0.1,))
    tip = link.add_site(name="tip")
    arm.sensor.add_framepos(objtype="site", objname="tip", reftype="body", refname="link")
    world = mjcf.RootElement("world")
    world.attach(arm)
    assert '<framepos objtype="site" objname="arm/tip" reftype="body" refname="arm/link"/>' in (
        world.to_xml_string())
    assert arm.sensor.framepos[0].objname is tip
    assert world.compile().nsensor == 1


# 4. find and find_all anywhere


def _test_model_with_its_copy_attached() -> tuple[mjcf.RootElement, mjcf.RootElement,
                                                   mjcf.Element]:
    """dm_control's test model ("model") with a copy of itself ("submodel") attached."""
    assert TEST_MODEL is not None
    model = mjcf.from_path(TEST_MODEL)
    model.model = "model"
    sub = copy.copy(model)
    sub.model = "submodel"
    return model, sub, model.attach(sub)


@needs_assets
def test_find_anywhere_and_nameless_assets() -> None:
    assert ASSETS is not None
    model, _, frame = _test_model_with_its_copy_attached()
    b_0 = model.find("body", "b_0")
    b_1 = model.find("body", "b_1")
    assert b_0 is not None and b_1 is not None
    assert b_0.find("geom", "b_0_0") is not None and b_1.find("geom", "b_0_0") is None
    assert model.find("attachment_frame", "submodel") is frame
    assert len(b_0.find_all("joint", immediate_children_only=True)) == 1
    assert len(model.find_all("geom")) == 2 * len(model.find_all("geom", exclude_attachments=True))
    nameless = mjcf.from_path(ASSETS / "test_assets" / "model_with_nameless_assets.xml")
    assert nameless.find("mesh", "cube") is not None
    assert nameless.find("texture", "deepmind") is not None


# 5. views include attachments


@needs_assets
def test_views_include_attachments() -> None:
    model, sub, frame = _test_model_with_its_copy_attached()
    actuators = model.actuator.get_children()
    assert all(a in actuators for a in sub.actuator.get_children())
    assert 'name="submodel/b_0_0"' in model.actuator.to_xml_string()
    assert frame.all_children() == sub.worldbody.all_children()


# 6. live child lists


def test_child_lists_are_live_views() -> None:
    model = mjcf.RootElement()
    for i in range(3):
        model.worldbody.add_body(name=f"b_{i}")
    assert model.worldbody.body["b_1"].name == "b_1"
    del model.worldbody.body[0]
    assert [b.name for b in model.worldbody.body] == ["b_1", "b_2"]
    assert model.find("body", "b_0") is None


# 7. defaults


def test_commit_defaults_and_resolve_agree_with_mujoco() -> None:
    root = mjcf.RootElement()
    root.default.general.forcelimited = "true"
    root.default.motor.forcerange = (-2, 3)
    arm = root.default.add_default(dclass="arm")
    arm.geom.size = (0.2,)
    body = root.worldbody.add_body()
    joint = body.add_joint(name="j")
    geom = body.add_geom(dclass=arm)  # a class given as an element
    motor = root.actuator.add_motor(joint=joint)
    assert motor.resolve("forcelimited") == "true"  # a <general> default applies to <motor>
    m = root.compile()
    assert list(m.actuator_forcerange[0]) == [-2, 3]
    size = geom.resolve("size")
    assert size is not None and float(size[0]) == 0.2
    assert float(m.geom_size[0, 0]) == 0.2
    mjcf.commit_defaults(geom)
    assert geom.size is not None and geom.size.tolist() == [0.2]


# 8. elements where names are expected


def test_elements_given_where_names_are_expected() -> None:
    root = mjcf.RootElement("model_1")
    body = root.worldbody.add_body()
    body.add_geom(size=(0.1,))
    sensor = root.sensor.add_framepos(objtype="body", objname=body)
    other = mjcf.RootElement("model_2")
    frame = root.attach(other)
    frame_sensor = root.sensor.add_framelinacc(objtype="body", objname=frame)
    text = root.to_xml_string()
    assert 'objname="unnamed_body_0"' in text and 'name="unnamed_body_0"' in text
    assert str(frame_sensor) == '<framelinacc objtype="body" objname="model_2/"/>'
    assert sensor.objname is body and root.compile().nsensor == 2
    with pytest.raises(ValueError, match="namespace"):  # dm_control: ValueError
        root.actuator.add_motor(joint=body)  # type: ignore[arg-type]  # deliberately wrong


# 9. dm_control's API names


@needs_assets
def test_dm_control_api_names(tmp_path: Path) -> None:
    model = mjcf.RootElement("named")
    assert model.model == "named"
    model.worldbody.add_body(name="a")
    model.worldbody.insert("body", position=0, name="first")
    assert [b.name for b in model.worldbody.body] == ["first", "a"]
    geom = model.worldbody.body[0].add_geom(dclass="main", size=(0.1,))
    assert geom.dclass == "main" and "dclass" in geom.get_attributes()
    assert str(model.worldbody.body[0]) == '<body name="first">...</body>'
    with pytest.raises(ValueError, match="must end with '.xml'"):
        mjcf.export_with_assets(model, tmp_path, out_file_name="model.png")
    assert os.path.isfile(mjcf.export_with_assets(model, tmp_path, out_file_name="m.xml"))
    child = mjcf.RootElement("child")
    frame = model.attach(child)
    assert child.parent_model is model and child.root_model is model
    assert mjcf.get_attachment_frame(child) is frame
    assert model.enter_scope("child") is child
    assert child.full_identifier == "child/"
    free = frame.add_freejoint()
    assert mjcf.get_frame_freejoint(frame) is free and mjcf.get_frame_joints(frame) == [free]
    assert geom.is_same_as(copy.deepcopy(geom)) and not geom.is_removed
    geom.remove()
    assert geom.is_removed
    assert ASSETS is not None
    separated = mjcf.from_path(ASSETS / "test_assets" / "model_with_separators.xml",
                               escape_separators=True)
    assert all("\\/" in g.name for g in separated.find_all("geom") if g.name and "/" in g.name)


# 10. small semantics


def test_small_semantics() -> None:
    model = mjcf.RootElement("m")
    body = model.worldbody.add_body(name="b", pos=(1, 2, 3))
    body.pos = ""  # type: ignore[assignment]  # clears, as in dm_control (typed: None)
    assert body.pos is None
    with pytest.raises(ValueError, match="world body"):
        model.worldbody.add_body(name="world")
    sub = mjcf.RootElement("sub")
    sub.option.timestep = 0.001
    model.attach(sub)
    with pytest.raises(ValueError, match=r"remove\(affect_attachments=True\)"):
        del model.option
    model.option.remove(affect_attachments=True)
    assert sub.option.timestep is None


# 11. global settings on attach


def test_global_settings_on_attach() -> None:
    model_1 = mjcf.RootElement()
    model_1.size.memory = "10000"
    model_2 = mjcf.RootElement()
    model_2.size.memory = "1M"
    model_2.compiler.angle = "radian"
    model_1.attach(model_2)
    assert model_1.size.memory == "1048576" and model_1.compiler.angle == "radian"
    model_3 = mjcf.RootElement("third")
    model_3.compiler.angle = "degree"
    with pytest.raises(ValueError, match="Conflicting values for attribute `angle`"):
        model_1.attach(model_3)


# 12. names with '/'


@needs_assets
def test_names_with_separators_load_and_round_trip() -> None:
    assert ASSETS is not None
    path = ASSETS / "test_assets" / "model_with_separators.xml"
    model = mjcf.from_path(path)
    names = [g.name for g in model.find_all("geom") if g.name]
    assert any("/" in n for n in names)
    assert all(model.find("geom", n) is not None for n in names)
    again = mjcf.from_xml_string(model.to_xml_string(), model_dir=str(path.parent))
    assert [g.name for g in again.find_all("geom") if g.name] == names
    with pytest.raises(ValueError, match="without '/'"):
        model.worldbody.add_body(name="a/b")


# 13. exception classes


def test_exception_classes_are_dm_controls() -> None:
    model = mjcf.RootElement()
    with pytest.raises(AttributeError):
        model.worldbody.add("motor")
    with pytest.raises(AttributeError):
        model.worldbody = None  # type: ignore[misc, assignment]
    with pytest.raises(ValueError):
        model.worldbody.add_body(name=7)  # type: ignore[arg-type]
    with pytest.raises(ValueError):
        model.sensor.add_jointpos(joint=model.worldbody.add_body())  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="already exists"):
        model.add("compiler")
        model.add("compiler")
