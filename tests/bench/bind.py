"""The bind workload: N joints of a compiled model, their qpos read.

typed-mjcf: ``mjcf.Physics.from_mjcf_model(model)`` made outside the timing, then
``physics.bind(joints).qpos`` (a first bind: names resolved, rows computed) and the same read
again (the binding is cached). The floor is what a MuJoCo user writes by hand: ``mj_name2id``
for each scoped name, ``jnt_qposadr`` for the rows, ``data.qpos[rows]``. Both read the same
values (checked). Times are medians of process CPU time, each case run round robin with its
floor.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from typing import Any

JOINTS = 1_000


def _model(n: int) -> Any:
    import typed_mjcf as mjcf

    model = mjcf.RootElement(model="bind")
    for i in range(n):
        body = model.worldbody.add_body(name=f"b{i}", pos=(0.3 * (i % 40), 0.3 * (i // 40), 1))
        body.add_joint(name=f"j{i}", axis=(0, 1, 0))
        body.add_geom(type="capsule", size=(0.02,), fromto=(0, 0, 0, 0, 0, 0.1))
    return model


def _medians(runs: list[Callable[[], object]], repeats: int) -> list[float]:
    """The median CPU time of each of ``runs``, run round robin (a case and its floor share
    the machine's load as it changes)."""
    samples: list[list[float]] = [[] for _ in runs]
    for _ in range(repeats):
        for run, times in zip(runs, samples, strict=True):
            start = time.process_time()
            run()
            times.append(time.process_time() - start)
    return [statistics.median(times) for times in samples]


# the cases, in order: the bind floor, a first bind, a cached bind; the compile floor, and
# the physics made from the model
LABELS = ("mj_name2id + data.qpos[jnt_qposadr[ids]] (floor)",
          "typed-mjcf physics.bind(joints).qpos, first bind",
          "typed-mjcf physics.bind(joints).qpos, cached binding",
          "mujoco.MjModel.from_xml_string(the model's text) (floor)",
          "typed-mjcf Physics.from_mjcf_model(model)")
CASES = ("floor", "first_bind", "cached", "compile_floor", "from_mjcf_model")  # (for targets)


def bind_cases(n: int = JOINTS) -> list[Callable[[], object]]:
    """The cases of :data:`LABELS` on a model of ``n`` joints (also counted by
    ``python -m tests.bench.instructions --bind``)."""
    import mujoco
    import numpy as np

    import typed_mjcf as mjcf

    model = _model(n)
    joints = model.find_all("joint")
    names = [j.full_identifier for j in joints]
    physics = mjcf.Physics.from_mjcf_model(model)
    m, d = physics.model, physics.data
    d.qpos[:] = np.arange(m.nq)

    def by_hand() -> object:
        ids = [mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, name) for name in names]
        return d.qpos[m.jnt_qposadr[ids]]

    def first_bind() -> object:
        physics._bindings.clear()  # a first bind each run, not the cached one
        return physics.bind(joints).qpos

    def cached() -> object:
        return physics.bind(joints).qpos

    np.testing.assert_array_equal(np.asarray(first_bind()), np.asarray(by_hand()))
    text = model.to_xml_string()
    return [by_hand, first_bind, cached, lambda: mujoco.MjModel.from_xml_string(text),
            lambda: mjcf.Physics.from_mjcf_model(model)]


def bench_bind(n: int = JOINTS, repeats: int = 21) -> list[dict[str, Any]]:
    """The rows of the bind table: label, median seconds, ratio to the mj_name2id floor."""
    by_hand, first_bind, cached, compile_text, from_model = bind_cases(n)
    compiles = max(3, (repeats + 1) // 2)  # tens of ms each: fewer runs, as many as noise needs
    floor, first, again = _medians([by_hand, first_bind, cached], repeats)
    compiled, physics_made = _medians([compile_text, from_model], compiles)
    times = [floor, first, again, compiled, physics_made]
    bases = [floor, floor, floor, compiled, compiled]
    return [{"label": label, "case": case, "median": t, "ratio": t / base, "n": n}
            for label, case, t, base in zip(LABELS, CASES, times, bases, strict=True)]


def render_bind(rows: list[dict[str, Any]]) -> list[str]:
    if not rows:
        return []
    out = ["## Bind", "",
           (f"{rows[0]['n']:,} hinge joints of a compiled model, their qpos read: "
            "physics.bind() against doing it by hand with mj_name2id; the physics made from "
            "the model against MuJoCo compiling the model's text (the floor above each)."), "",
           "| case | median | ratio to the floor |", "|---|---|---|"]
    out += [f"| {r['label']} | {r['median'] * 1000:.3f} ms | {r['ratio']:.2f}x |" for r in rows]
    return [*out, ""]


if __name__ == "__main__":
    print("\n".join(render_bind(bench_bind())))
