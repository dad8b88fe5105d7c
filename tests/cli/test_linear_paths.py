"""CLI paths stay linear inside the default limits: ``fmt`` on many start tags on one line
(10**6 ``<site/>`` did not answer in 120 s: a scan back to the line's start, and a copy of the
line before each tag). Counted, not timed: Python lines executed (tests/operations.py) and
the bytes the start-tag scan searches and copies."""

from __future__ import annotations

import contextlib
import io
from collections.abc import Callable
from pathlib import Path
from typing import SupportsIndex

from typed_mjcf.cli import _starttags, main

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

    assert growth(checking, 1000, 8000) < 9
