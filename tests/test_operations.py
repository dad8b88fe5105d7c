"""The line counts of the complexity checks (tests/operations.py) say which modules of
typed_mjcf they count, are checked against what ran, and skip where one is compiled."""

from __future__ import annotations

import pytest

import typed_mjcf
from typed_mjcf import _build

from .operations import growth, lines_executed


def test_a_count_of_the_modules_that_ran_is_taken() -> None:
    assert lines_executed(_build.describe, counted=("_build",)) > 0
    assert growth(lambda n: _build.describe, 1, 8, counted=("_build",)) == 1


def test_a_count_naming_a_module_that_ran_no_line_fails() -> None:
    with pytest.raises(AssertionError, match=r"ran no line of this call: \['_model.validate'\]"):
        lines_executed(_build.describe, counted=("_build", "_model.validate"))


def test_a_count_leaving_out_the_modules_that_ran_its_lines_fails() -> None:
    with pytest.raises(AssertionError, match=r"modules not in counted ran more than 5% .*"
                                             r"'_build'"):
        lines_executed(_build.describe, counted=())


def test_a_count_of_a_compiled_module_skips_and_says_so(
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(typed_mjcf, "COMPILED", ("typed_mjcf._build",))
    for count in (lambda: lines_executed(_build.describe, counted=("_build",)),
                  lambda: growth(lambda n: _build.describe, 1, 8, counted=("_build",))):
        with pytest.raises(pytest.skip.Exception,
                           match=r"^compiled build: counts the Python lines of "
                                 r"typed_mjcf._build, which mypyc compiled"):
            count()
