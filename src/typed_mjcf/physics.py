"""``mjcf.Physics``: simulate a model, and bind its elements to MuJoCo's arrays.

dm_control's ``mjcf.Physics`` API (its names and signatures, written anew on ``mujoco``)::

    physics = mjcf.Physics.from_mjcf_model(model)     # compiled as model.compile() compiles
    physics.bind(shoulder).qpos                       # -> numpy array, typed per kind
    physics.bind(model.find_all("joint")).qpos += 0.1 # several elements of one kind
    physics.named.data.xpos["arm/hand", "z"]          # MuJoCo's arrays by names
    with physics.reset_context():
        physics.bind(shoulder).qpos = 0.5
    physics.step(10)
    pixels = physics.render(240, 320, camera_id="overhead")

``physics.model`` and ``physics.data`` are ``mujoco.MjModel`` and ``mujoco.MjData`` (of
subclasses that add what dm_control's wrappers have: ``ptr``, ``name2id``, ``id2name``,
``disable``). Elements are found in the compiled model by their scoped names; unnamed ones by
where they were compiled (:mod:`typed_mjcf._sim.ids`), when the physics was made from their
model.
"""

from __future__ import annotations

import contextlib
import os
import sys
import warnings
from collections.abc import Generator, Iterable, Mapping
from typing import TYPE_CHECKING, Final, Literal, NamedTuple, Self, TypeAlias, cast, overload

import mujoco
import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.behaviour import FLAGS
from typed_mjcf._core.errors import (
    BindingError,
    FileReadError,
    InvalidTypeError,
    InvalidValueError,
    MjcfError,
    PhysicsError,
    RenderError,
)
from typed_mjcf._core.tree import Element, ModelBase
from typed_mjcf._generated import bindings as _bindings
from typed_mjcf._generated.bindings import *  # the binding classes, one per kind
from typed_mjcf._generated.bindings import Bind, NamedData, NamedModel
from typed_mjcf._model.resource_limits import (
    DEFAULT_COMPILE_LIMITS,
    DEFAULT_RENDER_LIMITS,
    CompileLimits,
    RenderLimits,
    check_offscreen,
)
from typed_mjcf._sim.binding import (
    PICKLING_NOT_SUPPORTED,
    Binding,
    EmptyBinding,
    binding_tables,
    new_binding,
)
from typed_mjcf._sim.compile import compile_from_memory
from typed_mjcf._sim.gl import ensure_gl_backend, gl_error
from typed_mjcf._sim.ids import compile_for_physics, ids_for_text, kind_of, row_kind
from typed_mjcf._sim.model_state import model_state
from typed_mjcf._sim.name_table import name_ids
from typed_mjcf._sim.named import make_axes, struct_indexers
from typed_mjcf.types import Array, ArrayValues

if TYPE_CHECKING:
    from typed_mjcf._base import ModelRoot

__all__ = ["Binding", "Data", "Model", "Named", "Physics", "PhysicsError",
           "RenderError"]
__all__ += _bindings.__all__

_PICKLING_NOT_SUPPORTED: Final = PICKLING_NOT_SUPPORTED  # dm_control's name, its tests read it
# render_flag_overrides: MuJoCo's rendering flags by name ("shadow") or enum, and values
RenderFlags: TypeAlias = Mapping[str, bool] | Mapping[mujoco.mjtRndFlag, bool]
_INVALID_STATE: Final = "Physics state is invalid. Warning(s) raised: {}"


# dm_control's PhysicsError class -> ours deriving from it too (made once each)
_DM_CONTROL_ERRORS: Final[dict[type[BaseException], type[PhysicsError]]] = {}


def _physics_error_class() -> type[PhysicsError]:
    """:class:`PhysicsError`; under ``install_as_dm_control_mjcf()``, once dm_control's
    ``rl.control`` is imported, a subclass of it that is also dm_control's
    ``control.PhysicsError`` (composer catches that: a diverging episode ends, rather than
    the error escaping). dm_control is never imported here."""
    control = sys.modules.get("dm_control.rl.control") if FLAGS.dm_control_physics_error else None
    theirs: object = getattr(control, "PhysicsError", None)
    if not isinstance(theirs, type) or not issubclass(theirs, BaseException):
        return PhysicsError
    found = _DM_CONTROL_ERRORS.get(theirs)
    if found is None:
        found = _DM_CONTROL_ERRORS[theirs] = cast(type[PhysicsError], type(
            "PhysicsError", (PhysicsError, theirs),
            {"__module__": __name__, "__doc__": PhysicsError.__doc__}))
    return found


