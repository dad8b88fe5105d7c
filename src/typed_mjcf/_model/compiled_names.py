"""The names MuJoCo's compiler gives to objects the exported model does not name itself.

A reference may name an object that exists only in the compiled model: a copy a
``<replicate>`` makes (``ball0-11``), a body a ``<flexcomp>`` makes (``flag_0``), an unnamed
mesh named after its file, anything a model attached with MJCF's ``<attach prefix>`` brings
from a file typed-mjcf does not read. :class:`CompiledNames` walks a model once (attached
models included) and answers which element a name comes from, so that ``validate()`` does not
report such references and compile errors can point at the element that made the object.

How MuJoCo derives each name is a fact of the language (``schema/facts.toml``, rendered
into :class:`~typed_mjcf._core.language.GrammarFacts`): name templates with placeholders
(``{name}_{vertex}``), which this module turns into patterns. A family of names is the
literal text every name starts with (its *head*) and a pattern for the rest, so a name is
looked up by its prefixes, in time proportional to its length.
"""

from __future__ import annotations

import itertools
import math
import re
import string
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Final, cast

from typed_mjcf._core import tree as _tree
from typed_mjcf._core.language import GrammarFacts
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts
from typed_mjcf._text.files import element_file_stem


@dataclass(frozen=True, slots=True)
class _Number:
    """A placeholder standing for a number: written with ``width`` digits (``None``: as a
    plain decimal, no leading zeros) and less than ``bound`` (``None``: any)."""

    width: int | None
    bound: int | None

    @property
    def regex(self) -> str:
        return r"(0|[1-9][0-9]*)" if self.width is None else rf"([0-9]{{{self.width}}})"


@dataclass(frozen=True, slots=True)
class _Anything:
    """A placeholder standing for any text (the names of a model MuJoCo reads from a file)."""


_ANYTHING: Final = _Anything()
Piece = str | _Number | _Anything
# The <replicate>s enclosing an element, outermost first: (separator, count) of each.
Chain = tuple[tuple[str, int], ...]


class Family:
    """The names one element gives rise to in the compiled model."""

    __slots__ = ("bounds", "claims", "head", "origin", "pattern", "pieces")

    def __init__(self, origin: Element, pieces: Sequence[Piece], claims: bool = False) -> None:
        self.origin = origin  # the element the compiled objects come from
        self.pieces = tuple(pieces)
        # whether MuJoCo refuses another object of the namespace with one of these names
        # ("repeated name"): a replicate's copies and a mesh named after its file do; the
        # bodies a <flexcomp> makes do not (MuJoCo 4.0.0 compiles a body named like one)
        self.claims = claims
        literal = next((i for i, piece in enumerate(pieces) if not isinstance(piece, str)),
                       len(pieces))
        self.head = "".join(str(piece) for piece in pieces[:literal])
        rest = pieces[literal:]
        regex: list[str] = []
        bounds: list[int | None] = []
        for piece in rest:
            if isinstance(piece, str):
                regex.append(re.escape(piece))
            elif isinstance(piece, _Number):
                regex.append(piece.regex)
                bounds.append(piece.bound)
            else:
                regex.append(".*")
        self.pattern = re.compile("".join(regex), re.DOTALL) if regex else None
        self.bounds = tuple(bounds)

    @property
    def exact(self) -> bool:
        """Whether the family is one name (its head)."""
        return self.pattern is None

    def names(self, limit: int) -> list[str] | None:
        """Every name of the family, or ``None`` if it has more than ``limit`` or any text
        may stand in it."""
        ranges: list[range] = []
        for piece in self.pieces:
            if isinstance(piece, _Anything) or (isinstance(piece, _Number)
                                                and piece.bound is None):
                return None
            if isinstance(piece, _Number):
                ranges.append(range(cast(int, piece.bound)))
        if math.prod(len(r) for r in ranges) > limit:
            return None
        out: list[str] = []
        for numbers in itertools.product(*ranges):
            values = iter(numbers)
            out.append("".join(piece if isinstance(piece, str) else
                               str(next(values)).zfill(cast(_Number, piece).width or 0)
                               for piece in self.pieces))
        return out

    def matches_tail(self, tail: str) -> bool:
        """Whether ``head + tail`` is a name of the family."""
        if self.pattern is None:
            return not tail
        match = self.pattern.fullmatch(tail)
        if match is None:
            return False
        return all(bound is None or int(text) < bound
                   for text, bound in zip(match.groups(), self.bounds, strict=True))


