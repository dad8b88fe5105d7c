"""What ``Physics.from_mjcf_model`` does beyond MuJoCo's compile of the model's text (issue 38:
its time against ``MjModel.from_xml_string``): the work only a failure or a file needs is not
done for a model without them. Counted, not timed (``python -m tests.bench --only bind``
times it)."""

from __future__ import annotations

import sys
from collections.abc import Callable
from types import FrameType

import typed_mjcf as mjcf
from typed_mjcf._model.validate import validate
from typed_mjcf._model.write import collect

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


def test_files_are_looked_for_only_among_the_attributes_that_name_files() -> None:
    """A model without files: collecting them visits each element once, not every attribute
    of its row (a geom's row has dozens), twice."""
    model = _bodies(100)
    elements = len(list(model.iter_elements()))
    collect(model)
    lines = lines_executed(lambda: collect(model))
    assert lines < 40 * elements, lines / elements  # was about 100 lines an element
