"""Instructions (callgrind's ``Ir``) each phase of a fixed workload executes, for copies of
``src/`` and ``generated/`` side by side: counted, where time on a shared machine swings.
What remains is the memory layout's noise (a change anywhere moves where objects live, and
what hashes by address): each copy runs once per environment padding (``--pads``), which
moves the process's memory, and the median is reported with its spread.

    git archive 3996bec^ src generated | tar -x -C /tmp/before    # a copy to compare with
    python -m tests.bench.instructions before=/tmp/before now=.   # ratios against the first
    python -m tests.bench.instructions --bind --pads 0 before=/tmp/before now=.  # bind cases

Needs valgrind; runs from the repository root (the workloads are ``tests/bench``'s, the
library each copy's: its ``src/`` and ``generated/`` come first on ``PYTHONPATH``). Each
phase is counted between two ``os.getppid()`` calls, after one untimed round of every
phase (caches, checked texts, write plans), with the cyclic collector off.

``--floors`` counts issue 38's workloads at their sizes, each beside raw lxml doing the same
XML work (its ratio to that floor), and a copy given as ``LABEL=python:PATH`` is the
typed-mjcf installed for the interpreter ``PATH`` (a compiled build), not a folder:

    python -m tests.bench.instructions --floors --pads 0 pure=. compiled=python:.venv-c/bin/python

``--steps`` counts ``Physics.from_mjcf_model`` on the bind workload's model step by step,
each against MuJoCo compiling the same text (``docs/benchmarks.md`` has the table).
"""

from __future__ import annotations

import argparse
import gc
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
N = 300  # W1's bodies


PHASES = ("W1 build (N=300, named, add_<tag>())", "W1 export", "W2 parse W1's text",
          "W2 export parsed", "humanoid_CMU parse + export",
          "W3 build + attach + export (k=10)", "W1 generic add(), unnamed")


def _phases() -> list[Callable[[], object]]:
    """The workload of each of :data:`PHASES`, in order."""
    from tests.bench import workloads as w

    w.TypedMjcf().load()
    mjcf: Any = w.mjcf_t
    text = w._typed_export(w._typed_w1(N, True))
    human = w.humanoid_path()
    built: list[object] = [None]
    parsed: list[object] = [None]

    def build() -> None:
        built[0] = w._typed_w1(N, True)

    def parse() -> None:
        parsed[0] = mjcf.from_xml_string(text)

    return [build, lambda: w._typed_export(built[0]), parse,
            lambda: w._typed_export(parsed[0]),
            lambda: w._typed_export(mjcf.from_path(human)),
            lambda: w._typed_export(w._typed_w3(10)),
            lambda: w._typed_w1_generic(N, False)]


# --bind: the bind workload's cases (tests/bench/bind.py), each with the floor it is
# compared with (an index into BIND_PHASES)
BIND_PHASES = ("bind floor: mj_name2id + slices", "physics.bind(joints).qpos, first bind",
               "compile floor: MjModel.from_xml_string", "Physics.from_mjcf_model(model)")
BIND_FLOORS = (0, 0, 2, 2)


def _bind_phases() -> list[Callable[[], object]]:
    from tests.bench.bind import bind_cases

    by_hand, first_bind, _, compile_text, from_model = bind_cases()
    return [by_hand, first_bind, compile_text, from_model]


# --floors: issue 38's workloads, each after its floor (raw lxml doing the same XML work)
FLOOR_PHASES = ("W1 floor: lxml (N=5,000, named)", "W1 build + export (N=5,000, named)",
                "humanoid floor: lxml", "humanoid_CMU parse + export",
                "W1 text floor: lxml", "W2 parse + export W1's text (N=5,000)",
                "W3 floor: lxml (K=500)", "W3 build + attach + export (K=500)")
FLOOR_OF = (0, 0, 2, 2, 4, 4, 6, 6)


def _floor_phases() -> list[Callable[[], object]]:
    from tests.bench import workloads as w

    w.TypedMjcf().load()
    w.RawLxml().load()
    mjcf: Any = w.mjcf_t
    human = w.humanoid_path()
    text = w._typed_export(w._typed_w1(5000, True))
    return [lambda: w._lxml_export(w._lxml_w1(5000, True)),
            lambda: w._typed_export(w._typed_w1(5000, True)),
            lambda: w._lxml_export(w._lxml_parse_path(human)),
            lambda: w._typed_export(mjcf.from_path(human)),
            lambda: w._lxml_export(w._lxml_parse_text(text)),
            lambda: w._typed_export(mjcf.from_xml_string(text)),
            lambda: w._lxml_export(w._lxml_w3(500)),
            lambda: w._typed_export(w._typed_w3(500))]


# --steps: Physics.from_mjcf_model on the bind workload's model, step by step, each against
# the compile floor (what takes it past MuJoCo's own reading and compiling of the text)
STEP_PHASES = ("compile floor: MjModel.from_xml_string", "validation (ensure_valid)",
               "resource checks (check_compile)", "export with marker names",
               "MjSpec read + markers cleared + compile", "ids of the unnamed elements",
               "copy into physics.model's class", "Physics.from_mjcf_model(model), all")
STEP_FLOORS = (0,) * len(STEP_PHASES)


