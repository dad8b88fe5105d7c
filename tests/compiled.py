"""What a test cannot do to the compiled build (``nox -s tests_compiled``): patch a compiled
module's function, constant or class attribute, since compiled callers bind those when they
are compiled. Such a test checks the source's structure (every route goes through one
function), which the pure-Python run (``nox -s tests``) checks; the compiled run skips it."""

from __future__ import annotations

import pytest

import typed_mjcf


def patches(module: str) -> pytest.MarkDecorator:
    """Skip in the build where ``typed_mjcf.<module>`` is compiled."""
    return pytest.mark.skipif(
        f"typed_mjcf.{module}" in typed_mjcf.COMPILED,
        reason=f"patches typed_mjcf.{module}, compiled in this build (its callers do not see "
               "a patch); the pure-Python run checks it")
