"""``typed-mjcf render`` and ``typed-mjcf diff --render``: PNG files of the size asked for,
showing what the models hold, and one-line errors (exit 2) for what cannot be rendered."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.render.scenes import box_scene, decode_png, red
from typed_mjcf.cli import main

from .bad_inputs import BAD, EXPECTED


@pytest.fixture(autouse=True)
def _files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    for name, text in BAD.items():
        if text is not None:
            Path(name).write_text(text, encoding="utf-8")
    Path("box.xml").write_text(box_scene().to_xml_string(), encoding="utf-8")


def _size(path: str) -> tuple[int, int]:
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


@pytest.mark.parametrize(("options", "size"), [
    ([], (640, 480)),
    (["--size", "200x150"], (200, 150)),
    (["--size", "300x200", "--views", "front,side,top"], (300, 200)),
    (["--size", "160x120", "--camera", "above", "--keyframe", "moved"], (160, 120)),
    (["--size", "160x120", "--keyframe", "0", "--time", "0.1"], (160, 120)),
])
def test_the_picture_has_the_size_asked_for(options: list[str], size: tuple[int, int],
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["render", "box.xml", "-o", "box.png", *options]) == 0
    assert capsys.readouterr() == ("", "")
    assert _size("box.png") == size
    assert red(decode_png(Path("box.png").read_bytes())).any()


def test_the_camera_and_keyframe_options_reach_the_picture() -> None:
    assert main(["render", "box.xml", "-o", "a.png", "--camera", "above", "--size", "160x120"]) == 0
    assert main(["render", "box.xml", "-o", "b.png", "--camera", "above", "--size", "160x120",
                 "--keyframe", "moved"]) == 0
    model = box_scene()
    assert np.array_equal(decode_png(Path("a.png").read_bytes()),
                          model.render("above", width=160, height=120))
    assert np.array_equal(decode_png(Path("b.png").read_bytes()),
                          model.render("above", width=160, height=120, keyframe="moved"))


@pytest.mark.parametrize(("options", "message"), [
    (["--camera", "abov"], ("box.xml: render: camera='abov' names no camera of the model "
                            "(did you mean 'above'?); cameras: 'above'")),
    (["--views", "front,back"], ("box.xml: render: view 'back' is neither a preset (front, "
                                 "side, top, iso) nor a camera of the model; cameras: 'above'")),
    (["--keyframe", "7"], "box.xml: render: keyframe=7: expected an index from 0 to 0"),
    (["--camera", "above", "--views", "top"], "give --camera or --views, not both"),
])
def test_what_cannot_be_rendered_is_one_line_and_exit_2(
        options: list[str], message: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["render", "box.xml", "-o", "box.png", *options]) == 2
    assert capsys.readouterr().err == f"typed-mjcf render: {message}\n"
    assert not Path("box.png").exists()


@pytest.mark.parametrize("name", list(BAD))
def test_bad_input_is_one_line_and_exit_2(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["render", name, "-o", "out.png"]) == 2
    assert capsys.readouterr().err == f"typed-mjcf render: {EXPECTED[name]}\n"
    assert main(["diff", name, "box.xml", "--render", "out.png"]) == 2
    assert capsys.readouterr().err == f"typed-mjcf diff: {EXPECTED[name]}\n"


def test_a_bad_size_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["render", "box.xml", "-o", "box.png", "--size", "640"])
    assert exit_info.value.code == 2
    assert "'640': expected WIDTHxHEIGHT, e.g. 640x480" in capsys.readouterr().err


def _panels(path: str, width: int, height: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    picture = decode_png(Path(path).read_bytes())
    strip = picture.shape[0] - height
    assert picture.shape[1] == 3 * width and 0 < strip < 40
    body = picture[strip:]
    return body[:, :width], body[:, width : 2 * width], body[:, 2 * width :]


def test_diff_render_halves_differ_exactly_where_the_models_differ(
        capsys: pytest.CaptureFixture[str]) -> None:
    """B's box is blue: the two pictures differ on the box (its red pixels in A, and the
    pixels its edges blend), nowhere else; the third panel marks those pixels."""
    other = box_scene()
    box = other.find("geom", "box")
    assert box is not None
    box.rgba = (0, 0, 1, 1)
    Path("blue.xml").write_text(other.to_xml_string(), encoding="utf-8")
    assert main(["diff", "box.xml", "blue.xml", "--render", "diff.png",
                 "--render-size", "200x150"]) == 1
    out = capsys.readouterr().out
    assert '~ worldbody/body[box]/geom[box]: rgba "1 0 0 1" -> "0 0 1 1"' in out
    a, b, marked = _panels("diff.png", 200, 150)
    changed = np.any(a != b, axis=2)
    box_a = red(a)
    assert box_a.sum() > 100
    assert changed[box_a].all()
    near_box = box_a.copy()  # the box's pixels and two around them (blended edges)
    for _ in range(2):
        near_box[1:] |= near_box[:-1].copy()
        near_box[:-1] |= near_box[1:].copy()
        near_box[:, 1:] |= near_box[:, :-1].copy()
        near_box[:, :-1] |= near_box[:, 1:].copy()
    assert not changed[~near_box].any()
    magenta = np.all(marked == (255, 0, 255), axis=2)
    assert magenta[box_a].all() and not magenta[~near_box].any()


def test_diff_render_of_a_moved_part_marks_both_places(capsys: pytest.CaptureFixture[str]
                                                       ) -> None:
    other = box_scene()
    box = other.find("body", "box")
    assert box is not None
    box.pos = (-0.5, 0, 0.2)
    Path("moved.xml").write_text(other.to_xml_string(), encoding="utf-8")
    assert main(["diff", "box.xml", "moved.xml", "--render", "diff.png",
                 "--render-size", "200x150"]) == 1
    capsys.readouterr()
    a, b, _ = _panels("diff.png", 200, 150)
    changed = np.any(a != b, axis=2)
    assert changed[red(a)].all() and changed[red(b)].all()
    columns = np.nonzero(changed)[1]
    assert columns.min() < 100 < columns.max()  # on both sides of the middle


def _near(mask: np.ndarray, pixels: int) -> np.ndarray:
    grown = mask.copy()
    for _ in range(pixels):
        grown[1:] |= grown[:-1].copy()
        grown[:-1] |= grown[1:].copy()
        grown[:, 1:] |= grown[:, :-1].copy()
        grown[:, :-1] |= grown[:, 1:].copy()
    return grown


def test_diff_render_marks_the_geometry_not_its_shadow_or_reflection(
        capsys: pytest.CaptureFixture[str]) -> None:
    """A red ball grows over a reflective floor under a light that casts shadows: its shadow
    and reflection on the floor change too (the pictures differ there), but only the ball's
    own pixels are marked."""
    def scene(radius: float) -> str:
        model = mjcf.RootElement(model="ball")
        model.worldbody.add_light(pos=(0.6, 0.3, 2), dir=(-0.3, -0.15, -1), castshadow=True)
        model.asset.add_material(name="mirror", reflectance=0.6, rgba=(0.5, 0.5, 0.5, 1))
        model.worldbody.add_geom(type="plane", size=(2, 2, 0.1), material="mirror")
        ball = model.worldbody.add_body(name="ball", pos=(0, 0, 0.6))
        ball.add_geom(name="ball", type="sphere", size=(radius,), rgba=(1, 0, 0, 1))
        return model.to_xml_string()

    Path("small.xml").write_text(scene(0.2), encoding="utf-8")
    Path("big.xml").write_text(scene(0.23), encoding="utf-8")
    assert main(["diff", "small.xml", "big.xml", "--render", "diff.png",
                 "--render-size", "240x180"]) == 1
    capsys.readouterr()
    a, b, marked = _panels("diff.png", 240, 180)
    magenta = np.all(marked == (255, 0, 255), axis=2)
    ball = _near(red(a) | red(b), 2)
    shown_differ = np.any(a != b, axis=2)
    assert shown_differ[~ball].sum() > 50  # the floor's shadow and reflection did change
    assert magenta.sum() > 50  # the ball's rim is marked
    assert not magenta[~_near(ball, 1)].any()  # and nothing of the floor


def test_diff_render_of_equal_models_marks_nothing(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["diff", "box.xml", "box.xml", "--render", "same.png",
                 "--render-size", "120x90"]) == 0
    assert capsys.readouterr() == ("", "")
    a, b, marked = _panels("same.png", 120, 90)
    assert np.array_equal(a, b)
    assert not np.all(marked == (255, 0, 255), axis=2).any()
