"""A bind of many elements reads the kind's names once (typed_mjcf._sim.name_table) instead of an
mj_name2id call per element; the ids are the ones mj_name2id gives."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from typed_mjcf._sim.binding import binding_tables
from typed_mjcf._sim.name_table import name_ids
from typed_mjcf.physics import Physics  # (its generated bindings fill binding_tables())

from ..operations import lines_executed


def _arm(name: str) -> mjcf.RootElement:
    arm = mjcf.RootElement(model=name)
    body = arm.worldbody.add_body(name="l0")
    for k in range(4):
        body.add_joint(name=f"j{k}", axis=(0, 1, 0))
        body.add_joint(axis=(1, 0, 0))  # unnamed
        body.add_geom(type="capsule", size=(0.02,), fromto=(0, 0, 0, 0, 0, 0.1))
        arm.actuator.add_motor(name=f"m{k}", joint=f"j{k}")
        body = body.add_body(name=f"l{k + 1}", pos=(0, 0, 0.1))
    return arm


def _model() -> mjcf.RootElement:
    model = mjcf.RootElement(model="world")
    for i in range(3):
        site = model.worldbody.add_site(name=f"mount{i}", pos=(i, 0, 0))
        site.attach(_arm(f"arm{i}"))
    model.worldbody.add_body(name="free").add_freejoint(name="free")
    model.worldbody.body[-1].add_geom(size=(0.1,))
    return model


def test_the_name_table_of_every_kind_is_mj_name2id() -> None:
    compiled = _model().compile()
    made = 0
    for kind in binding_tables().kinds.values():
        table = name_ids(compiled, kind.size)
        if table is None:
            continue
        made += 1
        objtype = getattr(mujoco.mjtObj, kind.objtype)
        count = int(getattr(compiled, kind.size))
        named = {mujoco.mj_id2name(compiled, objtype, i) for i in range(count)} - {None, ""}
        assert set(table) == named, kind
        assert all(mujoco.mj_name2id(compiled, objtype, n) == i for n, i in table.items())
    assert made >= 3  # bodies, joints, geoms at least


def test_a_large_bind_asks_mj_name2id_for_no_name(monkeypatch: pytest.MonkeyPatch) -> None:
    model = _model()
    joints = [j for j in model.find_all("joint") if j.name is not None]
    physics = Physics.from_mjcf_model(model)
    m, d = physics.model, physics.data
    d.qpos[:] = np.arange(m.nq)
    expected = [d.qpos[m.jnt_qposadr[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT,
                                                         str(j.full_identifier))]]
                for j in joints if j.tag == "joint"]
    calls: list[str] = []
    real = mujoco.mj_name2id

    def counting(model: mujoco.MjModel, objtype: int, name: str) -> int:
        calls.append(name)
        return real(model, objtype, name)

    monkeypatch.setattr(mujoco, "mj_name2id", counting)
    hinges = [j for j in joints if j.tag == "joint"]
    np.testing.assert_array_equal(physics.bind(hinges).qpos, expected)
    assert calls == []
    with pytest.raises(mjcf.BindingError, match="multiple element types"):
        mixed: list[mjcf.Element] = [*hinges, model.worldbody.body[-1]]
        physics.bind(mixed)


def test_a_large_bind_finds_kind_and_ids_without_a_loop_over_them_in_python() -> None:
    """Issue 38: a first bind against mj_name2id by hand. The elements' kind is found per
    class (one class per row) and a batch whose names all find an object is looked up at
    once; what is left per element is its scoped name (about 10 Python lines an element, was
    23). The ids are those each element alone binds to, and the batch of any other case
    (an unnamed element, one named after the compile) goes element by element."""
    model = mjcf.RootElement(model="many")
    for i in range(400):
        body = model.worldbody.add_body(name=f"b{i}", pos=(i, 0, 0))
        body.add_joint(name=f"j{i}", axis=(0, 1, 0))
        body.add_joint(axis=(1, 0, 0))  # unnamed
        body.add_geom(size=(0.1,))
    physics = Physics.from_mjcf_model(model)
    named = [j for j in model.find_all("joint") if j.name is not None]
    physics.bind(named)
    physics._bindings.clear()  # pyright: ignore[reportPrivateUsage]  # a first bind again
    lines = lines_executed(lambda: physics.bind(named),
                           counted=("_core.tree", "physics", "_sim.name_table", "_sim.binding"))
    assert lines < 15 * len(named), lines / len(named)
    every = model.find_all("joint")
    alone = [physics.bind(j).element_id for j in every]
    np.testing.assert_array_equal(physics.bind(named).element_id, alone[0::2])
    np.testing.assert_array_equal(physics.bind(every).element_id, alone)
    later = every[1]
    later.name = "named_later"  # not in the compiled model: found where it was compiled
    np.testing.assert_array_equal(physics.bind([*named, later]).element_id,
                                  [*alone[0::2], alone[1]])
