"""Build dm_control's own model builders and dump the compiled models' numeric fields.

Run as a script in a fresh interpreter (the ``dm_control.mjcf`` redirection is process-wide):

    python tests/dm_control/builders.py typed OUT.pickle   # after install_as_dm_control_mjcf()
    python tests/dm_control/builders.py dm_control OUT.pickle   # dm_control's own mjcf

Builders that pose their walker with ``mjcf.Physics`` cannot run on dm_control's side on
MuJoCo 4; for them (for all), dm_control's models are built in an environment with MuJoCo 3
and compiled here (not at test time)::

    python3.11 -m venv /tmp/dm3 && /tmp/dm3/bin/pip install dm_control==1.0.49 mujoco==3.17.0
    /tmp/dm3/bin/python tests/dm_control/builders.py xml DM3.pickle   # XML text and assets
    python tests/dm_control/builders.py typed TYPED.pickle
    python tests/dm_control/builders.py compare TYPED.pickle DM3.pickle

Each builder is one of dm_control's locomotion walkers and arenas, manipulation props and
arenas, or entities (and a few compositions of them, as its tasks make them), built with the
code as dm_control ships it. A builder's entry in the output is either the compiled model's
fields (every numeric ``MjModel`` array, and the names of every object) or the error it
raised, as text. ``test_builders.py`` compares the two runs.
"""

from __future__ import annotations

import pickle
import sys
import traceback
from collections.abc import Callable
from typing import Any

import numpy as np

# The builders, by name. Each returns an object with ``mjcf_model`` (a composer Entity) or
# the model itself; the seed is set before each, for the ones that draw random numbers.
BUILDERS: dict[str, Callable[[], Any]] = {}


def builder(name: str) -> Callable[[Callable[[], Any]], Callable[[], Any]]:
    def register(function: Callable[[], Any]) -> Callable[[], Any]:
        BUILDERS[name] = function
        return function
    return register


