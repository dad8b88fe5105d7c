"""Batched worlds on MuJoCo Warp (CPU device) against MuJoCo on the CPU, world by world."""

from __future__ import annotations

from typing import NamedTuple

import mujoco
import numpy as np
import numpy.typing as npt
import pytest

import typed_mjcf as mjcf
from typed_mjcf.errors import BindingError, InvalidValueError
from typed_mjcf.warp import UnbatchedWarning, Worlds, put_worlds

N = 4
STEPS = 150
# MuJoCo Warp computes in float32 (MuJoCo in float64), and its collision and solver code is
# its own: measured here (MuJoCo Warp 4.0.0, CPU device), the worlds agree to 6.6e-7 in qpos
# and 2.8e-6 in qvel after 150 steps of contact (falling, rolling, sliding); the tolerances
# leave a factor of about 15 for that rounding, while the worlds' positions differ from each
# other by 0.04 to 0.5 (a value not written, or written into the wrong world, fails).
QPOS_TOLERANCE = 1e-5
QVEL_TOLERANCE = 1e-4


class Scene(NamedTuple):
    model: mjcf.RootElement
    ball: mjcf.Body
    ball_inertial: mjcf.Inertial
    sphere: mjcf.Geom
    crate_inertial: mjcf.Inertial
    box: mjcf.Geom
    joints: list[mjcf.Freejoint]


def _scene() -> Scene:
    model = mjcf.RootElement(model="worlds")
    model.option.timestep = 0.004
    model.worldbody.add_geom(type="plane", size=(5, 5, 0.1))
    ball = model.worldbody.add_body(name="ball", pos=(0, 0, 0.2))
    ball_joint = ball.add_freejoint()
    ball_inertial = ball.add_inertial(pos=(0, 0, 0), mass=1, diaginertia=(0.004, 0.004, 0.004))
    sphere = ball.add_geom(type="sphere", size=(0.1,))
    crate = model.worldbody.add_body(pos=(1, 0, 0.2))  # unnamed
    crate_joint = crate.add_freejoint()
    crate_inertial = crate.add_inertial(pos=(0, 0, 0), mass=1, diaginertia=(0.01, 0.01, 0.01))
    box = crate.add_geom(type="box", size=(0.1, 0.1, 0.1))
    return Scene(model, ball, ball_inertial, sphere, crate_inertial, box,
                 [ball_joint, crate_joint])


def _draw(scene: Scene) -> list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]]:
    rng = np.random.default_rng(39)
    return [(scene.sphere, "friction", rng.uniform(0.3, 1.5, (N, 3)) * [1, 0.01, 0.001]),
            (scene.box, "friction", rng.uniform(0.3, 1.5, (N, 3)) * [1, 0.01, 0.001]),
            (scene.ball_inertial, "mass", rng.uniform(0.5, 2.0, N)),
            (scene.crate_inertial, "mass", rng.uniform(0.5, 2.0, N)),
            (scene.sphere, "size", rng.uniform(0.05, 0.15, (N, 1))),
            (scene.box, "size", rng.uniform(0.05, 0.15, (N, 3)))]


# each world's starting velocities: the ball rolls, the crate slides (friction matters)
_QVEL = np.array([[1.0, 0.5, 0, 0, 0, 0], [-1.5, 0, 0, 0, 0, 2.0]])


@pytest.fixture(scope="module")
def stepped() -> tuple[Scene, list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]],
                       Worlds, list[mujoco.MjData]]:
    scene = _scene()
    draw = _draw(scene)
    with pytest.warns(UnbatchedWarning, match=r"MjModel\.dof_length"):
        worlds = put_worlds(scene.model, draw, device="cpu")
    worlds.bind(scene.joints).qvel = np.broadcast_to(_QVEL.reshape(-1), (N, 12))
    worlds.step(STEPS)
    # the same worlds on MuJoCo, each compiled from the typed model with its values
    cpu: list[mujoco.MjData] = []
    for world in range(N):
        for element, attribute, values in draw:
            setattr(element, attribute, values[world])
        compiled = scene.model.compile()
        data = mujoco.MjData(compiled)
        data.qvel[:] = _QVEL.reshape(-1)
        mujoco.mj_step(compiled, data, nstep=STEPS)
        cpu.append(data)
    return scene, draw, worlds, cpu


