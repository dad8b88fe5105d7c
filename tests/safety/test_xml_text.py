"""Strings XML cannot hold (NUL, U+0001, U+FFFE, lone surrogates: anything outside XML 1.0's
``Char`` production) are refused by every string-like attribute, at assignment; every string
accepted is exported and read back as it was."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import typed_mjcf as mjcf
from typed_mjcf._core.tree import element_classes


def _is_xml_char(c: str) -> bool:  # XML 1.0, production [2] Char
    n = ord(c)
    return c in "\t\n\r" or 0x20 <= n <= 0xD7FF or 0xE000 <= n <= 0xFFFD or n >= 0x10000


BAD = ["\x00", "\x01", "\x08", "\x0b", "\x1f", "\ufffe", "\uffff", "\ud800", "\udfff"]
STRINGS = st.text(st.one_of(st.characters(), st.sampled_from([*BAD, "\t", "\n", "\r", "/", "&",
                                                              "<", '"', "'", "\x7f", "\x85"])),
                  min_size=1, max_size=12)


def _model() -> tuple[mjcf.RootElement, dict[str, tuple[mjcf.Element, str]]]:
    """A model with one attribute of each string-like kind, by kind."""
    model = mjcf.RootElement()
    body = model.worldbody.add_body()
    geom = body.add_geom(size=(1,))
    mesh = model.asset.add_mesh()
    text = model.custom.add_text()
    return model, {"id": (body, "name"), "ref": (geom, "material"), "string": (model, "model"),
                   "file": (mesh, "file"), "text": (text, "data")}


def test_every_string_like_kind_is_covered() -> None:
    kinds = {a.kind for cls in element_classes().values() for a in cls.spec.attributes.values()
             if a.kind in ("id", "ref", "string", "file", "chars")}
    assert kinds == {"id", "ref", "string", "file", "chars"}
    _, attributes = _model()
    for element, name in attributes.values():
        assert element.spec.by_name[name].kind in kinds


@pytest.mark.parametrize("bad", BAD)
def test_characters_xml_cannot_hold_are_refused_with_the_standard_message(bad: str) -> None:
    model, attributes = _model()
    for element, name in attributes.values():
        with pytest.raises(mjcf.InvalidValueError,
                           match=rf"invalid {name}=.* on <{element.spec.tag}>: expected .*that XML "
                                 rf"can hold \(U\+{ord(bad):04X} at offset 1 is not an XML "):
            setattr(element, name, f"a{bad}b")
        assert getattr(element, name) is None  # unchanged
    chars = model.compiler
    with pytest.raises(mjcf.InvalidValueError, match="XML can hold"):
        chars.eulerseq = f"x{bad}z"
    assert model.to_xml_string()  # nothing half-set


@settings(max_examples=300, derandomize=True, deadline=None, database=None)
@given(text=STRINGS)
def test_every_accepted_string_is_exported_and_read_back(text: str) -> None:
    model, attributes = _model()
    accepted: dict[str, str] = {}
    for kind, (element, name) in attributes.items():
        try:
            setattr(element, name, text)
        except mjcf.InvalidValueError:
            assert not all(map(_is_xml_char, text)) or (kind == "id" and "/" in text), text
            continue
        assert all(map(_is_xml_char, text)), text
        accepted[kind] = name
    xml = model.to_xml_string()
    again = mjcf.from_xml_string(xml)
    _, read = _model_like(again)
    for kind, name in accepted.items():
        element = read[kind]
        value = getattr(element, name)
        if kind == "file":  # written as get_assets() names it where the name needs it
            assert isinstance(value, str) and value, (text, xml)
            continue
        assert value == text, (kind, text, xml)
    assert again.to_xml_string() == xml


def _model_like(model: mjcf.RootElement) -> tuple[mjcf.RootElement, dict[str, mjcf.Element]]:
    return model, {"id": model.worldbody.body[0], "ref": model.worldbody.body[0].geom[0],
                   "string": model, "file": model.asset.mesh[0], "text": model.custom.text[0]}
