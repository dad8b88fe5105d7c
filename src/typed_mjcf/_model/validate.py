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

import functools
import operator
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Final, Literal, cast

import numpy as np

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.errors import InvalidValueError, did_you_mean
from typed_mjcf._core.grammar import AttributeSpec, ElementSpec
from typed_mjcf._core.language import ChildNeeds
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._model.compiled_names import CompiledNames
from typed_mjcf._text.export import is_empty_single

Severity = Literal["error", "warning"]
Rule = Literal[
    "exclusive", "together", "requires", "oneof", "required-attribute", "required-child",
    "range", "unresolved-reference", "default-class", "world-body", "replicate-joint", "self-attach",
    "replicate-names", "unused-default", "child-needs", "repeated-name",
]

RULES: Final[dict[Rule, str]] = {
    "exclusive": "at most one of the grammar's exclusive attribute bundles may be present",
    "together": "attributes the grammar ties together appear all or none",
    "requires": "an attribute the grammar says requires others appears only with them",
    "oneof": "at least one of the grammar's alternative attribute bundles is complete",
    "required-attribute": "a required attribute is set (not checked in <default> classes)",
    "required-child": "a required child element is present",
    "range": "each number is within the bounds MuJoCo accepts (schema/facts.toml's bounds)",
    "unresolved-reference": "a reference names an element of the model (or one MuJoCo "
                            "defines); a warning in a <default> class",
    "default-class": "a nested <default> has a class name; the top-level one is 'main'",
    "world-body": "the world body has no joints and no <inertial> (also through <frame>s)",
    "replicate-joint": "a joint is not a direct child of <replicate> (also through <frame>s)",
    "self-attach": "an <attach> without model= (self-attachment) names a body= or frame=",
    "replicate-names": "no named sensor without an object when the model has several <replicate>s",
    "unused-default": "a default class is used by some class= or childclass= (warning)",
    "child-needs": "a child MuJoCo crashes on without some attributes has them "
                   "(schema/facts.toml's child_needs)",
    "repeated-name": "no name MuJoCo's compiler gives (a <replicate>'s copies, a mesh named "
                     "after its file) is another object's name",
}

# Suggestions ("did you mean") compare a name with every name of its namespace: only the first
# unresolved references get one, so that a broken model still validates in linear time.
_MAX_HINTS: Final = 20


@dataclass(frozen=True, slots=True)
class Finding:
    """One problem found in a model: where, which rule, what."""

    path: str
    rule: Rule
    message: str
    severity: Severity = "error"
    # the element found at fault, for tools that point into its file (typed_mjcf.cli check)
    element: Element | None = field(default=None, compare=False, repr=False)

    def __str__(self) -> str:
        return f"{self.path}: {self.rule}: {self.message}"


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
    def errors(self) -> tuple[Finding, ...]:
        return tuple(f for f in self.findings if f.severity == "error")


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def errors(findings: Iterable[Finding]) -> list[Finding]:
    """The findings that are errors."""
    return [f for f in findings if f.severity == "error"]


def ensure_valid(model: ModelBase) -> list[Finding]:
    """Raise :class:`ValidationError` if the model has errors; else return its warnings."""
    findings = validate(model)
    if any(f.severity == "error" for f in findings):
        raise ValidationError(findings)
    return findings


# ---------------------------------------------------------------------------- per-row plans


@dataclass(frozen=True, slots=True)
class _Plan:
    """What to check on the elements of one grammar row (computed once per row per call)."""

    constraints: tuple[tuple[str, tuple[tuple[str, ...], ...]], ...]
    required: tuple[AttributeSpec, ...]
    required_children: tuple[str, ...]
    references: tuple[AttributeSpec, ...]
    name_lists: tuple[AttributeSpec, ...]  # texts listing names, each checked as a reference
    bounded: tuple[AttributeSpec, ...]  # numbers with bounds
    off: tuple[AttributeSpec, ...]  # numbers with values that count as not set
    named_after_file: bool  # unnamed, MuJoCo names the element after its file


@functools.cache
def _rows_by_name() -> dict[str, ElementSpec]:
    return {cls.spec.row: cls.spec for cls in _tree.element_classes().values()}


