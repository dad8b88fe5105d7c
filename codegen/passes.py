"""Normalisation passes from the grammar's IR to the IR the renderer reads.

Each pass is a small function that edits a schema in place. ``normalize`` runs them, in
order, on a copy of its input and ends with consistency checks, so the renderer can trust
every row, child and name it is given.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from collections.abc import Iterable, Mapping

from codegen import ir, naming
from codegen.errors import FactsError
from codegen.facts import AttributeOverride, ConstraintFact, EnumFact, Facts

DEFAULT_ROW = "default"  # the <default> class row; its children are per-tag settings
PROJECTION_PREFIX = "default_"  # rows valid only inside <default>
_NOT_DEFAULTABLE = frozenset({"name", "class"})  # identity, never inherited from a class


def normalize(schema: ir.Schema, facts: Facts) -> ir.Schema:
    """The renderer's IR: ``schema`` (left untouched) with ``facts`` applied and checked."""
    out = copy.deepcopy(schema)
    route_root_children(out, facts.root_children)
    apply_enum_facts(out, facts.enums)
    # Overrides on declared rows go first so default projections inherit them; an entry may
    # also name a projection row, which only exists afterwards, or an attribute the wheel
    # adds, which sync types (and where an entry that names nothing is an error).
    declared = set(out.elements)
    apply_overrides(out, overrides_on(out, facts.attributes))
    add_constraints(out, facts.constraints)
    project_defaults(out)
    apply_overrides(out, [o for o in overrides_on(out, facts.attributes)
                          if o.element not in declared])
    mark_single(out, facts.single)
    drop_unreachable(out)
    finish(out, facts)
    drop_unused_enums(out)
    check(out)
    return out


# ------------------------------------------------------------------------------ passes


def route_root_children(schema: ir.Schema, routes: Mapping[str, str]) -> None:
    """Point the root's child ``source`` at row ``target`` (``body`` -> ``worldbody``)."""
    root = schema.elements[schema.root]
    for source, target in routes.items():
        if target not in schema.elements:
            raise _mistake(f"[root_children] {source}", f"no row {target!r}")
        index = next((i for i, c in enumerate(root.children) if c.element == source), None)
        if index is None:
            if any(c.element == target for c in root.children):
                continue  # already routed: normalizing twice is harmless
            raise _mistake(f"[root_children] {source}", f"the root {root.name!r} has no child {source!r}")
        old = root.children[index]
        root.children[index] = ir.ChildDef(target, old.card, old.single)


def apply_enum_facts(schema: ir.Schema, enums: Iterable[EnumFact]) -> None:
    """Hand-kept keyword sets (``[[enum]]``): added, or replacing the sources' keywords."""
    for fact in enums:
        schema.enums[fact.name] = enum_from_fact(fact, schema.enums.get(fact.name))


def enum_from_fact(fact: EnumFact, old: ir.EnumDef | None) -> ir.EnumDef:
    """The enum an ``[[enum]]`` entry makes of ``old`` (None: a new enum)."""
    ctype = fact.ctype if fact.ctype is not None else old.ctype if old else None
    doc = fact.doc if fact.doc is not None else old.doc if old else ""
    return ir.EnumDef(fact.name, list(fact.values), ctype, doc)


def mark_single(schema: ir.Schema, single: Mapping[str, Iterable[str]]) -> None:
    """Expose the named children (by tag) of each parent row as properties."""
    for parent, tags in single.items():
        row = _row(schema, parent, "single")
        by_tag = {schema.elements[c.element].tag: c for c in row.children}
        for tag in tags:
            child = by_tag.get(tag)
            if child is None:
                raise _mistake(f"[single] {parent}", f"row {parent!r} has no child tag {tag!r}")
            child.single = True


def add_constraints(schema: ir.Schema, facts: Iterable[ConstraintFact]) -> None:
    """Add each ``[[constraint]]`` to its row (once: normalizing twice is harmless)."""
    for fact in facts:
        row = schema.elements.get(fact.element)
        if row is None:
            raise _mistake(f"[[constraint]] {fact.element}", f"no row {fact.element!r}")
        names = {a.name for a in row.attributes}
        unknown = [n for b in fact.bundles for n in b if n not in names]
        if unknown:
            raise _mistake(f"[[constraint]] {fact.element}", f"row {fact.element!r} has no attribute {unknown[0]!r}")
        constraint = ir.ConstraintDef(fact.kind, [list(b) for b in fact.bundles])
        if constraint not in row.constraints:
            row.constraints.append(constraint)


