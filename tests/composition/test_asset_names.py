"""What the text of ``to_xml_string()`` names for each file, and how ``get_assets()`` keys it
(README, "File names"): files as the source names them, keys by base name, which is how
MuJoCo's in-memory loader finds a file (two different files of one base name: by their path,
which MjSpec's assets hold apart). The routes load the model ``compile()`` gives:
``MjModel.from_xml_string(text, get_assets())``, and the text saved beside its source."""

from __future__ import annotations

import re
from pathlib import Path
from xml.sax.saxutils import quoteattr

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.compare import model_differences
from tests.support.meshes import box_stl, tetra_obj
from typed_mjcf.errors import ExportError


def write(folder: Path, files: dict[str, bytes], xml: str) -> Path:
    for relative, contents in files.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_bytes(contents)
    path = folder / "model.xml"
    path.write_text(xml, encoding="utf-8")
    return path


MESHES = """<mujoco model="m">
  <compiler meshdir="assets"/>
  <asset>{meshes}</asset>
  <worldbody>{geoms}</worldbody>
</mujoco>"""


def model_with(folder: Path, files: dict[str, bytes]) -> Path:
    meshes = "".join(f'<mesh name="m{i}" file="{f.removeprefix("assets/")}"/>'
                     for i, f in enumerate(files))
    geoms = "".join(f'<geom type="mesh" mesh="m{i}" pos="{i} 0 0"/>' for i in range(len(files)))
    return write(folder, files, MESHES.format(meshes=meshes, geoms=geoms))


def both_routes(model: mjcf.RootElement, source: Path) -> tuple[str, dict[str, bytes]]:
    """Check both routes against ``compile()``; the text and the files."""
    compiled = model.compile()
    text, assets = model.to_xml_string(), model.get_assets()
    assert model_differences(compiled, mujoco.MjModel.from_xml_string(text, assets)) == []
    beside = source.with_name("edited.xml")
    beside.write_text(text, encoding="utf-8")
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(str(beside))) == []
    return text, assets


def test_files_are_named_as_the_source_names_them(tmp_path: Path) -> None:
    source = model_with(tmp_path, {"assets/a.stl": box_stl(0.1),
                                   "assets/parts/b.obj": tetra_obj(1, 1, 1),
                                   "c.stl": box_stl(0.3)})
    source.write_text(source.read_text().replace('file="c.stl"', 'file="../c.stl"'))
    text, assets = both_routes(mjcf.from_path(source), source)
    assert 'meshdir="assets"' in text
    for file in ('file="a.stl"', 'file="parts/b.obj"', 'file="../c.stl"'):
        assert file in text
    assert sorted(assets) == ["a.stl", "b.obj", "c.stl"]


def test_one_file_in_two_folders_is_one_asset(tmp_path: Path) -> None:
    """dm_control's model_with_assets.xml: cube.stl and more_meshes/cube.stl, the same
    bytes. Both keep their paths; get_assets() holds the file once."""
    cube = box_stl(0.1)
    source = model_with(tmp_path, {"assets/cube.stl": cube, "assets/more/cube.stl": cube,
                                   "assets/more/Cube.stl": cube})
    text, assets = both_routes(mjcf.from_path(source), source)
    assert 'file="more/cube.stl"' in text and 'file="more/Cube.stl"' in text
    assert assets == {"cube.stl": cube}


def test_two_different_files_of_one_name(tmp_path: Path) -> None:
    """MuJoCo's in-memory loader from a dict finds files by base name and refuses two keys
    that differ in their folders only; MjSpec's assets keep them apart by path. The text names
    both as the source does (it loads beside the source), compile() and get_assets() keep them
    apart by their path below the model's folder, and the exported folder keeps the folders."""
    source = model_with(tmp_path, {"assets/torso/base_link.stl": box_stl(0.1),
                                   "assets/gripper/base_link.stl": box_stl(0.2)})
    with pytest.raises(ValueError, match="Repeated file name"):  # why not the dict route
        mujoco.MjModel.from_xml_string("<mujoco/>", {"a/cube.stl": b"1", "b/cube.stl": b"2"})
    model = mjcf.from_path(source)
    compiled = model.compile()
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(str(source))) == []
    text, assets = model.to_xml_string(), model.get_assets()
    assert 'file="torso/base_link.stl"' in text and 'file="gripper/base_link.stl"' in text
    assert assets == {"assets/torso/base_link.stl": box_stl(0.1),
                      "assets/gripper/base_link.stl": box_stl(0.2)}
    beside = source.with_name("edited.xml")
    beside.write_text(text, encoding="utf-8")
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(str(beside))) == []
    spec = mujoco.MjSpec.from_string(text, assets=assets)
    assert model_differences(compiled, spec.compile()) == []
    physics = mjcf.Physics.from_xml_string(text, assets)  # dm_control's pair, through MjSpec
    assert np.array_equal(physics.model.geom_rbound, compiled.geom_rbound)
    assert physics.bind(model.find_all("geom")[1]).size is not None  # unnamed, found
    with pytest.raises(ExportError, match=(
            "'assets/torso/base_link.stl' and 'assets/gripper/base_link.stl' are different "
            "files with one base name")):
        model.get_assets(flat=True)
    exported = mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert (tmp_path / "out" / "assets" / "gripper" / "base_link.stl").read_bytes() == (
        box_stl(0.2))
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(exported)) == []


