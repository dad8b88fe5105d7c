"""The MuJoCo bridge: compiling, and converting to and from ``mujoco.MjSpec``.

``mujoco`` is imported when first needed: it is the heaviest import of the library, and
building, reading and writing models do not need it. When MuJoCo refuses a model, the error
keeps MuJoCo's message and names the element it is about (:mod:`typed_mjcf._sim.locate`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, cast

from typed_mjcf._core.errors import CompileError, InvalidTypeError
from typed_mjcf._core.tree import ModelBase
from typed_mjcf._model.keyframes import LayoutError
from typed_mjcf._model.resource_limits import DEFAULT_COMPILE_LIMITS, CompileLimits, check_compile
from typed_mjcf._model.validate import ensure_valid
from typed_mjcf._model.write import collect
from typed_mjcf._sim.compile import compile_from_memory, spec_from_memory
from typed_mjcf._sim.locate import locate
from typed_mjcf._sim.text import vfs_text
from typed_mjcf._text.files import CollectedFiles

if TYPE_CHECKING:
    import mujoco


def _mujoco_error(model: ModelBase, message: str, collected: CollectedFiles) -> CompileError:
    """MuJoCo's message, with the path of the element it is about where one is known."""
    message = message.strip()
    location = locate(model, message, collected)
    if location is None:
        return CompileError(f"MuJoCo could not compile the model: {message}")
    return CompileError(f"MuJoCo could not compile the model: {message}\n({location.note})",
                        path=location.path)


def _text(model: ModelBase, limits: CompileLimits) -> tuple[str, CollectedFiles]:
    """The model's text for MuJoCo; a composed model whose keyframes are combined is compiled
    once without them (within ``limits``), and MuJoCo may refuse it then."""
    try:
        return vfs_text(model, limits=limits)
    except LayoutError as error:
        raise _mujoco_error(model, error.mujoco_message, collect(model)) from None


def compile_model(model: ModelBase,
                  limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjModel:
    """Validate, check what MuJoCo would allocate against ``limits``, then compile with
    MuJoCo (files passed through a virtual file system)."""
    ensure_valid(model)
    check_compile(model, limits)  # before _text: a composed model's keyframes compile it
    xml, collected = _text(model, limits)
    try:
        return compile_from_memory(xml, collected.files)
    except (ValueError, RuntimeError) as error:  # (RuntimeError: a C++ exception it did not
        raise _mujoco_error(model, str(error), collected) from None  # expect)


def to_spec(model: ModelBase,
            limits: CompileLimits = DEFAULT_COMPILE_LIMITS) -> mujoco.MjSpec:
    """The model as a ``mujoco.MjSpec``, checked against ``limits`` first (``MjSpec`` reads
    replicates and flexcomps out as it parses, and is made to be compiled)."""
    check_compile(model, limits)
    xml, collected = _text(model, limits)
    try:
        return spec_from_memory(xml, collected.files)
    except (ValueError, RuntimeError) as error:
        raise _mujoco_error(model, str(error), collected) from None


def spec_to_xml(spec: mujoco.MjSpec) -> str:
    """The MJCF text MuJoCo writes for a spec (compiling it first, as ``to_xml`` requires)."""
    import mujoco

    if not isinstance(cast(object, spec), mujoco.MjSpec):
        raise InvalidTypeError(f"from_spec needs a mujoco.MjSpec, got {type(spec).__name__}")
    spec.compile()
    return spec.to_xml()
