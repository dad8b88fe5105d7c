"""``[language]`` travels generically: typed_mjcf._core.language declares each fact once, and
codegen/language.py reads, stores and renders whatever that declaration has."""

from __future__ import annotations

import dataclasses
import os
import shutil
import subprocess
import sys
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Literal

import pytest

from codegen import ir, language
from codegen.facts import FactsError, load_facts
from typed_mjcf._core.language import FROM_GRAMMAR, GrammarFacts, KeyframeFacts
from typed_mjcf._core.tree import grammar_facts


def _table() -> dict[str, object]:
    raw = tomllib.loads((ir.SCHEMA_DIR / "facts.toml").read_text(encoding="utf-8"))
    return dict(raw["language"])


def test_the_generated_facts_are_facts_toml_language() -> None:
    """What the runtime reads is the table as declared: no field dropped on the way."""
    facts = load_facts().language
    assert facts is not None
    assert grammar_facts() == dataclasses.replace(facts, root=ir.load().root)
    table = _table()
    declared = {f.name for f in dataclasses.fields(GrammarFacts) if f.metadata != FROM_GRAMMAR}
    assert set(table) == declared
    assert grammar_facts().replicate_copy == table["replicate_copy"]


def test_the_schema_stores_the_facts_and_reads_them_back() -> None:
    schema = ir.load()
    assert ir.loads(ir.dumps(schema)).language == schema.language == grammar_facts()


# A declaration with one fact more, as a maintainer would add it to GrammarFacts.
Extended = dataclasses.make_dataclass(
    "Extended", [("mirrored", frozenset[str]), ("limits", Mapping[str, Literal["lo", "hi"]]),
                 ("note", "str | None", dataclasses.field(default=None))],
    bases=(GrammarFacts,), frozen=True, kw_only=True)


def test_a_new_fact_is_read_stored_and_rendered_without_naming_it() -> None:
    table = {**_table(), "mirrored": ["joint", "site"], "limits": {"geom@size": "hi"}}
    facts = language.read_table(Extended, table, "f.toml: [language]")
    assert facts.mirrored == frozenset({"joint", "site"})
    assert facts.limits == {"geom@size": "hi"}
    assert facts.note is None  # typed `str | None`: may be left out
    assert language.read_table(Extended, language.to_plain(facts), "json") == facts
    namespace = {"Extended": Extended, "KeyframeFacts": KeyframeFacts,
                 **{name: getattr(language.declaration, name) for name in language.classes()}}
    rendered = eval(language.source(facts), namespace)  # the generated tables' expression
    assert rendered == facts


@pytest.mark.parametrize(("change", "message"), [
    ({"mirrored": None}, "f.toml: [language]: missing key 'mirrored' (a list of strings)"),
    ({"mirrored": "joint"}, ("f.toml: [language] mirrored: expected a list of strings, got "
                            "'joint'")),
    ({"mirrored": ["joint", 1]}, ("f.toml: [language] mirrored: expected a list of strings, "
                                 "got ['joint', 1]")),
    ({"limits": {"geom@size": "max"}}, ("f.toml: [language] limits geom@size: expected one of "
                                       "'lo', 'hi', got 'max'")),
    ({"limits": ["lo"]}, "f.toml: [language] limits: expected a table, got ['lo']"),
    ({"note": 3}, "f.toml: [language] note: expected a string, got 3"),
    ({"main_class": True}, "f.toml: [language] main_class: expected a string, got True"),
    ({"keyframe": {"qpos": "qpos"}}, ("f.toml: [language] keyframe: missing key 'qvel' (a "
                                     "string)")),
    ({"mirroed": []}, "f.toml: [language]: unknown key 'mirroed' (known keys: "),
])
def test_a_mistake_is_one_line_naming_the_key_and_what_was_expected(
        change: dict[str, object], message: str) -> None:
    table = {**_table(), "mirrored": ["joint"], "limits": {}}
    table.update({k: v for k, v in change.items() if v is not None})
    for key in [k for k, v in change.items() if v is None]:
        del table[key]
    with pytest.raises(FactsError) as info:
        language.read_table(Extended, table, "f.toml: [language]")
    assert str(info.value).startswith(message) and "\n" not in str(info.value)


def _run(copy: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": f"{copy}{os.pathsep}{copy / 'src'}"}
    return subprocess.run([sys.executable, *argv], cwd=copy, env=env, capture_output=True,
                          text=True, timeout=600, check=False)


def test_a_new_fact_goes_from_facts_toml_to_the_runtime(tmp_path: Path) -> None:
    """CONTRIBUTING's recipe on a copy of the repository: one field in GrammarFacts, one key
    in facts.toml, `python -m codegen generate`; the runtime then has the fact. Before the
    key is written the generator says what is missing in one line, although the generated
    package, stale, no longer imports."""
    root = Path(__file__).resolve().parents[2]
    copy = tmp_path / "repo"
    for part in ("codegen", "schema", "generated"):
        shutil.copytree(root / part, copy / part)
    shutil.copytree(root / "src", copy / "src", symlinks=True)
    shutil.copy(root / "pyproject.toml", copy / "pyproject.toml")  # the pins generate checks
    declaration = copy / "src" / "typed_mjcf" / "_core" / "language.py"
    text = declaration.read_text(encoding="utf-8")
    declaration.write_text(text.replace(
        "    keyframe: KeyframeFacts\n",
        "    keyframe: KeyframeFacts\n    mirrored: frozenset[str]  # a new fact\n"),
        encoding="utf-8")
    assert "mirrored" in declaration.read_text(encoding="utf-8")

    missing = _run(copy, "-m", "codegen", "generate")
    assert missing.returncode == 2, missing.stderr
    assert missing.stderr.strip().splitlines() == [
        "python -m codegen: error: " + str(copy / "schema" / "facts.toml")
        + ": [language]: missing key 'mirrored' (a list of strings)"]
    assert _run(copy, "-c", "import typed_mjcf").returncode != 0  # stale: no such field yet

    facts = copy / "schema" / "facts.toml"
    facts.write_text(facts.read_text(encoding="utf-8").replace(
        "[language]\n", '[language]\nmirrored = ["joint", "site"]\n', 1), encoding="utf-8")
    done = _run(copy, "-m", "codegen", "generate")
    assert done.returncode == 0, done.stderr
    used = _run(copy, "-c", "from typed_mjcf._core.tree import grammar_facts; "
                            "print(sorted(grammar_facts().mirrored))")
    assert used.stdout.strip() == "['joint', 'site']", used.stderr
