"""Timing: cases run round-robin (one repeat of each case in turn, so a burst of load on a
shared machine hits every library alike), with a time budget per case and size.

Every run records wall-clock time and the process's CPU time of each phase. The report
uses :data:`CLOCK`: CPU time by default, since all four libraries run these workloads on one
thread and CPU time does not count the time other processes held the core (on a shared
2-core machine wall-clock medians swing by 2x); the budget always counts wall-clock time.
"""

from __future__ import annotations

import gc
import math
import statistics
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Self

from tests.bench.workloads import Workload

CLOCK = "cpu"  # "cpu" or "wall": what SizeResult.median reports unless told
CLOCKS = ("cpu", "wall")


@dataclass
class Sample:
    make: float  # seconds of wall-clock time
    export: float
    make_cpu: float  # seconds of process CPU time
    export_cpu: float
    gc: float = 0.0  # seconds (wall-clock) the cyclic collector ran during make + export
    full_collections: int = 0  # of them, collections of the oldest generation

    @property
    def total(self) -> float:
        return self.make + self.export

    @property
    def cpu(self) -> float:
        return self.make_cpu + self.export_cpu

    def get(self, phase: str, clock: str) -> float:
        if clock == "wall":
            return {"make": self.make, "export": self.export, "total": self.total}[phase]
        return {"make": self.make_cpu, "export": self.export_cpu, "total": self.cpu}[phase]


@dataclass
class Case:
    """One row of a table: a library (and API and naming) on one workload at several sizes."""

    workload: str  # "W1", "W2", "W3"
    library: str  # adapter key
    title: str
    api: str = ""
    naming: str = ""  # "named" / "unnamed" for W1
    source: str = ""  # W2: which text
    note: str = ""
    sizes: dict[int, SizeResult] = field(default_factory=dict)

    @property
    def label(self) -> str:
        return " ".join(x for x in (self.title, self.api, self.naming, self.source) if x)


@dataclass
class SizeResult:
    size: int
    samples: list[Sample] = field(default_factory=list)
    skipped: str = ""  # why the size was not run
    estimate: float | None = None  # predicted seconds when skipped
    valid: bool | None = None  # the output compiled with MuJoCo to the expected model
    invalid: str = ""  # what is wrong with the output
    error: str = ""  # the run failed

    def median_gc(self) -> tuple[float, float] | None:
        """Median seconds in the cyclic collector, and median full collections, per run."""
        if not self.samples:
            return None
        return (statistics.median(s.gc for s in self.samples),
                statistics.median(s.full_collections for s in self.samples))

    def median(self, phase: str = "total", clock: str | None = None) -> float | None:
        """The median seconds of ``phase`` (make, export or total) on ``clock``."""
        if not self.samples:
            return None
        return statistics.median(s.get(phase, clock or CLOCK) for s in self.samples)

    def as_json(self) -> dict[str, Any]:
        return {
            "size": self.size,
            "samples": [{"make": s.make, "export": s.export, "total": s.total,
                         "make_cpu": s.make_cpu, "export_cpu": s.export_cpu, "cpu": s.cpu,
                         "gc": s.gc, "full_collections": s.full_collections}
                        for s in self.samples],
            "median": {f"{phase}_{clock}": self.median(phase, clock)
                       for clock in CLOCKS for phase in ("make", "export", "total")},
            "skipped": self.skipped or None,
            "estimate": self.estimate,
            "valid": self.valid,
            "invalid": self.invalid or None,
            "error": self.error or None,
        }


class CollectorClock:
    """Time spent in CPython's cyclic garbage collector, through ``gc.callbacks``."""

    def __init__(self) -> None:
        self.seconds = 0.0
        self.full_collections = 0
        self._started = 0.0

    def __enter__(self) -> Self:
        gc.callbacks.append(self._callback)
        return self

    def __exit__(self, *exc: object) -> None:
        gc.callbacks.remove(self._callback)

    def _callback(self, phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            self._started = time.perf_counter()
            return
        self.seconds += time.perf_counter() - self._started
        if info["generation"] == 2:
            self.full_collections += 1


def run_once(workload: Workload, text: bool = True) -> tuple[Sample, str]:
    """Time ``make`` then ``export``; return the sample and the text written (``""`` from a
    remote workload unless ``text``)."""
    if workload.remote is not None:
        fields, written = workload.remote(text)
        return Sample(**fields), written
    gc.collect()
    with CollectorClock() as collector:
        c0, t0 = time.process_time(), time.perf_counter()
        model = workload.make()
        c1, t1 = time.process_time(), time.perf_counter()
        text = workload.export(model)
        c2, t2 = time.process_time(), time.perf_counter()
    del model
    return Sample(t1 - t0, t2 - t1, c1 - c0, c2 - c1, collector.seconds,
                  collector.full_collections), text


def growth_exponent(n1: float, t1: float, n2: float, t2: float) -> float:
    """``p`` in ``t ~ n**p`` between two sizes."""
    return math.log(t2 / t1) / math.log(n2 / n1)


def predict(case: Case, size: int) -> float | None:
    """The expected seconds of one run at ``size``, from the sizes measured so far (with the
    growth they showed, at least linear)."""
    done = [(n, r.median(clock="wall")) for n, r in sorted(case.sizes.items())
            if r.samples and n < size]
    if not done:
        return None
    n2, t2 = done[-1]
    assert t2 is not None
    exponent = 1.0
    if len(done) >= 2:
        n1, t1 = done[-2]
        assert t1 is not None
        exponent = max(1.0, growth_exponent(n1, t1, n2, t2))
    return t2 * (size / n2) ** exponent


@dataclass
class Budget:
    per_case_size: float = 60.0  # stop repeating once a case spent this long at one size
    max_run: float = 150.0  # skip a size whose single run is predicted to take longer


def run_round_robin(
    cases: Sequence[Case],
    size: int,
    workloads: dict[int, Workload],
    repeats: int,
    budget: Budget,
    on_sample: Callable[[Case, Sample], None] | None = None,
) -> None:
    """Run ``repeats`` rounds at ``size``; ``workloads`` maps ``id(case)`` to its workload.
    Cases absent from ``workloads`` were skipped by the caller."""
    spent = {id(c): 0.0 for c in cases}
    for _ in range(repeats):
        ran = False
        for case in cases:
            workload = workloads.get(id(case))
            if workload is None:
                continue
            result = case.sizes[size]
            if result.error:
                continue
            if result.samples and spent[id(case)] >= budget.per_case_size:
                continue
            try:
                sample, _ = run_once(workload, text=False)
            except Exception as error:  # noqa: BLE001 - a library failing is a result
                result.error = f"{type(error).__name__}: {error}"[:300]
                continue
            result.samples.append(sample)
            spent[id(case)] += sample.total
            ran = True
            if on_sample is not None:
                on_sample(case, sample)
        if not ran:
            break
