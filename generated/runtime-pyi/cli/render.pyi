# Generated from src/typed_mjcf/cli/render.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``typed-mjcf render``: a picture of a model as a PNG file (and ``diff --render``'s)."""
from __future__ import annotations
import argparse
from typed_mjcf import VIEWS
from typed_mjcf.tooling import ModelBase, key_from_text, render, render_pair, write_png
NAME = "render"
HELP = "render a model to a PNG picture (offscreen, no display needed)"
DESCRIPTION = f"""\
Compile a model with MuJoCo and render it offscreen to a PNG file: from the default view
(the whole model, framed as MuJoCo's viewer frames it), from one of its cameras (--camera),
or as a contact sheet of labelled views (--views: the presets {", ".join(VIEWS)}, or names
of the model's cameras). --keyframe poses the model first, --time simulates that many
seconds from there.

  typed-mjcf render robot.xml -o robot.png
  typed-mjcf render robot.xml -o sheet.png --views front,side,top,iso --size 1280x960
  typed-mjcf render big.xml -o big.png --limit max_texture_pixels=200000000 --limit max_steps=10000000

What a few bytes of MJCF may make MuJoCo allocate (textures, height fields, builtin meshes,
flexcomps, replicated elements, the offscreen buffer) and the steps of --time are bounded;
the error names the limit, and --limit NAME=VALUE raises it.

Headless by default: MuJoCo renders with EGL, else OSMesa, unless MUJOCO_GL names a back
end; when none works, the error says what to install.

exit status: 0 the picture is written, 2 the model cannot be read, compiled or rendered (a
one-line error)."""

def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    ...

def size(text: str) -> tuple[int, int]:
    """``640x480`` as (640, 480); argparse reports the error."""
    ...

def views(text: str) -> tuple[str, ...]: ...

def run(args: argparse.Namespace) -> int: ...

def write_diff_picture(path: str, a: ModelBase, b: ModelBase, a_name: str, b_name: str,
                       panel: tuple[int, int]) -> bool:
    """``diff --render``: the two models side by side and where their pictures differ;
    False (an error printed) when it cannot be made."""
    ...
