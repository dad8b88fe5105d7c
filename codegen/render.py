"""Render ``schema/`` into the ``generated/`` package with jinja2 (StrictUndefined).

Two files per grammar: ``elements.py``, the run-time tables (one class per row, each with
its row as keyword-argument specs, defaults omitted), and ``elements.pyi``, the typing surface
checkers and editors read (attributes, each one declaration typed by the generic descriptor
``_Attr[read, assigned]``; ``add_<tag>()`` with one keyword parameter per attribute,
documented; overloads of ``add``/``insert``/``find``/``resolve``; TypedDicts).
The templates stay thin: every name, type and docstring is computed here by small typed
functions, and the templates only lay them out.
"""

from __future__ import annotations

import dataclasses
import textwrap
from dataclasses import dataclass
from pathlib import Path

import jinja2

from codegen import bindings, docs, ir, language, release_facts, releases, rows
from codegen.naming import RESERVED, py_name
from codegen.typing_names import Alias, Typer

GENERATOR_VERSION = "2"
TEMPLATES = Path(__file__).resolve().parent / "templates"
GENERATED_DIR = Path(__file__).resolve().parent.parent / "generated" / "typed_mjcf_generated"
DOCS_URL = docs.DOCS_URL
# find()'s name for attachment frames (dm_control's; typed_mjcf._base.ATTACHMENT_FRAME).
ATTACHMENT_FRAME = "attachment_frame"


@dataclass(frozen=True)
class PropertyView:
    """An attribute: ``py_name: _Attr[getter | None, setter | None]``, then its docstring."""

    py_name: str
    getter: str
    setter: str
    doc: str


@dataclass(frozen=True)
class ParamView:
    py_name: str
    annotation: str


@dataclass(frozen=True)
class ChildView:
    tag: str
    py_name: str
    class_name: str
    single: bool
    params: list[ParamView]
    doc: str


@dataclass(frozen=True)
class ResolveView:
    names: str  # the Literal's arguments: '"pos", "quat"'
    type: str


@dataclass(frozen=True)
class ClassView:
    class_name: str
    bases: str  # at run time
    stub_bases: str  # for checkers
    short_doc: str
    doc: str
    table: str
    properties: list[PropertyView]
    children: list[ChildView]
    params: list[ParamView]
    resolves: list[ResolveView]
    is_root: bool
    init_params: list[ParamView]  # the root's keyword arguments besides its name
    child_tags: str  # the Literal's arguments: '"body", "geom"'
    misused_child: str  # add()'s deprecation messages, as Python string literals
    not_a_child: str


@dataclass(frozen=True)
class NamespaceView:
    name: str
    type: str


def child_py_name(tag: str) -> str:
    """The Python name of a child list or property: a runtime method's name gets a trailing
    underscore (``body.attach_`` is the list of ``<attach>`` children), like ``class_``."""
    name = py_name(tag)
    return name + "_" if name in RESERVED else name


# ---------------------------------------------------------------------------- run-time tables


def _attribute_spec(schema: ir.Schema, typer: Typer, el: ir.ElementDef,
                    a: ir.AttributeDef, notes: releases.Notes) -> str:
    """``A(...)``: the attribute's row (``typed_mjcf._core.rows.AttributeRow``), keywords and
    their maps named by the module's aliases."""
    values: dict[str, object] = {**rows.release_values(schema, a), "name": a.name,
                                 "py_name": a.py_name if a.py_name != a.name else ""}
    if a.enum is not None:
        values["keywords"] = rows.Source(f"get_args({typer.keyword_type(a)})")
    alone = typer.alone_type(a)
    if alone is not None:
        values["alone"] = rows.Source(f"get_args({alone})")
    values["ordered"] = a.ordered
    if a.namespace_from is not None:
        values["namespace_from"] = rows.Source(
            f"({a.namespace_from!r}, {typed_map_name(typer, a)})")
    values["required"] = a.required
    values["computed"] = a.computed is not None
    values["pattern"] = a.pattern
    values["bounds"] = _bounds(a.bounds)
    values["off"] = _bounds(a.off)
    values["directory"] = tuple(a.directory or ())
    expected_anchor = f"{el.anchor}-{a.name}" if el.anchor else None
    if a.anchor != expected_anchor:
        values["anchor"] = a.anchor
    values["doc"] = docs.attribute_doc(typer, a, notes.get(el.name, {}).get(a.name))
    values["scope"] = el.name == schema.root and a.name == schema.facts().model_name
    return rows.call("A", rows.ROW, values)