@functools.cache
def _namespaces() -> frozenset[str]:
    return frozenset(cls.spec.namespace for cls in _tree.element_classes().values()
                     if cls.spec.namespace is not None)


def _projection_constraints(spec: ElementSpec) -> list[tuple[str, tuple[tuple[str, ...], ...]]]:
    """The exclusive constraints of the row a <default> row projects, over attributes the
    projection keeps: MuJoCo checks them in default classes too (e.g. <default><camera
    fovy sensorsize/>) though the generated projection rows do not carry them."""
    primary = _rows_by_name().get(spec.row.removeprefix("default_"))
    if primary is None or primary is spec:
        return []
    return [(kind, bundles) for kind, bundles in primary.constraints
            if kind == "exclusive"
            and all(name in spec.by_name for bundle in bundles for name in bundle)]


def _make_plan(spec: ElementSpec, projection: bool) -> _Plan:
    constraints = list(spec.constraints)
    if projection:
        # Attributes of default classes are optional by design: only exclusions apply.
        constraints = [c for c in constraints if c[0] == "exclusive"]
        constraints += [c for c in _projection_constraints(spec) if c not in constraints]
    return _Plan(
        constraints=tuple(constraints),
        required=() if projection else tuple(a for a in spec.attributes.values() if a.required),
        required_children=tuple(c.tag for c in spec.children.values() if c.card == "!"),
        references=spec.references,
        name_lists=tuple(a for a in spec.attributes.values() if a.name_list is not None),
        bounded=tuple(a for a in spec.attributes.values() if a.bounds),
        off=tuple(a for a in spec.attributes.values() if a.off),
        named_after_file=not projection and spec.namespace in grammar_facts().named_after_file,
    )


# ---------------------------------------------------------------------------- the pass


@dataclass(slots=True)
class _Pending:
    """A reference by name that the model's namespaces did not resolve during the pass."""

    order: int
    element: Element
    attribute: str
    namespace: str
    name: str
    in_default: bool  # made in a <default> class (not the class= of an element)


@dataclass(slots=True)
class _Pass:
    model: ModelBase
    namespaces: frozenset[str]
    found: list[tuple[int, int, Element, Rule, str, Severity]] = field(
        default_factory=list[tuple[int, int, Element, Rule, str, Severity]])
    plans: dict[tuple[int, bool], _Plan] = field(default_factory=dict[tuple[int, bool], _Plan])
    pending: list[_Pending] = field(default_factory=list[_Pending])
    replicates: int = 0
    named_after_files: bool = False  # some element is (compiled names to check)
    objectless_sensors: list[tuple[int, Element]] = field(
        default_factory=list[tuple[int, Element]])
    classes: dict[str, tuple[int, Element]] = field(default_factory=dict[str, tuple[int, Element]])
    used_classes: set[str] = field(default_factory=set[str])

    def add(self, order: int, element: Element, rule: Rule, message: str,
            severity: Severity = "error") -> None:
        # The path is computed only for findings, when they are reported.
        self.found.append((order, len(self.found), element, rule, message, severity))

    def plan(self, spec: ElementSpec, projection: bool) -> _Plan:
        key = (id(spec), projection)
        plan = self.plans.get(key)
        if plan is None:
            plan = self.plans[key] = _make_plan(spec, projection)
        return plan

    def findings(self) -> list[Finding]:
        self.found.sort(key=lambda item: (item[0], item[1]))
        paths = _tree.paths(element for _, _, element, _, _, _ in self.found)
        return [Finding(path, rule, message, severity, element)
                for path, (_, _, element, rule, message, severity) in zip(paths, self.found,
                                                                           strict=True)]


def _is_written(parent: Element, child: Element) -> bool:
    """Whether the exporter writes ``child`` (an empty once-only section is left out): only
    what MuJoCo reads is checked."""
    return not is_empty_single(parent, child)


Owner = Literal["in_world", "in_body", "in_replicate"]


def _owner(element: Element, parent: Element | None, owner: Owner | None,
           model: ModelBase) -> Owner | None:
    """What encloses ``element``'s children in the kinematic tree: the world body, a body or
    a replicate (frames are transparent); ``None`` outside the tree."""
    facts = grammar_facts()
    if not element.spec.holds_bodies or (owner is None and parent is not model):
        return None
    tag = element.spec.tag
    if owner is None:
        return "in_world"
    if tag == facts.frame:
        return owner
    return "in_replicate" if tag == facts.replicate else "in_body"


