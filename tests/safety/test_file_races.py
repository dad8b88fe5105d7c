"""The file opened is the file checked: a process that can write the model's folder and swaps
a file (or a folder of the path) for a link out of it while the library reads gets nothing
from outside (typed_mjcf._core.access.open_confined)."""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Callable, Generator
from contextlib import contextmanager
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl

SECRET = b"secret contents outside the model's folder"
OUTSIDE_BODY = "<mujoco><worldbody><body name='outside'/></worldbody></mujoco>"
INSIDE_BODY = "<mujoco><worldbody><body name='inside'/></worldbody></mujoco>"

pytestmark = pytest.mark.skipif(os.open not in os.supports_dir_fd or os.name == "nt",
                                reason="needs os.open with dir_fd and symbolic links")


@pytest.fixture
def layout(tmp_path: Path) -> Path:
    """``model/`` with ``mesh.stl``, ``inc.xml`` and ``d/`` (the same two inside), beside
    ``outside/`` whose ``mesh.stl`` and ``inc.xml`` are the secrets."""
    model, outside = tmp_path / "model", tmp_path / "outside"
    for folder in (model, model / "d", outside):
        folder.mkdir()
    for folder in (model, model / "d"):
        (folder / "mesh.stl").write_bytes(box_stl())
        (folder / "inc.xml").write_text(INSIDE_BODY)
    (outside / "mesh.stl").write_bytes(SECRET)
    (outside / "inc.xml").write_text(OUTSIDE_BODY)
    return tmp_path


def swap(path: Path, target: Path) -> None:
    """Put a link to ``target`` in place of ``path`` (one rename: never missing)."""
    link = path.with_name(path.name + ".link")
    link.unlink(missing_ok=True)
    link.symlink_to(target)
    os.replace(link, path)


def swap_before_opening(monkeypatch: pytest.MonkeyPatch, name: str,
                        swap_now: Callable[[], object]) -> None:
    """Run ``swap_now`` just before the name ``name`` is opened in a folder (``dir_fd``): a
    reader that opens a path without resolving it first meets the swap there."""
    real_open = os.open

    def open_after_swap(path: str, flags: int, mode: int = 0o777, *,
                        dir_fd: int | None = None) -> int:
        if path == name and dir_fd is not None:
            swap_now()
        return real_open(path, flags, mode, dir_fd=dir_fd)

    monkeypatch.setattr(os, "open", open_after_swap)


