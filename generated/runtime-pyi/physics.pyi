# Generated from src/typed_mjcf/physics.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
from collections.abc import Generator, Iterable, Mapping
from typing import TYPE_CHECKING, Final, Literal, NamedTuple, Self, TypeAlias, cast, overload
import mujoco
import numpy as np
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
from typed_mjcf._generated.bindings import *
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
from typed_mjcf.types import Array, ArrayValues
from typed_mjcf._base import ModelRoot
__all__ = ["Binding", "Data", "Model", "Named", "Physics", "PhysicsError",
           "RenderError"]
__all__ += _bindings.__all__
RenderFlags: TypeAlias = Mapping[str, bool] | Mapping[mujoco.mjtRndFlag, bool]

class Model(mujoco.MjModel):
    """A ``mujoco.MjModel`` with what dm_control's model wrapper adds."""
    @property
    def ptr(self) -> Model:
        """The model itself (dm_control code passes ``model.ptr`` to ``mujoco``)."""
        ...
    def name2id(self, name: str, object_type: str | int | mujoco.mjtObj) -> int:
        """The id of the object named ``name`` of ``object_type`` (``"geom"``,
        ``mujoco.mjtObj.mjOBJ_GEOM`` or its int value); ``InvalidValueError`` if none."""
        ...
    def id2name(self, object_id: int, object_type: str | int | mujoco.mjtObj) -> str:
        """The name of the object ``object_id`` of ``object_type`` (``""`` if unnamed)."""
        ...
    @contextlib.contextmanager
    def disable(self, *flags: str | mujoco.mjtDisableBit) -> Generator[None, None, None]:
        """Disable MuJoCo's ``flags`` (``"actuation"``, ``"contact"``, ...) in the block."""
        ...

class Data(mujoco.MjData):
    """A ``mujoco.MjData`` with dm_control's ``ptr``."""
    @property
    def ptr(self) -> Data:
        """The data itself (dm_control code passes ``data.ptr`` to ``mujoco``)."""
        ...

def _count(model: mujoco.MjModel, objtype: mujoco.mjtObj) -> int: ...

class Named(NamedTuple):
    """``physics.named``: MjModel's and MjData's arrays indexed by names."""
    model: NamedModel
    data: NamedData

