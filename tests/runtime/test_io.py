"""Export options, parsing (errors, includes, folders), assets and the MuJoCo bridge."""

from __future__ import annotations

import io
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf.errors import ExportError

# ----------------------------------------------------------------------------- export


def test_floats_are_written_in_the_shortest_exact_form() -> None:
    model = mjcf.RootElement()
    body = model.worldbody.add_body(pos=(0.1, 1 / 3, 1e-7))
    body.add_geom(size=(0.05,), rgba=(0.1, 0.2, 0.3, 1))
    xml = model.to_xml_string()
    assert 'pos="0.1 0.3333333333333333 1e-07"' in xml
    assert 'rgba="0.1 0.2 0.3 1"' in xml  # float32 attribute, shortest float32 text
    parsed = mjcf.from_xml_string(xml)
    pos = parsed.worldbody.body[0].pos
    assert pos is not None and pos.tolist() == [0.1, 1 / 3, 1e-7]  # bit for bit


def test_precision_zero_threshold_and_pretty_print() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(pos=(1 / 3, 1e-12, 2.0))
    assert 'pos="0.333 1e-12 2"' in model.to_xml_string(precision=3)
    assert 'pos="0.3333333333333333 0 2"' in model.to_xml_string(zero_threshold=1e-9)
    compact = model.to_xml_string(pretty_print=False)
    assert "\n" not in compact.strip()
    assert model.to_xml().tag == "mujoco"


def test_output_is_plain_mjcf() -> None:
    model = mjcf.RootElement(model="m")
    model.worldbody.add_body().add_geom(size=(0.1,))
    xml = model.to_xml_string()
    assert 'class="/"' not in xml and "name=" not in xml.replace('model="m"', "")


def test_reference_to_an_unnamed_element_cannot_be_exported() -> None:
    model = mjcf.RootElement()
    joint = model.worldbody.add_body().add_joint(name="j")
    model.actuator.add_motor(joint=joint)
    joint.name = None
    with pytest.raises(mjcf.ExportError, match="no name"):
        model.to_xml_string()


# ----------------------------------------------------------------------------- parse


def test_parse_converts_every_value() -> None:
    model = mjcf.from_xml_string(
        '<mujoco model="m"><worldbody><body name="b" pos="1 2 3">'
        '<joint name="j" type="slide" limited="true" range="-1 1" group="2"/>'
        '<geom size=".1" rgba="1 0 0 1"/></body></worldbody></mujoco>')
    joint = model.find("joint", "j")
    assert joint is not None
    assert joint.type == "slide" and joint.limited == "true" and joint.group == 2
    assert joint.range is not None and joint.range.tolist() == [-1.0, 1.0]
    assert isinstance(model.worldbody.body[0], mjcf.Body)


@pytest.mark.parametrize(("xml", "pattern"), [
    ("<mujoco><worldbody><body></worldbody></mujoco>", r"line 1: malformed XML"),
    ("<mujoco>\n<worldbody>\n<bodyy/></worldbody></mujoco>", r"line 3: <bodyy> is not a legal.*did you mean 'body'"),
    ("<mujoco>\n<worldbody><body poss='1 2 3'/></worldbody></mujoco>", r"line 2: worldbody/body\[0\]: <body> has no attribute 'poss'.*did you mean 'pos'"),
    ("<mujoco>\n\n<worldbody><geom size='1 2 3 4'/></worldbody></mujoco>", r"line 3: .*expected 1 to 3 numbers"),
    ("<mujoco><worldbody><body name='a'/><body name='a'/></worldbody></mujoco>", r"unique"),
    ("<robot/>", r"root element is <robot>"),
    ("<mujoco>\n<worldbody><geom type='Box'/></worldbody></mujoco>",
     r"line 2: .*type='Box'.*expected 'box' \(MuJoCo reads keywords only as"),
])
def test_parse_errors_are_the_library_error_with_a_line(xml: str, pattern: str) -> None:
    with pytest.raises(mjcf.ParseError, match=pattern):
        mjcf.from_xml_string(xml)


