# Generated from src/typed_mjcf/_text/merge.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Global settings both an attached model and its parent set: combined by the setting's rule
(``schema/facts.toml``'s ``merge_rules``: dm_control's conflict behaviours) when it has one."""
from __future__ import annotations
from typed_mjcf._core.tree import Element, grammar_facts

def combine(rule: str, mine: object, theirs: object) -> object:
    """Two values of a setting both models set, combined by its rule (``None``: no way)."""
    ...

def rule_of(section: Element, name: str) -> str | None:
    """The rule combining two values of ``section``'s attribute ``name``, if any."""
    ...
