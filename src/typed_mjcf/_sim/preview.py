"""Pictures of models: compile, pose, render offscreen, and lay out labelled views.

A model is compiled through :func:`typed_mjcf._sim.bridge.compile_model` (the same path as
``compile()``), posed in a fresh ``MjData`` (a keyframe, then ``time`` seconds of
simulation), and rendered with MuJoCo's own renderer (``MjrContext``, as ``mujoco.Renderer``
does) on a context of the back end :mod:`typed_mjcf._sim.gl` chose.
"""

from __future__ import annotations

import math
import numbers
import os
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Final, Self, cast

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, RenderError, did_you_mean
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._model.resource_limits import (
    DEFAULT_RENDER_LIMITS,
    RenderLimits,
    check_offscreen,
    check_steps,
)
from typed_mjcf._sim.bridge import compile_model
from typed_mjcf._sim.font import GLYPH_HEIGHT, GLYPH_WIDTH, draw_text, text_size
from typed_mjcf._sim.gl import ensure_gl_backend, gl_context
from typed_mjcf._sim.png import encode_png

if TYPE_CHECKING:
    import mujoco
    from numpy.typing import NDArray

    Image = NDArray[np.uint8]

Point = tuple[float, float, float]


@dataclass(frozen=True)
class FreeView:
    """A free camera looking at ``lookat`` from ``distance`` away, turned ``azimuth``
    degrees about the vertical axis and tilted ``elevation`` degrees (negative: from above),
    as in MuJoCo's viewer. What is left ``None`` is as the default view has it: the
    model's centre, 1.5 times its extent, ``<visual><global azimuth elevation>``."""

    azimuth: float | None = None
    elevation: float | None = None
    distance: float | None = None
    lookat: Point | None = None


# Named views (azimuth, elevation): robots in MJCF usually face +x. "front" looks at the
# model from +x, "side" from -y (MuJoCo's default direction: +x to the right), "top" from
# above (+x to the right, +y up), "iso" from +x, -y and above.
VIEWS: Final[dict[str, tuple[float, float]]] = {
    "front": (180.0, -10.0), "side": (90.0, -10.0), "top": (90.0, -90.0), "iso": (135.0, -30.0),
}
MAX_SIZE: Final = 8192  # pixels on a side: more than any offscreen buffer needs
_MAX_GEOMS: Final = 10_000  # geoms a scene holds (mujoco.Renderer's default)
_BACKGROUND: Final = (32, 32, 32)  # around tiles and behind labels
_INK: Final = (235, 235, 235)
_CHANGED: Final = (255, 0, 255)  # pixels that differ, in a difference panel


# ---------------------------------------------------------------------------- public entry


