# Generated from src/typed_mjcf/variation/__init__.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Typed randomisation: distributions on attributes, drawn per world, and structural
variants built, validated, exported and compiled on local processes or Ray.

    from typed_mjcf.variation import Variation, uniform, choice

    v = Variation()
    v.of(geom).friction = uniform((0.5, 0.005, 1e-4), (1.5, 0.01, 1e-3))  # checked as friction
    v.of(geom).type = choice(["box", "sphere"])
    draws = v.draw(seed=0, n=1000)  # Drawn(element, attribute, values), values[i]: world i

World ``i``'s values depend only on ``(seed, i)``. Imports nothing heavy (Ray on first use).
"""
from typed_mjcf.variation._apply import compile_worlds, world_model
from typed_mjcf.variation._distributions import (
    Distribution,
    choice,
    log_uniform,
    normal,
    uniform,
)
from typed_mjcf.variation._drawn import Drawn, Draws
from typed_mjcf.variation._record import Variation, world_rng
from typed_mjcf.variation._structural import (
    Variant,
    VariantError,
    generate,
    structure_rng,
    variants,
)
__all__ = [
    "Distribution",
    "Drawn",
    "Draws",
    "Variant",
    "VariantError",
    "Variation",
    "choice",
    "compile_worlds",
    "generate",
    "log_uniform",
    "normal",
    "structure_rng",
    "uniform",
    "variants",
    "world_model",
    "world_rng",
]