def overrides_on(schema: ir.Schema, overrides: Iterable[AttributeOverride],
                 ) -> list[AttributeOverride]:
    """The ``overrides`` naming an attribute ``schema`` has."""
    return [o for o in overrides if o.element in schema.elements
            and any(a.name == o.name for a in schema.elements[o.element].attributes)]


def apply_overrides(schema: ir.Schema, overrides: Iterable[AttributeOverride]) -> None:
    """Hand-kept corrections of single attributes (e.g. ``mujoco@model`` is a string)."""
    for override in overrides:
        where = f"[[attribute]] {override.element}@{override.name}"
        row = _row(schema, override.element, where)
        try:
            attr = row.attribute(override.name)
        except KeyError:
            raise _mistake(where, f"row {row.name!r} has no such attribute") from None
        apply_override(attr, override, schema)


def apply_override(attr: ir.AttributeDef, override: AttributeOverride,
                   schema: ir.Schema) -> None:
    """Set the fields ``override`` gives on ``attr``; raise if they contradict its kind."""
    _apply_override(attr, override)
    problem = _attribute_problem(attr, schema)
    if problem:
        raise _mistake(f"[[attribute]] {override.element}@{override.name}", problem)


def project_defaults(schema: ir.Schema) -> None:
    """Give each per-tag child of the default row its own ``default_<decl>`` row."""
    default = schema.elements.get(DEFAULT_ROW)
    if default is None:
        return
    for index, child in enumerate(default.children):
        if child.element == DEFAULT_ROW:  # nested classes: a list, like any recursion
            child.single = False
            continue
        element = child.element
        if not element.startswith(PROJECTION_PREFIX):
            element = _add_projection(schema, element)
        default.children[index] = ir.ChildDef(element, child.card, single=True)


def finish(schema: ir.Schema, facts: Facts) -> None:
    """The fact-derived fields, applied after normalizing and again after a sync (which may
    have added rows)."""
    apply_directories(schema, facts.directories)
    add_constraints(schema, facts.constraints)  # (also on a sync: an entry added since)
    _check_rows(schema, facts)
    rename_classes(schema, facts.class_names)
    mark_default_rows(schema, facts.default_rows)
    mark_composition(schema, facts.compose, facts.attachment_sites)
    language = facts.language
    schema.language = None if language is None else dataclasses.replace(language,
                                                                         root=schema.root)
    schema.stale_language = ""
    if language is not None:
        for name in language.joints:  # rows, not tags (<equality><joint> is no joint)
            _row(schema, name, f"[language] joints {name}")
        mark_typed_references(schema, language.typed_references)


def _check_rows(schema: ir.Schema, facts: Facts) -> None:
    """The rows and sections the keyed tables name exist (a sync reads them too)."""
    for parent in facts.single:  # (children a release lacks are left alone)
        _row(schema, parent, f"[single] {parent}")
    for site in facts.attachment_sites:
        _row(schema, site, f"[attachment_sites] {site}")
    sections = {schema.elements[c.element].tag for c in schema.elements[schema.root].children}
    for tag in facts.compose:
        if tag not in sections:
            raise _mistake(f"[compose] {tag}", f"no root section {tag!r}")


def mark_typed_references(schema: ir.Schema, table: Mapping[str, str]) -> None:
    """References whose namespace another attribute's keyword names (a sensor's objname,
    by its objtype): on every row that has both attributes."""
    for row in schema.elements.values():
        names = {a.name for a in row.attributes}
        for attribute in row.attributes:
            type_attribute = table.get(attribute.name)
            if type_attribute is not None and type_attribute in names:
                attribute.namespace_from = type_attribute


def mark_default_rows(schema: ir.Schema, table: Mapping[str, Iterable[str]]) -> None:
    """Point each element row at the <default> child row holding its defaults."""
    for row in schema.elements.values():
        if row.projection_of is not None and row.projection_of in schema.elements:
            schema.elements[row.projection_of].default_row = row.name
    for default_row, elements in table.items():
        _row(schema, default_row, f"[default_rows] {default_row}")
        for name in elements:
            if name in schema.elements:  # a listed row the installed wheel lacks: nothing to mark
                schema.elements[name].default_row = default_row