def render(model: ModelBase, camera: object = None, *, width: object = 640,
           height: object = 480, time: object = 0.0, keyframe: object = None,
           views: object = None, limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Image:
    """The model as a height x width x 3 ``uint8`` image (see ``RootElement.render``); the
    arguments are checked here, whatever their static types said."""
    if isinstance(camera, numbers.Number):
        raise InvalidTypeError(f"render: camera={camera!r}: the size is given by keyword, "
                               f"render(width=..., height=...); the first argument is the "
                               f"camera (a name, a <camera> or a FreeView)")
    limits = _check_limits(limits)
    width, height = _check_size(width, height)
    seconds = _check_time(time)
    names = _check_views(views)
    if names is not None and camera is not None:
        raise InvalidValueError("render: give camera= or views=, not both")
    ensure_gl_backend()  # before compiling imports mujoco: MUJOCO_GL is set by then
    m = compile_model(model, limits.compile)
    data = _posed(model, m, keyframe, seconds, limits)
    if names is None:
        with _Offscreen(m, width, height, limits) as offscreen:
            return offscreen.shoot(data, _camera(model, m, camera), width, height)
    columns, rows = _grid(len(names))
    scale = _label_scale(width // columns)
    tile_w, tile_h = width // columns, height // rows - _strip(scale)
    _check_size(tile_w, tile_h, f"each of {len(names)} views")
    with _Offscreen(m, tile_w, tile_h, limits) as offscreen:
        tiles = [offscreen.shoot(data, _view(m, name), tile_w, tile_h) for name in names]
    return _sheet(list(zip(names, tiles, strict=True)), columns, width, height, scale)


def render_png(model: ModelBase, path: str | os.PathLike[str], camera: object = None, *,
               width: object = 640, height: object = 480, time: object = 0.0,
               keyframe: object = None, views: object = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> None:
    """Write :func:`render`'s picture to ``path`` as a PNG file."""
    _check_path(path)
    picture = render(model, camera, width=width, height=height, time=time, keyframe=keyframe,
                     views=views, limits=limits)
    write_png(path, picture)


def _check_path(path: object) -> None:
    if not isinstance(path, str | os.PathLike):
        raise InvalidTypeError(f"render_png: path must be a path (str or os.PathLike[str]), "
                               f"got {type(path).__name__}")


def write_png(path: str | os.PathLike[str], picture: Image) -> None:
    """Write ``picture`` as a PNG file; a path that cannot be written is a RenderError."""
    _check_path(path)
    try:
        with open(path, "wb") as file:
            file.write(encode_png(picture))
    except OSError as error:
        raise RenderError(f"cannot write the picture to {os.fspath(path)}: "
                          f"{error.strerror or error}") from None


def render_pair(a: ModelBase, b: ModelBase, width: int = 640, height: int = 480,
                labels: tuple[str, str] = ("A", "B"), camera: str | FreeView | None = None,
                lighting: bool = False, limits: RenderLimits = DEFAULT_RENDER_LIMITS
                ) -> tuple[Image, int]:
    """Two models side by side from the same camera, and a third panel showing the first
    with the pixels where the two models differ painted magenta; also how many differ.

    Both are framed together (the default view of their union) and rendered with the same
    visual scale, so a pixel differs only where the models differ. Which pixels differ is
    found on pictures drawn without shadows, reflections, fog and haze (unless
    ``lighting``): a changed size or position then lights the geometry that changed, not the
    floor where its shadow and reflection moved.
    """
    width, height = _check_size(width, height)
    ensure_gl_backend()
    limits = _check_limits(limits)
    compiled = [compile_model(a, limits.compile), compile_model(b, limits.compile)]
    center, extent = _union(*(_bounds(m) for m in compiled))
    pictures: list[Image] = []
    compared: list[Image] = []
    for model, m in zip((a, b), compiled, strict=True):
        m.stat.center[:] = center  # lights, shadows and clipping scale with these
        m.stat.extent = extent
        data = _posed(model, m, None, 0.0, limits)
        with _Offscreen(m, width, height, limits) as offscreen:
            view = camera if camera is not None else FreeView(
                azimuth=float(compiled[0].vis.global_.azimuth),
                elevation=float(compiled[0].vis.global_.elevation))
            pictures.append(offscreen.shoot(data, _camera(model, m, view), width, height))
            if not lighting:
                offscreen.plain()
                compared.append(offscreen.shoot(data, _camera(model, m, view), width, height))
    compared = compared or pictures
    changed = np.any(compared[0] != compared[1], axis=2)
    grey = (pictures[0].mean(axis=2, keepdims=True) * 0.5 + 40).astype(np.uint8)
    difference = np.repeat(grey, 3, axis=2)
    difference[changed] = _CHANGED
    count = int(changed.sum())
    panels = [(labels[0], pictures[0]), (labels[1], pictures[1]),
              (f"difference: {count} pixel{'s' if count != 1 else ''}", difference)]
    scale = _label_scale(width)
    return _sheet(panels, 3, 3 * width, height + _strip(scale), scale), count


# ---------------------------------------------------------------------------- arguments


def _check_size(width: object, height: object, what: str = "the picture") -> tuple[int, int]:
    checked: list[int] = []
    for name, value in (("width", width), ("height", height)):
        if isinstance(value, bool) or not isinstance(value, numbers.Integral):
            raise InvalidTypeError(f"render: {name}={value!r}: expected a whole number of "
                                   f"pixels")
        if not 1 <= int(value) <= MAX_SIZE:
            raise InvalidValueError(f"render: {name}={value!r} for {what}: expected 1 to "
                                    f"{MAX_SIZE} pixels")
        checked.append(int(value))
    return checked[0], checked[1]


def _check_time(time: object) -> float:
    if isinstance(time, bool) or not isinstance(time, numbers.Real):
        raise InvalidTypeError(f"render: time={time!r}: expected seconds, a number")
    seconds = float(time)
    if not (math.isfinite(seconds) and seconds >= 0):
        raise InvalidValueError(f"render: time={time!r}: expected zero or more seconds")
    return seconds


def _check_limits(limits: object) -> RenderLimits:
    if not isinstance(limits, RenderLimits):
        raise InvalidTypeError(f"render: limits={limits!r}: expected a "
                               f"typed_mjcf.RenderLimits")
    return limits


def _check_views(views: object) -> list[str] | None:
    if views is None:
        return None
    items = (list(cast("Sequence[object]", views))
             if isinstance(views, Sequence) and not isinstance(views, str) else [])
    names = [item for item in items if isinstance(item, str)]
    if not names or len(names) != len(items):
        raise InvalidValueError(f"render: views={views!r}: expected a sequence of names, "
                                f"e.g. ('front', 'side')")
    return names


# ---------------------------------------------------------------------------- pose


def _posed(model: ModelBase, m: mujoco.MjModel, keyframe: object,
           seconds: float, limits: RenderLimits) -> mujoco.MjData:
    """The model's state after ``seconds`` of simulation from ``keyframe`` (or ``qpos0``)."""
    import mujoco

    steps = check_steps(seconds, float(m.opt.timestep), limits)
    data = mujoco.MjData(m)
    if keyframe is not None:
        mujoco.mj_resetDataKeyframe(m, data, _key_id(model, m, keyframe))
    for _ in range(steps):
        mujoco.mj_step(m, data)
    mujoco.mj_forward(m, data)  # positions of bodies and geoms for the pose reached
    return data


def _key_id(model: ModelBase, m: mujoco.MjModel, keyframe: object) -> int:
    import mujoco

    kind = int(mujoco.mjtObj.mjOBJ_KEY)
    if isinstance(keyframe, Element):
        name = _tree.element_name(keyframe)  # keys combine by their own name when composed
        if not _is_kind(keyframe, kind):
            raise InvalidTypeError(f"render: keyframe={keyframe.path}: expected a key element, "
                                   f"its name or its index")
        if name is None:
            return _unnamed_key(model, keyframe, m)
        keyframe = name
    if isinstance(keyframe, bool) or not isinstance(keyframe, str | numbers.Integral):
        raise InvalidTypeError(f"render: keyframe={keyframe!r}: expected a key's name, its "
                               f"index or the key element")
    names = [m.key(i).name for i in range(m.nkey)]
    if isinstance(keyframe, str):
        found = mujoco.mj_name2id(m, kind, keyframe)
        if found < 0:
            raise InvalidValueError(f"render: keyframe={keyframe!r} names no key of the model"
                                    f"{did_you_mean(keyframe, names)}; {_listed('keys', names)}")
        return found
    if not 0 <= int(keyframe) < m.nkey:
        raise InvalidValueError(f"render: keyframe={keyframe!r}: expected an index from 0 to "
                                f"{m.nkey - 1}" if m.nkey else
                                f"render: keyframe={keyframe!r}: the model has no keys")
    return int(keyframe)


def key_from_text(model: ModelBase, text: str) -> str | int:
    """A key as a command line names it: its name, or its index when it is a number that
    no key of the model is named."""
    import mujoco

    if not text.isdigit():
        return text
    kind = int(mujoco.mjtObj.mjOBJ_KEY)
    named = any(_tree.element_name(e) == text and _is_kind(e, kind)
                for e in _tree.iter_composed(model, True))
    return text if named else int(text)


def _unnamed_key(model: ModelBase, key: Element, m: mujoco.MjModel) -> int:
    """An unnamed key's index: its place among the model's keys, when no attached model
    adds keys of its own (whose places in the composed model MuJoCo decides)."""
    if _tree.model_of(key) is not model or _tree.attached_models(model):
        raise InvalidValueError(f"render: keyframe={key.path}: an unnamed key of a composed "
                                f"model; name it, or give its index in the compiled model")
    keys = [e for e in _tree.iter_composed(model, False) if e.spec.namespace == key.spec.namespace]
    index = keys.index(key)
    if index >= m.nkey:  # pragma: no cover - each written key is one compiled key
        raise InvalidValueError(f"render: keyframe={key.path}: not in the compiled model")
    return index


def _is_kind(element: Element, kind: int) -> bool:
    """Whether ``element`` declares an object of MuJoCo type ``kind`` (an ``mjtObj``)."""
    import mujoco

    namespace = element.spec.namespace
    return namespace is not None and mujoco.mju_str2Type(namespace) == kind


# ---------------------------------------------------------------------------- cameras


def _camera(model: ModelBase, m: mujoco.MjModel, choice: object) -> mujoco.MjvCamera:
    """The ``MjvCamera`` for ``camera=``: the default view, a free view, or a model's."""
    import mujoco

    camera = mujoco.MjvCamera()
    mujoco.mjv_defaultFreeCamera(m, camera)  # centre and extent, as MuJoCo's viewer frames
    if choice is None:
        return camera
    if isinstance(choice, FreeView):
        return _free(camera, choice)
    if isinstance(choice, Element):
        if not _is_kind(choice, int(mujoco.mjtObj.mjOBJ_CAMERA)):
            raise InvalidTypeError(f"render: camera={choice.path}: expected a camera element, "
                                   f"a camera's name or a FreeView")
        own = _tree.element_name(choice)
        scope, top = _tree.scope_of(choice), _tree.scope_of(model)
        if not scope.is_within(top) or _tree.model_of(choice) is None:
            raise InvalidValueError(f"render: camera={choice.path}: the camera is not part of "
                                    f"this model")
        if own is None:
            raise InvalidValueError(f"render: camera={choice.path}: an unnamed camera cannot "
                                    f"be found in the compiled model; give it a name")
        name = scope.prefix(top) + own  # its name in the compiled model
        choice = name
    if not isinstance(choice, str):
        raise InvalidTypeError(f"render: camera={choice!r}: expected a camera's name, a "
                               f"camera element or a FreeView")
    camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
    camera.fixedcamid = _camera_id(m, choice)
    return camera


def _camera_id(m: mujoco.MjModel, name: str) -> int:
    import mujoco

    found = mujoco.mj_name2id(m, int(mujoco.mjtObj.mjOBJ_CAMERA), name)
    if found < 0:
        names = _camera_names(m)
        raise InvalidValueError(f"render: camera={name!r} names no camera of the model"
                                f"{did_you_mean(name, names)}; {_listed('cameras', names)}")
    return found


def _camera_names(m: mujoco.MjModel) -> list[str]:
    return [name for i in range(m.ncam) if (name := m.camera(i).name)]


def _free(camera: mujoco.MjvCamera, view: FreeView) -> mujoco.MjvCamera:
    azimuth = _angle("azimuth", view.azimuth)
    elevation = _angle("elevation", view.elevation)
    distance = _angle("distance", view.distance)
    if azimuth is not None:
        camera.azimuth = azimuth
    if elevation is not None:
        camera.elevation = elevation
    if distance is not None:
        if distance <= 0:
            raise InvalidValueError(f"render: FreeView distance={view.distance!r}: expected "
                                    f"a positive distance")
        camera.distance = distance
    if view.lookat is not None:
        point = np.asarray(view.lookat, dtype=np.float64)
        if point.shape != (3,) or not np.all(np.isfinite(point)):
            raise InvalidValueError(f"render: FreeView lookat={view.lookat!r}: expected a "
                                    f"point (x, y, z)")
        camera.lookat[:] = point
    return camera


def _angle(name: str, value: object) -> float | None:
    """A FreeView number, checked (the dataclass does not check what it is given)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(
            float(value)):
        raise InvalidValueError(f"render: FreeView {name}={value!r}: expected a number")
    return float(value)


def _view(m: mujoco.MjModel, name: str) -> mujoco.MjvCamera:
    """A camera for one name of ``views=``: the model's camera of that name, else a preset."""
    import mujoco

    if mujoco.mj_name2id(m, int(mujoco.mjtObj.mjOBJ_CAMERA), name) >= 0:
        camera = mujoco.MjvCamera()
        camera.type = mujoco.mjtCamera.mjCAMERA_FIXED
        camera.fixedcamid = _camera_id(m, name)
        return camera
    if name not in VIEWS:
        cameras = _camera_names(m)
        raise InvalidValueError(f"render: view {name!r} is neither a preset "
                                f"({', '.join(VIEWS)}) nor a camera of the model"
                                f"{did_you_mean(name, [*VIEWS, *cameras])}; "
                                f"{_listed('cameras', cameras)}")
    camera = mujoco.MjvCamera()
    mujoco.mjv_defaultFreeCamera(m, camera)
    camera.azimuth, camera.elevation = VIEWS[name]
    return camera


def _listed(what: str, names: list[str]) -> str:
    if not names:
        return f"the model has no named {what}"
    shown = ", ".join(repr(n) for n in names[:10])
    return f"{what}: {shown}{', ...' if len(names) > 10 else ''}"


# ---------------------------------------------------------------------------- framing


def _bounds(m: mujoco.MjModel) -> tuple[NDArray[np.float64], float]:
    return np.array(m.stat.center, dtype=np.float64), float(m.stat.extent)


def _union(first: tuple[NDArray[np.float64], float],
           second: tuple[NDArray[np.float64], float]) -> tuple[NDArray[np.float64], float]:
    """The smallest sphere holding two spheres (centre, radius)."""
    (c1, r1), (c2, r2) = first, second
    gap = float(np.linalg.norm(c2 - c1))
    if r1 >= gap + r2:
        return c1, r1
    if r2 >= gap + r1:
        return c2, r2
    radius = (gap + r1 + r2) / 2
    return c1 + (c2 - c1) * ((radius - r1) / gap), radius


# ---------------------------------------------------------------------------- rendering


_LIGHTING_EFFECTS: Final = ("mjRND_SHADOW", "mjRND_REFLECTION", "mjRND_FOG", "mjRND_HAZE",
                             "mjRND_SKYBOX")


class _Offscreen:
    """MuJoCo's offscreen renderer for one compiled model: the calls ``mujoco.Renderer``
    makes, on a context of the chosen back end. The model's offscreen buffer is enlarged (on
    this compiled copy) when a picture needs more than ``<visual><global offwidth
    offheight>`` give."""

    def __init__(self, m: mujoco.MjModel, width: int, height: int,
                 limits: RenderLimits) -> None:
        import mujoco

        visual = m.vis.global_
        check_offscreen((width, height), (int(visual.offwidth), int(visual.offheight)), limits)
        visual.offwidth = max(int(visual.offwidth), width)
        visual.offheight = max(int(visual.offheight), height)
        self.m = m
        self.context = gl_context(visual.offwidth, visual.offheight)
        try:
            self.mjr = mujoco.MjrContext(m, int(mujoco.mjtFontScale.mjFONTSCALE_100))
            mujoco.mjr_setBuffer(int(mujoco.mjtFramebuffer.mjFB_OFFSCREEN), self.mjr)
        except Exception as error:  # noqa: BLE001 - MuJoCo's GL errors: say them once
            self.close()
            raise RenderError(f"cannot render: MuJoCo could not set up OpenGL rendering "
                              f"({visual.offwidth}x{visual.offheight} offscreen buffer): "
                              f"{' '.join(str(error).split())}") from None
        self.scene = mujoco.MjvScene(m, _MAX_GEOMS)
        self.options = mujoco.MjvOption()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def plain(self) -> None:
        """Draw from now on without the effects of lighting that reach beyond an object
        (shadows, reflections, fog, haze, the skybox)."""
        import mujoco

        for flag in _LIGHTING_EFFECTS:
            self.scene.flags[int(getattr(mujoco.mjtRndFlag, flag))] = False

    def shoot(self, data: mujoco.MjData, camera: mujoco.MjvCamera, width: int,
              height: int) -> Image:
        import mujoco

        self.context.make_current()
        mujoco.mjv_updateScene(self.m, data, self.options, None, camera,
                               int(mujoco.mjtCatBit.mjCAT_ALL), self.scene)
        viewport = mujoco.MjrRect(0, 0, width, height)
        mujoco.mjr_render(viewport, self.scene, self.mjr)
        pixels = np.empty((height, width, 3), dtype=np.uint8)
        mujoco.mjr_readPixels(pixels, None, viewport, self.mjr)
        return np.ascontiguousarray(pixels[::-1])  # OpenGL's rows go bottom to top

    def close(self) -> None:
        """Free MuJoCo's GL resources (the context is the thread's, kept for the next)."""
        mjr = getattr(self, "mjr", None)
        if mjr is not None:
            self.context.make_current()
            mjr.free()
            del self.mjr


# ---------------------------------------------------------------------------- layout


def _grid(count: int) -> tuple[int, int]:
    """Columns and rows for ``count`` tiles: one row up to three, then a square-ish grid."""
    columns = count if count <= 3 else math.ceil(math.sqrt(count))
    return columns, math.ceil(count / columns)


def _label_scale(tile_width: int) -> int:
    return 2 if tile_width >= 480 else 1


def _strip(scale: int) -> int:
    """The height of the label strip above each tile."""
    return (GLYPH_HEIGHT + 6) * scale


def _sheet(tiles: list[tuple[str, Image]], columns: int, width: int, height: int,
           scale: int) -> Image:
    """Tiles in a grid of ``columns``, each under a strip with its label."""
    sheet = np.empty((height, width, 3), dtype=np.uint8)
    sheet[:] = _BACKGROUND
    strip = _strip(scale)
    for i, (label, tile) in enumerate(tiles):
        tile_h, tile_w = tile.shape[:2]
        x, y = (i % columns) * tile_w, (i // columns) * (tile_h + strip)
        draw_text(sheet, _fitted(label, tile_w - 6 * scale, scale), x + 3 * scale,
                  y + 3 * scale, _INK, scale)
        sheet[y + strip : y + strip + tile_h, x : x + tile_w] = tile
    return sheet


def _fitted(label: str, width: int, scale: int) -> str:
    """``label``, shortened with ``...`` to fit ``width`` pixels."""
    if text_size(label, scale)[0] <= width:
        return label
    keep = max(width // ((GLYPH_WIDTH + 1) * scale) - 3, 0)  # a glyph and a gap each
    return label[:keep] + "..."
