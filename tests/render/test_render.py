"""``model.render()``: pictures whose content follows from the scene and the camera.

The scene (:mod:`.scenes`) is a red box on a grey plane; each test works out where the box
must appear and checks the pixels there and elsewhere. Rendering is offscreen, with the back
end the library picks (EGL on the CI machine, no display).
"""

from __future__ import annotations

import numpy as np
import pytest

import typed_mjcf as mjcf

from .scenes import (
    ABOVE,
    BOX_AT,
    box_scene,
    centroid,
    grey,
    projected_top,
    red,
)

W, H = 320, 240
DOWN = mjcf.FreeView(azimuth=90, elevation=-90, distance=ABOVE, lookat=(0, 0, 0))


def test_a_red_box_on_a_grey_plane_is_red_where_it_projects_and_grey_elsewhere() -> None:
    image = box_scene().render(DOWN, width=W, height=H)
    assert image.shape == (H, W, 3) and image.dtype == np.uint8
    left, right, top, bottom = projected_top(W, H)
    rows, columns = np.mgrid[0:H, 0:W]
    inside = ((columns > left + 2) & (columns < right - 2)
              & (rows > top + 2) & (rows < bottom - 2))
    # The box's sides show between its top face and the image centre (perspective): the
    # rest of the picture, away from the box's outline, is the grey plane.
    near = ((columns > W / 2 + 0.8 * (left - W / 2) - 3) & (columns < right + 3)
            & (rows > top - 3) & (rows < bottom + 3))
    assert inside.sum() > 1000
    assert red(image)[inside].all()
    assert grey(image)[~near].all()
    assert not red(image)[~near].any()


def test_a_named_camera_sees_what_its_pose_implies() -> None:
    model = box_scene()
    named = model.render("above", width=W, height=H)
    left, right, top, bottom = projected_top(W, H)
    column, row = centroid(red(named))
    assert left < column < right + 10 and top - 2 < row < bottom + 2
    # The free view from the same place looking the same way is the same picture.
    down = model.render(DOWN, width=W, height=H)
    assert np.abs(named.astype(int) - down.astype(int)).mean() < 0.5
    # A camera element works as its name does.
    camera = model.find("camera", "above")
    assert isinstance(camera, mjcf.Camera)
    assert np.array_equal(model.render(camera, width=W, height=H), named)


@pytest.mark.parametrize(("azimuth", "side"), [(90, "right"), (270, "left"), (180, "centre")])
def test_the_box_moves_to_the_side_the_azimuth_puts_it(azimuth: float, side: str) -> None:
    """Azimuth 90 looks along +y (+x to the right), 270 along -y (+x to the left), 180
    along -x (the box, on the x axis, in the middle)."""
    view = mjcf.FreeView(azimuth=azimuth, elevation=-20, distance=3, lookat=(0, 0, 0.2))
    column, _ = centroid(red(box_scene().render(view, width=W, height=H)))
    offset = column - W / 2
    if side == "right":
        assert offset > 30
    elif side == "left":
        assert offset < -30
    else:
        assert abs(offset) < 3


def test_the_box_moves_as_the_point_looked_at_does() -> None:
    centred = mjcf.FreeView(azimuth=90, elevation=-90, distance=ABOVE, lookat=(BOX_AT[0], 0, 0))
    beyond = mjcf.FreeView(azimuth=90, elevation=-90, distance=ABOVE, lookat=(1.0, 0.3, 0))
    model = box_scene()
    column, row = centroid(red(model.render(centred, width=W, height=H)))
    assert abs(column - W / 2) < 2 and abs(row - H / 2) < 2
    column, row = centroid(red(model.render(beyond, width=W, height=H)))
    assert column < W / 2 - 20 and row > H / 2 + 10  # lookat beyond +x, +y: box left, down


def test_a_keyframe_pose_changes_the_picture() -> None:
    model = box_scene()
    still = model.render("above", width=W, height=H)
    moved = model.render("above", width=W, height=H, keyframe="moved")
    _, row_still = centroid(red(still))
    _, row_moved = centroid(red(moved))
    _, _, top, bottom = projected_top(W, H, y_shift=0.8)  # the key slides it 0.8 m
    assert top - 2 < row_moved < bottom + 2 and row_moved < row_still - 40
    key = model.find("key", "moved")
    assert key is not None
    assert np.array_equal(model.render("above", width=W, height=H, keyframe=0), moved)
    assert np.array_equal(model.render("above", width=W, height=H, keyframe=key), moved)