def test_repeated_sections_merge_in_document_order() -> None:
    model = mjcf.from_xml_string(
        "<mujoco><worldbody><body name='a'/></worldbody><option timestep='0.01'/>"
        "<worldbody><body name='b'/></worldbody><option gravity='0 0 0'/></mujoco>")
    assert [b.name for b in model.worldbody.body] == ["a", "b"]
    assert model.option.timestep == 0.01
    assert model.option.gravity is not None and model.option.gravity.tolist() == [0, 0, 0]


def test_include_is_expanded_in_place_anywhere(tmp_path: Path) -> None:
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "legs.xml").write_text(
        "<mujoco><body name='leg1'><joint name='j1'/><geom size='.1'/></body>"
        "<body name='leg2'><joint name='j2'/><geom size='.1'/></body></mujoco>")
    (tmp_path / "robot.xml").write_text(
        "<mujoco><worldbody><body name='torso'><geom size='.1'/>"
        "<include file='parts/legs.xml'/>"
        "<body name='tail'><joint name='j3'/><geom size='.1'/></body>"
        "</body></worldbody></mujoco>")
    model = mjcf.from_path(tmp_path / "robot.xml")
    torso = model.find("body", "torso")
    assert torso is not None
    assert [b.name for b in torso.body] == ["leg1", "leg2", "tail"]
    original = mujoco.MjModel.from_xml_path(str(tmp_path / "robot.xml"))
    compiled = model.compile()
    assert compiled.njnt == original.njnt == 3
    assert [compiled.joint(i).id for i in range(3)] == [0, 1, 2]


def test_include_errors_name_the_files(tmp_path: Path) -> None:
    (tmp_path / "a.xml").write_text("<mujoco><include file='b.xml'/></mujoco>")
    (tmp_path / "b.xml").write_text("<mujoco><include file='a.xml'/></mujoco>")
    (tmp_path / "main.xml").write_text("<mujoco>\n<include file='a.xml'/></mujoco>")
    with pytest.raises(mjcf.ParseError, match="a.xml.*b.xml.*a.xml"):
        mjcf.from_path(tmp_path / "main.xml")
    (tmp_path / "missing.xml").write_text("<mujoco>\n<include file='nope.xml'/></mujoco>")
    with pytest.raises(mjcf.ParseError, match=r"missing.xml:2: .*nope.xml"):
        mjcf.from_path(tmp_path / "missing.xml")


def test_from_file_reads_an_open_file() -> None:
    model = mjcf.from_file(io.StringIO("<mujoco model='x'/>"))
    assert model.model == "x"


# ----------------------------------------------------------------------------- assets


def test_meshdir_is_honoured_and_files_travel_through_the_vfs(tmp_path: Path) -> None:
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "box.stl").write_bytes(box_stl())
    (tmp_path / "model.xml").write_text(
        "<mujoco><compiler meshdir='meshes'/><asset><mesh name='box' file='box.stl'/></asset>"
        "<worldbody><body><freejoint/><geom type='mesh' mesh='box'/></body></worldbody></mujoco>")
    model = mjcf.from_path(tmp_path / "model.xml")
    assert model.get_assets() == {"box.stl": box_stl()}
    compiled = model.compile()
    original = mujoco.MjModel.from_xml_path(str(tmp_path / "model.xml"))
    assert np.array_equal(compiled.mesh_vert, original.mesh_vert)  # type: ignore[attr-defined]


def test_in_memory_assets_compile_and_export_with_readable_names(tmp_path: Path) -> None:
    model = mjcf.RootElement(model="boxy")
    mesh = model.asset.add_mesh(name="cube", file=mjcf.Asset(box_stl(), ".stl"))
    body = model.worldbody.add_body()
    body.add_freejoint()
    body.add_geom(type="mesh", mesh=mesh)
    text = model.to_xml_string()
    assert 'file="cube.stl"' in text  # the name get_assets() gives it: the pair loads
    assert model.get_assets() == {"cube.stl": box_stl()}
    assert mujoco.MjModel.from_xml_string(text, model.get_assets()).nmesh == 1
    assert model.compile().nmesh == 1
    path = mjcf.export_with_assets(model, tmp_path / "out")
    assert Path(path).name == "boxy.xml"
    assert (tmp_path / "out" / "cube.stl").read_bytes() == box_stl()
    assert mujoco.MjModel.from_xml_path(path).nmesh == 1
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")]


