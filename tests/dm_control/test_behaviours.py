"""dm_control's behaviours as a table (``typed_mjcf.Behaviour``): each flag on alone does what
its line says and nothing without it; the docs list the table; the presets and the ways to
select one; dm_control's naming rules, each in one home."""

from __future__ import annotations

import dataclasses
import hashlib
import re
import sys
import types
from collections.abc import Callable, Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import typed_mjcf as mjcf
from tests.support.meshes import box_stl
from typed_mjcf._core.behaviour import listing

DOCS = Path(__file__).resolve().parents[2] / "docs" / "guide" / "dm-control.md"
FLAGS = [flag.name for flag in dataclasses.fields(mjcf.Behaviour)]


@pytest.fixture(autouse=True)
def _typed() -> Iterator[None]:
    """Every test starts and ends with the typed API's choices."""
    with mjcf.behaviour(mjcf.Behaviour.typed()):
        yield


def _model() -> mjcf.RootElement:
    return mjcf.RootElement(model="m")


# ---------------------------------------------------------------------------- one check per flag
# flag -> what to observe, and what it gives (on, off)


def _arrays_in_place() -> object:
    body = _model().worldbody.add_body(pos=(1, 2, 3))
    try:
        body.pos[0] = 5  # type: ignore[index]
    except ValueError:  # read-only
        pass
    return body.pos.tolist()  # type: ignore[union-attr]


def _on_demand_children() -> object:
    return _model().worldbody.add_body().inertial is None  # type: ignore[comparison-overlap]


def _single_freejoint() -> object:
    body = _model().worldbody.add_body()
    body.add_freejoint()
    return isinstance(body.freejoint, mjcf.Element)


def _once_only_children_by_tag() -> object:
    return isinstance(_model().worldbody.add_body().get_children("inertial"), mjcf.Element)


def _eager_children() -> object:
    return "compiler" in [child.tag for child in _model().get_children()]


def _unnamed_identifiers() -> object:
    return _model().worldbody.add_body().full_identifier


def _frame_names_end_in_separator() -> object:
    arena = mjcf.RootElement(model="arena")
    frame = arena.worldbody.add_site(name="s").attach(mjcf.RootElement(model="robot"))
    return frame.add_joint(name="root_x").full_identifier


def _unnamed_model_name() -> object:
    return mjcf.RootElement().model


def _hashed_file_names() -> object:
    model = _model()
    model.asset.add_mesh(name="cube", file=mjcf.Asset(box_stl(0.1), ".stl", name="cube"))
    return list(model.get_assets())


def _named_after_files() -> object:
    mesh = _model().asset.add_mesh(file=mjcf.Asset(box_stl(0.1), ".stl", name="cube"))
    return mesh.name


def _references_stay_names() -> object:
    model = _model()
    model.worldbody.add_body(name="b")
    return model.contact.add_exclude(body1="b", body2="b").body1


def _element_name_keyword() -> object:
    body = _model().worldbody.add_body()
    try:
        return body.add(element_name="geom", size=[0.1]).tag  # type: ignore[call-overload]
    except mjcf.InvalidTypeError:
        return "refused"


def _scalar_copies() -> object:
    model = _model()
    geom = model.worldbody.add_geom(type="sphere", size=(0.1,), contype=3)
    return type(mjcf.Physics.from_mjcf_model(model).bind(geom).contype).__name__


def _dm_control_physics_error(monkeypatch: pytest.MonkeyPatch) -> object:
    control = types.ModuleType("dm_control.rl.control")
    theirs = type("PhysicsError", (RuntimeError,), {})
    setattr(control, "PhysicsError", theirs)
    monkeypatch.setitem(sys.modules, "dm_control.rl.control", control)
    model = _model()
    body = model.worldbody.add_body()
    body.add_freejoint()
    body.add_geom(type="sphere", size=(0.1,))
    physics = mjcf.Physics.from_mjcf_model(model)
    physics.data.qpos[0] = np.nan
    with pytest.raises(mjcf.PhysicsError) as raised:
        physics.step()
    return isinstance(raised.value, theirs)


def _compile_error_advice() -> object:
    model = _model()
    model.actuator.add_motor(name="drive", joint="nowhere")
    with pytest.raises(mjcf.ValidationError) as refused:
        mjcf.Physics.from_mjcf_model(model)
    return "--pymjcf_debug" in str(refused.value)


CHECKS: dict[str, tuple[Callable[..., object], object, object]] = {
    "arrays_in_place": (_arrays_in_place, [5, 2, 3], [1, 2, 3]),
    "on_demand_children": (_on_demand_children, True, False),
    "single_freejoint": (_single_freejoint, True, False),
    "once_only_children_by_tag": (_once_only_children_by_tag, True, False),
    "eager_children": (_eager_children, True, False),
    "unnamed_identifiers": (_unnamed_identifiers, "//unnamed_body_0", None),
    "frame_names_end_in_separator": (_frame_names_end_in_separator, "robot/root_x/",
                                     "robot/root_x"),
    "unnamed_model_name": (_unnamed_model_name, "unnamed_model", None),
    "hashed_file_names": (
        _hashed_file_names,
        [f"cube-{hashlib.sha1(box_stl(0.1), usedforsecurity=False).hexdigest()}.stl"],
        ["cube.stl"]),
    "named_after_files": (_named_after_files, "cube", None),
    "references_stay_names": (_references_stay_names, "b", None),  # None: see below
    "element_name_keyword": (_element_name_keyword, "geom", "refused"),
    "scalar_copies": (_scalar_copies, "int32", "BoundArray"),
    "dm_control_physics_error": (_dm_control_physics_error, True, False),
    "compile_error_advice": (_compile_error_advice, True, False),
}