class Physics(Bind):
    """A MuJoCo simulation of a model, with its elements bound to MuJoCo's arrays."""
    legacy_step: bool = True
    _data: Data
    _named: Named | None
    _dirty: bool
    _source: ModelBase | None
    _unnamed: Mapping[int, tuple[Element, tuple[int, ...]]]
    _text: tuple[str, Mapping[str, bytes]] | None
    _text_ids: dict[int, Mapping[int, tuple[Element, tuple[int, ...]]] | None]
    _bindings: dict[object, Binding]
    _renderers: dict[tuple[int, int], mujoco.Renderer]
    _warnings_cause_exception: bool
    def __init__(self, data: mujoco.MjData) -> None:
        """A physics of ``data`` (its model is ``data.model``). The named constructors are
        the usual way: :meth:`from_mjcf_model`, :meth:`from_xml_string`, ..."""
        ...
    @classmethod
    def from_model(cls, model: mujoco.MjModel) -> Self:
        """A physics of a compiled ``model``."""
        ...
    @classmethod
    def from_xml_string(cls, xml_string: str, assets: Mapping[str, bytes] | None = None,
                        ) -> Self:
        """A physics of MJCF text (``assets``: files it reads, by name). Elements of the
        model the text was written from (``model.to_xml_string()``) can be bound."""
        ...
    @classmethod
    def from_xml_path(cls, file_path: str | os.PathLike[str]) -> Self:
        """A physics of an MJCF file."""
        ...
    @classmethod
    def from_byte_string(cls, byte_string: bytes) -> Self:
        """A physics of a model binary (MJB) held in memory."""
        ...
    @classmethod
    def from_binary_path(cls, file_path: str | os.PathLike[str]) -> Self:
        """A physics of a model binary (MJB) file."""
        ...
    @classmethod
    def from_mjcf_model(cls, mjcf_model: ModelRoot, *,
                        limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> Self:
        """A physics of ``mjcf_model``, compiled as ``mjcf_model.compile(limits)`` compiles
        it; every element of it can be bound, named or not."""
        ...
    def reload_from_mjcf_model(self, mjcf_model: ModelRoot, *,
                               limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> None:
        """Compile ``mjcf_model`` again into this physics (its state is reset)."""
        ...
    def reload_from_xml_string(self, xml_string: str,
                               assets: Mapping[str, bytes] | None = None) -> None:
        """Load MJCF text into this physics (its state is reset)."""
        ...
    def reload_from_xml_path(self, file_path: str | os.PathLike[str]) -> None:
        """Load an MJCF file into this physics (its state is reset)."""
        ...
    @property
    def model(self) -> Model:
        """The compiled model (a ``mujoco.MjModel``)."""
        ...
    @property
    def data(self) -> Data:
        """The simulation state (a ``mujoco.MjData``)."""
        ...
    @property
    def named(self) -> Named:
        """MuJoCo's arrays indexed by names: ``physics.named.data.qpos["arm/elbow"]``."""
        ...
    def step(self, nstep: int = 1) -> None:
        """Advance the simulation ``nstep`` timesteps (controls as ``set_control`` set)."""
        ...
    def forward(self) -> None:
        """Recompute the derived quantities (positions, sensors...) without advancing."""
        ...
    def reset(self, keyframe_id: int | None = None) -> None:
        """Reset the state to the model's initial one, or to keyframe ``keyframe_id``."""
        ...
    def after_reset(self) -> None:
        """Bring the derived quantities in step with a state just set (actuation off)."""
        ...
    @contextlib.contextmanager
    def reset_context(self) -> Generator[Self, None, None]:
        """Reset on entry; set the state in the block; ``after_reset`` on exit."""
        ...
    @contextlib.contextmanager
    def check_invalid_state(self) -> Generator[None, None, None]:
        """Raise :class:`PhysicsError` if MuJoCo raises a warning in the block (only warn,
        inside :meth:`suppress_physics_errors`)."""
        ...
    @contextlib.contextmanager
    def suppress_physics_errors(self) -> Generator[None, None, None]:
        """MuJoCo's warnings are warned, not raised, in the block."""
        ...
    def check_divergence(self) -> None:
        """dm_control's hook: nothing to check beyond :meth:`check_invalid_state`."""
        ...
    @property
    def is_dirty(self) -> bool:
        """Whether inputs were written since the derived quantities were computed."""
        ...
    def mark_as_dirty(self) -> None:
        """Say the derived quantities are stale (the next read of one recomputes them)."""
        ...
    def timestep(self) -> float:
        """The simulation timestep, in seconds."""
        ...
    def time(self) -> float:
        """The simulated time, in seconds."""
        ...
    def control(self) -> Array[np.float64]:
        """A copy of the controls."""
        ...
    def set_control(self, control: ArrayValues) -> None:
        """Set the controls for the next steps."""
        ...
    def position(self) -> Array[np.float64]:
        """A copy of the generalized positions (``qpos``)."""
        ...
    def velocity(self) -> Array[np.float64]:
        """A copy of the generalized velocities (``qvel``)."""
        ...
    def activation(self) -> Array[np.float64]:
        """A copy of the actuators' activations (``act``)."""
        ...
    def state(self) -> Array[np.float64]:
        """The state: qpos, qvel, act (and the plugins' state), concatenated."""
        ...
    def get_state(self, sig: int | None = None) -> Array[np.float64]:
        """:meth:`state`, or MuJoCo's ``mj_getState`` of the state elements ``sig``."""
        ...
    def set_state(self, physics_state: ArrayValues, sig: int | None = None) -> None:
        """Set what :meth:`get_state` gives."""
        ...
    def copy(self, share_model: bool = False) -> Self:
        """An independent copy of this physics (sharing the compiled model with
        ``share_model=True``); bindings are made anew on it."""
        ...
    def free(self) -> None:
        """Free the renderers (OpenGL contexts) this physics holds."""
        ...
    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[False] = False, segmentation: Literal[False] = False,
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.uint8]:
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
        ...
    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[True], segmentation: Literal[False] = False,
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.float32]:
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
        ...
    @overload
    def render(self, height: int = 240, width: int = 320, camera_id: int | str = -1, *,
               depth: Literal[False] = False, segmentation: Literal[True],
               scene_option: mujoco.MjvOption | None = None,
               render_flag_overrides: RenderFlags | None = None,
               limits: RenderLimits = DEFAULT_RENDER_LIMITS) -> Array[np.int32]:
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
        ...
    @property
    def contexts(self) -> None:
        """dm_control's rendering contexts: None here, where a renderer is made per image size
        when first used. Reading it frees the renderers, so the next image uploads the model
        as it is then: dm_control's code reads it to upload a height field (or texture, mesh)
        it changed (``if physics.contexts: ... mjr_uploadHField``)."""
        ...
    def __getstate__(self) -> Data: ...
    def __setstate__(self, data: Data) -> None: ...
    def __del__(self) -> None: ...