def test_warp_worlds_match_mujoco_models_compiled_one_by_one(stepped: tuple[
        Scene, list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]], Worlds,
        list[mujoco.MjData]]) -> None:
    scene, _, worlds, cpu = stepped
    qpos = worlds.bind(scene.joints).qpos
    qvel = worlds.bind(scene.joints).qvel
    assert qpos.shape == (N, 14) and qvel.shape == (N, 12)
    expected_qpos = np.stack([d.qpos for d in cpu])
    expected_qvel = np.stack([d.qvel for d in cpu])
    np.testing.assert_allclose(qpos, expected_qpos, rtol=0, atol=QPOS_TOLERANCE)
    np.testing.assert_allclose(qvel, expected_qvel, rtol=0, atol=QVEL_TOLERANCE)
    # the worlds went different ways (the values matter to the motion)
    spread = np.ptp(expected_qpos[:, [0, 7]], axis=0)
    assert (spread > 100 * QPOS_TOLERANCE).all(), spread


def test_bind_gives_each_worlds_values_by_the_cpu_names(stepped: tuple[
        Scene, list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]], Worlds,
        list[mujoco.MjData]]) -> None:
    scene, draw, worlds, cpu = stepped
    friction = worlds.bind(scene.sphere).friction
    np.testing.assert_allclose(friction, draw[0][2], rtol=1e-6)
    np.testing.assert_allclose(worlds.bind(scene.box).size, draw[5][2], rtol=1e-6)
    mass = worlds.bind(scene.model.worldbody.body[1]).mass  # the unnamed crate
    np.testing.assert_allclose(mass, draw[3][2], rtol=1e-6)
    # a field every world shares: one row seen by each world
    assert worlds.bind(scene.sphere).rgba.shape == (N, 4)
    # MjData arrays: per world, as MuJoCo's
    np.testing.assert_allclose(worlds.bind(scene.ball).xpos,
                               np.stack([d.xpos[1] for d in cpu]), atol=QPOS_TOLERANCE)
    with pytest.raises(AttributeError, match="does not have attribute 'frictoin'.*'friction'"):
        _ = worlds.bind(scene.sphere).frictoin  # type: ignore[attr-defined]  # pyright: ignore[reportAttributeAccessIssue]


def test_writing_through_bind_sets_each_world(stepped: tuple[
        Scene, list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]], Worlds,
        list[mujoco.MjData]]) -> None:
    scene, _, worlds, _ = stepped
    binding = worlds.bind(scene.sphere)
    new = np.arange(3 * N, dtype=np.float64).reshape(N, 3) / 10
    binding.friction = new
    np.testing.assert_allclose(worlds.bind(scene.sphere).friction, new, rtol=1e-6)
    with pytest.raises(BindingError, match="not batched"):
        binding.rgba = np.ones((N, 4))


def test_a_new_draw_is_written_into_the_same_worlds(stepped: tuple[
        Scene, list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]], Worlds,
        list[mujoco.MjData]]) -> None:
    """An episode's new values, without putting the model again: the batched fields equal
    a fresh put_worlds of the same draw's; a draw varying a field these worlds share is
    refused."""
    scene, draw, worlds, _ = stepped
    for element, attribute, _ in draw:  # the fixture left the last world's values
        setattr(element, attribute, None if attribute == "friction" else {
            "mass": 1.0, "size": (0.1,) if element is scene.sphere else (0.1, 0.1, 0.1)}[
                attribute])
    rng = np.random.default_rng(7)
    new = [(element, attribute, rng.permutation(values)) for element, attribute, values in draw]
    with pytest.warns(UnbatchedWarning):
        worlds.write(new)
    with pytest.warns(UnbatchedWarning):
        fresh = put_worlds(scene.model, new, device="cpu")
    assert fresh.batched == worlds.batched
    for name in worlds.batched:
        np.testing.assert_array_equal(getattr(worlds.warp_model, name).numpy(),
                                      getattr(fresh.warp_model, name).numpy(), err_msg=name)
    np.testing.assert_allclose(worlds.bind(scene.sphere).friction, new[0][2], rtol=1e-6)
    with pytest.raises(InvalidValueError, match=r"MjModel\.geom_rgba"):
        worlds.write([(scene.sphere, "rgba", np.full((N, 4), 0.5))])