def validate(model: ModelBase) -> list[Finding]:
    """Every finding in ``model``, in document order; empty when MuJoCo's rules hold."""
    state = _Pass(model, _namespaces())
    order = 0
    # (element, parent, what encloses it in the kinematic tree)
    stack: list[tuple[Element, Element | None, Owner | None]] = [(model, None, None)]
    classes = grammar_facts().class_namespace
    while stack:
        element, parent, owner = stack.pop()
        order += 1
        projection = (parent is not None and parent.spec.namespace == classes
                      and element.spec.namespace != classes)
        _check_element(state, order, element, parent, projection)
        if owner is not None:
            _check_tree(state, order, element, owner)
        owner = _owner(element, parent, owner, model)
        for child in reversed(_tree.children(element)):
            if _is_written(element, child):
                stack.append((child, element, owner))
    if state.pending or state.replicates or state.named_after_files:
        compiled = CompiledNames(model)  # a walk of its own: only when names may be made
        _resolve_pending(state, compiled)
        _check_repeated_names(state, compiled)
    _check_replicated_sensors(state)
    _check_unused_classes(state)
    return state.findings()


def _check_element(state: _Pass, order: int, element: Element, parent: Element | None,
                   projection: bool) -> None:
    spec = element.spec
    attrs = _tree.values(element)
    plan = state.plan(spec, projection)
    tag = spec.tag
    facts = grammar_facts()
    if plan.constraints:
        set_attrs = _present(element, attrs, plan.off) if plan.off else attrs
        for kind, bundles in plan.constraints:
            _check_constraint(state, order, element, set_attrs, kind, bundles)
    for attribute in plan.required:
        if attribute.name not in attrs:
            state.add(order, element, "required-attribute",
                      f"<{tag}> requires the attribute {attribute.name!r}, which is not set")
    if plan.required_children:
        present = {child.spec.tag for child in _tree.children(element)
                   if _is_written(element, child)}
        for child_tag in plan.required_children:
            if child_tag not in present:
                state.add(order, element, "required-child",
                          f"<{tag}> requires a <{child_tag}> child, which it does not have "
                          f"(an empty one is not written)")
    for attribute in plan.bounded:
        if attribute.name in attrs:
            _check_bounds(state, order, element, attribute)
    if spec.namespace == facts.class_namespace:
        _declare_class(state, order, element, parent)
    needs = facts.child_needs.get(spec.row)
    if needs is not None and not projection:
        _check_child_needs(state, order, element, attrs, needs)
    if plan.references:
        skipped = _child_model_references(spec, attrs)
        for attribute in plan.references:
            value = attrs.get(attribute.name)
            if value is None or attribute.name in skipped:
                continue
            namespace = _tree.reference_namespace(element, attribute)
            if namespace is not None and namespace in state.namespaces:
                _check_reference(state, order, element, attribute.name, namespace, value)
    for attribute in plan.name_lists:
        value, listed = attrs.get(attribute.name), attribute.name_list
        if isinstance(value, str) and listed is not None and listed in state.namespaces:
            for name in value.split():
                _check_reference(state, order, element, attribute.name, listed, name)
    if tag == facts.replicate:
        state.replicates += 1
    elif (parent is not None and parent.spec.tag == facts.sensor_section and spec.namespace
          and _tree.element_name(element) is not None
          and not any(a.name in attrs for a in plan.references)):
        state.objectless_sensors.append((order, element))
    if plan.named_after_file and _tree.element_name(element) is None:
        state.named_after_files = True


def _check_tree(state: _Pass, order: int, element: Element, owner: Owner) -> None:
    """Rules of the kinematic tree: what the world body and replicates may hold."""
    facts = grammar_facts()
    tag = element.spec.tag
    joint = element.spec.row in facts.joints
    if joint and owner == "in_world":
        state.add(order, element, "world-body",
                  f"the world body cannot have joints: move the <{tag}> into a <body>")
    elif joint and owner == "in_replicate":
        state.add(order, element, "replicate-joint",
                  f"a <{tag}> cannot be a direct child of <replicate> (frames do not count): "
                  f"wrap it in a <body>")
    elif tag == facts.inertia and owner == "in_world":
        state.add(order, element, "world-body",
                  "the world body cannot have inertia: move the <inertial> into a <body>")
    elif facts.attach is not None and tag == facts.attach.tag:
        attach = facts.attach
        attrs = _tree.values(element)
        if attach.model not in attrs and not any(a in attrs for a in attach.references):
            state.add(order, element, "self-attach",
                      f"an <attach> without {attach.model}= attaches from this model and "
                      f"needs {' or '.join(a + '=' for a in attach.references)}")