@pytest.mark.parametrize("first", ["torso", "gripper"])
def test_a_mesh_named_after_its_file_keeps_its_name(tmp_path: Path, first: str) -> None:
    """An unnamed mesh is named by MuJoCo after its file (``base_link``); another, earlier
    file of that base name must not rename it (as a ``-2`` suffix did): the geom naming it
    compiles, on every route (a real gripper model, its meshes' order swapped)."""
    order = [first, *({"torso", "gripper"} - {first})]
    files = {f"assets/{part}/base_link.stl": box_stl(0.1 if part == "torso" else 0.2)
             for part in order}
    meshes = ('<mesh name="torso" file="torso/base_link.stl"/>',
              '<mesh file="gripper/base_link.stl"/>')
    source = write(tmp_path, files, MESHES.format(
        meshes="".join(meshes if first == "torso" else meshes[::-1]),
        geoms='<body><freejoint/><geom type="mesh" mesh="torso"/>'
              '<geom type="mesh" mesh="base_link" pos="1 0 0"/></body>'))
    expected = mujoco.MjModel.from_xml_path(str(source))
    model = mjcf.from_path(source)
    assert model_differences(expected, model.compile()) == []
    physics = mjcf.Physics.from_mjcf_model(model)
    assert np.array_equal(physics.model.geom_rbound, expected.geom_rbound)
    exported = mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert model_differences(expected, mujoco.MjModel.from_xml_path(exported)) == []


def test_in_memory_contents_are_named_by_their_key(tmp_path: Path) -> None:
    source = model_with(tmp_path, {"assets/cube.stl": box_stl(0.1)})
    model = mjcf.from_path(source)
    model.asset.add_mesh(name="extra", file=mjcf.Asset(box_stl(0.2), ".stl", name="cube"))
    model.asset.add_mesh(name="same", file=mjcf.Asset(box_stl(0.1), ".stl", name="cube"))
    model.worldbody.add_geom(type="mesh", mesh="extra")
    model.worldbody.add_geom(type="mesh", mesh="same")
    compiled = model.compile()
    text, assets = model.to_xml_string(), model.get_assets()
    assert 'file="cube.stl"' in text and 'file="cube-2.stl"' in text
    assert assets == {"cube.stl": box_stl(0.1), "cube-2.stl": box_stl(0.2)}
    assert model_differences(compiled, mujoco.MjModel.from_xml_string(text, assets)) == []


def test_attached_models_from_other_folders(tmp_path: Path) -> None:
    """Each attached model's files resolve in its own folders: the text names them by their
    absolute path, so it loads beside the parent's source; get_assets() keys them by base
    name, and a file with the parent's bytes is the parent's."""
    parent_source = model_with(tmp_path / "parent", {"assets/cube.stl": box_stl(0.1)})
    child_source = write(tmp_path / "child", {"meshes/cube.stl": box_stl(0.1),
                                              "meshes/tip.obj": tetra_obj(1, 2, 3)}, """
<mujoco model="child">
  <compiler meshdir="meshes"/>
  <asset><mesh name="cube" file="cube.stl"/><mesh file="tip.obj"/></asset>
  <worldbody><body name="b"><geom type="mesh" mesh="cube"/><geom type="mesh" mesh="tip"/>
  </body></worldbody>
</mujoco>""")
    parent = mjcf.from_path(parent_source)
    parent.worldbody.attach(mjcf.from_path(child_source))
    text, assets = both_routes(parent, parent_source)
    assert f'file="{tmp_path / "child" / "meshes" / "tip.obj"}"' in text
    assert 'mesh="child/tip"' in text
    assert sorted(assets) == ["cube.stl", "tip.obj"]


TAB = {"\t": "&#9;"}  # (a tab written as such is read as a space)


@pytest.mark.parametrize("name", ['a"b.stl', ".dot.stl", " lead.stl", "a\tb.stl", "a|b.stl",
                                  "a:b.stl", "a&b'<c>.stl"])
def test_a_file_name_file_systems_differ_on_is_written_as_the_source_names_it(
        tmp_path: Path, name: str) -> None:
    """A name with characters Windows refuses (or a leading dot) is the source's name on
    every route (never a sanitised one, which names another file and renames the mesh MuJoCo
    names after it); the folder export, which cannot write it everywhere, refuses it."""
    (tmp_path / name).write_bytes(box_stl(0.1))
    source = tmp_path / "model.xml"
    source.write_text(
        f'<mujoco><asset><mesh file={quoteattr(name, TAB)}/></asset><worldbody>'
        f'<geom type="mesh" mesh={quoteattr(name.removesuffix(".stl"), TAB)}/></worldbody>'
        f'</mujoco>',
        encoding="utf-8")
    expected = mujoco.MjModel.from_xml_path(str(source))
    model = mjcf.from_path(source)
    assert model_differences(expected, model.compile()) == []
    beside = source.with_name("edited.xml")
    beside.write_text(model.to_xml_string(), encoding="utf-8")
    assert model_differences(expected, mujoco.MjModel.from_xml_path(str(beside))) == []
    assert list(model.get_assets()) == [name]
    with pytest.raises(ExportError, match=re.escape(
            f"asset/mesh[0]: file={name!r}: cannot export a file named {name!r}: expected a "
            f"name file systems take everywhere")):
        mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert not (tmp_path / "out").exists() or not list((tmp_path / "out").iterdir())
