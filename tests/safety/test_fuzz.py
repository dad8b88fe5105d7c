"""Fuzzing the parser with mutated real MJCF: only the library's errors may escape.

The seeds are the MJCF models shipped in the installed ``dm_control`` and ``mujoco``
packages (found at test time, as in ``tests/runtime/test_corpus.py``). Each example takes
one model and applies one or more mutations: byte flips, truncation, renamed tags and
attributes, changed, swapped or deleted values, duplicated, moved or deleted elements and
deleted closing tags. Then:

- reading it either succeeds or raises a :class:`typed_mjcf.MjcfError` (never a raw lxml
  error, ``KeyError``, ``RecursionError``, ...), and not the parser's safety net for
  unexpected exceptions (whose message starts "internal error" or names an exception);
- whatever is read exports to MJCF that reads again and exports to the same text.

Hypothesis runs derandomized (the same examples every run), so the test is reproducible;
``FUZZ_EXAMPLES`` sets how many (default 500, a few seconds).
"""

from __future__ import annotations

import os
import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import typed_mjcf
from tests.support.mutations import MUTATIONS, SEEDS
from typed_mjcf.errors import MjcfError

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "500"))

def test_seeds_are_found() -> None:
    assert len(SEEDS) > 20


@settings(max_examples=EXAMPLES, derandomize=True, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.sampled_from(range(len(SEEDS))),
       mutations=st.lists(st.sampled_from(sorted(MUTATIONS)), min_size=1, max_size=3),
       rng=st.randoms(use_true_random=False))
def test_mutated_mjcf_raises_only_library_errors(seed: int, mutations: list[str],
                                                 rng: random.Random) -> None:
    ident, path, data = SEEDS[seed]
    for mutation in mutations:
        data = MUTATIONS[mutation](data, rng)
    try:
        model = typed_mjcf.from_xml_string(data, base_dir=path.parent, source=ident)
    except MjcfError as error:
        assert error.__cause__ is None or isinstance(error.__cause__, MjcfError), (
            f"{ident} {mutations}: an unexpected exception reached the safety net: "
            f"{error.__cause__!r}")
        return
    xml = model.to_xml_string()
    again = typed_mjcf.from_xml_string(xml, base_dir=path.parent)
    assert again.to_xml_string() == xml, (ident, mutations)


@pytest.mark.parametrize("mutation", sorted(MUTATIONS))
def test_every_mutation_changes_something(mutation: str) -> None:
    """The mutations do mutate (a broken mutation would make the fuzz test vacuous)."""
    _, _, data = next(s for s in SEEDS if s[0] == "dm_control/suite/cartpole.xml")
    rng = random.Random(0)
    assert any(MUTATIONS[mutation](data, rng) != data for _ in range(10))


def test_section_holding_only_empty_sections_exports_as_a_fixed_point() -> None:
    """Regression: found by this fuzzer (<option><flag/></option> was written <option/>)."""
    model = typed_mjcf.from_xml_string("<mujoco><option><flag/></option></mujoco>")
    xml = model.to_xml_string()
    assert typed_mjcf.from_xml_string(xml).to_xml_string() == xml
