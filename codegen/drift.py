"""Ask the installed MuJoCo parser whether each attribute still has the type schema/ gives it.

Sync adds and removes attribute *names*; this module checks what the bindings encode about
an attribute the schema already has, by loading tiny models through the installed parser
(``MjSpec.from_string``, as :mod:`codegen.probe` does for names) and reading its messages:

* **count**: n values of ``1`` for n around the schema's bounds; the reader says ``attribute
  'x' does not have enough data`` or ``has too much data`` when n is outside its own;
* **kind**: an int that takes ``1.5``, a number that is refused (``invalid keyword: '1'``) or a
  keyword or bool attribute that takes any word is no longer what the schema says;
* **keywords**: each keyword of the schema's enum, of XMLreference.rst's ``:at-val:`` list and
  of the bound C enum, one at a time: ``invalid keyword: 'w'`` refuses it;
* **default**: the model with the attribute set to the schema's default is saved back by
  ``MjSpec.to_xml`` (which writes values that differ from MuJoCo's defaults) exactly as the
  model without it; the new default is the documented one when that saves back unchanged;
* **spellings**: each keyword's integer value (the enum's value column, else its C constant),
  on every keyword attribute, hand-typed ones too: a reader that also takes the number
  (``<headlight active="1">`` in 4.0.0) is recorded in the attribute's ``numbers``;
* **string lists**: an id, reference or string stored in an ``mj*Vec`` field of its ``mjs``
  struct (what MjSpec reports) takes several values.

A change that can be typed from what the probe saw (a count, a keyword set, a default) is
applied; one that cannot (a kind, a keyword set shared by attributes that now differ) is
listed in :attr:`Drift.untypable` with the ``schema/facts.toml`` entry that types it, and
``python -m codegen generate`` stops. Attributes and enums that facts.toml sets by hand are
left to it: the facts record what the parser alone does not say.
"""

from __future__ import annotations

import copy
import dataclasses
import re
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal, cast

from codegen import ir, probe, unset
from codegen.wheel import AtVal, Reference, parse_at_val

PROBE_SITES = Path(__file__).resolve().parents[1] / "schema" / "probe.toml"
Verdict = Literal["ok", "short", "long", "bad", "keyword", "unknown"]
# How far past the schema's bounds counts are tried, and the most values ever tried.
_COUNT_MARGIN = 2
_COUNT_CAP = 24
_VECTOR_TYPES = frozenset({"mjStringVec", "mjIntVec", "mjFloatVec", "mjDoubleVec"})
# Names: one name, or a list of them when the mjs field is a vector (free text holds either).
_STRING_KINDS = frozenset({"id", "ref"})


def verdict(name: str, value: str, outcome: probe.Outcome) -> Verdict:
    """What loading ``name="value"`` says about the value (``ok``: the attribute's reader
    took it, whatever failed later)."""
    if outcome.error is None:
        return "ok"
    message = (outcome.error.strip().splitlines() or [""])[0]
    quoted = f"'{name}'"
    if "unrecognized attribute" in message:
        return "unknown"
    if "does not have enough data" in message and quoted in message:
        return "short"
    if "has too much data" in message and quoted in message:
        return "long"
    if "invalid keyword:" in message:  # quotes the value, or "(null)" for flags
        return "keyword"
    if quoted in message and ("bad format" in message or "problem reading" in message):
        return "bad"
    return "ok"


@dataclass(frozen=True)
class Change:
    """One attribute whose type the installed MuJoCo no longer agrees with."""

    row: str
    name: str
    what: Literal["kind", "keywords", "count", "default", "spellings", "defaults"]
    before: str
    after: str

    def line(self) -> str:
        return f"{self.row}@{self.name} {self.what}: {self.before} -> {self.after}"


@dataclass
class Drift:
    """What the probe found: changes applied, changes to type by hand, and coverage."""

    applied: list[Change] = field(default_factory=list[Change])
    untypable: list[tuple[Change, str]] = field(default_factory=list[tuple[Change, str]])
    probed: int = 0  # attributes checked
    defaults: int = 0  # of them, defaults compared in a model MuJoCo saves
    rows_skipped: list[str] = field(default_factory=list[str])  # no probe model loads