def _present(element: Element, attrs: Mapping[str, object],
             off: tuple[AttributeSpec, ...]) -> Mapping[str, object]:
    """``attrs`` without the values marked "off" (schema/facts.toml's ``off``: inheritrange="0"),
    which MuJoCo's presence checks take as not set."""
    unset = {a.name for a in off if a.name in attrs and _keeps(element, a, a.off)}
    return {n: v for n, v in attrs.items() if n not in unset} if unset else attrs


def _keeps(element: Element, attribute: AttributeSpec,
           conditions: tuple[tuple[str, float], ...]) -> bool:
    """Whether every number of the attribute's value keeps all ``conditions``."""
    value = _tree.read_value(element, attribute)
    return keeps(value, conditions)


def keeps(value: object, conditions: tuple[tuple[str, float], ...]) -> bool:
    """Whether every number of ``value`` (a number or an array, as read) keeps all
    ``conditions`` (an attribute's ``bounds`` or ``off``)."""
    numbers = (cast(list[float], value.tolist()) if isinstance(value, np.ndarray)
               else [cast(float, value)])
    return all(_KEEPS[op](float(x), limit) for x in numbers for op, limit in conditions)


def _check_constraint(state: _Pass, order: int, element: Element, attrs: Mapping[str, object],
                      kind: str, bundles: tuple[tuple[str, ...], ...]) -> None:
    tag = element.spec.tag
    names = attrs.keys()
    touched = [b for b in bundles if not names.isdisjoint(b)]  # some name of b is set
    if kind == "exclusive":
        if len(touched) > 1:
            state.add(order, element, "exclusive",
                      f"<{tag}> may set at most one of {_listing(bundles)}; it sets "
                      f"{_set_names(touched, attrs)}")
    elif kind == "together":
        complete = [b for b in bundles if all(name in attrs for name in b)]
        if touched and len(complete) < len(bundles):
            missing = [name for b in bundles for name in b if name not in attrs]
            state.add(order, element, "together",
                      f"<{tag}> sets {_set_names(touched, attrs)} but not "
                      f"{', '.join(missing)}: {_listing(bundles)} go together")
    elif kind == "requires":
        first, *needed = bundles
        if any(name in attrs for name in first):
            missing = [name for b in needed for name in b if name not in attrs]
            if missing:
                state.add(order, element, "requires",
                          f"<{tag}> sets {'+'.join(first)}, which requires "
                          f"{', '.join(missing)}")
    elif kind == "oneof" and not any(all(name in attrs for name in b) for b in bundles):
        state.add(order, element, "oneof",
                  f"<{tag}> must set all of at least one of {_listing(bundles)}")


def _listing(bundles: tuple[tuple[str, ...], ...]) -> str:
    """A constraint's bundles as a finding lists them (``a+b | c``): written only for a
    finding (joining the names of every constraint that holds cost a tenth of the pass)."""
    return " | ".join("+".join(bundle) for bundle in bundles)


_KEEPS: Final[dict[str, Callable[[float, float], bool]]] = {
    ">": operator.gt, ">=": operator.ge, "<": operator.lt, "<=": operator.le}


def _check_child_needs(state: _Pass, order: int, element: Element, attrs: Mapping[str, object],
                       needs: ChildNeeds) -> None:
    """The children of ``element`` that MuJoCo crashes on without attributes they lack."""
    given = [name for name in needs.when if name in attrs]
    if needs.when and not given:
        return
    for child in _tree.children(element):
        if child.spec.tag != needs.child or not _is_written(element, child):
            continue
        if not any(name in _tree.values(child) for name in needs.needs):
            with_given = f" with {', '.join(n + '=' for n in given)}" if given else ""
            state.add(order, child, "child-needs",
                      f"a <{needs.child}> in a <{element.spec.tag}>{with_given} needs "
                      f"{' or '.join(n + '=' for n in needs.needs)}: without, MuJoCo "
                      f"{needs.effect}")