def mark_composition(schema: ir.Schema, compose: Mapping[str, str],
                     sites: Iterable[str]) -> None:
    """Which rows can host an attached model, and how top-level sections compose.

    A model attaches to the root (its worldbody), to a row that holds bodies, or to an
    attachment site (dm_control's semantics: the frame goes beside it, at its pose).
    """
    root = schema.elements[schema.root]
    for child in root.children:
        row = schema.elements[child.element]
        row.compose = compose.get(row.tag, row.compose)
    site_rows = set(sites)
    for element in schema.elements.values():
        holds_bodies = element.projection_of is None and any(
            c.element == "body" for c in element.children)
        element.attachable = (holds_bodies or element.name == schema.root
                              or element.name in site_rows)


def rename_classes(schema: ir.Schema, names: Mapping[str, str]) -> None:
    """Python class names that the declaration name would give to a runtime name."""
    for row_name, class_name in names.items():
        _row(schema, row_name, f"[class_names] {row_name}").class_name = class_name


def apply_directories(schema: ir.Schema,
                      directories: Mapping[tuple[str, str], list[str]]) -> None:
    """Tell file attributes which <compiler> attributes name their folder."""
    for (row_name, attribute_name), folders in directories.items():
        key = f"[directories] {row_name}@{attribute_name}"
        attribute = _row(schema, row_name, key).attribute(attribute_name)
        if attribute.kind != "file":
            raise _mistake(key, "not a file attribute")
        attribute.directory = list(folders)


def drop_unreachable(schema: ir.Schema) -> None:
    """Rows no chain of children leads to from the root are not part of the language."""
    reachable: set[str] = set()
    pending = [schema.root]
    while pending:
        name = pending.pop()
        if name not in reachable:
            reachable.add(name)
            pending.extend(c.element for c in schema.elements[name].children)
    schema.elements = {k: v for k, v in schema.elements.items() if k in reachable}


def drop_unused_enums(schema: ir.Schema) -> None:
    used = {n for e in schema.elements.values() for a in e.attributes for n in enums_of(a)}
    schema.enums = {k: v for k, v in schema.enums.items() if k in used}


def enums_of(attr: ir.AttributeDef) -> list[str]:
    """The enums an attribute uses: its own and those whose keywords it takes alone."""
    return ([attr.enum] if attr.enum else []) + list(attr.alone or [])


def check(schema: ir.Schema) -> None:
    """Raise ValueError listing every name clash or dangling reference."""
    facts = _naming_fact_problems(schema)
    if facts:
        more = f" (and {len(facts) - 1} more)" if len(facts) > 1 else ""
        raise _mistake("[language]", facts[0].removeprefix("language ") + more)
    problems = [
        *_reference_problems(schema),
        *_class_name_problems(schema),
        *_flags_problems(schema),
        *(p for e in schema.elements.values() for p in _element_problems(schema, e)),
    ]
    if problems:
        raise ValueError(f"{len(problems)} schema problem(s):\n  " + "\n  ".join(problems))


# ----------------------------------------------------------------------------- helpers


def _row(schema: ir.Schema, name: str, where: str) -> ir.ElementDef:
    """The row ``name`` that the facts entry ``where`` names."""
    row = schema.elements.get(name)
    if row is None:
        raise _mistake(where, f"no row {name!r}")
    return row


def _mistake(where: str, problem: str) -> FactsError:
    """A facts.toml entry that does not fit the schema, in one line."""
    return FactsError(f"schema/facts.toml {where}: {problem}")


_OVERRIDABLE = ("dtype", "arity", "enum", "ordered", "namespace", "default", "required",
                "nodefault", "pattern", "field", "doc")


def _apply_override(attr: ir.AttributeDef, o: AttributeOverride) -> None:
    if o.kind is not None and o.kind != attr.kind:
        attr.kind = o.kind
        _drop_fields_of_other_kinds(attr)
    for name in _OVERRIDABLE:  # None in an override means "unchanged"
        value: object = getattr(o, name)
        if value is not None:
            setattr(attr, name, value)
    if o.alone is not None:
        attr.alone = list(o.alone)
    if o.bounds is not None:
        attr.bounds = list(o.bounds)
    if o.off is not None:
        attr.off = list(o.off)


def _drop_fields_of_other_kinds(attr: ir.AttributeDef) -> None:
    """After a kind change, forget what only the old kind had (a ref's namespace, ...)."""
    if attr.kind not in ("int", "real"):
        attr.dtype = None
    elif attr.kind == "int":
        attr.dtype = "int"
    if attr.kind not in ("int", "real", "chars", "string"):
        attr.arity = None
    if attr.kind not in ("keyword", "flags"):
        attr.enum = None
    if attr.kind != "flags":
        attr.alone, attr.ordered = None, False
    if attr.kind not in ("id", "ref"):
        attr.namespace = None
    if attr.kind not in ("string", "chars"):
        attr.pattern = None
    if attr.kind not in ("int", "real"):
        attr.bounds = attr.off = None