@dataclass
class _Probe:
    """One row's probe model and the parser; ``value`` loads the row with one attribute."""

    site: probe.Site
    parser: probe.Parser
    baseline: probe.Outcome

    def load(self, name: str, text: str) -> probe.Outcome:
        xml = self.site.model(name).replace(f'{name}="{probe.PROBE_VALUE}"',
                                            f'{name}="{_escape(text)}"', 1)
        return self.parser(xml)

    def verdict(self, name: str, text: str) -> Verdict:
        return verdict(name, text, self.load(name, text))


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")


def site(schema: ir.Schema, row: str, parser: probe.Parser,
         extra: Mapping[str, Mapping[str, str]] | None = None) -> _Probe | None:
    """A probe model for ``row`` that the parser reads: the shortest path to it, each
    required attribute given a plain value of its kind (a name for references: the reader
    does not resolve them), bodies on the path named (flexcomp needs it), and ``extra``
    (tag -> attributes, schema/probe.toml) where a row needs more to be read at all."""
    path = probe.path_to(schema, row)
    if path is None:
        return None
    required: dict[str, dict[str, str]] = {}
    for name in path:
        element = schema.elements[name]
        attrs = required.setdefault(element.tag, {})
        for attr in element.attributes:
            if attr.required:
                attrs[attr.name] = _plain(attr, schema)
        attrs.update((k, v) for k, v in (extra or {}).get(name, {}).items()
                     if k != WORLD and not k.startswith(COMPILE)
                     and (k != probe.CONTENT or name == row))
    tags = tuple(schema.elements[n].tag for n in path)
    if "body" in tags[:-1]:
        required.setdefault("body", {}).setdefault("name", "typedmjcf_body")
    holds = any(schema.elements[c.element].tag == "body"
                for c in schema.elements[row].children)
    found = probe.Site(tags, required, holds, weighted=True,
                       world=(extra or {}).get(row, {}).get(WORLD, ""))
    baseline = parser(found.model())
    return None if baseline.error is not None else _Probe(found, parser, baseline)


# Objects a probe model's references can name (the default probe needs a model MuJoCo
# compiles, so an actuator or a sensor needs its target), all named TARGET; a second body
# holds what some rows need besides (a ball joint, a second geom and site: OTHER), which
# schema/probe.toml names.
TARGET = "typedmjcf_target"
OTHER = "typedmjcf_other"
WORLD = "_world"  # schema/probe.toml: what the root holds for the row (a plugin), as MJCF
# schema/probe.toml's [ROW.compile]: attributes only the default probe's model has (a mesh's
# vertices: beside them the reader refuses every builtin, which the keyword probe reads)
COMPILE = "compile."
_WORLD = (f'<worldbody><body name="{TARGET}"><joint name="{TARGET}" range="-1 1"/>'
          f'<geom name="{TARGET}" size="0.1"/><site name="{TARGET}"/>'
          f'<camera name="{TARGET}"/></body>'
          f'<body name="{OTHER}" pos="0 0 1"><joint name="{OTHER}" type="ball"/>'
          f'<geom name="{OTHER}" size="0.1"/><site name="{OTHER}"/></body></worldbody>'
          f'<tendon><fixed name="{TARGET}" range="-1 1"><joint joint="{TARGET}" coef="1"/>'
          f'</fixed></tendon>'  # limited: the limit sensors need it
          f'<actuator><motor name="{TARGET}" joint="{TARGET}"/></actuator>')
_TARGETS = frozenset({"body", "joint", "geom", "site", "camera", "tendon", "actuator"})


