"""Per-world values written into a compiled model (typed_mjcf.parametric): the same model,
field by field, as compiling each world's typed model one by one."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt
import pytest

import typed_mjcf as mjcf
from typed_mjcf import parametric
from typed_mjcf._sim import parametric as _parametric
from typed_mjcf._sim.bridge import compile_model
from typed_mjcf._sim.parametric import RECOMPUTED_STATS, changed_rows
from typed_mjcf.errors import InvalidValueError, NotParametricError
from typed_mjcf.parametric import parametric_models, parametric_physics

N = 4


class Parts(NamedTuple):
    ball: mjcf.Body
    inertial: mjcf.Inertial
    sphere: mjcf.Geom
    box: mjcf.Geom
    hinge: mjcf.Joint


def _scene() -> tuple[mjcf.RootElement, Parts]:
    model = mjcf.RootElement(model="scene")
    model.worldbody.add_geom(type="plane", size=(5, 5, 0.1))
    ball = model.worldbody.add_body(name="ball", pos=(0, 0, 0.3))
    ball.add("freejoint")
    inertial = ball.add("inertial", pos=(0, 0, 0), mass=1, diaginertia=(0.01, 0.01, 0.01))
    sphere = ball.add_geom(type="sphere", size=(0.1,), friction=(1, 0.005, 0.0001))
    crate = model.worldbody.add_body(pos=(0.5, 0, 0.3))  # unnamed: bound by where it compiled
    crate.add("freejoint")
    crate.add("inertial", pos=(0, 0, 0), mass=0.5, diaginertia=(0.02, 0.02, 0.02))
    box = crate.add_geom(type="box", size=(0.1, 0.1, 0.1))
    arm = model.worldbody.add_body(name="arm", pos=(0, 1, 1))
    hinge = arm.add("joint", name="hinge", type="hinge", damping=0.1)
    arm.add_geom(type="capsule", fromto=(0, 0, 0, 0.3, 0, 0), size=(0.03,))
    return model, Parts(ball, inertial, sphere, box, hinge)


def _draw(parts: Parts, seed: int = 0,
          ) -> list[tuple[mjcf.Element, str, npt.NDArray[np.float64]]]:
    rng = np.random.default_rng(seed)
    return [(parts.sphere, "friction", rng.uniform(0.5, 1.5, (N, 3))),
            (parts.inertial, "mass", rng.uniform(0.5, 2.0, N)),
            (parts.sphere, "size", rng.uniform(0.05, 0.15, (N, 1))),
            (parts.box, "size", rng.uniform(0.05, 0.15, (N, 3))),
            (parts.hinge, "damping", rng.uniform(0.0, 1.0, N))]


def test_the_worlds_equal_the_models_compiled_one_by_one() -> None:
    """Every MjModel array exactly, and the statistics the solver reads to 1e-12: friction,
    a mass (explicit inertial), a sphere's and a box's size (rbound, aabb, subtree masses,
    invweight0 derived), a joint's damping."""
    model, parts = _scene()
    draw = _draw(parts)
    worlds = parametric_models(draw)
    assert len(worlds) == N
    for world, written in enumerate(worlds):
        for element, attribute, values in draw:
            setattr(element, attribute, values[world])
        compiled = model.compile()
        assert changed_rows(compiled, written) == {}, world
        for name in RECOMPUTED_STATS:
            assert getattr(written.stat, name) == pytest.approx(
                getattr(compiled.stat, name), rel=1e-12, abs=0)
    # worlds that differ: the values are each world's own
    assert len({float(w.geom_friction[1, 0]) for w in worlds}) == N


def test_probing_leaves_the_model_as_it_was() -> None:
    model, parts = _scene()
    before = model.to_xml_string()
    parametric_models(_draw(parts))
    assert model.to_xml_string() == before


