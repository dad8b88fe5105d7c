"""Differential testing against MuJoCo's own parser: mutants of the corpus models, read by
typed-mjcf (``from_xml_string`` then ``validate()``) and by MuJoCo (``MjSpec.from_string``,
in a worker process that is restarted if MuJoCo crashes), counted by agreement.

``python -m tests.safety.differential [COUNT] [SEED]`` prints the counts and the cases where
the two disagree; ``test_differential.py`` runs a small bounded sample in CI.
"""

from __future__ import annotations

import json
import random
import subprocess
import sys
import warnings
from collections import Counter
from dataclasses import dataclass, field

import typed_mjcf as mjcf
from tests.support.mutations import MUTATIONS, SEEDS
from typed_mjcf._model.validate import validate

_WORKER = r"""
import json, sys
import mujoco
for line in sys.stdin:
    try:
        mujoco.MjSpec.from_string(json.loads(line))
        answer = ""
    except Exception as error:
        answer = (str(error).strip() or type(error).__name__).splitlines()[0]
    sys.stdout.write(json.dumps(answer) + "\n")
    sys.stdout.flush()
"""


class MujocoParser:
    """MuJoCo's parser in a worker process; ``None``: it accepts the text, else its error."""

    def __init__(self) -> None:
        self.process: subprocess.Popen[str] | None = None

    def __call__(self, xml: str) -> str | None:
        if self.process is None or self.process.poll() is not None:
            self.process = subprocess.Popen([sys.executable, "-c", _WORKER], text=True,
                                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        assert self.process.stdin is not None and self.process.stdout is not None
        self.process.stdin.write(json.dumps(xml) + "\n")
        self.process.stdin.flush()
        line = self.process.stdout.readline()
        if not line:  # the worker died: MuJoCo crashed on this text
            code = self.process.wait()
            self.process = None
            return f"crash (exit {code})"
        answer: str = json.loads(line)
        return answer or None

    def close(self) -> None:
        if self.process is not None:
            self.process.stdin.close()  # type: ignore[union-attr]
            self.process.wait()
            self.process = None


# MuJoCo's parser resolves default classes only; other names are resolved by its compiler.
def _parser_finding(rule: str, message: str) -> bool:
    return rule != "unresolved-reference" or "names no default class" in message


def ours(xml: str) -> str | None:
    """``None`` if typed-mjcf reads ``xml`` and ``validate()`` finds no error in it that
    MuJoCo's parser would find (an unresolved reference other than to a class is MuJoCo's
    compiler's finding), else why not."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = mjcf.from_xml_string(xml)
    except mjcf.MjcfError as error:
        return f"load: {str(error)[:200]}"
    errors = [f for f in validate(model)
              if f.severity == "error" and _parser_finding(f.rule, f.message)]
    return f"validate: {errors[0].rule}: {errors[0].message[:200]}" if errors else None


@dataclass
class Counts:
    mutants: int = 0
    both_accept: int = 0
    both_refuse: int = 0
    # MuJoCo refuses, typed-mjcf reads the text: validate() finds the error (caught), or
    # finds none (a false accept); (MuJoCo's error, xml)
    caught: list[tuple[str, str]] = field(default_factory=lambda: [])
    false_accepts: list[tuple[str, str]] = field(default_factory=lambda: [])
    false_rejects: list[tuple[str, str]] = field(default_factory=lambda: [])
    crashes: int = 0


def mutants(count: int, seed: int) -> list[str]:
    """``count`` mutants (1 to 3 mutations) of the corpus models MuJoCo's parser reads as
    text alone (no includes), as text."""
    usable = [data for _, _, data in SEEDS if b"<include" not in data]
    rng = random.Random(seed)
    found: list[str] = []
    while len(found) < count:
        data = rng.choice(usable)
        for _ in range(rng.randint(1, 3)):
            data = MUTATIONS[rng.choice(sorted(MUTATIONS))](data, rng)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            continue  # both parsers take the text as a str
        if "\0" not in text:
            found.append(text)
    return found


def run(count: int, seed: int = 0) -> Counts:
    counts = Counts()
    parser = MujocoParser()
    try:
        for xml in mutants(count, seed):
            counts.mutants += 1
            theirs, mine = parser(xml), ours(xml)
            if theirs is not None and theirs.startswith("crash"):
                counts.crashes += 1
            if mine is None and theirs is None:
                counts.both_accept += 1
            elif mine is not None and theirs is not None:
                counts.both_refuse += 1
                if mine.startswith("validate:"):
                    counts.caught.append((theirs, xml))
            elif mine is None:
                counts.false_accepts.append((str(theirs), xml))
            else:
                counts.false_rejects.append((mine, xml))
    finally:
        parser.close()
    return counts


def main() -> None:
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 0
    counts = run(count, seed)
    print(f"{counts.mutants} mutants: {counts.both_accept} accepted by both, "
          f"{counts.both_refuse} refused by both, {len(counts.false_accepts)} false accepts, "
          f"{len(counts.false_rejects)} false rejects, {counts.crashes} MuJoCo crashes")
    read = len(counts.caught) + len(counts.false_accepts)
    print(f"MuJoCo refuses, typed-mjcf reads: {read}; caught by validate(): "
          f"{len(counts.caught)}, not caught (false accepts): {len(counts.false_accepts)}")
    for title, cases in (("caught by validate() (MuJoCo's error)", counts.caught),
                         ("false accepts (MuJoCo's error)", counts.false_accepts),
                         ("false rejects (our error)", counts.false_rejects)):
        print(f"\n{title}:")
        for why, _ in Counter(w[:90] for w, _ in cases).most_common():
            print(f"  {why}")


if __name__ == "__main__":
    main()
