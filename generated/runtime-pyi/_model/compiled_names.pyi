# Generated from src/typed_mjcf/_model/compiled_names.py by codegen/runtime_stubs.py (python -m codegen render); do not edit.
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
import re
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typed_mjcf._core.language import GrammarFacts
from typed_mjcf._core.names import SEPARATOR, NameScope
from typed_mjcf._core.tree import Element, ModelBase, grammar_facts

@dataclass(frozen=True, slots=True)
class _Number:
    """A placeholder standing for a number: written with ``width`` digits (``None``: as a
    plain decimal, no leading zeros) and less than ``bound`` (``None``: any)."""
    width: int | None
    bound: int | None
    @property
    def regex(self) -> str: ...

@dataclass(frozen=True, slots=True)
class _Anything:
    """A placeholder standing for any text (the names of a model MuJoCo reads from a file)."""
Piece = str | _Number | _Anything
Chain = tuple[tuple[str, int], ...]

class Family:
    """The names one element gives rise to in the compiled model."""
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
        ...
    def names(self, limit: int) -> list[str] | None:
        """Every name of the family, or ``None`` if it has more than ``limit`` or any text
        may stand in it."""
        ...
    def matches_tail(self, tail: str) -> bool:
        """Whether ``head + tail`` is a name of the family."""
        ...

def replicated(pieces: Sequence[Piece], chain: Chain, facts: GrammarFacts) -> list[Piece]:
    """The names of the copies of an element named ``pieces`` inside ``chain``'s replicates:
    each adds its suffix, innermost first."""
    ...

def _walk(model: ModelBase) -> Iterator[tuple[Element, Chain]]:
    """Every element of the composed model (attached models inside their frames), with the
    replicates enclosing it."""
    ...
_Key = tuple[int, str | None]

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
    def _collect(self, element: Element, chain: Chain) -> None: ...
    def origin(self, scope: NameScope, namespace: str, name: str) -> Element | None:
        """The element a compiled object named ``name`` comes from, as seen from ``scope``
        (``arm/flag_0`` looks ``flag_0`` up in the scope attached as ``arm``)."""
        ...
    def repeated(self, limit: int = 10_000) -> Iterator[tuple[Element, str, Element]]:
        """Names MuJoCo's compiler would give twice in one namespace: (the element making
        the name, the name, the element that has it already: named so, or making it too).
        A family with more than ``limit`` names is not enumerated."""
        ...
    def exact_names(self, scope: NameScope, namespace: str) -> Iterable[str]:
        """The single names given in ``scope`` (files' stems), for suggestions."""
        ...
