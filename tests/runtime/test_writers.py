"""The exporter's two writers, and the garbage collector around bulk work.

Models with nothing attached are written straight to text in one pass; composed models are
built as nodes first (attached models' sections join the parent's) and then serialised.
Both must write the same text for the same elements.
"""

from __future__ import annotations

import gc
from collections.abc import Iterator
from pathlib import Path

import pytest
from lxml import etree

import typed_mjcf as mjcf
from tests.support.corpus import CORPUS
from typed_mjcf._core.codecs import Format
from typed_mjcf._model.write import element_text
from typed_mjcf._text.export import Writer
from typed_mjcf._text.xmltext import serialize
from typed_mjcf.errors import ExportError, ParseError


def _models() -> list[object]:
    return [pytest.param(path, id=ident) for ident, path in CORPUS]


@pytest.mark.parametrize("path", _models())
def test_text_writer_and_node_writer_agree(path: Path) -> None:
    try:
        model = mjcf.from_path(path)
    except ParseError:
        pytest.skip("typed-mjcf does not read it (tested in test_corpus)")
    for pretty in (True, False):
        for fmt in (Format(), Format(precision=4, zero_threshold=1e-6), Format(canonical=True)):
            text = Writer(model, fmt).text(model, pretty)
            assert text == serialize(Writer(model, fmt).element(model, None), pretty)


def test_text_writer_escapes_what_needs_escaping() -> None:
    model = mjcf.RootElement(model='a "quoted" <name> & more\tand a tab')
    model.worldbody.add_body(name="b&c")
    text = element_text(model, Format(), pretty_print=False)
    assert text == serialize(Writer(model).element(model, None), pretty_print=False)
    assert 'model="a &quot;quoted&quot; &lt;name&gt; &amp; more&#9;and a tab"' in text
    assert mjcf.from_xml_string(text).model == model.model


@pytest.fixture
def collector_enabled() -> Iterator[None]:
    was = gc.isenabled()
    gc.enable()
    yield
    if not was:
        gc.disable()


@pytest.mark.usefixtures("collector_enabled")
def test_export_and_parse_give_the_collector_back() -> None:
    model = mjcf.RootElement()
    model.worldbody.add_body(name="b").add_geom(size=(0.1,))
    text = model.to_xml_string()
    assert gc.isenabled()
    mjcf.from_xml_string(text)
    assert gc.isenabled()
    with pytest.raises(ParseError):
        mjcf.from_xml_string("<mujoco><worldbody><bodyy/></worldbody></mujoco>")
    assert gc.isenabled()
    joint = model.worldbody.add_body().add_joint(name="j")
    model.actuator.add_motor(joint=joint)
    joint.name = None
    with pytest.raises(ExportError, match="no name"):
        model.to_xml_string()
    assert gc.isenabled()


def test_a_disabled_collector_stays_disabled() -> None:
    was = gc.isenabled()
    gc.disable()
    try:
        model = mjcf.from_xml_string("<mujoco><worldbody><body/></worldbody></mujoco>")
        model.to_xml_string()
        assert not gc.isenabled()
    finally:
        if was:
            gc.enable()


@pytest.mark.parametrize("composed", [False, True])
def test_deep_models_are_indented_like_libxml2(composed: bool) -> None:
    """Indentation stops growing at libxml2's cap, so a 2,000-deep chain writes about as
    much text as lxml does for the same tree (not 2 spaces x depth per line), on both
    writers."""
    model = mjcf.RootElement()
    body: mjcf.Body | mjcf.Worldbody = model.worldbody
    for _ in range(2000):
        body = body.add_body()
    if composed:
        model.worldbody.add_site(name="s").attach(mjcf.RootElement(model="arm"))
    text = model.to_xml_string()
    tree = etree.fromstring(text.encode(), etree.XMLParser(huge_tree=True))
    ours = etree.tostring(tree, pretty_print=True).decode()
    assert text.strip() == ours.strip()
    assert max(len(line) - len(line.lstrip()) for line in text.splitlines()) == 60
    assert len(text) < 300_000  # 2,000 levels of 2 spaces each would be over 4 million


TRICKY_TEXTS = ['a&b', 'a<b>c', 'say "hi"', "it's", "two\nlines", "tab\there", "cr\rhere",
                "naïve ∞ 日本", "100%", "%s %d %(x)s", "&amp;", "plain"]


@pytest.mark.parametrize("text", TRICKY_TEXTS)
def test_every_text_is_escaped_as_xml_needs_whatever_path_writes_it(text: str) -> None:
    """Plain output writes an element's texts into a template and escapes only when the
    result shows markup; the text must read back the same either way."""
    model = mjcf.RootElement(model=text)
    body = model.worldbody.add_body(name=text.replace("/", ""), pos=(0, 0, 1))
    body.add_geom(name="g", size=(0.1,), material=text)
    model.custom.add_text(name="t", data=text)
    parsed = mjcf.from_xml_string(model.to_xml_string())
    for source in (model, parsed):
        for pretty in (True, False):
            written = element_text(source, Format(), pretty_print=pretty)
            assert written == serialize(Writer(source).element(source, None), pretty)
            root = etree.fromstring(written.encode())
            assert root.get("model") == text
            xml_body = root.find("worldbody/body")
            assert xml_body is not None
            assert xml_body.get("name") == text
            assert xml_body.get("pos") == "0 0 1"
            xml_geom = xml_body.find("geom")
            assert xml_geom is not None
            assert xml_geom.get("material") == text
            xml_text = root.find("custom/text")
            assert xml_text is not None
            assert xml_text.get("data") == text
