# Generated from src/typed_mjcf/_releases/facts.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Facts about MJCF as a whole that differ between the MuJoCo releases covered, applied for
the release in use (``typed_mjcf._releases.gating.RELEASE``) once, at import.

The generated table (from ``schema/releases/behaviour.toml``) says from which release on each
fact holds; here each fact the runtime knows is turned into what the runtime does without
it. Nothing asks for a release number: a release lacking a fact gets the older behaviour.
"""
from __future__ import annotations
from typing import Final
from typed_mjcf._releases.gating import RELEASE, needs_at_least, version_key
UNDERFLOWING_NUMBERS: Final = "underflowing_numbers"
ASSET_CACHE_CHECKS_CONTENTS: Final = "asset_cache_checks_contents"
KNOWN: Final = (UNDERFLOWING_NUMBERS, ASSET_CACHE_CHECKS_CONTENTS)

def has(fact: str, release: str = RELEASE) -> bool: ...

def needs(fact: str) -> str:
    """"needs MuJoCo >= X; installed Y" for a fact the release in use lacks."""
    ...

def apply(release: str = RELEASE) -> None:
    """Follow ``release``'s facts (the release in use; tests pass another to see its
    behaviour on any MuJoCo, then call it again without one)."""
    ...

def clears_asset_cache() -> bool:
    """Whether compile() starts from an empty MuJoCo asset cache."""
    ...