def _bounds(texts: list[str] | None) -> tuple[tuple[str, float], ...]:
    """``["> 0"]`` as the row holds it: ``((">", 0.0),)``."""
    return tuple((op, float(limit)) for op, limit in map(str.split, texts or ()))


def typed_map_name(typer: Typer, a: ir.AttributeDef) -> str:
    """The module constant holding a typed reference's keyword -> namespace map."""
    namespaces = typer.typed_reference_map(a)
    return "_NAMESPACES_" + "_".join(sorted(set(namespaces))).upper()


def _element_spec(schema: ir.Schema, typer: Typer, el: ir.ElementDef,
                  notes: releases.Notes) -> str:
    lines = [f"{el.tag!r},"]
    if el.name != el.tag:
        lines.append(f"{el.name!r},")
    if el.attributes:
        lines.append("attributes=(")
        lines += [f"    {_attribute_spec(schema, typer, el, a, notes)}," for a in el.attributes]
        lines.append("),")
    if el.children:
        lines.append("children=(")
        for c in el.children:
            child = schema.elements[c.element]
            args = [repr(child.tag), repr(child.class_name)]
            if c.single:
                args.append("single=True")
            if c.card != "*":
                args.append(f"card={c.card!r}")
            name = child_py_name(child.tag)
            if name != child.tag:
                args.append(f"py_name={name!r}")
            lines.append(f"    C({', '.join(args)}),")
        lines.append("),")
    constraints = tuple((k.kind, tuple(tuple(b) for b in k.bundles)) for k in el.constraints)
    if constraints:
        lines.append(f"constraints={constraints!r},")
    if el.anchor is not None:
        lines.append(f"anchor={el.anchor!r},")
    if el.doc:
        lines.append(f"doc={el.doc!r},")
    if el.compose is not None:
        lines.append(f"compose={el.compose!r},")
    if el.attachable:
        lines.append("attachable=True,")
    if el.ignores_unknown:
        lines.append("ignores_unknown=True,")
    if el.default_row is not None:
        lines.append(f"defaults={schema.elements[el.default_row].tag!r},")
    return textwrap.indent("\n".join(lines), " " * 8)


def _facts(schema: ir.Schema) -> str:
    """The keyword arguments of the generated ``GrammarFacts(...)``, one per line."""
    facts = dataclasses.replace(schema.facts(), root=schema.root)
    return "\n".join(f"    {f.name}={language.source(getattr(facts, f.name))},"
                     for f in dataclasses.fields(facts))


# ---------------------------------------------------------------------------- typing surface


def _class_doc(el: ir.ElementDef) -> str:
    head = f"``<{el.tag}>``"
    if el.projection_of is not None:
        head += f" in a ``<default>`` class: the defaults of ``<{el.tag}>`` elements"
    elif el.doc:
        head += f": {el.doc}"
    parts = [head + "."]
    if el.anchor is not None:
        parts.append(f"Reference: {DOCS_URL}#{el.anchor}")
    return textwrap.indent(docs.escape("\n\n".join(parts)) + "\n", " " * 4).strip() + "\n    "


def _resolve_type(typer: Typer, a: ir.AttributeDef) -> str:
    """What ``resolve(name)`` returns: never None where the grammar has a default."""
    getter = typer.getter(a)
    return getter if a.default is not None else f"{getter} | None"


def _resolves(typer: Typer, el: ir.ElementDef) -> list[ResolveView]:
    """``resolve()``'s overloads: one per return type (an overload carries a type), naming
    every attribute that resolves to it, in the order the types first appear."""
    names: dict[str, list[str]] = {}
    for a in el.attributes:
        names.setdefault(_resolve_type(typer, a), []).append(f'"{a.py_name}"')
    return [ResolveView(", ".join(group), type_) for type_, group in names.items()]


