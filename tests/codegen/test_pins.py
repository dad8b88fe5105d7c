"""Release day: the MuJoCo pins move with schema/ (codegen/pins.py, noxfile.py, codegen check)."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

from codegen import commands, ir, pins, wheel

PYPROJECT = """\
dependencies = [
    "lxml>=5",
    "mujoco>=4.0.0,<4.1",
]
dev = [
    "mujoco==4.0.0",
    "dm_control>=1.0.50",
]
"""


def test_a_patch_release_moves_the_dev_pin_only() -> None:
    text, changes = pins.moved(PYPROJECT, "4.0.2")
    assert changes == ["dev extra: mujoco==4.0.0 -> mujoco==4.0.2"]
    assert '"mujoco==4.0.2"' in text and '"mujoco>=4.0.0,<4.1"' in text
    assert pins.disagreements(text, "4.0.2") == []


def test_a_minor_release_raises_the_range() -> None:
    text, changes = pins.moved(PYPROJECT, "4.1.0")
    assert changes[1] == "dependencies: mujoco>=4.0.0,<4.1 -> mujoco>=4.0.0,<4.2"
    assert pins.read(text) == ("4.1.0", ("4.0.0", "4.2"))


def test_an_older_release_keeps_the_range_and_is_reported() -> None:
    text, _ = pins.moved(PYPROJECT, "3.17.0")
    assert pins.read(text) == ("3.17.0", ("4.0.0", "4.1"))  # the lower bound: by hand
    assert pins.disagreements(text, "3.17.0") == [
        "the dependency range mujoco>=4.0.0,<4.1 leaves out 3.17.0"]


def test_a_core_pin_becomes_a_mujoco_pin() -> None:
    old = PYPROJECT.replace('"mujoco==4.0.0"', '"mujoco-core==4.0.0"')
    assert pins.disagreements(old, "4.0.0") == ["the dev extra pins 4.0.0, not mujoco==4.0.0"]
    text, changes = pins.moved(old, "4.0.0")
    assert changes and '"mujoco==4.0.0"' in text and "mujoco-core" not in text


def test_pins_it_cannot_find_are_an_error() -> None:
    with pytest.raises(pins.PinError, match='one "mujoco==X" pin'):
        pins.read(PYPROJECT.replace('"mujoco==4.0.0",', ""))


def test_update_writes_the_file(tmp_path: Path) -> None:
    path = tmp_path / "pyproject.toml"
    path.write_text(PYPROJECT, encoding="utf-8")
    assert pins.update("4.0.0", path) == []
    assert pins.update("4.1.3", path) != []
    assert pins.read(path.read_text(encoding="utf-8")) == ("4.1.3", ("4.0.0", "4.2"))


def test_the_committed_pins_agree_with_schema() -> None:
    version = ir.load().mujoco_version
    assert pins.disagreements(pins.PYPROJECT.read_text(encoding="utf-8"), version) == []


def test_noxfile_reads_the_version_from_schema() -> None:
    """MUJOCO_VERSION is computed from schema/mjcf.json (one place), not a second literal."""
    tree = ast.parse(Path("noxfile.py").read_text(encoding="utf-8"))
    (value,) = [node.value for node in tree.body if isinstance(node, ast.Assign)
                and any(isinstance(t, ast.Name) and t.id == "MUJOCO_VERSION"
                        for t in node.targets)]
    assert not isinstance(value, ast.Constant)
    namespace = {"json": json, "Path": Path}
    assert eval(compile(ast.Expression(value), "noxfile.py", "eval"), namespace) \
        == ir.load().mujoco_version


def test_check_names_a_mujoco_other_than_the_pinned_one(
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(wheel, "read_version", lambda: "9.9.9")
    assert commands.check() == 1
    out = capsys.readouterr().out
    assert "the installed mujoco is 9.9.9" in out
    assert "--mujoco-version 9.9.9" in out and "pip install -e '.[dev]'" in out
