"""``typed-mjcf fmt``: the canonical form keeps the model, comments and includes, and is a fixed
point; over the corpus, in a writable mirror of its packages, MuJoCo compiles every formatted
model to exactly what it compiles from the original."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf.cli import main
from typed_mjcf.cli.fmt import format_model

from ..runtime.model_compare import model_differences
from .corpus import CORPUS, compiled, corpus_params, mirror


@pytest.fixture(scope="module")
def formatted(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The corpus mirror after one ``fmt`` of every corpus file (which formats what they
    include too); files that cannot be read are reported and left as they are."""
    folder = mirror(tmp_path_factory.mktemp("corpus"))
    main(["fmt", *(str(folder / ident) for ident, _ in CORPUS)])
    return folder


def _parses(ident: str, path: Path) -> None:
    try:
        mujoco.MjSpec.from_file(str(path))
    except ValueError as error:
        pytest.skip(f"{ident}: MuJoCo does not parse it by itself: {' '.join(str(error).split())}")


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_the_formatted_model_compiles_the_same(ident: str, path: Path, formatted: Path) -> None:
    expected = compiled(ident, path)
    actual = mujoco.MjModel.from_xml_path(str(formatted / ident))  # MuJoCo reads the includes
    assert model_differences(expected, actual) == []


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_formatting_twice_changes_nothing(ident: str, path: Path, formatted: Path) -> None:
    _parses(ident, path)
    results = format_model(str(formatted / ident))
    assert [r.path for r in results if r.changed] == []


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_the_exporters_canonical_text_is_formatted(ident: str, path: Path,
                                                   tmp_path: Path) -> None:
    """Without comments, includes or blank lines, fmt's form is the exporter's."""
    _parses(ident, path)
    exported = tmp_path / "exported.xml"
    exported.write_text(mjcf.from_path(path).to_xml_string(canonical=True), encoding="utf-8")
    (result,) = format_model(str(exported))
    assert result.after == exported.read_text(encoding="utf-8")


MAIN = """\
<?xml version="1.0"?>
<!-- a model -->
<mujoco model="m">
    <compiler/>
  <option>   <flag/> </option>

  <worldbody>
     <!-- the arm -->
     <body pos="0 0 1.0" name="arm"><geom size=".10" type="capsule" fromto="0 0 0 0 0 .5"/>



       <joint   axis="0 1 0" range="-1 1" limited="true" name=""/>
     </body>
     stray &amp; text
     <include file="parts.xml"/>
  </worldbody>
</mujoco>
<!-- the end -->
"""
PARTS = """<mujoco   model="ignored">
<body name='leg'><geom  rgba="1 0 0 1.0" type="box" size=".1 .1 .1"/></body></mujoco>"""

MAIN_FORMATTED = """\
<?xml version="1.0" encoding="utf-8"?>
<!-- a model -->
<mujoco model="m">
  <worldbody>
    <!-- the arm -->
    <body name="arm" pos="0 0 1">
      <geom type="capsule" size="0.1" fromto="0 0 0 0 0 0.5"/>

      <joint axis="0 1 0" limited="true" range="-1 1"/>
    </body>
    stray &amp; text
    <include file="parts.xml"/>
  </worldbody>
</mujoco>
<!-- the end -->
"""
PARTS_FORMATTED = """\
<mujoco model="ignored">
  <body name="leg">
    <geom type="box" size="0.1 0.1 0.1" rgba="1 0 0 1"/>
  </body>
</mujoco>
"""


def _example(folder: Path) -> Path:
    (folder / "parts.xml").write_text(PARTS, encoding="utf-8")
    model = folder / "m.xml"
    model.write_text(MAIN, encoding="utf-8")
    return model


