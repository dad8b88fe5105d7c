"""schema/releases/behaviour.toml read strictly (codegen/release_facts.py): a mistake names the
file, the fact and what was expected."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from codegen import release_facts
from codegen.errors import FactsError


def _load(tmp_path: Path, text: str) -> dict[str, str]:
    path = tmp_path / "behaviour.toml"
    path.write_text(text, encoding="utf-8")
    return release_facts.load(path)


def test_the_committed_facts_load_and_some_covered_release_has_each() -> None:
    facts = release_facts.load()
    assert facts and release_facts.checked(facts, "99.0.0") == facts


@pytest.mark.parametrize(("text", "expected"), [
    ('[underflowing_numbers]\nsince = "4.0.0"\nwhy = "x"\n', "one key, since"),
    ('underflowing_numbers = "4.0.0"\n', "one key, since"),
    ('[underflowing_numbers]\nsince = 4\n', r"since = 4: expected a release number"),
    ('[underflowing_numbers]\nsince = "four"\n', "expected a release number"),
])
def test_a_malformed_entry_is_refused_naming_it(tmp_path: Path, text: str,
                                                expected: str) -> None:
    with pytest.raises(FactsError, match=rf"behaviour.toml \[underflowing_numbers\]: .*"
                                         rf"{expected}"):
        _load(tmp_path, text)


def test_a_fact_newer_than_the_newest_release_is_refused(tmp_path: Path) -> None:
    facts = _load(tmp_path, '[underflowing_numbers]\nsince = "4.1.0"\n')
    assert release_facts.checked(facts, "4.1.0") == facts
    with pytest.raises(FactsError, match="newer than the newest release covered, 4.0.0"):
        release_facts.checked(facts, "4.0.0")


def test_the_table_is_rendered_as_python_literals() -> None:
    text = release_facts.render_table({"b": "4.0.0", "a": "3.17.0"})
    values = {node.target.id: ast.literal_eval(node.value) for node in ast.parse(text).body
              if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name)
              and node.value is not None}
    assert values == {"SINCE": {"a": "3.17.0", "b": "4.0.0"}}
