"""Growth of two whole-model operations with the model's size, as time (CPU) ratios: what
the unit suite checks by counting Python lines (``tests/operations.py``), reported here in
seconds, never asserted.

    python -m tests.bench.scaling            # validate(): 1,000 and 8,000 bodies; a parse
                                             # of 375 and 3,000 repeated <default> sections
    python -m tests.bench.scaling --quick    # tiny sizes (what the smoke test runs)
"""

from __future__ import annotations

import argparse
import gc
import time
from collections.abc import Callable, Sequence

import typed_mjcf as mjcf
from typed_mjcf._model.validate import validate


def chain(n: int) -> mjcf.RootElement:
    """``n`` bodies in chains of 50, each with a geom and a joint of a default class, and a
    motor per joint (``tests/fidelity/test_validate.py``'s model)."""
    model = mjcf.RootElement()
    model.default.add_default(class_="c")
    parent: mjcf.Body | mjcf.Worldbody = model.worldbody
    for i in range(n):
        body = parent.add_body(name=f"b{i}", childclass="c")
        body.add_geom(size=(0.1,), class_="c")
        body.add_joint(name=f"j{i}")
        model.actuator.add_motor(joint=f"j{i}")
        parent = body if i % 50 else model.worldbody
    return model


def repeated_defaults(n: int) -> str:
    """``n`` default classes, then ``n`` repeated ``<default>`` sections
    (``tests/safety/test_errors.py``'s model; was quadratic)."""
    classes = "".join(f"<default class='c{i}'><geom size='1'/></default>" for i in range(n))
    repeats = "".join(f"<default><geom size='{i % 2 + 2}'/></default>" for i in range(n))
    return f"<mujoco>\n<default>{classes}</default>\n{repeats}</mujoco>"


def seconds(call: Callable[[], object], repeats: int) -> float:
    """The least CPU time of ``repeats`` calls, the collector run before each."""
    best = float("inf")
    for _ in range(repeats):
        gc.collect()
        start = time.process_time()
        call()
        best = min(best, time.process_time() - start)
    return best


def cases(quick: bool) -> list[tuple[str, Callable[[int], Callable[[], object]], int, int]]:
    def validating(n: int) -> Callable[[], object]:
        model = chain(n)
        return lambda: validate(model)

    def parsing(n: int) -> Callable[[], object]:
        text = repeated_defaults(n)
        return lambda: mjcf.from_xml_string(text)

    scale = 10 if quick else 1
    return [("validate(), bodies", validating, 1000 // scale, 8000 // scale),
            ("parse, repeated <default> sections", parsing, 375 // scale, 3000 // scale)]


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.bench.scaling")
    parser.add_argument("--quick", action="store_true", help="tiny sizes")
    args = parser.parse_args(argv)
    repeats = 1 if args.quick else 3
    print("| operation | small | large | s small | s large | ratio (linear: x size) |")
    print("|---|---:|---:|---:|---:|---:|")
    for title, make, small, large in cases(args.quick):
        t_small = seconds(make(small), repeats)
        t_large = seconds(make(large), repeats)
        ratio = t_large / t_small if t_small else float("nan")
        print(f"| {title} | {small} | {large} | {t_small:.3f} | {t_large:.3f} | "
              f"{ratio:.1f} (x{large // small}) |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
