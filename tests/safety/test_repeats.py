"""A once-only child repeated in one element (two ``<joint>`` in one ``<default>``, two
``<inertial>``, two ``<headlight>``) is refused at load, as MuJoCo refuses it, instead of
being merged with the later value winning; repeated sections (two ``<option>``) still merge,
as in MuJoCo. Every once-only child of the grammar is checked, found from its cardinality."""

from __future__ import annotations

from collections import deque
from pathlib import Path

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.grammar import ElementSpec
from typed_mjcf._text.parse import root_class


def _once_only_children() -> list[tuple[list[ElementSpec], str]]:
    """Every (path of rows from the root, child tag) whose child may appear once."""
    root = root_class().spec
    found: list[tuple[list[ElementSpec], str]] = []
    queue, seen = deque([[root]]), {id(root)}
    while queue:
        path = queue.popleft()
        for tag, child in path[-1].children.items():
            if child.once:
                found.append((path, tag))
            if id(child.cls.spec) not in seen:
                seen.add(id(child.cls.spec))
                queue.append([*path, child.cls.spec])
    return found


ONCE = _once_only_children()


def _wrapped(path: list[ElementSpec], inner: str) -> str:
    for spec in reversed(path):
        inner = f"<{spec.tag}>{inner}</{spec.tag}>"
    return inner


def test_the_grammar_has_once_only_children() -> None:
    assert len(ONCE) >= 40  # a vacuous list would make the next test pass on nothing


@pytest.mark.parametrize(("path", "tag"), ONCE,
                         ids=["/".join(s.tag for s in p) + f"/{t}" for p, t in ONCE])
def test_a_repeated_once_only_child_is_refused_as_mujoco_refuses_it(
        path: list[ElementSpec], tag: str) -> None:
    xml = _wrapped(path, f"\n<{tag}/>\n<{tag}/>\n")
    with pytest.raises(mjcf.ParseError, match=rf"^line 3: a second <{tag}> in .*\(the first is "
                                              rf"on line 2\): MuJoCo allows one <{tag}> in "
                                              rf"<{path[-1].tag}>"):
        mjcf.from_xml_string(xml)
    with pytest.raises(ValueError):  # ("unique element ... found 2 times", or another reason)
        mujoco.MjModel.from_xml_string(xml)


def test_the_common_cases_name_mujocos_reason() -> None:
    for xml in ("<mujoco><default><joint damping='1'/><joint damping='2'/></default></mujoco>",
                "<mujoco><visual><headlight/><headlight ambient='1 1 1'/></visual></mujoco>",
                ("<mujoco><worldbody><body><inertial mass='1' pos='0 0 0'/>"
                 "<inertial mass='2' pos='0 0 0'/></body></worldbody></mujoco>")):
        with pytest.raises(mjcf.ParseError, match="a second"):
            mjcf.from_xml_string(xml)
        with pytest.raises(ValueError, match="unique element"):
            mujoco.MjModel.from_xml_string(xml)


def test_once_only_children_of_repeated_sections_are_read_in_order() -> None:
    xml = ("<mujoco><option><flag energy='enable'/></option>"
           "<option><flag energy='disable'/></option>"
           "<default><joint damping='1'/></default><default><joint damping='2'/></default>"
           "<worldbody><body><joint/><geom size='1'/></body></worldbody></mujoco>")
    model = mjcf.from_xml_string(xml)
    compiled = mujoco.MjModel.from_xml_string(xml)
    assert model.option.flag.energy == "disable"
    damping = model.default.joint.damping
    assert damping is not None and list(damping) == [compiled.dof_damping[0]] == [2.0]
    # ... but a repeat inside the second section is still a repeat
    with pytest.raises(mjcf.ParseError, match="a second <flag> in option"):
        mjcf.from_xml_string("<mujoco><option><flag/></option><option><flag/>\n<flag/>"
                             "</option></mujoco>")


def test_a_repeat_through_an_include_names_both_files(tmp_path: Path) -> None:
    (tmp_path / "part.xml").write_text("<mujoco>\n<joint damping='2'/></mujoco>")
    (tmp_path / "main.xml").write_text(
        "<mujoco>\n<default>\n<joint damping='1'/>\n<include file='part.xml'/></default></mujoco>")
    with pytest.raises(mjcf.ParseError, match=r"part.xml:2: a second <joint> in default \(the "
                                              r"first is at main.xml:3\).*included from "
                                              r"main.xml:4"):
        mjcf.from_path(tmp_path / "main.xml")