def test_a_file_swapped_for_a_link_after_the_check_is_not_read(
        layout: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The swap made exactly between resolving the path and opening it (the race, made
    certain): the old code resolved again and read the link's target."""
    model_folder = layout / "model"
    model = mjcf.from_xml_string("<mujoco><asset><mesh file='mesh.stl'/></asset></mujoco>",
                                 model_dir=model_folder)
    real = os.path.realpath

    def resolve_then_swap(path: str) -> str:
        resolved = real(path)
        if path.endswith("mesh.stl") and not os.path.islink(path):
            swap(model_folder / "mesh.stl", layout / "outside" / "mesh.stl")
        return resolved

    monkeypatch.setattr(os.path, "realpath", resolve_then_swap)
    swap_before_opening(monkeypatch, "mesh.stl",
                        lambda: resolve_then_swap(str(model_folder / "mesh.stl")))
    with pytest.raises(mjcf.FileAccessError, match=r"mesh.stl \(really .*outside/mesh.stl\) "
                                                   r"is outside the model's folder"):
        model.get_assets()


def test_a_folder_swapped_for_a_link_after_the_check_is_not_read(
        layout: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    model_folder = layout / "model"
    (model_folder / "main.xml").write_text("<mujoco><include file='d/inc.xml'/></mujoco>")
    real = os.path.realpath

    def resolve_then_swap(path: str) -> str:
        resolved = real(path)
        if path.endswith("inc.xml") and not os.path.islink(model_folder / "d"):
            (model_folder / "d").rename(model_folder / "d-moved")  # a folder: two steps
            (model_folder / "d").symlink_to(layout / "outside")
        return resolved

    monkeypatch.setattr(os.path, "realpath", resolve_then_swap)
    swap_before_opening(monkeypatch, "d",
                        lambda: resolve_then_swap(str(model_folder / "d" / "inc.xml")))
    with pytest.raises(mjcf.FileAccessError, match=r"d/inc.xml \(really .*outside/inc.xml\) "
                                                   r"is outside the model's folder"):
        mjcf.from_path(model_folder / "main.xml")


def test_a_link_that_stays_inside_is_still_followed(layout: Path) -> None:
    model_folder = layout / "model"
    (model_folder / "alias").symlink_to(model_folder / "d")
    (model_folder / "m.stl").symlink_to("d/mesh.stl")
    model = mjcf.from_xml_string("<mujoco><include file='alias/inc.xml'/><asset>"
                                 "<mesh file='m.stl'/><mesh name='b' file='alias/mesh.stl'/>"
                                 "</asset></mujoco>", model_dir=model_folder)
    assert model.find("body", "inside") is not None
    assert set(model.get_assets().values()) == {box_stl()}


@contextmanager
def swapping(pairs: list[tuple[Path, Path, Path]]) -> Generator[list[int]]:
    """A thread swapping each ``(path, inside, outside)``: ``path`` becomes a link to
    ``outside``, then to ``inside`` again, in a loop until the block ends (yields the
    number of swaps made)."""
    done = threading.Event()
    swaps = [0]

    def run() -> None:
        while not done.is_set():
            for path, inside, outside in pairs:
                swap(path, outside)
                swap(path, inside)
                swaps[0] += 1

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    try:
        yield swaps
    finally:
        done.set()
        thread.join()


def race(read: Callable[[], bool], seconds: float) -> tuple[int, int]:
    """Call ``read`` (true: it read something from outside) for ``seconds``; return how
    many reads came from outside and how many were made."""
    outside = reads = 0
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            outside += read()
        except mjcf.MjcfError:
            pass  # refused or not found mid-swap: nothing was read
        reads += 1
    return outside, reads


def test_a_writer_swapping_links_in_a_loop_reads_nothing_outside(layout: Path) -> None:
    """A thread swaps ``mesh.stl``, ``inc.xml`` and the folder ``d`` between the model's own
    (through links inside the folder: allowed) and links out of it while the library reads
    them for a few seconds: no read reaches outside."""
    model_folder, outside = layout / "model", layout / "outside"
    kept = layout / "model" / "kept"
    kept.mkdir()
    for name in ("mesh.stl", "inc.xml"):
        os.replace(model_folder / name, kept / name)
    os.replace(model_folder / "d", kept / "d")
    pairs = [(model_folder / "mesh.stl", kept / "mesh.stl", outside / "mesh.stl"),
             (model_folder / "inc.xml", kept / "inc.xml", outside / "inc.xml"),
             (model_folder / "d", kept / "d", outside)]
    for path, inside, _ in pairs:
        path.symlink_to(inside)
    main = model_folder / "main.xml"
    main.write_text("<mujoco><include file='inc.xml'/><include file='d/inc.xml'/><asset>"
                    "<mesh file='mesh.stl'/><mesh name='b' file='d/mesh.stl'/></asset>"
                    "</mujoco>")

    def load() -> bool:
        model = mjcf.from_path(main)
        return model.find("body", "outside") is not None

    model = mjcf.from_xml_string("<mujoco><asset><mesh file='mesh.stl'/><mesh name='b' "
                                 "file='d/mesh.stl'/></asset></mujoco>", model_dir=model_folder)
    with swapping(pairs) as swaps:
        assets = race(lambda: SECRET in model.get_assets().values(), 2.0)
        loads = race(load, 2.0)
    assert swaps[0] > 0
    assert assets[1] > 0 and loads[1] > 0
    assert (assets[0], loads[0]) == (0, 0), (assets, loads, swaps)
