"""Builds of typed-mjcf side by side: the pure-Python one and a compiled one (issue 38).

A build is an interpreter whose environment holds a typed-mjcf (``--build compiled=PATH``,
PATH its ``python``). Its workloads run in a child process of that interpreter
(``python -m tests.bench.builds serve``), one request at a time, so the harness keeps its
round robin: each run of a case is a request, timed in the child (its process CPU time and
wall-clock time), between the runs of the other cases. The build of the harness's own
interpreter is measured in process, as before; every row names its build.

    python -m tests.bench --only W1,W2 --libs typed,lxml --build compiled=.venv-mypyc/bin/python
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

from tests.bench.workloads import Adapter, Workload

REPO = Path(__file__).resolve().parents[2]


def build_of(module: Any) -> str:
    """Which build an imported ``typed_mjcf`` is: "compiled" or "pure"."""
    compiled = getattr(module, "COMPILED", None)
    if compiled is None:  # a build without the flag: a compiled module is an extension
        core = getattr(getattr(module, "_tree", None), "__file__", "") or ""
        compiled = not core.endswith(".py")
    return "compiled" if compiled else "pure"


def describe_local() -> dict[str, str]:
    import typed_mjcf

    return {"build": build_of(typed_mjcf), "version": str(typed_mjcf.__version__),
            "python": sys.executable, "file": str(typed_mjcf.__file__)}


class RemoteTyped(Adapter):
    """typed-mjcf's workloads in a child process of another interpreter."""

    def __init__(self, name: str, python: str) -> None:
        self.name, self.python = name, python
        self.key = f"typed@{name}"
        self.title = f"typed-mjcf [{name}]"
        self._child: subprocess.Popen[str] | None = None
        self._texts: dict[int, int] = {}  # id(text) -> key in the child
        self.info: dict[str, str] = {}

    # the child --------------------------------------------------------------------------
    def _ask(self, request: dict[str, Any]) -> dict[str, Any]:
        child = self._child
        if child is None or child.poll() is not None:
            raise RuntimeError(f"the {self.name} build's child process is not running")
        assert child.stdin is not None and child.stdout is not None
        child.stdin.write(json.dumps(request) + "\n")
        child.stdin.flush()
        line = child.stdout.readline()
        if not line:
            raise RuntimeError(f"the {self.name} build's child process ended")
        answer: dict[str, Any] = json.loads(line)
        if "error" in answer:
            raise RuntimeError(answer["error"])
        return answer

    def load(self) -> None:
        if self._child is not None:
            return
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([str(REPO), *filter(None, [env.get("PYTHONPATH")])])
        self._child = subprocess.Popen(
            [self.python, "-m", "tests.bench.builds", "serve"], cwd=REPO, env=env, text=True,
            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.info = self._ask({"op": "describe"})
        self.title = f"typed-mjcf [{self.info['build']}: {self.name}]" if (
            self.info["build"] != self.name) else f"typed-mjcf [{self.name}]"

    def available(self) -> str | None:
        try:
            self.load()
        except (OSError, RuntimeError, ValueError) as error:
            return f"{self.python}: {error}"
        return None

    def close(self) -> None:
        if self._child is not None:
            self._child.kill()
            self._child.wait()
            self._child = None

    def version(self) -> str:
        return f"{self.info.get('version', '?')} ({self.info.get('build', '?')}, {self.python})"

    # the workloads ----------------------------------------------------------------------
    def _workload(self, request: dict[str, Any]) -> Workload:
        def run(text: bool) -> tuple[dict[str, float], str]:
            answer = self._ask({**request, "op": "run", "text": text})
            return answer["sample"], answer.get("text", "")

        return Workload(_remote_only, _remote_only, remote=run)

    def w1_apis(self) -> tuple[str, ...]:
        return ("add_<tag>()", 'add("<tag>")')

    def w1(self, n: int, named: bool, api: str) -> Workload:
        return self._workload({"workload": "w1", "n": n, "named": named, "api": api})

    def w2_path(self, path: str) -> Workload:
        return self._workload({"workload": "w2_path", "source": path})

    def w2_text(self, text: str) -> Workload:
        key = self._texts.get(id(text))
        if key is None:
            key = self._texts[id(text)] = len(self._texts)
            self._ask({"op": "text", "key": key, "text": text})
        return self._workload({"workload": "w2_text", "key": key})

    def w3(self, k: int) -> Workload:
        return self._workload({"workload": "w3", "k": k})

    def bind(self, n: int, repeats: int) -> list[dict[str, Any]]:
        rows: list[dict[str, Any]] = self._ask({"op": "bind", "n": n, "repeats": repeats})["rows"]
        return rows


def _remote_only(*_: object) -> Any:
    raise RuntimeError("a remote workload runs through Workload.remote")


# ----------------------------------------------------------------------------- the child


def serve() -> int:
    """Answer requests on stdin, one JSON object a line, until it closes."""
    from tests.bench import timing
    from tests.bench.workloads import TypedMjcf

    adapter = TypedMjcf()
    adapter.load()
    texts: dict[int, str] = {}
    for line in sys.stdin:
        request = json.loads(line)
        try:
            answer = _answer(request, adapter, texts, timing)
        except Exception as error:  # noqa: BLE001 - the harness records a failing run
            answer = {"error": f"{type(error).__name__}: {error}"[:300]}
        sys.stdout.write(json.dumps(answer) + "\n")
        sys.stdout.flush()
    return 0


def _answer(request: dict[str, Any], adapter: Any, texts: dict[int, str],
            timing: Any) -> dict[str, Any]:
    op = request["op"]
    if op == "describe":
        return describe_local()
    if op == "text":
        texts[request["key"]] = request["text"]
        return {}
    if op == "bind":
        from tests.bench.bind import bench_bind

        return {"rows": bench_bind(request["n"], request["repeats"])}
    kind = request["workload"]
    if kind == "w1":
        workload = adapter.w1(request["n"], request["named"], request["api"])
    elif kind == "w2_path":
        workload = adapter.w2_path(request["source"])
    elif kind == "w2_text":
        workload = adapter.w2_text(texts[request["key"]])
    else:
        workload = adapter.w3(request["k"])
    sample, text = timing.run_once(workload)
    answer: dict[str, Any] = {"sample": sample.__dict__}
    if request.get("text"):
        answer["text"] = text
    return answer


if __name__ == "__main__":
    if sys.argv[1:] == ["serve"]:
        raise SystemExit(serve())
    print(__doc__, file=sys.stderr)
    raise SystemExit(2)
