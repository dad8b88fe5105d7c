"""Structural variants: N typed models, each built by a user function from its own seeded
generator (which child, how many objects, which model attached), then validated, exported
and compiled here, on local processes (the default) or on a Ray cluster.

World ``i``'s generator depends only on ``(seed, i)``, so the variants are the same whether
they are built in this process, on any number of processes, or on Ray. Results cross
process boundaries by pickling: MJCF text, the typed model, MuJoCo's compiled model.
"""

from __future__ import annotations

import importlib
import math
import os
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from typing import TYPE_CHECKING, Generic, Protocol, TypeVar, cast

import numpy as np

from typed_mjcf._base import ModelRoot
from typed_mjcf._core.errors import InvalidTypeError, InvalidValueError, MjcfError
from typed_mjcf._model.validate import ValidationError
from typed_mjcf.variation._record import STRUCTURAL, check_worlds, world_rng

if TYPE_CHECKING:
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
    xml: str | None  # the exported MJCF (xml=True)
    model: M | None  # the typed model (keep_model=True)
    compiled: mujoco.MjModel | None  # MuJoCo's model (compile=True)
    warnings: tuple[str, ...]  # validate()'s warnings (validate=True)


@dataclass(frozen=True, slots=True)
class _Steps:
    validate: bool
    xml: bool
    compile: bool
    keep_model: bool


def structure_rng(seed: int, world: int) -> np.random.Generator:
    """World ``world``'s generator for structure (another stream than its drawn values')."""
    return world_rng(seed, world, STRUCTURAL)


def variants(build: Build[M], seed: int, n: int, *, first: int = 0) -> list[M]:
    """The models of worlds ``first`` to ``first + n - 1``: ``build(rng, i)`` for each, in
    this process, ``rng`` world ``i``'s own generator."""
    check_worlds(seed, n, first)
    return [build(structure_rng(seed, world), world) for world in range(first, first + n)]


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
    check_worlds(seed, n, first)
    steps = _Steps(validate, xml, compile, keep_model)
    if processes is not None and (not _is_int(processes) or processes < 0):
        raise InvalidValueError(f"processes must be None or an int >= 0, got {processes!r}")
    workers = (os.cpu_count() or 1) if processes is None else max(processes, 1)
    size = chunk if chunk is not None else max(1, math.ceil(n / (4 * workers)))
    if not _is_int(size) or size < 1:
        raise InvalidValueError(f"chunk must be an int >= 1, got {chunk!r}")
    starts = range(first, first + n, size)
    tasks = [(s, min(s + size, first + n)) for s in starts]
    if ray is not False:
        return _on_ray(ray, build, seed, tasks, steps)
    if processes == 0:
        return [v for start, stop in tasks for v in _run(build, seed, start, stop, steps)]
    with ProcessPoolExecutor(max_workers=workers) as pool:
        futures = [pool.submit(_run, build, seed, start, stop, steps) for start, stop in tasks]
        return [v for future in futures for v in future.result()]


def _is_int(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _run(build: Build[M], seed: int, start: int, stop: int, steps: _Steps) -> list[Variant[M]]:
    """Worlds ``start`` to ``stop - 1``: what runs in a worker."""
    done: list[Variant[M]] = []
    for world in range(start, stop):
        try:
            done.append(_one(build, seed, world, steps))
        except Exception as error:  # sent back as text: every error pickles so
            raise VariantError(f"world {world} (seed {seed}): {type(error).__name__}: "
                               f"{error}") from error
    return done


def _one(build: Build[M], seed: int, world: int, steps: _Steps) -> Variant[M]:
    model = build(structure_rng(seed, world), world)
    if not isinstance(cast(object, model), ModelRoot):
        raise InvalidTypeError(f"build() must return a model (a RootElement), got {model!r}")
    warnings: tuple[str, ...] = ()
    if steps.validate:
        findings = model.validate()
        if any(f.severity == "error" for f in findings):
            raise ValidationError(findings)
        warnings = tuple(str(f) for f in findings)
    return Variant(world, model.to_xml_string() if steps.xml else None,
                   model if steps.keep_model else None,
                   model.compile() if steps.compile else None, warnings)


# ---------------------------------------------------------------------------- Ray


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
    try:
        module = importlib.import_module("ray")
    except ImportError:
        raise ImportError("generate(ray=...) needs Ray, which is not installed: "
                          "pip install 'typed-mjcf[ray]'") from None
    return cast(_Ray, module)


def _on_ray(ray: bool | str, build: Build[M], seed: int,
            tasks: Sequence[tuple[int, int]], steps: _Steps) -> list[Variant[M]]:
    if not isinstance(cast(object, ray), bool | str):
        raise InvalidTypeError(f"ray must be True or a cluster's address, got {ray!r}")
    engine = ray_module()
    if not engine.is_initialized():
        engine.init(address=ray if isinstance(ray, str) else None)
    remote = engine.remote(_run)
    done = engine.get([remote.remote(build, seed, start, stop, steps) for start, stop in tasks])
    return [v for part in cast(list[list[Variant[M]]], done) for v in part]
