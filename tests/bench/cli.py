"""``python -m tests.bench``: run the workloads, print the report, optionally save JSON."""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from tests.bench import timing
from tests.bench.bind import bench_bind
from tests.bench.builds import RemoteTyped, build_of
from tests.bench.child import IMPORT_SNIPPET, importtime_breakdown
from tests.bench.report import Results, render
from tests.bench.timing import Budget, Case, SizeResult, predict, run_once, run_round_robin
from tests.bench.variation import bench_variation
from tests.bench.workloads import (
    ADAPTERS,
    ARM_LINKS,
    CHAIN,
    Adapter,
    Workload,
    humanoid_path,
)

REPO = Path(__file__).resolve().parents[2]
WORKLOADS = ("W1", "W2", "W3", "bind", "variation", "import", "memory")


@dataclass(frozen=True)
class Plan:
    mode: str
    w1_sizes: tuple[int, ...]
    w1_repeats: dict[int, int]
    # dm_control's unnamed export is quadratic: it runs at these sizes only (the small ones
    # show the growth), the larger W1 sizes are reported as skipped, with an estimate.
    dm_unnamed_sizes: tuple[int, ...]
    w2_text_n: int
    w2_repeats: dict[str, int]
    w3_sizes: tuple[int, ...]
    w3_repeats: dict[int, int]
    import_repeats: int
    import_modules: tuple[str, ...]
    memory_n: int
    bind_joints: int = 1_000
    bind_repeats: int = 21
    variation_worlds: tuple[int, int] = (1_000, 200)  # parametric, structural
    warm_n: int = 20
    warm_k: int = 2
    budget: Budget = field(default_factory=Budget)


FULL = Plan(
    mode="full",
    w1_sizes=(1_000, 5_000, 20_000),
    w1_repeats={250: 3, 500: 3, 1_000: 7, 5_000: 5, 20_000: 3},
    dm_unnamed_sizes=(250, 500, 1_000, 5_000),
    w2_text_n=5_000,
    w2_repeats={"humanoid": 21, "w1": 5},
    w3_sizes=(10, 100, 500),
    w3_repeats={10: 9, 100: 5, 500: 3},
    import_repeats=7,
    import_modules=("typed_mjcf", "lxml.etree", "mujoco", "dm_control.mjcf"),
    memory_n=20_000,
)

QUICK = Plan(
    mode="quick",
    w1_sizes=(20, 50),
    w1_repeats={20: 2, 50: 2},
    dm_unnamed_sizes=(20, 50),
    w2_text_n=50,
    w2_repeats={"humanoid": 2, "w1": 2},
    w3_sizes=(2, 5),
    w3_repeats={2: 2, 5: 2},
    import_repeats=2,
    import_modules=("typed_mjcf",),
    memory_n=50,
    bind_joints=20,
    bind_repeats=3,
    variation_worlds=(4, 4),  # and no Ray row (its start: tens of seconds)
    budget=Budget(per_case_size=5.0, max_run=10.0),
)


