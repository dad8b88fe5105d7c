"""Ask the installed MuJoCo parser which attribute names it reads on rows printSchema omits.

``mj_printSchema`` has no row for ``<worldbody>``, ``<frame>`` or ``<replicate>``: MuJoCo's
reader handles them by hand. ``<worldbody>`` is checked against the body row and then refuses
every attribute; ``<frame>`` and ``<replicate>`` are not checked at all, so the parser ignores
an attribute it does not know instead of reporting it. The probe therefore asks whether the
parser *reads* a name: it loads a tiny model with the name set to :data:`PROBE_VALUE` (no
number, keyword or default class), and the name is read when

* loading fails with a message naming the attribute or quoting the value (``bad format in
  attribute 'pos'``, ``invalid keyword: '...'``, ``unknown default childclass``), other than
  the schema's ``unrecognized attribute``; or
* loading succeeds and the model saved back differs from the one without the name (a string
  the reader keeps: a frame's name, replicate's separator).

A message naming neither (``World body cannot have attributes``) refuses the element, not the
name: the name is not read. Probing is deterministic; nothing is cached beyond one parser.
"""

from __future__ import annotations

import importlib
import re
import warnings
from collections import deque
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Literal, cast

from codegen import ir

PROBE_VALUE = "typedmjcf_probe"
UNKNOWN_NAME = "typedmjcf_no_such_attribute"  # tells whether the row's reader checks names
# What the probed row holds, when it holds bodies: named, so that names the row changes
# (replicate's suffixes) show in the saved model.
_CONTENT = '<body name="b"><geom size="0.1"/></body>'
_MASS = '<geom size="0.1"/>'
_NAME_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_UNKNOWN = "unrecognized attribute"  # the schema check's message for a name it lacks

Verdict = Literal["read", "unknown", "refused"]
# In a Site's ``required``: not an attribute but MJCF the element holds first (a tendon's path)
CONTENT = "_content"


@dataclass(frozen=True)
class Outcome:
    """One load: the parser's message when it failed, else the model saved back as MJCF."""

    error: str | None = None
    saved: str = ""


Parser = Callable[[str], Outcome]


@dataclass(frozen=True)
class Site:
    """Where a row is probed: the tags from the root down to it, the attributes the path
    needs to load (tag -> name -> text), and whether the row holds bodies."""

    path: tuple[str, ...]
    required: Mapping[str, Mapping[str, str]] = field(
        default_factory=dict[str, Mapping[str, str]])
    holds_bodies: bool = False
    # a body on the path holds a geom: a moving body needs mass for MuJoCo to compile (and
    # save) the model, which the default probe compares
    weighted: bool = False
    world: str = ""  # what the root holds first (objects the row's references name)

    def model(self, attribute: str | None = None) -> str:
        """The probe model, with ``attribute`` set to :data:`PROBE_VALUE` on the row."""
        inner = _CONTENT if self.holds_bodies else ""
        for depth, tag in reversed(list(enumerate(self.path))):
            attrs = dict(self.required.get(tag, {}))
            inner = attrs.pop(CONTENT, "") + inner
            if attribute is not None and depth == len(self.path) - 1:
                attrs[attribute] = PROBE_VALUE
            if self.weighted and tag == "body":
                inner = _MASS + inner
            if depth == 0:
                inner = self.world + inner
            text = "".join(f' {k}="{v}"' for k, v in attrs.items())
            inner = f"<{tag}{text}>{inner}</{tag}>"
        return inner


@dataclass(frozen=True)
class Discovery:
    """The names the parser reads on one row (in candidate order) and, by message, the names
    it refused with a message that names neither them nor the value."""

    read: tuple[str, ...]
    refused: Mapping[str, tuple[str, ...]] = field(
        default_factory=dict[str, tuple[str, ...]])
    ignores_unknown: bool = False  # a name no MJCF has loads without a word: it is ignored


class ProbeError(ValueError):
    """The probe model does not load without a candidate: it cannot tell anything."""


def classify(name: str, outcome: Outcome, baseline: Outcome) -> Verdict:
    """Whether loading ``outcome`` shows that the parser reads ``name`` (see the module)."""
    if outcome.error is None:
        return "read" if outcome.saved != baseline.saved else "unknown"
    message = _first_line(outcome.error)
    if _UNKNOWN in message:
        return "unknown"
    named = re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", message)
    quoted = f"'{PROBE_VALUE}'" in message
    return "read" if named or quoted else "refused"


def _first_line(error: str | None) -> str:
    """The message proper: MuJoCo's next line names the element and line, not the cause."""
    lines = (error or "").strip().splitlines()
    return lines[0] if lines else ""


