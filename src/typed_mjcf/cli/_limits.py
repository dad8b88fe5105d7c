"""``--limit NAME=VALUE``: raising (or lowering) a compile or render limit from the command
line, one way for every command that compiles (the names are the fields of
:class:`~typed_mjcf.CompileLimits` and :class:`~typed_mjcf.RenderLimits`)."""

from __future__ import annotations

import argparse
import dataclasses
from collections.abc import Callable

from typed_mjcf import CompileLimits, RenderLimits
from typed_mjcf.errors import MjcfError
from typed_mjcf.tooling import DEFAULT_RENDER_LIMITS


def _names(cls: type[CompileLimits | RenderLimits]) -> list[str]:
    """The whole-number fields of ``cls`` (RenderLimits' ``compile`` is a table of its own)."""
    return [f.name for f in dataclasses.fields(cls) if f.type in ("int", int)]


COMPILE_NAMES = _names(CompileLimits)
RENDER_NAMES = _names(RenderLimits)


def add_limit_argument(parser: argparse.ArgumentParser, render: bool) -> None:
    """Declare ``--limit`` (the render limits too with ``render``)."""
    names = COMPILE_NAMES + (RENDER_NAMES if render else [])
    parser.add_argument(
        "--limit", action="append", default=[], metavar="NAME=VALUE",
        type=_limit_parser(names),
        help=f"raise (or lower) a limit on what MuJoCo may allocate, repeatable; NAME is "
             f"one of {', '.join(names)} (see typed_mjcf.CompileLimits"
             f"{' and RenderLimits' if render else ''}), e.g. --limit "
             f"max_texture_pixels=200000000")


def _limit_parser(names: list[str]) -> Callable[[str], tuple[str, int]]:
    def parse(text: str) -> tuple[str, int]:
        name, equals, value = text.partition("=")
        name = name.strip().replace("-", "_")
        if not equals:
            raise argparse.ArgumentTypeError(f"{text!r}: expected NAME=VALUE, e.g. "
                                             f"max_texture_pixels=200000000")
        if name not in names:
            raise argparse.ArgumentTypeError(f"{name!r} is not a limit; limits: "
                                             f"{', '.join(names)}")
        try:
            number = int(value.strip().replace("_", ""))
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r}: {value!r} is not a whole "
                                             f"number") from None
        try:
            limits(((name, number),))
        except MjcfError as problem:
            raise argparse.ArgumentTypeError(f"{text!r}: {problem}") from None
        return name, number

    parse.__name__ = "limit"  # argparse names the type in its error
    return parse


def limits(pairs: list[tuple[str, int]] | tuple[tuple[str, int], ...]) -> RenderLimits:
    """The render limits (and their compile limits) with ``pairs`` (name, value) set."""
    compile_values = {name: value for name, value in pairs if name in COMPILE_NAMES}
    render_values = {name: value for name, value in pairs if name not in COMPILE_NAMES}
    compile_limits = dataclasses.replace(DEFAULT_RENDER_LIMITS.compile, **compile_values)
    return dataclasses.replace(DEFAULT_RENDER_LIMITS, compile=compile_limits, **render_values)
