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


def drive(bind: bool = False) -> None:
    """The workload, run under callgrind: every phase once untimed, then each counted."""
    phases = _bind_phases() if bind else _phases()
    for run in phases:
        run()
    gc.collect()
    gc.disable()
    for run in phases:
        os.getppid()
        run()
    os.getppid()


def _count(copy: Path, pad: int, out: Path, bind: bool = False) -> list[int]:
    """Instructions per phase of one run of ``copy``."""
    env = dict(os.environ, PYTHONPATH=f"{copy / 'src'}{os.pathsep}{copy / 'generated'}",
               PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
               PAD="x" * pad)
    command = ["valgrind", "--tool=callgrind", "--dump-before=os_getppid*",
               f"--callgrind-out-file={out}", sys.executable, "-m",
               "tests.bench.instructions", "--drive", *(["--bind"] if bind else [])]
    if shutil.which("setarch"):  # no address randomisation: one layout per padding
        command = ["setarch", platform.machine(), "-R", *command]
    subprocess.run(command, env=env, cwd=ROOT, check=True, capture_output=True)
    # part 1 is the start and the untimed round, part k + 2 phase k
    return [_summary(Path(f"{out}.{k + 2}"))
            for k in range(len(BIND_PHASES if bind else PHASES))]


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
    parser.add_argument("--drive", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.drive:
        drive(args.bind)
        return 0
    copies = [(label, Path(folder).resolve())
              for label, folder in (item.split("=", 1) for item in args.copies)]
    pads = [int(p) for p in args.pads.split(",")]
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(args.jobs) as pool:
        submitted = {label: [pool.submit(_count, folder, pad, Path(tmp) / f"{label}.{pad}.cg",
                                         args.bind)
                             for pad in pads] for label, folder in copies}
        counts = {label: [run.result() for run in futures]
                  for label, futures in submitted.items()}
    base = copies[0][0]
    print(f"instructions (millions, median of {len(pads)} layouts, +-half the spread); "
          f"ratios against {base}")
    for k, phase in enumerate(BIND_PHASES if args.bind else PHASES):
        cells = []
        for label, _ in copies:
            runs = [run[k] for run in counts[label]]
            median = statistics.median(runs)
            spread = (max(runs) - min(runs)) / 2 / median * 100
            cell = f"{label} {median / 1e6:.2f} (+-{spread:.1f}%)"
            if args.bind:  # against its floor, in the same runs
                floor = statistics.median([run[BIND_FLOORS[k]] for run in counts[label]])
                cell += f" {median / floor:.2f}x"
            if label != base:
                ratio = median / statistics.median([run[k] for run in counts[base]])
                cell += f" {100 * (ratio - 1):+.1f}%"
            cells.append(cell)
        print(f"{phase:36} " + "  ".join(cells))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
