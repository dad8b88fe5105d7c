"""from_zip: a damaged, encrypted or unsupported archive is a ParseError naming the archive and
the entry; entries are inflated only when used and never past the limits (zip bombs); the
archive's own names (``../``, absolute, repeated) reach nothing outside it. Archives are
made at test time; the big ones are small on disk (highly compressible)."""

from __future__ import annotations

import json
import re
import struct
import subprocess
import sys
import textwrap
import zipfile
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._core import tree as _tree  # pyright: ignore[reportPrivateUsage]

MODEL = "<mujoco model='z'><asset><mesh name='b' file='b.stl'/></asset></mujoco>"


def archive(path: Path, entries: dict[str, bytes | str],
            method: int = zipfile.ZIP_DEFLATED) -> Path:
    with zipfile.ZipFile(path, "w", method) as z:
        for name, data in entries.items():
            z.writestr(name, data)
    return path


def _patch(path: Path, change: str) -> None:
    """Damage the last entry of the stored (uncompressed) archive at ``path``: its data
    (``crc``), its encryption flag (``encrypted``) or its compression method (``method``)."""
    data = bytearray(path.read_bytes())
    with zipfile.ZipFile(path) as z:
        info = z.infolist()[-1]
    local, central = info.header_offset, data.rfind(b"PK\x01\x02")
    if change == "crc":
        name_length, extra_length = struct.unpack_from("<HH", data, local + 26)
        data[local + 30 + name_length + extra_length] ^= 0xFF
    for flags_at in (local + 6, central + 8):  # the local header, then the central one
        if change == "encrypted":
            struct.pack_into("<H", data, flags_at, struct.unpack_from("<H", data, flags_at)[0] | 1)
        elif change == "method":
            struct.pack_into("<H", data, flags_at + 2, 99)
    path.write_bytes(bytes(data))


@pytest.mark.parametrize(("change", "expected"), [
    ("crc", r"BadZipFile: Bad CRC-32"),
    ("encrypted", r"RuntimeError: .*encrypted"),
    ("method", r"NotImplementedError: .*compression"),
])
@pytest.mark.parametrize("damaged", ["m/model.xml", "m/b.stl"])
def test_damaged_entries_are_parse_errors_naming_archive_and_entry(
        tmp_path: Path, change: str, expected: str, damaged: str) -> None:
    entries: dict[str, bytes | str] = {"m/model.xml": MODEL, "m/b.stl": box_stl()}
    entries[damaged] = entries.pop(damaged)  # last
    path = archive(tmp_path / "m.zip", entries, zipfile.ZIP_STORED)
    _patch(path, change)
    with pytest.raises(mjcf.ParseError) as info:
        mjcf.from_zip(path).get_assets()
    assert info.value.source == str(path)
    assert info.value.detail.startswith(f"{damaged}: cannot read the entry: ")
    assert re.search(expected, info.value.detail), info.value.detail


def test_not_a_zip_and_missing_archive(tmp_path: Path) -> None:
    (tmp_path / "x.zip").write_bytes(b"not a zip at all")
    with pytest.raises(mjcf.ParseError, match=r"x.zip: not a zip archive"):
        mjcf.from_zip(tmp_path / "x.zip")
    with pytest.raises(mjcf.FileReadError, match=r"nope.zip: cannot read the archive"):
        mjcf.from_zip(tmp_path / "nope.zip")


def test_only_used_entries_are_inflated(tmp_path: Path) -> None:
    path = archive(tmp_path / "m.zip", {"m/model.xml": MODEL, "m/b.stl": box_stl(),
                                        "m/unused.bin": b"\0" * (1 << 20)})
    model = mjcf.from_zip(path)
    assert model.get_assets() == {"b.stl": box_stl()}
    assert sorted(_tree.memory_files(model)) == ["b.stl"]  # unused.bin never inflated


