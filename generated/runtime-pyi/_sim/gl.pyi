# Generated from src/typed_mjcf/_sim/gl.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The OpenGL back end MuJoCo renders with: headless by default, one clear error otherwise.

MuJoCo reads ``MUJOCO_GL`` once, when ``mujoco`` is imported: ``mujoco.gl_context`` picks
its ``GLContext`` class then (GLFW, which needs a display, when the variable is unset), and
``mujoco.Renderer`` uses that class. A program that imported ``mujoco`` (or compiled a model)
before asking for a picture has therefore chosen already. So the library makes its contexts
from the chosen back end's module itself (:func:`gl_context`), whichever was imported first,
and sets ``MUJOCO_GL`` for code that imports ``mujoco`` later.
"""
from __future__ import annotations
from collections.abc import Sequence
from typing import Final, Protocol, cast
from typed_mjcf._core.errors import RenderError

class GLContext(Protocol):
    """What the library uses of MuJoCo's ``GLContext`` classes."""
    def make_current(self) -> None: ...
    def free(self) -> None: ...

def ensure_gl_backend() -> str:
    """The back end pictures are rendered with (``egl``, ``osmesa``, ``glfw``...).

    ``MUJOCO_GL`` when it is set; otherwise the first back end that makes a context here
    (EGL, then OSMesa on Linux), and ``MUJOCO_GL`` is set to it. Raises :class:`RenderError`
    naming what to install when none works (never an OpenGL traceback).
    """
    ...

def gl_context(width: int, height: int) -> GLContext:
    """This thread's OpenGL context of the chosen back end, current, for buffers up to
    ``width`` x ``height``. It is kept for the next picture: MuJoCo's ``MjrContext`` sets up
    several times faster in a context that has rendered before (measured with Mesa)."""
    ...

def gl_error(error: BaseException, warned: Sequence[str] = ()) -> RenderError:
    """What a failure to make an OpenGL context (outside :func:`gl_context`) says, as one
    error naming the back end and what to do (with what the back end ``warned`` first, such
    as GLFW's "The DISPLAY environment variable is missing")."""
    ...
