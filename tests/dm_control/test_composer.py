"""dm_control's composer environments run on typed-mjcf: after
``install_as_dm_control_mjcf()``, each of ``manipulation.ALL``'s tasks and the locomotion
examples that need no downloaded data (``composer_envs.py`` lists them) resets and steps 100
steps with seeded actions within its action spec, every observation finite and matching the
observation spec, whose names are the observables the task declares enabled. The "vision"
tasks, each a "features" task with a camera image added to its observations, step 20 steps.

The environments run in subprocesses (``composer_envs.py``): the redirection of
``dm_control.mjcf`` is process-wide. The "features" tasks and the locomotion examples are one
run; those that render a camera image at every step (the "vision" tasks, the locomotion
examples with an egocentric camera) four more, marked slow (rendered
without shadows and reflections: ``composer_envs._cheaper_renders``).
Environments that cannot run are listed in ``FAILING`` with the reason (strict).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from . import harness

pytestmark = pytest.mark.skipif(harness.mjcf_folder() is None,
                                reason="dm_control is not installed")

SCRIPT = Path(__file__).with_name("composer_envs.py")

FEATURES = tuple(f"manipulation.{task}" for task in (
    "stack_2_bricks_features", "stack_2_bricks_moveable_base_features",
    "stack_3_bricks_features", "stack_3_bricks_random_order_features",
    "stack_2_of_3_bricks_random_order_features", "reassemble_3_bricks_fixed_order_features",
    "reassemble_5_bricks_random_order_features", "lift_brick_features",
    "lift_large_box_features", "place_brick_features", "place_cradle_features",
    "reach_duplo_features", "reach_site_features"))
VISION = tuple(f"manipulation.{task}" for task in (
    "stack_2_bricks_vision", "stack_2_bricks_moveable_base_vision", "stack_3_bricks_vision",
    "stack_2_of_3_bricks_random_order_vision", "reassemble_3_bricks_fixed_order_vision",
    "reassemble_5_bricks_random_order_vision", "lift_brick_vision", "lift_large_box_vision",
    "place_brick_vision", "place_cradle_vision", "reach_duplo_vision", "reach_site_vision"))
LOCOMOTION = (
    "locomotion.basic_cmu_2019.cmu_humanoid_run_walls",
    "locomotion.basic_cmu_2019.cmu_humanoid_run_gaps",
    "locomotion.basic_cmu_2019.cmu_humanoid_go_to_target",
    "locomotion.basic_cmu_2019.cmu_humanoid_maze_forage",
    "locomotion.basic_cmu_2019.cmu_humanoid_heterogeneous_forage",
    "locomotion.basic_rodent_2020.rodent_escape_bowl",
    "locomotion.basic_rodent_2020.rodent_run_gaps",
    "locomotion.basic_rodent_2020.rodent_maze_forage",
    "locomotion.basic_rodent_2020.rodent_two_touch",
)

# environment -> why it cannot run on typed-mjcf (README "Running dm_control's code unchanged")
FAILING: dict[str, str] = {}


def run(names: tuple[str, ...], folder: Path) -> dict[str, Any]:
    out = folder / "composer.json"
    env = {**os.environ, "MUJOCO_GL": os.environ.get("MUJOCO_GL", "egl")}
    done = subprocess.run([sys.executable, str(SCRIPT), "typed", str(out), *names],
                          capture_output=True, text=True, timeout=1500, env=env, check=False)
    assert done.returncode == 0, done.stderr[-4000:]
    # composer's prop placer warns when props do not come to rest (with typed-mjcf's views
    # of saved contype values they fell through the floor; dm_control 1.0.49 on MuJoCo 3.17
    # warns for none of these environments)
    assert "Failed to settle physics" not in done.stderr, done.stderr[-4000:]
    with out.open(encoding="utf-8") as handle:
        results: dict[str, Any] = json.load(handle)
    return results


def failures(results: dict[str, Any], steps: Mapping[str, int]) -> dict[str, str]:
    """Each environment that did not reset, step its steps and observe as its spec says."""
    found: dict[str, str] = {}
    for name, result in results.items():
        if isinstance(result, str):
            found[name] = result
            continue
        problems: list[str] = []
        if result["steps"] != steps.get(name, STEPS):
            problems.append(f"stepped {result['steps']} steps")
        if not result["finite"]:
            problems.append("an observation was not finite")
        if not result["conforming"]:
            problems.append("an observation did not match the observation spec")
        if sorted(result["spec"]) != result["declared"]:
            problems.append(f"observation spec {sorted(result['spec'])} != the task's enabled "
                            f"observables {result['declared']}")
        for key, (shape, dtype) in result["spec"].items():
            if np.dtype(dtype).kind not in "biuf" or any(size < 0 for size in shape):
                problems.append(f"{key}: spec {shape} {dtype}")
        if problems:
            found[name] = "; ".join(problems)
    return found


def check(names: tuple[str, ...], folder: Path, steps: Mapping[str, int] | None = None,
          ) -> None:
    """Run ``names``, each ``steps[name]`` steps (100 if not given)."""
    steps = steps or {}
    results = run(tuple(f"{name}={steps.get(name, STEPS)}" for name in names), folder)
    assert sorted(results) == sorted(names)
    found = failures(results, steps)
    unexpected = {name: why for name, why in found.items() if name not in FAILING}
    now_running = sorted(name for name in names if name in FAILING and name not in found)
    report = "\n\n".join(f"{name}:\n{why}" for name, why in unexpected.items())
    assert not unexpected, report
    assert not now_running, f"listed in FAILING but now run: {now_running}"


STEPS = 100
VISION_STEPS = 20

# the environments whose observations include a camera image, rendered (in software on CI)
# at every step (with no shadows or reflections, composer_envs._cheaper_renders)
RENDERING = VISION + tuple(name for name in LOCOMOTION if not name.endswith("go_to_target"))


def test_manipulation_features_tasks_run(tmp_path: Path) -> None:
    """The 13 "features" tasks of ``manipulation.ALL`` and the locomotion example that
    renders no camera image (one subprocess for all: each would import dm_control again)."""
    check(FEATURES + tuple(name for name in LOCOMOTION if name not in RENDERING), tmp_path)


@pytest.mark.parametrize("quarter", range(4))
def test_environments_with_cameras_run(quarter: int, tmp_path: Path) -> None:
    """The 8 locomotion examples with an egocentric camera (100 steps each, as in the test
    above) and the 12 "vision" tasks, in quarters that pytest-xdist can run side by side.
    A vision task is its "features" task (the same model, task and physics, stepped 100
    steps by the test above) with a camera image among its observations, so it steps
    ``VISION_STEPS``, an image at each: the renderer made once and used again. Renderers
    made anew after a recompile are the locomotion mazes' (several resets in 100 steps)."""
    check(RENDERING[quarter::4], tmp_path, dict.fromkeys(VISION, VISION_STEPS))