def targeted(schema: ir.Schema, row: ir.ElementDef, p: _Probe,
             fixed: Mapping[str, str] | None = None) -> _Probe:
    """``p``, or where MuJoCo cannot save its model, the same row with a world of targets
    and one reference of the row naming its target (the first that makes it save);
    ``fixed`` (the row's schema/probe.toml entry) keeps its values."""
    if not p.baseline.saved.startswith(probe.UNSAVED):
        return p
    every: list[dict[str, str]] = []  # the row's references, each naming its target
    compile_only = {k.removeprefix(COMPILE): v for k, v in (fixed or {}).items()
                    if k.startswith(COMPILE)}
    for attr in row.attributes:
        if fixed is not None and attr.name in fixed:
            continue
        if attr.kind == "ref" and attr.namespace in _TARGETS:
            every.append({attr.name: TARGET})
        elif attr.namespace_from is not None:
            enum = schema.enums.get(row.attribute(attr.namespace_from).enum or "")
            for word in ("site", "body", "joint", "geom"):
                if enum is not None and word in enum.keywords:
                    every.append({attr.namespace_from: word, attr.name: TARGET})
                    break
    # the required references together, then with each other one
    needed = {k: v for ref in every for k, v in ref.items()
              if any(a.name == k and a.required for a in row.attributes)}
    refs = [needed] + [{**needed, **ref} for ref in every if not ref.keys() <= needed.keys()]
    for ref in refs:
        required = {tag: dict(attrs) for tag, attrs in p.site.required.items()}
        required.setdefault(row.tag, {}).update({**compile_only, **ref})
        found = dataclasses.replace(p.site, required=required, world=_WORLD + p.site.world)
        baseline = p.parser(found.model())
        if baseline.error is None and not baseline.saved.startswith(probe.UNSAVED):
            return _Probe(found, p.parser, baseline)
    return p


def load_sites(path: Path = PROBE_SITES) -> dict[str, dict[str, str]]:
    """schema/probe.toml: row -> the attributes its probe model needs besides required ones
    (``_content``, ``_world``: MJCF it holds; ``[ROW.compile]``'s keys prefixed COMPILE)."""
    if not path.exists():
        return {}
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    out: dict[str, dict[str, str]] = {}
    for row, attrs in raw.items():
        table = cast("dict[str, object]", attrs) if isinstance(attrs, dict) else None
        inner: object = table.pop("compile", {}) if table is not None else {}
        if table is None or not isinstance(inner, dict) or not all(
                isinstance(v, str) for v in [*table.values(),
                                             *cast("dict[str, object]", inner).values()]):
            raise ValueError(f"{path}: [{row}] must hold attribute = \"text\" lines")
        out[row] = {str(k): str(v) for k, v in table.items()}
        out[row].update((COMPILE + str(k), str(v))
                        for k, v in cast("dict[str, object]", inner).items())
    return out


def _plain(attr: ir.AttributeDef, schema: ir.Schema) -> str:
    """A value of the attribute's kind that the reader takes."""
    if attr.default is not None:
        return attr.default
    count = attr.arity[0] if attr.arity is not None and attr.arity[0] > 0 else 1
    if attr.kind in ("int", "real"):
        return " ".join(["1"] * count)
    if attr.kind == "bool":
        return "false"
    if attr.kind in ("keyword", "flags") and attr.enum in schema.enums:
        return schema.enums[attr.enum].keywords[0]
    return "p"


# ------------------------------------------------------------------------------ probing


def probe_counts(p: _Probe, attr: ir.AttributeDef) -> tuple[int, int | None] | None:
    """The value counts the reader takes (``None`` high: more than the cap), or None when it
    says nothing about counts (it takes every count tried)."""
    low, high = attr.arity if attr.arity is not None else (1, 1)
    top = min(_COUNT_CAP, (high if high is not None else max(low, 1)) + _COUNT_MARGIN)
    verdicts: dict[int, Verdict] = {}
    for n in range(1, _COUNT_CAP + 1):
        verdicts[n] = p.verdict(attr.name, " ".join(["1"] * n))
        bounded = any(v in ("short", "long") for v in verdicts.values())
        if verdicts[n] == "long" or (n >= top and not bounded):
            break  # past the last count taken, or the reader does not count
    if not any(v in ("short", "long") for v in verdicts.values()):
        return None
    fits = [n for n, v in verdicts.items() if v not in ("short", "long")]
    if not fits:
        return None
    return min(fits), max(fits) if "long" in verdicts.values() else None


def probe_keywords(p: _Probe, attr: ir.AttributeDef, candidates: list[str]) -> list[str]:
    """The candidates the reader takes as the attribute's value, in candidate order."""
    return [k for k in candidates if p.verdict(attr.name, k) == "ok"]


