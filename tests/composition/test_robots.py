"""Composing real-robot-shaped models the way people do, and loading what is exported again.

The arm, gripper and mobile base of :mod:`tests.composition.robots` (files written at test
time, each with its own mesh folder, default classes, keyframes and constraints of every kind)
are composed: the gripper at the arm's site, at one of its bodies, both at the world, nested
two deep (gripper on arm on rover), and two arms with a gripper each. Every composition

- compiles (``compile()``);
- loads again as ``MjModel.from_xml_string(to_xml_string(), get_assets())`` and from the
  folder ``export_with_assets()`` writes, to the same compiled model, field by field
  (:func:`tests.support.compare.model_differences`);
- has the keyframes of MuJoCo's own compile of each part, each part's values at its joints
  and actuators (found by name), MuJoCo's defaults where a part has no key of that name.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest
from lxml import etree

import typed_mjcf as mjcf
from tests.support.compare import model_differences
from typed_mjcf._core import tree as _tree
from typed_mjcf.errors import ExportError

from .robots import HAND_XML, Parts, body, site

Composition = tuple[mjcf.RootElement, dict[str, Path]]  # the model; each part's prefix -> file

QPOS_SIZE = {0: 7, 1: 4, 2: 1, 3: 1}  # mjtJoint: free, ball, slide, hinge
DOF_SIZE = {0: 6, 1: 3, 2: 1, 3: 1}


def at_site(parts: Parts) -> Composition:
    arm = parts.arm()
    site(arm, "attachment_site").attach(parts.hand())
    return arm, {"": parts.arm_path, "gripper/": parts.hand_path}


def at_body(parts: Parts) -> Composition:
    arm = parts.arm()
    frame = body(arm, "wrist").attach(parts.hand())
    frame.pos = (0.05, 0, 0)
    return arm, {"": parts.arm_path, "gripper/": parts.hand_path}


def at_world(parts: Parts) -> Composition:
    cell = mjcf.RootElement(model="cell")
    cell.worldbody.add_geom(name="floor", type="plane", size=(2, 2, 0.1))
    cell.worldbody.attach(parts.arm()).pos = (0, 0, 0.1)
    frame = cell.attach(parts.hand())  # a free gripper beside it, waiting on the table
    frame.pos = (0.4, 0.3, 0.2)
    frame.add_freejoint()
    return cell, {"arm/": parts.arm_path, "gripper/": parts.hand_path}


def nested(parts: Parts) -> Composition:
    rover, arm = parts.base(), parts.arm()
    site(arm, "attachment_site").attach(parts.hand())
    body(rover, "mount").attach(arm)
    return rover, {"": parts.base_path, "arm/": parts.arm_path,
                   "arm/gripper/": parts.hand_path}


def two_arms(parts: Parts) -> Composition:
    cell = mjcf.RootElement(model="cell")
    left = parts.arm()
    left.model = "left"
    site(left, "attachment_site").attach(parts.hand())
    right = copy.deepcopy(left)
    right.model = "right"
    cell.worldbody.add_site(name="left_mount", pos=(0, 0.3, 0))
    cell.worldbody.add_site(name="right_mount", pos=(0, -0.3, 0))
    site(cell, "left_mount").attach(left)
    site(cell, "right_mount").attach(right)
    return cell, {"left/": parts.arm_path, "left/gripper/": parts.hand_path,
                  "right/": parts.arm_path, "right/gripper/": parts.hand_path}


COMPOSITIONS: dict[str, Callable[[Parts], Composition]] = {
    "at_site": at_site, "at_body": at_body, "at_world": at_world, "nested": nested,
    "two_arms": two_arms}


# ----------------------------------------------------------------------------- oracle


def _named(m: mujoco.MjModel, kind: mujoco.mjtObj, count: int) -> list[str]:
    return [mujoco.mj_id2name(m, kind, i) or "" for i in range(count)]


def _owner(name: str, prefixes: list[str]) -> str:
    return max((p for p in prefixes if name.startswith(p)), key=len)


def expected_keys(m: mujoco.MjModel, parts: dict[str, Path]) -> dict[str, dict[str, object]]:
    """Each whole-model key as MuJoCo's compile of each part (from its own file) gives it."""
    alone = {prefix: mujoco.MjModel.from_xml_path(str(path)) for prefix, path in parts.items()}
    names: list[str] = []
    for part in alone.values():
        names += [n for n in _named(part, mujoco.mjtObj.mjOBJ_KEY, part.nkey) if n not in names]
    joints = _named(m, mujoco.mjtObj.mjOBJ_JOINT, m.njnt)
    actuators = _named(m, mujoco.mjtObj.mjOBJ_ACTUATOR, m.nactuator)
    expected: dict[str, dict[str, object]] = {}
    for key_name in names:
        qpos, qvel = np.array(m.qpos0), np.zeros(m.nv)
        ctrl, act = np.zeros(m.nu), np.zeros(m.na)
        time = 0.0
        for prefix, part in alone.items():
            k = mujoco.mj_name2id(part, mujoco.mjtObj.mjOBJ_KEY, key_name)
            if k < 0:
                continue
            time = float(part.key_time[k]) or time
            for j, name in enumerate(joints):
                if not name or _owner(name, list(parts)) != prefix:
                    continue
                pj = mujoco.mj_name2id(part, mujoco.mjtObj.mjOBJ_JOINT, name[len(prefix):])
                if pj < 0:
                    continue  # an attachment frame's joint: not the part's
                size, dofs = QPOS_SIZE[int(m.jnt_type[j])], DOF_SIZE[int(m.jnt_type[j])]
                a, pa = int(m.jnt_qposadr[j]), int(part.jnt_qposadr[pj])
                qpos[a:a + size] = part.key_qpos[k][pa:pa + size]
                a, pa = int(m.jnt_dofadr[j]), int(part.jnt_dofadr[pj])
                qvel[a:a + dofs] = part.key_qvel[k][pa:pa + dofs]
            for u, name in enumerate(actuators):
                if _owner(name, list(parts)) != prefix:
                    continue
                pu = mujoco.mj_name2id(part, mujoco.mjtObj.mjOBJ_ACTUATOR, name[len(prefix):])
                a, pa, n = (int(m.actuator_ctrladr[u]), int(part.actuator_ctrladr[pu]),
                            int(m.actuator_ctrlnum[u]))
                ctrl[a:a + n] = part.key_ctrl[k][pa:pa + n]
                a, pa, n = (int(m.actuator_actadr[u]), int(part.actuator_actadr[pu]),
                            int(m.actuator_actnum[u]))
                act[a:a + n] = part.key_act[k][pa:pa + n]
        expected[key_name] = {"qpos": qpos, "qvel": qvel, "ctrl": ctrl, "act": act,
                              "time": time}
    return expected


