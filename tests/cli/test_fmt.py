"""``typed-mjcf fmt``: by default it changes only the layout (indentation, long start tags),
keeping what the author wrote; ``--canonical`` writes the exporter's canonical form. Both
keep the model, comments and includes, and are fixed points; over the corpus, in a writable
mirror of its packages, MuJoCo compiles every formatted model to exactly what it compiles
from the original, and fmt changes few lines of each file."""

from __future__ import annotations

import statistics
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from tests.support.compare import model_differences
from tests.support.corpus import CORPUS, compiled, corpus_params, mirror
from typed_mjcf.cli import main
from typed_mjcf.cli._common import BadInput
from typed_mjcf.cli._starttags import WIDTH
from typed_mjcf.cli.fmt import format_model

from .fmt_changes import Change, changes

MODES = {"default": [], "canonical": ["--canonical"]}


@pytest.fixture(scope="module", params=list(MODES))
def formatted(request: pytest.FixtureRequest,
              tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, bool]:
    """The corpus mirror after one ``fmt`` of every corpus file (which formats what they
    include too), by default or canonically; files that cannot be read are reported and
    left as they are."""
    mode: str = request.param
    folder = mirror(tmp_path_factory.mktemp(f"corpus-{mode}"))
    main(["fmt", *MODES[mode], *(str(folder / ident) for ident, _ in CORPUS)])
    return folder, mode == "canonical"


def _parses(ident: str, path: Path) -> None:
    try:
        mujoco.MjSpec.from_file(str(path))
    except ValueError as error:
        pytest.skip(f"{ident}: MuJoCo does not parse it by itself: {' '.join(str(error).split())}")


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_the_formatted_model_compiles_the_same(ident: str, path: Path,
                                               formatted: tuple[Path, bool]) -> None:
    expected = compiled(ident, path)
    folder, _ = formatted
    actual = mujoco.MjModel.from_xml_path(str(folder / ident))  # MuJoCo reads the includes
    assert model_differences(expected, actual) == []


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_formatting_twice_changes_nothing(ident: str, path: Path,
                                          formatted: tuple[Path, bool]) -> None:
    _parses(ident, path)
    folder, canonical = formatted
    results = format_model(str(folder / ident), canonical=canonical)
    assert [r.path for r in results if r.changed] == []


def _corpus_changes(canonical: bool = False, width: int = WIDTH) -> list[Change]:
    """What fmt changes in each file of the corpus (included files once)."""
    found: dict[str, Change] = {}
    for _, path in CORPUS:
        try:
            for change in changes(str(path), canonical, width):
                found.setdefault(change.path, change)
        except BadInput:
            continue
    return list(found.values())


def test_fmt_changes_few_lines_of_the_corpus() -> None:
    """By default fmt changes under a tenth of the lines of most corpus files (median under
    5%; the files above are those whose authors wrote start tags longer than 100 characters,
    which fmt breaks, or indented inconsistently); keeping long tags (``--width 0``), under a
    tenth of every file of more than 20 lines. The canonical form changes far more (median
    35%), so these bounds fail if the default form reorders or respells attributes."""
    default = _corpus_changes()
    assert len(default) >= 50
    shares = [c.share for c in default]
    assert statistics.median(shares) < 0.05
    assert sum(1 for s in shares if s < 0.10) / len(shares) >= 0.65
    kept = [c for c in _corpus_changes(width=0) if c.lines > 20 and c.share >= 0.10]
    assert kept == []
    canonical = [c.share for c in _corpus_changes(canonical=True)]
    assert statistics.median(canonical) > 0.20  # the bound above can tell the two apart


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_the_exporters_canonical_text_is_formatted(ident: str, path: Path,
                                                   tmp_path: Path) -> None:
    """Without comments, includes or blank lines, fmt's form is the exporter's."""
    _parses(ident, path)
    exported = tmp_path / "exported.xml"
    exported.write_text(mjcf.from_path(path).to_xml_string(canonical=True), encoding="utf-8")
    (result,) = format_model(str(exported), canonical=True)
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


