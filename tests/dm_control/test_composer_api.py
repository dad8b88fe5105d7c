"""What dm_control's composer (and the code its environments run) needs of ``mjcf.Physics``
and the loaders, each found by running its environments (``test_composer.py``)."""

from __future__ import annotations

import importlib
import zipfile
from collections.abc import Callable
from pathlib import Path
from typing import cast

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._dmcompat import installed
from typed_mjcf.errors import FileAccessError, InvalidValueError


def model() -> mjcf.RootElement:
    root = mjcf.RootElement(model="m")
    root.worldbody.add_light(pos=(0, 0, 3))
    root.worldbody.add_geom(name="floor", type="plane", size=(1, 1, 0.1))
    body = root.worldbody.add_body(name="ball", pos=(0, 0, 1))
    body.add_freejoint(name="root")
    body.add_geom(name="ball", type="sphere", size=(0.1,), contype=3)
    link = root.worldbody.add_body(name="link")
    link.add_joint(name="hinge", axis=(0, 1, 0))
    link.add_geom(type="capsule", size=(0.02,), fromto=(0, 0, 0, 0, 0, 0.3))
    return root


def test_a_diverging_physics_raises_dm_controls_physics_error_under_the_switch() -> None:
    """composer catches ``dm_control.rl.control.PhysicsError`` (a diverging episode ends);
    typed-mjcf's error is that class too under the switch, and stays typed-mjcf's."""
    pytest.importorskip("dm_control")
    control = importlib.import_module("dm_control.rl.control")
    with installed():
        physics = mjcf.Physics.from_mjcf_model(model())
        physics.data.qpos[0] = np.nan
        with pytest.raises(control.PhysicsError, match="BADQPOS") as raised:
            physics.step()
        assert isinstance(raised.value, mjcf.PhysicsError)
    physics = mjcf.Physics.from_mjcf_model(model())
    physics.data.qpos[0] = np.nan
    with pytest.raises(mjcf.PhysicsError) as raised:
        physics.step()
    assert not isinstance(raised.value, control.PhysicsError)


def test_a_single_elements_value_is_a_copy_under_the_switch() -> None:
    """dm_control gives one element's value of a one-dimensional array as a numpy scalar (a
    copy): its prop placer saves a geom's contype, sets 0, and restores the saved value."""
    root = model()
    geom = root.find("geom", "ball")
    assert geom is not None
    with installed():
        physics = mjcf.Physics.from_mjcf_model(root)
        saved = physics.bind(geom).contype
        physics.bind(geom).contype = 0
        assert type(cast(object, saved)) is np.int32 and saved == 3  # (typed: an array)
        physics.bind(geom).contype = saved
        assert physics.named.model.geom_contype["ball"] == 3
    physics = mjcf.Physics.from_mjcf_model(root)
    view = physics.bind(geom).contype  # the typed API's: a view of MuJoCo's array
    physics.bind(geom).contype = 0
    assert view.shape == () and view == 0


def test_operations_on_a_single_elements_value_give_numpy_scalars() -> None:
    """As on a plain 0-d array (dm_control's bowl arena: ``np.ogrid[-1:1:nrow * 1j]``)."""
    root = model()
    joint = root.find("joint", "hinge")
    assert joint is not None
    physics = mjcf.Physics.from_mjcf_model(root)
    dofadr = physics.bind(joint).dofadr  # one row per joint: a 0-d array
    assert dofadr.shape == () and isinstance(dofadr * 1j, np.complex128)
    assert len(np.ogrid[-1:1:(physics.bind(joint).dofadr + 3) * 1j]) == 9
    positions = physics.bind(root.find_all("joint")).qpos
    assert type(positions + 1) is type(positions) and (positions + 1).shape == (8,)


