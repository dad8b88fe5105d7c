"""``python -m tests.bench.builds``: typed-mjcf's builds side by side (the pure-Python one and
the one mypyc compiled), each against raw lxml, in one run.

Two builds of one package cannot share a process, so each runs in a child process of its own
(a Python that imports that build), and the parent asks them in turn, round robin, to time
one workload at a time: a change of load on a shared machine falls on both builds alike.
Each child times raw lxml too, and the ratio of a build is to the lxml of its own process.

    python -m tests.bench.builds --build pure=.venv/bin/python \\
        --build compiled=/tmp/compiled-venv/bin/python
    python -m tests.bench.builds --build pure=python --build compiled=python@/tmp/build/src
    python -m tests.bench.builds --quick ...     # tiny sizes, a few seconds

``NAME=PYTHON[@PATH]``: ``PATH`` goes first on the child's ``PYTHONPATH`` (a folder holding a
``typed_mjcf``). Each child prints the build it runs (``typed_mjcf.COMPILED``) first, so the
report says which build each column is. Times are CPU medians (``time.process_time``).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any, TextIO

REPO = Path(__file__).resolve().parents[2]

# (label, workload, size): W1 build + export of N named bodies, W2 parse + export of
# humanoid_CMU.xml and of W1's output at N, W3 attach K arms + export (issue 38's targets)
FULL = (("W1 5,000 bodies", "W1", 5_000, 7), ("W2 humanoid_CMU.xml", "W2h", 0, 21),
        ("W2 W1's text (5,000)", "W2t", 5_000, 7), ("W3 attach 500", "W3", 500, 5))
QUICK = (("W1 50 bodies", "W1", 50, 3), ("W2 humanoid_CMU.xml", "W2h", 0, 3),
         ("W2 W1's text (50)", "W2t", 50, 3), ("W3 attach 5", "W3", 5, 3))
TARGETS = {"W1": 1.6, "W2h": 3.0, "W2t": 8.0, "W3": 2.5}  # issue 38, compiled build vs lxml


# ---------------------------------------------------------------------------- the child


def _serve(stdin: TextIO, stdout: TextIO) -> None:
    """Answer requests (one JSON line each: workload, library, size) with CPU seconds."""
    import typed_mjcf
    from tests.bench.timing import run_once
    from tests.bench.workloads import ADAPTERS, humanoid_path

    adapters = {key: ADAPTERS[key]() for key in ("typed", "lxml")}
    for adapter in adapters.values():
        adapter.load()
    texts: dict[int, str] = {}
    print(json.dumps({"compiled": list(typed_mjcf.COMPILED),
                      "file": typed_mjcf.__file__}), file=stdout, flush=True)
    for line in stdin:
        request = json.loads(line)
        adapter, size = adapters[request["library"]], int(request["size"])
        kind = request["workload"]
        if kind == "W1":
            workload = adapter.w1(size, True, adapter.w1_apis()[0])
        elif kind == "W2h":
            workload = adapter.w2_path(humanoid_path())
        elif kind == "W2t":
            if size not in texts:  # typed-mjcf's W1 output, as tests/bench's W2 takes it
                maker = adapters["typed"].w1(size, True, adapters["typed"].w1_apis()[0])
                texts[size] = maker.export(maker.make())
            workload = adapter.w2_text(texts[size])
        else:
            workload = adapter.w3(size)
        sample, _ = run_once(workload)
        print(json.dumps({"cpu": sample.cpu}), file=stdout, flush=True)


# ---------------------------------------------------------------------------- the parent


class Child:
    def __init__(self, name: str, spec: str) -> None:
        python, _, path = spec.partition("@")
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (path, str(REPO), env.get("PYTHONPATH", "")) if p)
        self.name = name
        self.process = subprocess.Popen(
            [python, "-m", "tests.bench.builds", "--serve"], cwd=REPO, env=env, text=True,
            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.info = self._read()

    def _read(self) -> dict[str, Any]:
        assert self.process.stdout is not None
        line = self.process.stdout.readline()
        if not line:
            raise RuntimeError(f"build {self.name!r}: the child stopped (see its error above)")
        return dict(json.loads(line))

    def time(self, workload: str, library: str, size: int) -> float:
        assert self.process.stdin is not None
        self.process.stdin.write(json.dumps(
            {"workload": workload, "library": library, "size": size}) + "\n")
        self.process.stdin.flush()
        return float(self._read()["cpu"])

    def close(self) -> None:
        assert self.process.stdin is not None
        self.process.stdin.close()
        self.process.wait()


def run(builds: dict[str, str], cases: Sequence[tuple[str, str, int, int]],
        ) -> dict[str, dict[str, dict[str, float]]]:
    """Median CPU seconds: {case label: {"<build> typed" | "<build> lxml": seconds}}."""
    children = [Child(name, spec) for name, spec in builds.items()]
    try:
        for child in children:
            compiled = child.info["compiled"]
            print(f"{child.name}: {child.info['file']} "
                  f"({'compiled: ' + ', '.join(compiled) if compiled else 'pure Python'})",
                  file=sys.stderr, flush=True)
        medians: dict[str, dict[str, float]] = {}
        for label, workload, size, repeats in cases:
            samples: dict[str, list[float]] = {}
            for child in children:  # one warm-up run each, untimed
                for library in ("typed", "lxml"):
                    child.time(workload, library, size)
            for round_ in range(repeats):
                order = children if round_ % 2 == 0 else children[::-1]
                for child in order:
                    for library in ("typed", "lxml") if round_ % 2 == 0 else ("lxml", "typed"):
                        samples.setdefault(f"{child.name} {library}", []).append(
                            child.time(workload, library, size))
            medians[label] = {key: statistics.median(values) for key, values in samples.items()}
            print(f"  {label}: done", file=sys.stderr, flush=True)
        return {"medians": medians}
    finally:
        for child in children:
            child.close()


def render(builds: Sequence[str], cases: Sequence[tuple[str, str, int, int]],
           medians: dict[str, dict[str, float]]) -> str:
    head = "| workload | " + " | ".join(
        f"{build} (ms) | {build} / lxml" for build in builds) + " | target |"
    lines = [head, "|" + "---|" * (2 * len(builds) + 2)]
    for label, workload, _, _ in cases:
        row = medians[label]
        cells = []
        for build in builds:
            typed, lxml = row[f"{build} typed"], row[f"{build} lxml"]
            cells += [f"{typed * 1e3:,.1f}", f"{typed / lxml:.2f}x"]
        lines.append(f"| {label} | " + " | ".join(cells) + f" | <= {TARGETS[workload]}x |")
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.bench.builds", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", action="append", default=[], metavar="NAME=PYTHON[@PATH]")
    parser.add_argument("--quick", action="store_true", help="tiny sizes (a few seconds)")
    parser.add_argument("--json", metavar="PATH", help="save the medians as JSON")
    parser.add_argument("--serve", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.serve:
        _serve(sys.stdin, sys.stdout)
        return 0
    builds = dict(spec.split("=", 1) for spec in args.build)
    if not builds:
        parser.error("name at least one --build NAME=PYTHON[@PATH]")
    cases = QUICK if args.quick else FULL
    result = run(builds, cases)
    print(render(list(builds), cases, result["medians"]))
    if args.json:
        Path(args.json).write_text(json.dumps(result, indent=2), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