def test_physics_per_world_bind_each_worlds_values() -> None:
    model, parts = _scene()
    physics = mjcf.Physics.from_mjcf_model(model)
    physics.bind(parts.hinge).qpos = 0.25
    draw = _draw(parts, seed=1)
    worlds = parametric_physics(physics, draw)
    for world, copy in enumerate(worlds):
        np.testing.assert_array_equal(copy.bind(parts.sphere).friction, draw[0][2][world])
        np.testing.assert_array_equal(copy.bind(parts.box).size, draw[3][2][world])
        assert float(copy.bind(parts.ball).mass) == draw[1][2][world]
        assert copy.bind(parts.hinge).qpos.tolist() == [0.25]  # the state is copied
    np.testing.assert_array_equal(physics.bind(parts.sphere).friction, [1, 0.005, 0.0001])


def test_an_attribute_the_compiler_derives_more_from_is_refused() -> None:
    """A free body's pos is also its qpos0: no single field takes it."""
    _, parts = _scene()
    with pytest.raises(NotParametricError) as caught:
        parametric_models([(parts.ball, "pos", np.ones((2, 3)))])
    message = str(caught.value)
    assert message.startswith("worldbody/body[ball]: 'pos' of <body> cannot be written")
    assert "qpos0" in message and "compile one model per world" in message


def test_a_size_that_gives_its_body_mass_and_inertia_is_refused() -> None:
    """Without an explicit <inertial>, the compiler computes the body's mass and inertia from
    its geoms, which mj_setConst does not: the size must be compiled per world."""
    _, parts = _scene()
    crate = parts.box.parent
    assert isinstance(crate, mjcf.Body)
    crate.inertial.remove()
    with pytest.raises(NotParametricError) as caught:
        parametric_models([(parts.box, "size", np.full((2, 3), 0.2))])
    message = str(caught.value)
    assert message.startswith("worldbody/body[1]/geom[0]: 'size' of <geom> cannot be written "
                              "into the compiled model (writing MjModel.geom_size and "
                              "mj_setConst leave body_inertia, body_invweight0, body_mass, ")
    assert message.endswith("compile one model per world instead")


@pytest.mark.parametrize(("attribute", "values", "expected"), [
    ("size", [[0.1], [0.1, 0.2, 0.3, 0.4]], (
        "worldbody/body[ball]/geom[0]: world 1: invalid size=[0.1, 0.2, 0.3, 0.4] on <geom>: "
        "expected 1 to 3 numbers, got 4")),
    ("friction", [[1, 0, 0], [np.nan, 0, 0]], (
        "worldbody/body[ball]/geom[0]: world 1: invalid friction=[nan, 0.0, 0.0] on <geom>: "
        "expected each number finite")),
])
def test_a_bad_value_names_element_attribute_value_and_world(
        attribute: str, values: list[list[float]], expected: str) -> None:
    model, parts = _scene()
    before = model.to_xml_string()
    ragged = np.empty(len(values), dtype=object)
    ragged[:] = [np.asarray(v) for v in values]
    with pytest.raises(InvalidValueError) as caught:
        parametric_models([(parts.sphere, attribute, ragged)])
    assert str(caught.value) == expected
    assert model.to_xml_string() == before


def test_a_stale_physics_is_refused() -> None:
    model, parts = _scene()
    physics = mjcf.Physics.from_mjcf_model(model)
    parts.sphere.friction = (2, 0.005, 0.0001)
    with pytest.raises(InvalidValueError, match="not the draw's model as it is now"):
        parametric_physics(physics, _draw(parts))


def test_a_new_draw_for_the_same_model_compiles_once(monkeypatch: pytest.MonkeyPatch) -> None:
    """The routes are learnt once per model (one probe compile per attribute), then reused
    while the model compiles to the same arrays; a change to the model learns them again."""
    _, parts = _scene()
    compiles: list[int] = []
    real = compile_model

    def counted(root: mjcf.RootElement) -> object:
        compiles.append(1)
        return real(root)

    monkeypatch.setattr(parametric, "compile_model", counted)
    monkeypatch.setattr(_parametric, "compile_model", counted)
    parametric_models(_draw(parts, seed=1))
    assert len(compiles) == 1 + 5  # the model, then each attribute of the draw probed
    parametric_models(_draw(parts, seed=2))
    assert len(compiles) == 1 + 5 + 1
    parts.hinge.damping = 0.5  # the model changed: the routes are learnt again
    parametric_models(_draw(parts, seed=3))
    assert len(compiles) == 1 + 5 + 1 + 1 + 5
