"""How a number is written is decided in one place each: the precision default
(``_codecs.DEFAULT_PRECISION``) and the spelling of a float (``_codecs.real_text``).

Each test changes that one place and checks that every route that writes a number moved
with it: assignment then export, parsing then export (with and without ``canonical``),
``str()``, ``to_xml()``, ``to_xml_string()``, ``get_attribute_xml_string()``, files written
with their assets, composed models, combined keyframes, the MjSpec bridge and compiling, and
the command line (``fmt --canonical``, ``to-python``).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path

import pytest
from lxml import etree

import typed_mjcf as mjcf
from tests.compiled import patches
from typed_mjcf import tooling
from typed_mjcf._core import codecs as _codecs
from typed_mjcf._core.tree import element_classes
from typed_mjcf.cli import main

X = 0.98765  # written "0.98765" by default; "0.988" at 3 digits; "0.99" by the test spelling
HEX = float.hex(X)  # read from a file, converted (the pattern for kept texts takes decimals)
FILE = f"""<mujoco>
  <worldbody>
    <geom name="kept" size="{X}"/>
    <geom name="converted" size="{HEX}"/>
  </worldbody>
</mujoco>
"""


def _token(text: str, token: str) -> bool:
    """Whether ``token`` is a whole number in ``text``."""
    return re.search(rf"(?<![\w.+-]){re.escape(token)}(?![\w.])", text) is not None


def _assigned() -> tuple[mjcf.RootElement, mjcf.Element]:
    model = mjcf.RootElement(model="m")
    geom = model.worldbody.add_geom(name="g")
    geom.size = (X,)  # assignment
    return model, geom


def _composed() -> mjcf.RootElement:
    """A model with one attached, each with a key "k": the keys are combined on export."""
    part = mjcf.from_xml_string("""<mujoco model="part"><worldbody><body name="b">
        <joint name="s" type="slide"/><geom name="pg" size=".1"/></body></worldbody>
        <keyframe><key name="k"/></keyframe></mujoco>""")
    key = part.keyframe.key[0]
    key.qpos = (X,)
    geom = part.find("geom", "pg")
    assert geom is not None
    geom.size = (X,)
    parent = mjcf.from_xml_string("""<mujoco model="parent"><worldbody><body name="a">
        <joint name="h" type="slide"/><geom size=".1"/><site name="mount"/></body>
        </worldbody><keyframe><key name="k" qpos="0"/></keyframe></mujoco>""")
    site = parent.find("site", "mount")
    assert site is not None
    site.attach(part)
    return parent


def routes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, str]:
    """The text each route writes for ``X`` (for MuJoCo's routes: the number it read)."""
    out: dict[str, str] = {}
    model, geom = _assigned()
    out["assignment, to_xml_string"] = model.to_xml_string()
    out["str()"] = str(geom)
    out["to_xml"] = etree.tostring(geom.to_xml()).decode()
    out["get_attribute_xml_string"] = geom.get_attribute_xml_string("size") or ""
    folder = tmp_path / "assets"
    mjcf.export_with_assets(model, folder, "m.xml")
    out["export_with_assets"] = (folder / "m.xml").read_text(encoding="utf-8")
    out["MjSpec bridge"] = repr(float(model.to_spec().geoms[0].size[0]))
    out["compile"] = repr(float(model.compile().geom_size[0][0]))
    parsed = mjcf.from_xml_string(FILE)
    out["parse, export (a converted value)"] = str(parsed.find("geom", "converted"))
    out["parse, export canonical"] = parsed.to_xml_string(canonical=True)
    out["parse, assign, export"] = _reassigned(parsed)
    composed = _composed()
    text = composed.to_xml_string()
    out["composed model"] = text.split("<keyframe>")[0]
    out["combined keyframe"] = text.split("<keyframe>")[1]
    source = tmp_path / "file.xml"
    source.write_text(FILE, encoding="utf-8")
    assert main(["fmt", "--canonical", str(source)]) == 0
    out["fmt --canonical"] = source.read_text(encoding="utf-8")
    capsys.readouterr()
    source = tmp_path / "code.xml"
    source.write_text(FILE, encoding="utf-8")
    assert main(["to-python", str(source)]) == 0
    out["to-python"] = capsys.readouterr().out
    return out


def _reassigned(parsed: mjcf.RootElement) -> str:
    geom = parsed.find("geom", "kept")
    assert geom is not None
    geom.size = (X,)
    return str(geom)


def test_by_default_every_route_writes_the_shortest_form(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    written = routes(tmp_path, capsys)
    assert {name for name, text in written.items() if not _token(text, repr(X))} == set()


def test_the_precision_default_moves_every_route(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(_codecs, "DEFAULT_PRECISION", 3)
    written = routes(tmp_path, capsys)
    # to-python writes the model exactly: an export option does not round its code
    assert _token(written.pop("to-python"), repr(X))
    assert {name for name, text in written.items() if not _token(text, "0.988")} == set()
    # and numbers read from a file are rewritten too (the default asks for 3 digits)
    assert _token(mjcf.from_xml_string(FILE).to_xml_string(), "0.988")
    assert not _token(mjcf.from_xml_string(FILE).to_xml_string(), repr(X))


def _two_decimals(values: Sequence[float], single: bool = False,
                  precision: int | None = None) -> str:
    return " ".join(format(x, ".2f") for x in values)


@patches("_core.codecs")
def test_the_float_spelling_moves_every_route(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    # the command line's spelling is the codec's (through typed_mjcf.tooling, the same function)
    assert tooling.real_text is _codecs.real_text
    monkeypatch.setattr(_codecs, "real_text", _two_decimals)
    monkeypatch.setattr(tooling, "real_text", _two_decimals)
    written = routes(tmp_path, capsys)
    assert {name for name, text in written.items() if not _token(text, "0.99")} == set()
    # a text read from a file and not asked to be reformatted is written as it was read
    kept = mjcf.from_xml_string(FILE).find("geom", "kept")
    assert str(kept) == f'<geom name="kept" size="{X}"/>'


def test_every_codec_writes_a_text_it_kept_as_it_is() -> None:
    """Every codec of the grammar writes a text it kept as read as its ``keeps_read_text``
    says (as it is, when the output keeps source text): the exporter's write plan follows
    that declaration without calling ``write`` (test_value_routes.py flips it)."""
    checked = 0
    for cls in element_classes().values():
        for attribute in cls.spec.attributes.values():
            if not attribute.as_is:
                continue
            codec = attribute.codec
            for text in ("0.5", "1", "1 2 3", "1 2 3 4", "x", "a b", *attribute.keywords):
                try:
                    stored = codec.parse(text)
                except _codecs.Rejected:
                    continue
                if type(stored) is str:  # a text kept as read: written as the codec says
                    kept = codec.write(stored, _codecs.Format()) is stored
                    assert kept == codec.keeps_read_text, attribute
                    checked += 1
    assert checked > 1000  # (the grammar has thousands)
