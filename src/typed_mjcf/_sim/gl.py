"""The OpenGL back end MuJoCo renders with: headless by default, one clear error otherwise.

MuJoCo reads ``MUJOCO_GL`` once, when ``mujoco`` is imported: ``mujoco.gl_context`` picks
its ``GLContext`` class then (GLFW, which needs a display, when the variable is unset), and
``mujoco.Renderer`` uses that class. A program that imported ``mujoco`` (or compiled a model)
before asking for a picture has therefore chosen already. So the library makes its contexts
from the chosen back end's module itself (:func:`gl_context`), whichever was imported first,
and sets ``MUJOCO_GL`` for code that imports ``mujoco`` later.
"""

from __future__ import annotations

import ctypes
import importlib
import importlib.util
import os
import platform
import sys
import threading
from collections.abc import Sequence
from typing import Final, Protocol, cast

from typed_mjcf._core.errors import RenderError

# Back ends tried in order when MUJOCO_GL is unset: the headless ones on Linux.
_HEADLESS: Final = ("egl", "osmesa")
_TRIED: Final = {"Linux": _HEADLESS, "Darwin": ("cgl", "glfw")}
# The shared library each needs (the names it is installed under) and how to install it.
_LIBRARY: Final = {"egl": ("libEGL.so.1", "libEGL.so"),
                   "osmesa": ("libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so")}
_INSTALL: Final = {"egl": "libegl1 and libgl1-mesa-dri", "osmesa": "libosmesa6"}
# mujoco.gl_context's values of MUJOCO_GL: these pick a back end module, the rest GLFW.
_MODULE: Final = {"egl": "mujoco.egl", "osmesa": "mujoco.osmesa", "cgl": "mujoco.cgl"}
_KNOWN: Final = frozenset({"egl", "osmesa", "cgl", "glfw", "glx", "wgl", "enable", "enabled",
                           "on", "true", "1"})
_OFF: Final = frozenset({"disable", "disabled", "off", "false", "0"})


class GLContext(Protocol):
    """What the library uses of MuJoCo's ``GLContext`` classes."""

    def make_current(self) -> None: ...

    def free(self) -> None: ...


class _ContextClass(Protocol):
    def __call__(self, max_width: int, max_height: int) -> GLContext: ...


_chosen: dict[str, str] = {}  # "backend" once one has made a context in this process
_THREAD = threading.local()  # .context: (the context, its width, its height), once made


def ensure_gl_backend() -> str:
    """The back end pictures are rendered with (``egl``, ``osmesa``, ``glfw``...).

    ``MUJOCO_GL`` when it is set; otherwise the first back end that makes a context here
    (EGL, then OSMesa on Linux), and ``MUJOCO_GL`` is set to it. Raises :class:`RenderError`
    naming what to install when none works (never an OpenGL traceback).
    """
    if "backend" in _chosen:
        return _chosen["backend"]
    wanted = os.environ.get("MUJOCO_GL", "").strip().lower()
    if wanted in _OFF:
        raise RenderError(f"cannot render: MUJOCO_GL={wanted} turns MuJoCo's rendering off; "
                          f"unset it or set it to egl, osmesa or glfw")
    if wanted and wanted not in _KNOWN:
        raise RenderError(f"cannot render: MUJOCO_GL={wanted!r} is not a back end MuJoCo "
                          f"knows; expected egl, osmesa or glfw")
    candidates = (wanted,) if wanted else _TRIED.get(platform.system(), ("glfw",))
    reasons: list[str] = []
    for backend in candidates:
        reason = _probe(backend)
        if reason is None:
            _chosen["backend"] = backend
            os.environ.setdefault("MUJOCO_GL", backend)
            return backend
        reasons.append(f"{backend}: {reason}")
    raise RenderError(_no_backend_message(wanted, candidates, reasons))


def gl_context(width: int, height: int) -> GLContext:
    """This thread's OpenGL context of the chosen back end, current, for buffers up to
    ``width`` x ``height``. It is kept for the next picture: MuJoCo's ``MjrContext`` sets up
    several times faster in a context that has rendered before (measured with Mesa)."""
    backend = ensure_gl_backend()
    kept: tuple[GLContext, int, int] | None = getattr(_THREAD, "context", None)
    if kept is not None and kept[1] >= width and kept[2] >= height:
        context = kept[0]
    else:
        if kept is not None:
            width, height = max(width, kept[1]), max(height, kept[2])
            _THREAD.context = None
            kept[0].free()
        try:
            context = _context_class(backend)(width, height)
        except Exception as error:  # noqa: BLE001 - the GL libraries raise anything: say it once
            raise RenderError(f"cannot render: the {backend} back end could not make an "
                              f"OpenGL context: {_one_line(error)}") from None
        _THREAD.context = (context, width, height)
    try:
        context.make_current()
    except Exception as error:  # noqa: BLE001
        raise RenderError(f"cannot render: the {backend} back end could not make its OpenGL "
                          f"context current: {_one_line(error)}") from None
    return context