class Model(mujoco.MjModel):
    """A ``mujoco.MjModel`` with what dm_control's model wrapper adds."""

    @property
    def ptr(self) -> Model:
        """The model itself (dm_control code passes ``model.ptr`` to ``mujoco``)."""
        return self

    def name2id(self, name: str, object_type: str | int | mujoco.mjtObj) -> int:
        """The id of the object named ``name`` of ``object_type`` (``"geom"``,
        ``mujoco.mjtObj.mjOBJ_GEOM`` or its int value); ``InvalidValueError`` if none."""
        objtype = _objtype(object_type)
        _check_name(name)
        found = mujoco.mj_name2id(self, objtype, name)
        if found < 0:
            raise InvalidValueError(f"no {objtype.name[6:].lower()} named {name!r} in the "
                                    "compiled model")
        return found

    def id2name(self, object_id: int, object_type: str | int | mujoco.mjtObj) -> str:
        """The name of the object ``object_id`` of ``object_type`` (``""`` if unnamed)."""
        objtype = _objtype(object_type)
        if not 0 <= object_id < _count(self, objtype):
            raise InvalidValueError(f"no {objtype.name[6:].lower()} {object_id} in the model")
        return mujoco.mj_id2name(self, objtype, object_id) or ""

    @contextlib.contextmanager
    def disable(self, *flags: str | mujoco.mjtDisableBit) -> Generator[None, None, None]:
        """Disable MuJoCo's ``flags`` (``"actuation"``, ``"contact"``, ...) in the block."""
        saved = self.opt.disableflags
        for flag in flags:
            bit = flag if isinstance(flag, mujoco.mjtDisableBit) else _disable_bit(flag)
            self.opt.disableflags |= int(bit)
        try:
            yield
        finally:
            self.opt.disableflags = saved


class Data(mujoco.MjData):
    """A ``mujoco.MjData`` with dm_control's ``ptr``."""

    @property
    def ptr(self) -> Data:
        """The data itself (dm_control code passes ``data.ptr`` to ``mujoco``)."""
        return self


def _check_name(name: object) -> None:
    if not isinstance(name, str):  # (MuJoCo's mj_name2id crashes on None)
        raise InvalidValueError(f"name2id: a name is a string, got {name!r}")


def _objtype(object_type: str | int | mujoco.mjtObj) -> mujoco.mjtObj:
    if isinstance(object_type, mujoco.mjtObj):
        return object_type
    if isinstance(object_type, int):  # dm_control's enums are plain ints
        try:
            return mujoco.mjtObj(object_type)
        except ValueError:
            raise InvalidValueError(f"{object_type!r} is not a kind of MuJoCo object (an "
                                    f"mjtObj value)") from None
    name = f"mjOBJ_{object_type.upper()}"
    members = mujoco.mjtObj.__members__
    if name not in members:
        kinds = sorted(m[6:].lower() for m in members if m.startswith("mjOBJ_"))
        raise InvalidValueError(f"{object_type!r} is not a kind of MuJoCo object; kinds: "
                                f"{', '.join(kinds)}")
    return members[name]


def _count(model: mujoco.MjModel, objtype: mujoco.mjtObj) -> int:
    for size, name in binding_tables().objects.items():
        if name == objtype.name:
            return int(getattr(model, size))
    return 0


def _disable_bit(flag: str) -> mujoco.mjtDisableBit:
    name = f"mjDSBL_{flag.upper()}"
    members = mujoco.mjtDisableBit.__members__
    if name not in members:
        raise InvalidValueError(f"{flag!r} is not one of MuJoCo's disable flags: "
                                f"{', '.join(m[6:].lower() for m in members)}")
    return members[name]


def _render_flag(flag: str | mujoco.mjtRndFlag) -> mujoco.mjtRndFlag:
    if isinstance(flag, mujoco.mjtRndFlag):
        return flag
    name = f"mjRND_{flag.upper()}"
    members = mujoco.mjtRndFlag.__members__
    if name not in members:
        flags = ", ".join(m[6:].lower() for m in members if m.startswith("mjRND_"))
        raise InvalidValueError(f"{flag!r} is not one of MuJoCo's rendering flags: {flags}")
    return members[name]