def log(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------- checks


def _compile(text: str) -> Any:
    import mujoco

    return mujoco.MjModel.from_xml_string(text)


def _counts(model: Any) -> dict[str, int]:
    return {k: int(getattr(model, k)) for k in ("njnt", "ngeom", "nsite", "nu", "nsensor")}


def check(results: Results, label: str, text: str, expected: dict[str, int]) -> tuple[bool, str]:
    """Whether ``text`` compiles to a model with the ``expected`` counts; recorded."""
    try:
        found = _counts(_compile(text))
    except Exception as error:  # noqa: BLE001 - MuJoCo's refusal is the finding
        valid, message = False, f"does not compile: {str(error).splitlines()[0]}"
    else:
        wrong = {k: (found[k], v) for k, v in expected.items() if found[k] != v}
        valid = not wrong
        message = "" if valid else "counts (found, expected): " + ", ".join(
            f"{k} {f}/{e}" for k, (f, e) in wrong.items())
    results.validity.append({"case": label, "valid": valid, "error": message})
    return valid, message


def w1_expected(n: int) -> dict[str, int]:
    return {"njnt": n, "ngeom": n, "nsite": n, "nu": n, "nsensor": n}


def w3_expected(k: int) -> dict[str, int]:
    return {"njnt": k * ARM_LINKS, "ngeom": k * ARM_LINKS, "nsite": 2 * k, "nu": k * ARM_LINKS}


# ----------------------------------------------------------------------------- sized workloads


def run_sized(
    results: Results,
    cases: list[Case],
    adapters: dict[str, Adapter],
    sizes: Sequence[int],
    repeats: dict[int, int],
    workload_of: Callable[[Adapter, Case, int], Workload],
    allowed: Callable[[Case], Sequence[int]],
    warm: int,
    expected: Callable[[int], dict[str, int]],
    plan: Plan,
) -> None:
    # Warm-up and output check, outside the timing: a tiny run of every case.
    for case in cases:
        try:
            _, text = run_once(workload_of(adapters[case.library], case, warm))
        except Exception as error:  # noqa: BLE001 - a library failing is a result
            case.note = f"failed at the warm-up size: {type(error).__name__}: {error}"[:300]
            continue
        valid, message = check(results, f"{case.workload} {case.label} at {warm}", text,
                               expected(warm))
        if not valid:
            case.note = f"output at size {warm} is wrong: {message}"
    every = sorted(set(sizes).union(*(allowed(c) for c in cases)))
    for size in every:
        chosen: dict[int, Workload] = {}
        for case in cases:
            if size not in allowed(case) and size not in sizes:
                continue
            result = case.sizes[size] = SizeResult(size)
            estimate = predict(case, size)
            if size not in allowed(case):
                result.skipped = "capped"
                result.estimate = estimate
                continue
            if estimate is not None and estimate > plan.budget.max_run:
                result.skipped = f"predicted over the {plan.budget.max_run:.0f} s budget"
                result.estimate = estimate
                continue
            chosen[id(case)] = workload_of(adapters[case.library], case, size)
        log(f"  size {size:,}: {len(chosen)} cases, up to {repeats.get(size, 1)} runs each")
        run_round_robin(cases, size, chosen, repeats.get(size, 1), plan.budget)
        for case in cases:
            result = case.sizes.get(size)
            if result is not None and result.samples:
                log(f"    {case.label:<48} {_both(result)} ({len(result.samples)} runs)")
            elif result is not None and result.error:
                log(f"    {case.label:<48} failed: {result.error}")


def _both(result: SizeResult) -> str:
    cpu, wall = result.median(clock="cpu"), result.median(clock="wall")
    assert cpu is not None and wall is not None
    return f"CPU {cpu * 1000:10.2f} ms, wall {wall * 1000:10.2f} ms"


def bench_w1(results: Results, adapters: dict[str, Adapter], plan: Plan) -> None:
    log("W1 build + export")
    cases: list[Case] = []
    for naming in ("named", "unnamed"):
        for key, adapter in adapters.items():
            for api in adapter.w1_apis():
                case = Case("W1", key, adapter.title, api=api, naming=naming)
                if key == "dm_control" and naming == "unnamed":
                    case.note = (
                        "joints unnamed too, referred to as elements; quadratic export, so it "
                        f"runs only at N={', '.join(f'{n:,}' for n in plan.dm_unnamed_sizes)} "
                        f"and within the time budget")
                cases.append(case)

    def allowed(case: Case) -> Sequence[int]:
        if case.library == "dm_control" and case.naming == "unnamed":
            return plan.dm_unnamed_sizes
        return plan.w1_sizes

    run_sized(results, cases, adapters, plan.w1_sizes, plan.w1_repeats,
              lambda a, c, n: a.w1(n, c.naming == "named", c.api), allowed, plan.warm_n,
              w1_expected, plan)
    for case in cases:
        extra = [n for n in sorted(case.sizes) if n not in plan.w1_sizes]
        if extra:
            measured = ", ".join(
                f"N={n:,}: {case.sizes[n].median() * 1000:,.0f} ms" for n in extra
                if case.sizes[n].samples)
            if measured:
                case.note += f" (also measured {measured}"
                done = [(n, r.median()) for n, r in sorted(case.sizes.items()) if r.samples]
                if len(done) >= 2:
                    (n1, t1), (n2, t2) = done[0], done[-1]
                    assert t1 is not None and t2 is not None
                    case.note += (f"; t ~ N^{timing.growth_exponent(n1, t1, n2, t2):.2f} "
                                  f"from N={n1:,} to {n2:,}")
                case.note += ")"
        for n in plan.w1_sizes:
            r = case.sizes.get(n)
            if r is not None and r.skipped and r.estimate is not None:
                case.note += ("; " if case.note else "") + (
                    f"N={n:,} skipped ({r.skipped}), est. {r.estimate:,.0f} s (wall) a run")
    results.w1 = cases
    results.meta["w1_sizes"] = list(plan.w1_sizes)


def bench_w3(results: Results, adapters: dict[str, Adapter], plan: Plan) -> None:
    log("W3 compose")
    cases = [Case("W3", key, adapter.title) for key, adapter in adapters.items()]
    run_sized(results, cases, adapters, plan.w3_sizes, plan.w3_repeats,
              lambda a, c, k: a.w3(k), lambda c: plan.w3_sizes, plan.warm_k, w3_expected, plan)
    results.w3 = cases
    results.meta["w3_sizes"] = list(plan.w3_sizes)


def bench_w2(results: Results, adapters: dict[str, Adapter], plan: Plan) -> None:
    log("W2 parse + export")
    sources: list[tuple[str, str, str, int]] = []  # (label, kind, path or text, repeats)
    try:
        path = humanoid_path()
    except RuntimeError as error:
        log(f"  {error}")
    else:
        sources.append(("humanoid_CMU.xml", "path", path, plan.w2_repeats["humanoid"]))
    maker = adapters.get("typed") or adapters.get("lxml")
    if maker is not None:
        text = maker.w1(plan.w2_text_n, True, maker.w1_apis()[0])
        text_xml = text.export(text.make())
        sources.append((f"W1 N={plan.w2_text_n:,} output ({len(text_xml) / 1e6:.2f} MB)",
                        "text", text_xml, plan.w2_repeats["w1"]))
    import mujoco

    for label, kind, source, repeats in sources:
        reference = (mujoco.MjModel.from_xml_path(source) if kind == "path"
                     else mujoco.MjModel.from_xml_string(source))
        expected = _counts(reference)
        cases = [Case("W2", key, adapter.title, source=label) for key, adapter in adapters.items()]
        chosen: dict[int, Workload] = {}
        for case in cases:
            adapter = adapters[case.library]
            workload = adapter.w2_path(source) if kind == "path" else adapter.w2_text(source)
            result = case.sizes[0] = SizeResult(len(source))
            try:  # warm-up and output check
                _, out = run_once(workload)
            except Exception as error:  # noqa: BLE001 - a library failing is a result
                result.error = f"{type(error).__name__}: {error}"[:300]
                continue
            result.valid, result.invalid = check(results, f"W2 {case.label}", out, expected)
            chosen[id(case)] = workload
        log(f"  {label}: {len(chosen)} cases, {repeats} runs each")
        run_round_robin(cases, 0, chosen, repeats, plan.budget)
        for case in cases:
            result = case.sizes[0]
            if result.samples:
                log(f"    {case.label:<48} {_both(result)}")
        results.w2 += cases


# ----------------------------------------------------------------------------- subprocesses


def _child_env(bytecode: bool) -> dict[str, str]:
    env = dict(os.environ)
    if bytecode:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(REPO), *filter(None, [env.get("PYTHONPATH")])])
    return env


