# Generated from src/typed_mjcf/cli/_limits.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""``--limit NAME=VALUE``: raising (or lowering) a compile or render limit from the command
line, one way for every command that compiles (the names are the fields of
:class:`~typed_mjcf.CompileLimits` and :class:`~typed_mjcf.RenderLimits`)."""
from __future__ import annotations
import argparse
from typed_mjcf import CompileLimits, RenderLimits

def _names(cls: type[CompileLimits | RenderLimits]) -> list[str]:
    """The whole-number fields of ``cls`` (RenderLimits' ``compile`` is a table of its own)."""
    ...
COMPILE_NAMES = _names(CompileLimits)
RENDER_NAMES = _names(RenderLimits)

def add_limit_argument(parser: argparse.ArgumentParser, render: bool) -> None:
    """Declare ``--limit`` (the render limits too with ``render``)."""
    ...

def limits(pairs: list[tuple[str, int]] | tuple[tuple[str, int], ...]) -> RenderLimits:
    """The render limits (and their compile limits) with ``pairs`` (name, value) set."""
    ...