def assert_keys_as_each_part_says(m: mujoco.MjModel, parts: dict[str, Path]) -> None:
    expected = expected_keys(m, parts)
    assert _named(m, mujoco.mjtObj.mjOBJ_KEY, m.nkey) == list(expected)
    for k, (name, vectors) in enumerate(expected.items()):
        for field, want in vectors.items():
            got = getattr(m, f"key_{field}")[k]
            np.testing.assert_array_equal(got, want, err_msg=f"key {name!r}: {field}")


# ----------------------------------------------------------------------------- checks


def file_attributes(text: str) -> list[str]:
    """Every file a model's text names (``file`` and the cube-map ``file*`` attributes)."""
    root = etree.fromstring(text.encode())
    return [str(value) for element in root.iter() if isinstance(element.tag, str)
            for name, value in element.attrib.items() if str(name).startswith("file")]


def assert_loads_again(model: mjcf.RootElement, out: Path) -> mujoco.MjModel:
    """compile() is MuJoCo's model of the text written beside the source, of the text with
    get_assets() (MuJoCo's dict route where no two different files share a base name, else
    MjSpec's assets, which keep them apart), and of the exported folder."""
    compiled = model.compile()
    text, assets = model.to_xml_string(), model.get_assets()
    beside = Path(_tree.base_dir(model) or out.parent) / "typed-mjcf-written.xml"
    beside.write_text(text, encoding="utf-8")
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(str(beside))) == [], (
        "to_xml_string() beside the source")
    beside.unlink()
    apart = [key for key in assets if "/" in key]
    if apart:
        with pytest.raises(ExportError, match="one base name"):
            model.get_assets(flat=True)
    else:
        in_memory = mujoco.MjModel.from_xml_string(text, model.get_assets(flat=True))
        assert model_differences(compiled, in_memory) == [], "to_xml_string() + get_assets()"
    path = mjcf.export_with_assets(model, str(out))
    assert model_differences(compiled, mujoco.MjModel.from_xml_path(path)) == [], "exported"
    assert sorted(p.name for p in out.iterdir()) == sorted(
        {*(key.split("/")[0] for key in assets), Path(path).name})
    return compiled


@pytest.mark.parametrize("compose", list(COMPOSITIONS.values()), ids=list(COMPOSITIONS))
def test_composition_compiles_exports_and_loads_again(
        compose: Callable[[Parts], Composition], tmp_path: Path) -> None:
    model, parts = compose(Parts(tmp_path / "robots"))
    compiled = assert_loads_again(model, tmp_path / "export")
    assert compiled.neq == 5 * len([p for p in parts.values() if p.name != "rover.xml"])
    assert_keys_as_each_part_says(compiled, parts)


