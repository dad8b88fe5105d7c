"""Reset and step dm_control's composer environments; report each one's result as JSON.

Run as a script in a fresh interpreter (the ``dm_control.mjcf`` redirection is process-wide):

    python tests/dm_control/composer_envs.py typed OUT.json [NAME[=STEPS] ...]
    python tests/dm_control/composer_envs.py dm_control OUT.json [NAME ...]

``typed`` calls ``install_as_dm_control_mjcf()`` first; ``dm_control`` runs dm_control's own
mjcf, whose Physics cannot run on MuJoCo 4: run it in a separate environment (measured with
dm_control 1.0.49 and mujoco 3.17.0: ``python3.11 -m venv /tmp/dm3 && /tmp/dm3/bin/pip
install dm_control==1.0.49 mujoco==3.17.0``), then compare the two runs' specs:

    python tests/dm_control/composer_envs.py compare TYPED.json DM_CONTROL.json

Each environment (the manipulation tasks of ``manipulation.ALL`` and the locomotion examples
that need no downloaded data) is made with a fixed seed, reset, and stepped ``STEPS`` times
(or the number given after its name) with seeded uniform actions within ``action_spec()``.
Its entry is either a record (the observation spec: name -> [shape, dtype]; the observables
the task declares enabled; whether every observation was finite and matched its spec; the
steps run) or the error, as text.
"""

from __future__ import annotations

import json
import sys
import time
import traceback
from collections.abc import Callable
from typing import Any

import numpy as np

STEPS = 100

# The locomotion examples, by module and function. cmu_2020_tracking's needs the CMU mocap
# data file (downloaded separately), so it is not here.
LOCOMOTION = {
    "basic_cmu_2019": ("cmu_humanoid_run_walls", "cmu_humanoid_run_gaps",
                       "cmu_humanoid_go_to_target", "cmu_humanoid_maze_forage",
                       "cmu_humanoid_heterogeneous_forage"),
    "basic_rodent_2020": ("rodent_escape_bowl", "rodent_run_gaps", "rodent_maze_forage",
                          "rodent_two_touch"),
}


def environments() -> dict[str, Callable[[], Any]]:
    """Every environment, by name: a function that makes it."""
    import functools
    import importlib

    manipulation = importlib.import_module("dm_control.manipulation")
    found: dict[str, Callable[[], Any]] = {}
    for name in manipulation.ALL:
        found[f"manipulation.{name}"] = functools.partial(manipulation.load, name, seed=0)
    for module_name, functions in LOCOMOTION.items():
        module = importlib.import_module(f"dm_control.locomotion.examples.{module_name}")
        for function in functions:
            found[f"locomotion.{module_name}.{function}"] = functools.partial(
                getattr(module, function), random_state=np.random.RandomState(0))
    return found


def _spec(spec: Any) -> list[Any]:
    return [list(spec.shape), np.dtype(spec.dtype).name]


def run(make: Callable[[], Any], count: int = STEPS) -> dict[str, Any]:
    """Make, reset and step one environment ``count`` steps; what it gave."""
    env = make()
    try:
        spec = env.observation_spec()
        declared = sorted(name for name, observable in env.task.observables.items()
                          if observable.enabled)
        action_spec = env.action_spec()
        random = np.random.RandomState(0)
        conforming, finite = True, True

        def check(observation: Any) -> None:
            nonlocal conforming, finite
            if sorted(observation) != sorted(spec):
                conforming = False
            for name, value in observation.items():
                array = np.asarray(value)
                if name in spec and (array.shape != tuple(spec[name].shape)
                                     or array.dtype != spec[name].dtype):
                    conforming = False
                if array.dtype.kind in "fc" and not np.all(np.isfinite(array)):
                    finite = False

        check(env.reset().observation)
        steps = 0
        for _ in range(count):
            shape: tuple[int, ...] = tuple(action_spec.shape)
            low = np.broadcast_to(np.asarray(action_spec.minimum, action_spec.dtype), shape)
            high = np.broadcast_to(np.asarray(action_spec.maximum, action_spec.dtype), shape)
            action = random.uniform(low, high, size=shape).astype(low.dtype)
            check(env.step(action).observation)
            steps += 1
        return {"spec": {name: _spec(value) for name, value in spec.items()},
                "declared": declared, "action": _spec(action_spec), "steps": steps,
                "finite": finite, "conforming": conforming}
    finally:
        env.close()