def class_view(schema: ir.Schema, typer: Typer, el: ir.ElementDef,
               notes: releases.Notes | None = None) -> ClassView:
    notes = {} if notes is None else notes  # row -> attribute -> the releases that have it
    mine = notes.get(el.name, {})
    properties = [PropertyView(a.py_name, typer.getter(a), typer.setter(a),
                               docs.property_doc(typer, el, a, mine.get(a.name)))
                  for a in el.attributes]
    params = [ParamView(a.py_name, typer.setter(a)) for a in el.attributes]
    if any(a.name == schema.facts().dclass for a in el.attributes):
        dclass = next(a for a in el.attributes if a.name == schema.facts().dclass)
        properties.append(PropertyView("dclass", typer.getter(dclass), typer.setter(dclass),
                                       "dm_control's name for ``class_``."))
        params.append(ParamView("dclass", typer.setter(dclass)))
    children: list[ChildView] = []
    for c in el.children:
        child = schema.elements[c.element]
        child_params = [ParamView(a.py_name, typer.setter(a)) for a in child.attributes]
        child_params += [ParamView("dclass", typer.setter(a)) for a in child.attributes
                         if a.name == schema.facts().dclass]  # dm_control's name
        entries = docs.adder_entries(typer, child, schema.facts().dclass,
                                     notes.get(child.name))
        children.append(ChildView(child.tag, child_py_name(child.tag), child.class_name,
                                  c.single, child_params, docs.adder_doc(typer, child, entries)))
    is_root = el.name == schema.root
    bases = "ModelRoot" if is_root else "Element"
    # the root's pictures take its Camera and Key (ModelRoot's type parameters)
    stub_bases = "_Typed, _ModelRoot[Camera, Key]" if is_root else "_Typed"
    if el.attachable:
        bases += ", Attachable"
        stub_bases += ", _Attach"
    resolves = _resolves(typer, el)
    child_tags = sorted({schema.elements[c.element].tag for c in el.children})
    return ClassView(
        class_name=el.class_name, bases=bases, stub_bases=stub_bases,
        short_doc=docs.escape(f"``<{el.tag}>``."), doc=_class_doc(el),
        table=_element_spec(schema, typer, el, notes), properties=properties, children=children,
        params=params, resolves=resolves, is_root=is_root,
        init_params=[p for p in params if p.py_name != schema.facts().model_name],
        child_tags=", ".join(f'"{tag}"' for tag in child_tags),
        misused_child=_python_string(misused_child(el.tag)),
        not_a_child=_python_string(not_a_child(el.tag)))


# add()/insert() with a literal tag: a call that fails the tag's own overload (a keyword the
# child lacks, a value of the wrong type) or names a tag that is no child would otherwise match
# the `str` overload, which must stay for tags known only at run time. A deprecated overload
# between the two takes those literal tags instead: the one standard way (PEP 702) to make a
# checker report a call that some overload accepts (pyright strict: reportDeprecated; mypy:
# the `deprecated` error code). The messages say what is wrong, since "deprecated" does not.


def misused_child(tag: str) -> str:
    return (f"wrong keywords: add()/insert() with the tag of a child of <{tag}> take that "
            f"child's attributes, as its add_<tag>() does; a keyword is not one of them or "
            f"its value has the wrong type")


def not_a_child(tag: str) -> str:
    return f"wrong tag: the grammar allows no such child under <{tag}> (see its add_<tag>())"


def _python_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _tuple_repr(values: list[str]) -> str:
    """A tuple of strings as Python writes it, double-quoted (the project's style)."""
    inner = ", ".join(f'"{v}"' for v in values)
    return f"({inner},)" if len(values) == 1 else f"({inner})"


def _environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(TEMPLATES),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )
    env.filters["tuple_repr"] = _tuple_repr
    return env