def bench_imports(results: Results, plan: Plan, builds: Sequence[RemoteTyped] = (),
                  local: str = "") -> None:
    log("import time")
    env = _child_env(bytecode=True)
    runs = [(module, sys.executable, f"{module} [{local}]" if local and module == "typed_mjcf"
             else module) for module in plan.import_modules]
    runs += [("typed_mjcf", b.python, b.title.replace("typed-mjcf", "typed_mjcf")) for b in builds
             if "typed_mjcf" in plan.import_modules]
    for module, python, label in runs:
        command = [python, "-c", IMPORT_SNIPPET.format(module=module)]
        walls: list[float] = []
        cpus: list[float] = []
        entry: dict[str, Any] = {"module": label, "wall": walls, "cpu": cpus}
        try:
            subprocess.run(command, env=env, cwd=REPO, check=True, capture_output=True)  # warm-up
            for _ in range(plan.import_repeats):
                out = subprocess.run(command, env=env, cwd=REPO, check=True,
                                     capture_output=True, text=True)
                wall, cpu = out.stdout.strip().splitlines()[-1].split()
                walls.append(float(wall))
                cpus.append(float(cpu))
        except (subprocess.CalledProcessError, ValueError, IndexError) as error:
            entry["error"] = str(error)[:300]
        entry["samples"] = cpus if timing.CLOCK == "cpu" else walls
        entry["median"] = statistics.median(entry["samples"]) if entry["samples"] else None
        entry["median_wall"] = statistics.median(walls) if walls else None
        entry["median_cpu"] = statistics.median(cpus) if cpus else None
        if walls:
            log(f"  {label:<20} CPU {entry['median_cpu']:.3f} s, "
                f"wall {entry['median_wall']:.3f} s")
        results.imports.append(entry)
    try:
        rows = importtime_breakdown("typed_mjcf", env)
    except subprocess.CalledProcessError:
        return
    results.importtime = rows


