"""The variation workload (issue 39): randomised worlds of a real robot, and structural
variants on local processes and Ray.

Parametric: dm_control's ``suite/humanoid.xml``, every geom's friction and every joint's
damping varied; ``Variation.draw`` of N worlds (sampling, each value checked by its
attribute's codec) against N recompiles (``compile_worlds``: copy, assign, compile), in
process CPU time. Writing the drawn values into compiled models without a recompile (CPU
copies, MuJoCo Warp) is the warp part's row, beside these.

Structural: ``scene`` (1 to 5 objects of random shapes, one of two grippers attached) built,
validated, exported and compiled by ``generate`` on 1 and 2 local processes and on a local Ray
cluster (when Ray is installed; started before the timing): variants per second of wall time,
so the machine's load (in the report's header) matters.
"""

from __future__ import annotations

import gc
import time
from pathlib import Path
from typing import Any

import numpy as np

PARAMETRIC_WORLDS = 1_000
STRUCTURAL_WORLDS = 200
ROOT = Path(__file__).resolve().parents[2]


def scene(rng: np.random.Generator, world: int) -> Any:
    """A structural variant (module-level: it pickles by name to workers)."""
    from tests.variation.builders import table_scene

    return table_scene(rng, world)


def _robot() -> Any:
    import typed_mjcf as mjcf
    from tests.bench.workloads import humanoid_path
    from typed_mjcf.variation import Variation, uniform

    model = mjcf.from_path(humanoid_path().replace("humanoid_CMU.xml", "humanoid.xml"))
    v = Variation()
    for geom in model.find_all("geom"):
        v.of(geom).friction = (uniform(0.5, 1.5), 0.005, 1e-4)
    for joint in model.find_all("joint"):
        if joint.tag == "joint":
            v.of(joint).damping = uniform(0.0, 2.0)
    return model, v


def bench_variation(parametric: int = PARAMETRIC_WORLDS, structural: int = STRUCTURAL_WORLDS,
                    ray: bool = True) -> list[dict[str, Any]]:
    """The rows of the variation table: label, seconds, worlds, per second, how measured
    (``ray=False``: no Ray row, whose cluster takes tens of seconds to start)."""
    from typed_mjcf.variation import compile_worlds, generate

    model, v = _robot()
    rows: list[dict[str, Any]] = []
    start = time.process_time()
    draws = v.draw(seed=0, n=parametric)
    rows.append(_row(f"sample {len(v)} attributes (draw)", time.process_time() - start,
                     parametric, "CPU"))
    start = time.process_time()
    compiled = compile_worlds(model, draws)
    rows.append(_row("recompile per world (copy, assign, compile)",
                     time.process_time() - start, len(compiled), "CPU"))
    del compiled, draws, model  # (a process forked with 1,000 compiled models costs more)
    gc.collect()
    for processes in (1, 2):
        start = time.perf_counter()
        generate(scene, seed=0, n=structural, processes=processes, compile=True)
        rows.append(_row(f"structural variants, {processes} process"
                         f"{'es' if processes > 1 else ''}", time.perf_counter() - start,
                         structural, "wall"))
    if ray:
        rows.append(_on_ray(structural))
    return rows


def _on_ray(n: int) -> dict[str, Any]:
    from typed_mjcf.variation import generate

    try:
        import ray
    except ImportError:
        return _row("structural variants, Ray (not installed: pip install 'typed-mjcf[ray]')",
                    None, n, "wall")
    try:
        ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False,
                 runtime_env={"env_vars": {"PYTHONPATH": str(ROOT)}})
    except Exception as error:  # noqa: BLE001 (Ray raises Exception: a loaded machine, its 30 s start deadline)
        return _row(f"structural variants, Ray (could not start: {error})", None, n, "wall")
    try:
        generate(scene, seed=0, n=2, ray=True, chunk=1)  # workers started, modules imported
        start = time.perf_counter()
        generate(scene, seed=0, n=n, ray=True, compile=True)
        return _row("structural variants, Ray (local, 2 CPUs)", time.perf_counter() - start,
                    n, "wall")
    finally:
        ray.shutdown()


def _row(label: str, seconds: float | None, n: int, clock: str) -> dict[str, Any]:
    return {"label": label, "seconds": seconds, "n": n, "clock": clock,
            "per_second": None if not seconds else n / seconds}


def render_variation(rows: list[dict[str, Any]]) -> list[str]:
    if not rows:
        return []
    out = ["## Variation", "",
           ("Randomised worlds of dm_control's humanoid (sampling against a recompile per "
            "world), and structural variants built, validated, exported and compiled "
            "(wall time: the header's load average matters)."), "",
           "| case | worlds | time | per second | clock |", "|---|---|---|---|---|"]
    for r in rows:
        time_text = "-" if r["seconds"] is None else f"{r['seconds']:.3f} s"
        rate = "-" if r["per_second"] is None else f"{r['per_second']:,.0f}"
        out.append(f"| {r['label']} | {r['n']:,} | {time_text} | {rate} | {r['clock']} |")
    return [*out, ""]


if __name__ == "__main__":
    print("\n".join(render_variation(bench_variation())))
