"""Settings the whole test session needs before anything imports ``mujoco``."""

import os

# MuJoCo picks its OpenGL back end when first imported: EGL renders without a display (on
# Mesa's software EGL where there is no GPU), so the tests that render (the README's example,
# tests/physics) run on headless machines. A back end the user chose is kept.
os.environ.setdefault("MUJOCO_GL", "egl")