def bench_memory(results: Results, adapters: dict[str, Adapter], plan: Plan) -> None:
    log(f"peak memory, W1 N={plan.memory_n:,}")
    for key, adapter in adapters.items():
        python = adapter.python if isinstance(adapter, RemoteTyped) else sys.executable
        library = "typed" if isinstance(adapter, RemoteTyped) else key
        command = [python, "-m", "tests.bench.child", "memory", library, str(plan.memory_n)]
        try:
            out = subprocess.run(command, env=_child_env(bytecode=False), cwd=REPO, check=True,
                                 capture_output=True, text=True, timeout=900)
            entry = json.loads(out.stdout.strip().splitlines()[-1])
        except (subprocess.CalledProcessError, subprocess.TimeoutExpired, ValueError) as error:
            entry = {"library": key, "error": str(error)[:300]}
        entry["library"] = adapter.title
        if "error" not in entry:
            log(f"  {key:<12} +{(entry['peak_bytes'] - entry['baseline_bytes']) / 2**20:.0f} MiB")
        results.memory.append(entry)


# ----------------------------------------------------------------------------- main


def _load_average() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "?"


def _git_state() -> str:
    """The commit measured, and whether the runtime differs from it (read-only git calls)."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=REPO, check=True,
                              capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--", "src", "generated"],
                               cwd=REPO, check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return head + (" + uncommitted changes in src/ or generated/" if dirty.strip() else "")


def _bind_rows(rows: list[dict[str, Any]], title: str) -> list[dict[str, Any]]:
    """The bind rows of one build: its own rows named by ``title``, the floor measured in
    the same process named as such."""
    for row in rows:
        row["label"] = (row["label"].replace("typed-mjcf", title) if "typed-mjcf" in row["label"]
                        else f"{row['label']}, in the process of {title}")
    return rows


def parse_args(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog="python -m tests.bench",
        description="typed-mjcf side by side with dm_control.mjcf, MjSpec and raw lxml.")
    parser.add_argument("--quick", action="store_true", help="tiny sizes (a few seconds)")
    parser.add_argument("--json", metavar="PATH", help="save the raw numbers as JSON")
    parser.add_argument("--from-json", metavar="PATH",
                        help="run nothing: print the report of a run saved with --json")
    parser.add_argument("--only", default=",".join(WORKLOADS),
                        help=f"comma-separated subset of {','.join(WORKLOADS)}")
    parser.add_argument("--libs", default=",".join(ADAPTERS),
                        help=f"comma-separated subset of {','.join(ADAPTERS)}")
    parser.add_argument("--budget", type=float, default=None,
                        help="seconds a case may spend at one size before it stops repeating")
    parser.add_argument("--max-run", type=float, default=None,
                        help="skip a size whose single run is predicted to take longer (s)")
    parser.add_argument("--build", action="append", default=[], metavar="NAME=PYTHON",
                        help="also run typed-mjcf's workloads with the typed-mjcf of another "
                             "interpreter (e.g. compiled=.venv-mypyc/bin/python), in a child "
                             "process, round robin with the others; repeatable")
    parser.add_argument("--clock", choices=timing.CLOCKS, default=timing.CLOCK,
                        help="what the tables report: process CPU time (default; robust on "
                             "a shared machine) or wall-clock time; the JSON has both")
    args = parser.parse_args(argv)
    for name, valid in (("only", WORKLOADS), ("libs", tuple(ADAPTERS))):
        chosen = [x.strip() for x in getattr(args, name).split(",") if x.strip()]
        unknown = [x for x in chosen if x not in valid]
        if unknown:
            parser.error(f"--{name}: unknown {', '.join(unknown)}; choose from {', '.join(valid)}")
        setattr(args, name, chosen)
    builds = []
    for item in args.build:
        name, _, python = item.partition("=")
        if not name or not python:
            parser.error(f"--build: {item!r} is not NAME=PYTHON")
        builds.append((name, python))
    args.build = builds
    return args


def main(argv: Sequence[str] | None = None) -> int:
    args = parse_args(argv)
    timing.CLOCK = args.clock
    if args.from_json:
        saved = Results.from_json(json.loads(Path(args.from_json).read_text()))
        saved.meta["clock"] = args.clock
        print(render(saved))
        return 0
    plan = QUICK if args.quick else FULL
    if args.budget is not None or args.max_run is not None:
        plan = Plan(**{**plan.__dict__, "budget": Budget(
            args.budget if args.budget is not None else plan.budget.per_case_size,
            args.max_run if args.max_run is not None else plan.budget.max_run)})
    results = Results()
    adapters: dict[str, Adapter] = {}
    unavailable: dict[str, str] = {}
    for key in args.libs:
        adapter = ADAPTERS[key]()
        why = adapter.available()
        if why is None:
            adapters[key] = adapter
        else:
            unavailable[key] = why
    if "lxml" in args.libs and "lxml" not in adapters:
        log("lxml is needed for the floor")
        return 2
    local_build = ""
    if "typed" in adapters:  # every row says which build it measured
        import typed_mjcf

        local_build = build_of(typed_mjcf)
        adapters["typed"].title = f"typed-mjcf [{local_build}]"
    builds: list[RemoteTyped] = []
    for name, python in args.build:
        remote = RemoteTyped(name, python)
        why = remote.available()
        if why is None:
            builds.append(remote)
        else:
            unavailable[remote.key] = why
    if builds:  # the builds' rows side by side, before the peers'
        order = [*(["typed"] if "typed" in adapters else []), *(b.key for b in builds)]
        adapters = {**{b.key: b for b in builds}, **adapters}
        adapters = {**{k: adapters[k] for k in order}, **adapters}
    results.meta = {
        "mode": plan.mode,
        "date": datetime.datetime.now().isoformat(timespec="seconds"),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "git": _git_state(),
        "cpus": os.cpu_count(),
        "load_start": _load_average(),
        "versions": {a.title: a.version() for a in adapters.values()},
        "builds": {"typed": local_build, **{b.key: b.info.get("build", "?") for b in builds}},
        "unavailable": unavailable,
        "chain": CHAIN,
        "plan": {k: (v if not isinstance(v, Budget) else v.__dict__)
                 for k, v in plan.__dict__.items()},
        "gc": "enabled (collected before each run)",
        "clock": args.clock,
    }
    if "W1" in args.only:
        bench_w1(results, adapters, plan)
    if "W2" in args.only:
        bench_w2(results, adapters, plan)
    if "W3" in args.only:
        bench_w3(results, adapters, plan)
    if "bind" in args.only and "typed" in adapters:
        log("bind")
        results.bind = _bind_rows(bench_bind(plan.bind_joints, plan.bind_repeats),
                                  adapters["typed"].title)
        for remote in builds:
            results.bind += _bind_rows(remote.bind(plan.bind_joints, plan.bind_repeats),
                                       remote.title)
    if "variation" in args.only and "typed" in adapters:
        log("variation")
        results.variation = bench_variation(*plan.variation_worlds, ray=not args.quick)
    if "import" in args.only:
        bench_imports(results, plan, builds, local_build)
    if "memory" in args.only:
        bench_memory(results, adapters, plan)
    results.meta["load_end"] = _load_average()
    for remote in builds:
        remote.close()
    report = render(results)
    print(report)
    if args.json:
        Path(args.json).write_text(json.dumps(results.as_json(), indent=2) + "\n")
        log(f"raw numbers saved to {args.json}")
    return 0
