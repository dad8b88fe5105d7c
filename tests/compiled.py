"""What a test cannot do to the compiled build (``nox -s tests_compiled``): patch a compiled
module's function, constant or class attribute, since compiled callers bind those when they
are compiled. Such a test checks the source's structure (every route goes through one
function), which the pure-Python run (``nox -s tests``) checks; the compiled run skips it.
Nor can it count a compiled module's Python lines (tests/operations.py): there are none."""

from __future__ import annotations

from collections.abc import Collection

import pytest

import typed_mjcf


def patches(module: str) -> pytest.MarkDecorator:
    """Skip in the build where ``typed_mjcf.<module>`` is compiled."""
    return pytest.mark.skipif(
        f"typed_mjcf.{module}" in typed_mjcf.COMPILED,
        reason=f"patches typed_mjcf.{module}, compiled in this build (its callers do not see "
               "a patch); the pure-Python run checks it")


def skip_counting(modules: Collection[str]) -> None:
    """Skip a check that counts the Python lines of ``typed_mjcf.<module>`` for each of
    ``modules`` (tests/operations.py) in the build where one is compiled: its code runs no
    traced line, so the count would leave its work out and the check pass without checking."""
    compiled = [f"typed_mjcf.{module}" for module in sorted(modules)
                if f"typed_mjcf.{module}" in typed_mjcf.COMPILED]
    if compiled:
        pytest.skip(f"compiled build: counts the Python lines of {', '.join(compiled)}, which "
                    "mypyc compiled (they run no traced line); the pure-Python run checks it")