def _step_phases() -> list[Callable[[], object]]:
    import mujoco

    import typed_mjcf as mjcf
    from tests.bench.bind import _model
    from typed_mjcf import physics
    from typed_mjcf._core.tree import Element
    from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, check_compile
    from typed_mjcf._model.validate import ensure_valid
    from typed_mjcf._sim import ids
    from typed_mjcf._sim.text import vfs_text

    model = _model(1000)
    text = model.to_xml_string()
    mjcf.Physics.from_mjcf_model(model)  # (the binding tables loaded)

    def export() -> tuple[str, dict[str, bytes], list[Element], dict[int, tuple[Element, str]]]:
        marks: list[Element] = []
        written: dict[int, tuple[Element, str]] = {}
        marked, collected = vfs_text(model, namer=ids._namer(model, marks, written),
                                     limits=DEFAULT_COMPILE_LIMITS)
        return marked, collected.files, marks, written

    marked, files, marks, written = export()
    compiled, found = ids._compile_marked(marked, files, marks)
    return [lambda: mujoco.MjModel.from_xml_string(text), lambda: ensure_valid(model),
            lambda: check_compile(model, DEFAULT_COMPILE_LIMITS), export,
            lambda: ids._compile_marked(marked, files, marks),
            lambda: ids._ids(compiled, found, written), lambda: physics._as_model(compiled),
            lambda: mjcf.Physics.from_mjcf_model(model)]


_MODES: dict[str, tuple[tuple[str, ...], tuple[int, ...] | None]] = {
    "": (PHASES, None), "bind": (BIND_PHASES, BIND_FLOORS), "floors": (FLOOR_PHASES, FLOOR_OF),
    "steps": (STEP_PHASES, STEP_FLOORS)}


def drive(mode: str = "") -> None:
    """The workload, run under callgrind: every phase once untimed, then each counted."""
    phases = {"": _phases, "bind": _bind_phases, "floors": _floor_phases,
              "steps": _step_phases}[mode]()
    for run in phases:
        run()
    gc.collect()
    gc.disable()
    for run in phases:
        os.getppid()
        run()
    os.getppid()


def _count(copy: str, pad: int, out: Path, mode: str = "") -> list[int]:
    """Instructions per phase of one run of ``copy`` (a folder, or ``python:PATH``)."""
    env = dict(os.environ, PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
               PAD="x" * pad)
    python = sys.executable
    if copy.startswith("python:"):  # that interpreter's own typed-mjcf
        python = copy.removeprefix("python:")
    else:
        folder = Path(copy).resolve()
        env["PYTHONPATH"] = f"{folder / 'src'}{os.pathsep}{folder / 'generated'}"
    command = ["valgrind", "--tool=callgrind", "--dump-before=os_getppid*",
               f"--callgrind-out-file={out}", python, "-m",
               "tests.bench.instructions", "--drive", *([f"--{mode}"] if mode else [])]
    if shutil.which("setarch"):  # no address randomisation: one layout per padding
        command = ["setarch", platform.machine(), "-R", *command]
    subprocess.run(command, env=env, cwd=ROOT, check=True, capture_output=True)
    # part 1 is the start and the untimed round, part k + 2 phase k
    return [_summary(Path(f"{out}.{k + 2}")) for k in range(len(_MODES[mode][0]))]


def _summary(path: Path) -> int:
    for line in path.read_text().splitlines():
        if line.startswith("summary:"):
            return int(line.split()[1])
    raise ValueError(f"{path}: no summary line")


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("copies", nargs="*", metavar="LABEL=DIR",
                        help="a folder holding src/ and generated/ (the first is the base)")
    parser.add_argument("--pads", default="0,40,80",
                        help="environment paddings, one run each (default: 0,40,80)")
    parser.add_argument("--jobs", type=int, default=1, help="runs at once (default: 1)")
    parser.add_argument("--bind", action="store_true",
                        help="count the bind workload (tests/bench/bind.py), each case also "
                             "as a ratio to its floor")
    parser.add_argument("--floors", action="store_true",
                        help="count issue 38's workloads, each also as a ratio to raw lxml")
    parser.add_argument("--steps", action="store_true",
                        help="count Physics.from_mjcf_model step by step, each against the "
                             "compile floor")
    parser.add_argument("--drive", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    mode = ("bind" if args.bind else "floors" if args.floors else "steps" if args.steps
            else "")
    if args.drive:
        drive(mode)
        return 0
    copies = [(label, folder) for label, folder in (item.split("=", 1) for item in args.copies)]
    pads = [int(p) for p in args.pads.split(",")]
    phases, floors = _MODES[mode]
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(args.jobs) as pool:
        submitted = {label: [pool.submit(_count, folder, pad, Path(tmp) / f"{label}.{pad}.cg",
                                         mode)
                             for pad in pads] for label, folder in copies}
        counts = {label: [run.result() for run in futures]
                  for label, futures in submitted.items()}
    base = copies[0][0]
    print(f"instructions (millions, median of {len(pads)} layouts, +-half the spread); "
          f"ratios against {base}")
    for k, phase in enumerate(phases):
        cells = []
        for label, _ in copies:
            runs = [run[k] for run in counts[label]]
            median = statistics.median(runs)
            spread = (max(runs) - min(runs)) / 2 / median * 100
            cell = f"{label} {median / 1e6:.2f} (+-{spread:.1f}%)"
            if floors is not None:  # against its floor, in the same runs
                floor = statistics.median([run[floors[k]] for run in counts[label]])
                cell += f" {median / floor:.2f}x"
            if label != base:
                ratio = median / statistics.median([run[k] for run in counts[base]])
                cell += f" {100 * (ratio - 1):+.1f}%"
            cells.append(cell)
        print(f"{phase:36} " + "  ".join(cells))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
