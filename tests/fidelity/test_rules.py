"""Every rule of the validation tables held against MuJoCo: for each (``rule_cases.rules()``,
read from the grammar tables) MuJoCo refuses the model breaking it and the library does too,
with that rule's finding; MuJoCo compiles the nearest legal variants (the "off" value, the
attributes split between a class and the class below it, ...) and the library accepts them.
MuJoCo compiles in a worker process (``tests/support/compile_worker.py``): after some
refusals ("Caught an unknown exception!", a <model> without a file) the next compile in that
process hangs."""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import pytest

import typed_mjcf as mjcf
from tests.support.compile_worker import MujocoWorker
from typed_mjcf._model.validate import validate

from .rule_cases import Rule, cases, rules

# The rule kind -> the rule of validate()'s finding for it.
FINDING_RULE = {"required": "required-attribute", "bounds": "range", "exclusive": "exclusive",
                "together": "together", "requires": "requires", "oneof": "oneof"}


@pytest.fixture(scope="module")
def compile_error() -> Iterator[MujocoWorker]:
    worker = MujocoWorker()
    yield worker
    worker.close()


def _files(tmp_path: Path, xml: str) -> Path:
    (tmp_path / "child.xml").write_text("<mujoco><worldbody><body name='cb'/></worldbody>"
                                        "</mujoco>")  # a <model> asset's file
    path = tmp_path / "model.xml"
    path.write_text(xml)
    return path


def _library_errors(path: Path) -> list[str]:
    """The rules of the library's errors for a file (``load`` when reading refuses it)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = mjcf.from_path(path)
    except mjcf.MjcfError:
        return ["load"]
    return [f.rule for f in validate(model) if f.severity == "error"]


RULES = rules()


def test_every_rule_has_cases() -> None:
    """A new table row (a constraint, a required attribute, a bound) needs a context in
    rule_cases.ROWS: without one this fails, naming the row."""
    assert RULES
    assert [rule.ident for rule in RULES if cases(rule) is None] == []


@pytest.mark.parametrize("rule", RULES, ids=[rule.ident for rule in RULES])
def test_mujoco_and_the_library_refuse_what_the_rule_refuses(
        rule: Rule, compile_error: MujocoWorker, tmp_path: Path) -> None:
    case = cases(rule)
    if case is None:
        pytest.skip("no context in rule_cases.ROWS (test_every_rule_has_cases fails)")
    path = _files(tmp_path, case.refused)
    assert compile_error.compile_file(path) is not None, f"MuJoCo compiles {case.refused}"
    assert FINDING_RULE[rule.kind] in _library_errors(path), case.refused


@pytest.mark.parametrize("rule", RULES, ids=[rule.ident for rule in RULES])
def test_mujoco_and_the_library_accept_the_nearest_legal_variants(
        rule: Rule, compile_error: MujocoWorker, tmp_path: Path) -> None:
    case = cases(rule)
    if case is None:
        pytest.skip("no context in rule_cases.ROWS (test_every_rule_has_cases fails)")
    assert case.accepted
    for what, xml in case.accepted.items():
        path = _files(tmp_path, xml)
        assert compile_error.compile_file(path) is None, f"{what}: MuJoCo refuses {xml}"
        assert _library_errors(path) == [], f"{what}: the library refuses {xml}"