def test_fmt_keeps_what_the_author_wrote(tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    """Comments, text, blank lines (one at most), the XML declaration
    and <include> stay; the included file is formatted in the place it is included (a
    <body>'s row, not the root's); attributes go to grammar order with canonical values;
    empty attributes and once-only sections with nothing in them go."""
    model = _example(tmp_path)
    before = mujoco.MjModel.from_xml_path(str(model))
    assert main(["fmt", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == MAIN_FORMATTED
    assert (tmp_path / "parts.xml").read_text(encoding="utf-8") == PARTS_FORMATTED
    assert capsys.readouterr().out.splitlines() == [
        f"reformatted {model}", f"reformatted {tmp_path / 'parts.xml'}",
        "2 files reformatted, 0 files already formatted"]
    assert model_differences(before, mujoco.MjModel.from_xml_path(str(model))) == []
    assert main(["fmt", str(model)]) == 0
    assert capsys.readouterr().out == "0 files reformatted, 2 files already formatted\n"


def test_check_lists_what_would_change_and_writes_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = _example(tmp_path)
    assert main(["fmt", "--check", str(model)]) == 1
    assert model.read_text(encoding="utf-8") == MAIN
    assert capsys.readouterr().out.splitlines() == [
        f"would reformat {model}", f"would reformat {tmp_path / 'parts.xml'}",
        "2 files would be reformatted, 0 files already formatted"]
    main(["fmt", str(model)])
    capsys.readouterr()
    assert main(["fmt", "--check", str(model)]) == 0
    assert capsys.readouterr().out == "0 files would be reformatted, 2 files already formatted\n"


def test_diff_shows_the_changes_as_a_patch(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    model = _example(tmp_path)
    assert main(["fmt", "--diff", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == MAIN
    captured = capsys.readouterr()
    assert f"--- {model} (before)\n+++ {model} (formatted)\n" in captured.out
    assert '-     <body pos="0 0 1.0" name="arm"><geom size=".10" type="capsule"' in captured.out
    assert '+    <body name="arm" pos="0 0 1">\n' in captured.out
    assert captured.err == "2 files would be reformatted, 0 files already formatted\n"
    assert main(["fmt", "--check", "--diff", str(model)]) == 1


def test_a_file_included_twice_is_formatted_once(tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    model = _example(tmp_path)
    other = tmp_path / "other.xml"
    other.write_text('<mujoco><worldbody><include file="parts.xml"/></worldbody></mujoco>',
                     encoding="utf-8")
    assert main(["fmt", "--check", str(model), str(other)]) == 1
    assert capsys.readouterr().out.count("parts.xml") == 1


def test_processing_instructions_stay(tmp_path: Path) -> None:
    model = tmp_path / "m.xml"
    model.write_text('<?xml-stylesheet href="a.css"?>\n<mujoco><worldbody><?keep this ?>'
                     "<geom size='1'/></worldbody></mujoco>", encoding="utf-8")
    (result,) = format_model(str(model))
    assert result.after == ('<?xml-stylesheet href="a.css"?>\n<mujoco>\n  <worldbody>\n'
                            '    <?keep this ?>\n    <geom size="1"/>\n  </worldbody>\n'
                            "</mujoco>\n")


def test_a_doctype_stays_unless_it_declares_something(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    plain = tmp_path / "plain.xml"
    plain.write_text("<!DOCTYPE mujoco>\n<mujoco><worldbody/></mujoco>\n", encoding="utf-8")
    (result,) = format_model(str(plain))
    assert result.after == "<!DOCTYPE mujoco>\n<mujoco/>\n"
    declaring = tmp_path / "declaring.xml"
    text = "<!DOCTYPE mujoco [<!ELEMENT mujoco ANY>]>\n<mujoco/>\n"
    declaring.write_text(text, encoding="utf-8")
    assert main(["fmt", str(declaring)]) == 2
    assert "the DOCTYPE declares an internal subset" in capsys.readouterr().err
    assert declaring.read_text(encoding="utf-8") == text


def test_fmt_keeps_an_attribute_mujoco_ignores(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    model = tmp_path / "m.xml"
    model.write_text('<mujoco><worldbody><frame zz="1" pos="0 0 1.0"><geom size=".1"/></frame>'
                     '</worldbody></mujoco>', encoding="utf-8")
    assert main(["fmt", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == (
        '<mujoco>\n  <worldbody>\n    <frame pos="0 0 1" zz="1">\n      <geom size="0.1"/>\n'
        '    </frame>\n  </worldbody>\n</mujoco>\n')
    assert capsys.readouterr().err == ""  # nothing is dropped, so nothing to warn about
