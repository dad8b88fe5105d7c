"""Public projects built on dm_control.mjcf and composer, run on typed-mjcf: their own tests.

Not run by the test suite (it needs the projects, installed apart). The projects, from PyPI:
``dm-robotics-moma`` 0.10.0 (robots, grippers, sensors, arenas and tasks built with
dm_control.mjcf and composer), ``dm-robotics-manipulation`` 0.10.0 (props and a basket cell
on moma) and ``dexterity`` 0.0.15 (dexterous hands and manipulation tasks). Their tests run
from the installed packages, twice:

- typed-mjcf: dm_control 1.0.50 and MuJoCo 4 (this project's test dependencies), with
  ``install_as_dm_control_mjcf()`` before anything is collected
  (``-p tests.dm_control.install_plugin``)::

    python3.11 -m venv /tmp/typed && /tmp/typed/bin/pip install -e . "dm_control>=1.0.50" \\
        pytest pillow attrs pydot opencv-python-headless typing-extensions
    /tmp/typed/bin/pip install --no-deps dm-robotics-moma==0.10.0 \\
        dm-robotics-manipulation==0.10.0 dm-robotics-transformations==0.10.0 \\
        dm-robotics-geometry==0.10.0 dm-robotics-agentflow==0.10.0 \\
        dm-robotics-controllers==0.10.0 dexterity==0.0.15
    python tests/dm_control/public_projects.py run /tmp/typed/bin/python TYPED.json --typed

- dm_control itself, as the projects pin it (dm_control 1.0.31, MuJoCo 3.3.3): the same,
  with ``/tmp/base/bin/pip install dm_control==1.0.31 mujoco==3.3.3 pytest pillow ...``
  (not ``-e .``) and ``run /tmp/base/bin/python BASE.json`` (no ``--typed``);

then ``python tests/dm_control/public_projects.py compare TYPED.json BASE.json`` prints, per
project, how many tests pass in each and every test whose outcome differs, with its first
error line (``--no-deps``: the projects pin dm_control and mujoco exactly).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
# project -> the package whose tests are run (from the installed files)
PROJECTS = {"dm-robotics-moma": "dm_robotics.moma",
            "dm-robotics-manipulation": "dm_robotics.manipulation",
            "dexterity": "dexterity"}
TIMEOUT = 1800


def run(python: str, typed: bool) -> dict[str, dict[str, str]]:
    """Each project's tests by id: "passed", "skipped", or the first line of the failure.
    Each test file runs in a process of its own: a crash (dm-robotics-controllers' binary is
    built against MuJoCo 3.3.3's structs) takes only that file's tests with it."""
    found: dict[str, dict[str, str]] = {}
    for project, package in PROJECTS.items():
        folder = subprocess.run(
            [python, "-c", f"import {package} as p, os; print(os.path.dirname(p.__file__))"],
            capture_output=True, text=True, check=True).stdout.strip()
        found[project] = {}
        for test_file in sorted(Path(folder).rglob("*_test.py")):
            found[project].update(_run_file(python, typed, test_file, Path(folder)))
        passed = sum(1 for o in found[project].values() if o == "passed")
        print(f"{project}: {passed} of {len(found[project])} passed", file=sys.stderr)
    return found


def _run_file(python: str, typed: bool, test_file: Path, folder: Path) -> dict[str, str]:
    with tempfile.TemporaryDirectory() as work:
        report = Path(work) / "report.xml"
        command = [python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--rootdir", work,
                   "-c", os.devnull, f"--junitxml={report}", str(test_file)]
        if typed:
            command[3:3] = ["-p", "tests.dm_control.install_plugin"]
        env = {**os.environ, "MUJOCO_GL": "egl", "PYTHONPATH": str(REPO) if typed else ""}
        done = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True,
                              timeout=TIMEOUT, check=False)
        name = test_file.relative_to(folder).as_posix()
        outcomes = {f"{name}::{test}": outcome for test, outcome in _outcomes(report).items()}
        if not outcomes:
            outcomes = {name: f"failed: the test process ended with {done.returncode} "
                              "before reporting"}
        return outcomes


def _outcomes(report: Path) -> dict[str, str]:
    if not report.exists():
        return {}
    outcomes: dict[str, str] = {}
    for case in ET.parse(report).getroot().iter("testcase"):
        test_id = f"{(case.get('classname') or '').split('.')[-1]}.{case.get('name')}"
        problem = next((c for c in case if c.tag in ("failure", "error")), None)
        if problem is not None:
            message = (problem.get("message") or problem.text or "").strip()
            outcomes[test_id] = "failed: " + (message.splitlines() or [""])[0][:300]
        elif any(c.tag == "skipped" for c in case):
            outcomes[test_id] = "skipped"
        else:
            outcomes[test_id] = "passed"
    return outcomes


def compare(typed: dict[str, dict[str, str]], base: dict[str, dict[str, str]]) -> None:
    for project in PROJECTS:
        mine, theirs = typed.get(project, {}), base.get(project, {})
        count = {name: sum(1 for o in runs.values() if o == "passed")
                 for name, runs in (("typed", mine), ("dm_control", theirs))}
        print(f"{project}: {len(mine)} tests; passed on typed-mjcf {count['typed']}, on "
              f"dm_control {count['dm_control']}")
        for test_id in sorted(set(mine) | set(theirs)):
            a, b = mine.get(test_id, "absent"), theirs.get(test_id, "absent")
            if a != b and not (a.startswith("failed") and b.startswith("failed")):
                print(f"  {test_id}\n    typed-mjcf: {a}\n    dm_control: {b}")
            elif a.startswith("failed"):
                print(f"  {test_id} fails in both\n    typed-mjcf: {a}\n    dm_control: {b}")


def main(argv: list[str]) -> None:
    if argv[:1] == ["run"] and len(argv) in (3, 4):
        results = run(argv[1], typed=argv[3:] == ["--typed"])
        Path(argv[2]).write_text(json.dumps(results, indent=1, sort_keys=True),
                                 encoding="utf-8")
    elif argv[:1] == ["compare"] and len(argv) == 3:
        compare(*(json.loads(Path(p).read_text(encoding="utf-8")) for p in argv[1:]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
