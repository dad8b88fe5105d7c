"""Benchmarks: typed-mjcf side by side with dm_control.mjcf, mujoco.MjSpec and raw lxml.

Run from the repository root::

    nox -s bench                       # the full suite (several minutes)
    python -m tests.bench              # the same, in the current environment
    python -m tests.bench --quick      # tiny sizes, a few seconds (what the smoke test runs)
    python -m tests.bench --json out.json --only W1,W3 --libs typed,lxml

Workloads (:mod:`tests.bench.workloads`): W1 build + export of N bodies, W2 parse + export of
a real model and of W1's output, W3 composition of K attached arms; plus the import time of
``typed_mjcf`` and the peak memory of W1 (:mod:`tests.bench.child`, in fresh subprocesses).
Every library runs the same workloads in one process, round-robin, and the report
(:mod:`tests.bench.report`) gives medians, ratios to the raw-lxml floor, growth with size
and the performance targets met or missed.

:mod:`tests.bench.scaling` (``python -m tests.bench.scaling``) reports how the time of
``validate()`` and of parsing repeated ``<default>`` sections grows with the model: the unit
suite checks that growth by counting operations (``tests/operations.py``), never by timing.

Only ``test_bench_smoke.py`` is a test module; the others are not collected by pytest.
"""
