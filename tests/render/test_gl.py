"""The OpenGL back end: headless by default whatever was imported first, and one clear error
naming what to install when none works (never an OpenGL traceback)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from typed_mjcf._sim import gl as _gl

from .scenes import box_scene


def test_headless_by_default_even_after_mujoco_chose_glfw() -> None:
    """With MUJOCO_GL unset and no display, ``import mujoco`` picks GLFW (which cannot work
    here) for ``mujoco.Renderer``; a picture is still made, with EGL, and MUJOCO_GL says so."""
    script = textwrap.dedent("""
        import os
        import mujoco
        import typed_mjcf as mjcf
        from tests.render.scenes import box_scene, red
        assert "glfw" in mujoco.GLContext.__module__
        image = box_scene().render(width=64, height=48)
        print(os.environ["MUJOCO_GL"], image.shape, bool(red(image).any()))
    """)
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "DISPLAY",
                                                            "PYOPENGL_PLATFORM")}
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            env=env, cwd=Path(__file__).resolve().parents[2], check=False,
                            timeout=120)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["egl", "(48,", "64,", "3)", "True"]


def test_physics_render_after_mujoco_chose_glfw_says_to_set_mujoco_gl_first() -> None:
    """``Physics.render`` draws with ``mujoco.Renderer``, whose back end MuJoCo chose when it
    was imported (GLFW, with MUJOCO_GL unset then): the error says so and what to set, once
    (no OpenGL traceback)."""
    script = textwrap.dedent("""
        import mujoco
        import typed_mjcf as mjcf
        model = mjcf.RootElement()
        model.worldbody.add_geom(size=(1,))
        physics = mjcf.Physics.from_mjcf_model(model)
        try:
            physics.render(32, 32)
        except mjcf.RenderError as error:
            print(error)
    """)
    env = {k: v for k, v in os.environ.items() if k not in ("MUJOCO_GL", "DISPLAY",
                                                            "PYOPENGL_PLATFORM")}
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            env=env, check=False, timeout=120)
    assert result.returncode == 0, result.stderr
    message = result.stdout.strip()
    assert message.startswith("cannot render: mujoco was imported before MUJOCO_GL=egl was "
                              "set, so its renderer uses glfw: "), message
    assert "set MUJOCO_GL before anything imports mujoco" in message
    assert "MUJOCO_GL=egl python" in message and "osmesa on the CPU" in message
    assert len(message.splitlines()) == 1
    # what GLFW warned is in the one error, not printed before it
    assert "The DISPLAY environment variable is missing" in message
    assert "GLFWError" not in result.stderr and "warn" not in result.stderr, result.stderr


@pytest.fixture
def unchosen(monkeypatch: pytest.MonkeyPatch) -> pytest.MonkeyPatch:
    """The process as if no back end had been chosen yet (restored afterwards)."""
    monkeypatch.setattr(_gl, "_chosen", {})
    monkeypatch.delenv("MUJOCO_GL", raising=False)
    return monkeypatch


def test_the_first_back_end_that_works_is_chosen_and_kept(unchosen: pytest.MonkeyPatch) -> None:
    assert _gl.ensure_gl_backend() == "egl"
    assert os.environ["MUJOCO_GL"] == "egl"


def _missing(name: str) -> object:
    raise OSError(f"{name}: cannot open shared object file: No such file or directory")


def test_no_back_end_is_one_error_naming_what_to_install(unchosen: pytest.MonkeyPatch) -> None:
    unchosen.setattr(_gl.platform, "system", lambda: "Linux")
    unchosen.setattr(_gl.ctypes, "CDLL", _missing)
    with pytest.raises(mjcf.RenderError) as caught:
        box_scene().render(width=32, height=24)
    assert str(caught.value) == (
        "cannot render: no OpenGL back end works here (MUJOCO_GL is not set; egl: libEGL.so "
        "is not installed; osmesa: libOSMesa.so is not installed); install EGL (Debian/Ubuntu: "
        "apt-get install libegl1 and libgl1-mesa-dri) or OSMesa (Debian/Ubuntu: apt-get "
        "install libosmesa6), or set MUJOCO_GL to a back end that works here")
    assert "MUJOCO_GL" not in os.environ
    assert caught.value.__context__ is None  # no OpenGL traceback chained to it


def test_a_back_end_that_fails_says_why_in_one_line(unchosen: pytest.MonkeyPatch) -> None:
    """What the GL library raised, whatever its type, becomes the error's reason."""
    class Broken:
        def __init__(self, width: int, height: int) -> None:
            raise OSError("eglInitialize failed:\n  no device")

    unchosen.setenv("MUJOCO_GL", "egl")
    unchosen.setattr(_gl, "_context_class", lambda backend: Broken)
    with pytest.raises(mjcf.RenderError, match=r"MUJOCO_GL=egl; egl: eglInitialize failed: no "
                       r"device\); install EGL \(Debian/Ubuntu: apt-get install libegl1 and "
                       r"libgl1-mesa-dri\)") as caught:
        _gl.ensure_gl_backend()
    assert caught.value.__context__ is None


@pytest.mark.parametrize(("value", "message"), [
    ("disable", r"MUJOCO_GL=disable turns MuJoCo's rendering off"),
    ("vulkan", r"MUJOCO_GL='vulkan' is not a back end MuJoCo knows"),
])
def test_a_mujoco_gl_that_cannot_render_is_refused(unchosen: pytest.MonkeyPatch, value: str,
                                                   message: str) -> None:
    unchosen.setenv("MUJOCO_GL", value)
    with pytest.raises(mjcf.RenderError, match=message):
        _gl.ensure_gl_backend()
