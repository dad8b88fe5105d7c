"""``typed-mjcf render``: a picture of a model as a PNG file (and ``diff --render``'s)."""

from __future__ import annotations

import argparse
import re

from typed_mjcf import VIEWS
from typed_mjcf.cli._common import BAD_INPUT, OK, BadInput, error, load, one_line, shown
from typed_mjcf.cli._limits import add_limit_argument, limits
from typed_mjcf.errors import MjcfError
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

_SIZE = re.compile(r"(\d+)[xX](\d+)")


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("file", metavar="MODEL.xml", help="the model to render")
    parser.add_argument("-o", "--output", required=True, metavar="PICTURE.png",
                        help="the PNG file to write")
    parser.add_argument("--camera", metavar="NAME", help="render from the model's camera NAME")
    parser.add_argument("--size", type=size, default=(640, 480), metavar="WIDTHxHEIGHT",
                        help="the picture's size in pixels (default 640x480)")
    parser.add_argument("--views", type=views, metavar="NAME,NAME,...",
                        help=f"a contact sheet of these views ({', '.join(VIEWS)}, or the "
                             "model's cameras), each labelled")
    parser.add_argument("--keyframe", metavar="KEY",
                        help="pose the model as the key named KEY (or numbered KEY) first")
    parser.add_argument("--time", type=float, default=0.0, metavar="SECONDS",
                        help="simulate this many seconds before rendering (default 0)")
    add_limit_argument(parser, render=True)
    parser.set_defaults(run=run)


def size(text: str) -> tuple[int, int]:
    """``640x480`` as (640, 480); argparse reports the error."""
    match = _SIZE.fullmatch(text.strip())
    if match is None:
        raise argparse.ArgumentTypeError(f"{text!r}: expected WIDTHxHEIGHT, e.g. 640x480")
    return int(match[1]), int(match[2])


def views(text: str) -> tuple[str, ...]:
    names = tuple(name.strip() for name in text.split(",") if name.strip())
    if not names:
        raise argparse.ArgumentTypeError(f"{text!r}: expected names, e.g. front,side,top")
    return names


def run(args: argparse.Namespace) -> int:
    if args.camera is not None and args.views is not None:
        error(NAME, "give --camera or --views, not both")
        return BAD_INPUT
    try:
        model = load(args.file)
    except BadInput as problem:
        error(NAME, str(problem))
        return BAD_INPUT
    try:
        keyframe = None if args.keyframe is None else key_from_text(model, args.keyframe)
        width, height = args.size
        picture = render(model, args.camera, width=width, height=height, time=args.time,
                         keyframe=keyframe, views=args.views, limits=limits(args.limit))
        write_png(args.output, picture)
    except MjcfError as problem:
        error(NAME, f"{shown(args.file)}: {one_line(str(problem))}")
        return BAD_INPUT
    return OK


def write_diff_picture(path: str, a: ModelBase, b: ModelBase, a_name: str, b_name: str,
                       panel: tuple[int, int]) -> bool:
    """``diff --render``: the two models side by side and where their pictures differ;
    False (an error printed) when it cannot be made."""
    try:
        width, height = panel
        picture, _ = render_pair(a, b, width, height, labels=(f"A: {shown(a_name)}",
                                                      f"B: {shown(b_name)}"))
        write_png(path, picture)
    except MjcfError as problem:
        error("diff", f"--render: {one_line(str(problem))}")
        return False
    return True
