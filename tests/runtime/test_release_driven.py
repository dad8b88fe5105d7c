"""The release tests (test_release_gates, test_release_types) for every older release covered,
on the MuJoCo installed here: typed-mjcf is made to follow that release's grammar
(tests.runtime.release_driver), so what each release gates and types is checked in every
run, not only by ``nox -s releases`` on that MuJoCo."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.runtime.release_driver import RELEASE_VARIABLE
from typed_mjcf._generated.releases import RELEASES

ROOT = Path(__file__).resolve().parents[2]
TESTS = ["tests/runtime/test_release_gates.py", "tests/runtime/test_release_types.py"]


@pytest.mark.parametrize("release", RELEASES[:-1])
def test_the_release_tests_pass_for_an_older_release(release: str) -> None:
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-n", "0",
         "-p", "tests.runtime.release_driver", *TESTS],
        cwd=ROOT, env={**os.environ, RELEASE_VARIABLE: release}, capture_output=True,
        text=True, check=False, timeout=600)
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-2000:]
    assert " passed" in result.stdout and " failed" not in result.stdout
