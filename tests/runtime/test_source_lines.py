"""Where a parsed model's elements were read (file and line), and the findings that use it."""

from __future__ import annotations

import copy
from pathlib import Path

import typed_mjcf as mjcf
from typed_mjcf._core import tree as _tree

MAIN = """\
<mujoco model="m">
  <include file="parts.xml"/>
  <worldbody>
    <body name="b">
      <geom size="1"/>
    </body>
  </worldbody>
  <asset>
    <material name="red"/>
  </asset>
</mujoco>
"""
PARTS = """\
<mujoco>
  <asset>

    <texture name="t" builtin="flat" width="8" height="8"/>
  </asset>
</mujoco>
"""


def _write(folder: Path) -> Path:
    (folder / "parts.xml").write_text(PARTS, encoding="utf-8")
    main = folder / "main.xml"
    main.write_text(MAIN, encoding="utf-8")
    return main


def test_each_element_knows_its_file_and_line(tmp_path: Path) -> None:
    main = _write(tmp_path)
    model = mjcf.from_path(main)
    parts = str(tmp_path / "parts.xml")
    assert _tree.source_of(model) == (str(main), 1)
    body = model.find("body", "b")
    assert body is not None
    assert _tree.source_of(body) == (str(main), 4)
    assert _tree.source_of(body.geom[0]) == (str(main), 5)
    assert _tree.source_of(model.asset.texture[0]) == (parts, 4)
    # the second <asset> merged into the first (read from parts.xml): its children keep theirs
    assert _tree.source_of(model.asset) == (parts, 2)
    assert _tree.source_of(model.asset.material[0]) == (str(main), 9)


def test_the_source_map_lists_elements_in_reading_order_and_includes(tmp_path: Path) -> None:
    main = _write(tmp_path)
    model = mjcf.from_path(main)
    sources = _tree.source_map(model)
    assert sources is not None
    assert [e.path for e in sources.lines] == [
        "<root>", "asset", "asset/texture[t]", "worldbody", "worldbody/body[b]",
        "worldbody/body[b]/geom[0]", "asset/material[red]"]
    by, parent = sources.includes[str(tmp_path / "parts.xml")]
    assert by == str(main) and parent is model


def test_text_given_in_memory_has_lines_but_no_file() -> None:
    model = mjcf.from_xml_string("<mujoco>\n<worldbody>\n<geom size='1'/>\n</worldbody>\n</mujoco>")
    assert _tree.source_of(model.worldbody.geom[0]) == (None, 3)


def test_elements_made_in_python_and_copies_have_no_source() -> None:
    model = mjcf.from_xml_string("<mujoco><worldbody><geom size='1'/></worldbody></mujoco>")
    added = model.worldbody.add_geom(size=2)
    assert _tree.source_of(added) is None
    assert _tree.source_of(mjcf.RootElement()) is None
    clone = copy.deepcopy(model)
    assert _tree.source_map(clone) is None
    assert _tree.source_of(clone.worldbody.geom[0]) is None
    geom = model.worldbody.geom[0]
    geom.remove()
    assert _tree.source_of(geom) is None  # no longer in the model it was read into


def test_findings_name_their_element(tmp_path: Path) -> None:
    main = tmp_path / "m.xml"
    main.write_text('<mujoco>\n<worldbody>\n<geom size="1" material="rde"/>\n</worldbody>\n'
                    '<asset><material name="red"/></asset>\n</mujoco>\n', encoding="utf-8")
    model = mjcf.from_path(main)
    (finding,) = model.validate()
    geom = model.worldbody.geom[0]
    assert finding.element is geom
    assert _tree.source_of(geom) == (str(main), 3)
    # the element is not part of a finding's identity or text
    assert str(finding) == f"{geom.path}: unresolved-reference: {finding.message}"
    assert finding == mjcf.Finding(finding.path, finding.rule, finding.message)


SPREAD = """\
<mujoco>
  <!-- <geom
       size="1"/> -->
  <worldbody>
    <geom name="a"
          size="1"/><geom name="b" size="1"/>
    <body
        name="b1"
        pos="0 0 1"><geom name="c"
                          size="{size}" material="rde"/>
    </body>
  </worldbody>
  <asset><material name="red"/></asset>
</mujoco>
"""


def test_a_tag_over_several_lines_is_placed_on_the_line_it_begins(tmp_path: Path) -> None:
    # libxml2 gives the line where a start tag ends; findings point at its "<"
    main = tmp_path / "m.xml"
    main.write_text(SPREAD.format(size="1"), encoding="utf-8")
    model = mjcf.from_path(main)
    a, b = model.worldbody.geom
    body = model.find("body", "b1")
    assert body is not None
    assert _tree.source_of(a) == (str(main), 5)
    assert _tree.source_of(b) == (str(main), 5)  # ends on a's last line: only order tells
    assert _tree.source_of(body) == (str(main), 7)
    assert _tree.source_of(body.geom[0]) == (str(main), 9)
    (finding,) = model.validate()
    assert finding.element is body.geom[0]


def test_a_value_refused_at_load_names_the_line_its_tag_begins(tmp_path: Path) -> None:
    main = tmp_path / "m.xml"
    main.write_text(SPREAD.format(size="1x"), encoding="utf-8")
    for read in (lambda: mjcf.from_path(main),
                 lambda: mjcf.from_xml_string(main.read_text(encoding="utf-8"))):
        try:
            read()
        except mjcf.ParseError as error:
            assert error.line == 9, error
            assert "1x" in str(error)
        else:
            raise AssertionError("the value was accepted")