def test_named_indexers_have_dm_controls_axes() -> None:
    """``inverse_kinematics`` converts joint names to dof indices with
    ``named.model.dof_jntid.axes.row.convert_key_item``."""
    physics = mjcf.Physics.from_mjcf_model(model())
    row = physics.named.model.dof_jntid.axes.row
    assert physics.named.model.dof_jntid.axes.col is None
    np.testing.assert_array_equal(np.asarray(row.convert_key_item(["hinge"])), [6])
    rows = np.asarray(row.convert_key_item(["root", "hinge"]), dtype=np.intp)
    np.testing.assert_array_equal(np.arange(7)[rows], [0, 1, 2, 3, 4, 5, 6])
    assert physics.named.data.xpos.axes.col is not None
    assert physics.named.data.xpos.axes.col.convert_key_item("z") == 2


def test_render_takes_render_flag_overrides() -> None:
    """composer's camera observables pass ``render_flag_overrides``."""
    physics = mjcf.Physics.from_mjcf_model(model())
    plain = physics.render(48, 64)
    wireframe = physics.render(48, 64, render_flag_overrides={"wireframe": True})
    assert wireframe.shape == plain.shape and not np.array_equal(wireframe, plain)
    np.testing.assert_array_equal(physics.render(48, 64), plain)  # for that image only
    with pytest.raises(InvalidValueError, match="wireframe"):
        physics.render(48, 64, render_flag_overrides={"wirefram": True})
    with pytest.raises(InvalidValueError, match="depth"):
        physics.render(48, 64, depth=True, render_flag_overrides={"wireframe": True})


def test_files_outside_the_models_folder_are_read_under_the_switch(tmp_path: Path) -> None:
    """dm_control's arenas load their XML, then point ``compiler.texturedir`` at another
    folder of theirs: dm_control reads any path a model names. Only its loaders do: the
    typed API's keep a model to its folder, switch or not (a zip to its archive)."""
    folder, textures = tmp_path / "model", tmp_path / "textures"
    folder.mkdir()
    textures.mkdir()
    (folder / "arena.xml").write_text("<mujoco><worldbody/></mujoco>", encoding="utf-8")
    (textures / "grass.png").write_bytes(b"not read as an image here")
    with zipfile.ZipFile(tmp_path / "arena.zip", "w") as archive:
        archive.writestr("arena.xml", "<mujoco><asset><texture name='t' type='2d' "
                                      f"file='{textures / 'grass.png'}'/></asset></mujoco>")

    def load(from_path: Callable[[Path], mjcf.RootElement]) -> mjcf.RootElement:
        root = from_path(folder / "arena.xml")
        root.compiler.texturedir = str(textures)
        root.asset.add_texture(name="grass", type="2d", file="grass.png")
        return root

    with installed():
        dm_control_mjcf = importlib.import_module("dm_control.mjcf")
        for loader in (dm_control_mjcf.from_path, dm_control_mjcf.parser.from_path):
            assets = load(loader).get_assets()
            assert list(assets.values()) == [b"not read as an image here"]
        assert list(dm_control_mjcf.from_zip(tmp_path / "arena.zip").get_assets().values()) == [
            b"not read as an image here"]
        with pytest.raises(FileAccessError, match="outside the model's folder"):
            load(mjcf.from_path).get_assets()
        with pytest.raises(FileAccessError, match="not among the files of the archive"):
            mjcf.from_zip(tmp_path / "arena.zip").get_assets()
    with pytest.raises(FileAccessError, match="outside the model's folder"):
        load(mjcf.from_path).get_assets()


def test_renderers_are_made_again_after_contexts_is_read() -> None:
    """dm_control's bowl arena changes its height field, then re-uploads it to the rendering
    context if ``physics.contexts``: here reading it frees the renderers, so the next image
    shows the model's data as it is then."""
    root = model()
    root.asset.add_hfield(name="terrain", nrow=3, ncol=3, size=(1, 1, 0.5, 0.1))
    root.worldbody.add_geom(name="terrain", type="hfield", hfield="terrain", pos=(0, 0, 0.5))
    physics = mjcf.Physics.from_mjcf_model(root)
    flat = physics.render(48, 64)
    physics.model.hfield_data[:] = 1.0  # a raised terrain, not yet uploaded
    assert np.array_equal(physics.render(48, 64), flat)  # the old upload: why dm_control's
    assert physics.contexts is None                      # code re-uploads it
    assert not np.array_equal(physics.render(48, 64), flat)
