"""Numbers a float32 attribute (dtype "float" in schema/: ``rgba``, ``shininess``...) cannot
hold: MuJoCo's reader refuses a finite one beyond a float32's range ("number is too large"),
so every route refuses it with the library's error, the element left as it was, where numpy
would have made it inf silently. Infinity itself, spelled or given, is kept as MuJoCo keeps
it."""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.codecs import FLOAT32_MAX

# just beyond a float32's largest value (MuJoCo refuses it) and just within (it compiles)
BEYOND, WITHIN = 3.4028236e38, 3.4e38


def _geom_text(red: str) -> str:
    return f'<mujoco><worldbody><geom size="1" rgba="{red} 0 0 1"/></worldbody></mujoco>'


def _mujoco_reads(red: str) -> bool:
    try:
        mujoco.MjModel.from_xml_string(_geom_text(red))
    except ValueError as error:
        assert "number is too large" in str(error)
        return False
    return True


def test_mujoco_refuses_what_a_float32_cannot_hold() -> None:
    """The facts the library follows, measured on the installed MuJoCo."""
    assert BEYOND > FLOAT32_MAX > WITHIN
    assert [_mujoco_reads(t) for t in ("1e300", "-1e300", repr(BEYOND), repr(WITHIN), "inf")] \
        == [False, False, False, True, True]


def _model() -> tuple[mjcf.RootElement, mjcf.Geom]:
    model = mjcf.RootElement()
    geom = model.worldbody.add_geom(name="g", size=(1,), rgba=(0.5, 0.5, 0.5, 1))
    return model, geom


ROUTES: dict[str, Callable[[mjcf.Geom, float], None]] = {
    "tuple": lambda g, x: setattr(g, "rgba", (x, 0, 0, 1)),
    "list": lambda g, x: setattr(g, "rgba", [x, 0.0, 0.0, 1.0]),
    "numpy float64": lambda g, x: setattr(g, "rgba", np.array([x, 0, 0, 1])),
    "numpy scalars": lambda g, x: setattr(g, "rgba", [np.float64(x), 0, 0, 1]),
    "text": lambda g, x: setattr(g, "rgba", f"{x!r} 0 0 1"),
    "set_attributes": lambda g, x: g.set_attributes(rgba=(x, 0, 0, 1)),
}


@pytest.mark.parametrize("route", sorted(ROUTES))
@pytest.mark.parametrize("value", [1e300, -1e300, BEYOND])
def test_assigning_beyond_a_float32_is_refused(route: str, value: float) -> None:
    model, geom = _model()
    with pytest.raises(mjcf.InvalidValueError) as caught:
        ROUTES[route](geom, value)
    message = str(caught.value)
    assert message.startswith("worldbody/geom[g]: invalid rgba=") and "<geom>" in message
    assert "float32" in message and "3.4028235e+38" in message
    if route != "numpy float64":  # (numpy spells its array's numbers its own way)
        assert repr(value) in message
    assert geom.rgba is not None and geom.rgba.tolist() == [0.5, 0.5, 0.5, 1]
    assert 'rgba="0.5 0.5 0.5 1"' in model.to_xml_string()


@pytest.mark.parametrize("route", sorted(ROUTES))
def test_what_a_float32_holds_is_kept(route: str) -> None:
    _, geom = _model()
    for value in (WITHIN, float("inf"), -float("inf")):
        ROUTES[route](geom, value)
        assert geom.rgba is not None and geom.rgba[0] == np.float32(value)


def test_adding_beyond_a_float32_is_refused() -> None:
    model = mjcf.RootElement()
    with pytest.raises(mjcf.InvalidValueError, match="float32"):
        model.worldbody.add_geom(name="g", size=(1,), rgba=(1e300, 0, 0, 1))
    assert model.find("geom", "g") is None and model.worldbody.geom[:] == []


def test_a_single_float32_number_is_refused_too() -> None:
    model = mjcf.RootElement()
    material = model.asset.add_material(name="m", shininess=0.5)
    for value in (1e300, BEYOND, "1e300"):
        with pytest.raises(mjcf.InvalidValueError,
                           match=r"asset/material\[m\]: invalid shininess=.*float32"):
            setattr(material, "shininess", value)  # (the text too, which the setter's type refuses)
        assert material.shininess == 0.5
    material.shininess = float("inf")
    assert material.shininess == float("inf")


@pytest.mark.parametrize("text", ["1e300", repr(BEYOND)])
def test_reading_beyond_a_float32_is_refused(text: str) -> None:
    with pytest.raises(mjcf.ParseError, match="rgba.*float32"):
        mjcf.from_xml_string(_geom_text(text))
    assert mjcf.from_xml_string(_geom_text(repr(WITHIN))).worldbody.geom[0].rgba is not None


def test_a_double_attribute_takes_any_double() -> None:
    _, geom = _model()
    geom.pos = (1e300, 0, 0)
    assert geom.pos is not None and geom.pos[0] == 1e300