def compare(typed: dict[str, Any], theirs: dict[str, Any]) -> list[str]:
    """Where two runs' observation and action specs differ (and which ran in one only)."""
    found: list[str] = []
    for name in sorted(set(typed) | set(theirs)):
        ours, reference = typed.get(name), theirs.get(name)
        if not isinstance(ours, dict) or not isinstance(reference, dict):
            found.append(f"{name}: typed-mjcf {_outcome(ours)}, dm_control {_outcome(reference)}")
            continue
        for key in ("spec", "action", "declared"):
            if ours[key] != reference[key]:
                found.append(f"{name}: {key} differs: {ours[key]} != {reference[key]}")
    return found


def _outcome(result: object) -> str:
    return "not run" if result is None else "ran" if isinstance(result, dict) else "failed"


SHADOW_MAP = 64  # texels a side; the models ask for 4096


def _cheaper_renders() -> None:
    """Render camera observations without shadows, reflections or multisampling (and with a
    small shadow map, which the context still allocates).

    Nothing reads the pixels (the test checks each observation's shape, dtype and spec), and
    in software rendering (no GPU: Mesa's llvmpipe) the shadow pass, the reflection pass and
    multisampling (``offsamples``, 4 by default) are most of an image's cost: measured per
    frame (CPU, 20 frames after a reset), manipulation.stack_3_bricks_vision's 84 x 84 image
    60 ms with shadows and reflections (already with the 64-texel map and no multisampling),
    20 ms without; cmu_humanoid_maze_forage's 64 x 64 one 11 -> 3 ms. Every observation is
    still rendered at every step, through typed-mjcf's ``Physics.render`` and the renderer it
    keeps per image size; only the scene flags of that renderer are changed, once, when it
    is made (``render_flag_overrides`` of a call still apply on top)."""
    import mujoco

    from typed_mjcf.physics import Physics

    make = Physics._renderer  # a renderer is made per image size, when first used

    def renderer(self: Physics, height: int, width: int, *args: Any) -> Any:
        known = (height, width) in self._renderers
        quality = self.model.vis.quality
        quality.shadowsize = min(quality.shadowsize, SHADOW_MAP)
        quality.offsamples = 0
        made = make(self, height, width, *args)  # *args: what else _renderer takes
        if not known:
            for flag in (mujoco.mjtRndFlag.mjRND_SHADOW, mujoco.mjtRndFlag.mjRND_REFLECTION):
                made.scene.flags[flag] = 0
        return made

    Physics._renderer = renderer  # type: ignore[method-assign]


def main(argv: list[str]) -> None:
    which, out, names = argv[1], argv[2], argv[3:]
    if which == "compare":  # composer_envs.py compare TYPED.json DM_CONTROL.json
        with open(out, encoding="utf-8") as a, open(names[0], encoding="utf-8") as b:
            found = compare(json.load(a), json.load(b))
        print("\n".join(found) or "the same observation and action specs")
        raise SystemExit(1 if found else 0)
    if which not in ("typed", "dm_control"):
        raise SystemExit("usage: composer_envs.py typed|dm_control OUT.json [NAME ...]")
    if which == "typed":
        import typed_mjcf

        typed_mjcf.install_as_dm_control_mjcf()
        _cheaper_renders()
    wanted = {name: int(steps or STEPS) for name, _, steps in
              (argument.partition("=") for argument in names)}
    results: dict[str, Any] = {}
    for name, make in environments().items():
        if wanted and name not in wanted:
            continue
        start = time.perf_counter()
        try:
            results[name] = run(make, wanted.get(name, STEPS))
        except Exception:  # noqa: BLE001 - reported, checked by the test
            results[name] = traceback.format_exc(limit=-8)
        print(f"{name}: {time.perf_counter() - start:.1f} s", file=sys.stderr)  # to report
        with open(out, "w", encoding="utf-8") as handle:
            json.dump(results, handle, indent=1, sort_keys=True)


if __name__ == "__main__":
    main(sys.argv)
