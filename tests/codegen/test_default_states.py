"""Every attribute of schema/ has a default, ``computed``, or a reason it has none.

The reasons come from codegen/unset.py's rules (names, references, lists, alternatives...) or
schema/unset.toml; ``[unprobed.*]`` entries there are defaults the probe cannot tell yet. The
probe tests below run the installed MuJoCo's parser on rows the first pass could not compile.
"""

from __future__ import annotations

import copy

import pytest

from codegen import drift, ir, unset
from codegen.wheel import Wheel, read_wheel

_COMMITTED = ir.load()


def test_every_attribute_has_a_default_computed_or_a_reason() -> None:
    left = [f"{name}@{a.name}" for name, row in sorted(_COMMITTED.elements.items())
            for a in row.attributes if a.default is None and a.computed is None
            and unset.reason(_COMMITTED, row, a, unset.load()) is None]
    assert left == []


def test_a_recorded_reason_names_an_attribute_that_has_no_default() -> None:
    """An entry goes stale when the probe finds the default (or a rule covers it)."""
    for (name, attr_name), why in unset.load().items():
        row = _COMMITTED.elements[name]
        attr = row.attribute(attr_name)
        assert attr.default is None and attr.computed is None, (name, attr_name, why)
        assert unset.rule(row, attr) is None, (name, attr_name)


def test_a_recorded_computation_is_the_attribute_s_computed() -> None:
    """[computed.ROW] is written into schema/ by the probe, typed-by-hand attributes too."""
    for (name, attr_name), why in unset.computed().items():
        attr = _COMMITTED.elements[name].attribute(attr_name)
        assert (attr.default, attr.computed) == (None, why), (name, attr_name)
    assert _COMMITTED.elements["default_geom"].attribute("mass").computed == \
        unset.computed()[("geom", "mass")]


def test_the_rules_give_reasons_by_kind_and_shape() -> None:
    body = _COMMITTED.elements["body"]
    assert unset.rule(body, body.attribute("name")) == _names()
    assert "alternative to quat" in (unset.rule(body, body.attribute("axisangle")) or "")
    assert "user data" in (unset.rule(body, body.attribute("user")) or "")
    key = _COMMITTED.elements["key"]
    assert "list" in (unset.rule(key, key.attribute("qpos")) or "")
    framepos = _COMMITTED.elements["framepos"]
    assert "together with refname" in (unset.rule(framepos, framepos.attribute("reftype")) or "")
    # a <default> row's copy takes its row's reason (the constraint is on the row)
    default_body = _COMMITTED.elements["default_geom"]
    assert "alternative" in (unset.reason(_COMMITTED, default_body,
                                          default_body.attribute("euler"), {}) or "")


def _names() -> str:
    return "a name: the element has none unless given"


def test_counts() -> None:
    """The states' counts (``python -m codegen.unset`` prints them)."""
    found = unset.states(_COMMITTED)
    assert "unknown" not in found and found["default"] > 1100
    assert sum(found.values()) == sum(len(r.attributes) for r in _COMMITTED.elements.values())


# ------------------------------------------------------ the probe on rows it now compiles


@pytest.fixture(scope="module")
def wheel() -> Wheel:
    return read_wheel()


@pytest.fixture
def schema() -> ir.Schema:
    return copy.deepcopy(_COMMITTED)


def check(schema: ir.Schema, wheel: Wheel, rows: set[str]) -> list[str]:
    assert wheel.drift_parser is not None
    found = drift.check(schema, wheel.drift_parser, wheel.reference, wheel.enums,
                        wheel.structs, drift.load_sites(), set(), set(), rows)
    return [c.line() for c in found.applied if c.what == "default"]


def _clear(schema: ir.Schema, rows: tuple[str, ...], name: str) -> None:
    for row in rows:
        schema.elements[row].attribute(name).default = None


def test_a_computed_value_gets_its_recorded_reason(schema: ir.Schema, wheel: Wheel) -> None:
    """position@timeconst: 0 (no filter) writes dynprm 0, absent keeps 1: no value reads as
    absent, and schema/unset.toml says why, not the generic text."""
    schema.elements["position"].attribute("timeconst").computed = drift.COMPUTED
    size = schema.elements["geom"].attribute("size")  # every probe model of a geom sets it
    size.computed = None
    assert check(schema, wheel, {"position", "geom"}) == [
        "position@timeconst default: (computed) -> (computed)",
        "geom@size default: (none) -> (computed)"]
    assert schema.elements["position"].attribute("timeconst").computed == \
        unset.computed()[("position", "timeconst")]
    assert size.computed == unset.computed()[("geom", "size")]


def test_a_tendon_s_default_is_probed_with_its_path(schema: ir.Schema, wheel: Wheel) -> None:
    """A fixed tendon compiles only with a path: schema/probe.toml's _content gives one."""
    _clear(schema, ("fixed",), "stiffness")
    assert check(schema, wheel, {"fixed"}) == ['fixed@stiffness default: (none) -> "0 0 0"']


def test_a_ball_joint_sensor_is_probed_on_a_ball_joint(schema: ir.Schema,
                                                        wheel: Wheel) -> None:
    _clear(schema, ("ballquat",), "noise")
    assert check(schema, wheel, {"ballquat"}) == ['ballquat@noise default: (none) -> "0"']


def test_a_flags_default_is_the_documented_set(schema: ir.Schema, wheel: Wheel) -> None:
    _clear(schema, ("camera", "default_camera"), "output")
    assert check(schema, wheel, {"camera"}) == ['camera@output default: (none) -> "rgb"']


def test_another_row_s_default_is_a_candidate(schema: ir.Schema, wheel: Wheel) -> None:
    """A flexcomp's radius is its flex's 0.005, which no plain value (0, 1, 2) is."""
    attr = schema.elements["flexcomp"].attribute("radius")
    attr.default, attr.computed = None, drift.COMPUTED
    assert check(schema, wheel, {"flexcomp"}) == [
        'flexcomp@radius default: (computed) -> "0.005"']


def test_an_orientation_alternative_loses_a_default_of_its_own(schema: ir.Schema,
                                                               wheel: Wheel) -> None:
    """axisangle="1 0 0 0" reads as absent on a flexcomp, but quat's default applies."""
    schema.elements["flexcomp"].attribute("axisangle").default = "1 0 0 0"
    assert check(schema, wheel, {"flexcomp"}) == [
        'flexcomp@axisangle default: "1 0 0 0" -> (none)']
    assert schema.elements["flexcomp"].attribute("quat").default == "1 0 0 0"


def test_a_default_row_of_its_own_takes_its_rows_agreed_default(schema: ir.Schema,
                                                                wheel: Wheel) -> None:
    """No probe model reaches <default><tendon>: fixed and spatial agree on its defaults."""
    _clear(schema, ("default_tendon",), "stiffness")
    assert check(schema, wheel, {"fixed"}) == [
        'default_tendon@stiffness default: (none) -> "0 0 0"']
