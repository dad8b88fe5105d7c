"""The generator's one error for a mistake in ``schema/facts.toml``."""

from __future__ import annotations


class FactsError(ValueError):
    """Malformed or inapplicable facts: one line naming the file, the entry and what was
    expected (``python -m codegen`` prints it as it is)."""
