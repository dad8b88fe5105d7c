# Generated from src/typed_mjcf/_model/resource_limits.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Bounds on what compiling and rendering a model may allocate, checked before MuJoCo does.

A few bytes of MJCF can make MuJoCo allocate gigabytes (a builtin texture's width and
height, an hfield's rows and columns, a small PNG declaring a huge picture) or step for hours
(a tiny timestep under a long simulated time): :class:`CompileLimits` and
:class:`RenderLimits` bound them as :class:`~typed_mjcf.ParseLimits` bounds reading. Which
elements allocate what is the grammar's ``allocations`` fact (``schema/facts.toml``).
"""
from __future__ import annotations
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Final
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts

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
    max_texture_pixels: int = ...
    max_hfield_samples: int = ...
    max_mesh_vertices: int = ...
    max_flex_points: int = ...
    max_replicated_elements: int = ...
    def __post_init__(self) -> None: ...

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
    max_offscreen_pixels: int = ...
    compile: CompileLimits = field(default_factory=CompileLimits)
    def __post_init__(self) -> None: ...
DEFAULT_COMPILE_LIMITS: Final = CompileLimits()
DEFAULT_RENDER_LIMITS: Final = RenderLimits()

def check_compile(model: ModelBase, limits: CompileLimits) -> None:
    """Raise :class:`CompileError` naming the element, attribute and value that take a
    count of ``limits`` past its bound (the counts are the whole model's)."""
    ...

def allocations(model: ModelBase) -> Iterator[tuple[Element, str, str, int]]:
    """What compiling ``model`` allocates beyond its bytes: (the element, the CompileLimits
    field counting it, which attributes say so as text, the count), in document order."""
    ...

def totals(model: ModelBase) -> dict[str, int]:
    """The model's count for each field of :class:`CompileLimits`."""
    ...

def check_steps(seconds: float, timestep: float, limits: RenderLimits) -> int:
    """The steps of ``seconds`` of simulation; :class:`RenderError` past the limit."""
    ...

def check_offscreen(picture: tuple[int, int], model_size: tuple[int, int],
                    limits: RenderLimits) -> None:
    """:class:`RenderError` when the offscreen buffer (each side the larger of the
    picture's and the model's ``offwidth``/``offheight``) would pass the limit."""
    ...
