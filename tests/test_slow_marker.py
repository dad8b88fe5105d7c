"""The lists of tests/conftest.py (SLOW; SPREAD, GROUPS and FIRST, the scheduling's) name
tests that exist."""

import ast

from tests.conftest import FIRST, GROUPS, SLOW, SPREAD, TESTS


def test_every_slow_entry_exists() -> None:
    missing: list[str] = []
    for entry in SLOW:
        module, _, function = entry.partition("::")
        path = TESTS / module
        if not path.is_file():
            missing.append(entry)
        elif function:
            tree = ast.parse(path.read_text(encoding="utf-8"))
            if not any(isinstance(node, ast.FunctionDef) and node.name == function
                       for node in tree.body):
                missing.append(entry)
    assert missing == []


def test_every_scheduling_entry_exists() -> None:
    """SPREAD, GROUPS and FIRST (tests/conftest.py) name test modules that exist."""
    named = {*SPREAD, *GROUPS, *GROUPS.values(), *FIRST}
    assert sorted(m for m in named if not (TESTS / m).is_file()) == []
