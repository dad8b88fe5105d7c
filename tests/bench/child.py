"""Measurements that need a fresh interpreter, run by :mod:`tests.bench.cli`.

    python -m tests.bench.child memory typed 20000        # peak RSS of W1 (named) at N

prints one JSON object on stdout. Import times are measured with a bare ``python -c``
(:data:`IMPORT_SNIPPET`), so that nothing but the module itself is imported in the timing.
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import time
from typing import Any

IMPORT_SNIPPET = ("import time; t, c = time.perf_counter(), time.process_time(); "
                  "import {module}; "
                  "print(time.perf_counter() - t, time.process_time() - c)")


def _max_rss_bytes() -> int:
    """This process's peak resident memory: VmHWM of /proc (ru_maxrss on Linux would carry
    the parent's peak over the fork into this process)."""
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # KiB on Linux


def peak_memory(library: str, n: int) -> dict[str, Any]:
    """Peak resident memory (VmHWM) of W1 (named, the library's main API) at ``n`` bodies.

    The baseline is the peak after importing the library and a tiny warm-up run; the growth
    above it is what the model (and its export) cost, C allocations (libxml2, MuJoCo)
    included, which tracemalloc would not see.
    """
    import gc

    from tests.bench.workloads import ADAPTERS

    adapter = ADAPTERS[library]()
    adapter.load()
    api = adapter.w1_apis()[0]
    warm = adapter.w1(20, True, api)
    warm.export(warm.make())
    gc.collect()
    baseline = _max_rss_bytes()
    workload = adapter.w1(n, True, api)
    start = time.perf_counter()
    model = workload.make()
    after_make = _max_rss_bytes()
    text = workload.export(model)
    peak = _max_rss_bytes()
    return {
        "library": library, "api": api, "n": n, "baseline_bytes": baseline,
        "after_make_bytes": after_make, "peak_bytes": peak, "xml_chars": len(text),
        "seconds": time.perf_counter() - start,
    }


def importtime_breakdown(module: str, env: dict[str, str] | None = None) -> list[dict[str, Any]]:
    """``python -X importtime -c 'import <module>'``: every module's self and cumulative
    microseconds."""
    out = subprocess.run([sys.executable, "-X", "importtime", "-c", f"import {module}"],
                         capture_output=True, text=True, env=env, check=True)
    rows: list[dict[str, Any]] = []
    for line in out.stderr.splitlines():
        if not line.startswith("import time:") or "self [us]" in line:
            continue
        self_us, cumulative_us, name = line[len("import time:"):].split("|", 2)
        rows.append({"self_us": int(self_us), "cumulative_us": int(cumulative_us),
                     "module": name.rstrip(), "depth": (len(name) - len(name.lstrip())) // 2})
    return rows


def main(argv: list[str]) -> int:
    if len(argv) == 3 and argv[0] == "memory":
        result = peak_memory(argv[1], int(argv[2]))
    else:
        print(__doc__, file=sys.stderr)
        return 2
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