def _attribute_problem(attr: ir.AttributeDef, schema: ir.Schema) -> str | None:
    """Why ``attr``'s fields contradict its kind, or None."""
    if attr.kind == "int" and attr.dtype != "int":
        return "an int attribute has dtype 'int'"
    if attr.kind == "real" and attr.dtype not in ("double", "float"):
        return "a real attribute needs dtype 'double' or 'float'"
    if attr.kind in ("keyword", "flags") and attr.enum not in schema.enums:
        return f"{attr.kind} attribute needs a declared enum, got {attr.enum!r}"
    if (attr.bounds or attr.off) and attr.kind not in ("int", "real"):
        return f"only numbers take bounds and off values, not a {attr.kind} attribute"
    if attr.kind != "flags" and (attr.alone or attr.ordered):
        return f"only flags take keywords alone or in order, not a {attr.kind} attribute"
    if attr.alone:
        return _alone_problem(attr, schema)
    if attr.kind in ("id", "ref") and not attr.namespace:
        return f"{attr.kind} attribute needs a namespace"
    if attr.kind == "chars" and (attr.arity is None or attr.arity[1] is None):
        return "chars attribute needs a bounded arity"
    return None


def _alone_problem(attr: ir.AttributeDef, schema: ir.Schema) -> str | None:
    """Keywords taken alone come from declared enums, and each spells one thing only."""
    missing = [n for n in attr.alone or [] if n not in schema.enums]
    if missing:
        return f"alone names undeclared enum {missing[0]!r}"
    seen: dict[str, str] = {}
    for name in enums_of(attr):
        for keyword in schema.enums[name].keywords:
            if keyword in seen:
                return (f"keyword {keyword!r} of enum {name!r} is also one of enum "
                        f"{seen[keyword]!r}: a value would be ambiguous")
            seen[keyword] = name
    return None


def _add_projection(schema: ir.Schema, primary_name: str) -> str:
    """Add the default-class row of a primary declaration; return its name."""
    primary = schema.elements[primary_name]
    name = PROJECTION_PREFIX + primary_name
    if name in schema.elements:
        raise ValueError(f"default projection of {primary_name!r} collides with declared row "
                         f"{name!r}")
    attributes = [copy.deepcopy(a) for a in primary.attributes
                  if a.name not in _NOT_DEFAULTABLE and not a.nodefault]
    for attr in attributes:
        attr.required = False  # a class only supplies values; the element must still set them
    schema.elements[name] = ir.ElementDef(
        name=name, tag=primary.tag, class_name="Default" + primary.class_name,
        attributes=attributes, struct=primary.struct, projection_of=primary_name,
    )
    return name


_PLACEHOLDERS = re.compile(r"\{(\w*)\}")


def _template_problems(where: str, template: str, allowed: set[str]) -> list[str]:
    fields = _PLACEHOLDERS.findall(template)
    problems = [f"{where}: unknown placeholder {{{f}}} (known: {', '.join(sorted(allowed))})"
                for f in fields if f not in allowed]
    if not template.startswith("{name}"):
        problems.append(f"{where}: a generated name starts with {{name}}")
    return problems


