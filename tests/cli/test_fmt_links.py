"""``typed-mjcf fmt`` formats the file a symbolic link names (the link stays a link) and
writes hard-linked files in place (every name sees the formatted text), keeping the mode;
an unreadable path is reported once."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from typed_mjcf.cli import main

UNFORMATTED = "<mujoco>   <worldbody>  <geom size='1'/></worldbody></mujoco>\n"


def _formatted(path: Path) -> bool:
    return path.read_text() != UNFORMATTED and "<geom" in path.read_text()


def test_a_symbolic_link_is_followed_and_kept(tmp_path: Path) -> None:
    target = tmp_path / "real" / "model.xml"
    target.parent.mkdir()
    target.write_text(UNFORMATTED)
    target.chmod(0o640)
    link = tmp_path / "link.xml"
    link.symlink_to(target)
    assert main(["fmt", str(link)]) == 0
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert _formatted(target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert sorted(p.name for p in target.parent.iterdir()) == ["model.xml"]  # no temporary
    assert main(["fmt", "--check", str(link)]) == 0


def test_a_hard_linked_file_is_written_in_place(tmp_path: Path) -> None:
    first = tmp_path / "a.xml"
    first.write_text(UNFORMATTED)
    second = tmp_path / "b.xml"
    os.link(first, second)
    inode = first.stat().st_ino
    assert main(["fmt", str(first)]) == 0
    assert first.stat().st_ino == inode == second.stat().st_ino
    assert first.stat().st_nlink == 2
    assert _formatted(second)


def test_two_links_to_one_file_format_it_once(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "model.xml"
    target.write_text(UNFORMATTED)
    (tmp_path / "l1.xml").symlink_to(target)
    assert main(["fmt", str(target), str(tmp_path / "l1.xml")]) == 0
    assert "1 file reformatted, 0 files already formatted" in capsys.readouterr().out


def test_a_folder_is_reported_once(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["fmt", str(tmp_path)]) != 0
    err = capsys.readouterr().err
    assert err.count("cannot read the file") == 1, err
    assert err.strip().endswith("cannot read the file: it is a folder")
