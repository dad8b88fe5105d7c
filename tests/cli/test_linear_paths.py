"""CLI paths stay linear inside the default limits: ``fmt`` on many start tags on one line
(10**6 ``<site/>`` did not answer in 120 s: a scan back to the line's start, and a copy of the
line before each tag), ``to-python`` of a long number list (60 MB took 1.9 GB: a Python string
per number, 32x the text). Counted, not timed: Python lines executed (tests/operations.py),
the bytes the start-tag scan searches and copies, and peak memory (tracemalloc)."""

from __future__ import annotations

import contextlib
import io
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from typing import SupportsIndex

import typed_mjcf as mjcf
from typed_mjcf.cli import _starttags, main
from typed_mjcf.cli.to_python import to_python

from ..operations import growth


def _sites(count: int) -> bytes:
    return b"<mujoco><worldbody>" + b"<site/>" * count + b"</worldbody></mujoco>"


class _Counted(bytes):
    """Bytes that count what ``rfind`` searches and slicing copies."""

    touched = 0

    def rfind(self, sub: bytes, start: SupportsIndex | None = None,  # type: ignore[override]
              end: SupportsIndex | None = None) -> int:
        low = 0 if start is None else int(start)
        high = len(self) if end is None else int(end)
        _Counted.touched += max(high - low, 0)
        return super().rfind(sub, low, high)

    def __getitem__(self, key: SupportsIndex | slice) -> int | bytes:  # type: ignore[override]
        if isinstance(key, slice):
            _Counted.touched += len(range(*key.indices(len(self))))
        return super().__getitem__(key)


def _bytes_touched(count: int) -> int:
    _Counted.touched = 0
    tags = _starttags.start_tags(_Counted(_sites(count)))
    assert len(tags) == count + 2
    return _Counted.touched


def test_fmt_check_of_many_tags_on_one_line_is_linear(tmp_path: Path) -> None:
    """The start-tag scan looks at each byte a bounded number of times (its C work: the
    ratio was 64), and the whole command executes Python lines in proportion."""
    small, large = _bytes_touched(1000), _bytes_touched(8000)
    assert large / small < 9, (small, large)

    def checking(count: int) -> Callable[[], object]:
        path = tmp_path / f"s{count}.xml"
        path.write_bytes(_sites(count))

        def run() -> object:
            with contextlib.redirect_stdout(io.StringIO()):
                return main(["fmt", "--check", str(path)])
        return run

    assert growth(checking, 1000, 8000,
                  counted=("cli.fmt", "cli._starttags", "_text.parse", "_core.tree")) < 9


def _numbers(folder: Path, count: int) -> mjcf.RootElement:
    path = folder / f"n{count}.xml"
    path.write_text('<mujoco><asset><mesh name="m" vertex="' + "0.125 -7 1e-3 " * count
                    + '"/></asset></mujoco>')
    return mjcf.from_path(path)


def _peak(model: mjcf.RootElement) -> int:
    """Peak memory (bytes) of writing the model as Python, the model read already."""
    tracemalloc.start()
    try:
        to_python(model, ".")
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_to_python_of_a_long_number_list_is_linear_and_costs_a_few_times_its_text(
        tmp_path: Path) -> None:
    def writing(count: int) -> Callable[[], object]:
        model = _numbers(tmp_path, count)
        return lambda: to_python(model, ".")

    assert growth(writing, 500, 4000, counted=("cli.to_python", "cli._pycode", "_core.codecs")) < 9
    # What each more byte of text costs (past the fixed cost of a piece converted at a time):
    # 21 bytes before, about 3 now (the code it writes is 1.5 times the text).
    small, large = 80_000, 240_000  # numbers x 3: 1.1 and 3.4 MB of text
    extra_text = 14 * (large - small)
    per_byte = (_peak(_numbers(tmp_path, large)) - _peak(_numbers(tmp_path, small))) / extra_text
    assert per_byte < 5, per_byte
