# Generated from src/typed_mjcf/_model/validate.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""Whole-model checks: the rules of MuJoCo that no single assignment can enforce.

Assignment already checks each value on its own (types, keywords, lengths, unique names).
What is left needs the whole model: attributes that exclude or require each other, required
attributes and children, references that must name something, and default classes. The
checks run in one pass over the tree (plus work proportional to what they find), so
validating is O(N) in the number of elements.

Every finding has a rule name (see :data:`RULES`), the path of the element and a message;
``str(finding)`` is ``"path: rule: message"``. Errors are what MuJoCo would refuse; warnings
(``unused-default``) are legal but probably not meant.
"""
from __future__ import annotations
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Final, Literal, cast
from typed_mjcf._core.errors import InvalidValueError, did_you_mean
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
Severity = Literal["error", "warning"]
Rule = Literal[
    "exclusive", "together", "requires", "oneof", "required-attribute", "required-child",
    "range", "unresolved-reference", "default-class", "world-body", "replicate-joint", "self-attach",
    "replicate-names", "unused-default", "child-needs", "repeated-name",
]
RULES: Final[dict[Rule, str]] = ...

@dataclass(frozen=True, slots=True)
class Finding:
    """One problem found in a model: where, which rule, what."""
    path: str
    rule: Rule
    message: str
    severity: Severity = "error"
    element: Element | None = field(default=None, compare=False, repr=False)
    def __str__(self) -> str: ...

class ValidationError(InvalidValueError):
    """The model breaks rules MuJoCo enforces; ``findings`` lists every problem found."""
    def __init__(self, findings: Sequence[Finding]) -> None:
        self.findings: tuple[Finding, ...] = tuple(findings)
        errors = [f for f in self.findings if f.severity == "error"]
        warnings = [f for f in self.findings if f.severity == "warning"]
        lines = [f"the model is not valid MJCF ({_count(len(errors), 'error')}):"]
        lines += [f"  {finding}" for finding in errors]
        if warnings:
            lines.append(f"and {_count(len(warnings), 'warning')}:")
            lines += [f"  {finding}" for finding in warnings]
        super().__init__("\n".join(lines))
    @property
    def errors(self) -> tuple[Finding, ...]: ...

def _count(n: int, noun: str) -> str: ...

def errors(findings: Iterable[Finding]) -> list[Finding]:
    """The findings that are errors."""
    ...

def ensure_valid(model: ModelBase) -> list[Finding]:
    """Raise :class:`ValidationError` if the model has errors; else return its warnings."""
    ...
Owner = Literal["in_world", "in_body", "in_replicate"]

def validate(model: ModelBase) -> list[Finding]:
    """Every finding in ``model``, in document order; empty when MuJoCo's rules hold."""
    ...

def keeps(value: object, conditions: tuple[tuple[str, float], ...]) -> bool:
    """Whether every number of ``value`` (a number or an array, as read) keeps all
    ``conditions`` (an attribute's ``bounds`` or ``off``)."""
    ...

def ensure_no_crash(model: ModelBase) -> None:
    """Raise :class:`ValidationError` for what would crash MuJoCo (``child_needs``), in
    ``model`` and the models attached to it: for the routes that compile a model without
    validating it (a composed model's keyframes)."""
    ...

def expected_bounds(attribute: AttributeSpec) -> str:
    """What ``attribute``'s bounds expect, e.g. "each value >= 0 (MuJoCo refuses others)"."""
    ...

def element_in_model(model: ModelBase, target: Element) -> bool:
    """Whether a reference to ``target`` can be written for ``model``: the target is in
    ``model`` or in a model attached into it."""
    ...