def test_every_flag_has_a_check() -> None:
    assert list(CHECKS) == FLAGS


def _observe(flag: str, monkeypatch: pytest.MonkeyPatch) -> object:
    check = CHECKS[flag][0]
    found = check(monkeypatch) if check is _dm_control_physics_error else check()
    if flag == "references_stay_names" and isinstance(found, mjcf.Element):
        return None  # linked: the body itself
    return found


@pytest.mark.parametrize("flag", FLAGS)
def test_a_flag_on_alone_does_what_it_says(flag: str, monkeypatch: pytest.MonkeyPatch) -> None:
    with mjcf.behaviour(mjcf.Behaviour(**{flag: True})):
        assert _observe(flag, monkeypatch) == CHECKS[flag][1]


@pytest.mark.parametrize("flag", FLAGS)
def test_without_the_flag_the_typed_api_keeps_its_choice(
        flag: str, monkeypatch: pytest.MonkeyPatch) -> None:
    every_other = dataclasses.replace(mjcf.Behaviour.dm_control(), **{flag: False})
    assert _observe(flag, monkeypatch) == CHECKS[flag][2]
    with mjcf.behaviour(every_other):  # the others on do not bring it back
        assert _observe(flag, monkeypatch) == CHECKS[flag][2]


# ---------------------------------------------------------------------------- the table itself


def test_the_docs_list_the_table() -> None:
    """docs/guide/dm-control.md lists the flags as ``listing()`` gives them (paste it there)."""
    text = DOCS.read_text(encoding="utf-8")
    found = re.search(r"<!-- behaviours: .*? -->\n(.*?)\n<!-- /behaviours -->", text,
                      re.DOTALL)
    assert found is not None, "the docs lost their list of behaviours"
    assert found.group(1).splitlines() == listing()


def test_the_presets_and_selecting_one() -> None:
    assert mjcf.current_behaviour() == mjcf.Behaviour.typed() == mjcf.Behaviour()
    dm = mjcf.Behaviour.dm_control()
    assert all(getattr(dm, flag) for flag in FLAGS)
    previous = mjcf.set_behaviour(dm)
    try:
        assert previous == mjcf.Behaviour.typed() and mjcf.current_behaviour() == dm
        with mjcf.behaviour(mjcf.Behaviour(unnamed_model_name=True)) as chosen:
            assert chosen.unnamed_model_name and not chosen.arrays_in_place
            assert mjcf.current_behaviour() == chosen
        assert mjcf.current_behaviour() == dm
    finally:
        mjcf.set_behaviour(previous)
    with pytest.raises(dataclasses.FrozenInstanceError):
        dm.arrays_in_place = False  # type: ignore[misc]
    with pytest.raises(TypeError, match="takes a typed_mjcf.Behaviour, got bool"):
        mjcf.set_behaviour(True)  # type: ignore[arg-type]


def test_install_selects_dm_controls_preset() -> None:
    from typed_mjcf._dmcompat import installed

    with installed():
        assert mjcf.current_behaviour() == mjcf.Behaviour.dm_control()
    assert mjcf.current_behaviour() == mjcf.Behaviour.typed()


# ---------------------------------------------------------------------------- naming rules, one home


def test_an_attachment_frame_counts_among_unnamed_bodies_in_the_xml_too() -> None:
    """dm_control counts an attachment frame among its model's bodies (dm_control 1.0.49:
    ``//unnamed_body_1`` for the body after it); the XML named that body as
    ``full_identifier`` did not (``//unnamed_body_0``, a name MuJoCo then had twice)."""
    with mjcf.behaviour(mjcf.Behaviour.dm_control()):
        arena = mjcf.RootElement(model="arena")
        robot = mjcf.RootElement(model="robot")
        robot.worldbody.add_body()
        arena.worldbody.add_site(name="s").attach(robot)
        body = arena.worldbody.add_body()
        assert body.full_identifier == "//unnamed_body_1"
        assert '<body name="//unnamed_body_1"/>' in arena.to_xml_string()
        compiled = arena.compile()
    names = [mujoco.mj_id2name(compiled, mujoco.mjtObj.mjOBJ_BODY, i)
             for i in range(compiled.nbody)]
    assert names == ["world", "robot/", "robot//unnamed_body_0", "//unnamed_body_1"]


def test_an_unnamed_asset_is_named_as_mujoco_names_its_file() -> None:
    """A mesh named after its file takes the name MuJoCo gives the file the typed API
    writes: an in-memory asset's name (its dots kept), else the element's tag."""
    def meshes() -> list[mjcf.Mesh]:
        model = _model()
        return [model.asset.add_mesh(file=mjcf.Asset(box_stl(0.1), ".stl", name="cube.v2")),
                model.asset.add_mesh(file=mjcf.Asset(box_stl(0.2), ".stl"))]

    typed = meshes()
    compiled = typed[0].root.compile()
    given = [mujoco.mj_id2name(compiled, mujoco.mjtObj.mjOBJ_MESH, i) for i in range(2)]
    assert given == ["cube.v2", "mesh"]
    with mjcf.behaviour(mjcf.Behaviour(named_after_files=True)):
        assert [mesh.name for mesh in meshes()] == given
