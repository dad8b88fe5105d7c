"""What ``Physics.from_mjcf_model`` does beyond MuJoCo's compile of the model's text (issue 38:
its time against ``MjModel.from_xml_string``): the work only a failure or a file needs is not
done for a model without them. Counted, not timed (``python -m tests.bench --only bind``
times it)."""

from __future__ import annotations

import sys
from collections.abc import Callable, Mapping
from types import FrameType
from typing import cast

import mujoco
import pytest

import typed_mjcf as mjcf
from typed_mjcf._core.tree import Element, iter_composed
from typed_mjcf._model.validate import validate
from typed_mjcf._model.write import collect
from typed_mjcf._sim.ids import _MARK, _namer, _spec_id, _unmark  # pyright: ignore[reportPrivateUsage]
from typed_mjcf._sim.text import vfs_text
from typed_mjcf.physics import Physics  # (its generated bindings fill binding_tables())

from ..compiled import skip_counting
from ..operations import lines_executed


def _bodies(n: int, *, named_geoms: bool = False) -> mjcf.RootElement:
    model = mjcf.RootElement(model="m")
    for i in range(n):
        body = model.worldbody.add_body(name=f"b{i}", pos=(i, 0, 1))
        body.add_joint(name=f"j{i}", axis=(0, 1, 0))
        body.add_geom(name=f"g{i}" if named_geoms else None, type="capsule", size=(0.02,),
                      fromto=(0, 0, 0, 0, 0, 0.1))
    return model


def _joins(call: Callable[[], object]) -> int:
    """How many times ``call()`` calls ``str.join``."""
    count = 0

    def profile(frame: FrameType, event: str, arg: object) -> None:
        nonlocal count
        if event == "c_call" and getattr(arg, "__name__", None) == "join" and isinstance(
                getattr(arg, "__self__", None), str):
            count += 1

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        call()
    finally:
        sys.setprofile(previous)
    return count


def test_a_valid_model_is_validated_without_writing_a_message() -> None:
    """Geoms and bodies have a constraint (at most one of quat, axisangle, ...): when it
    holds, the names it lists are not joined (that was a tenth of the pass)."""
    model = _bodies(50)
    assert validate(model) == []
    assert _joins(lambda: validate(model)) == 0
    body = model.worldbody.body[0]
    body.quat, body.euler = (1, 0, 0, 0), (0, 0, 0)
    finding = validate(model)[0]
    assert "at most one of quat | axisangle | xyaxes | zaxis | euler" in str(finding)


def test_the_walk_in_export_order_calls_no_function_per_element() -> None:
    """``iter_composed`` (the marks of unnamed elements, the compile limits, the export walk
    it): an element's children are read from the tree without a copy or an accessor call;
    what remains per element is resuming the two generators."""
    skip_counting(("_core.tree",))  # (compiled, its calls make no profile events)
    model = _bodies(100)
    elements = len(list(model.iter_elements()))
    calls = 0

    def profile(frame: FrameType, event: str, arg: object) -> None:
        nonlocal calls
        calls += event == "call"

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        walked = list(iter_composed(model, True))
    finally:
        sys.setprofile(previous)
    assert walked == list(model.iter_elements())  # (no attachments: document order)
    assert calls < 3 * elements, calls / elements  # was 4 an element


def test_files_are_looked_for_only_among_the_attributes_that_name_files() -> None:
    """A model without files: collecting them visits each element once, not every attribute
    of its row (a geom's row has dozens), twice."""
    model = _bodies(100)
    elements = len(list(model.iter_elements()))
    collect(model)
    lines = lines_executed(lambda: collect(model), counted=("_text.files", "_core.tree"))
    assert lines < 40 * elements, lines / elements  # was about 100 lines an element


class _Watched:
    """A spec that records which of its attributes are read."""

    def __init__(self, spec: mujoco.MjSpec) -> None:
        self.spec = spec
        self.read: list[str] = []

    def __getattr__(self, name: str) -> object:
        self.read.append(name)
        return cast(object, getattr(self.spec, name))


def _replicated() -> mjcf.RootElement:
    model = mjcf.from_xml_string("""<mujoco><worldbody>
      <replicate count="3" offset="1 0 0"><body><joint/><geom size=".1"/><site/>
        <replicate count="2" offset="0 1 0"><frame><body name="n"><joint/><geom size=".1"/>
          <camera/><light/></body></frame></replicate></body></replicate>
      <frame><geom size=".2"/><body><freejoint/><geom size=".1"/></body></frame>
      <body name="last"><geom size=".1"/></body>
    </worldbody></mujoco>""")
    return model


@pytest.mark.parametrize("make", [_replicated, lambda: _bodies(20)])
def test_marked_objects_are_found_body_by_body(make: Callable[[], mjcf.RootElement]) -> None:
    """MuJoCo reads a spec-wide list of objects bodies hold (``spec.geoms``) by a search of
    the whole tree for each next one (quadratic: 215 ms for 4,000 geoms): the marks are found
    in each body's own lists, which hold the same objects in the same order."""
    model = make()
    marks: list[Element] = []
    text, _ = vfs_text(model, namer=_namer(model, marks, {}))
    assert marks
    spec = mujoco.MjSpec.from_string(text)
    watched = _Watched(spec)
    found = _unmark(cast(mujoco.MjSpec, watched), marks)
    assert not {"bodies", "geoms", "joints", "sites", "cameras", "lights"} & set(watched.read)
    spec.compile()
    # the same objects in the same order as the spec's own lists give them (a spec compiled
    # with the marks kept: names do not change the ids)
    again = mujoco.MjSpec.from_string(text)
    again.compile()
    expected: dict[int, list[int]] = {}
    for objects in (again.bodies, again.geoms, again.joints, again.sites, again.cameras,
                    again.lights):
        for obj in objects:
            if _MARK in obj.name:
                element = marks[int(obj.name.split("-")[-2])]
                expected.setdefault(id(element), []).append(obj.id)
    assert {key: [_spec_id(obj) for obj in objects]
            for key, (_, objects) in found.items()} == expected


def test_a_model_with_every_bound_element_named_is_compiled_without_a_spec(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """No marks to find: the text is compiled as ``compile()`` compiles it, with no MjSpec
    made and edited."""
    model = _bodies(3, named_geoms=True)
    made: list[str] = []
    real = mujoco.MjSpec.from_string

    def counting(xml: str, include: Mapping[str, bytes] | None = None,
                 assets: dict[str, bytes] | None = None) -> mujoco.MjSpec:
        made.append(xml)
        return real(xml, include=include, assets=assets)

    monkeypatch.setattr(mujoco.MjSpec, "from_string", counting)
    physics = Physics.from_mjcf_model(model)
    assert made == []
    assert physics.bind(model.find_all("geom")[1]).element_id == 1
    unnamed = _bodies(3)
    Physics.from_mjcf_model(unnamed)  # unnamed geoms: marked, found in a spec
    assert len(made) == 1