def _define() -> None:
    from dm_control.entities.manipulators.kinova import jaco_arm, jaco_hand
    from dm_control.entities.props import duplo, position_detector
    from dm_control.entities.props import primitive as entity_primitive
    from dm_control.locomotion import arenas, walkers
    from dm_control.locomotion.arenas import labmaze_textures, mazes, padded_room
    from dm_control.locomotion.walkers import cmu_humanoid, fruitfly_v2, rescale
    from dm_control.manipulation import props
    from dm_control.manipulation.shared import arenas as manipulation_arenas
    from dm_control.manipulation.shared import observations, robots, workspaces

    walker_classes = {"Ant": walkers.Ant, "CMUHumanoid": cmu_humanoid.CMUHumanoid,
                      "CMUHumanoidPositionControlled": walkers.CMUHumanoidPositionControlled,
                      "CMUHumanoidPositionControlledV2020":
                          walkers.CMUHumanoidPositionControlledV2020,
                      "JumpingBallWithHead": walkers.JumpingBallWithHead,
                      "RollingBallWithHead": walkers.RollingBallWithHead,
                      "Rat": walkers.Rat, "FruitFly": fruitfly_v2.FruitFly}
    for name, cls in walker_classes.items():
        builder(f"walker.{name}")(cls)
    builder("walker.CMUHumanoid(rescaled)")(
        lambda: _rescaled(cmu_humanoid.CMUHumanoid(), rescale))
    builder("walker.Ant(marker_rgba)")(lambda: walkers.Ant(marker_rgba=(0.1, 0.2, 0.3, 0.4)))
    builder("walker.CMUHumanoidPositionControlledV2020(marker_rgba)")(
        lambda: walkers.CMUHumanoidPositionControlledV2020(marker_rgba=(0.1, 0.2, 0.3, 0.4)))

    builder("arena.Floor")(arenas.Floor)
    builder("arena.Bowl")(arenas.Bowl)
    builder("arena.EmptyCorridor")(arenas.EmptyCorridor)
    builder("arena.GapsCorridor")(arenas.GapsCorridor)
    builder("arena.WallsCorridor")(arenas.WallsCorridor)
    builder("arena.SkyBox")(lambda: labmaze_textures.SkyBox(style="sky_03"))
    builder("arena.WallTextures")(lambda: labmaze_textures.WallTextures(style="style_01"))
    builder("arena.FloorTextures")(lambda: labmaze_textures.FloorTextures(style="style_01"))

    def maze(random: bool) -> Any:
        textures = {"skybox_texture": labmaze_textures.SkyBox(style="sky_03"),
                    "wall_textures": labmaze_textures.WallTextures(style="style_01"),
                    "floor_textures": labmaze_textures.FloorTextures(style="style_01")}
        if random:
            return arenas.RandomMazeWithTargets(
                x_cells=11, y_cells=11, xy_scale=3, max_rooms=4, room_min_size=4,
                room_max_size=5, spawns_per_room=1, targets_per_room=3, **textures)
        room = padded_room.PaddedRoom(room_size=5, num_objects=2)
        return mazes.MazeWithTargets(maze=room, xy_scale=2, **textures)
    builder("arena.MazeWithTargets(PaddedRoom)")(lambda: maze(False))
    builder("arena.RandomMazeWithTargets")(lambda: maze(True))

    for name in ("Box", "BoxWithSites", "Capsule", "Cylinder", "Ellipsoid", "Sphere"):
        builder(f"manipulation.props.{name}")(getattr(props, name))
    builder("manipulation.arena.Standard")(manipulation_arenas.Standard)
    builder("manipulation.robots.make_arm")(
        lambda: robots.make_arm(observations.PERFECT_FEATURES))
    builder("manipulation.robots.make_hand")(
        lambda: robots.make_hand(observations.PERFECT_FEATURES))

    builder("entities.JacoArm")(jaco_arm.JacoArm)
    builder("entities.JacoHand")(jaco_hand.JacoHand)
    builder("entities.Duplo")(duplo.Duplo)
    builder("entities.Duplo(easy_align)")(lambda: duplo.Duplo(easy_align=True, flanges=False))
    builder("entities.Primitive(sphere)")(
        lambda: entity_primitive.Primitive(geom_type="sphere", size=[0.1]))
    builder("entities.PositionDetector")(
        lambda: position_detector.PositionDetector(pos=(0, 0, 0.5), size=(0.1, 0.2, 0.3)))

    # compositions, as the tasks make them
    def arm_with_hand() -> Any:
        arm = jaco_arm.JacoArm()
        arm.attach(jaco_hand.JacoHand())
        return arm

    def manipulation_scene() -> Any:
        arena = manipulation_arenas.Standard()
        arm = robots.make_arm(observations.PERFECT_FEATURES)
        arm.attach(robots.make_hand(observations.PERFECT_FEATURES))
        arena.attach_offset(arm, offset=(0, 0.4, 0))
        for name in ("Box", "Sphere"):
            prop = getattr(props, name)()
            frame = arena.add_free_entity(prop)
            frame.pos = (0.1, 0.1, 0.3)
        workspaces.add_target_site(arena.mjcf_model.worldbody, radius=0.05, visible=True,
                                   rgba="0 0 1 0.3", name="target")
        return arena

    def corridor_with_walker(walker: Callable[[], Any]) -> Any:
        arena = arenas.EmptyCorridor()
        arena.add_free_entity(walker())
        return arena

    def stacked_duplos() -> Any:
        arena = arenas.Floor()
        for i in range(3):
            frame = arena.add_free_entity(duplo.Duplo())
            frame.pos = (0, 0, 0.1 * i)
        return arena

    builder("composed.JacoArm+JacoHand")(arm_with_hand)
    builder("composed.manipulation scene")(manipulation_scene)
    builder("composed.EmptyCorridor+CMUHumanoidPositionControlledV2020")(
        lambda: corridor_with_walker(walkers.CMUHumanoidPositionControlledV2020))
    builder("composed.EmptyCorridor+Ant")(lambda: corridor_with_walker(walkers.Ant))
    builder("composed.EmptyCorridor+Rat")(lambda: corridor_with_walker(walkers.Rat))
    builder("composed.Floor+3 Duplos")(stacked_duplos)


def _rescaled(walker: Any, rescale: Any) -> Any:
    rescale.rescale_humanoid(walker, 1.2, 0.9, mass=50)
    return walker


