"""MuJoCo's OpenGL back end for rendering, and one clear error when there is none.

MuJoCo picks its back end from the ``MUJOCO_GL`` environment variable when ``mujoco`` is
imported: ``egl`` renders without a display (on a GPU, or on the CPU with Mesa's EGL),
``osmesa`` on the CPU, ``glfw`` (the default) needs a display. typed-mjcf never sets it:
rendering uses what the user chose, and a back end that cannot work is one
:class:`RenderError` naming it and what to set instead, not a traceback from OpenGL.
"""

from __future__ import annotations

import os
import platform
from typing import Final

from typed_mjcf.errors import MjcfError

_COMMON: Final = ("", "glfw", "enable", "enabled", "on", "true", "1", "disable", "disabled",
                  "off", "false", "0")
_BY_SYSTEM: Final = {"Linux": ("egl", "osmesa", "glx"), "Windows": ("wgl",), "Darwin": ("cgl",)}
ADVICE: Final = ("set MUJOCO_GL before Python starts: MUJOCO_GL=egl renders without a "
                 "display (GPU, or Mesa's EGL on the CPU), MUJOCO_GL=osmesa on the CPU, "
                 "MUJOCO_GL=glfw with a display")


class RenderError(MjcfError, RuntimeError):
    """Rendering is not possible here: no OpenGL back end MuJoCo can use."""


def gl_backend() -> str:
    """The back end ``MUJOCO_GL`` names (``""``: MuJoCo's default, glfw)."""
    return os.environ.get("MUJOCO_GL", "").strip().lower()


def ensure_gl_backend() -> str:
    """The back end rendering will use; :class:`RenderError` if ``MUJOCO_GL`` names one MuJoCo
    does not have on this system (checked before MuJoCo's import would fail on it)."""
    backend = gl_backend()
    valid = _COMMON + _BY_SYSTEM.get(platform.system(), ())
    if backend not in valid:
        raise RenderError(f"MUJOCO_GL={backend!r} is not an OpenGL back end MuJoCo has on "
                          f"{platform.system()} ({', '.join(v for v in valid if v)}); {ADVICE}")
    if backend in ("disable", "disabled", "off", "false", "0"):
        raise RenderError(f"rendering is disabled (MUJOCO_GL={backend!r}); {ADVICE}")
    return backend


def gl_error(error: BaseException) -> RenderError:
    """What a failure to make an OpenGL context says, as one error."""
    backend = gl_backend() or "glfw (MuJoCo's default)"
    cause = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
    return RenderError(f"cannot render: MuJoCo could not make an OpenGL context with "
                       f"MUJOCO_GL={backend}: {cause}; {ADVICE}")
