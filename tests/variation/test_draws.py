"""Distributions on attributes, drawn per world: seeded, checked by the attribute's own rules,
and refused when assigned to an element directly."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf.errors import (
    CompileError,
    InvalidTypeError,
    InvalidValueError,
    UnknownAttributeError,
)
from typed_mjcf.variation import (
    Draws,
    Variation,
    choice,
    compile_worlds,
    log_uniform,
    normal,
    uniform,
    world_model,
)


def _scene() -> tuple[mjcf.RootElement, mjcf.Geom, mjcf.Position]:
    model = mjcf.RootElement(model="scene")
    body = model.worldbody.add_body(name="box", pos=(0, 0, 0.3))
    body.add_freejoint()
    geom = body.add_geom(name="g", type="box", size=(0.05, 0.05, 0.05), mass=1)
    arm = model.worldbody.add_body(name="arm")
    arm.add_joint(name="hinge", axis=(0, 1, 0))
    arm.add_geom(size=(0.02,), fromto=(0, 0, 0, 0.3, 0, 0), type="capsule")
    servo = model.actuator.add_position(name="servo", joint="hinge", kp=10)
    return model, geom, servo


def _variation(geom: mjcf.Geom) -> Variation:
    v = Variation()
    v.of(geom).friction = uniform((0.5, 0.005, 1e-4), (1.5, 0.01, 1e-3))
    v.of(geom).mass = log_uniform(0.5, 2.0)
    v.of(geom).rgba = (uniform(0.0, 1.0), 0.5, 0.5, 1.0)
    v.of(geom).condim = choice([1, 3, 4])
    v.of(geom).material = choice(["red", "blue"])
    return v


def test_draws_hold_one_row_per_world_in_the_attributes_form() -> None:
    _, geom, _ = _scene()
    draws = _variation(geom).draw(seed=3, n=6)
    assert [(d.element, d.attribute) for d in draws] == [
        (geom, "friction"), (geom, "mass"), (geom, "rgba"), (geom, "condim"),
        (geom, "material")]
    friction, mass, rgba, condim, material = (d.values for d in draws)
    assert friction.shape == (6, 3) and friction.dtype == np.float64
    assert np.all((friction >= (0.5, 0.005, 1e-4)) & (friction <= (1.5, 0.01, 1e-3)))
    assert mass.shape == (6,) and np.all((mass >= 0.5) & (mass <= 2.0))
    assert rgba.shape == (6, 4) and rgba.dtype == np.float32  # rgba is a float attribute
    assert np.all(rgba[:, 1:] == (0.5, 0.5, 1.0)) and len(set(rgba[:, 0].tolist())) == 6
    assert set(condim.tolist()) <= {1, 3, 4} and condim.dtype.kind == "i"
    assert set(material.tolist()) <= {"red", "blue"}
    assert _plain(draws.world(4)) == [(d.element, d.attribute, d.values[4].tolist())
                                      for d in draws]


def _plain(world: list[tuple[object, str, object]]) -> list[tuple[object, str, object]]:
    return [(e, a, v.tolist() if isinstance(v, np.ndarray) else v) for e, a, v in world]


def test_a_worlds_values_depend_only_on_the_seed_and_its_index() -> None:
    _, geom, _ = _scene()
    v = _variation(geom)
    whole = v.draw(seed=11, n=10)
    parts = [v.draw(seed=11, n=4), v.draw(seed=11, n=3, first=4), v.draw(seed=11, n=3, first=7)]
    for k, drawn in enumerate(whole):
        joined = np.concatenate([part[k].values for part in parts])
        assert np.array_equal(joined, drawn.values), drawn.attribute
    # one world alone, far away, is the same as in a long draw
    assert _plain(v.draw(seed=11, n=1, first=9).world(9)) == _plain(whole.world(9))
    other = v.draw(seed=12, n=10)
    assert not np.array_equal(other[0].values, whole[0].values)
    # an unpickled variation draws the same
    assert np.array_equal(pickle.loads(pickle.dumps(v)).draw(seed=11, n=10)[1].values,
                          whole[1].values)


def test_integers_from_both_ends_when_uniform_is_given_ints() -> None:
    _, geom, servo = _scene()
    v = Variation()
    v.of(geom).priority = uniform(1, 3)
    v.of(servo).kp = uniform(1, 3)  # a real attribute: integral values, as reals
    priority, kp = (d.values for d in v.draw(seed=0, n=200))
    assert priority.dtype.kind == "i" and set(priority.tolist()) == {1, 2, 3}
    assert kp.dtype == np.float64 and set(kp.tolist()) == {1.0, 2.0, 3.0}


def test_a_draw_out_of_the_attributes_bounds_names_element_attribute_value_and_world() -> None:
    _, _, servo = _scene()
    v = Variation()
    v.of(servo).kv = normal(0.5, 1.0)  # schema/facts.toml: position kv >= 0
    with pytest.raises(InvalidValueError) as raised:
        v.draw(seed=0, n=50)
    message = str(raised.value)
    assert message.startswith("actuator/position[servo]: invalid kv=-")
    assert "expected >= 0 (MuJoCo refuses others); drawn for world " in message
    world = int(message.rsplit("drawn for world ", 1)[1].split()[0])
    # that world's generator, alone, draws that value: never clipped
    with pytest.raises(InvalidValueError, match=f"drawn for world {world} "):
        v.draw(seed=0, n=1, first=world)
    assert servo.kv is None  # the element is left as it was


def test_a_distribution_that_cannot_fit_is_refused_when_stated() -> None:
    model, geom, servo = _scene()
    v = Variation()
    cases = [
        (geom, "pos", uniform((0, 0), (1, 1)), InvalidValueError, "expected 3 numbers, got 2"),
        (geom, "condim", uniform(0.5, 4.5), InvalidValueError, "expected an integer"),
        (geom, "type", choice(["box", "spher"]), InvalidValueError, "did you mean 'sphere'"),
        (geom, "type", uniform(0.0, 1.0), InvalidTypeError, "expected one of 'plane'"),
        (servo, "ctrlrange", uniform((0.0,), (1.0,)), InvalidValueError, "expected 2 numbers"),
    ]
    for element, name, distribution, error, expected in cases:
        with pytest.raises(error) as raised:
            setattr(v.of(element), name, distribution)
        message = str(raised.value)
        assert message.startswith(f"{element.path}: invalid {name}="), message
        assert expected in message and f"a value {distribution!r} draws" in message, message
    with pytest.raises(UnknownAttributeError, match="did you mean 'friction'"):
        v.of(geom).frictoin = uniform(0.5, 1.5)  # type: ignore[attr-defined]
    with pytest.raises(InvalidTypeError, match="expected a distribution"):
        v.of(geom).mass = 2.0  # a fixed value goes on the element itself
    with pytest.raises(UnknownAttributeError):
        v.of(geom).remove()  # the stand-in records assignments only
    assert len(v) == 0 and model.to_xml_string() == _scene()[0].to_xml_string()


@pytest.mark.parametrize(("make", "expected"), [
    (lambda: uniform(2.0, 1.0), "low must not exceed high"),
    (lambda: uniform((0, 1), (1, 2, 3)), "must have the same length"),
    (lambda: uniform("a", "b"), "must be a number or a sequence of numbers"),
    (lambda: normal(0.0, -1.0), "std must be >= 0"),
    (lambda: log_uniform(0.0, 1.0), "expected 0 < low <= high"),
    (lambda: uniform(0.0, float("inf")), "must be finite"),
    (lambda: choice([]), "expected at least one option"),
    (lambda: choice("box"), "expected a sequence of options"),
])
def test_distributions_check_their_arguments(make: object, expected: str) -> None:
    assert callable(make)
    with pytest.raises((InvalidValueError, InvalidTypeError), match=expected):
        make()


def test_a_distribution_assigned_to_an_element_is_refused_leaving_it_unchanged() -> None:
    model, geom, _ = _scene()
    before = model.to_xml_string()
    routes = [
        lambda: setattr(geom, "mass", uniform(0.5, 1.5)),
        lambda: setattr(geom, "friction", (uniform(0.5, 1.5), 0.005, 1e-4)),
        lambda: setattr(geom, "type", choice(["box", "sphere"])),
        lambda: geom.set_attributes(rgba=(1, 0, 0, 1), mass=normal(1.0, 0.1)),
        lambda: model.worldbody.add_geom(size=(0.1,), mass=uniform(0.5, 1.5)),
    ]
    for route in routes:
        with pytest.raises(InvalidTypeError) as raised:
            route()
        message = str(raised.value)
        assert message.startswith("worldbody/"), message
        assert "invalid " in message, message
        assert any(f"{name}(" in message for name in ("uniform", "choice", "normal")), message
        assert "Variation().of(element).<attribute> = ..." in message, message
    assert model.to_xml_string() == before


def test_a_copy_of_the_model_per_world_and_a_recompile() -> None:
    model, geom, _ = _scene()
    model.asset.add_material(name="red", rgba=(1, 0, 0, 1))
    model.asset.add_material(name="blue", rgba=(0, 0, 1, 1))
    before = model.to_xml_string()
    draws = _variation(geom).draw(seed=5, n=4)
    copy = world_model(model, draws, 2)
    copied = copy.find("geom", "g")
    assert copied is not None and copied is not geom
    assert np.array_equal(copied.friction, draws[0].values[2])
    assert copied.mass == draws[1].values[2]
    assert model.to_xml_string() == before  # the model itself is left as it was
    compiled = compile_worlds(model, draws)
    assert len(compiled) == 4
    for world, m in enumerate(compiled):
        assert np.allclose(m.geom_friction[0], draws[0].values[world])
        assert np.isclose(m.body_mass[1], draws[1].values[world])
        assert m.geom_condim[0] == draws[3].values[world]


def test_a_recompile_that_mujoco_refuses_names_the_element_and_the_world() -> None:
    model, geom, _ = _scene()
    v = Variation()
    v.of(geom).size = uniform((-0.05, 0.05, 0.05), (0.05, 0.1, 0.1))  # MuJoCo: size > 0
    draws = v.draw(seed=1, n=8)
    bad = int(np.flatnonzero(draws[0].values[:, 0] <= 0)[0])
    with pytest.raises(CompileError) as raised:
        compile_worlds(model, draws)
    assert raised.value.path == "worldbody/body[box]/geom[g]"
    assert f"drawn for world {bad} (seed 1)" in str(raised.value)


def test_draws_of_an_element_of_another_model_are_refused_on_a_copy() -> None:
    model, _, _ = _scene()
    _, other, _ = _scene()
    v = Variation()
    v.of(other).mass = uniform(1.0, 2.0)
    with pytest.raises(InvalidValueError, match="not in the model"):
        world_model(model, v.draw(seed=0, n=1), 0)


def test_seeds_and_counts_are_checked() -> None:
    _, geom, _ = _scene()
    v = _variation(geom)
    for seed, n, first in [(-1, 1, 0), (0, -1, 0), (0, 1, -2), (1.5, 1, 0), (True, 1, 0)]:
        with pytest.raises(InvalidValueError):
            v.draw(seed, n, first=first)  # type: ignore[arg-type]
    draws = v.draw(seed=0, n=0)
    assert isinstance(draws, Draws) and all(len(d.values) == 0 for d in draws)
    with pytest.raises(IndexError, match="was not drawn"):
        draws.world(0)