def test_time_simulates_from_the_pose() -> None:
    """A ball dropped from 1 m has fallen g t^2 / 2 = 0.44 m after 0.3 s."""
    model = mjcf.RootElement(model="drop")
    model.worldbody.add_light(pos=(0, -1, 3))
    model.worldbody.add_geom(type="plane", size=(2, 2, 0.1), rgba=(0.5, 0.5, 0.5, 1))
    ball = model.worldbody.add_body(name="ball", pos=(0, 0, 1))
    ball.add_freejoint()
    ball.add_geom(type="sphere", size=(0.1,), rgba=(1, 0, 0, 1))
    side = mjcf.FreeView(azimuth=90, elevation=0, distance=3, lookat=(0, 0, 0.75))
    rows = [centroid(red(model.render(side, width=W, height=H, time=t)))[1] for t in (0.0, 0.3)]
    focal = (H / 2) / np.tan(np.radians(22.5))
    assert rows[1] - rows[0] == pytest.approx(focal * 0.5 * 9.81 * 0.3**2 / 3, rel=0.1)


def test_the_default_view_frames_the_whole_model() -> None:
    model = mjcf.RootElement(model="far")
    model.worldbody.add_light(pos=(10, 10, 5))
    model.worldbody.add_geom(type="box", size=(0.5, 0.5, 0.5), pos=(10, 10, 0), rgba=(1, 0, 0, 1))
    model.worldbody.add_geom(type="box", size=(0.5, 0.5, 0.5), pos=(12, 8, 0), rgba=(1, 0, 0, 1))
    image = model.render(width=W, height=H)
    mask = red(image)
    assert mask.sum() > 500
    edge = np.concatenate([mask[0], mask[-1], mask[:, 0], mask[:, -1]])
    assert not edge.any()  # nothing cut off
    column, row = centroid(mask)
    assert abs(column - W / 2) < W / 4 and abs(row - H / 2) < H / 4


