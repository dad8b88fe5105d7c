"""``typed-mjcf check --compile`` reads a model's files only inside its folder, unless
``--allow-files FOLDER`` names another."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.meshes import box_stl
from typed_mjcf.cli import main


def test_files_outside_the_folder_need_allow_files(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "box.stl").write_bytes(box_stl())
    (tmp_path / "model").mkdir()
    model = tmp_path / "model" / "m.xml"
    model.write_text("<mujoco>\n<compiler meshdir='../meshes'/>\n<asset><mesh name='b' "
                     "file='box.stl'/></asset>\n<worldbody><body><freejoint/><geom type='mesh' "
                     "mesh='b'/></body></worldbody></mujoco>")
    assert main(["check", "--compile", str(model)]) == 1
    out = capsys.readouterr().out
    assert f"m.xml:3: compile: asset/mesh[b]: file='box.stl': {tmp_path / 'meshes' / 'box.stl'} " \
           f"is outside the model's folder {tmp_path / 'model'}" in out
    assert main(["check", "--compile", "--allow-files", str(tmp_path / "meshes"), str(model)]) == 0


def test_check_compiles_two_files_of_one_base_name(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    """The child compiling for `check` keeps the files apart by folder, as compile() does
    (MuJoCo's dict route refuses two keys with one base name)."""
    for part, size in (("torso", 0.1), ("gripper", 0.2)):
        (tmp_path / "assets" / part).mkdir(parents=True)
        (tmp_path / "assets" / part / "base_link.stl").write_bytes(box_stl(size))
    model = tmp_path / "m.xml"
    model.write_text("<mujoco><compiler meshdir='assets'/><asset>"
                     "<mesh name='t' file='torso/base_link.stl'/>"
                     "<mesh file='gripper/base_link.stl'/></asset><worldbody><body><freejoint/>"
                     "<geom type='mesh' mesh='t'/><geom type='mesh' mesh='base_link'/></body>"
                     "</worldbody></mujoco>")
    assert main(["check", "--compile", str(model)]) == 0, capsys.readouterr().out
