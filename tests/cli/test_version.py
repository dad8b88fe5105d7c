"""``typed-mjcf --version`` names the MuJoCo releases the bindings cover and the installed one."""

from __future__ import annotations

import mujoco
import pytest

from typed_mjcf import COMPILED, __version__
from typed_mjcf._generated.releases import RELEASES
from typed_mjcf.cli import main


def test_version_names_the_releases_covered_and_the_installed_one(
        capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stopped:
        main(["--version"])
    assert stopped.value.code == 0
    lines = capsys.readouterr().out.splitlines()
    build = f"compiled by mypyc: {len(COMPILED)} modules" if COMPILED else "pure Python"
    assert lines[0] == f"typed-mjcf {__version__} ({build})"
    assert lines[1].startswith(f"MuJoCo releases covered: {', '.join(RELEASES)}; ")
    assert f"installed: {mujoco.__version__}" in lines[1]
