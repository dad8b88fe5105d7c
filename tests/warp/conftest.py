"""The MuJoCo Warp tests (the ``warp`` extra) run in their own session, ``nox -s warp``,
which installs it: without it (``nox -s tests``, the edit loop) this folder is not
collected (the first kernel build alone takes minutes of CPU)."""

from __future__ import annotations

import importlib.util
import os

if os.environ.get("WARP_TEST_SESSION") and not importlib.util.find_spec("mujoco_warp"):
    raise RuntimeError("nox -s warp: MuJoCo Warp is not installed (the warp extra)")
collect_ignore_glob = [] if importlib.util.find_spec("mujoco_warp") else ["test_*.py"]
