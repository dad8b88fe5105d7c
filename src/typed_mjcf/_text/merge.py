"""Global settings both an attached model and its parent set: combined by the setting's rule
(``schema/facts.toml``'s ``merge_rules``: dm_control's conflict behaviours) when it has one."""

from __future__ import annotations

import re

from typed_mjcf._core.tree import Element, grammar_facts

_BYTES = re.compile(r"(\d+)\s*([KMGT]?)", re.IGNORECASE)
_UNITS = {"": 1, "k": 1 << 10, "m": 1 << 20, "g": 1 << 30, "t": 1 << 40}


def _bytes(text: object) -> int | None:
    match = _BYTES.fullmatch(str(text).strip())
    return None if match is None else int(match.group(1)) * _UNITS[match.group(2).lower()]


def combine(rule: str, mine: object, theirs: object) -> object:
    """Two values of a setting both models set, combined by its rule (``None``: no way)."""
    if rule == "max-bytes":
        a, b = _bytes(mine), _bytes(theirs)
        return None if a is None or b is None else str(max(a, b))
    if isinstance(mine, int | float) and isinstance(theirs, int | float):
        return min(mine, theirs) if rule == "min" else max(mine, theirs)
    return None


def rule_of(section: Element, name: str) -> str | None:
    """The rule combining two values of ``section``'s attribute ``name``, if any."""
    return grammar_facts().merge_rules.get(f"{section.spec.tag}@{name}")
