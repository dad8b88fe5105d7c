"""An export interrupted while its renames run (SIGTERM, SIGINT) leaves its folder entirely
old: the renames done are put back and the signal then acts as it would have. One killed
(SIGKILL) leaves files of both exports and temporaries, which the next export repairs."""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import typed_mjcf as mjcf

from .export_signals_model import MESHES, model

CHILD = """
import os, signal, sys
# Ctrl-C raises KeyboardInterrupt, as in a process started from a shell (one started by a
# pytest-xdist worker may inherit SIGINT ignored, and then the export rightly goes on)
signal.signal(signal.SIGINT, signal.default_int_handler)
sys.path[:0] = [{tests!r}]
from export_signals_model import model  # not the test module: no pytest to import
import typed_mjcf as mjcf
from typed_mjcf._model import assets_io as _assets_io

folder, version, at, how = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
real = _assets_io._put_in_place
calls = [0]

def put(*args):
    calls[0] += 1
    done = real(*args)
    if calls[0] == at:  # the signal comes just after a rename, before it is recorded
        os.kill(os.getpid(), getattr(signal, how))
    return done

_assets_io._put_in_place = put
if at == 0:  # exports without end, for a signal from outside
    print("ready", flush=True)
    for n in range(10**9):
        mjcf.export_with_assets(model(("old", "new")[n % 2]), folder, overwrite=True)
try:
    mjcf.export_with_assets(model(version), folder, overwrite=True)
except KeyboardInterrupt:
    sys.exit(130)
print("finished", flush=True)
"""


def _versions(folder: Path) -> set[str]:
    """Which exports the folder's files come from ("old", "new"); fails on a temporary."""
    names = sorted(os.listdir(folder))
    assert not [n for n in names if n.endswith(".tmp")], names
    assert len(names) == MESHES + 1, names
    found = {(folder / f"m{i}.obj").read_text().split()[0] for i in range(MESHES)}
    found.add({"0.002": "old", "0.001": "new"}[
        str(mjcf.from_path(folder / "m.xml").option.timestep)])
    return found


def _child(folder: Path, version: str, at: int, how: str) -> subprocess.Popen[str]:
    code = CHILD.format(tests=str(Path(__file__).parent))
    return subprocess.Popen([sys.executable, "-c", code, str(folder), version, str(at), how],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


@pytest.mark.parametrize(("how", "status", "at"), [
    ("SIGTERM", -signal.SIGTERM, 1), ("SIGTERM", -signal.SIGTERM, 15),
    ("SIGTERM", -signal.SIGTERM, 31),  # the XML, last
    ("SIGINT", 130, 15),  # a KeyboardInterrupt just after a rename was not recorded either
])
def test_a_signal_during_the_renames_leaves_the_folder_entirely_old(
        tmp_path: Path, how: str, status: int, at: int) -> None:
    mjcf.export_with_assets(model("old"), tmp_path)
    child = _child(tmp_path, "new", at, how)
    out, err = child.communicate(timeout=120)
    assert child.returncode == status, err
    assert "finished" not in out
    assert _versions(tmp_path) == {"old"}


def test_a_signal_after_the_last_rename_leaves_the_folder_entirely_new(tmp_path: Path) -> None:
    mjcf.export_with_assets(model("old"), tmp_path)
    child = _child(tmp_path, "new", 32, "SIGTERM")  # never reached: the export finishes
    assert child.wait(timeout=120) == 0
    assert _versions(tmp_path) == {"new"}


def test_sigterm_at_any_time_leaves_one_export_whole(tmp_path: Path) -> None:
    """Signals from outside at random times (a bounded number of runs, seeded)."""
    chance = random.Random(8)
    for _ in range(6):
        mjcf.export_with_assets(model("old"), tmp_path, overwrite=True)
        child = _child(tmp_path, "", 0, "SIGTERM")
        assert child.stdout is not None and child.stdout.readline() == "ready\n"
        time.sleep(chance.uniform(0.0, 0.3))
        child.send_signal(signal.SIGTERM)
        child.communicate(timeout=120)
        assert child.returncode == -signal.SIGTERM
        assert len(_versions(tmp_path)) == 1


def test_the_next_export_repairs_what_a_killed_one_left(tmp_path: Path) -> None:
    mjcf.export_with_assets(model("old"), tmp_path)
    child = _child(tmp_path, "new", 15, "SIGKILL")
    child.communicate(timeout=120)
    assert child.returncode == -signal.SIGKILL
    left = os.listdir(tmp_path)
    assert [n for n in left if n.startswith(".typed-mjcf-") and n.endswith(".tmp")]
    # Files of both exports: the next export (with overwrite, as the killed one had) repairs.
    assert {(tmp_path / f"m{i}.obj").read_text().split()[0] for i in range(MESHES)} == {
        "old", "new"}
    mjcf.export_with_assets(model("new"), tmp_path, overwrite=True)
    assert _versions(tmp_path) == {"new"}
