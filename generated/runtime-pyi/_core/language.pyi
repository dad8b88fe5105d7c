# Generated from src/typed_mjcf/_core/language.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
"""The language facts: the one declaration of ``[language]`` in ``schema/facts.toml``.

Each field of :class:`GrammarFacts` is one key of that table, with its type: the generator
reads this declaration to parse the table strictly, store it in ``schema/mjcf.json`` and write
the ``GrammarFacts(...)`` call of the generated tables (``codegen/language.py``), so a new fact
is a field here, its entry in facts.toml and its use in a feature. This module imports nothing
from the package: the generator loads it by path, so a stale generated package cannot stop
the render that fixes it.
"""
from __future__ import annotations
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Final, Literal
FROM_GRAMMAR: Final = {"source": "grammar"}
MergeRule = Literal["min", "max", "max-bytes"]

@dataclass(frozen=True, kw_only=True)
class KeyframeFacts:
    """How a keyframe's vectors map onto the compiled model (for combining keyframes)."""
    qpos: str
    qvel: str
    act: str
    ctrl: str
    mpos: str
    mquat: str
    time: str

@dataclass(frozen=True, kw_only=True)
class AttachFacts:
    """``<attach>``: the attribute naming the child model (a model asset), the prefix it
    scopes the child's names with, and the attributes naming a body or frame of the child
    (or, without a model, of this model: self-attachment needs one of them)."""
    tag: str
    model: str
    prefix: str
    references: tuple[str, ...]

@dataclass(frozen=True, kw_only=True)
class FlexcompFacts:
    """``<flexcomp>``: the bodies MuJoCo's compiler makes for it, named after it by a
    template: ``{name}`` the flexcomp's name, ``{vertex}`` a vertex's index, ``{i}``,
    ``{j}``, ``{k}`` a grid node's indices along each axis."""
    tag: str
    namespace: str
    dof: str
    rigid: str
    vertex_body: str
    node_body: str
    nodes: Mapping[str, int]

@dataclass(frozen=True, kw_only=True)
class ChildNeeds:
    """A child MuJoCo cannot compile without some attributes when its parent sets others: it
    crashes (no error to catch), so ``validate()`` refuses the model first."""
    child: str
    when: tuple[str, ...]
    needs: tuple[str, ...]
    effect: str

@dataclass(frozen=True, kw_only=True)
class GeneratedShape:
    """A shape MuJoCo's compiler generates from a list of numbers: it allocates ``factor`` x
    the product of the numbers at the places ``counts`` names (``params`` names each place,
    as MuJoCo's reference does)."""
    params: tuple[str, ...]
    counts: tuple[str, ...]
    factor: int

@dataclass(frozen=True, kw_only=True)
class Allocation:
    """Memory MuJoCo's compiler allocates for an element, sized by its attributes or by the
    header of an image it decodes rather than by the model's bytes: ``compile()`` counts it
    against a field of ``CompileLimits`` before MuJoCo allocates."""
    limit: str
    sizes: tuple[str, ...]
    generator: str
    shape: str
    cubes: frozenset[str]
    images: tuple[str, ...]
    values: str | None = None
    builtins: Mapping[str, GeneratedShape] | None = None
    copies: str | None = None

@dataclass(frozen=True, kw_only=True)
class GrammarFacts:
    """Facts about the language as a whole, from ``schema/facts.toml``'s ``[language]``
    (one key per field; a field typed ``X | None`` may be left out)."""
    root: str = field(default="", metadata=FROM_GRAMMAR)
    main_class: str
    world_body: str
    body: str
    frame: str
    replicate: str
    joints: frozenset[str]
    freejoint: str
    free_type: str
    joint_type: str
    shared_defaults: frozenset[str]
    ordered_children: frozenset[str]
    class_for_children: frozenset[str]
    inertia: str
    sensor_section: str
    mocap: str
    childclass: str
    dclass: str
    class_namespace: str
    actuator_namespace: str
    model_name: str
    named_after_file: Mapping[str, str]
    named_from_contents: frozenset[str]
    attach: AttachFacts | None = None
    replicate_separator: str
    merge_rules: Mapping[str, MergeRule]
    skin_file: str
    replicate_count: str
    replicate_copy: str
    copied_with_replicate: frozenset[str]
    name_lists: Mapping[str, str]
    typed_references: Mapping[str, str]
    type_namespaces: Mapping[str, str]
    flexcomp: FlexcompFacts | None = None
    keyframe: KeyframeFacts
    child_needs: Mapping[str, ChildNeeds]
    allocations: Mapping[str, Allocation]
