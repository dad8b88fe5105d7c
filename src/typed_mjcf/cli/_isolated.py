"""Compiling with MuJoCo in a child process, so that a crash inside MuJoCo (some malformed
models make it dereference a null pointer) is reported instead of killing the command.

The child reads the model's text and files (pickled by this module) on stdin and writes
MuJoCo's error, if any, on stdout; a child killed by a signal is a crash.
"""

from __future__ import annotations

import pickle
import signal
import subprocess
import sys
from collections.abc import Mapping

from typed_mjcf.errors import CompileError

_CHILD = """
import pickle, sys
import mujoco
xml, files = pickle.load(sys.stdin.buffer)
try:  # as typed_mjcf._sim.compile compiles (a fresh process: no asset cache to empty)
    if len({k.replace("\\\\", "/").rsplit("/", 1)[-1].casefold() for k in files}) == len(files):
        mujoco.MjModel.from_xml_string(xml, files)
    else:  # files of one base name, kept apart by their paths
        includes = {k: v for k, v in files.items() if k.lower().endswith(".xml")}
        mujoco.MjSpec.from_string(xml, include=includes, assets=files).compile()
except (ValueError, RuntimeError) as error:
    sys.stdout.write(str(error) or type(error).__name__)
"""


class MujocoCrashed(CompileError):
    """MuJoCo's compiler died (a signal, or an exit without an answer) on the model."""


def compile_in_child(xml: str, files: Mapping[str, bytes]) -> str | None:
    """MuJoCo's error compiling ``xml`` with ``files``, or ``None`` if it compiled; raises
    :class:`MujocoCrashed` if the compiler crashed."""
    done = subprocess.run([sys.executable, "-c", _CHILD], input=pickle.dumps((xml, dict(files))),
                          capture_output=True, check=False)
    if done.returncode < 0:
        try:
            name = signal.Signals(-done.returncode).name
        except ValueError:
            name = str(-done.returncode)
        raise MujocoCrashed(f"MuJoCo crashed compiling the model: signal {name}")
    if done.returncode != 0:
        last = done.stderr.decode("utf-8", "replace").strip().splitlines()[-1:] or [""]
        raise MujocoCrashed(f"MuJoCo's compiler exited with status {done.returncode}"
                            + (f": {last[0]}" if last[0] else ""))
    answer = done.stdout.decode("utf-8", "replace")
    return answer or None