def candidate_keywords(attr: ir.AttributeDef, schema: ir.Schema, ref: Reference,
                       enums: Mapping[str, Mapping[str, int]]) -> list[str]:
    """The schema's keywords, then those XMLreference.rst documents."""
    words: list[str] = []
    enum = schema.enums.get(attr.enum or "")
    if enum is not None:
        words += enum.keywords
    documented = _documented(attr, ref)
    if documented is not None:
        words += documented.keywords
    # Not every constant of the C enum: some readers take all of mjtObj and leave the
    # choice to the compiler (a sensor's reftype), so only a documented keyword is new.
    return list(dict.fromkeys(words))


def _documented(attr: ir.AttributeDef, ref: Reference) -> AtVal | None:
    text = ref.at_val(attr.anchor) if attr.anchor else None
    return parse_at_val(text) if text is not None else None


def _count_text(arity: tuple[int, int | None] | None) -> str:
    if arity is None:
        return "1"
    low, high = arity
    return str(low) if low == high else f"{low}..{'' if high is None else high}"


def _words(values: list[str]) -> str:
    return "[" + ", ".join(values) + "]"


class _Checker:
    """Compares every probed attribute of ``schema`` with the parser, editing ``schema``."""

    def __init__(self, schema: ir.Schema, parser: probe.Parser, ref: Reference,
                 enums: Mapping[str, Mapping[str, int]],
                 structs: Mapping[str, Mapping[str, str]],
                 sites: Mapping[str, Mapping[str, str]],
                 hand: set[tuple[str, str]], hand_enums: set[str]) -> None:
        self.sites = sites
        self.schema = schema
        self.parser = parser
        self.ref = ref
        self.enums = enums
        self.structs = structs
        self.hand = hand
        self.hand_enums = hand_enums
        self.drift = Drift()
        self.why_computed = unset.computed()  # how MuJoCo computes a value, where recorded
        self.for_defaults: _Probe | None = None  # the row's probe for defaults (targeted)
        # enum -> (row, attribute, keywords the parser took) for every probed user
        self.keyword_sets: dict[str, list[tuple[str, str, list[str]]]] = {}

    def run(self, rows: set[str] | None) -> Drift:
        for name in sorted(self.schema.elements if rows is None else rows):
            row = self.schema.elements[name]
            if row.projection_of is not None or row.alias is not None or not row.attributes:
                continue
            p = site(self.schema, name, self.parser, self.sites)
            if p is None:
                self.drift.rows_skipped.append(name)
                continue
            self.for_defaults = targeted(self.schema, row, p, self.sites.get(name))
            for attr in list(row.attributes):
                if (name, attr.name) in self.hand:
                    continue
                self.drift.probed += 1
                self._attribute(p, row, attr)
        self._enums()
        self._default_rows()
        self._recorded_computed(rows)
        return self.drift

    def _recorded_computed(self, rows: set[str] | None) -> None:
        """schema/unset.toml's [computed] reasons on the attributes the probe leaves (typed
        by hand, or set by every probe model) without a default."""
        for (name, attr_name), why in sorted(self.why_computed.items()):
            row = self.schema.elements.get(name)
            if row is None or rows is not None and name not in rows:
                continue
            attr = next((a for a in row.attributes if a.name == attr_name), None)
            if attr is not None and attr.default is None and attr.computed != why:
                before = "(computed)" if attr.computed is not None else "(none)"
                self._apply(row, attr, Change(name, attr_name, "default", before,
                                              "(computed)"), computed=why)

    def _default_rows(self) -> None:
        """A <default> row of its own (default_tendon: no row projects it, no probe model
        reaches it) takes the default its rows agree on (fixed and spatial tendons)."""
        for name, row in sorted(self.schema.elements.items()):
            served = [r for r in self.schema.elements.values() if r.default_row == name]
            if row.projection_of is not None or not served:
                continue
            for attr in row.attributes:
                if attr.default is not None or attr.computed is not None:
                    continue
                found = {a.default for r in served for a in r.attributes
                         if a.name == attr.name and (a.kind, a.arity, a.enum)
                         == (attr.kind, attr.arity, attr.enum)}
                if len(found) == 1 and None not in found:
                    (value,) = found
                    self._apply(row, attr, Change(name, attr.name, "default", "(none)",
                                                  f'"{value}"'), default=value)

    # -- one attribute

    def _attribute(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        if attr.kind in ("int", "real"):
            if self._numeric_kind(p, row, attr):
                self._counts(p, row, attr)
                self._default(self.for_defaults, row, attr)
        elif attr.kind in ("keyword", "bool", "flags"):
            if self._keyword_kind(p, row, attr):
                self._default(self.for_defaults, row, attr)
        elif attr.kind in _STRING_KINDS:
            self._string_list(row, attr)
        elif attr.kind == "string":
            self._string_kind(p, row, attr)

    def _string_kind(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        """Free text that the reader now reads as numbers or as a keyword."""
        seen = p.verdict(attr.name, probe.PROBE_VALUE)
        if seen == "bad":
            self._kind_changed(row, attr, "a number", 'real", arity = [<count>]')
        elif seen == "keyword":
            self._kind_changed(row, attr, "keyword", 'keyword", enum = "<an [[enum]]>')

    def _numeric_kind(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> bool:
        """False (and an untypable change) when the attribute is no longer a number."""
        count = attr.arity[0] if attr.arity is not None and attr.arity[0] > 0 else 1
        ones = " ".join(["1"] * count)
        if p.verdict(attr.name, ones) == "keyword":
            return self._kind_changed(row, attr, "keyword", "keyword or flags")
        documented = _documented(attr, self.ref)
        if documented is not None and documented.kind in ("keyword", "bool"):
            words = list(documented.keywords) or ["false", "true"]
            taken = [w for w in words if p.verdict(attr.name, w) == "ok"]
            if taken:  # numbers still read, and keywords too (headlight active: 0, auto)
                fields = (f'keyword", enum = "<an [[enum]] of {", ".join(taken)}>'
                          + (f'", default = "{documented.default}' if documented.default else ""))
                return self._kind_changed(row, attr, "keyword " + _words(taken), fields)
        if attr.kind == "int" and p.verdict(attr.name, " ".join(["1.5"] * count)) == "ok":
            return self._kind_changed(row, attr, "real", "real")
        return True

    def _keyword_kind(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> bool:
        if p.verdict(attr.name, probe.PROBE_VALUE) == "ok" and _saves(p) \
                and not p.load(attr.name, probe.PROBE_VALUE).saved.startswith(probe.UNSAVED):
            return self._kind_changed(row, attr, "string", "string")  # not checked late
        if attr.kind == "bool":
            words = [w for w in ("false", "true") if p.verdict(attr.name, w) == "ok"]
            if words != ["false", "true"]:
                return self._kind_changed(row, attr, "keyword " + _words(words), "keyword")
            return True
        if attr.enum in self.hand_enums or attr.alone:
            return True
        candidates = candidate_keywords(attr, self.schema, self.ref, self.enums)
        taken = probe_keywords(p, attr, candidates)
        self.keyword_sets.setdefault(attr.enum or "", []).append((row.name, attr.name, taken))
        return True

    def _kind_changed(self, row: ir.ElementDef, attr: ir.AttributeDef, after: str,
                      kind: str) -> bool:
        change = Change(row.name, attr.name, "kind", attr.kind, after)
        self.drift.untypable.append((change, _fact(row.name, attr.name, f'kind = "{kind}"')))
        return False

    def _counts(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        seen = probe_counts(p, attr)
        old = attr.arity if attr.arity is not None else (1, 1)
        if seen is None or seen == old:
            return
        if old[1] is not None and old[1] >= _COUNT_CAP and seen[1] is None:
            return  # more values than the probe tries: as many as it saw
        new = None if seen == (1, 1) else seen
        self._apply(row, attr, Change(row.name, attr.name, "count", _count_text(attr.arity),
                                      _count_text(new)), arity=new)

    def _default(self, p: _Probe | None, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        if p is None or p.baseline.saved.startswith(probe.UNSAVED):
            return  # MuJoCo cannot save the probe model: nothing to compare
        if attr.default is None:
            self._missing_default(p, row, attr)
            return
        if _alternative(row, attr):  # quat's default applies, not one of its own
            self._apply(row, attr, Change(row.name, attr.name, "default", f'"{attr.default}"',
                                          "(none)"), default=None)
            return
        self.drift.defaults += 1
        if p.load(attr.name, attr.default).saved == p.baseline.saved:
            return
        documented = _documented(attr, self.ref)
        new = documented.default if documented is not None else None
        if new is not None and p.load(attr.name, new).saved == p.baseline.saved \
                and p.load(attr.name, new).error is None:
            self._apply(row, attr, Change(row.name, attr.name, "default", f'"{attr.default}"',
                                          f'"{new}"'), default=new)
            return
        change = Change(row.name, attr.name, "default", f'"{attr.default}"', "(another)")
        self.drift.untypable.append(
            (change, _fact(row.name, attr.name, 'default = "<the value MuJoCo uses>"')))

    def _missing_default(self, p: _Probe, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        """No default yet: MuJoCo's documented default when MuJoCo saves the model with it
        back as with the attribute left out, else the one plain value that does; when the
        saved model shows the attribute (some value changes it) and none does, MuJoCo
        computes the value (``computed``); else the probe cannot tell. The defaults other rows
        give the attribute are candidates too. An alternative to an attribute with a default
        (axisangle beside quat) has none of its own."""
        if _alternative(row, attr):  # quat's default applies
            if attr.computed is not None:
                self._apply(row, attr, Change(row.name, attr.name, "default", "(computed)",
                                              "(none)"), computed=None)
            return
        if attr.name in p.site.required.get(row.tag, {}):
            return  # the probe model sets it (no model leaves it out)
        plain = default_candidates(attr, self.schema)
        documented = _documented(attr, self.ref)
        shown = documented.default if documented is not None and documented.default else None
        # then the default other rows give the attribute (a flexcomp's radius: its flex's)
        texts = list(dict.fromkeys(plain + ([shown] if shown else [])
                                   + borrowed_defaults(attr, self.schema)))
        saved = {text: p.load(attr.name, text) for text in texts}
        same = [t for t, o in saved.items() if o.error is None and o.saved == p.baseline.saved]
        if len(same) == len(texts) or not same and all(o.error for o in saved.values()):
            return  # the saved model does not show the attribute: nothing to tell
        if len(same) > 1:
            plain_same = [t for t in same if t in plain]
            if len(plain_same) != 1 and shown in same:
                same = [shown]  # the documented one, of several read alike
            elif plain_same:
                same = plain_same
        why = self.why_computed.get((row.name, attr.name), COMPUTED)
        if len(same) > 1 or not same and (attr.computed == why or not plain):
            return  # several read alike (a zero quaternion and the unit one): cannot tell
        self.drift.defaults += 1
        before = "(computed)" if attr.computed is not None else "(none)"
        if same:
            self._apply(row, attr, Change(row.name, attr.name, "default", before,
                                          f'"{same[0]}"'), default=same[0], computed=None)
            return
        self._apply(row, attr, Change(row.name, attr.name, "default", before, "(computed)"),
                    computed=why)

    def _string_list(self, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        c_type = self.structs.get(row.struct or "", {}).get(attr.field or attr.name)
        if c_type is None:
            return
        is_list = c_type in _VECTOR_TYPES
        if is_list and attr.arity is None:
            new: tuple[int, int | None] | None = (1, None)
        elif not is_list and attr.arity is not None:
            new = None
        else:
            return
        change = Change(row.name, attr.name, "count", _count_text(attr.arity), _count_text(new))
        # the runtime's id and ref codecs hold one name: a list of them is free text (as
        # flex@body's bodies), typed by hand; one name again is a ref of a namespace
        fields = 'kind = "string"' if new is not None else 'kind = "ref", namespace = "<...>"'
        self.drift.untypable.append((change, _fact(row.name, attr.name, fields)))

    def _apply(self, row: ir.ElementDef, attr: ir.AttributeDef, change: Change,
               **fields: object) -> None:
        """Change the attribute and the default-class rows' copies that agreed with it."""
        old = copy.deepcopy(attr)
        for target in [row, *self._projections(row.name)]:
            for index, other in enumerate(target.attributes):
                if other.name == attr.name and (target is row or _same_type(other, old)):
                    for key, value in fields.items():
                        setattr(other, key, value)
                    target.attributes[index] = other
        self.drift.applied.append(change)

    def _projections(self, name: str) -> list[ir.ElementDef]:
        return [r for _, r in sorted(self.schema.elements.items()) if r.projection_of == name]

    # -- keyword sets, once every user of an enum is probed

    def _enums(self) -> None:
        for enum_name, users in sorted(self.keyword_sets.items()):
            enum = self.schema.enums.get(enum_name)
            if enum is None:
                continue
            sets = {tuple(taken) for _, _, taken in users}
            if all(set(t) == set(enum.keywords) for t in sets):
                continue
            row, name, taken = users[0]
            change = Change(row, name, "keywords", _words(enum.keywords), _words(taken))
            if len({frozenset(t) for t in sets}) > 1 or not taken:
                lines = "; ".join(f"{r}@{n} {_words(t)}" for r, n, t in users)
                fact = (f"[[enum]] entries for the keyword sets the users of {enum_name} now "
                        f"take ({lines}), and [[attribute]] entries naming them")
                self.drift.untypable.append((change, fact))
                continue
            self._set_keywords(enum, taken)
            self.drift.applied.extend(
                Change(r, n, "keywords", change.before, change.after) for r, n, _ in users)

    def _set_keywords(self, enum: ir.EnumDef, taken: list[str]) -> None:
        """Keep the values of kept keywords; bind new ones to the C enum or to integers."""
        values = dict(enum.values)
        consts = {c.split("_", 1)[-1].lower(): c for c in self.enums.get(enum.ctype or "", {})}
        used = [int(v) for v in values.values() if re.fullmatch(r"-?\d+", v)]
        next_int = max(used, default=-1) + 1
        out: list[tuple[str, str]] = []
        for word in taken:
            if word in values:
                out.append((word, values[word]))
            elif word.lower() in consts:
                out.append((word, consts[word.lower()]))
            else:
                out.append((word, str(next_int)))
                next_int += 1
        kept = [k for k in enum.keywords if k in taken]
        order = {k: i for i, k in enumerate(kept)}
        enum.values = sorted(out, key=lambda kv: order.get(kv[0], len(order)))


# Why an attribute has no default, when the probe finds none (docs: "computed by MuJoCo").
COMPUTED = ("MuJoCo derives the value when the attribute is absent: no plain value written "
            "saves back as the attribute left out (codegen/drift.py)")


def _alternative(row: ir.ElementDef, attr: ir.AttributeDef) -> bool:
    """``attr``, a number, is refused beside another attribute that has a default (quat's
    orientation alternatives): that one's default applies when neither is given. Of two
    with a default (a flexcomp's quat and axisangle), the first in the constraint owns it."""
    if attr.kind not in ("int", "real"):
        return False  # a keyword or flag (light type beside directional) has its own
    for c in row.constraints:
        if c.kind != "exclusive" or not any(attr.name in b for b in c.bundles):
            continue
        names = [n for b in c.bundles for n in b]
        for name in names:
            other = next((a for a in row.attributes if a.name == name), None)
            if other is None or other.default is None or any(
                    attr.name in b and name in b for b in c.bundles):
                continue
            if attr.default is None or names.index(name) < names.index(attr.name):
                return True
    return False


def default_candidates(attr: ir.AttributeDef, schema: ir.Schema) -> list[str]:
    """Plain values a default may be, then one that shows the attribute in a saved model:
    zeros and ones of the full count (``2``: a contrast), false and true, the keywords."""
    if attr.kind == "bool":
        return ["false", "true"]
    if attr.kind in ("keyword", "flags"):  # flags: each alone (the documented set follows)
        enum = schema.enums.get(attr.enum or "")
        return list(enum.keywords) if enum is not None else []
    if attr.kind not in ("int", "real"):
        return []
    low, high = attr.arity if attr.arity is not None else (1, 1)
    count = high if high is not None else low
    if count < 1 or count > _COUNT_CAP:
        return []
    unit = [" ".join(["1"] + ["0"] * (count - 1))] if count > 1 else []
    return [" ".join([v] * count) for v in ("0", "1", "2")] + unit


def borrowed_defaults(attr: ir.AttributeDef, schema: ir.Schema) -> list[str]:
    """The defaults other rows give an attribute of this name and type, sorted."""
    return sorted({a.default for r in schema.elements.values() for a in r.attributes
                   if a.name == attr.name and a.default is not None and a is not attr
                   and (a.kind, a.arity, a.enum) == (attr.kind, attr.arity, attr.enum)})


def _saves(p: _Probe) -> bool:
    return not p.baseline.saved.startswith(probe.UNSAVED)


def _same_type(a: ir.AttributeDef, b: ir.AttributeDef) -> bool:
    return (a.kind, a.arity, a.enum, a.default) == (b.kind, b.arity, b.enum, b.default)


def _fact(row: str, name: str, fields: str) -> str:
    return (f'[[attribute]] element = "{row}", name = "{name}", {fields}, '
            'reason = "<what MuJoCo X changed>"')


# ---------------------------------------------------------------------------- spellings


def keyword_numbers(schema: ir.Schema, attr: ir.AttributeDef,
                    enums: Mapping[str, Mapping[str, int]]) -> dict[str, int]:
    """Each keyword of ``attr``'s enum with its integer: the value column's integer text, or
    the value of its C constant."""
    enum = schema.enums.get(attr.enum or "")
    if enum is None:
        return {}
    consts = enums.get(enum.ctype or "", {})
    out: dict[str, int] = {}
    for word, value in enum.values:
        if re.fullmatch(r"-?\d+", value):
            out[word] = int(value)
        elif value in consts:
            out[word] = consts[value]
    return out


def probe_numbers(p: _Probe, attr: ir.AttributeDef,
                  numbers: Mapping[str, int]) -> dict[str, int] | None:
    """The keywords whose integer the reader also takes for ``attr`` (None: the probe model
    cannot tell, its reader taking any word, as a frame sensor's reftype without refname)."""
    if p.verdict(attr.name, probe.PROBE_VALUE) not in ("keyword", "bad"):
        return None
    return {w: n for w, n in numbers.items() if p.verdict(attr.name, str(n)) == "ok"}


def check_spellings(schema: ir.Schema, parser: probe.Parser,
                    enums: Mapping[str, Mapping[str, int]],
                    sites: Mapping[str, Mapping[str, str]],
                    rows: set[str] | None = None) -> Drift:
    """Record in ``schema`` (each keyword attribute's ``numbers``, on its row and the default
    rows projecting it) which other spellings the installed reader takes; a change is
    :attr:`Drift.applied`. Every keyword attribute is probed, those facts.toml types too."""
    drift = Drift()
    for name in sorted(schema.elements if rows is None else rows):
        row = schema.elements[name]
        users = [a for a in row.attributes if a.kind == "keyword"]
        if row.projection_of is not None or row.alias is not None or not users:
            continue
        p = site(schema, name, parser, sites)
        if p is None:
            drift.rows_skipped.append(name)
            continue
        for attr in users:
            found = probe_numbers(p, attr, keyword_numbers(schema, attr, enums))
            if found is None:
                continue
            drift.probed += 1
            new = found or None
            if new == attr.numbers:
                continue
            drift.applied.append(Change(name, attr.name, "spellings", _spelt(attr.numbers),
                                        _spelt(new)))
            for target in [row] + [r for r in schema.elements.values()
                                   if r.projection_of == name]:
                for other in target.attributes:
                    if other.name == attr.name and other.enum == attr.enum:
                        other.numbers = None if new is None else dict(new)
    return drift


def _spelt(numbers: Mapping[str, int] | None) -> str:
    return "[" + ", ".join(f"{w}={n}" for w, n in (numbers or {}).items()) + "]"


def check(schema: ir.Schema, parser: probe.Parser, ref: Reference,
          enums: Mapping[str, Mapping[str, int]], structs: Mapping[str, Mapping[str, str]],
          sites: Mapping[str, Mapping[str, str]],
          hand: set[tuple[str, str]], hand_enums: set[str],
          rows: set[str] | None = None) -> Drift:
    """Probe every attribute of ``schema`` (of ``rows``, when given) that a loading model
    reaches; ``schema`` is edited for the changes that can be typed."""
    return _Checker(schema, parser, ref, enums, structs, sites, hand, hand_enums).run(rows)
