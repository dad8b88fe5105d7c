"""Counting what a function does, for complexity checks in the unit suite.

A unit test never asserts time (a shared CI machine makes it flaky, a fast one hides a
regression); it may compare how many Python lines a call executes at two sizes. The count is
exact and the same on every machine: a loop in Python that grows quadratically shows as a
ratio of 64 for 8x the input, a linear one about 8. Timings are reported by tests/bench.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from types import FrameType
from typing import TypeAlias

Tracer: TypeAlias = "Callable[[FrameType, str, object], Tracer | None]"


def lines_executed(call: Callable[[], object]) -> int:
    """How many Python lines ``call()`` executes (every frame, library and test alike)."""
    count = 0

    def local(frame: FrameType, event: str, arg: object) -> Tracer:
        nonlocal count
        if event == "line":
            count += 1
        return local

    def calls(frame: FrameType, event: str, arg: object) -> Tracer:
        return local

    previous = sys.gettrace()
    sys.settrace(calls)
    try:
        call()
    finally:
        sys.settrace(previous)
    return count


def growth(make: Callable[[int], Callable[[], object]], small: int, large: int) -> float:
    """How much more work ``make(large)()`` does than ``make(small)()`` (Python lines, after
    one untraced warm-up run of each)."""
    make(small)()
    make(large)()
    return lines_executed(make(large)) / lines_executed(make(small))