def _as_model(model: mujoco.MjModel) -> Model:
    """``model`` as a :class:`Model` (its contents copied once)."""
    return model if isinstance(model, Model) else _copy_model(model)


def _copy_model(model: mujoco.MjModel) -> Model:
    out = Model.__new__(Model)
    out.__setstate__(model_state(model))
    return out


class Named(NamedTuple):
    """``physics.named``: MjModel's and MjData's arrays indexed by names."""

    model: NamedModel
    data: NamedData


class Physics(Bind):
    """A MuJoCo simulation of a model, with its elements bound to MuJoCo's arrays."""

    legacy_step: bool = True  # step as dm_control does: positions stay in step with qpos

    _data: Data
    _named: Named | None  # made on first use of .named (a tenth of a model's load)
    _dirty: bool
    _source: ModelBase | None
    _unnamed: Mapping[int, tuple[Element, tuple[int, ...]]]
    _text: tuple[str, Mapping[str, bytes]] | None  # the MJCF text (and files) compiled
    _text_ids: dict[int, Mapping[int, tuple[Element, tuple[int, ...]]] | None]
    _bindings: dict[object, Binding]
    _renderers: dict[tuple[int, int], mujoco.Renderer]
    _warnings_cause_exception: bool

    def __init__(self, data: mujoco.MjData) -> None:
        """A physics of ``data`` (its model is ``data.model``). The named constructors are
        the usual way: :meth:`from_mjcf_model`, :meth:`from_xml_string`, ..."""
        self._warnings_cause_exception = True
        self._source = None
        self._unnamed = {}
        self._renderers = {}
        self._reload_from_data(data)

    # ------------------------------------------------------------------ constructors

    @classmethod
    def from_model(cls, model: mujoco.MjModel) -> Self:
        """A physics of a compiled ``model``."""
        return cls(Data(_as_model(model)))

    @classmethod
    def from_xml_string(cls, xml_string: str, assets: Mapping[str, bytes] | None = None,
                        ) -> Self:
        """A physics of MJCF text (``assets``: files it reads, by name). Elements of the
        model the text was written from (``model.to_xml_string()``) can be bound."""
        physics = cls.from_model(_load(xml_string, assets))
        physics._text = (xml_string, dict(assets or {}))
        return physics

    @classmethod
    def from_xml_path(cls, file_path: str | os.PathLike[str]) -> Self:
        """A physics of an MJCF file."""
        return cls.from_model(_load_path(file_path))

    @classmethod
    def from_byte_string(cls, byte_string: bytes) -> Self:
        """A physics of a model binary (MJB) held in memory."""
        return cls.from_model(_as_model(_load_binary(byte_string)))

    @classmethod
    def from_binary_path(cls, file_path: str | os.PathLike[str]) -> Self:
        """A physics of a model binary (MJB) file."""
        path = _path(file_path)
        try:
            with open(path, "rb") as stream:
                contents = stream.read()
        except OSError as error:
            raise FileReadError(f"cannot read the file: {error.strerror or error}",
                                path) from None
        return cls.from_byte_string(contents)

    @classmethod
    def from_mjcf_model(cls, mjcf_model: ModelRoot, *,
                        limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Self:
        """A physics of ``mjcf_model``, compiled as ``mjcf_model.compile(limits)`` compiles
        it; every element of it can be bound, named or not."""
        physics = cls.__new__(cls)
        physics._warnings_cause_exception = True
        physics._renderers = {}
        physics._load_mjcf(mjcf_model, limits)
        return physics

    def reload_from_mjcf_model(self, mjcf_model: ModelRoot, *,
                               limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> None:
        """Compile ``mjcf_model`` again into this physics (its state is reset)."""
        self._load_mjcf(mjcf_model, limits)

    def reload_from_xml_string(self, xml_string: str,
                               assets: Mapping[str, bytes] | None = None) -> None:
        """Load MJCF text into this physics (its state is reset)."""
        self._source, self._unnamed = None, {}
        self._reload_from_data(Data(_load(xml_string, assets)))
        self._text = (xml_string, dict(assets or {}))

    def reload_from_xml_path(self, file_path: str | os.PathLike[str]) -> None:
        """Load an MJCF file into this physics (its state is reset)."""
        self._source, self._unnamed = None, {}
        self._reload_from_data(Data(_load_path(file_path)))

    def _load_mjcf(self, mjcf_model: ModelRoot, limits: CompileLimits) -> None:
        if not isinstance(cast(object, mjcf_model), ModelBase):
            raise InvalidTypeError(f"mjcf_model must be a model (a typed_mjcf.RootElement), "
                                   f"got {type(mjcf_model).__name__}")
        try:
            compiled = compile_for_physics(mjcf_model, limits)
        except ValueError as error:
            if not FLAGS.compile_error_advice:
                raise
            # dm_control's debug mode: where the elements named were made and set
            raise _tree.COMPAT.explained(error, mjcf_model) from None
        self._source = mjcf_model
        self._unnamed = compiled.unnamed
        self._reload_from_data(Data(_as_model(compiled.model)))

    def _reload_from_data(self, data: mujoco.MjData) -> None:
        if not isinstance(data, Data):
            model = _as_model(data.model)
            fresh = Data(model)
            mujoco.mj_copyData(fresh, model, data)
            data = fresh
        self._data = data
        self._text, self._text_ids = None, {}
        self._free_renderers()
        self._bindings = {(): new_binding(EmptyBinding, self, "", np.zeros(0, np.intp), False,
                                          "no elements")}
        self._dirty = False
        try:
            self.after_reset()
        except PhysicsError as error:
            warnings.warn(str(error), RuntimeWarning, stacklevel=3)
        self._named = None

    # ------------------------------------------------------------------ model and data

    @property
    def model(self) -> Model:
        """The compiled model (a ``mujoco.MjModel``)."""
        return cast(Model, self._data.model)

    @property
    def data(self) -> Data:
        """The simulation state (a ``mujoco.MjData``)."""
        return self._data

    @property
    def named(self) -> Named:
        """MuJoCo's arrays indexed by names: ``physics.named.data.qpos["arm/elbow"]``."""
        if self._named is None:
            axes = make_axes(self.model)
            model_indexers, data_indexers = struct_indexers(self.model, self._data, axes)
            self._named = Named(model=NamedModel(model_indexers),
                                data=NamedData(data_indexers))
        return self._named

    # ------------------------------------------------------------------ simulating

    def step(self, nstep: int = 1) -> None:
        """Advance the simulation ``nstep`` timesteps (controls as ``set_control`` set)."""
        with self.check_invalid_state():
            model, data = self.model, self._data
            if not self.legacy_step:
                mujoco.mj_step(model, data, nstep)
            elif model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4:
                mujoco.mj_step(model, data, nstep)
                mujoco.mj_step1(model, data)
            else:
                # dm_control's order: finish the step mj_step1 began, then begin the next, so
                # positions and velocities derived from qpos/qvel stay current after a step
                mujoco.mj_step2(model, data)
                if nstep > 1:
                    mujoco.mj_step(model, data, nstep - 1)
                mujoco.mj_step1(model, data)

    def forward(self) -> None:
        """Recompute the derived quantities (positions, sensors...) without advancing."""
        with self.check_invalid_state():
            mujoco.mj_forward(self.model, self._data)
        self._dirty = False

    def reset(self, keyframe_id: int | None = None) -> None:
        """Reset the state to the model's initial one, or to keyframe ``keyframe_id``."""
        if keyframe_id is None:
            mujoco.mj_resetData(self.model, self._data)
        else:
            if not 0 <= keyframe_id < self.model.nkey:
                raise InvalidValueError(f"keyframe_id must be between 0 and "
                                        f"{self.model.nkey - 1} inclusive, got {keyframe_id}")
            mujoco.mj_resetDataKeyframe(self.model, self._data, keyframe_id)
        with self.model.disable("actuation"):  # no meaningful controls yet
            self.forward()

    def after_reset(self) -> None:
        """Bring the derived quantities in step with a state just set (actuation off)."""
        with self.model.disable("actuation"):
            self.forward()

    @contextlib.contextmanager
    def reset_context(self) -> Generator[Self, None, None]:
        """Reset on entry; set the state in the block; ``after_reset`` on exit."""
        try:
            self.reset()
        except PhysicsError:
            pass
        yield self
        self.after_reset()

    @contextlib.contextmanager
    def check_invalid_state(self) -> Generator[None, None, None]:
        """Raise :class:`PhysicsError` if MuJoCo raises a warning in the block (only warn,
        inside :meth:`suppress_physics_errors`)."""
        before = np.array(self._data.warning.number, copy=True)
        yield
        after = np.asarray(self._data.warning.number)
        raised = [name for name, new in zip(mujoco.mjtWarning.__members__, after > before,
                                            strict=False) if new]
        if raised:
            message = _INVALID_STATE.format(", ".join(raised))
            if self._warnings_cause_exception:
                raise _physics_error_class()(message)
            warnings.warn(message, RuntimeWarning, stacklevel=3)

    @contextlib.contextmanager
    def suppress_physics_errors(self) -> Generator[None, None, None]:
        """MuJoCo's warnings are warned, not raised, in the block."""
        saved = self._warnings_cause_exception
        self._warnings_cause_exception = False
        try:
            yield
        finally:
            self._warnings_cause_exception = saved

    def check_divergence(self) -> None:
        """dm_control's hook: nothing to check beyond :meth:`check_invalid_state`."""

    @property
    def is_dirty(self) -> bool:
        """Whether inputs were written since the derived quantities were computed."""
        return self._dirty

    def mark_as_dirty(self) -> None:
        """Say the derived quantities are stale (the next read of one recomputes them)."""
        self._dirty = True

    # ------------------------------------------------------------------ state

    def timestep(self) -> float:
        """The simulation timestep, in seconds."""
        return float(self.model.opt.timestep)

    def time(self) -> float:
        """The simulated time, in seconds."""
        return float(self._data.time)

    def control(self) -> Array[np.float64]:
        """A copy of the controls."""
        return np.array(self._data.ctrl, copy=True)

    def set_control(self, control: ArrayValues) -> None:
        """Set the controls for the next steps."""
        np.copyto(self._data.ctrl, np.asarray(control, dtype=np.float64))

    def position(self) -> Array[np.float64]:
        """A copy of the generalized positions (``qpos``)."""
        return np.array(self._data.qpos, copy=True)

    def velocity(self) -> Array[np.float64]:
        """A copy of the generalized velocities (``qvel``)."""
        return np.array(self._data.qvel, copy=True)

    def activation(self) -> Array[np.float64]:
        """A copy of the actuators' activations (``act``)."""
        return np.array(self._data.act, copy=True)

    def _state_items(self) -> list[Array[np.float64]]:
        items = [self._data.qpos, self._data.qvel, self._data.act]
        if self.model.nplugin:
            items.append(self._data.plugin_state)
        return items

    def state(self) -> Array[np.float64]:
        """The state: qpos, qvel, act (and the plugins' state), concatenated."""
        return np.concatenate(self._state_items())

    def get_state(self, sig: int | None = None) -> Array[np.float64]:
        """:meth:`state`, or MuJoCo's ``mj_getState`` of the state elements ``sig``."""
        if sig is None:
            return self.state()
        out = np.empty(mujoco.mj_stateSize(self.model, sig), np.float64)
        mujoco.mj_getState(self.model, self._data, out, sig)
        return out

    def set_state(self, physics_state: ArrayValues, sig: int | None = None) -> None:
        """Set what :meth:`get_state` gives."""
        values = np.asarray(physics_state, dtype=np.float64)
        if sig is not None:
            mujoco.mj_setState(self.model, self._data, values, sig)
            return
        items = self._state_items()
        expected = sum(item.size for item in items)
        if values.shape != (expected,):
            raise InvalidValueError(f"a physics state has shape ({expected},), got "
                                    f"{values.shape}")
        start = 0
        for item in items:
            np.copyto(item, values[start:start + item.size])
            start += item.size

    def copy(self, share_model: bool = False) -> Self:
        """An independent copy of this physics (sharing the compiled model with
        ``share_model=True``); bindings are made anew on it."""
        model = self.model if share_model else _copy_model(self.model)
        data = Data(model)
        mujoco.mj_copyData(data, model, self._data)
        new = type(self).__new__(type(self))
        new._warnings_cause_exception = True
        new._renderers = {}
        new._source, new._unnamed = self._source, self._unnamed
        new._reload_from_data(data)
        new._text = self._text
        return new

    def free(self) -> None:
        """Free the renderers (OpenGL contexts) this physics holds."""
        self._free_renderers()

    # ------------------------------------------------------------------ rendering

    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[False] = False, segmentation: Literal[False] = False,
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.uint8]: ...
    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[True], segmentation: Literal[False] = False,
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.float32]: ...
    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[False] = False, segmentation: Literal[True],
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.int32]: ...

    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: bool = False, segmentation: bool = False,
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS,
               ) -> Array[np.uint8] | Array[np.float32] | Array[np.int32]:
        """An image of the scene from camera ``camera_id`` (a name or an id; -1: the free
        camera): height x width x 3 ``uint8`` RGB; with ``depth``, height x width
        ``float32`` distances in metres; with ``segmentation``, height x width x 2 ``int32``
        (object id, ``mjtObj`` type; -1, -1 for the background). ``render_flag_overrides``:
        MuJoCo's rendering flags to set for this image (``{"shadow": False}``; RGB only).
        Uses the OpenGL back end ``MUJOCO_GL`` chooses (``egl`` renders without a
        display). The size is ``height, width``, in that order, as in dm_control, whose code
        calls it positionally; typed-mjcf's own ``model.render`` takes ``width=``/``height=``
        by keyword. ``limits.max_offscreen_pixels`` bounds the offscreen buffer a new size
        allocates (the model's ``offwidth`` x ``offheight``)."""
        if depth and segmentation:
            raise InvalidValueError("render: depth and segmentation cannot both be True")
        if render_flag_overrides and (depth or segmentation):
            raise InvalidValueError("render: render_flag_overrides are not supported for "
                                    "depth or segmentation rendering")
        flags = [(_render_flag(flag), bool(value))
                 for flag, value in (render_flag_overrides or {}).items()]
        camera = self._camera(camera_id)
        renderer = self._renderer(height, width, limits)
        if self._dirty:
            self.forward()
        saved: list[tuple[mujoco.mjtRndFlag, bool]] = []
        if depth:
            renderer.enable_depth_rendering()
        elif segmentation:
            renderer.enable_segmentation_rendering()
        try:
            renderer.update_scene(self._data, camera, scene_option)
            for flag, value in flags:  # the renderer's scene is reused: restored below
                saved.append((flag, bool(renderer.scene.flags[flag])))
                renderer.scene.flags[flag] = value
            pixels: Array[np.uint8] | Array[np.float32] | Array[np.int32] = renderer.render()
            return pixels
        finally:
            for flag, value in reversed(saved):
                renderer.scene.flags[flag] = value
            renderer.disable_depth_rendering()
            renderer.disable_segmentation_rendering()

    def _camera(self, camera_id: int | str) -> int:
        if isinstance(camera_id, str):
            return self.model.name2id(camera_id, mujoco.mjtObj.mjOBJ_CAMERA)
        if not -1 <= camera_id < self.model.ncam:
            raise InvalidValueError(f"camera_id={camera_id}: the model has {self.model.ncam} "
                                    f"cameras (-1 is the free camera)")
        return camera_id

    def _renderer(self, height: int, width: int, limits: RenderLimits) -> mujoco.Renderer:
        found = self._renderers.get((height, width))
        if found is not None:
            return found
        offwidth, offheight = self.model.vis.global_.offwidth, self.model.vis.global_.offheight
        check_offscreen((width, height), (int(offwidth), int(offheight)), limits)
        ensure_gl_backend()
        if width > offwidth or height > offheight:
            raise InvalidValueError(
                f"render: {width}x{height} is larger than the model's offscreen buffer "
                f"({offwidth}x{offheight}); set <visual><global offwidth=... offheight=.../>")
        # GLFW reports why it failed as warnings before the error (no display): they belong
        # in the one error, not printed ahead of it; on success they are passed on as they came
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                renderer = mujoco.Renderer(self.model, height, width)
            except Exception as error:  # noqa: BLE001  # OpenGL fails in many ways: one error
                raise gl_error(error, [str(w.message) for w in caught]) from None
        for warning in caught:
            warnings.warn_explicit(warning.message, warning.category, warning.filename,
                                   warning.lineno)
        self._renderers[(height, width)] = renderer
        return renderer

    @property
    def contexts(self) -> None:
        """dm_control's rendering contexts: None here, where a renderer is made per image size
        when first used. Reading it frees the renderers, so the next image uploads the model
        as it is then: dm_control's code reads it to upload a height field (or texture, mesh)
        it changed (``if physics.contexts: ... mjr_uploadHField``)."""
        self._free_renderers()

    def _free_renderers(self) -> None:
        for renderer in getattr(self, "_renderers", {}).values():
            renderer.close()
        self._renderers = {}

    # ------------------------------------------------------------------ binding

    if not TYPE_CHECKING:  # typed per kind of element by Bind (bindings.pyi)

        def bind(self, mjcf_elements):
            """The binding of an element, or of a sequence of elements of one kind, to this
            physics: ``physics.bind(joint).qpos``. Bindings are cached."""
            return self._bind(mjcf_elements)

    def _bind(self, mjcf_elements: Element | Iterable[Element] | None) -> Binding:
        if mjcf_elements is None:
            raise BindingError("mjcf_elements is None.")
        if not isinstance(cast(object, mjcf_elements), Element | Iterable):
            raise BindingError(f"cannot bind {mjcf_elements!r}: bind takes an MJCF element "
                               f"or a sequence of them")
        if isinstance(mjcf_elements, Element):
            elements: list[Element] = [mjcf_elements]
            key: object = mjcf_elements
        else:
            elements = list(mjcf_elements)
            key = tuple(elements)
        try:
            return self._bindings[key]
        except KeyError:
            pass
        except TypeError:  # unhashable: not cached
            key = None
        single = isinstance(mjcf_elements, Element)
        if not elements:
            return self._bindings[()]
        kind = self._kind_of_all(elements)
        ids = self._ids_of(elements, kind)
        label = elements[0].path if single else f"{len(elements)} <{kind}> elements"
        binding = new_binding(binding_tables().kinds[kind].binding, self, kind, ids,
                              single, label)
        if key is not None:
            self._bindings[key] = binding
        return binding

    def _kind_of_all(self, elements: list[Element]) -> str:
        """The one kind of ``elements`` (found once per row: the kind of an element whose
        row has a namespace is that namespace's)."""
        # one class per row: elements of rows with one namespace MuJoCo binds are of that
        # kind (the world body, errors and mixed kinds: element by element, below)
        kinds = {row_kind(cls) for cls in set(map(type, elements))}
        kind = kinds.pop() if len(kinds) == 1 else None
        if kind is not None:
            return kind
        first: str | None = None
        for element in elements:
            kind = self._kind(element)
            if first is None:
                first = kind
            elif kind != first:
                for other in elements:  # an element that cannot be bound is named first
                    self._kind(other)
                raise BindingError(f"Cannot bind to a collection containing multiple element "
                                   f"types ({first!r} != {kind!r}).")
        assert first is not None  # elements is not empty
        return first

    def _kind(self, element: object) -> str:
        if not isinstance(element, Element):
            raise BindingError(f"cannot bind {element!r}: bind takes MJCF elements")
        kind = kind_of(element)
        if kind is None:
            raise BindingError(f"{element.path}: elements of type <{element.spec.tag}> cannot "
                               f"be bound to physics (MuJoCo compiles them into no object "
                               f"it indexes)")
        return kind

    def _ids_of(self, elements: list[Element], kind: str) -> Array[np.intp]:
        """The compiled ids of ``elements`` (of ``kind``), in order (a replicated element:
        one per copy)."""
        model, unnamed = self.model, self._unnamed
        compiled = binding_tables().kinds[kind]
        objtype = getattr(mujoco.mjtObj, compiled.objtype)
        name2id = mujoco.mj_name2id
        # a batch of more than an eighth of the kind: every name read at once is cheaper
        table = (name_ids(model, compiled.size)
                 if len(elements) * 8 >= int(getattr(model, compiled.size)) else None)
        owns = _tree.own_scoped_names(elements)
        if table is not None and unnamed.keys().isdisjoint(map(id, elements)):
            # every element found by its own name at once (no name: "", which none has);
            # any other case, element by element below
            numbers = [table.get(own or "", -1) for own in owns]
            if min(numbers) >= 0:
                return np.asarray(numbers, dtype=np.intp)
        prefixes: dict[int, str] = {}  # each name scope's prefix, computed once
        out: list[int] = []
        for element, own in zip(elements, owns, strict=True):
            if own is not None and id(element) not in unnamed:  # the common case, at once
                found = name2id(model, objtype, own) if table is None else table.get(own, -1)
                if found >= 0:
                    out.append(found)
                    continue
            if element.is_removed:
                raise BindingError(f"{element.path}: the element was removed from its model, "
                                   f"so it cannot be bound (bind the elements of the model as "
                                   f"it is)")
            entry = unnamed.get(id(element))
            if entry is not None and entry[0] is element:
                if not entry[1]:
                    raise BindingError(f"{element.path}: MuJoCo's compiler made no <{kind}> "
                                       f"of it")
                out += entry[1]
                continue
            name = _scoped_name(element, prefixes)
            if name is None and self._text is not None:
                entry = self._from_text(element)
                if entry is not None and entry[1]:
                    out += entry[1]
                    continue
            if name is None:
                raise BindingError(self._unbound(element, "it has no name, and "))
            found = name2id(model, objtype, name) if table is None else table.get(name, -1)
            if found < 0:
                raise BindingError(self._unbound(element, f"the compiled model has no {kind} "
                                                          f"named {name!r}: "))
            out.append(found)
        return np.asarray(out, dtype=np.intp)

    def _from_text(self, element: Element) -> tuple[Element, tuple[int, ...]] | None:
        """An unnamed element of a physics made from text: found if the text is its model's
        ``to_xml_string()``."""
        assert self._text is not None
        root = _tree.scope_model(_tree.scope_of(element).outermost())
        if id(root) not in self._text_ids:
            self._text_ids[id(root)] = ids_for_text(root, *self._text)
        found = self._text_ids[id(root)]
        return None if found is None else found.get(id(element))

    def _unbound(self, element: Element, why: str) -> str:
        source = self._source
        if source is not None and _tree.scope_of(element).outermost() is _tree.scope_of(
                source).outermost():
            return (f"{element.path}: not in the model as this physics compiled it ({why}"
                    f"was it added after?); reload_from_mjcf_model(model) compiles it again")
        return (f"{element.path}: cannot be bound to this physics ({why}an unnamed element "
                f"is found only by a physics made from its model: Physics.from_mjcf_model, "
                f"or from_xml_string(model.to_xml_string()))")

    # ------------------------------------------------------------------ pickling

    def __getstate__(self) -> Data:
        return self._data

    def __setstate__(self, data: Data) -> None:
        self._warnings_cause_exception = True
        self._renderers = {}
        self._source, self._unnamed = None, {}
        self._reload_from_data(data)

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self._free_renderers()


