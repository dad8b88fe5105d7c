"""Keywords MuJoCo's reader also takes as numbers (``<headlight active="1">``, the spelling
every 3.x file uses): parsing and assignment take exactly what the installed MuJoCo reads,
store the keyword, and export writes that keyword, which MuJoCo compiles the same.

The facts are the grammar's (``numbers`` of an attribute in schema/mjcf.json, probed by
codegen/drift.py); tests/codegen/test_type_drift.py holds them against the reader.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.codecs import KeywordCodec
from typed_mjcf._core.tree import element_classes
from typed_mjcf.errors import MjcfError

HEADLIGHT = '<mujoco><visual><headlight active="{}"/></visual></mujoco>'


def _saved(xml: str) -> bytes:
    model = mujoco.MjModel.from_xml_string(xml)
    buffer = np.zeros(mujoco.mj_sizeModel(model), np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer.tobytes()


def _numbered() -> list[tuple[str, str, tuple[tuple[str, int], ...]]]:
    """(class, attribute, numbers) of every keyword attribute taking numbers."""
    return [(name, a.name, a.numbers) for name, cls in sorted(element_classes().items())
            for a in cls.spec.attributes.values() if a.numbers]


def test_the_grammar_has_numeric_spellings_and_their_codecs_take_them() -> None:
    found = _numbered()
    assert ("headlight", "active", (("false", 0), ("true", 1), ("auto", 2))) in \
        [(c.lower(), n, v) for c, n, v in found]
    for cls_name, name, numbers in found:
        codec = element_classes()[cls_name].spec.attributes[name].codec
        assert isinstance(codec, KeywordCodec)
        assert {codec.parse(str(n)) for _, n in numbers} == {k for k, _ in numbers}


@pytest.mark.parametrize(("text", "keyword"), [
    ("0", "false"), ("1", "true"), ("2", "auto"), ("01", "true"), ("+1", "true"),
    (" 2 ", "auto"), ("-0", "false")])
def test_a_number_is_read_as_its_keyword_and_compiles_the_same(text: str, keyword: str) -> None:
    xml = HEADLIGHT.format(text)
    model = mjcf.from_xml_string(xml)
    assert model.visual.headlight.active == keyword
    written = model.to_xml_string()
    assert f'active="{keyword}"' in written  # the canonical spelling
    assert _saved(written) == _saved(xml) == _saved(HEADLIGHT.format(keyword))


@pytest.mark.parametrize("text", ["0", "1", "2", " 1", "00002", "3", "-1", "1.0", "1e0",
                                  "1_0", "True", "AUTO", " auto", "0x1", "1 2"])
def test_a_file_is_read_exactly_as_mujoco_reads_it(text: str) -> None:
    """typed-mjcf's verdict on the text is MuJoCo's: read (as the same model) or refused."""
    xml = HEADLIGHT.format(text)
    try:
        theirs: bytes | None = _saved(xml)
    except ValueError:
        theirs = None
    try:
        written: str | None = mjcf.from_xml_string(xml).to_xml_string()
    except MjcfError as error:
        assert str(error).startswith("line 1: visual/headlight: ") and "active" in str(error)
        written = None
    assert (written is None) == (theirs is None), (text, written, theirs is None)
    if written is not None:
        assert _saved(written) == theirs


@pytest.mark.parametrize(("value", "keyword"), [
    (0, "false"), (1, "true"), (2, "auto"), ("1", "true"), (np.int64(2), "auto")])
def test_assignment_takes_the_numbers_mujoco_reads(value: object, keyword: str) -> None:
    model = mjcf.RootElement()
    model.visual.headlight.active = value  # type: ignore[assignment]  # numbers: untyped
    assert model.visual.headlight.active == keyword


@pytest.mark.parametrize("value", [3, -1, "3", 1.0, " auto", "x"])
def test_a_refused_number_names_what_was_expected_and_changes_nothing(value: object) -> None:
    model = mjcf.RootElement()
    headlight = model.visual.headlight
    headlight.active = "false"
    with pytest.raises(MjcfError) as raised:
        headlight.active = value  # type: ignore[assignment]
    message = str(raised.value)
    assert message.startswith("visual/headlight: ") and "active" in message
    assert repr(value) in message and "'false', 'true', 'auto' (or 0, 1, 2)" in message
    assert headlight.active == "false"