def discover(site: Site, candidates: Iterable[str], parser: Parser) -> Discovery:
    """The candidate names the parser reads on the row at ``site``."""
    baseline = parser(site.model())
    if baseline.error is not None:
        raise ProbeError(f"probe of <{site.path[-1]}>: the model without a candidate does "
                         f"not load: {baseline.error.strip()}")
    read: list[str] = []
    refused: dict[str, list[str]] = {}
    for name in dict.fromkeys(candidates):
        if not _NAME_RE.fullmatch(name):
            continue  # not an XML attribute name (reference prose: "dim=1", "data =")
        outcome = parser(site.model(name))
        verdict = classify(name, outcome, baseline)
        if verdict == "read":
            read.append(name)
        elif verdict == "refused":
            refused.setdefault(_first_line(outcome.error), []).append(name)
    nonsense = parser(site.model(UNKNOWN_NAME))
    ignores_unknown = nonsense.error is None and nonsense.saved == baseline.saved
    return Discovery(tuple(read), {k: tuple(v) for k, v in refused.items()}, ignores_unknown)


# ------------------------------------------------------------------------ probe sites


def site_for(schema: ir.Schema, row_name: str) -> Site | None:
    """The shortest path of child edges from the root to ``row_name`` (outside <default>),
    with the required attributes along it; None when none leads there or a required
    attribute has no value the probe can make up (a reference, a file)."""
    path = path_to(schema, row_name)
    if path is None:
        return None
    required: dict[str, dict[str, str]] = {}
    for name in path:
        row = schema.elements[name]
        for attr in row.attributes:
            if attr.required:
                text = _valid_text(attr, schema)
                if text is None:
                    return None
                required.setdefault(row.tag, {})[attr.name] = text
    row = schema.elements[row_name]
    holds_bodies = any(schema.elements[c.element].tag == "body" for c in row.children)
    return Site(tuple(schema.elements[n].tag for n in path), required, holds_bodies)


def path_to(schema: ir.Schema, target: str) -> list[str] | None:
    """The rows from the root down to ``target`` by child edges, outside <default>."""
    parents: dict[str, str | None] = {schema.root: None}
    queue = deque([schema.root])
    while queue:
        name = queue.popleft()
        if name == target:
            path = [name]
            while (parent := parents[path[-1]]) is not None:
                path.append(parent)
            return path[::-1]
        for edge in schema.elements[name].children:
            child = schema.elements[edge.element]
            if edge.element not in parents and child.projection_of is None \
                    and child.tag != "default":
                parents[edge.element] = name
                queue.append(edge.element)
    return None


def _valid_text(attr: ir.AttributeDef, schema: ir.Schema) -> str | None:
    """A value the parser accepts for ``attr``: its default, else a plain one of its kind."""
    if attr.default is not None:
        return attr.default
    count = attr.arity[0] if attr.arity is not None and attr.arity[0] > 0 else 1
    if attr.kind in ("int", "real"):
        return " ".join(["1"] * count)  # 1: a count must be positive
    if attr.kind == "bool":
        return "false"
    if attr.kind in ("keyword", "flags") and attr.enum in schema.enums:
        return schema.enums[attr.enum].keywords[0]
    if attr.kind in ("string", "id"):
        return "p"
    return None


# ----------------------------------------------------------------------- mujoco parser


class MujocoParser:
    """The installed parser: ``MjSpec.from_string``, then ``to_xml`` of the spec. Outcomes
    are kept per model text, as sync may probe the same models more than once."""

    def __init__(self) -> None:
        spec_type = _get(importlib.import_module("mujoco"), "MjSpec")
        self._from_string = cast(Callable[[str], object], _get(spec_type, "from_string"))
        self._outcomes: dict[str, Outcome] = {}

    def __call__(self, xml: str) -> Outcome:
        outcome = self._outcomes.get(xml)
        if outcome is None:
            outcome = self._outcomes[xml] = self._load(xml)
        return outcome

    def _load(self, xml: str) -> Outcome:
        try:
            spec = self._from_string(xml)
            saved = cast(Callable[[], object], _get(spec, "to_xml"))()
        except (ValueError, RuntimeError) as exc:  # what mujoco raises for a model it refuses
            return Outcome(error=str(exc))
        if not isinstance(saved, str):
            raise TypeError("MjSpec.to_xml did not return text")
        return Outcome(saved=saved)


UNSAVED = "\0unsaved: "  # ``saved`` of a model the parser read but MuJoCo could not save


class SpecParser(MujocoParser):
    """The installed parser, telling apart what it refuses (``error``) from a model it read
    but cannot compile (``saved`` starts with :data:`UNSAVED`): the reader's verdicts do not
    need a model that compiles, only the default probe does."""

    def _load(self, xml: str) -> Outcome:
        try:
            spec = self._from_string(xml)
        except (ValueError, RuntimeError) as exc:
            return Outcome(error=str(exc))
        try:
            with warnings.catch_warnings():  # deprecated attributes warn when saved
                warnings.simplefilter("ignore")
                saved: object = cast(Callable[[], object], _get(spec, "to_xml"))()
        except (ValueError, RuntimeError) as exc:  # to_xml compiles first
            return Outcome(saved=UNSAVED + str(exc))
        return Outcome(saved=str(saved))


def _get(obj: object, name: str) -> object:
    """An attribute of an untyped mujoco object, as ``object`` for the caller to check."""
    value: object = getattr(obj, name)
    return value
