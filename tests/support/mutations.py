"""Mutations of real MJCF for the fuzzers (``tests/safety/test_fuzz.py``, ``differential.py``):
the seeds (the corpus models' bytes), and each mutation by name: byte flips, truncation,
renamed tags and attributes, changed, swapped or deleted values, duplicated, moved or deleted
elements and deleted closing tags."""

from __future__ import annotations

import copy
import random
import re
from collections.abc import Callable
from pathlib import Path

from lxml import etree

from tests.support.corpus import corpus
from typed_mjcf._core.tree import element_classes

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
