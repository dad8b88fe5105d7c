"""``typed-mjcf mujoco-stubs`` and how the stubs ship: inside typed_mjcf, never as an
installed ``mujoco-stubs/`` that another distribution may own."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from typed_mjcf.cli import main
from typed_mjcf.cli.mujoco_stubs import MARKER

ROOT = Path(__file__).resolve().parents[2]
STUBS = ROOT / "generated" / "mujoco-stubs"


def _pyi(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*.pyi"))}


def test_the_stubs_are_copied_into_typings_and_replaced_on_the_next_run(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["mujoco-stubs"]) == 0
    copied = tmp_path / "typings" / "mujoco"
    assert _pyi(copied) == _pyi(STUBS) and _pyi(copied)
    assert "mypy_path" in capsys.readouterr().out
    (copied / "stale.pyi").write_text("x: int\n", encoding="utf-8")  # from an older release
    assert main(["mujoco-stubs"]) == 0
    assert _pyi(copied) == _pyi(STUBS)


def test_a_folder_it_did_not_write_is_left_alone(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    theirs = tmp_path / "mujoco"
    theirs.mkdir()
    (theirs / "__init__.pyi").write_text("# someone else's\n", encoding="utf-8")
    assert main(["mujoco-stubs", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err == (f"typed-mjcf mujoco-stubs: {theirs}: exists and was not written by "
                   "typed-mjcf; remove it or name another directory\n")
    assert (theirs / "__init__.pyi").read_text(encoding="utf-8") == "# someone else's\n"
    assert not (theirs / MARKER).exists()


def test_the_wheel_installs_no_stubs_package_of_its_own() -> None:
    """Only typed_mjcf is installed; the stubs ride inside it (pyproject's wheel target)."""
    wheel = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))[
        "tool"]["hatch"]["build"]["targets"]["wheel"]
    assert wheel["packages"] == ["src/typed_mjcf"]
    assert wheel["force-include"]["generated/mujoco-stubs"] == "typed_mjcf/_mujoco_stubs"
    # whatever else is forced in (the runtime's stubs) lands inside typed_mjcf too
    for target in wheel["force-include"].values():
        assert target == "typed_mjcf" or target.startswith("typed_mjcf/"), target
