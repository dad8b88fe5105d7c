"""How much ``typed-mjcf fmt`` changes a file: the lines of the original it does not keep as
they are, as a share of the file's lines.

``python -m tests.cli.fmt_changes [--canonical] [--width N] [MODEL.xml ...]`` prints each file's share
and the distribution (median, max, how many files are under 10%) over the given files, or
over the corpus when none is given. The files are only read.
"""

from __future__ import annotations

import argparse
import difflib
import statistics
import sys
from dataclasses import dataclass

from typed_mjcf.cli._common import BadInput
from typed_mjcf.cli._starttags import WIDTH
from typed_mjcf.cli.fmt import format_model


@dataclass(frozen=True)
class Change:
    path: str
    lines: int  # lines of the original
    changed: int  # of them, lines fmt does not keep as they are

    @property
    def share(self) -> float:
        return self.changed / self.lines if self.lines else 0.0


def changed_lines(before: str, after: str) -> int:
    """The lines of ``before`` that ``after`` does not keep as they are (replaced or
    removed), by a line diff."""
    matcher = difflib.SequenceMatcher(None, before.splitlines(), after.splitlines(),
                                      autojunk=False)
    return sum(i2 - i1 for op, i1, i2, _, _ in matcher.get_opcodes() if op != "equal")


def changes(path: str, canonical: bool = False, width: int = WIDTH) -> list[Change]:
    """What fmt changes in a model's file and in each file it includes."""
    found: list[Change] = []
    for result in format_model(path, canonical=canonical, width=width):
        before = result.before.decode("utf-8", "replace")
        found.append(Change(result.path, len(before.splitlines()),
                            changed_lines(before, result.after)))
    return found


def summary(found: list[Change]) -> str:
    shares = [c.share for c in found]
    under = sum(1 for s in shares if s < 0.10)
    return (f"{len(found)} files: median {statistics.median(shares):.1%}, "
            f"max {max(shares):.1%}, under 10%: {under} ({under / len(found):.0%})")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.cli.fmt_changes")
    parser.add_argument("files", nargs="*", metavar="MODEL.xml")
    parser.add_argument("--canonical", action="store_true")
    parser.add_argument("--width", type=int, default=WIDTH)
    args = parser.parse_args(argv)
    files: list[str] = args.files
    if not files:
        from tests.support.corpus import CORPUS
        files = [str(path) for _, path in CORPUS]
    found: dict[str, Change] = {}
    for file in files:
        try:
            for change in changes(file, args.canonical, args.width):
                found.setdefault(change.path, change)
        except BadInput as problem:
            print(f"unreadable: {problem}", file=sys.stderr)
    for change in sorted(found.values(), key=lambda c: c.share):
        print(f"{change.share:6.1%} {change.changed:5}/{change.lines:<5} {change.path}")
    print(summary(list(found.values())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
