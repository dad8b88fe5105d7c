"""The ``slow`` list of tests/conftest.py names tests that exist."""

import ast

from tests.conftest import SLOW, TESTS


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
