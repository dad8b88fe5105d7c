"""The generated MJCF reference (generated/mjcf-reference/): current with schema/, a page per
row, and examples that run."""

from __future__ import annotations

import copy
import re

import pytest

import typed_mjcf as mjcf
from codegen import ir, reference
from typed_mjcf import Element


@pytest.fixture(scope="module")
def schema() -> ir.Schema:
    return ir.load()


@pytest.fixture(scope="module")
def pages(schema: ir.Schema) -> dict[str, str]:
    return reference.render(schema)


def test_pages_equal_a_fresh_render(pages: dict[str, str]) -> None:
    stale = reference.stale(pages)
    assert not stale, f"generated/mjcf-reference/ is stale ({stale[:5]}): python -m codegen render"


def test_every_row_has_a_page_in_the_index(schema: ir.Schema, pages: dict[str, str]) -> None:
    assert set(pages) == {f"{name}.md" for name in schema.elements} | {"index.md"}
    linked = set(re.findall(r"\]\(([a-z0-9_]+\.md)\)", pages["index.md"]))
    assert linked == set(pages) - {"index.md"}


def test_links_between_pages_resolve(pages: dict[str, str]) -> None:
    for name, text in pages.items():
        for target in re.findall(r"\]\(([^)]+\.md)\)", text):
            assert target in pages, f"{name} links to {target}, which is no page"


def test_a_page_lists_every_attribute_with_type_default_and_releases(
        pages: dict[str, str]) -> None:
    joint = pages["joint.md"]
    assert "def add_joint(" in joint and "    type: JointType | None = ...," in joint
    assert "| `axis` | `Reals3` | `0 0 1` | all |" in joint
    assert "| `springyield` | `Real` | `0` | MuJoCo >= 4.0.0 |" in joint
    assert "| `class` (`class_`) |" in joint
    assert "[`<body>` (Body)](body.md)" in joint  # a parent


def test_a_schema_change_changes_the_page(schema: ir.Schema) -> None:
    changed = copy.deepcopy(schema)
    joint = changed.elements["joint"]
    joint.attributes.append(ir.AttributeDef(name="viscosity", py_name="viscosity", kind="real",
                                            dtype="double", default="0.5"))
    joint.attribute("damping").default = "0.25"
    pages = reference.render(changed)
    assert "| `viscosity` | `Real` | `0.5` |" in pages["joint.md"]
    assert "| `damping` | `Reals1To3` | `0.25` |" in pages["joint.md"]
    assert reference.stale(pages) == ["joint.md"]


def test_removed_attributes_are_listed_with_their_releases(schema: ir.Schema) -> None:
    older = copy.deepcopy(schema)
    older.mujoco_version = "3.17.0"
    older.elements["joint"].attributes.append(
        ir.AttributeDef(name="oldthing", py_name="oldthing", kind="int"))
    page = reference.render(schema, {"3.17.0": older})["joint.md"]
    assert "- `oldthing`: MuJoCo 3.17.0" in page


def _example(text: str) -> str:
    found = re.search(r"## Example\n\n```python\n(.*?)```", text, re.DOTALL)
    assert found is not None
    return found.group(1)


def test_every_example_runs_and_makes_its_element(schema: ir.Schema,
                                                  pages: dict[str, str]) -> None:
    for row in schema.elements.values():
        scope: dict[str, object] = {}
        exec(_example(pages[f"{row.name}.md"]), scope)  # noqa: S102 (our generated text)
        made = scope.get("element", scope["model"])
        assert isinstance(made, Element)
        assert type(made).__name__ == row.class_name, row.name
        model = scope["model"]
        assert isinstance(model, mjcf.RootElement)
        assert model.to_xml_string().startswith("<mujoco")