def _naming_fact_problems(schema: ir.Schema) -> list[str]:
    """The facts naming what MuJoCo's compiler makes must name rows, attributes and keywords
    of the grammar: a MuJoCo release that renames one shows up here, not as wrong names."""
    language = schema.language
    if language is None:
        return []
    rows: dict[str, list[ir.ElementDef]] = {}
    for row in schema.elements.values():
        rows.setdefault(row.tag, []).append(row)
    problems: list[str] = []

    def attribute(tag: str, name: str, kind: str) -> ir.AttributeDef | None:
        """The attribute of that name and kind of a row of that tag (tags repeat: <flex> in
        <deformable> and in <equality>)."""
        found = next((a for row in rows.get(tag, []) for a in row.attributes
                      if a.name == name and a.kind == kind), None)
        if found is None:
            problems.append(f"language facts: <{tag}> has no {kind} attribute {name!r}")
        return found

    if language.replicate in rows:  # (small test grammars have none)
        attribute(language.replicate, language.replicate_count, "int")
        attribute(language.replicate, language.replicate_separator, "string")
    problems += _template_problems("language replicate_copy", language.replicate_copy,
                                   {"name", "sep", "index"})
    attach = language.attach
    if attach is not None and attach.tag in rows:
        for name in (attach.model, attach.prefix, *attach.references):
            if not any(a.name == name for row in rows[attach.tag] for a in row.attributes):
                problems.append(f"language attach: <{attach.tag}> has no attribute {name!r}")
    problems += [f"language merge_rules {key}: expected a key \"tag@attribute\""
                 for key in language.merge_rules if "@" not in key]
    for key in language.name_lists:
        tag, _, name = key.partition("@")
        if tag in rows:
            attribute(tag, name, "string")
    sections = {c.element for c in schema.elements[schema.root].children}
    problems += [f"language copied_with_replicate: no root section {section!r}"
                 for section in language.copied_with_replicate if section not in sections]
    flexcomp = language.flexcomp
    if flexcomp is not None and flexcomp.tag in rows:
        dof = attribute(flexcomp.tag, flexcomp.dof, "keyword")
        attribute(flexcomp.tag, flexcomp.rigid, "bool")
        if dof is not None and dof.enum in schema.enums:
            keywords = {k for k, _ in schema.enums[dof.enum].values}
            problems += [f"language flexcomp nodes: {k!r} is no keyword of <{flexcomp.tag}> "
                         f"{flexcomp.dof}" for k in flexcomp.nodes if k not in keywords]
        problems += [f"language flexcomp nodes {k}: expected a positive integer, got {n}"
                     for k, n in flexcomp.nodes.items() if n < 1]
        problems += _template_problems("language flexcomp vertex_body", flexcomp.vertex_body,
                                       {"name", "vertex"})
        problems += _template_problems("language flexcomp node_body", flexcomp.node_body,
                                       {"name", "i", "j", "k"})
    return problems


def _reference_problems(schema: ir.Schema) -> list[str]:
    problems: list[str] = []
    for e in schema.elements.values():
        targets: list[tuple[str, str | None]] = [("child", c.element) for c in e.children]
        targets += [("alias", e.alias), ("projection_of", e.projection_of)]
        problems += [f"row {e.name!r}: {what} names missing row {target!r}"
                     for what, target in targets
                     if target is not None and target not in schema.elements]
        problems += [f"row {e.name!r}: attribute {a.name!r} uses missing enum {name!r}"
                     for a in e.attributes for name in enums_of(a)
                     if name not in schema.enums]
    return problems


def _flags_problems(schema: ir.Schema) -> list[str]:
    """Keywords taken alone or in order: on flags only, from declared, disjoint enums."""
    problems: list[str] = []
    for e in schema.elements.values():
        for a in e.attributes:
            declared = all(n in schema.enums for n in enums_of(a))  # else: a missing enum
            problem = _attribute_problem(a, schema) if (a.alone or a.ordered) and declared \
                else None
            if problem is not None:
                problems.append(f"row {e.name!r}: attribute {a.name!r}: {problem}")
    return problems


def _class_name_problems(schema: ir.Schema) -> list[str]:
    owners: dict[str, list[str]] = {}
    for e in schema.elements.values():
        owners.setdefault(e.class_name, []).append(e.name)
    return [f"class name {cls!r} is shared by rows {', '.join(map(repr, names))}"
            for cls, names in owners.items() if len(names) > 1]


def _element_problems(schema: ir.Schema, element: ir.ElementDef) -> list[str]:
    """Clashes among one row's Python names: child tags, attributes, the runtime API."""
    where = f"row {element.name!r}"
    problems: list[str] = []
    tags: dict[str, str] = {}
    for child in element.children:
        row = schema.elements.get(child.element)
        if row is None:
            continue  # reported by _reference_problems
        if row.tag in tags:
            problems.append(f"{where}: children {tags[row.tag]!r} and {row.name!r} share tag "
                            f"{row.tag!r}")
        tags.setdefault(row.tag, row.name)
    child_names = {naming.py_name(tag): tag for tag in tags}
    for attr in element.attributes:
        if attr.py_name in child_names:
            problems.append(f"{where}: attribute {attr.name!r} and child tag "
                            f"{child_names[attr.py_name]!r} share the Python name "
                            f"{attr.py_name!r}")
    for attr in element.attributes:  # child tags that clash take a trailing underscore
        if attr.py_name in naming.RESERVED:
            problems.append(f"{where}: attribute name {attr.py_name!r} is reserved by the "
                            f"runtime API")
    return problems