def test_the_parts_are_what_they_claim(tmp_path: Path) -> None:
    """Guards the fixtures: every equality kind, actuators taking several controls and
    activations, mesh folders, a shared and a clashing file name."""
    parts = Parts(tmp_path)
    arm = mujoco.MjModel.from_xml_path(str(parts.arm_path))
    assert sorted(set(arm.eq_type.tolist())) == sorted(
        int(t) for t in (mujoco.mjtEq.mjEQ_CONNECT, mujoco.mjtEq.mjEQ_WELD,
                         mujoco.mjtEq.mjEQ_JOINT, mujoco.mjtEq.mjEQ_TENDON,
                         mujoco.mjtEq.mjEQ_FLEX))
    assert (arm.nactuator, arm.nu, arm.na, arm.nkey) == (12, 15, 5, 2)
    hand = mujoco.MjModel.from_xml_path(str(parts.hand_path))
    assert int(mujoco.mjtEq.mjEQ_JOINT) in hand.eq_type.tolist() and hand.nkey == 1
    arm_files = (parts.arm_path.parent / "assets")
    hand_files = (parts.hand_path.parent / "meshes")
    assert (arm_files / "screw.stl").read_bytes() == (hand_files / "hardware/screw.stl").read_bytes()
    assert (arm_files / "base_link.stl").read_bytes() != (hand_files / "base_link.stl").read_bytes()


def test_a_parent_key_with_an_equality_joint_in_the_attached_model(tmp_path: Path) -> None:
    """The issue's case: the arm has a key, the gripper an <equality><joint> and no key; the
    combined key is the arm's with the gripper at qpos0, as MjSpec's attach gives it."""
    parts = Parts(tmp_path)
    keyless = parts.hand_path.with_name("gripper_keyless.xml")
    start = HAND_XML.index("  <keyframe>")
    keyless.write_text(HAND_XML[:start] + "</mujoco>\n", encoding="utf-8")
    arm = parts.arm()
    site(arm, "attachment_site").attach(mjcf.from_path(keyless))
    ours = arm.compile()
    spec = mujoco.MjSpec.from_file(str(parts.arm_path))
    spec.attach(mujoco.MjSpec.from_file(str(keyless)), prefix="gripper/",
                site=spec.site("attachment_site"))
    theirs = spec.compile()
    assert (ours.nkey, ours.nq, ours.nu) == (theirs.nkey, theirs.nq, theirs.nu) == (2, 13, 17)
    for field in ("key_qpos", "key_qvel", "key_ctrl", "key_act", "key_time"):
        np.testing.assert_array_equal(getattr(ours, field), getattr(theirs, field),
                                      err_msg=field)
    assert_loads_again(arm, tmp_path / "export")


def test_saved_beside_its_source_a_composition_loads_there(tmp_path: Path) -> None:
    """The text of a composition, saved beside the file of the model everything is attached
    to: its own files by the paths it wrote, the attached models' by absolute paths."""
    parts = Parts(tmp_path / "robots", own_base_link=False)
    rover, _ = nested(parts)
    text = rover.to_xml_string()
    beside = parts.base_path.with_name("rover_with_arm.xml")
    beside.write_text(text, encoding="utf-8")
    assert model_differences(rover.compile(), mujoco.MjModel.from_xml_path(str(beside))) == []
    files = file_attributes(text)
    assert "chassis.obj" in files  # the rover's own, as its source names it
    assert str(parts.hand_path.parent / "meshes" / "finger.obj") in files


def test_a_file_name_two_different_files_have_is_given_once(tmp_path: Path) -> None:
    """The arm's and the gripper's base_link.stl differ: the text names each as its source
    does (the gripper's by its absolute path), and get_assets() keeps them apart by their
    folders (MuJoCo's loader from a dict finds files by base name; a ``-2`` suffix would
    rename the mesh MuJoCo names after the file); every other file keeps its path. The
    gripper's screw.stl has the arm's bytes: one file."""
    parts = Parts(tmp_path / "robots")
    arm, _ = at_site(parts)
    text, assets = arm.to_xml_string(), arm.get_assets()
    files = file_attributes(text)
    hand_base = str(parts.hand_path.parent / "meshes" / "base_link.stl")
    assert "base_link.stl" in files and hand_base in files
    assert assets["meshes/base_link.stl"] == Path(hand_base).read_bytes()
    assert assets["assets/base_link.stl"] == (
        parts.arm_path.parent / "assets" / "base_link.stl").read_bytes()
    assert "base_link.stl" not in assets
    assert [f for f in files if "screw" in f] == [
        "screw.stl", str(parts.hand_path.parent / "meshes" / "hardware" / "screw.stl")]
    assert [k for k in assets if "screw" in k] == ["screw.stl"]


@pytest.mark.parametrize("part", ["arm_path", "hand_path", "base_path"])
def test_each_robot_file_is_the_model_mujoco_compiles(tmp_path: Path, part: str) -> None:
    """The differential property of the corpus tests (test_corpus.py, test_corpus_validate.py,
    test_corpus_asset_routes.py) on the robot-shaped files: loaded, validate() finds no
    error, compile() and the text written beside the source are MuJoCo's own model."""
    path: Path = getattr(Parts(tmp_path), part)
    expected = mujoco.MjModel.from_xml_path(str(path))
    model = mjcf.from_path(path)
    assert [f for f in model.validate() if f.severity == "error"] == []
    assert model_differences(expected, model.compile()) == []
    beside = path.with_name("typed-mjcf-written.xml")
    beside.write_text(model.to_xml_string(), encoding="utf-8")
    assert model_differences(expected, mujoco.MjModel.from_xml_path(str(beside))) == []
