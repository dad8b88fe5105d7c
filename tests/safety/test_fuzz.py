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

import copy
import os
import random
import re
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

import typed_mjcf
from typed_mjcf._core.tree import element_classes
from typed_mjcf.errors import MjcfError

from ..runtime.test_corpus import corpus

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "500"))

SEEDS: list[tuple[str, Path, bytes]] = [(ident, path, path.read_bytes()) for ident, path in corpus()]
TAGS = sorted({cls.spec.tag for cls in element_classes().values()} | {"include"})
ATTRIBUTES = sorted({a.name for cls in element_classes().values()
                     for a in cls.spec.attributes.values()})
VALUES = [
    "", " ", "nan", "NaN", "inf", "-inf", "1e400", "-1e400", "1e-400", "0x10", "1_000",
    "\u0661\u0662", "1,2", "true", "false", "TRUE", "2147483648", "-2147483649",
    "99999999999999999999999", "1 2 3 4 5 6 7 8 9 10 11 12 13", "0 0 0 0", "-", ".", "e",
    "1e", "+1", "1.5", "-0", " 1 ", "\t1\n2", "a/b", "world", "main", "\u00e9",
    "\u202e", "x" * 300, "&amp;", "<", "'\"", "0 0 0 0 0 0 0", "1 0 0 0", "-1 -1 -1",
]
Mutation = Callable[[bytes, random.Random], bytes]
_CLOSING = re.compile(rb"</[A-Za-z_][\w.-]*\s*>")


def _elements(root: etree._Element) -> list[etree._Element]:
    return [e for e in root.iter() if isinstance(e.tag, str)]


def _misspell(word: str, rng: random.Random) -> str:
    i = rng.randrange(len(word) + 1)
    choice = rng.randrange(3)
    if choice == 0 and word:
        return word[:i] + word[i + 1:] or "x"
    if choice == 1:
        return word[:i] + rng.choice("abcdefghijklmnopqrstuvwxyz_") + word[i:]
    return word.upper()


def byte_flips(data: bytes, rng: random.Random) -> bytes:
    buffer = bytearray(data)
    for _ in range(rng.randint(1, 6)):
        if buffer:
            buffer[rng.randrange(len(buffer))] = rng.randrange(256)
    return bytes(buffer)


def truncate(data: bytes, rng: random.Random) -> bytes:
    return data[:rng.randrange(len(data) + 1)]


def delete_closing_tag(data: bytes, rng: random.Random) -> bytes:
    matches = list(_CLOSING.finditer(data))
    if not matches:
        return data
    match = rng.choice(matches)
    return data[:match.start()] + data[match.end():]


def _tree_mutation(data: bytes, rng: random.Random, kind: str) -> bytes:
    try:
        root = etree.fromstring(data, etree.XMLParser(resolve_entities=False, no_network=True,
                                                      load_dtd=False))
    except etree.XMLSyntaxError:
        return data
    elements = _elements(root)
    element = rng.choice(elements)
    if kind == "tag":
        element.tag = rng.choice(TAGS) if rng.random() < 0.7 else _misspell(str(element.tag), rng)
    elif kind == "attribute":
        if element.attrib:
            name = rng.choice(sorted(element.attrib))
            value = element.attrib.pop(name)
            new = rng.choice(ATTRIBUTES) if rng.random() < 0.7 else _misspell(name, rng)
            element.set(new, value)
        else:
            element.set(rng.choice(ATTRIBUTES), rng.choice(VALUES))
    elif kind == "value":
        if element.attrib:
            name = rng.choice(sorted(element.attrib))
            other = rng.choice(elements).attrib
            donor = [str(v) for v in other.values()]
            element.set(name, rng.choice(VALUES + donor))
    elif kind == "same_attribute":  # a value another element has for that attribute
        if element.attrib:
            name = rng.choice(sorted(element.attrib))
            donors = [str(e.get(name)) for e in elements if e.get(name) is not None]
            element.set(name, rng.choice(donors))
    elif kind == "delete_attribute":
        if element.attrib:
            del element.attrib[rng.choice(sorted(element.attrib))]
    elif kind == "delete":
        parent = element.getparent()
        if parent is not None:
            parent.remove(element)
    elif kind == "duplicate":
        parent = element.getparent()
        if parent is not None:
            parent.insert(parent.index(element) + 1, copy.deepcopy(element))
    elif kind == "move":
        parent = element.getparent()
        target = rng.choice(elements)
        if parent is not None and element not in list(target.iterancestors()) and target is not element:
            target.append(element)
    return etree.tostring(root)


def _tree(kind: str) -> Mutation:
    return lambda data, rng: _tree_mutation(data, rng, kind)


MUTATIONS: dict[str, Mutation] = {
    "byte_flips": byte_flips,
    "truncate": truncate,
    "delete_closing_tag": delete_closing_tag,
    "rename_tag": _tree("tag"),
    "rename_attribute": _tree("attribute"),
    "change_value": _tree("value"),
    "swap_value": _tree("same_attribute"),
    "delete_attribute": _tree("delete_attribute"),
    "duplicate_element": _tree("duplicate"),
    "delete_element": _tree("delete"),
    "move_element": _tree("move"),
}


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
