"""Bounds on what compiling and rendering a model may allocate, checked before MuJoCo does.

A few bytes of MJCF can make MuJoCo allocate gigabytes (a builtin texture's width and
height, an hfield's rows and columns, a small PNG declaring a huge picture) or step for hours
(a tiny timestep under a long simulated time): :class:`CompileLimits` and
:class:`RenderLimits` bound them as :class:`~typed_mjcf.ParseLimits` bounds reading. Which
elements allocate what is the grammar's ``allocations`` fact (``schema/facts.toml``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Final

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.access import check_count
from typed_mjcf._core.errors import CompileError, InvalidTypeError, RenderError
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.language import Allocation, GeneratedShape
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._model.defaults import resolve
from typed_mjcf._text.files import CollectedFiles, compiler_folders, file_contents
from typed_mjcf.assets import Asset

_PNG: Final = b"\x89PNG\r\n\x1a\n"
_FACES: Final = 6  # of a cube texture


@dataclass(frozen=True, slots=True)
class CompileLimits:
    """Bounds on what MuJoCo may allocate compiling one model; pass a raised copy to
    compile more (``model.compile(limits=CompileLimits(max_texture_pixels=1 << 30))``).

    ``max_texture_pixels``
        Pixels of all textures (64 Mi, about 200 MB of RGB): a builtin texture's width x
        height (six width x width faces for a cube or skybox) and each PNG file's declared
        width x height, read from its header before MuJoCo decodes it.
    ``max_hfield_samples``
        Elevation samples of all height fields (64 Mi floats, 256 MB): nrow x ncol, or a PNG
        file's declared width x height.
    ``max_mesh_vertices``
        Vertices of all builtin meshes generated from ``params`` (16 Ki: a cone of 2,000
        took 0.3 s, of 20,000 more than 100 s).
    ``max_flex_points``
        Points of all flexcomps, the product of ``count`` (4096: a grid of 8000 took 45 s).
    ``max_replicated_elements``
        Elements ``<replicate>`` adds, nested copies multiplied (128 Ki: 90,000 geoms took
        16 s and 772 MB).
    """

    max_texture_pixels: int = 1 << 26
    max_hfield_samples: int = 1 << 26
    max_mesh_vertices: int = 1 << 14
    max_flex_points: int = 1 << 12
    max_replicated_elements: int = 1 << 17

    def __post_init__(self) -> None:
        for name in _COMPILE_FIELDS:
            check_count(f"CompileLimits.{name}", getattr(self, name))


_COMPILE_FIELDS: Final = ("max_texture_pixels", "max_hfield_samples", "max_mesh_vertices",
                          "max_flex_points", "max_replicated_elements")
# what each limit counts, for messages
_UNITS: Final = {"max_texture_pixels": "pixels", "max_hfield_samples": "samples",
                 "max_mesh_vertices": "vertices", "max_flex_points": "points",
                 "max_replicated_elements": "copied elements"}


@dataclass(frozen=True, slots=True)
class RenderLimits:
    """Bounds on what rendering one picture may cost; pass a raised copy to render more
    (``model.render(time=600, limits=RenderLimits(max_steps=10**8))``).

    ``max_steps``
        Simulation steps before the picture: ``time`` / the model's timestep (1,000,000).
    ``max_offscreen_pixels``
        Pixels of the offscreen buffer: the picture's, or the model's ``<visual><global
        offwidth offheight>`` when larger (8192 x 8192).
    ``compile``
        The :class:`CompileLimits` of the compile before rendering.
    """

    max_steps: int = 1_000_000
    max_offscreen_pixels: int = 8192 * 8192
    compile: CompileLimits = field(default_factory=CompileLimits)

    def __post_init__(self) -> None:
        for name in ("max_steps", "max_offscreen_pixels"):
            check_count(f"RenderLimits.{name}", getattr(self, name))
        _checked(self.compile, "RenderLimits.compile")


def _checked(limits: object, what: str) -> None:
    if not isinstance(limits, CompileLimits):
        raise InvalidTypeError(f"{what} must be a typed_mjcf.CompileLimits, got {limits!r}")


DEFAULT_COMPILE_LIMITS: Final = CompileLimits()
DEFAULT_RENDER_LIMITS: Final = RenderLimits()


def _raise_hint(cls: str, name: str) -> str:
    return f"to allow it, pass limits=typed_mjcf.{cls}({name}=...) with a larger value"


def check_compile(model: ModelBase, limits: CompileLimits) -> None:
    """Raise :class:`CompileError` naming the element, attribute and value that take a
    count of ``limits`` past its bound (the counts are the whole model's)."""
    _checked(limits, "limits")
    totals: dict[str, int] = {}
    for element, limit, what, count in allocations(model):
        bound = getattr(limits, limit)
        total = totals[limit] = totals.get(limit, 0) + count
        if total > bound:
            raise CompileError(
                f"{element.path}: {what} makes {total:,} {_UNITS[limit]} in the model, more "
                f"than the limit of {bound:,} (CompileLimits.{limit}); "
                f"{_raise_hint('CompileLimits', limit)}", path=element.path)


def allocations(model: ModelBase) -> Iterator[tuple[Element, str, str, int]]:
    """What compiling ``model`` allocates beyond its bytes: (the element, the CompileLimits
    field counting it, which attributes say so as text, the count), in document order."""
    facts = grammar_facts().allocations
    # elements with children inside copies: (how many times each is compiled, the innermost
    # copier, the limit counting its copies, what it says), for their children to inherit
    copied: dict[Element, tuple[int, Element, str, str]] = {}
    for element in _tree.iter_composed(model, True):
        parent = _tree.parent_of(element)
        found = None if parent is None else copied.get(parent)
        times = 1
        allocation = facts.get(element.spec.row)
        if found is not None:
            times, copier, limit, said = found
            if allocation is None or allocation.copies is None:  # (a copier is not kept)
                yield copier, limit, said, times - 1
        if allocation is not None:
            if allocation.copies is not None:
                count = _whole(resolve(element, allocation.copies))
                if count > 1:
                    times *= count
                    said = (f"{allocation.copies}={count} (what it holds compiled "
                            f"{times:,} times)")
                    found = (times, element, allocation.limit, said)
            for what, count in _counts(element, allocation):
                yield element, allocation.limit, what, count * times
        if found is not None and _tree.children(element):
            copied[element] = found


def totals(model: ModelBase) -> dict[str, int]:
    """The model's count for each field of :class:`CompileLimits`."""
    found: dict[str, int] = dict.fromkeys(_COMPILE_FIELDS, 0)
    for _, limit, _, count in allocations(model):
        found[limit] += count
    return found


def _counts(element: Element, allocation: Allocation) -> list[tuple[str, int]]:
    """What ``element`` allocates: (which attributes say so, as text; the count)."""
    found: list[tuple[str, int]] = []
    attributes = element.spec.by_key
    generator = attributes.get(allocation.generator)
    kind = None if generator is None else resolve(element, generator.name)
    if allocation.sizes and (generator is None or str(kind) != generator.default):
        sizes = [_whole(resolve(element, name)) for name in allocation.sizes]
        shape = (str(resolve(element, allocation.shape)) if allocation.shape in attributes
                 else None)
        said = ", ".join(f"{name}={_said(element, name, size)}"
                         for name, size in zip(allocation.sizes, sizes, strict=True))
        if shape in allocation.cubes:
            found.append((f"{said} (a {shape}: {_FACES} faces of {sizes[0]} x {sizes[0]})",
                          _FACES * sizes[0] * sizes[0]))
        else:
            found.append((said, math.prod(sizes)))
    builtin = (allocation.builtins or {}).get(str(kind))
    if builtin is not None and allocation.values is not None:
        found.append(_generated(element, allocation.values, str(kind), builtin))
    for name in allocation.images:
        attribute = attributes.get(name)
        value = None if attribute is None else _tree.read_value(element, attribute)
        if attribute is None or value is None:
            continue
        size = _png_size(_file_bytes(element, attribute, value))
        if size is not None:
            said = f"{attribute.py_name}={_shown(value)} (a PNG of {size[0]} x {size[1]})"
            found.append((said, size[0] * size[1]))
    return found


def _generated(element: Element, values: str, kind: str,
               builtin: GeneratedShape) -> tuple[str, int]:
    """What a generated shape allocates: (its parameters named, as text; the count)."""
    numbers = _numbers(resolve(element, values))
    given = dict(zip(builtin.params, numbers, strict=False))
    count = builtin.factor * math.prod(_whole(given.get(name, 0)) for name in builtin.counts)
    shown = ", ".join(f"{name} {_text(given[name])}" for name in dict.fromkeys(builtin.counts)
                      if name in given)
    return f"{values}={' '.join(map(_text, numbers))!r} (a {kind} of {shown})", count


def _numbers(value: object) -> list[float]:
    return [float(v) for v in value] if isinstance(value, np.ndarray) else []


def _text(number: float) -> str:
    return str(int(number)) if number.is_integer() else repr(number)


def _said(element: Element, name: str, size: int) -> str:
    numbers = _numbers(resolve(element, name))
    return " ".join(map(_text, numbers)) if numbers else str(size)


def _whole(value: object) -> int:
    """A count MuJoCo reads from ``value`` (a whole number, or the product of an array's; 0
    for anything else)."""
    if isinstance(value, np.ndarray):
        return math.prod(_whole(v) for v in value.tolist())
    if isinstance(value, float) and math.isfinite(value):
        value = int(value)
    return value if isinstance(value, int) and value > 0 else 0


def _shown(value: object) -> str:
    return "an Asset" if isinstance(value, Asset) else repr(value)


def _file_bytes(element: Element, attribute: AttributeSpec, value: object) -> bytes:
    """The file's contents, read where the model reads it (in memory, else confined)."""
    if isinstance(value, Asset):
        return value.contents
    model = _tree.model_of(element)
    assert model is not None and isinstance(value, str)
    return file_contents(element, attribute, value, model, compiler_folders(model),
                     CollectedFiles())


def _png_size(contents: bytes) -> tuple[int, int] | None:
    """A PNG's declared width and height (its IHDR chunk, first by the format's rule)."""
    if not contents.startswith(_PNG) or contents[12:16] != b"IHDR" or len(contents) < 24:
        return None
    return int.from_bytes(contents[16:20], "big"), int.from_bytes(contents[20:24], "big")


def check_steps(seconds: float, timestep: float, limits: RenderLimits) -> int:
    """The steps of ``seconds`` of simulation; :class:`RenderError` past the limit."""
    steps = round(seconds / timestep) if timestep > 0 else 0
    if steps > limits.max_steps:
        raise RenderError(
            f"render: time={seconds!r} at the model's timestep of {timestep!r} s is {steps:,} "
            f"steps, more than the limit of {limits.max_steps:,} (RenderLimits.max_steps); "
            f"{_raise_hint('RenderLimits', 'max_steps')}")
    return steps


def check_offscreen(picture: tuple[int, int], model_size: tuple[int, int],
                    limits: RenderLimits) -> None:
    """:class:`RenderError` when the offscreen buffer (each side the larger of the
    picture's and the model's ``offwidth``/``offheight``) would pass the limit."""
    width, height = max(picture[0], model_size[0]), max(picture[1], model_size[1])
    if width * height <= limits.max_offscreen_pixels:
        return
    raise RenderError(
        f"render: the offscreen buffer for a picture of {picture[0]} x {picture[1]} with the "
        f"model's <visual><global offwidth={model_size[0]} offheight={model_size[1]}> is "
        f"{width} x {height}, {width * height:,} "
        f"pixels, more than the limit of {limits.max_offscreen_pixels:,} "
        f"(RenderLimits.max_offscreen_pixels); "
        f"{_raise_hint('RenderLimits', 'max_offscreen_pixels')}")