def _ordered(schema: ir.Schema) -> list[ir.ElementDef]:
    """Root first, then by class name: a stable order that reads like a reference."""
    rest = sorted((e for e in schema.elements.values() if e.name != schema.root),
                  key=lambda e: e.class_name)
    return [schema.elements[schema.root], *rest]


def _typed_maps(schema: ir.Schema, typer: Typer) -> list[Alias]:
    maps: dict[str, str] = {}
    for el in schema.elements.values():
        for a in el.attributes:
            if a.namespace_from is not None:
                maps[typed_map_name(typer, a)] = repr(typer.typed_reference_map(a))
    return [Alias(name, value, "") for name, value in sorted(maps.items())]


def render(schema: ir.Schema, binding_table: dict[str, object] | None = None,
           older: dict[str, ir.Schema] | None = None) -> dict[str, str]:
    """The generated package: file name -> text (the bindings from ``schema/bindings.json``
    unless ``binding_table`` is given; the older releases from ``schema/releases/`` unless
    ``older`` is given)."""
    typer = Typer(schema)
    env = _environment()
    gates = releases.gates(schema, releases.load_releases() if older is None else older)
    notes = releases.notes(gates)
    classes = [class_view(schema, typer, el, notes) for el in _ordered(schema)]
    keyword_sets = typer.keyword_aliases()
    aliases = [*typer.array_aliases(), *typer.namespace_aliases(), *typer.target_aliases()]
    namespaces = [NamespaceView(ns, typer.namespace_type(ns)) for ns in typer.namespaces()]
    body = schema.elements.get(schema.facts().body)
    if body is not None:  # frames are bodies
        namespaces.append(NamespaceView(ATTACHMENT_FRAME, body.class_name))
    class_names = sorted(c.class_name for c in classes)
    context: dict[str, object] = {
        "mujoco_version": schema.mujoco_version,
        "generator_version": GENERATOR_VERSION,
        "classes": classes,
        "class_names": class_names,
        "keyword_sets": keyword_sets,
        "typed_maps": _typed_maps(schema, typer),
        "facts": _facts(schema),
        "fact_classes": ", ".join(language.classes()),
        "aliases": aliases,
        "exported": sorted([*class_names, *(a.name for a in [*keyword_sets, *aliases]),
                            "Namespace",
                            *(f"{c.class_name}Attributes" for c in classes)]),
        "namespaces": namespaces,
        "frame_tag": schema.facts().body,
        "frame_class": body.class_name if body is not None else "_Element",
        "namespace_literals": ", ".join(f'"{ns.name}"' for ns in namespaces),
        "tag_literals": ", ".join(f'"{tag}"' for tag in sorted(
            {el.tag for el in schema.elements.values()})),
    }
    table = bindings.load() if binding_table is None else binding_table
    binding_context = {**bindings.render_context(schema, table),
                       "generator_version": GENERATOR_VERSION}
    return {
        "bindings.py": env.get_template("bindings.py.jinja2").render(binding_context),
        "bindings.pyi": env.get_template("bindings.pyi.jinja2").render(binding_context),
        "elements.py": env.get_template("elements.py.jinja2").render(context),
        "elements.pyi": env.get_template("elements.pyi.jinja2").render(context),
        "__init__.py": env.get_template("__init__.py.jinja2").render(context),
        "releases.py": releases.render_table(gates, schema.mujoco_version),
        "release_facts.py": release_facts.render_table(
            release_facts.checked(release_facts.load(), schema.mujoco_version)),
    }


def write(files: dict[str, str], directory: Path = GENERATED_DIR) -> list[str]:
    """Write the rendered files; return the names that changed."""
    directory.mkdir(parents=True, exist_ok=True)
    changed: list[str] = []
    for name, text in sorted(files.items()):
        path = directory / name
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            changed.append(name)
    for stale in sorted([*directory.glob("*.py"), *directory.glob("*.pyi")]):
        if stale.name not in files:
            stale.unlink()
            changed.append(stale.name)
    py_typed = directory / "py.typed"
    if py_typed.exists():
        py_typed.unlink()  # the package is part of typed_mjcf, which is marked typed
        changed.append("py.typed")
    return changed
