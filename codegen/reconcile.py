"""Make the IR agree with the installed ``mujoco`` parser (``sync``).

The grammar file describes one MuJoCo version; the installed wheel is the authority on what
the parser accepts now. ``sync`` walks ``mj_printSchema``'s tree alongside the IR and

* adds rows, child edges and attributes the wheel has and the IR lacks, typing attributes
  from ``XMLreference.rst`` (or from the primary row, for default-class projections);
* gives the rows printSchema omits (``worldbody``, ``frame``, ``replicate``) the attributes
  the wheel's parser reads there (:mod:`codegen.probe`), adding and removing like the rest;
* removes child edges and attributes the wheel no longer has, then drops unreachable rows
  and enums no attribute uses;
* takes child cardinalities from the wheel, sets ``anchor`` on every row and attribute the
  reference documents, and checks enum C constants against ``mujoco.introspect``.

What cannot be typed precisely is added as a string and listed in ``Report.untyped``; a
hand-kept type goes in ``schema/facts.toml`` as an ``[[attribute]]`` entry, which sync also
applies to attributes the schema has.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from dataclasses import dataclass, field

from codegen import drift, ir, naming, probe
from codegen.errors import FactsError
from codegen.facts import AttributeOverride, Facts
from codegen.passes import (
    DEFAULT_ROW,
    PROJECTION_PREFIX,
    add_constraints,
    apply_override,
    enum_from_fact,
    enums_of,
)
from codegen.wheel import AtVal, Reference, Wheel, WheelRow, parse_at_val

# The longest tag path an anchor spells before the attribute: ``compiler-lengthrange-mode``.
_ANCHOR_DEPTH = 4
# The doc of an attribute added as a string for want of a type: it stays in the schema (and
# in the generated docstring) and every sync reports it until facts.toml types it.
UNTYPED_DOC = "UNTYPED: "

# --------------------------------------------------------------------------------- report


@dataclass
class Report:
    """What ``sync`` changed, in readable lines (``+`` added, ``-`` removed, ``~`` changed)."""

    version: tuple[str, str] | None = None  # (before, after) when it changed
    added_rows: list[str] = field(default_factory=list[str])
    removed_rows: list[str] = field(default_factory=list[str])
    changed_rows: list[str] = field(default_factory=list[str])
    added_attributes: list[str] = field(default_factory=list[str])
    removed_attributes: list[str] = field(default_factory=list[str])
    changed_attributes: list[str] = field(default_factory=list[str])
    added_children: list[str] = field(default_factory=list[str])
    removed_children: list[str] = field(default_factory=list[str])
    changed_children: list[str] = field(default_factory=list[str])
    added_enums: list[str] = field(default_factory=list[str])
    removed_enums: list[str] = field(default_factory=list[str])
    changed_enums: list[str] = field(default_factory=list[str])
    untyped: list[str] = field(default_factory=list[str])  # added as strings: fix by hand
    # types of existing attributes the installed parser disagrees with (codegen.drift)
    drifted: list[str] = field(default_factory=list[str])  # applied
    drift_errors: list[str] = field(default_factory=list[str])  # to type in facts.toml
    notes: list[str] = field(default_factory=list[str])  # inferences and oddities to review
    anchors: int = 0  # row and attribute anchors set or changed

    def _sections(self) -> list[tuple[str, str, list[str]]]:
        return [
            ("rows", "+", self.added_rows), ("rows", "-", self.removed_rows),
            ("children", "+", self.added_children), ("children", "-", self.removed_children),
            ("children", "~", self.changed_children),
            ("attributes", "+", self.added_attributes),
            ("attributes", "-", self.removed_attributes),
            ("attributes", "~", self.changed_attributes),
            ("enums", "+", self.added_enums), ("enums", "-", self.removed_enums),
            ("enums", "~", self.changed_enums),
        ]

    def is_empty(self) -> bool:
        """True when the IR already agreed with the wheel (notes do not count)."""
        return (self.version is None and self.anchors == 0 and not self.untyped
                and not self.drifted and not self.drift_errors and not self.changed_rows and not any(lines for _, _, lines in self._sections()))

    def format(self) -> str:
        """A readable summary, one change per line, grouped by what changed."""
        if self.is_empty():
            return "schema agrees with the installed mujoco" + self._format_notes()
        out: list[str] = []
        if self.version is not None:
            out.append(f"mujoco_version: {self.version[0] or '(none)'} -> {self.version[1]}")
        heading = ""
        for title, sign, lines in self._sections():
            if lines and title != heading:
                heading = title
                out.append(f"{title}:")
            out.extend(f"  {sign} {line}" for line in lines)
        if self.changed_rows:
            out.append(f"rows changed: {len(self.changed_rows)} "
                       f"({', '.join(self.changed_rows)})")
        if self.anchors:
            out.append(f"anchors: {self.anchors} set or changed")
        if self.drifted:
            out.append("types (probed against the installed parser):")
            out.extend(f"  ~ {line}" for line in self.drifted)
        if self.drift_errors:
            out.append("DRIFT that cannot be typed automatically (schema/ not written):")
            out.extend(f"  ! {line}" for line in self.drift_errors)
        if self.untyped:
            out.append("UNTYPED (added as strings; add [[attribute]] entries to "
                       "schema/facts.toml):")
            out.extend(f"  ! {line}" for line in self.untyped)
        return "\n".join(out) + self._format_notes()

    def _format_notes(self) -> str:
        if not self.notes:
            return ""
        return "\nnotes:\n" + "\n".join(f"  * {line}" for line in self.notes)


# ------------------------------------------------------------------------ describing types


def describe(attr: ir.AttributeDef) -> str:
    """``real double[1..3] = "1"``-style text for reports."""
    text: str = attr.kind
    if attr.kind in ("keyword", "flags"):
        text += f"<{attr.enum}>"
        if attr.alone:
            text += f" or alone <{', '.join(attr.alone)}>"
        if attr.ordered:
            text += " (ordered)"
    elif attr.kind in ("id", "ref"):
        text += f"<{attr.namespace}>"
    elif attr.dtype is not None and attr.kind == "real":
        text += f" {attr.dtype}"
    if attr.arity is not None:
        low, high = attr.arity
        text += f"[{low}]" if low == high else f"[{low}..{'' if high is None else high}]"
    if attr.default is not None:
        text += f' = "{attr.default}"'
    if attr.required:
        text += " (required)"
    return text


def _type_of(attr: ir.AttributeDef) -> tuple[object, ...]:
    """The fields that make an attribute's type (not its documentation or anchor)."""
    return (attr.kind, attr.dtype, attr.arity, attr.enum, attr.alone, attr.ordered,
            attr.namespace, attr.default, attr.pattern, attr.field)


