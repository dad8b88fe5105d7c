"""A compiled model's state written with ``mj_saveModel`` is ``__getstate__``'s, byte for byte,
and a Physics' model made from it is the compiled model (``typed_mjcf._sim.model_state``)."""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import pytest

import typed_mjcf
from typed_mjcf._sim import model_state as _model_state
from typed_mjcf._sim.model_state import model_state
from typed_mjcf.physics import Physics

TEXTURED = """<mujoco><asset>
  <texture name="sky" type="skybox" builtin="gradient" width="512" height="512"/>
  <texture name="grid" type="2d" builtin="checker" width="1024" height="1024"/>
  <material name="grid" texture="grid"/></asset>
  <worldbody><geom type="plane" size="1 1 1" material="grid"/>
    <body><freejoint/><geom size=".1"/></body></worldbody></mujoco>"""
SUITE = ("cartpole.xml", "humanoid.xml")


def models() -> list[mujoco.MjModel]:
    found = [mujoco.MjModel.from_xml_string(TEXTURED)]
    suite = pytest.importorskip("dm_control.suite")
    folder = suite.__path__[0]
    found += [mujoco.MjModel.from_xml_path(f"{folder}/{name}") for name in SUITE]
    return found


def test_the_state_is_getstates() -> None:
    assert _model_state._template() is not None  # the installed MuJoCo's format is known
    for model in models():
        assert model_state(model) == model.__getstate__()


FORMATS: dict[str, tuple[Callable[[bytes], bytes], bool]] = {
    # the size written once: the rule learnt still holds, the state is still written fast
    "size once": (lambda state: state[:9] + state[17:], True),
    # no size in the header: nothing to learn
    "no size": (lambda state: b"\x02" + state[17:], False),
    # a second field that is not the size (twice it): learnt from one probe, wrong on the other
    "another field": (lambda state: state[:9] + (2 * int.from_bytes(state[1:9], "little")
                                                 ).to_bytes(8, "little") + state[17:], False),
}


@pytest.mark.parametrize("name", FORMATS)
def test_another_format_is_learnt_or_falls_back_to_getstate(
        name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Another release's pickling format: ``model_state`` still gives ``__getstate__``'s
    bytes, written fast where the header's rule holds."""
    change, learnt = FORMATS[name]
    real = mujoco.MjModel.__getstate__
    monkeypatch.setattr(mujoco.MjModel, "__getstate__",
                        lambda model: change(real(model)))
    _model_state._template.cache_clear()
    try:
        assert (_model_state._template() is not None) == learnt
        for model in models():
            assert model_state(model) == model.__getstate__()
    finally:
        monkeypatch.undo()
        _model_state._template.cache_clear()


def test_physics_holds_the_compiled_model() -> None:
    root = typed_mjcf.from_xml_string(TEXTURED)
    physics = Physics.from_mjcf_model(root)
    expected = root.compile()
    assert physics.model.__getstate__() == expected.__getstate__()
    physics.step()
    assert physics.data.time > 0
