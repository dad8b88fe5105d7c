"""Property-based fidelity: random models built through the typed API.

Whenever ``validate(model)`` finds no error, MuJoCo's parser accepts the exported MJCF
(``MjSpec.from_string``; compiling is not required), and parse -> export is a fixed point.
Derandomized for CI stability: the same examples run every time.
"""

from __future__ import annotations

import mujoco
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import typed_mjcf as mjcf
from typed_mjcf._model.validate import validate

from .model_strategies import Builder

EXAMPLES = 100

SETTINGS = settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def _parser_error(xml: str) -> str | None:
    try:
        mujoco.MjSpec.from_string(xml)
    except ValueError as error:
        return str(error)
    return None


@SETTINGS
@given(st.data())
def test_models_without_errors_are_accepted_by_mujoco(data: st.DataObject) -> None:
    strict = data.draw(st.integers(0, 9), label="strict") < 9  # 1 in 10 breaks rules
    model = Builder(data, strict=strict).build()
    xml = model.to_xml_string()
    size = sum(1 for _ in model.iter_elements())
    event(f"elements: {'<10' if size < 10 else '10-29' if size < 30 else '30+'}")
    findings = validate(model)
    errors = [f for f in findings if f.severity == "error"]
    for finding in errors:
        event(f"error: {finding.rule}")
    if not errors:
        event("valid")
        message = _parser_error(xml)
        assert message is None, f"validate() found nothing, MuJoCo says: {message}\n{xml}"
    elif not strict:
        event("rule broken on purpose")


@SETTINGS
@given(st.data())
def test_parse_then_export_is_a_fixed_point(data: st.DataObject) -> None:
    model = Builder(data, strict=data.draw(st.booleans(), label="strict")).build()
    xml = model.to_xml_string()
    parsed = mjcf.from_xml_string(xml)
    again = parsed.to_xml_string()
    assert again == xml, f"exported:\n{xml}\nparsed and exported again:\n{again}"
    # what validate finds does not depend on how the model was made
    assert [str(f) for f in validate(parsed)] == [str(f) for f in validate(model)]
