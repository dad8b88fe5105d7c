# Generated from src/typed_mjcf/variation/_structural.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Structural variants: N typed models, each built by a user function from its own seeded
generator (which child, how many objects, which model attached), then validated, exported
and compiled here, on local processes (the default) or on a Ray cluster.

World ``i``'s generator depends only on ``(seed, i)``, so the variants are the same whether
they are built in this process, on any number of processes, or on Ray. Results cross
process boundaries by pickling: MJCF text, the typed model, MuJoCo's compiled model.
"""
from __future__ import annotations
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Generic, Protocol, TypeVar, cast
import numpy as np
from typed_mjcf._base import ModelRoot
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, MjcfError
import mujoco
M = TypeVar("M", bound=ModelRoot)
Build = Callable[[np.random.Generator, int], M]

class VariantError(MjcfError, ValueError):
    """Building, validating, exporting or compiling one variant failed; the message names
    the world and seed, and the error (sent back from a worker as text)."""

@dataclass(frozen=True, slots=True)
class Variant(Generic[M]):
    """One structural variant: what :func:`generate` was asked to keep of it."""
    world: int
    xml: str | None
    model: M | None
    compiled: mujoco.MjModel | None
    warnings: tuple[str, ...]

def structure_rng(seed: int, world: int) -> np.random.Generator:
    """World ``world``'s generator for structure (another stream than its drawn values')."""
    ...

def variants(build: Build[M], seed: int, n: int, *, first: int = 0) -> list[M]:
    """The models of worlds ``first`` to ``first + n - 1``: ``build(rng, i)`` for each, in
    this process, ``rng`` world ``i``'s own generator."""
    ...

def generate(build: Build[M], seed: int, n: int, *, first: int = 0, validate: bool = True,
             xml: bool = True, compile: bool = False, keep_model: bool = False,
             processes: int | None = None, ray: bool | str = False,
             chunk: int | None = None) -> list[Variant[M]]:
    """Build worlds ``first`` to ``first + n - 1`` with ``build(rng, i)`` and, for each,
    validate (errors raise, warnings kept), export (``xml``) and compile as asked.

    Runs on ``processes`` local processes (``None``: one per CPU; ``0``: in this process),
    or, with ``ray`` (``True``: the running Ray, or a new local one; a string: that
    cluster's address), on Ray. ``build`` must pickle (a module-level function). Each task
    builds ``chunk`` consecutive worlds. The result is the same however it runs.
    """
    ...

class _RemoteFunction(Protocol):
    def remote(self, *args: object) -> object: ...

class _Ray(Protocol):
    """What of Ray's API is used here."""
    def is_initialized(self) -> bool: ...
    def init(self, address: str | None = None) -> object: ...
    def remote(self, function: Callable[..., object], /) -> _RemoteFunction: ...
    def get(self, refs: list[object], /) -> list[object]: ...

def ray_module() -> _Ray:
    """Ray, imported on first use (an optional extra: ``pip install 'typed-mjcf[ray]'``)."""
    ...