# ----------------------------------------------------------------------------------- sync


def sync(schema: ir.Schema, wheel: Wheel, facts: Facts, older: bool = False,
         ) -> tuple[ir.Schema, Report]:
    """``schema`` (left untouched) made to agree with ``wheel``, and what changed; ``older``:
    the wheel is a release older than ``schema``'s (``[[attribute]]`` entries for attributes
    it lacks are skipped, not errors: codegen/releases.py)."""
    out = copy.deepcopy(schema)
    report = Report()
    _Sync(out, wheel, facts, report, older).run()
    return out, report


class _Sync:
    """One reconciliation; the methods edit ``schema`` in place and log to ``report``."""

    def __init__(self, schema: ir.Schema, wheel: Wheel, facts: Facts, report: Report,
                 older: bool = False) -> None:
        self.schema = schema
        self.older = older
        self.wheel = wheel
        self.ref: Reference = wheel.reference
        self.report = report
        self.single = facts.single
        self.overrides = {(o.element, o.name): o for o in facts.attributes}
        self.enum_facts = facts.enums
        self.constraint_facts = facts.constraints
        self.matches: dict[str, WheelRow] = {}  # IR row -> the printSchema row it stands for
        self.added_edges: dict[str, list[ir.ChildDef]] = {}  # per row, edges sync added
        self.touched: set[str] = set()
        self.new_untyped: set[tuple[str, str]] = set()  # (row, attribute) added as strings
        self._suffix_cache: dict[str, set[tuple[str, ...]]] = {}
        self._enum_users = self._used_enums()
        self.candidates = self._candidate_names()

    @property
    def rows(self) -> dict[str, ir.ElementDef]:
        return self.schema.elements

    def run(self) -> None:
        self._match(self.rows[self.schema.root], self.wheel.schema)
        self._sync_all_children()
        self._sync_alias_children()
        self._drop_unreachable()
        for row in self._attribute_order():
            self._sync_attributes(row, self.matches[row.name])
        for row in self._alias_rows():
            self._sync_probed_attributes(row)
        self._apply_enum_facts()
        self._set_anchors()  # the probe reads documented defaults by anchor (set again below)
        add_constraints(self.schema, self.constraint_facts)  # alternatives take no default
        self._probe_types()
        self._apply_overrides()
        self._probe_spellings()
        self._report_committed_untyped()
        self._check_enums()
        self._drop_unused_enums()
        self._set_anchors()
        self._set_version()
        self.report.changed_rows = sorted(self.touched & set(self.rows))

    # -- matching the printSchema tree to IR rows

    def _match(self, row: ir.ElementDef, wrow: WheelRow) -> None:
        """Pair ``row`` with ``wrow`` and, through existing edges, their children."""
        if row.name in self.matches:
            if _shape(self.matches[row.name]) != _shape(wrow):
                self.report.notes.append(f"row {row.name} stands for different printSchema "
                                         f"rows at different places; using the first")
            return
        self.matches[row.name] = wrow
        for edge in row.children:
            child = self.rows[edge.element]
            wchild = wrow.child(child.tag)
            if wchild is not None:
                self._match(child, wchild)
            elif _recursive(wrow, child):
                self._match(child, wrow)

    # -- child edges

    def _sync_all_children(self) -> None:
        done: set[str] = set()
        while pending := [n for n in self.matches if n not in done]:
            for name in pending:
                done.add(name)
                if self.rows[name].alias is None:
                    self._sync_children(self.rows[name], self.matches[name])

    def _sync_children(self, row: ir.ElementDef, wrow: WheelRow) -> None:
        listed: set[str] = set()
        for wchild in wrow.children:
            edge = self._edge(row, wchild)
            if edge is None:
                edge = self._add_edge(row, wchild)
            else:
                self._set_card(row, edge, wchild.card)
            listed.add(edge.element)
        for edge in list(row.children):
            child = self.rows[edge.element]
            if edge.element in listed or _recursive(wrow, child) or child.alias is not None:
                continue  # frame and replicate rows are not listed by printSchema
            self._remove_edge(row, edge)

    def _edge(self, row: ir.ElementDef, wchild: WheelRow) -> ir.ChildDef | None:
        return next((c for c in row.children if self.rows[c.element].tag in wchild.spellings),
                    None)

    def _add_edge(self, row: ir.ElementDef, wchild: WheelRow) -> ir.ChildDef:
        target = self._row_for(row, wchild)
        edge = ir.ChildDef(target.name, wchild.card, self._single(row, target, wchild.card))
        row.children.append(edge)
        self.added_edges.setdefault(row.name, []).append(edge)
        self.report.added_children.append(f"{row.name}/{target.name} {wchild.card}")
        self.touched.add(row.name)
        self._match(target, wchild)
        return edge

    def _set_card(self, row: ir.ElementDef, edge: ir.ChildDef, card: ir.Cardinality) -> None:
        if edge.card == card:
            return
        self.report.changed_children.append(f"{row.name}/{edge.element}: {edge.card} -> {card}")
        edge.card = card
        edge.single = self._single(row, self.rows[edge.element], card)
        self.touched.add(row.name)

    def _remove_edge(self, row: ir.ElementDef, edge: ir.ChildDef) -> None:
        row.children.remove(edge)
        self.report.removed_children.append(f"{row.name}/{edge.element} {edge.card}")
        self.touched.add(row.name)

    def _single(self, parent: ir.ElementDef, child: ir.ElementDef, card: ir.Cardinality) -> bool:
        """Normalisation's rule: ``?``/``!`` children and the hand-kept sections are single."""
        return card in "?!" or child.tag in self.single.get(parent.name, [])

    # -- rows for new children

    def _row_for(self, parent: ir.ElementDef, wchild: WheelRow) -> ir.ElementDef:
        """An existing row of the same shape, a new default projection, or a new row."""
        same = sorted(n for n, w in self.matches.items()
                      if self.rows[n].tag in wchild.spellings and _shape(w) == _shape(wchild))
        if same:
            return self.rows[same[0]]
        primary = self._primary(wchild) if parent.name == DEFAULT_ROW else None
        row = self._new_projection(primary) if primary else self._new_row(parent, wchild)
        self.rows[row.name] = row
        self.report.added_rows.append(self._describe_row(row))
        return row

    def _primary(self, wchild: WheelRow) -> ir.ElementDef | None:
        """The row a new ``<default>`` child projects: same tag, attributes a superset."""
        wanted = set(wchild.attributes)
        candidates = sorted(
            (self.rows[n] for n, w in self.matches.items()
             if self.rows[n].tag in wchild.spellings and wanted <= set(w.attributes)
             and self.rows[n].projection_of is None and self.rows[n].alias is None
             and not self._in_default(self.rows[n])),
            key=lambda r: (r.name != r.tag, r.name))
        if len(candidates) > 1 and candidates[1].name == candidates[1].tag:
            self.report.notes.append(f"default/{wchild.tag}: several primary rows "
                                     f"({', '.join(r.name for r in candidates)})")
        return candidates[0] if candidates else None

    def _new_projection(self, primary: ir.ElementDef) -> ir.ElementDef:
        name = PROJECTION_PREFIX + primary.name
        return ir.ElementDef(name=name, tag=primary.tag, class_name="Default" + primary.class_name,
                             struct=primary.struct, projection_of=primary.name)

    def _new_row(self, parent: ir.ElementDef, wchild: WheelRow) -> ir.ElementDef:
        tag = wchild.spellings[-1]
        name = tag if tag not in self.rows else f"{parent.name}_{tag}"
        if name in self.rows:
            raise ValueError(f"sync: cannot name the new <{tag}> row under {parent.name!r}: "
                             f"{name!r} exists")
        return ir.ElementDef(name=name, tag=tag,
                             class_name=naming.class_name(name, self.schema.root))

    def _describe_row(self, row: ir.ElementDef) -> str:
        text = f"{row.name} <{row.tag}> ({row.class_name})"
        return text + (f", projection of {row.projection_of}" if row.projection_of else "")

    # -- alias rows (worldbody, frame, replicate): the body row's grammar, restricted

    def _alias_rows(self) -> list[ir.ElementDef]:
        return [r for _, r in sorted(self.rows.items())
                if r.alias is not None and r.alias in self.matches]

    def _sync_alias_children(self) -> None:
        """Drop children the aliased row lost; add those it gained in this sync."""
        for row in self._alias_rows():
            wrow = self.matches[row.alias or ""]
            tags = {self.rows[c.element].tag for c in row.children}
            for edge in self.added_edges.get(row.alias or "", []):
                child = self.rows[edge.element]
                if child.tag not in tags:
                    row.children.append(ir.ChildDef(child.name, edge.card,
                                                    self._single(row, child, edge.card)))
                    self.report.added_children.append(f"{row.name}/{edge.element} {edge.card}")
                    self.touched.add(row.name)
            for edge in list(row.children):
                child = self.rows[edge.element]
                wchild = wrow.child(child.tag)
                if wchild is not None:
                    self._set_card(row, edge, wchild.card)
                elif not (_recursive(wrow, child) or child.alias is not None):
                    self._remove_edge(row, edge)

    def _sync_probed_attributes(self, row: ir.ElementDef) -> None:
        """Alias rows are not listed by printSchema: their attributes are the names the
        wheel's parser reads there (codegen.probe), typed like any attribute sync adds."""
        site = probe.site_for(self.schema, row.name)
        if self.wheel.parser is None or site is None:
            why = "the wheel has no parser" if site is not None else "no probe model for it"
            self.report.notes.append(f"{row.name}: attributes not checked ({why})")
            return
        found = probe.discover(site, self.candidates, self.wheel.parser)
        if row.ignores_unknown != found.ignores_unknown:
            row.ignores_unknown = found.ignores_unknown
            self.report.notes.append(
                f"{row.name}: MuJoCo's reader now "
                f"{'ignores' if found.ignores_unknown else 'refuses'} attributes it does not know")
            self.touched.add(row.name)
        for attr in [a for a in row.attributes if a.name not in found.read]:
            self._remove_attribute(row, attr)
        missing = [n for n in found.read if all(a.name != n for a in row.attributes)]
        for name in sorted(missing, key=lambda n: self.ref.position(self._anchor_of(row, n)
                                                                     or "")):
            self._add_attribute(row, name)
        for message, names in found.refused.items():
            self.report.notes.append(f"{row.name}: the reader refuses the element with any of "
                                     f"{len(names)} attributes the schema check admits "
                                     f"({message})")
        prefix, documented = self._documented(row)
        for name in sorted(documented - set(found.read)):
            self.report.notes.append(f"{row.name}@{name} is documented ({prefix}-{name}) but "
                                     "the parser does not read it")

    def _candidate_names(self) -> tuple[str, ...]:
        """Every attribute name the sources spell: printSchema, the IR as given (the grammar
        file's, when building from it) and XMLreference.rst, so an alias row's new attribute
        is found when it exists anywhere else."""
        names = {a for wrow in self.wheel.schema.walk() for a in wrow.attributes}
        names |= {a.name for r in self.rows.values() for a in r.attributes}
        names |= set(self.ref.names) | {a.rsplit("-", 1)[-1] for a in self.ref.entries}
        return tuple(sorted(names))

    def _documented(self, row: ir.ElementDef) -> tuple[str | None, set[str]]:
        """The longest anchor prefix of ``row`` that documents attributes, and their names."""
        children = {self.rows[c.element].tag for c in row.children}
        best: tuple[str | None, set[str]] = (None, set())
        for suffix in sorted(self._suffixes(row.name), key=lambda s: (len(s), s)):
            prefix = "-".join(suffix)
            names = {a[len(prefix) + 1:] for a in self.ref.anchors
                     if a.startswith(prefix + "-") and "-" not in a[len(prefix) + 1:]}
            if names - children:
                best = (prefix, names - children)
        return best

    # -- unreachable rows

    def _drop_unreachable(self) -> None:
        reachable: set[str] = set()
        pending = [self.schema.root]
        while pending:
            name = pending.pop()
            if name not in reachable:
                reachable.add(name)
                pending.extend(c.element for c in self.rows[name].children)
        for name in sorted(set(self.rows) - reachable):
            del self.rows[name]
            self.matches.pop(name, None)
            self.report.removed_rows.append(name)

    # -- attributes

    def _in_default(self, row: ir.ElementDef) -> bool:
        return row.name == DEFAULT_ROW or DEFAULT_ROW in self._parents(row.name)

    def _attribute_order(self) -> list[ir.ElementDef]:
        """Primary rows before the default-class rows that copy them."""
        rows = [self.rows[n] for n in sorted(self.matches) if self.rows[n].alias is None]
        return sorted(rows, key=lambda r: (self._in_default(r) and r.name != DEFAULT_ROW,
                                           r.name))

    def _sync_attributes(self, row: ir.ElementDef, wrow: WheelRow) -> None:
        listed = set(wrow.attributes)
        for attr in [a for a in row.attributes if a.name not in listed]:
            self._remove_attribute(row, attr)
        missing = [n for n in wrow.attributes if all(a.name != n for a in row.attributes)]
        for name in sorted(missing, key=lambda n: self.ref.position(self._anchor_of(row, n)
                                                                     or "")):
            self._add_attribute(row, name)
        primary = self.rows.get(row.projection_of or "")
        if primary is not None and missing:
            order = {a.name: i for i, a in enumerate(primary.attributes)}
            row.attributes.sort(key=lambda a: order.get(a.name, len(order)))

    def _remove_attribute(self, row: ir.ElementDef, attr: ir.AttributeDef) -> None:
        row.attributes.remove(attr)
        self.report.removed_attributes.append(f"{row.name}@{attr.name}: {describe(attr)}")
        self.touched.add(row.name)
        for constraint in list(row.constraints):
            bundles = [[n for n in b if n != attr.name] for b in constraint.bundles]
            constraint.bundles = [b for b in bundles if b]
            if len(constraint.bundles) < 2:
                row.constraints.remove(constraint)
                self.report.notes.append(f"{row.name}: dropped constraint {constraint.kind} "
                                         f"(it named the removed attribute {attr.name})")

    def _add_attribute(self, row: ir.ElementDef, name: str) -> None:
        attr, source = self._new_attribute(row, name)
        row.attributes.append(attr)
        self.touched.add(row.name)
        line = f"{row.name}@{name}: {describe(attr)}"
        self.report.added_attributes.append(f"{line}  [{source}]" if source else line)

    def _new_attribute(self, row: ir.ElementDef, name: str) -> tuple[ir.AttributeDef, str]:
        """A definition for a new attribute and where its type came from."""
        hand = self.overrides.get((row.name, name))
        if hand is not None and hand.kind is not None:
            return self._from_hand(hand), "facts.toml"
        copied = self._copied(row, name)
        if copied is not None:
            return copied
        anchor = self._anchor_of(row, name)
        text = self.ref.at_val(anchor) if anchor else None
        parsed = parse_at_val(text) if text is not None else None
        attr = self._from_at_val(row, name, parsed) if parsed is not None else None
        if attr is not None:
            return attr, anchor or ""
        if anchor is None:
            why = "no XMLreference.rst anchor"
        elif text is None:
            why = f"{anchor} states no type"
        elif parsed is None:
            why = f"{anchor} type {text!r} is not understood"
        else:
            why = f"{anchor} says {text!r}, but {name} is an identifier elsewhere"
        self.report.untyped.append(f"{row.name}@{name}: {why}")
        self.new_untyped.add((row.name, name))
        doc = f"{UNTYPED_DOC}{why}; give its type in schema/facts.toml [[attribute]]"
        return ir.AttributeDef(name=name, py_name=naming.py_name(name), kind="string",
                               doc=doc), "UNTYPED"

    def _copied(self, row: ir.ElementDef, name: str) -> tuple[ir.AttributeDef, str] | None:
        """Default-class rows take the primary's definition, or the one their family shares."""
        primary = self.rows.get(row.projection_of or "")
        if primary is not None:
            source = next((a for a in primary.attributes if a.name == name), None)
            if source is not None:
                attr = copy.deepcopy(source)
                attr.required = False
                return attr, f"copied from {primary.name}"
        if self._in_default(row) and row.projection_of is None:
            return self._family_definition(row, name)
        return None

    def _family_definition(self, row: ir.ElementDef, name: str,
                           ) -> tuple[ir.AttributeDef, str] | None:
        """``default/tendon`` sets what all tendon types share: the definition the children
        of the ``<tendon>`` rows give ``name``, when they all agree."""
        family = sorted({c.element for r in self.rows.values()
                         if r.tag == row.tag and not self._in_default(r) for c in r.children})
        defs = [(n, a) for n in family for a in self.rows[n].attributes if a.name == name]
        if not defs or len({_type_of(a) for _, a in defs}) != 1:
            return None
        attr = copy.deepcopy(defs[0][1])
        attr.required = False
        return attr, f"shared by {', '.join(n for n, _ in defs)}"

    def _from_hand(self, hand: AttributeOverride) -> ir.AttributeDef:
        attr = ir.AttributeDef(name=hand.name, py_name=naming.py_name(hand.name), kind="string")
        apply_override(attr, hand, self.schema)
        return attr

    def _from_at_val(self, row: ir.ElementDef, name: str, val: AtVal) -> ir.AttributeDef | None:
        attr = ir.AttributeDef(name=name, py_name=naming.py_name(name), kind="string",
                               arity=val.arity, default=val.default, required=val.required)
        if val.kind == "real":
            attr.kind, attr.dtype = "real", self._real_dtype(row, name)
        elif val.kind == "int":
            attr.kind, attr.dtype = "int", "int"
        elif val.kind == "bool":
            attr.kind = "bool"
        elif val.kind == "keyword":
            attr.kind, attr.enum = "keyword", self._enum_for(val.keywords, row, name)
        else:
            return self._string_type(row, attr)
        return attr

    def _real_dtype(self, row: ir.ElementDef, name: str) -> ir.DType:
        """``float`` when the row's mjs struct stores the attribute as float."""
        c_type = self.wheel.structs.get(row.struct or "", {}).get(name, "")
        return "float" if c_type in ("float", "mjFloatVec") else "double"

    def _string_type(self, row: ir.ElementDef, attr: ir.AttributeDef) -> ir.AttributeDef | None:
        """Documented as a string: a reference when every same-named attribute is one."""
        others = [a for r in self.rows.values() if r is not row for a in r.attributes
                  if a.name == attr.name and a.kind != "id"]
        spaces = {a.namespace for a in others if a.kind == "ref"}
        if others and len(spaces) == 1 and all(a.kind == "ref" for a in others):
            attr.kind, attr.namespace = "ref", spaces.pop()
            self.report.notes.append(f"{row.name}@{attr.name}: documented as a string, typed "
                                     f"ref<{attr.namespace}> like every other {attr.name}")
        elif any(a.name == attr.name and a.kind == "id"
                 for r in self.rows.values() for a in r.attributes):
            return None  # an identifier: its namespace cannot be guessed
        return attr

    # -- enums

    def _enum_for(self, keywords: tuple[str, ...], row: ir.ElementDef, name: str) -> str:
        """An existing enum with this keyword set, else a new one named after the attribute."""
        same = sorted((e for e in self.schema.enums.values() if set(e.keywords) == set(keywords)),
                      key=lambda e: (e.name != name, e.ctype is None, e.name))
        if same:
            return same[0].name
        enum_name = name if name not in self.schema.enums else f"{row.name}_{name}"
        ctype, values = self._bind(keywords, name)
        self.schema.enums[enum_name] = ir.EnumDef(enum_name, values, ctype)
        self.report.added_enums.append(
            f"{enum_name}{f' ({ctype})' if ctype else ''}: {', '.join(keywords)}")
        return enum_name

    def _bind(self, keywords: tuple[str, ...], name: str,
              ) -> tuple[str | None, list[tuple[str, str]]]:
        """Bind keywords to the C enum whose constants they spell (``none`` ->
        ``mjPASSTHROUGH_NONE``); integer positions when none or several match."""
        found: list[tuple[str, dict[str, str]]] = []
        for ctype, values in sorted(self.wheel.enums.items()):
            consts = [c for c in values if not c.startswith("mjN")]  # mjNXXX: a count
            spelled = {c.split("_", 1)[-1].lower(): c for c in consts}
            if len(spelled) == len(consts) and set(spelled) == {k.lower() for k in keywords}:
                found.append((ctype, {k: spelled[k.lower()] for k in keywords}))
        named = [f for f in found if name.lower() in f[0].lower()]
        chosen = named if len(named) == 1 else found
        if len(chosen) == 1:
            ctype, by_keyword = chosen[0]
            return ctype, [(k, by_keyword[k]) for k in keywords]
        return None, [(k, str(i)) for i, k in enumerate(keywords)]

    def _apply_enum_facts(self) -> None:
        """Every ``[[enum]]`` entry holds after a sync: its enum is added, or its keywords
        replace those the schema has."""
        for fact in self.enum_facts:
            old = self.schema.enums.get(fact.name)
            new = enum_from_fact(fact, old)
            if new == old:
                continue
            self.schema.enums[fact.name] = new
            if old is None:
                self.report.added_enums.append(
                    f"{new.name}{f' ({new.ctype})' if new.ctype else ''}: "
                    f"{', '.join(new.keywords)}  [facts.toml]")
                continue
            changes = [f"+ {k}" for k in new.keywords if k not in old.keywords]
            changes += [f"- {k}" for k in old.keywords if k not in new.keywords]
            if not changes:
                changes = [what for what, changed in (
                    ("keyword order", new.keywords != old.keywords),
                    ("C constants", sorted(new.values) != sorted(old.values)),
                    (f"C type {old.ctype} -> {new.ctype}", new.ctype != old.ctype),
                    ("doc", new.doc != old.doc)) if changed]
            self.report.changed_enums.append(f"{new.name}: {', '.join(changes)}  [facts.toml]")

    def _used_enums(self) -> set[str]:
        return {n for r in self.rows.values() for a in r.attributes for n in enums_of(a)}

    def _check_enums(self) -> None:
        """Every C constant of a bound enum must exist in the wheel; drop those that do not."""
        for enum in sorted(self.schema.enums.values(), key=lambda e: e.name):
            consts = self.wheel.enums.get(enum.ctype or "")
            if enum.ctype is None:
                continue
            if consts is None:
                self.report.notes.append(f"enum {enum.name}: C enum {enum.ctype} not in "
                                         "mujoco.introspect")
                continue
            gone = [(k, v) for k, v in enum.values if v not in consts and not _is_int(v)]
            for keyword, const in gone:
                enum.values.remove((keyword, const))
                self.report.changed_enums.append(
                    f"{enum.name}: - {keyword} ({const} is not in {enum.ctype})")

    def _drop_unused_enums(self) -> None:
        used = self._used_enums()
        for name in sorted(self._enum_users - used):
            if name in self.schema.enums:
                del self.schema.enums[name]
                self.report.removed_enums.append(name)

    # -- types of existing attributes, probed

    def _probe_types(self) -> None:
        """Kinds, keyword sets, counts and defaults the installed parser disagrees with
        (codegen.drift); attributes and enums facts.toml types are left to it."""
        if self.wheel.drift_parser is None:
            self.report.notes.append("attribute types not probed (the wheel has no parser)")
            return
        hand = {key for key, o in self.overrides.items() if o.kind is not None
                or o.enum is not None or o.arity is not None or o.default is not None}
        found = drift.check(self.schema, self.wheel.drift_parser, self.ref, self.wheel.enums,
                            self.wheel.structs, drift.load_sites(), hand,
                            {e.name for e in self.enum_facts})
        for change in found.applied:
            self.report.drifted.append(change.line())
            self.touched.add(change.row)
        for change, fact in found.untypable:
            self.report.drift_errors.append(f"{change.line()}; type it in schema/facts.toml: "
                                            f"{fact}")
        self.report.notes.append(
            f"attribute types probed: {found.probed} attributes ({found.defaults} defaults "
            "in a model MuJoCo saves); rows without a probe model "
            f"that MuJoCo reads (schema/probe.toml): {', '.join(found.rows_skipped) or 'none'}")

    def _probe_spellings(self) -> None:
        """Other spellings each keyword attribute's reader takes (codegen.drift), once every
        type is settled (facts.toml's too: headlight@active is a keyword by hand)."""
        if self.wheel.drift_parser is None:
            return
        found = drift.check_spellings(self.schema, self.wheel.drift_parser, self.wheel.enums,
                                      drift.load_sites())
        for change in found.applied:
            self.report.drifted.append(change.line())
            self.touched.add(change.row)
        self.report.notes.append(f"keyword spellings probed: {found.probed} attributes")

    # -- hand-kept types on existing attributes

    def _apply_overrides(self) -> None:
        """Every ``[[attribute]]`` entry holds after a sync, on its row and on the default
        projections of that row (as when normalizing the grammar, ``required`` stays off
        there); an entry naming no attribute is an error."""
        for (element, name), hand in sorted(self.overrides.items()):
            row = self.rows.get(element)
            if row is None or all(a.name != name for a in row.attributes):
                if self.older:
                    self.report.notes.append(f"{element}@{name}: not in this release; its "
                                             "schema/facts.toml entry is left out")
                    continue
                raise FactsError(f"schema/facts.toml [[attribute]] {element}@{name}: the synced "
                                 "schema has no such attribute; fix or remove the entry")
            self._override(row, hand)
            for projection in sorted(self.rows.values(), key=lambda r: r.name):
                if (projection.projection_of == element and (projection.name, name) not in
                        self.overrides and any(a.name == name for a in projection.attributes)):
                    self._override(projection, dataclasses.replace(
                        hand, element=projection.name, required=None, nodefault=None))

    def _override(self, row: ir.ElementDef, hand: AttributeOverride) -> None:
        index = next(i for i, a in enumerate(row.attributes) if a.name == hand.name)
        attr = row.attributes[index]
        typed = copy.deepcopy(attr)
        apply_override(typed, hand, self.schema)
        if attr.doc.startswith(UNTYPED_DOC) and hand.kind is not None and hand.doc is None:
            typed.doc = ""  # typed by hand now
        if typed == attr:
            return
        if _type_of(attr) != _type_of(typed) or attr.required != typed.required:
            self.report.changed_attributes.append(
                f"{row.name}@{hand.name}: {describe(attr)} -> {describe(typed)}  [facts.toml]")
        row.attributes[index] = typed
        self.touched.add(row.name)

    def _report_committed_untyped(self) -> None:
        """Attributes an earlier sync added as strings stay loud until facts.toml types them."""
        for row in sorted(self.rows.values(), key=lambda r: r.name):
            for attr in row.attributes:
                if attr.doc.startswith(UNTYPED_DOC) and (row.name, attr.name) not in \
                        self.new_untyped:
                    self.report.untyped.append(f"{row.name}@{attr.name}: still a string "
                                               f"({attr.doc.removeprefix(UNTYPED_DOC)})")

    # -- anchors

    def _parents(self, name: str) -> list[str]:
        return [r.name for r in self.rows.values() if any(c.element == name for c in r.children)]

    def _suffixes(self, name: str) -> set[tuple[str, ...]]:
        """Tag paths of up to ``_ANCHOR_DEPTH`` tags that end at row ``name``."""
        cached = self._suffix_cache.get(name)
        if cached is not None:
            return cached
        paths: set[tuple[str, ...]] = set()
        frontier: set[tuple[tuple[str, ...], str]] = {((self.rows[name].tag,), name)}
        while frontier:
            paths |= {p for p, _ in frontier}
            frontier = {((self.rows[parent].tag, *p), parent) for p, n in frontier
                        if len(p) < _ANCHOR_DEPTH for parent in self._parents(n)}
        self._suffix_cache[name] = paths
        return paths

    def _anchor_of(self, row: ir.ElementDef, name: str) -> str | None:
        """The attribute's anchor: documented entries first, then the longest tag path."""
        candidates = [a for a in ("-".join((*s, name)) for s in self._suffixes(row.name))
                      if a in self.ref]
        if not candidates:
            return None
        return min(candidates, key=lambda a: (a not in self.ref.entries, -a.count("-"), a))

    def _element_anchor(self, row: ir.ElementDef) -> str | None:
        candidates = [a for a in ("-".join(s) for s in self._suffixes(row.name))
                      if a in self.ref and a not in self.ref.entries]
        if candidates:
            return min(candidates, key=lambda a: (-a.count("-"), a))
        alias = self.rows.get(row.alias or "")
        return self._element_anchor(alias) if alias is not None else None

    def _set_anchors(self) -> None:
        if not self.ref.anchors:
            return  # a wheel without the reference: keep what the IR has
        self._suffix_cache.clear()
        for row in sorted(self.rows.values(), key=lambda r: r.projection_of is not None):
            self._set(row, self._element_anchor(row))
            primary = self.rows.get(row.projection_of or "")
            for attr in row.attributes:
                source = next((a for a in primary.attributes if a.name == attr.name),
                              None) if primary else None
                self._set(attr, source.anchor if source else self._anchor_of(row, attr.name))

    def _set(self, target: ir.ElementDef | ir.AttributeDef, anchor: str | None) -> None:
        if target.anchor != anchor:
            target.anchor = anchor
            self.report.anchors += 1

    def _set_version(self) -> None:
        if self.schema.mujoco_version != self.wheel.version:
            self.report.version = (self.schema.mujoco_version, self.wheel.version)
            self.schema.mujoco_version = self.wheel.version


# -------------------------------------------------------------------------------- helpers


def _recursive(wrow: WheelRow, child: ir.ElementDef) -> bool:
    """An edge into the row itself: printSchema marks recursion with ``R`` and lists no
    child (``default`` in ``default``, ``body`` in ``(world)body``)."""
    return wrow.card == "R" and child.tag in wrow.spellings


def _shape(wrow: WheelRow) -> tuple[object, ...]:
    """A printSchema row's grammar, ignoring the cardinality of the edge into it."""
    return (wrow.spellings[-1], wrow.attributes,
            tuple((c.card, _shape(c)) for c in wrow.children))


def _is_int(text: str) -> bool:
    return re.fullmatch(r"-?\d+", text) is not None
