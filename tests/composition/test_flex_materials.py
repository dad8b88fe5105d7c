"""A flex's (and flexcomp's) ``material``: one material name or one per element, each looked
up among the model's materials by MuJoCo ("unknown material 'nope' in flex") and prefixed on
attach (MjSpec.attach, MuJoCo 4.0.0). A name list of the material namespace
(``name_lists`` in schema/facts.toml): scoped in an attached model and checked by
``validate()``."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf

GRID = {"type": "grid", "count": (2, 2, 1), "spacing": (1, 1, 1), "dim": 2}


def _cloth(material: str, rgba: tuple[float, float, float, float]) -> mjcf.RootElement:
    cloth = mjcf.RootElement(model="cloth")
    cloth.asset.add_material(name="red", rgba=rgba)
    cloth.asset.add_material(name="blue", rgba=(0, 0, 1, 1))
    cloth.worldbody.add_flexcomp(name="f", material=material, **GRID)  # type: ignore[arg-type]
    return cloth


@pytest.mark.parametrize("material", ["red", "red blue"])
def test_an_attached_models_flex_names_its_own_materials(material: str) -> None:
    world = mjcf.RootElement(model="world")
    world.asset.add_material(name="red", rgba=(0, 1, 0, 1))  # the same name, another material
    world.worldbody.add_site(name="s").attach(_cloth(material, (1, 0, 0, 1)))
    text = world.to_xml_string()
    scoped = " ".join(f"cloth/{name}" for name in material.split())
    assert f'material="{scoped}"' in text
    assert world.validate() == []
    m = mujoco.MjModel.from_xml_string(text)
    used = m.mat_rgba[m.flex_matid].tolist()  # one material per element (the grid has 2)
    names = material.split()
    if len(names) == 1:
        names *= len(used)
    expected = {"red": [1, 0, 0, 1], "blue": [0, 0, 1, 1]}
    assert len(used) == 2 and used == [expected[name] for name in names]


def test_a_missing_flex_material_is_a_validate_error() -> None:
    cloth = _cloth("red nope", (1, 0, 0, 1))
    [finding] = cloth.validate()
    assert (finding.path, finding.rule, finding.severity) == (
        "worldbody/flexcomp[f]", "unresolved-reference", "error")
    assert finding.message == "material='nope' names no material in the model"
    with pytest.raises(mjcf.ValidationError, match="material='nope'"):
        cloth.compile()


def test_a_renamed_material_is_not_followed() -> None:
    """Names in a list are text (as a flex's bodies are): a rename leaves the old name,
    which validate() then reports."""
    cloth = _cloth("red", (1, 0, 0, 1))
    red = cloth.find("material", "red")
    assert red is not None
    red.name = "ruby"
    assert [f.message for f in cloth.validate()] == [
        "material='red' names no material in the model"]
    assert np.allclose(_cloth("red", (1, 0, 0, 1)).compile().flex_matid, 0)
