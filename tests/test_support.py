"""Test modules share helpers through ``tests/support/`` (or a helper module of their own
folder): no module imports a ``test_*.py`` module, so each test module can be read, moved and
run on its own."""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent


def imported_test_modules(path: Path, text: str) -> list[str]:
    """The ``test_*.py`` modules of ``tests`` that ``text`` (the file ``path``) imports,
    anywhere in it: absolute, relative, or inside a function."""
    package = path.relative_to(TESTS.parent).parts[:-1]
    found: set[str] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = package[:len(package) - node.level + 1] if node.level else ()
            module = ".".join([*base, *([node.module] if node.module else [])])
            found |= {module} | {f"{module}.{alias.name}" for alias in node.names}
    return sorted(name for name in found
                  if name.split(".")[0] == TESTS.name
                  and name.rsplit(".", 1)[-1].startswith("test_")
                  and (TESTS.parent / Path(*name.split("."))).with_suffix(".py").is_file())


def test_no_module_imports_a_test_module() -> None:
    found = [f"{path.relative_to(TESTS).as_posix()} imports {name}"
             for path in sorted(TESTS.rglob("*.py"))
             for name in imported_test_modules(path, path.read_text(encoding="utf-8"))]
    assert not found, found


def test_the_check_sees_each_way_of_importing() -> None:
    path = TESTS / "cli" / "probe.py"
    cases = {"from tests.runtime.test_io import x\n": ["tests.runtime.test_io"],
             "from ..runtime.test_io import x\n": ["tests.runtime.test_io"],
             "from . import test_cli\n": ["tests.cli.test_cli"],
             "def f():\n    import tests.cli.test_cli\n": ["tests.cli.test_cli"],
             "from tests.support.corpus import CORPUS\n": []}
    for text, expected in cases.items():
        assert imported_test_modules(path, text) == expected, text
