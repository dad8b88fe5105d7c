"""Counting what a function does, for complexity checks in the unit suite.

A unit test never asserts time (a shared CI machine makes it flaky, a fast one hides a
regression); it may compare how many Python lines a call executes at two sizes. The count is
exact and the same on every machine: a loop in Python that grows quadratically shows as a
ratio of 64 for 8x the input, a linear one about 8. Timings are reported by tests/bench.

Code compiled by mypyc runs no traced line, so each count names the modules of typed_mjcf
that make up its share of the lines (``counted``, spelled as pyproject's list of compiled
modules: ``"_text.parse"``). The build where one of them is compiled skips the check
(tests/compiled.py); and the count checks the names: each ran lines, and the package's other
modules make up at most ``UNNAMED`` of its lines (so a compiled one the names leave out can
hide no more than that).
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Collection, Mapping
from types import FrameType
from typing import TypeAlias

from tests.compiled import skip_counting

Tracer: TypeAlias = "Callable[[FrameType, str, object], Tracer | None]"

PACKAGE = "typed_mjcf."
UNNAMED = 0.05  # the share of the package's counted lines that modules not named may run


def lines_executed(call: Callable[[], object], counted: Collection[str]) -> int:
    """How many Python lines ``call()`` executes (every frame, library and test alike)."""
    skip_counting(counted)
    totals: dict[str, Callable[[], int]] = {}
    tracers: dict[str, Tracer] = {}

    def counter(module: str) -> Tracer:
        count = 0

        def local(frame: FrameType, event: str, arg: object) -> Tracer:
            nonlocal count
            if event == "line":
                count += 1
            return local
        totals[module] = lambda: count
        return local

    def calls(frame: FrameType, event: str, arg: object) -> Tracer:
        # one counter per module, found once per call: a line costs what a single count did
        module = str(frame.f_globals.get("__name__", ""))
        tracer = tracers.get(module)
        if tracer is None:
            tracer = tracers[module] = counter(module)
        return tracer

    previous = sys.gettrace()
    sys.settrace(calls)
    try:
        call()
    finally:
        sys.settrace(previous)
    lines = {module: total() for module, total in totals.items()}
    _check_named(lines, counted)
    return sum(lines.values())


def _check_named(lines: Mapping[str, int], counted: Collection[str]) -> None:
    """``counted`` names the package's modules that ran the count's lines (see above)."""
    ours = {module.removeprefix(PACKAGE): n for module, n in lines.items()
            if module.startswith(PACKAGE) and n}
    idle = sorted(set(counted) - set(ours))
    assert not idle, f"counted names modules that ran no line of this call: {idle}"
    unnamed = {module: n for module, n in ours.items() if module not in counted}
    assert sum(unnamed.values()) <= UNNAMED * sum(ours.values()), (
        f"modules not in counted ran more than {UNNAMED:.0%} of the package's lines "
        f"({sum(ours.values())}): {unnamed}")


def growth(make: Callable[[int], Callable[[], object]], small: int, large: int,
           counted: Collection[str]) -> float:
    """How much more work ``make(large)()`` does than ``make(small)()`` (Python lines, after
    one untraced warm-up run of each)."""
    skip_counting(counted)  # before the warm-up
    make(small)()
    make(large)()
    return lines_executed(make(large), counted) / lines_executed(make(small), counted)