def test_entry_names_reach_nothing_outside_the_archive(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    """``../``, absolute and repeated names are only names: the model reads them from the
    archive (never the disk), and loading writes nothing."""
    monkeypatch.chdir(tmp_path)
    path = archive(tmp_path / "m.zip", {
        "model.xml": "<mujoco><asset><mesh file='../../evil.stl'/>"
                     "<mesh file='/etc/passwd'/></asset></mujoco>",
        "../../evil.stl": b"from the archive 1", "/etc/passwd": b"from the archive 2"})
    before = sorted(p.name for p in tmp_path.iterdir())
    assets = mjcf.from_zip(path).get_assets()
    assert sorted(assets.values()) == [b"from the archive 1", b"from the archive 2"]
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    with zipfile.ZipFile(tmp_path / "d.zip", "w") as z:
        z.writestr("model.xml", "<mujoco><asset><mesh file='b.stl'/></asset></mujoco>")
        z.writestr("b.stl", b"first")
        with pytest.warns(UserWarning, match="Duplicate name"):
            z.writestr("b.stl", b"second")
    assert mjcf.from_zip(tmp_path / "d.zip").get_assets() == {"b.stl": b"second"}


def test_limits_are_checked_while_inflating(tmp_path: Path) -> None:
    big = b"<mujoco>" + b" " * (2 << 20) + b"</mujoco>"
    path = archive(tmp_path / "m.zip", {"model.xml": big})
    with pytest.raises(mjcf.ParseError, match="ParseLimits.max_bytes"):
        mjcf.from_zip(path, limits=mjcf.ParseLimits(max_bytes=1 << 20))
    path = archive(tmp_path / "a.zip", {"model.xml": MODEL, "b.stl": b"\0" * (2 << 20)})
    model = mjcf.from_zip(path, files=mjcf.FileAccess(max_bytes=1 << 20))
    with pytest.raises(mjcf.FileAccessError, match=r"b.stl: the entry inflates to 2097152 "
                                                   r"bytes, more than .*FileAccess.max_bytes"):
        model.get_assets()


_BOMB = textwrap.dedent("""
    import json, resource, sys, tracemalloc
    import typed_mjcf as mjcf
    path = sys.argv[1]
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    tracemalloc.start()
    outcome = "loaded"
    try:
        model = mjcf.from_zip(path)
        model.get_assets()
    except mjcf.MjcfError as error:
        outcome = type(error).__name__ + ": " + str(error)[:300]
    peak = tracemalloc.get_traced_memory()[1]
    after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(json.dumps({"peak_kib": peak // 1024, "rss_growth_kib": after - before,
                      "outcome": outcome}))
""")


def _bomb(path: Path, model: bytes, extra: dict[str, int]) -> Path:
    """An archive with ``model`` and entries of zeros of the given sizes (written in chunks,
    so making it takes little memory)."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED, compresslevel=1) as z:
        z.writestr("m/model.xml", model)
        for name, size in extra.items():
            with z.open(name, "w", force_zip64=True) as entry:
                chunk = b"\0" * (1 << 24)
                for _ in range(size // len(chunk)):
                    entry.write(chunk)
    return path


@pytest.mark.skipif(sys.platform == "win32", reason="resource is POSIX only")
@pytest.mark.parametrize("case", ["unused", "model"])
def test_zip_bombs_take_bounded_memory(tmp_path: Path, case: str) -> None:
    """An unused 1 GiB entry is never inflated; a 1 GiB model.xml is refused while inflating,
    at the text limit (64 MiB). Peak memory is measured in a fresh process."""
    gib = 1 << 30
    if case == "unused":
        path = _bomb(tmp_path / "b.zip", MODEL.encode(), {"m/unused.bin": gib})
    else:
        path = tmp_path / "b.zip"
        with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED, compresslevel=1) as z, \
                z.open("m/model.xml", "w", force_zip64=True) as entry:
            entry.write(b"<mujoco>")
            chunk = b" " * (1 << 24)
            for _ in range(gib // len(chunk)):
                entry.write(chunk)
            entry.write(b"</mujoco>")
    assert path.stat().st_size < 8 << 20  # small on disk (a few MB for 1 GiB)
    run = subprocess.run([sys.executable, "-c", _BOMB, str(path)], capture_output=True,
                         text=True, check=True, timeout=600)
    result = json.loads(run.stdout)
    if case == "unused":
        assert "ParseError" not in result["outcome"]
        assert "'b.stl': not among the files of the archive" in result["outcome"]
    else:
        assert "ParseLimits.max_bytes" in result["outcome"]
    # Bounded: well under the inflated size (1 GiB); the text limit is 64 MiB.
    # Bounded: far under the inflated size (1 GiB), whether or not it was refused by the
    # entry's header (Python's allocations and the process's peak alike).
    assert result["peak_kib"] < 100 * 1024 and result["rss_growth_kib"] < 100 * 1024, result
