"""Facts about MJCF as a whole that differ between the MuJoCo releases covered, applied for
the release in use (``typed_mjcf._releases.gating.RELEASE``) once, at import.

The generated table (from ``schema/releases/behaviour.toml``) says from which release on each
fact holds; here each fact the runtime knows is turned into what the runtime does without
it. Nothing asks for a release number: a release lacking a fact gets the older behaviour.
"""

from __future__ import annotations

from typing import Final

from typed_mjcf._core.codecs import refuse_underflow
from typed_mjcf._generated.release_facts import SINCE
from typed_mjcf._releases.gating import RELEASE, needs_at_least, version_key

# the facts the runtime applies (tests/runtime/test_release_facts.py: the table has these)
UNDERFLOWING_NUMBERS: Final = "underflowing_numbers"  # numbers read as subnormals or zero
ASSET_CACHE_CHECKS_CONTENTS: Final = "asset_cache_checks_contents"  # not by file name alone
KNOWN: Final = (UNDERFLOWING_NUMBERS, ASSET_CACHE_CHECKS_CONTENTS)

# whether compile() clears MuJoCo's asset cache first (the release in use serves a file of
# the virtual file system by its name alone)
_CLEAR_ASSET_CACHE: list[bool] = [False]


def has(fact: str, release: str = RELEASE) -> bool:
    return version_key(release) >= version_key(SINCE[fact])


def needs(fact: str) -> str:
    """"needs MuJoCo >= X; installed Y" for a fact the release in use lacks."""
    return needs_at_least(SINCE[fact])


def apply(release: str = RELEASE) -> None:
    """Follow ``release``'s facts (the release in use; tests pass another to see its
    behaviour on any MuJoCo, then call it again without one)."""
    refuse_underflow(None if has(UNDERFLOWING_NUMBERS, release)
                     else f"reading it {needs(UNDERFLOWING_NUMBERS)}")
    _CLEAR_ASSET_CACHE[0] = not has(ASSET_CACHE_CHECKS_CONTENTS, release)


def clears_asset_cache() -> bool:
    """Whether compile() starts from an empty MuJoCo asset cache."""
    return _CLEAR_ASSET_CACHE[0]
