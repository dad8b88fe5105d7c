"""dm_control.mjcf's own unit tests, run against typed_mjcf (see ``harness.py``).

Each test either passes or is listed in ``DIFFERENCES`` with the reason: a test of
dm_control's internals, or a deliberate difference documented in the README's "Migrating
from dm_control" section. A listed test that starts passing fails here (strict), so the
list stays true.
"""

from __future__ import annotations

import types
from functools import cache

import pytest

from . import harness

pytestmark = pytest.mark.skipif(harness.mjcf_folder() is None, reason="dm_control is not installed")

# Each reason names the README's "Migrating from dm_control" entry it is documented under.
INTERNALS = ("a test of dm_control's private slots: it sets element._spec = None and expects "
             "the tag property to fail reading it (README: Running dm_control's code "
             "unchanged)")
MIXED_BODIES = ("bind() takes mocap and other bodies together, as bodies; dm_control refuses "
                "the list as of two element types (README: Physics)")
SPELLING = ("the XML is written without dm_control's class=\"/\" on every element, with "
            "childclass=\"<model>/\" on an attachment frame and numbers as their shortest "
            "text (the classes that apply and the values are the same) (README: output)")
COMPOSITE = ("MuJoCo 4.0 removed <composite>, and typed-mjcf's grammar is the installed "
             "MuJoCo's (README: Physics)")
MESSAGES = ("error messages are worded differently (the exception classes are dm_control's) "
            "(README: errors)")
SPELLING_AND_MESSAGES = f"{SPELLING}; {MESSAGES}"

DIFFERENCES: dict[str, str] = {
    "element_test.ElementTest.testAttributeError": INTERNALS,
    "element_test.ElementTest.testAttach": SPELLING_AND_MESSAGES,
    "physics_test.PhysicsTest.test_bind_mocap_body": MIXED_BODIES,
    "physics_test.PhysicsTest.test_plugins_elasticity": COMPOSITE,
    "element_test.ElementTest.testAttachmentFrameChildReference": SPELLING,
    "element_test.ElementTest.testAttachmentFrames": SPELLING,
    "element_test.ElementTest.testDefaultIdentifier": SPELLING,
    "element_test.ElementTest.testSetAndGetAttributes": MESSAGES,
}


@cache
def module(name: str) -> types.ModuleType:
    return harness.load(name)


def cases() -> list[object]:
    if harness.mjcf_folder() is None:
        return []
    params: list[object] = []
    for name in harness.MODULES:
        for test_id in harness.test_ids(module(name)):
            key = f"{name}.{test_id}"
            reason = DIFFERENCES.get(key)
            marks = [pytest.mark.xfail(reason=reason, strict=True)] if reason else []
            params.append(pytest.param(name, test_id, id=key, marks=marks))
    return params


@pytest.mark.parametrize(("module_name", "test_id"), cases())
def test_dm_control(module_name: str, test_id: str) -> None:
    result = harness.run(module(module_name), test_id)
    assert result.testsRun >= 1
    problems = [*result.failures, *result.errors]
    if problems:
        pytest.fail("\n\n".join(text for _, text in problems), pytrace=False)
    if result.skipped:
        pytest.skip("; ".join(reason for _, reason in result.skipped))
