"""``typed-mjcf diff``: nothing for the same model however it is written, exactly the edit
for an edited one."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.corpus import corpus_params
from typed_mjcf._core import tree as _tree
from typed_mjcf._text.files import name_files
from typed_mjcf.cli import main
from typed_mjcf.cli.diff import diff_models


def _load(ident: str, path: Path) -> mjcf.RootElement:
    try:
        return mjcf.from_path(path)
    except mjcf.ParseError as error:
        pytest.skip(f"{ident}: typed-mjcf cannot read it: {error}")


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_a_model_does_not_differ_from_itself(ident: str, path: Path) -> None:
    assert diff_models(_load(ident, path), _load(ident, path)) == []
    assert diff_models(_load(ident, path), _load(ident, path), resolved=True) == []


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_formatting_does_not_show(ident: str, path: Path) -> None:
    """The canonical export spells numbers differently, orders attributes by the grammar,
    indents, expands includes and merges repeated sections: none of it is a difference.

    The one difference it may make is the name of a file whose flat name another file
    shares: ``to_xml_string`` names files as ``get_assets()`` does (as dm_control does)."""
    model = _load(ident, path)
    exported = mjcf.from_xml_string(model.to_xml_string(canonical=True), base_dir=path.parent)
    assert _without_file_renames(model, diff_models(model, exported)) == []


def _without_file_renames(model: mjcf.RootElement, lines: list[str]) -> list[str]:
    """``lines`` less those that rename a file to the flat name the library gives it."""
    names = name_files(model)
    by_path = {e.path: e for e in model.iter_elements()}
    kept: list[str] = []
    for line in lines:
        element_path, change = line.removeprefix("~ ").split(": ", 1)
        element = by_path.get(element_path)
        if element is not None and change.startswith("file "):
            written = change.split(" -> ")[1].split('"')[1]
            if written == names.name_of(element, element.spec.by_name["file"]):
                continue
        kept.append(line)
    return kept


@pytest.mark.parametrize(("ident", "path"), corpus_params())
def test_an_edit_shows_as_exactly_that_edit(ident: str, path: Path) -> None:
    model = _load(ident, path)
    edited = _load(ident, path)
    found = next(((e, a) for e in edited.iter_elements() for a in e.spec.attributes.values()
                  if a.kind == "real" and a.name in _tree.values(e)), None)
    if found is None:
        pytest.skip(f"{ident} sets no real-valued attribute")
    element, attribute = found
    name = attribute.name
    before = np.atleast_1d(np.asarray(_tree.read_value(element, attribute), dtype=np.float64))
    after = before + 0.5
    element.set_attributes(**{attribute.py_name: after if attribute.is_array else after[0]})
    rewritten = mjcf.from_xml_string(edited.to_xml_string(), base_dir=path.parent)
    lines = _without_file_renames(model, diff_models(model, rewritten))
    assert len(lines) == 1, lines
    assert lines[0].startswith(f"~ {element.path}: {name} ")
    written = lines[0].split(" -> ")[1].split('"')[1]
    dtype = np.float32 if attribute.dtype == "float" else np.float64
    assert np.array_equal(np.array(written.split(), dtype), after.astype(dtype))


A = """\
<mujoco model="m">
  <default>
    <default class="heavy"><geom density="2000"/></default>
  </default>
  <worldbody>
    <body name="arm" pos="0 0 1">
      <geom size="0.1"/>
      <geom size="0.2" class="heavy"/>
      <joint name="j1"/>
      <joint name="j2"/>
      <body name="hand"><geom size="0.05"/></body>
    </body>
    <body name="leg"/>
  </worldbody>
  <actuator><motor name="m" joint="j1"/></actuator>
