"""MuJoCo compiling in a child process, for tests that compile many models MuJoCo may crash
on or be left unusable by: after some refusals ("Caught an unknown exception!", a <model>
without a file) the next compile in the same process hangs, so the worker stops after any
error but a ``ValueError`` and is started again on the next call."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

_WORKER = r"""
import json, os, sys
import mujoco
for line in sys.stdin:
    path, xml, folder = json.loads(line)
    try:
        if path is not None:
            mujoco.MjModel.from_xml_path(path)
        else:
            os.chdir(folder)
            mujoco.MjModel.from_xml_string(xml)
        answer, broken = "", False
    except Exception as error:
        answer = (str(error).strip() or type(error).__name__).splitlines()[0]
        broken = not isinstance(error, ValueError)  # the next compile may hang: start anew
    sys.stdout.write(json.dumps(answer) + "\n")
    sys.stdout.flush()
    if broken:
        break
"""


class MujocoWorker:
    """MuJoCo's compile in a child process: each call answers ``None`` when the model
    compiles, else the first line of MuJoCo's error (``"crash"`` when the process died)."""

    def __init__(self) -> None:
        self.process: subprocess.Popen[str] | None = None

    def compile_file(self, path: Path) -> str | None:
        """MuJoCo's error compiling the file ``path``, or None."""
        return self._ask([str(path), None, None])

    def compile_text(self, xml: str, folder: Path) -> str | None:
        """MuJoCo's error compiling ``xml`` with ``folder`` as the current folder, or None."""
        return self._ask([None, xml, str(folder)])

    def _ask(self, request: list[str | None]) -> str | None:
        if self.process is None or self.process.poll() is not None:
            self.process = subprocess.Popen([sys.executable, "-c", _WORKER], text=True,
                                            stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                            stderr=subprocess.DEVNULL)
        assert self.process.stdin is not None and self.process.stdout is not None
        self.process.stdin.write(json.dumps(request) + "\n")
        self.process.stdin.flush()
        line = self.process.stdout.readline()
        if not line:
            self.process = None
            return "crash"
        answer: str = json.loads(line)
        return answer or None

    def close(self) -> None:
        if self.process is not None and self.process.stdin is not None:
            self.process.stdin.close()
            self.process.wait()
            self.process = None
