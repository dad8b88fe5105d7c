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

# A field with this metadata is not read from facts.toml: the generator sets it.
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
    namespace: str  # of the bodies it makes
    dof: str  # the attribute choosing vertex bodies or grid-node bodies
    rigid: str  # the attribute that, true, makes no bodies
    vertex_body: str
    node_body: str
    nodes: Mapping[str, int]  # dof keyword -> grid nodes per axis (the dofs with node bodies)


@dataclass(frozen=True, kw_only=True)
class ChildNeeds:
    """A child MuJoCo cannot compile without some attributes when its parent sets others: it
    crashes (no error to catch), so ``validate()`` refuses the model first."""

    child: str  # the child's tag
    # the parent's attributes: the need holds when any of them is set (always, if none)
    when: tuple[str, ...]
    needs: tuple[str, ...]  # the child's attributes: at least one must be set
    effect: str  # what MuJoCo does otherwise, for the message


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

    limit: str  # the CompileLimits field bounding the count
    sizes: tuple[str, ...]  # attributes whose product is the count allocated
    generator: str  # the attribute that, at its default, allocates nothing from sizes ("": always)
    shape: str  # the attribute whose keywords in ``cubes`` allocate a cube ("": none)
    cubes: frozenset[str]  # six square faces, ``sizes[0]`` on a side (the others unused)
    images: tuple[str, ...]  # file attributes: a PNG's declared pixels are decoded
    # the attribute holding the numbers a generated shape is made from, and the shapes (by
    # the generator's keyword) whose count they give; a shape not listed is not counted
    values: str | None = None
    builtins: Mapping[str, GeneratedShape] | None = None
    # the attribute counting the copies MuJoCo makes of what the element holds: each element
    # inside counts once per copy beyond the first (nested copies multiply)
    copies: str | None = None


@dataclass(frozen=True, kw_only=True)
class GrammarFacts:
    """Facts about the language as a whole, from ``schema/facts.toml``'s ``[language]``
    (one key per field; a field typed ``X | None`` may be left out)."""

    root: str = field(default="", metadata=FROM_GRAMMAR)  # the declaration name of the root row
    main_class: str  # the name of the top-level default class
    world_body: str  # the name MuJoCo gives the world body
    body: str  # the tag of bodies (attachment frames are bodies)
    frame: str  # the tag of <frame>, transparent in the kinematic tree
    replicate: str  # the tag of <replicate>
    joints: frozenset[str]  # rows (declaration names) of joints: what adds to qpos
    freejoint: str  # the tag of a free joint (so is a joint whose type is free_type)
    free_type: str
    joint_type: str  # the joint attribute naming its kind
    shared_defaults: frozenset[str]  # namespaces whose kinds share one default per class
    ordered_children: frozenset[str]  # tags whose children's order matters across tags
    class_for_children: frozenset[str]  # tags whose class= applies to their children too
    inertia: str  # the tag of a body's <inertial>
    sensor_section: str  # the tag of the root's <sensor> section
    mocap: str  # the body attribute that makes a body a mocap body
    childclass: str  # the attribute naming the default class of a subtree
    dclass: str  # the attribute naming an element's default class
    class_namespace: str  # the namespace of default classes
    actuator_namespace: str  # its elements are the model's controls
    model_name: str  # the root attribute naming the model (its scope when attached)
    named_after_file: Mapping[str, str]  # namespace -> attribute
    named_from_contents: frozenset[str]  # namespaces named by the file they read
    attach: AttachFacts | None = None
    replicate_separator: str  # <replicate>'s attribute suffixing copies' names
    # global settings combined on attach rather than refused: "tag@attribute" -> rule
    merge_rules: Mapping[str, MergeRule]
    skin_file: str  # "row@attribute" of binary skin files (bone names to scope)
    replicate_count: str  # <replicate>'s attribute counting its copies
    # a copy's name: {name} the original's, {sep} the separator, {index} the copy's index
    replicate_copy: str
    copied_with_replicate: frozenset[str]  # root sections copied with targets
    # string attributes listing names: "tag@attribute" -> the namespace of the names
    name_lists: Mapping[str, str]
    # references whose namespace another attribute's keyword names: reference -> that
    # attribute (the generator types them; a type keyword names its namespace, except
    # those type_namespaces renames)
    typed_references: Mapping[str, str]
    type_namespaces: Mapping[str, str]
    flexcomp: FlexcompFacts | None = None
    keyframe: KeyframeFacts
    # rows (declaration names) whose child needs attributes when the row sets others
    child_needs: Mapping[str, ChildNeeds]
    # rows (declaration names) whose compile allocates what their attributes or images declare
    allocations: Mapping[str, Allocation]