</mujoco>
"""


@pytest.fixture(autouse=True)
def _in_tmp_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)  # files are shown relative to the current folder


def _pair(tmp_path: Path, edited: str) -> tuple[Path, Path]:
    a, b = tmp_path / "a.xml", tmp_path / "b.xml"
    a.write_text(A, encoding="utf-8")
    b.write_text(edited, encoding="utf-8")
    return a, b


def _diff(tmp_path: Path, edited: str, resolved: bool = False) -> list[str]:
    a, b = _pair(tmp_path, edited)
    return diff_models(mjcf.from_path(a), mjcf.from_path(b), resolved=resolved)


def test_changed_added_removed_moved_and_reordered(tmp_path: Path) -> None:
    edited = (A.replace('<geom size="0.1"/>', '<geom size="0.1 " rgba="1 0 0 1"/>')
              .replace('<joint name="j1"/>\n      <joint name="j2"/>',
                       '<joint name="j2"/>\n      <joint name="j1"/>')
              .replace('<body name="hand"><geom size="0.05"/></body>', "")
              .replace('<body name="leg"/>',
                       '<body name="leg"><body name="hand"><geom size="0.05"/></body></body>')
              .replace('<motor name="m" joint="j1"/>', '<motor name="m" joint="j2"/><motor '
                                                       'name="n" joint="j1" gear="2"/>'))
    assert _diff(tmp_path, edited) == [
        "^ worldbody/body[arm]: order of <joint> children changed  [a.xml:6, b.xml:6]",
        '~ worldbody/body[arm]/geom[0]: rgba (unset) -> "1 0 0 1"  [a.xml:7, b.xml:7]',
        ("> worldbody/body[leg]/body[hand]: moved from worldbody/body[arm] to "
         "worldbody/body[leg]  [a.xml:11, b.xml:13]"),
        '~ actuator/motor[m]: joint "j1" -> "j2"  [a.xml:15, b.xml:15]',
        '+ actuator/motor[n]: <motor name="n" gear="2" joint="j1"/>  [b.xml:15]',
    ]


def test_an_unnamed_element_inserted_among_others_is_one_addition(tmp_path: Path) -> None:
    edited = A.replace('<geom size="0.1"/>', '<geom size="0.3"/><geom size="0.1"/>')
    assert _diff(tmp_path, edited) == [
        '+ worldbody/body[arm]/geom[0]: <geom size="0.3"/>  [b.xml:7]']
    removed = A.replace('<geom size="0.1"/>', "")
    assert _diff(tmp_path, removed) == [
        '- worldbody/body[arm]/geom[0]: <geom size="0.1"/>  [a.xml:7]']


def test_removing_an_element_reports_it_once_with_what_was_inside(tmp_path: Path) -> None:
    edited = A.replace('<body name="hand"><geom size="0.05"/></body>', "")
    assert _diff(tmp_path, edited) == [
        '- worldbody/body[arm]/body[hand]: <body name="hand">  [a.xml:11]',
        '-   worldbody/body[arm]/body[hand]/geom[0]: <geom size="0.05"/>']


def test_an_added_element_shows_what_is_inside_then_how_many_more(tmp_path: Path) -> None:
    fixed = "<fixed name='t'><joint joint='j1' coef='1'/></fixed>"
    found = _diff(tmp_path, A.replace("</mujoco>", f"<tendon>{fixed}</tendon></mujoco>"))
    assert found == [
        "+ tendon: <tendon>  [b.xml:16]",
        '+   tendon/fixed[t]: <fixed name="t">',
        '+     tendon/fixed[t]/joint[0]: <joint joint="j1" coef="1"/>']
    sites = "".join(f'<site name="s{i}"/>' for i in range(25))
    found = _diff(tmp_path, A.replace('<body name="leg"/>', f'<body name="leg2">{sites}</body>'))
    added = [line for line in found if line.startswith("+")]
    assert added[0] == '+ worldbody/body[leg2]: <body name="leg2">  [b.xml:13]'
    assert added[1:21] == [f'+   worldbody/body[leg2]/site[s{i}]: <site name="s{i}"/>'
                           for i in range(20)]
    assert added[21:] == ["+   ... and 5 more elements inside worldbody/body[leg2]"]


def test_resolved_values_show_what_a_default_class_changes(tmp_path: Path) -> None:
    edited = A.replace('density="2000"', 'density="3000"')
    assert _diff(tmp_path, edited) == [
        '~ default/default[heavy]/geom: density "2000" -> "3000"  [a.xml:3, b.xml:3]']
    assert _diff(tmp_path, edited, resolved=True) == [
        '~ default/default[heavy]/geom: density "2000" -> "3000"  [a.xml:3, b.xml:3]',
        '~ worldbody/body[arm]/geom[1]: density "2000" -> "3000"  [a.xml:8, b.xml:8]']
    # a value set to what the default gives is no difference once resolved
    same = A.replace('<geom size="0.1"/>', '<geom size="0.1" density="1000"/>')
    assert len(_diff(tmp_path, same)) == 1
    assert _diff(tmp_path, same, resolved=True) == []


def test_the_command_prints_a_header_and_exits_1_on_differences(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    a, b = _pair(tmp_path, A.replace('pos="0 0 1"', 'pos="0 0 1.5"'))
    assert main(["diff", str(a), str(a)]) == 0
    assert capsys.readouterr().out == ""
    assert main(["diff", str(a), str(b)]) == 1
    assert capsys.readouterr().out == (
        "--- a.xml\n+++ b.xml\n"
        '~ worldbody/body[arm]: pos "0 0 1" -> "0 0 1.5"  [a.xml:6, b.xml:6]\n')