def _fields(model: Any) -> dict[str, Any]:
    """Every numeric array of a compiled ``MjModel`` and every object's name."""
    import mujoco

    out: dict[str, Any] = {}
    for field in dir(model):
        if field.startswith(("_", "name_")) or field in (
                "names", "paths", "text_data", "text_adr", "text_size"):
            continue
        value = getattr(model, field, None)
        if isinstance(value, np.ndarray) and value.dtype.kind in "biuf":
            out[field] = np.array(value)
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            out[field] = value
    counts = {"BODY": "nbody", "JOINT": "njnt", "GEOM": "ngeom", "SITE": "nsite",
              "CAMERA": "ncam", "LIGHT": "nlight", "MESH": "nmesh", "TEXTURE": "ntex",
              "MATERIAL": "nmat", "HFIELD": "nhfield", "TENDON": "ntendon", "ACTUATOR": "nu",
              "SENSOR": "nsensor", "EQUALITY": "neq", "KEY": "nkey", "SKIN": "nskin"}
    for kind, count in counts.items():
        obj = getattr(mujoco.mjtObj, f"mjOBJ_{kind}")
        out[f"names:{kind}"] = [mujoco.mj_id2name(model, obj, i)
                                for i in range(getattr(model, count))]
    return out


def build_all(typed: bool, text_only: bool = False) -> dict[str, Any]:
    """Each builder's compiled fields (``text_only``: its XML text and assets instead)."""
    if typed:
        import typed_mjcf

        typed_mjcf.install_as_dm_control_mjcf()
    import mujoco

    _define()
    results: dict[str, Any] = {}
    for name, make in BUILDERS.items():
        np.random.seed(0)
        try:
            built = make()
            model = getattr(built, "mjcf_model", built)
            text, assets = model.to_xml_string(), model.get_assets()
            results[name] = ((text, assets) if text_only else
                             _fields(mujoco.MjModel.from_xml_string(text, assets)))
        except Exception:  # noqa: BLE001 - reported, compared by the test
            results[name] = traceback.format_exc(limit=-6)
    return results


def differences(ours: Any, theirs: Any) -> list[str]:
    """What differs between two builders' results (text: the error raised)."""
    if isinstance(theirs, str):
        return [f"dm_control itself failed: {theirs}"]
    if isinstance(ours, str):
        return [f"typed-mjcf failed: {ours}"]
    found: list[str] = []
    for field in sorted(set(ours) | set(theirs)):
        a, b = ours.get(field), theirs.get(field)
        if a is None or b is None:
            found.append(f"{field}: only in {'dm_control' if a is None else 'typed-mjcf'}")
        elif isinstance(b, list):
            if a != b:
                found.append(f"{field}: {a[:6]} != {b[:6]}")
        elif np.shape(a) != np.shape(b):
            found.append(f"{field}: shape {np.shape(a)} != {np.shape(b)}")
        elif not np.allclose(a, b, rtol=1e-6, atol=1e-9, equal_nan=True):
            found.append(f"{field}: differs")
    return found


def compare(typed_path: str, text_path: str) -> None:
    """Print, per builder, what differs between typed-mjcf's compiled model and dm_control's
    XML (built elsewhere, with ``xml``) compiled by the installed MuJoCo."""
    import mujoco

    with open(typed_path, "rb") as handle:
        ours = pickle.load(handle)
    with open(text_path, "rb") as handle:
        texts = pickle.load(handle)
    same = 0
    for name in ours:
        theirs = texts.get(name, "not built there")
        if not isinstance(theirs, str):
            try:
                theirs = _fields(mujoco.MjModel.from_xml_string(*theirs))
            except Exception:  # noqa: BLE001 - reported
                theirs = traceback.format_exc(limit=-2)
        found = differences(ours[name], theirs)
        same += not found
        print(f"{name}: {'same model' if not found else chr(10).join(['', *found])}")
    print(f"{same} of {len(ours)} the same")


def main(argv: list[str]) -> None:
    which = argv[1] if len(argv) > 1 else ""
    if which == "compare" and len(argv) == 4:
        compare(argv[2], argv[3])
        return
    if which not in ("typed", "dm_control", "xml") or len(argv) != 3:
        raise SystemExit("usage: builders.py typed|dm_control|xml OUT.pickle, or "
                         "builders.py compare TYPED.pickle XML.pickle")
    with open(argv[2], "wb") as handle:
        pickle.dump(build_all(which == "typed", text_only=which == "xml"), handle)


if __name__ == "__main__":
    main(sys.argv)