def test_canonical_fmt_keeps_what_the_author_wrote(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    """Comments, text, blank lines (one at most), the XML declaration
    and <include> stay; the included file is formatted in the place it is included (a
    <body>'s row, not the root's); attributes go to grammar order with canonical values;
    empty attributes and once-only sections with nothing in them go."""
    model = _example(tmp_path)
    before = mujoco.MjModel.from_xml_path(str(model))
    assert main(["fmt", "--canonical", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == MAIN_FORMATTED
    assert (tmp_path / "parts.xml").read_text(encoding="utf-8") == PARTS_FORMATTED
    assert capsys.readouterr().out.splitlines() == [
        f"reformatted {model}", f"reformatted {tmp_path / 'parts.xml'}",
        "2 files reformatted, 0 files already formatted"]
    assert model_differences(before, mujoco.MjModel.from_xml_path(str(model))) == []
    assert main(["fmt", "--canonical", str(model)]) == 0
    assert capsys.readouterr().out == "0 files reformatted, 2 files already formatted\n"


MAIN_LAID_OUT = """\
<?xml version="1.0"?>
<!-- a model -->
<mujoco model="m">
    <compiler/>
    <option>
        <flag/>
    </option>

    <worldbody>
        <!-- the arm -->
        <body pos="0 0 1.0" name="arm">
            <geom size=".10" type="capsule" fromto="0 0 0 0 0 .5"/>

            <joint   axis="0 1 0" range="-1 1" limited="true" name=""/>
        </body>
        stray &amp; text
        <include file="parts.xml"/>
    </worldbody>
</mujoco>
<!-- the end -->
"""
PARTS_LAID_OUT = """\
<mujoco   model="ignored">
  <body name='leg'>
    <geom  rgba="1 0 0 1.0" type="box" size=".1 .1 .1"/>
  </body>
</mujoco>
"""


def test_fmt_by_default_changes_only_the_layout(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """Attributes keep their order, spelling, quotes and spacing, the declaration stays as
    written, empty sections and attributes stay; the indentation step is the file's own (4
    in the model, whose root's first child is 4 in; 2 in the included file); one element
    per line."""
    model = _example(tmp_path)
    before = mujoco.MjModel.from_xml_path(str(model))
    assert main(["fmt", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == MAIN_LAID_OUT
    assert (tmp_path / "parts.xml").read_text(encoding="utf-8") == PARTS_LAID_OUT
    assert model_differences(before, mujoco.MjModel.from_xml_path(str(model))) == []
    capsys.readouterr()
    assert main(["fmt", str(model)]) == 0
    assert capsys.readouterr().out == "0 files reformatted, 2 files already formatted\n"


LONG = """\
<mujoco>
  <worldbody>
    <geom name="a_rather_long_name" type="capsule" fromto="0 0 0 0 0 0.5" size="0.05" rgba="1 0 0 1" friction="1 0.005 0.0001"/> <!-- kept here -->
    <geom name="broken" type="box"
          size="1 1 1"   rgba="0 1 0 1"/>
    <body
       name="b" pos="0 0 1"><geom size="1"/></body>
  </worldbody>
</mujoco>
"""
LONG_LAID_OUT = """\
<mujoco>
  <worldbody>
    <geom name="a_rather_long_name" type="capsule" fromto="0 0 0 0 0 0.5" size="0.05" rgba="1 0 0 1"
          friction="1 0.005 0.0001"/> <!-- kept here -->
    <geom name="broken" type="box"
          size="1 1 1"   rgba="0 1 0 1"/>
    <body
       name="b" pos="0 0 1">
      <geom size="1"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_long_start_tags_break_and_the_authors_breaks_stay(tmp_path: Path) -> None:
    """A start tag past 100 characters breaks before the attribute that passes the width,
    aligned with the first; a tag the author broke keeps its breaks (never joined up); a
    comment after a tag stays on its line; --width 0 breaks nothing the author did not."""
    model = tmp_path / "m.xml"
    model.write_text(LONG, encoding="utf-8")
    (result,) = format_model(str(model))
    assert result.after == LONG_LAID_OUT
    assert max(len(line) for line in result.after.splitlines() if "<!--" not in line) == 100
    model.write_text(result.after, encoding="utf-8")
    assert not format_model(str(model))[0].changed  # a fixed point
    model.write_text(LONG, encoding="utf-8")
    (kept,) = format_model(str(model), width=0)
    assert kept.after.splitlines()[2] == LONG.splitlines()[2]
    (narrow,) = format_model(str(model), width=60)
    assert max(len(line) for line in narrow.after.splitlines()
               if "<!--" not in line) <= 60


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
    assert main(["fmt", "--canonical", "--diff", str(model)]) == 0
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
                            "    <?keep this ?>\n    <geom size='1'/>\n  </worldbody>\n"
                            "</mujoco>\n")


@pytest.mark.parametrize("canonical", [False, True])
def test_blank_lines_outside_the_root_stay(tmp_path: Path, canonical: bool) -> None:
    """A licence header's blank line (the corpus's humanoid.xml), one at most, before the
    root and between what follows it; none where the author left none."""
    model = tmp_path / "m.xml"
    model.write_text("<!-- header\n  two lines -->\n\n\n<?keep?>\n<mujoco\n  model='m'>"
                     "<worldbody/></mujoco>\n<!-- a -->\n\n<!-- b -->\n<!-- c -->\n",
                     encoding="utf-8")
    (result,) = format_model(str(model), canonical=canonical)
    root = ('<mujoco model="m"/>' if canonical
            else "<mujoco\n  model='m'>\n  <worldbody/>\n</mujoco>")
    assert result.after == ("<!-- header\n  two lines -->\n\n<?keep?>\n" + root +
                            "\n<!-- a -->\n\n<!-- b -->\n<!-- c -->\n")
    model.write_text(result.after, encoding="utf-8")
    assert format_model(str(model), canonical=canonical)[0].after == result.after


def test_a_doctype_stays_unless_it_declares_something(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    plain = tmp_path / "plain.xml"
    plain.write_text("<!DOCTYPE mujoco>\n<mujoco><worldbody/></mujoco>\n", encoding="utf-8")
    (result,) = format_model(str(plain), canonical=True)
    assert result.after == "<!DOCTYPE mujoco>\n<mujoco/>\n"
    (result,) = format_model(str(plain))
    assert result.after == "<!DOCTYPE mujoco>\n<mujoco>\n  <worldbody/>\n</mujoco>\n"
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
    assert main(["fmt", "--canonical", str(model)]) == 0
    assert model.read_text(encoding="utf-8") == (
        '<mujoco>\n  <worldbody>\n    <frame pos="0 0 1" zz="1">\n      <geom size="0.1"/>\n'
        '    </frame>\n  </worldbody>\n</mujoco>\n')
    assert capsys.readouterr().err == ""  # nothing is dropped, so nothing to warn about