def _scoped_name(element: Element, prefixes: dict[int, str]) -> str | None:
    """``element.full_identifier``, the prefix of each scope computed once for a batch."""
    own = _tree.element_name(element)
    if own is None or _tree.attached_at(element) is not None:
        name = getattr(element, "full_identifier", None)  # the world body, frames
        return name if isinstance(name, str) else None
    scope = _tree.scope_of(element)
    prefix = prefixes.get(id(scope))
    if prefix is None:
        prefix = prefixes[id(scope)] = scope.prefix()
    return prefix + own


def _path(file_path: object) -> str:
    if not isinstance(file_path, str | os.PathLike):
        raise InvalidTypeError(f"file_path must be a path (str or os.PathLike[str]), got "
                               f"{type(file_path).__name__}")
    return os.fspath(cast("str | os.PathLike[str]", file_path))


def _load(xml_string: str, assets: Mapping[str, bytes] | None) -> Model:
    if not isinstance(cast(object, xml_string), str):
        raise InvalidTypeError(f"xml_string must be a str, got {type(xml_string).__name__}")
    if assets is not None and not isinstance(cast(object, assets), Mapping):
        raise InvalidTypeError(f"assets must be a mapping of names to bytes, got "
                               f"{type(assets).__name__}")
    try:
        return _as_model(compile_from_memory(xml_string, assets or {}))
    except ValueError as error:
        raise MjcfError(f"MuJoCo could not compile the model: {str(error).strip()}") from None


def _load_path(file_path: str | os.PathLike[str]) -> Model:
    path = _path(file_path)
    try:
        return _as_model(mujoco.MjModel.from_xml_path(path))
    except ValueError as error:
        raise MjcfError(f"MuJoCo could not compile {os.fspath(file_path)}: "
                        f"{str(error).strip()}") from None


def _load_binary(byte_string: bytes) -> mujoco.MjModel:
    model = Model.__new__(Model)
    model.__setstate__(byte_string)
    return model
