"""dm_control's own model builders (locomotion walkers and arenas, manipulation props and
arenas, entities, and compositions of them) built after ``install_as_dm_control_mjcf()``
compile to the same model as dm_control's own mjcf builds: every numeric ``MjModel`` field
equal (within float tolerance) and every object named alike.

Both runs are subprocesses (``builders.py``): redirecting ``dm_control.mjcf`` is
process-wide. Builders that differ are listed in ``DIFFERENT`` with the reason (strict).
"""

from __future__ import annotations

import pickle
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from . import harness
from .builders import differences

pytestmark = pytest.mark.skipif(harness.mjcf_folder() is None,
                                reason="dm_control is not installed")

SCRIPT = Path(__file__).with_name("builders.py")

# The builders of builders.py (checked against it when the results are read).
NAMES = (
    "walker.Ant", "walker.CMUHumanoid", "walker.CMUHumanoidPositionControlled",
    "walker.CMUHumanoidPositionControlledV2020", "walker.JumpingBallWithHead",
    "walker.RollingBallWithHead", "walker.Rat", "walker.FruitFly", "walker.CMUHumanoid(rescaled)",
    "walker.Ant(marker_rgba)", "walker.CMUHumanoidPositionControlledV2020(marker_rgba)",
    "arena.Floor", "arena.Bowl", "arena.EmptyCorridor", "arena.GapsCorridor",
    "arena.WallsCorridor", "arena.SkyBox", "arena.WallTextures", "arena.FloorTextures",
    "arena.MazeWithTargets(PaddedRoom)", "arena.RandomMazeWithTargets",
    "manipulation.props.Box", "manipulation.props.BoxWithSites", "manipulation.props.Capsule",
    "manipulation.props.Cylinder", "manipulation.props.Ellipsoid", "manipulation.props.Sphere",
    "manipulation.arena.Standard", "manipulation.robots.make_arm",
    "manipulation.robots.make_hand", "entities.JacoArm", "entities.JacoHand", "entities.Duplo",
    "entities.Duplo(easy_align)", "entities.Primitive(sphere)", "entities.PositionDetector",
    "composed.JacoArm+JacoHand", "composed.manipulation scene",
    "composed.EmptyCorridor+CMUHumanoidPositionControlledV2020", "composed.EmptyCorridor+Ant",
    "composed.EmptyCorridor+Rat", "composed.Floor+3 Duplos",
)

NEEDS_PHYSICS = ("built with mjcf.Physics (the walker's initial pose), which dm_control's own "
                 "cannot run on MuJoCo 4: dm_control's side cannot be built, not comparable here "
                 "(builders.py xml/compare compares them with dm_control on MuJoCo 3: the same)")
# builder -> why typed-mjcf's model differs from dm_control's
DIFFERENT: dict[str, str] = {
    "walker.CMUHumanoidPositionControlledV2020": NEEDS_PHYSICS,
    "walker.CMUHumanoid(rescaled)": NEEDS_PHYSICS,
    "walker.CMUHumanoidPositionControlledV2020(marker_rgba)": NEEDS_PHYSICS,
    "composed.EmptyCorridor+CMUHumanoidPositionControlledV2020": NEEDS_PHYSICS,
}


def built(which: str, folder: str) -> dict[str, Any]:
    out = Path(folder) / f"{which}.pickle"
    subprocess.run([sys.executable, str(SCRIPT), which, str(out)], check=True,
                   capture_output=True, timeout=900)
    with out.open("rb") as handle:
        return pickle.load(handle)


def test_builders_compile_to_dm_controls_models(tmp_path: Path) -> None:
    """One test for all builders (each run builds all of them once, in two subprocesses:
    split over pytest-xdist workers, every worker would build them all again). Each
    builder either compiles to dm_control's model or is listed in ``DIFFERENT``; a listed one
    that starts to match fails too, so the list stays true."""
    ours, theirs = built("typed", str(tmp_path)), built("dm_control", str(tmp_path))
    assert sorted(ours) == sorted(theirs) == sorted(NAMES)
    found = {name: differences(ours[name], theirs[name]) for name in NAMES}
    unexpected = {name: diffs for name, diffs in found.items()
                  if diffs and name not in DIFFERENT}
    now_equal = sorted(name for name in DIFFERENT if not found[name])
    report = "\n\n".join(f"{name}:\n" + "\n".join(diffs) for name, diffs in unexpected.items())
    assert not unexpected, report
    assert not now_equal, f"listed in DIFFERENT but now equal: {now_equal}"