def _expand(template: str, values: Mapping[str, Sequence[Piece]]) -> list[Piece]:
    """The pieces of a name template, its placeholders replaced by ``values``."""
    pieces: list[Piece] = []
    for literal, field, _, _ in string.Formatter().parse(template):
        if literal:
            pieces.append(literal)
        if field is not None:
            pieces.extend(values[field])
    return pieces


def _digits(count: int) -> int:
    """How many digits MuJoCo writes a copy's index with: as many as the count has."""
    return len(str(count))


def replicated(pieces: Sequence[Piece], chain: Chain, facts: GrammarFacts) -> list[Piece]:
    """The names of the copies of an element named ``pieces`` inside ``chain``'s replicates:
    each adds its suffix, innermost first."""
    out = list(pieces)
    for sep, count in reversed(chain):
        index = _Number(_digits(count), count)
        out = _expand(facts.replicate_copy, {"name": out, "sep": [sep] if sep else [],
                                             "index": [index]})
    return out


def _flexcomp_bodies(element: Element, name: str, facts: GrammarFacts) -> list[Piece] | None:
    """The names of the bodies a <flexcomp> named ``name`` makes (``None``: it makes none)."""
    flexcomp = facts.flexcomp
    if flexcomp is None or element.spec.tag != flexcomp.tag:
        return None
    rigid = element.spec.by_name.get(flexcomp.rigid)
    if rigid is not None and _tree.read_value(element, rigid) is True:
        return None
    dof_spec = element.spec.by_name.get(flexcomp.dof)
    dof = None if dof_spec is None else _tree.read_value(element, dof_spec)
    nodes = flexcomp.nodes.get(dof) if isinstance(dof, str) else None
    if nodes is None:
        return _expand(flexcomp.vertex_body, {"name": [name], "vertex": [_Number(None, None)]})
    node = [_Number(None, nodes)]
    return _expand(flexcomp.node_body, {"name": [name], "i": node, "j": node, "k": node})


def _walk(model: ModelBase) -> Iterator[tuple[Element, Chain]]:
    """Every element of the composed model (attached models inside their frames), with the
    replicates enclosing it."""
    facts = grammar_facts()
    stack: list[tuple[Element, Chain]] = [(model, ())]
    while stack:
        element, chain = stack.pop()
        yield element, chain
        if element.spec.tag == facts.replicate:
            chain = (*chain, _copies(element, facts))
        inside = [(child, chain) for child in _tree.children(element)]
        attached = _tree.attached_at(element)
        if attached is not None:
            for section in _tree.children(attached):
                if section.spec.holds_bodies:  # its bodies go in the frame, copied with it
                    inside += [(child, chain) for child in _tree.children(section)]
                else:
                    inside.append((section, ()))
        stack.extend(reversed(inside))


def _copies(replicate: Element, facts: GrammarFacts) -> tuple[str, int]:
    attrs = replicate.spec.by_name
    sep = attrs.get(facts.replicate_separator)
    count = attrs.get(facts.replicate_count)
    sep_value = None if sep is None else _tree.read_value(replicate, sep)
    count_value = None if count is None else _tree.read_value(replicate, count)
    return (sep_value if isinstance(sep_value, str) else "",
            count_value if isinstance(count_value, int) and count_value > 0 else 1)


_Key = tuple[int, str | None]  # (id of a scope, namespace; None: every namespace)


