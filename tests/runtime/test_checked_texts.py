"""Number codecs remember the texts they have checked (models repeat "0 0 1" many times),
and keyword codecs take the grammar's spelling without looking further: neither may accept
anything the full check refuses."""

from __future__ import annotations

import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.codecs import (
    _CHECKED_LENGTH,
    _CHECKED_TEXTS,
    ArrayCodec,
    BoolCodec,
    KeywordCodec,
    RealCodec,
    Rejected,
)
from typed_mjcf.errors import ParseError


def test_a_text_checked_by_one_codec_is_checked_again_by_another() -> None:
    double, single = RealCodec(single=False), RealCodec(single=True)
    assert double.parse("1e39") == "1e39"
    assert double.parse("1e39") == "1e39"  # remembered
    with pytest.raises(Rejected, match="float32"):
        single.parse("1e39")
    three, four = ArrayCodec("real", "double", 3, 3), ArrayCodec("real", "double", 4, 4)
    assert three.parse("0 0 1") == "0 0 1"
    with pytest.raises(Rejected):
        four.parse("0 0 1")


def test_refused_texts_are_refused_every_time() -> None:
    codec = ArrayCodec("real", "double", 3, 3)
    for _ in range(3):
        with pytest.raises(Rejected):
            codec.parse("0 0 1_0")
    real = RealCodec(single=False)
    for _ in range(3):
        with pytest.raises(Rejected):
            real.parse("１")  # a non-ASCII digit, which Python's float takes


def test_the_memory_of_checked_texts_is_bounded() -> None:
    codec = RealCodec(single=False)
    for i in range(_CHECKED_TEXTS + 100):
        assert codec.parse(str(i)) == str(i)
    assert len(codec.checked) == _CHECKED_TEXTS
    long_text = "1" * (_CHECKED_LENGTH + 1)
    fresh = RealCodec(single=False)
    assert fresh.parse(long_text) == long_text
    assert long_text not in fresh.checked


def test_keywords_and_bools_keep_their_exact_spelling() -> None:
    keyword = KeywordCodec(("hinge", "slide"))
    assert keyword.parse("hinge") == "hinge"
    with pytest.raises(Rejected, match="spells"):
        keyword.parse("Hinge")
    boolean = BoolCodec()
    assert boolean.parse("true") is True
    assert boolean.parse("false") is False
    with pytest.raises(Rejected, match="spells"):
        boolean.parse("True")


def test_a_model_refuses_at_load_what_another_attribute_took() -> None:
    ok = '<mujoco><worldbody><geom size="1e39"/></worldbody></mujoco>'
    assert mjcf.from_xml_string(ok).worldbody.geom[0].size.tolist() == [1e39]
    bad = '<mujoco><worldbody><geom size="1" rgba="1e39 0 0 1"/></worldbody></mujoco>'
    with pytest.raises(ParseError, match="line 1"):
        mjcf.from_xml_string(bad)