def test_views_make_a_labelled_contact_sheet_of_the_same_pictures() -> None:
    model = box_scene()
    sheet = model.render(width=640, height=480, views=("front", "side", "top", "iso"))
    assert sheet.shape == (480, 640, 3)
    tile_w = 320
    # The label strip holds two colours, background and ink; the picture starts below it.
    label_colours = {tuple(c) for c in np.unique(sheet[0, :tile_w], axis=0)}
    assert len(label_colours) == 1  # the top row of the strip, above the letters
    background = sheet[0, 0]
    strip = next(y for y in range(240)
                 if not (np.all(sheet[y, :tile_w] == background, axis=1)
                         | (sheet[y, :tile_w].min(axis=1) > 200)).all())
    assert 8 <= strip <= 30
    tile_h = 240 - strip
    # Each tile is the picture its preset gives alone; its label is in the strip above it.
    for i, name in enumerate(("front", "side", "top", "iso")):
        azimuth, elevation = mjcf.VIEWS[name]
        x, y = (i % 2) * tile_w, (i // 2) * 240
        alone = model.render(mjcf.FreeView(azimuth=azimuth, elevation=elevation), width=tile_w, height=tile_h)
        assert np.array_equal(sheet[y + strip : y + 240, x : x + tile_w], alone), name
        label = sheet[y : y + strip, x : x + tile_w]
        assert (label.max(axis=2) > 200).sum() > 10 * len(name), name  # letters drawn
    column, _ = centroid(red(sheet[240 + strip :, :tile_w]))  # top: +x to the right
    assert column > tile_w / 2


def test_a_model_camera_can_be_a_view_of_the_sheet() -> None:
    sheet = box_scene().render(width=400, height=200, views=("above", "top"))
    assert sheet.shape == (200, 400, 3)
    assert red(sheet[:, :200]).any() and red(sheet[:, 200:]).any()


def test_big_pictures_enlarge_the_offscreen_buffer_of_the_compiled_copy_only() -> None:
    model = box_scene()
    image = model.render(DOWN, width=1280, height=960)
    assert image.shape == (960, 1280, 3)
    small = model.render(DOWN, width=W, height=H)
    # The same scene at four times the pixels: the box covers the same share of it.
    assert red(image).mean() == pytest.approx(red(small).mean(), rel=0.05)
    assert model.visual.global_.offwidth is None  # the model itself is unchanged


def test_a_model_with_its_own_offscreen_size_keeps_it() -> None:
    model = box_scene()
    model.visual.global_.offwidth = 2000
    model.visual.global_.offheight = 1500
    assert model.render(DOWN, width=1800, height=1200).shape == (1200, 1800, 3)


def test_render_png_writes_the_picture(tmp_path: object) -> None:
    from pathlib import Path

    from .scenes import decode_png

    assert isinstance(tmp_path, Path)
    model = box_scene()
    model.render_png(tmp_path / "box.png", DOWN, width=W, height=H)
    assert np.array_equal(decode_png((tmp_path / "box.png").read_bytes()),
                          model.render(DOWN, width=W, height=H))


# ---------------------------------------------------------------------------- errors


def test_an_unknown_camera_is_named_with_the_cameras_there_are() -> None:
    with pytest.raises(mjcf.InvalidValueError, match=r"camera='abov' names no camera of the "
                       r"model \(did you mean 'above'\?\); cameras: 'above'"):
        box_scene().render("abov", width=W, height=H)


def test_an_unknown_view_lists_the_presets() -> None:
    with pytest.raises(mjcf.InvalidValueError, match=r"view 'fornt' is neither a preset "
                       r"\(front, side, top, iso\) nor a camera of the model \(did you mean "
                       r"'front'\?\)"):
        box_scene().render(width=W, height=H, views=("fornt",))


def test_cameras_that_cannot_be_used_are_refused_with_their_path() -> None:
    model = box_scene()
    unnamed = model.worldbody.add_camera(pos=(0, 0, 2))
    with pytest.raises(mjcf.InvalidValueError, match=r"worldbody/camera\[1\]: an unnamed "
                       r"camera cannot be found"):
        model.render(unnamed, width=W, height=H)
    geom = model.find("geom", "box")
    with pytest.raises(mjcf.InvalidTypeError, match=r"expected a camera element"):
        model.render(geom, width=W, height=H)  # type: ignore[arg-type]  # deliberately wrong
    other = box_scene().find("camera", "above")
    with pytest.raises(mjcf.InvalidValueError, match="not part of this model"):
        model.render(other, width=W, height=H)


def test_a_camera_of_an_attached_model_is_found_by_its_scoped_name() -> None:
    world = mjcf.RootElement(model="world")
    world.worldbody.add_light(pos=(0, 0, 3))
    inner = box_scene()
    world.worldbody.attach(inner)
    camera = inner.find("camera", "above")
    assert camera is not None
    assert np.array_equal(world.render(camera, width=W, height=H),
                          world.render("box_scene/above", width=W, height=H))


@pytest.mark.parametrize(("keyframe", "message"), [
    ("mvoed", r"keyframe='mvoed' names no key of the model \(did you mean 'moved'\?\)"),
    (3, r"keyframe=3: expected an index from 0 to 0"),
    (1.5, r"keyframe=1.5: expected a key's name, its index or the key element"),
])
def test_bad_keyframes_are_refused(keyframe: object, message: str) -> None:
    with pytest.raises(mjcf.MjcfError, match=message):
        box_scene().render(width=W, height=H, keyframe=keyframe)  # type: ignore[arg-type]


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"width": 0}, r"width=0 for the picture: expected 1 to 8192 pixels"),
    ({"height": 2.5}, r"height=2.5: expected a whole number of pixels"),
    ({"time": -1.0}, r"time=-1.0: expected zero or more seconds"),
    ({"views": "front"}, r"views='front': expected a sequence of names"),
    ({"views": ("front",), "camera": "above"}, r"give camera= or views=, not both"),
    ({"camera": mjcf.FreeView(distance=-1)}, r"FreeView distance=-1: expected a positive"),
    ({"camera": 320}, r"camera=320: the size is given by keyword, render\(width=\.\.\."),
])
def test_bad_arguments_are_refused(kwargs: dict[str, object], message: str) -> None:
    with pytest.raises(mjcf.MjcfError, match=message):
        box_scene().render(**kwargs)  # type: ignore[arg-type]