class CompiledNames:
    """The names a model's compiled objects take beyond those the model writes, by scope
    and namespace, each with the element it comes from."""

    def __init__(self, model: ModelBase) -> None:
        self.facts = grammar_facts()
        self.families: dict[_Key, dict[str, list[Family]]] = {}
        self.chains: dict[int, Chain] = {}  # elements copied by replicates, by id
        self.scopes: dict[int, NameScope] = {}  # the scopes of ``families``' keys
        for element, chain in _walk(model):
            self._collect(element, chain)

    # ---------------------------------------------------------------- collecting

    def _add(self, scope: NameScope, namespace: str | None, family: Family) -> None:
        self.scopes[id(scope)] = scope
        by_head = self.families.setdefault((id(scope), namespace), {})
        by_head.setdefault(family.head, []).append(family)

    def _collect(self, element: Element, chain: Chain) -> None:
        facts = self.facts
        spec = element.spec
        scope = _tree.scope_of(element)
        if not chain and self._copied(element):
            chain = self._target_chain(element)
        if chain:
            self.chains[id(element)] = chain
        attach = facts.attach
        if attach is not None and spec.tag == attach.tag:
            prefix = _tree.values(element).get(attach.prefix)
            if isinstance(prefix, str):
                # what it attaches (from a model typed-mjcf does not read, or a subtree of
                # this one) is named with the prefix: any such name may be one of its
                self._add(scope, None, Family(element, [prefix, _ANYTHING]))
            return
        namespace = spec.namespace
        if namespace is None:
            return
        name = _tree.element_name(element)
        if name is None:
            self._collect_unnamed(element, scope, namespace)
            return
        if chain:
            self._add(scope, namespace,
                      Family(element, replicated([name], chain, facts), claims=True))
        bodies = _flexcomp_bodies(element, name, facts)
        if bodies is not None and facts.flexcomp is not None:
            self._add(scope, facts.flexcomp.namespace,
                      Family(element, replicated(bodies, chain, facts)))

    def _collect_unnamed(self, element: Element, scope: NameScope, namespace: str) -> None:
        facts = self.facts
        file_attribute = facts.named_after_file.get(namespace)
        if file_attribute is not None:
            stem = element_file_stem(element, file_attribute)
            if stem:
                self._add(scope, namespace, Family(element, [stem], claims=True))
        elif namespace in facts.named_from_contents:
            # named by the file it reads, which typed-mjcf does not open: any name may be it
            self._add(scope, namespace, Family(element, [_ANYTHING]))

    def _copied(self, element: Element) -> bool:
        """Whether ``element`` is in a root section copied with what it refers to."""
        parent = element.parent
        return (parent is not None and isinstance(parent.parent, ModelBase)
                and parent.spec.tag in self.facts.copied_with_replicate)

    def _target_chain(self, element: Element) -> Chain:
        """The replicates copying what ``element`` or its children refer to (a tendon's
        sites, a tuple's objects): it is copied with them."""
        stack = [element]
        while stack:
            current = stack.pop()
            for target in self._targets(current):
                chain = self.chains.get(id(target))
                if chain:
                    return chain
            stack.extend(_tree.children(current))
        return ()

    def _targets(self, element: Element) -> Iterator[Element]:
        """What ``element`` refers to: its references' targets, and the elements named by
        its attributes that list names (a <flex>'s bodies)."""
        stored = _tree.values(element)
        for attribute in element.spec.references:
            target = stored.get(attribute.name)
            if isinstance(target, Element):
                yield target
        lists = self.facts.name_lists
        if not lists:
            return
        scope = _tree.scope_of(element)
        for name, value in stored.items():
            namespace = lists.get(f"{element.spec.tag}@{name}")
            if namespace is not None and isinstance(value, str):
                for part in value.split():
                    found = scope.find(namespace, part)
                    if isinstance(found, Element):
                        yield found

    # ---------------------------------------------------------------- looking up

    def origin(self, scope: NameScope, namespace: str, name: str) -> Element | None:
        """The element a compiled object named ``name`` comes from, as seen from ``scope``
        (``arm/flag_0`` looks ``flag_0`` up in the scope attached as ``arm``)."""
        for key in ((id(scope), namespace), (id(scope), None)):
            by_head = self.families.get(key)
            if by_head is None:
                continue
            for end in range(len(name), -1, -1):
                for family in by_head.get(name[:end], ()):
                    if family.matches_tail(name[end:]):
                        return family.origin
        if SEPARATOR in name:
            attached, rest = scope.enter(name)
            if attached is not None and attached is not scope:
                return self.origin(attached, namespace, rest)
        return None

    def repeated(self, limit: int = 10_000) -> Iterator[tuple[Element, str, Element]]:
        """Names MuJoCo's compiler would give twice in one namespace: (the element making
        the name, the name, the element that has it already: named so, or making it too).
        A family with more than ``limit`` names is not enumerated."""
        for (scope_id, namespace), by_head in self.families.items():
            if namespace is None:
                continue
            scope = self.scopes[scope_id]
            seen: dict[str, Element] = {}
            for families in by_head.values():
                for family in families:
                    names = family.names(limit) if family.claims else None
                    for name in names or ():
                        other = seen.setdefault(name, family.origin)
                        if other is not family.origin:
                            yield family.origin, name, other
                            continue
                        named = scope.lookup(namespace, name)
                        if (isinstance(named, Element) and named is not family.origin
                                and id(named) not in self.chains):
                            yield family.origin, name, named

    def exact_names(self, scope: NameScope, namespace: str) -> Iterable[str]:
        """The single names given in ``scope`` (files' stems), for suggestions."""
        by_head = self.families.get((id(scope), namespace), {})
        return [head for head, families in by_head.items()
                if any(family.exact for family in families)]
