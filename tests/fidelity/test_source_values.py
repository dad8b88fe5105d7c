"""Numbers read from a file are kept as their checked text (converted when first read, and
written as read when untouched): nothing about that may show, over every corpus model.

- a value a file spells wrong is still refused at load, with its line;
- a value read after load equals the plain conversion of its text (what eager conversion
  gave), type, dtype and bits;
- an untouched value is written exactly as the file spelled it;
- ``canonical=True`` writes what a model whose every value was set in Python writes.
"""

from __future__ import annotations

import re
import string
from pathlib import Path

import mujoco
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from lxml import etree

import typed_mjcf as mjcf
from tests.support.corpus import CORPUS
from typed_mjcf._core import tree as _tree
from typed_mjcf._core.codecs import ArrayCodec, RealCodec
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import Element


def _parseable() -> list[object]:
    params: list[object] = []
    for ident, path in CORPUS:
        try:
            mujoco.MjSpec.from_file(str(path))
        except ValueError:
            continue  # fragments and broken inputs: nothing MuJoCo reads to compare with
        params.append(pytest.param(ident, path, id=ident))
    return params


PARSEABLE = _parseable()


def test_the_corpus_has_models() -> None:
    assert len(PARSEABLE) >= 40


def _kept_texts(model: mjcf.RootElement) -> list[tuple[Element, AttributeSpec, str]]:
    """Every number attribute whose value is still the text read from the file."""
    kept: list[tuple[Element, AttributeSpec, str]] = []
    for element in model.iter_elements():
        stored = _tree.values(element)
        for attribute in element.spec.attributes.values():
            value = stored.get(attribute.name)
            if type(value) is str and isinstance(attribute.codec, ArrayCodec | RealCodec):
                kept.append((element, attribute, value))
    return kept


def _plain_conversion(attribute: AttributeSpec, text: str) -> object:
    """The text converted the obvious way, independently of the codecs."""
    if isinstance(attribute.codec, RealCodec):
        return float(text)
    assert isinstance(attribute.codec, ArrayCodec)
    if attribute.codec.is_int:
        return np.array([int(word) for word in text.split()], dtype=np.int32)
    doubles = np.array([float(word) for word in text.split()], dtype=np.float64)
    return doubles.astype(np.float32) if attribute.codec.single else doubles


@pytest.mark.parametrize(("ident", "path"), PARSEABLE)
def test_values_read_after_load_are_the_plain_conversion(ident: str, path: Path) -> None:
    model = mjcf.from_path(path)
    kept = _kept_texts(model)
    for element, attribute, text in kept:
        read = _tree.read_value(element, attribute)
        expected = _plain_conversion(attribute, text)
        where = f"{ident}: {element.path}@{attribute.name}={text!r}"
        if isinstance(expected, float):
            assert type(read) is float and np.float64(read).tobytes() == np.float64(
                expected).tobytes(), where
        else:
            assert isinstance(read, np.ndarray) and isinstance(expected, np.ndarray), where
            assert read.dtype == expected.dtype and read.tobytes() == expected.tobytes(), where
            assert not read.flags.writeable, where
        # reading again reads the same (the text is not consumed or changed)
        assert _tree.values(element)[attribute.name] == text, where


def _written_attributes(element: Element) -> dict[str, str]:
    start = element.to_xml_string(self_only=True, pretty_print=False)
    node = etree.fromstring(start.encode())
    return {str(k): str(v) for k, v in node.attrib.items()}


@pytest.mark.parametrize(("ident", "path"), PARSEABLE)
def test_untouched_values_are_written_as_read(ident: str, path: Path) -> None:
    model = mjcf.from_path(path)
    by_element: dict[int, list[tuple[AttributeSpec, str]]] = {}
    elements: dict[int, Element] = {}
    for element, attribute, text in _kept_texts(model):
        by_element.setdefault(id(element), []).append((attribute, text))
        elements[id(element)] = element
    for key, kept in by_element.items():
        written = _written_attributes(elements[key])
        for attribute, text in kept:
            assert written[attribute.name] == text, (ident, elements[key].path, attribute.name)


def _set_every_number_in_python(model: mjcf.RootElement) -> None:
    """Assign every number its value read back (names, keywords and the rest are stored
    converted at load: only numbers keep their text)."""
    for element, attribute, _ in _kept_texts(model):
        _tree.assign(element, attribute, _tree.read_value(element, attribute))


@pytest.mark.parametrize(("ident", "path"), PARSEABLE)
def test_canonical_output_is_that_of_values_set_in_python(ident: str, path: Path) -> None:
    loaded = mjcf.from_path(path)
    assigned = mjcf.from_path(path)
    _set_every_number_in_python(assigned)
    assert not _kept_texts(assigned)  # every number is now a value set in Python
    canonical = loaded.to_xml_string(canonical=True)
    assert canonical == assigned.to_xml_string()
    assert canonical == assigned.to_xml_string(canonical=True)


_QUOTED_NUMBERS = re.compile(r'\s(pos|size|rgba|range|quat|axis|fromto)="([^"]*)"')


@pytest.mark.parametrize(("ident", "path"), PARSEABLE)
def test_a_value_the_file_spells_wrong_is_refused_at_load_with_its_line(
        ident: str, path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    found = _QUOTED_NUMBERS.search(text)
    if found is None:
        pytest.skip(f"{ident} spells none of the attributes this test corrupts")
    line = text.count("\n", 0, found.start(2)) + 1
    broken = text[:found.start(2)] + found.group(2) + " 1x" + text[found.end(2):]
    with pytest.raises(mjcf.ParseError) as raised:
        mjcf.from_xml_string(broken, base_dir=path.parent)
    message = str(raised.value)
    assert message.startswith(f"line {line}: ") or f":{line}: " in message, message
    assert f"{found.group(1)}=" in message and "1x" in message, message


# The pattern that lets a number's text be kept must never pass what conversion refuses (the
# file's error would surface late) nor pass a wrong count. It may refuse what converts
# (hexadecimal, inf, very long numbers): those are converted at load instead.
_NUMBERISH = st.text(alphabet=string.digits + " +-.eExX_pinfa\t\n\u0663", max_size=24)


@pytest.mark.parametrize("dtype", ["double", "float"])
@given(text=_NUMBERISH)
def test_kept_text_is_only_text_that_converts(dtype: str, text: str) -> None:
    codec = ArrayCodec("real", dtype, 1, 3)
    if codec.pattern.fullmatch(text) is None:
        return
    converted = codec.from_text(text)  # raises if the pattern let through what it refuses
    assert 1 <= converted.shape[0] <= 3
    assert np.isfinite(converted).all()  # no overflow can hide in a kept text