def ensure_no_crash(model: ModelBase) -> None:
    """Raise :class:`ValidationError` for what would crash MuJoCo (``child_needs``), in
    ``model`` and the models attached to it: for the routes that compile a model without
    validating it (a composed model's keyframes)."""
    state = _Pass(model, _namespaces())
    rules = grammar_facts().child_needs
    for order, element in enumerate(_tree.iter_composed(model, True)):
        needs = rules.get(element.spec.row)
        if needs is not None:
            _check_child_needs(state, order, element, _tree.values(element), needs)
    if state.found:
        raise ValidationError(state.findings())


def _check_bounds(state: _Pass, order: int, element: Element,
                  attribute: AttributeSpec) -> None:
    if _keeps(element, attribute, attribute.bounds):
        return
    value = _tree.read_value(element, attribute)
    numbers = (cast(list[float], value.tolist()) if isinstance(value, np.ndarray)
               else [cast(float, value)])
    text = " ".join(f"{float(x):g}" for x in numbers)
    state.add(order, element, "range", f"<{element.spec.tag}> {attribute.name}=\"{text}\": "
                                       f"expected {expected_bounds(attribute)}")


def expected_bounds(attribute: AttributeSpec) -> str:
    """What ``attribute``'s bounds expect, e.g. "each value >= 0 (MuJoCo refuses others)"."""
    each = "each value " if attribute.is_array else ""
    expected = " and ".join(f"{op} {limit:g}" for op, limit in attribute.bounds)
    return f"{each}{expected} (MuJoCo refuses others)"


def _set_names(bundles: Iterable[tuple[str, ...]], attrs: Mapping[str, object]) -> str:
    return ", ".join(name for bundle in bundles for name in bundle if name in attrs)


def _declare_class(state: _Pass, order: int, element: Element, parent: Element | None) -> None:
    """Record a default class, and check its name."""
    facts = grammar_facts()
    name = _tree.element_name(element)
    top_level = parent is None or parent.spec.namespace != grammar_facts().class_namespace
    if top_level:
        if name is not None and name != facts.main_class:
            state.add(order, element, "default-class",
                      f"the top-level <default> is class {facts.main_class!r}; it cannot be "
                      f"renamed {name!r} (nest a <default class={name!r}> in it)")
    elif name is None:
        state.add(order, element, "default-class", "a nested <default> needs a class name")
    else:
        state.classes[name] = (order, element)


def _child_model_references(spec: ElementSpec, attrs: Mapping[str, object]) -> frozenset[str]:
    attach = grammar_facts().attach
    if attach is None or spec.tag != attach.tag or attrs.get(attach.model) is None:
        return frozenset()
    return frozenset(attach.references)


def _check_reference(state: _Pass, order: int, element: Element, attribute: str,
                     namespace: str, value: object) -> None:
    if isinstance(value, Element):
        _check_element_reference(state, order, element, attribute, value)
        name = _tree.element_name(value)
    elif isinstance(value, str):
        name = value
        scope = _tree.scope_of(element)
        if not _builtin(namespace, name) and scope.find(namespace, name) is None:
            in_default = (namespace != grammar_facts().class_namespace and element.parent is not None
                          and element.parent.spec.namespace == grammar_facts().class_namespace)
            state.pending.append(_Pending(order, element, attribute, namespace, name,
                                          in_default))
    else:
        return
    if namespace == grammar_facts().class_namespace and name is not None:
        state.used_classes.add(name)


def _builtin(namespace: str, name: str) -> bool:
    """Names MuJoCo defines itself: the class ``main`` and the world body."""
    facts = grammar_facts()
    return ((namespace == grammar_facts().class_namespace and name == facts.main_class)
            or (namespace == facts.body and name == facts.world_body))


