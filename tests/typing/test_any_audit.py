"""No ``Any`` in the types of the public API (see ``any_audit.py``, which also runs alone)."""

from __future__ import annotations

import pytest
from mypy.modulefinder import BuildSource

from tests.typing import any_audit
from tests.typing.any_audit import Audit

# Where the API meets mujoco: Any to a user's mypy if mujoco were untyped (it is typed by the
# shipped generated/mujoco-stubs, so the audit finds nothing there either).
MUJOCO_BOUNDARY = {
    "typed_mjcf.from_spec", "typed_mjcf.io.from_spec",
    "typed_mjcf._base.ModelRoot.compile", "typed_mjcf._base.ModelRoot.to_spec",
    "typed_mjcf._generated.elements.RootElement.compile (from ModelRoot)",
    "typed_mjcf._generated.elements.RootElement.to_spec (from ModelRoot)",
}


def listing(result: Audit) -> str:
    return "\n".join(f"  {f.symbol}: {f.where}: Any ({f.kind}) in {f.declared}"
                     for f in result.findings)


@pytest.fixture(scope="module")
def in_repo() -> Audit:
    return any_audit.run(as_user=False)


def test_no_any_in_the_public_api(in_repo: Audit) -> None:
    assert in_repo.classes > 300 and in_repo.symbols > 5000  # the walk reached the API
    assert not in_repo.unexpected, "Any in the public API:\n" + listing(in_repo)


def test_public_attributes_have_declared_types(in_repo: Audit) -> None:
    """pyright --verifytypes counts an inferred attribute as ambiguous, and through
    ``Element.spec`` that makes every class 'partially unknown'."""
    assert not in_repo.inferred, ("public attributes without a declared type:\n  "
                                  + "\n  ".join(in_repo.inferred))


def test_as_a_user_sees_it_only_mujoco_types_are_any() -> None:
    result = any_audit.run(as_user=True)
    outside = [f for f in result.findings
               if f.kind != "unresolved" or f.symbol not in MUJOCO_BOUNDARY]
    assert not outside, "Any beyond the mujoco boundary:\n" + listing(result)


PROBE = '''
from typing import Any, Callable, TypedDict
from typing_extensions import Unpack

class Options(TypedDict, total=False):
    level: Any

class Thing:
    def explicit(self, x: Any) -> int: ...
    def callback(self) -> Callable[..., int]: ...
    def untyped(self, x): ...
    def kwargs(self, **kwargs: Unpack[Options]) -> None: ...
    def clean(self, x: int) -> list[str]: ...
    @property
    def prop(self) -> dict[str, Any]: ...

def make() -> Thing: ...
'''


def test_the_audit_finds_every_kind_of_any() -> None:
    files = any_audit.analyse(sources=[BuildSource(None, "probe", PROBE)])
    result = any_audit.audit(files, modules=["probe"], packages=["probe"])
    found = {(f.symbol, f.kind) for f in result.findings}
    assert found == {
        ("probe.Thing.explicit", "explicit"),
        ("probe.Thing.callback", "explicit"),
        ("probe.Thing.untyped", "unannotated"),
        ("probe.Thing.kwargs", "explicit"),
        ("probe.Options", "explicit"),
        ("probe.Thing.prop", "explicit"),
    }, listing(result)