def test_different_files_with_the_same_name_get_distinct_names() -> None:
    model = mjcf.RootElement()
    model.asset.add_mesh(name="a", file=mjcf.Asset(box_stl(0.1), ".stl", name="part"))
    model.asset.add_mesh(name="b", file=mjcf.Asset(box_stl(0.2), ".stl", name="part"))
    model.asset.add_mesh(name="c", file=mjcf.Asset(box_stl(0.1), ".stl", name="part"))
    assert sorted(model.get_assets()) == ["part-2.stl", "part.stl"]


def test_attached_models_files_of_the_same_name_never_collide(tmp_path: Path) -> None:
    """Each model's own file, though both are called shape.stl: the text names each by its
    absolute path, compile() keeps them apart by folder (MuJoCo's dict route goes by base
    name)."""
    world = mjcf.RootElement(model="world")
    for n, size in ((1, 0.1), (2, 0.3)):
        folder = tmp_path / f"part{n}"
        folder.mkdir()
        (folder / "shape.stl").write_bytes(box_stl(size))
        part = mjcf.from_xml_string(
            '<mujoco model="p"><asset><mesh name="m" file="shape.stl"/></asset><worldbody>'
            '<body><geom type="mesh" mesh="m"/></body></worldbody></mujoco>',
            model_dir=str(folder))
        part.model = f"part{n}"
        world.attach(part)
    text, assets = world.to_xml_string(), world.get_assets()
    assert sorted(assets) == ["part1/shape.stl", "part2/shape.stl"]  # apart by folder
    with pytest.raises(ExportError, match="'part1/shape.stl' and 'part2/shape.stl'"):
        world.get_assets(flat=True)  # what MuJoCo's dict route cannot hold
    pair = mujoco.MjModel.from_xml_string(text)  # an attached model's files: absolute paths
    compiled = world.compile()
    for m in (pair, compiled):
        sizes = [float(np.ptp(m.mesh_vert[m.mesh_vertadr[i]:m.mesh_vertadr[i] + m.mesh_vertnum[i]],
                              axis=0)[0]) for i in range(m.nmesh)]
        assert sorted(round(x, 6) for x in sizes) == [0.2, 0.6]


# ----------------------------------------------------------------------------- bridge


def test_compile_validates_first_and_reraises_mujoco_errors_with_the_element_path() -> None:
    model = mjcf.RootElement()
    model.actuator.add_motor(joint="nonexistent")
    with pytest.raises(mjcf.ValidationError, match=r"actuator/motor\[0\]: unresolved-reference"):
        model.compile()
    model = mjcf.RootElement()
    body = model.worldbody.add_body(name="massless")
    body.add_joint(name="hinge")  # a moving body with no mass: only MuJoCo knows
    with pytest.raises(mjcf.CompileError, match=r"(?s)mass and inertia.*worldbody/body\[massless\]"):
        model.compile()


def test_to_spec_and_from_spec() -> None:
    model = mjcf.RootElement(model="arm")
    body = model.worldbody.add_body(name="b")
    body.add_joint(name="j")
    body.add_geom(size=(0.1,))
    spec = model.to_spec()
    assert isinstance(spec, mujoco.MjSpec)
    back = mjcf.from_spec(spec)
    assert back.find("joint", "j") is not None
    assert back.compile().njnt == 1


def test_export_names_the_xml_after_the_file_the_model_was_read_from(tmp_path: Path) -> None:
    source = tmp_path / "humanoid.xml"
    source.write_text('<mujoco model="Humanoid"><worldbody><geom size="1"/></worldbody>'
                      "</mujoco>", encoding="utf-8")
    read = mjcf.from_path(source)
    assert mjcf.export_with_assets(read, tmp_path / "a") == str(tmp_path / "a" / "humanoid.xml")
    assert mjcf.export_with_assets(read, tmp_path / "b", "robot.xml").endswith("robot.xml")
    # built in Python, or read from text: named after the model
    built = mjcf.RootElement(model="Humanoid")
    assert mjcf.export_with_assets(built, tmp_path / "c").endswith("Humanoid.xml")
    text = mjcf.from_xml_string(source.read_text(encoding="utf-8"))
    assert mjcf.export_with_assets(text, tmp_path / "d").endswith("Humanoid.xml")