def _check_element_reference(state: _Pass, order: int, element: Element, attribute: str,
                             target: Element) -> None:
    if target.is_removed:
        state.add(order, element, "unresolved-reference",
                  f"{attribute} referred to a <{target.spec.tag}> that was removed from its "
                  f"model (it lost its target)")
    elif not element_in_model(state.model, target):
        state.add(order, element, "unresolved-reference",
                  f"{attribute} refers to {target.path}, of another model")
    # an unnamed target is fine: the export names it (unnamed_<kind>_<n>)


def element_in_model(model: ModelBase, target: Element) -> bool:
    """Whether a reference to ``target`` can be written for ``model``: the target is in
    ``model`` or in a model attached into it."""
    return _tree.scope_of(target).is_within(_tree.scope_of(model))


def _resolve_pending(state: _Pass, compiled: CompiledNames) -> None:
    """Resolve the references the namespaces did not: names of objects MuJoCo's compiler
    makes (replicate copies, flexcomp bodies, meshes named after their files, what an
    <attach prefix> brings), here or in an attached model."""
    if not state.pending:
        return
    hints = _MAX_HINTS
    for ref in state.pending:
        if compiled.origin(_tree.scope_of(ref.element), ref.namespace, ref.name) is not None:
            continue
        # In a default class the reference matters only to elements that use the class, and
        # MuJoCo accepts a class nobody uses it from: a warning there, an error elsewhere.
        severity: Severity = "warning" if ref.in_default else "error"
        state.add(ref.order, ref.element, "unresolved-reference",
                  _unresolved_message(compiled, ref, hint=hints > 0), severity)
        hints -= 1


def _unresolved_message(compiled: CompiledNames, ref: _Pending, *, hint: bool) -> str:
    namespace, name = ref.namespace, ref.name
    suggestion = ""
    if hint:
        scope = _tree.scope_of(ref.element)
        suggestion = did_you_mean(name, [*scope.names(namespace),
                                         *compiled.exact_names(scope, namespace)])
    if namespace == grammar_facts().class_namespace:
        return (f"{ref.attribute}={name!r} names no default class (no <default "
                f"class={name!r}>){suggestion}")
    scoped = " (no attached model provides the scoped name)" if "/" in name else ""
    return f"{ref.attribute}={name!r} names no {namespace} in the model{scoped}{suggestion}"


def _check_repeated_names(state: _Pass, compiled: CompiledNames) -> None:
    """Names the compiler would give twice ("repeated name" in MuJoCo), reported at the
    element making the second."""
    repeated = list({(id(maker), id(other)): (maker, name, other)  # each pair once
                     for maker, name, other in reversed(list(compiled.repeated()))}.values())
    repeated.reverse()
    orders = _document_order(state.model) if repeated else {}
    for maker, name, other in repeated:
        state.add(orders.get(id(maker), 0), maker, "repeated-name",
                  f"MuJoCo's compiler names an object made from this element {name!r}, "
                  + (f"the name of {other.path}" if _tree.element_name(other) == name
                     else f"a name {other.path} makes too")
                  + f" (MuJoCo: repeated name {name!r})")


def _document_order(model: ModelBase) -> dict[int, int]:
    """Each element's place in :func:`validate`'s walk (document order), by id."""
    return {id(element): at for at, element in enumerate(model.iter_elements(), 1)}


def _check_replicated_sensors(state: _Pass) -> None:
    if state.replicates < 2:
        return
    for order, element in state.objectless_sensors:
        state.add(order, element, "replicate-names",
                  f"MuJoCo copies a <{element.tag}> that refers to no object once per "
                  f"<replicate>, with the same name each time: with {state.replicates} "
                  f"replicates in the model, {_tree.element_name(element)!r} would repeat; leave it "
                  f"unnamed")


def _check_unused_classes(state: _Pass) -> None:
    """Warn about default classes that no class= or childclass= uses, directly or through a
    class nested in them."""
    used: set[str] = set()
    for name in state.used_classes:
        entry = state.classes.get(name)
        element: Element | None = None if entry is None else entry[1]
        while element is not None and element.spec.namespace == grammar_facts().class_namespace:
            class_name = _tree.element_name(element)
            if class_name is None or class_name in used:
                break
            used.add(class_name)
            element = element.parent
    for name, (order, element) in state.classes.items():
        if name not in used:
            state.add(order, element, "unused-default",
                      f"default class {name!r} is defined but no element uses it "
                      f"(class= or childclass=)", "warning")
