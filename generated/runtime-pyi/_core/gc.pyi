# Generated from src/typed_mjcf/_core/gc.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Pausing the cyclic garbage collector around bulk work that creates no garbage cycles.

Parsing and exporting create many objects that either live on (the parsed tree) or are
freed by reference counting (the export's intermediate text). The collector would rescan
the whole live model again and again while they are made, finding nothing: superlinear time
on large models for no benefit. Reference counting is unaffected while it is paused.
"""
from __future__ import annotations
from collections.abc import Generator
from contextlib import contextmanager

@contextmanager
def collector_paused() -> Generator[None]:
    """Disable the cyclic collector for the block; restore it only if it was enabled."""
    ...
