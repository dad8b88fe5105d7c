"""export_with_assets writes only into its folder, atomically, and never silently replaces a
different file."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._model import assets_io as _assets_io  # pyright: ignore[reportPrivateUsage]

UNSAFE_NAMES = ["../../escape", "/abs/olute", "a/b", "a\\b", "..", ".", ".hidden", "con",
                "c:evil", "x" * 300, "tab\there", " ", "nul.txt"]


def files_under(folder: Path) -> set[str]:
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


def model_with_meshes(names: list[str | None], model_name: str = "m") -> mjcf.RootElement:
    model = mjcf.RootElement(model=model_name)
    for i, name in enumerate(names):
        mesh = model.asset.add_mesh(name=f"mesh{i}",
                                    file=mjcf.Asset(box_stl(0.1 + i / 100), ".stl", name=name))
        body = model.worldbody.add_body()
        body.add_freejoint()
        body.add_geom(type="mesh", mesh=mesh)
    return model


def test_asset_and_element_names_cannot_leave_the_folder(tmp_path: Path) -> None:
    model = model_with_meshes(list(UNSAFE_NAMES), model_name="../../model")
    # Element names feed file names too (an in-memory asset without a name of its own).
    for i, name in enumerate(["..", ".env", "x:y"]):
        model.asset.add_mesh(name=name, file=mjcf.Asset(box_stl(0.5 + i / 10), "stl"))
    out = tmp_path / "deep" / "out"
    path = mjcf.export_with_assets(model, out)
    assert files_under(tmp_path) == {"deep", "deep/out"} | {f"deep/out/{n}" for n in os.listdir(out)}
    names = os.listdir(out)
    assert len(names) == len(UNSAFE_NAMES) + 3 + 1
    for name in names:
        assert _assets_io.is_plain_file_name(name), name
        assert not name.startswith(".") and "/" not in name and "\\" not in name
        assert len(name.encode()) <= 210
    assert Path(path).parent == out and Path(path).name == "_.._model.xml"
    # get_assets() (what a user might write to disk) gives the same safe names.
    assert set(model.get_assets()) | {Path(path).name} == set(names)
    assert mujoco.MjModel.from_xml_path(path).nmesh == len(UNSAFE_NAMES) + 3


@pytest.mark.parametrize(("stem", "extension", "expected"), [
    ("mesh", ".stl", "mesh.stl"),
    ("my mesh.v2", ".STL", "my mesh.v2.STL"),
    ("../../x", ".stl", "_.._x.stl"),
    ("ok", "../../../y", "ok._.._.._y"),
    ("..", "", "file"),
    ("trailing. ", "", "trailing"),
    ("LPT1", ".png", "_LPT1.png"),
])
def test_safe_file_name(stem: str, extension: str, expected: str) -> None:
    assert _assets_io.safe_file_name(stem, extension) == expected
    assert _assets_io.is_plain_file_name(expected)


def test_names_differing_only_in_case_do_not_collide() -> None:
    model = model_with_meshes(["Part", "part", "PART"])
    assert sorted(model.get_assets()) == ["PART-3.stl", "Part.stl", "part-2.stl"]


def test_explicit_model_filename_must_be_plain(tmp_path: Path) -> None:
    model = model_with_meshes(["part"])
    model.asset.add_mesh(name="clash", file=mjcf.Asset(box_stl(), ".xml", name="PART"))
    for bad in ["../m.xml", "sub/m.xml", str(tmp_path / "m.xml"), ".m.xml"]:
        with pytest.raises(mjcf.ExportError, match="plain file name"):
            mjcf.export_with_assets(model, tmp_path / "out", bad)
    for not_xml in ["", "m.png"]:  # dm_control's rule too
        with pytest.raises(mjcf.ExportError, match="must end with '.xml'"):
            mjcf.export_with_assets(model, tmp_path / "out", not_xml)
    with pytest.raises(mjcf.ExportError, match="also the name of a file the model uses"):
        mjcf.export_with_assets(model, tmp_path / "out", "part.XML")
    assert not (tmp_path / "out").exists() or not os.listdir(tmp_path / "out")


def test_different_existing_files_are_not_overwritten_silently(tmp_path: Path) -> None:
    model = model_with_meshes(["part", "other"])
    out = tmp_path / "out"
    out.mkdir()
    (out / "part.stl").write_bytes(b"someone else's mesh")
    with pytest.raises(mjcf.ExportError, match=r"would replace 1 file.*part.stl.*overwrite=True"):
        mjcf.export_with_assets(model, out)
    assert sorted(os.listdir(out)) == ["part.stl"]  # nothing written
    assert (out / "part.stl").read_bytes() == b"someone else's mesh"
    path = mjcf.export_with_assets(model, out, overwrite=True)
    assert (out / "part.stl").read_bytes() == box_stl(0.1)
    assert sorted(os.listdir(out)) == ["m.xml", "other.stl", "part.stl"]
    # Identical files are fine, and left untouched.
    os.utime(path, (1, 1))
    assert mjcf.export_with_assets(model, out) == path
    assert os.stat(path).st_mtime == 1


def test_links_and_folders_in_the_way(tmp_path: Path) -> None:
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    out.mkdir()
    outside = tmp_path / "outside.stl"
    outside.write_bytes(b"do not touch")
    (out / "part.stl").symlink_to(outside)
    with pytest.raises(mjcf.ExportError, match=r"part.stl \(a symbolic link\)"):
        mjcf.export_with_assets(model, out)
    mjcf.export_with_assets(model, out, overwrite=True)
    assert outside.read_bytes() == b"do not touch"  # the link was replaced, not followed
    assert not (out / "part.stl").is_symlink()
    (out / "m.xml").unlink()
    (out / "m.xml").mkdir()
    with pytest.raises(mjcf.ExportError, match="a folder of that name is in the way"):
        mjcf.export_with_assets(model, out, overwrite=True)


def test_writes_are_atomic(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    out.mkdir()
    (out / "part.stl").write_bytes(b"old")

    def failing_replace(source: str, target: str) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", failing_replace)
    with pytest.raises(mjcf.ExportError, match="cannot write .*part.stl: No space left"):
        mjcf.export_with_assets(model, out, overwrite=True)
    monkeypatch.undo()
    assert os.listdir(out) == ["part.stl"]  # no temporary file left behind
    assert (out / "part.stl").read_bytes() == b"old"  # and the old file intact


def test_a_file_appearing_meanwhile_is_not_replaced(tmp_path: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    real_link = os.link

    def racing_link(source: str, target: str) -> None:
        if target.endswith("part.stl"):
            Path(target).write_bytes(b"written by someone else meanwhile")
        real_link(source, target)

    monkeypatch.setattr(os, "link", racing_link)
    with pytest.raises(mjcf.ExportError, match="appeared while exporting"):
        mjcf.export_with_assets(model, out)
    assert (out / "part.stl").read_bytes() == b"written by someone else meanwhile"
    assert not [n for n in os.listdir(out) if n.startswith(".")]


def test_written_files_have_ordinary_permissions(tmp_path: Path) -> None:
    path = mjcf.export_with_assets(model_with_meshes(["part"]), tmp_path)
    umask = os.umask(0o022)
    os.umask(umask)
    for name in (path, tmp_path / "part.stl"):
        assert stat.S_IMODE(os.stat(name).st_mode) == 0o666 & ~umask


def test_unwritable_folder_is_an_export_error(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(mjcf.ExportError, match="cannot create the folder"):
        mjcf.export_with_assets(model_with_meshes(["part"]), blocker / "out")


# ------------------------------------------------------------- one change, and the zip export


def _old_folder(out: Path) -> dict[str, bytes]:
    out.mkdir()
    (out / "part.stl").write_bytes(b"old part")
    (out / "m.xml").write_bytes(b"old xml")
    return {"part.stl": b"old part", "m.xml": b"old xml"}


def _contents(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir()}


@pytest.mark.parametrize("failure", [OSError(28, "No space left on device"), KeyboardInterrupt()])
def test_a_failure_partway_puts_every_file_back(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                failure: BaseException) -> None:
    """The asset is in place when renaming the XML fails (or is interrupted): the asset is
    put back, so the old XML never sits beside new assets, and no temporary file is left."""
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    before = _old_folder(out)
    real_replace = os.replace

    def failing_on_the_xml(source: str, target: str) -> None:
        if str(target).endswith("m.xml") and ".typed-mjcf-" in str(source):
            raise failure
        real_replace(source, target)

    monkeypatch.setattr(os, "replace", failing_on_the_xml)
    with pytest.raises(type(failure) if isinstance(failure, KeyboardInterrupt) else mjcf.ExportError):
        mjcf.export_with_assets(model, out, overwrite=True)
    monkeypatch.undo()
    assert _contents(out) == before


def test_a_failure_writing_a_temporary_file_changes_nothing(tmp_path: Path,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    before = _old_folder(out)
    calls = 0
    real_fsync = os.fsync

    def interrupted(fd: int) -> None:
        nonlocal calls
        calls += 1
        if calls == 2:  # the XML's temporary file, after the asset's
            raise KeyboardInterrupt
        real_fsync(fd)

    monkeypatch.setattr(os, "fsync", interrupted)
    with pytest.raises(KeyboardInterrupt):
        mjcf.export_with_assets(model, out, overwrite=True)
    monkeypatch.undo()
    assert _contents(out) == before


def _dead_pid() -> int:
    process = subprocess.Popen([sys.executable, "-c", "pass"])
    process.wait()
    return process.pid


def test_temporary_files_of_a_killed_export_are_removed_by_the_next(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    dead = out / f".typed-mjcf-{_dead_pid()}-abc123.tmp"
    dead.write_bytes(b"x" * 1000)
    running = out / f".typed-mjcf-{os.getpid()}-def456.tmp"  # an export still writing
    running.write_bytes(b"y")
    old_style = out / ".typed-mjcf-k2j3h4.tmp"  # no process id: stale once a day old
    old_style.write_bytes(b"z")
    os.utime(old_style, (1, 1))
    fresh_old_style = out / ".typed-mjcf-q9w8e7.tmp"
    fresh_old_style.write_bytes(b"z")
    unrelated = out / ".typed-mjcf-notes.txt"
    unrelated.write_bytes(b"keep")
    mjcf.export_with_assets(model_with_meshes(["part"]), out)
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [running.name, fresh_old_style.name, unrelated.name, "m.xml", "part.stl"])
    dead.write_bytes(b"x")
    mjcf.export_with_assets_as_zip(model_with_meshes(["part"]), out)
    assert not dead.exists()


def test_a_killed_export_leaves_only_a_temporary_file_the_next_removes(tmp_path: Path) -> None:
    out = tmp_path / "out"
    script = (
        "import os, sys, typed_mjcf as mjcf\n"
        "from tests.safety.test_export import model_with_meshes\n"
        "def die(*args, **kwargs):\n"
        "    os._exit(9)  # killed between writing the files and renaming them\n"
        "os.replace = os.link = die\n"
        f"mjcf.export_with_assets(model_with_meshes(['part']), {str(out)!r})\n")
    subprocess.run([sys.executable, "-c", script], check=False, cwd=Path(__file__).parents[2])
    left = sorted(p.name for p in out.iterdir())
    assert left and all(n.startswith(".typed-mjcf-") and n.endswith(".tmp") for n in left), left
    mjcf.export_with_assets(model_with_meshes(["part"]), out)
    assert sorted(p.name for p in out.iterdir()) == ["m.xml", "part.stl"]


def test_the_zip_export_writes_atomically_and_never_through_a_link(tmp_path: Path) -> None:
    model = model_with_meshes(["part"])
    out = tmp_path / "out"
    out.mkdir()
    outside = tmp_path / "outside.zip"
    outside.write_bytes(b"do not touch")
    (out / "m.zip").symlink_to(outside)
    with pytest.raises(mjcf.ExportError, match=r"m.zip \(a symbolic link\)"):
        mjcf.export_with_assets_as_zip(model, out)
    path = mjcf.export_with_assets_as_zip(model, out, overwrite=True)
    assert outside.read_bytes() == b"do not touch" and not Path(path).is_symlink()
    assert mjcf.from_zip(path).get_assets() == model.get_assets()
    again = mjcf.export_with_assets_as_zip(model, out)  # the same archive: no error
    assert again == path
    model.asset.mesh[0].file = mjcf.Asset(box_stl(0.7), ".stl", name="part")
    with pytest.raises(mjcf.ExportError, match=r"export_with_assets_as_zip would replace 1 "
                                               r"file\(s\) .*m.zip"):
        mjcf.export_with_assets_as_zip(model, out)
    assert mjcf.from_zip(path).get_assets() != model.get_assets()  # the old one is intact
    mjcf.export_with_assets_as_zip(model, out, overwrite=True)
    assert mjcf.from_zip(path).get_assets() == model.get_assets()
    assert sorted(os.listdir(out)) == ["m.zip"]


def test_the_zip_export_failing_leaves_the_old_archive(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / "m.zip").write_bytes(b"old archive")

    def failing_replace(source: str, target: str) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "replace", failing_replace)
    with pytest.raises(KeyboardInterrupt):
        mjcf.export_with_assets_as_zip(model_with_meshes(["part"]), out, overwrite=True)
    monkeypatch.undo()
    assert _contents(out) == {"m.zip": b"old archive"}


def test_a_kept_apart_files_folder_is_never_a_link(tmp_path: Path) -> None:
    """Two files of one base name are exported under their folders (``assets/a/x.stl``),
    made inside the export's folder: a link in its place is refused, nothing written."""
    for part, size in (("a", 0.1), ("b", 0.2)):
        (tmp_path / "src" / "assets" / part).mkdir(parents=True)
        (tmp_path / "src" / "assets" / part / "x.stl").write_bytes(box_stl(size))
    source = tmp_path / "src" / "m.xml"
    source.write_text("<mujoco><compiler meshdir='assets'/><asset><mesh name='a' "
                      "file='a/x.stl'/><mesh name='b' file='b/x.stl'/></asset></mujoco>")
    model = mjcf.from_path(source)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "assets").symlink_to(elsewhere)
    with pytest.raises(mjcf.MjcfError, match="assets: not a folder"):
        mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert not list(elsewhere.iterdir())
    (tmp_path / "out" / "assets").unlink()
    path = mjcf.export_with_assets(model, str(tmp_path / "out"))
    assert files_under(tmp_path / "out") >= {"assets/a/x.stl", "assets/b/x.stl"}
    assert mujoco.MjModel.from_xml_path(path).nmesh == 2
