"""The type checkers' runs over the typed code, shared by the modules that read them."""

from __future__ import annotations

import pytest

from tests.typing.test_typecheck import Checker, Diagnostic, run_typed_code


@pytest.fixture(scope="session")
def typed_code_reports(tmp_path_factory: pytest.TempPathFactory
                       ) -> dict[Checker, list[Diagnostic]]:
    """One mypy and one pyright run per session (tests/conftest.py keeps the modules that use
    it on one pytest-xdist worker: ``GROUPS``)."""
    return run_typed_code(tmp_path_factory.mktemp("mypy_cache"))