def _context_class(backend: str) -> _ContextClass:
    module = importlib.import_module(_MODULE.get(backend, "mujoco.glfw"))
    return cast(_ContextClass, module.GLContext)


def _probe(backend: str) -> str | None:
    """Why ``backend`` cannot render here, or ``None`` when it made a context."""
    libraries = _LIBRARY.get(backend, ())
    if libraries and not any(_loads(name) for name in libraries):
        return f"{libraries[-1]} is not installed"
    if backend in _HEADLESS and importlib.util.find_spec("OpenGL") is None:
        return "PyOpenGL is not installed (pip install PyOpenGL, or typed-mjcf[render])"
    platform_before = os.environ.get("PYOPENGL_PLATFORM")
    try:
        context = _context_class(backend)(1, 1)
        context.make_current()
        context.free()
    except Exception as error:  # noqa: BLE001 - the GL libraries raise anything: say it once
        # mujoco.egl and mujoco.osmesa set PyOpenGL's platform on import; let the next try
        # set its own.
        if platform_before is None:
            os.environ.pop("PYOPENGL_PLATFORM", None)
        return _one_line(error)
    return None


def _loads(library: str) -> bool:
    """Whether the dynamic loader finds ``library`` (PyOpenGL loads it the same way)."""
    try:
        ctypes.CDLL(library)
    except OSError:
        return False
    return True


def _no_backend_message(wanted: str, tried: tuple[str, ...], reasons: list[str]) -> str:
    install = " or ".join(f"{b.upper() if b == 'egl' else 'OSMesa'} "
                          f"(Debian/Ubuntu: apt-get install {_INSTALL[b]})"
                          for b in tried if b in _INSTALL)
    setting = f"MUJOCO_GL={wanted}" if wanted else "MUJOCO_GL is not set"
    advice = (f"install {install}, or set MUJOCO_GL to a back end that works here"
              if install else "set MUJOCO_GL to a back end that works here (glfw needs a "
              "display)")
    return (f"cannot render: no OpenGL back end works here ({setting}; "
            f"{'; '.join(reasons)}); {advice}")


def _mujocos_back_end() -> str | None:
    """The back end MuJoCo's renderer chose when ``mujoco`` was imported (``glfw`` when
    MUJOCO_GL was unset then), if it is known."""
    chooser = sys.modules.get("mujoco.rendering.classic.gl_context")
    cls = getattr(chooser, "GLContext", None)
    module = getattr(cls, "__module__", None)
    if not isinstance(module, str) or not module.startswith("mujoco."):
        return None
    return module.split(".")[1]


def _one_line(error: BaseException) -> str:
    text = " ".join(str(error).split()) or type(error).__name__
    return text if len(text) <= 200 else text[:197] + "..."


def gl_error(error: BaseException, warned: Sequence[str] = ()) -> RenderError:
    """What a failure to make an OpenGL context (outside :func:`gl_context`) says, as one
    error naming the back end and what to do (with what the back end ``warned`` first, such
    as GLFW's "The DISPLAY environment variable is missing")."""
    backend = os.environ.get("MUJOCO_GL", "").strip().lower() or "glfw (MuJoCo's default)"
    if warned:
        error = RuntimeError(f"{'; '.join(dict.fromkeys(warned))}; {_one_line(error)}")
    taken = _mujocos_back_end()
    if taken is not None and taken != backend:
        # mujoco.Renderer makes the context MuJoCo chose when it was imported: too late now
        return RenderError(f"cannot render: mujoco was imported before MUJOCO_GL={backend} "
                           f"was set, so its renderer uses {taken}: {_one_line(error)}; set "
                           f"MUJOCO_GL before anything imports mujoco (before Python starts: "
                           f"MUJOCO_GL=egl python ..., or os.environ['MUJOCO_GL'] = 'egl' "
                           f"first in the script): egl renders without a display (a GPU, or "
                           f"Mesa's EGL on the CPU), osmesa on the CPU, glfw with a display")
    return RenderError(f"cannot render: MuJoCo could not make an OpenGL context with "
                       f"MUJOCO_GL={backend}: {_one_line(error)}; set MUJOCO_GL before "
                       f"Python starts: egl renders without a display (a GPU, or Mesa's EGL "
                       f"on the CPU), osmesa on the CPU, glfw with a display")
