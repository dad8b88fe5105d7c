"""Render ``schema/`` into the ``generated/`` package with jinja2 (StrictUndefined).

The templates stay thin: every name, type and docstring is computed here by small typed
functions, and the templates only lay them out.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from pathlib import Path

import jinja2

from codegen import ir
from codegen.naming import py_name
from codegen.typing_names import Typer

GENERATOR_VERSION = "1"
TEMPLATES = Path(__file__).resolve().parent / "templates"
GENERATED_DIR = Path(__file__).resolve().parent.parent / "generated" / "typed_mjcf_generated"
DOCS_URL = "https://mujoco.readthedocs.io/en/stable/XMLreference.html"


@dataclass(frozen=True)
class PropertyView:
    py_name: str
    getter: str
    setter: str
    doc: str


@dataclass(frozen=True)
class ChildView:
    tag: str
    py_name: str
    class_name: str
    single: bool


@dataclass(frozen=True)
class ParamView:
    py_name: str
    annotation: str


@dataclass(frozen=True)
class ClassView:
    class_name: str
    base: str
    doc: str
    spec: str
    properties: list[PropertyView]
    children: list[ChildView]
    params: list[ParamView]
    is_root: bool
    attachable: bool
    attach_alias: bool  # also ``attach()``, dm_control's name, where no <attach> child takes it


@dataclass(frozen=True)
class NamespaceView:
    name: str
    classes: str


def _quote(text: str | None) -> str:
    return "None" if text is None else repr(text)


def _attribute_spec(schema: ir.Schema, a: ir.AttributeDef) -> str:
    args = [repr(a.name), repr(a.py_name), repr(a.kind)]
    if a.dtype is not None:
        args.append(f"dtype={a.dtype!r}")
    if a.arity is not None:
        args.append(f"arity={a.arity!r}")
    if a.enum is not None:
        args.append(f"keywords={tuple(schema.enums[a.enum].keywords)!r}")
    if a.namespace is not None:
        args.append(f"namespace={a.namespace!r}")
    if a.default is not None:
        args.append(f"default={a.default!r}")
    if a.required:
        args.append("required=True")
    if a.pattern is not None:
        args.append(f"pattern={a.pattern!r}")
    if a.directory:
        args.append(f"directory={tuple(a.directory)!r}")
    if a.anchor is not None:
        args.append(f"anchor={a.anchor!r}")
    if a.doc:
        args.append(f"text={a.doc!r}")
    return "_A(" + ", ".join(args) + ")"


def _element_spec(schema: ir.Schema, el: ir.ElementDef) -> str:
    lines = [f"_S({el.tag!r}, {el.name!r}, ("]
    lines += [f"    {_attribute_spec(schema, a)}," for a in el.attributes]
    lines.append("), (")
    for c in el.children:
        child = schema.elements[c.element]
        lines.append(f"    _C({child.tag!r}, {py_name(child.tag)!r}, {child.class_name!r}, "
                     f"{c.single!r}, {c.card!r}),")
    lines.append("),")
    constraints = tuple((k.kind, tuple(tuple(b) for b in k.bundles)) for k in el.constraints)
    if constraints:
        lines.append(f"constraints={constraints!r},")
    extra = ""
    if el.compose is not None:
        extra += f", compose={el.compose!r}"
    if el.attachable:
        extra += ", attachable=True"
    if el.default_row is not None:
        extra += f", defaults_tag={schema.elements[el.default_row].tag!r}"
    lines.append(f"anchor={_quote(el.anchor)}, text={el.doc!r}{extra})")
    return "\n".join(lines)


def _property_doc(typer: Typer, el: ir.ElementDef, a: ir.AttributeDef) -> str:
    head = f"``{a.name}``: {typer.describe(a)}."
    parts = [head]
    facts: list[str] = []
    if a.default is not None:
        facts.append(f'Default: "{a.default}".')
    if a.required:
        facts.append("Required.")
    if a.pattern is not None:
        facts.append(f"Must match ``{a.pattern}``.")
    if facts:
        parts.append(" ".join(facts))
    if a.doc:
        parts.append(a.doc[:1].upper() + a.doc[1:] + ("" if a.doc.endswith(".") else "."))
    if a.anchor is not None:
        parts.append(f"Reference: {DOCS_URL}#{a.anchor}")
    text = "\n\n".join(parts).replace("\\", "\\\\").replace('"""', "'''")
    return textwrap.indent(text, " " * 12).strip()  # laid out inside a property body


def _class_doc(el: ir.ElementDef) -> str:
    head = f"``<{el.tag}>``"
    if el.projection_of is not None:
        head += f" in a ``<default>`` class: the defaults of ``<{el.tag}>`` elements"
    elif el.doc:
        head += f": {el.doc}"
    parts = [head + "."]
    if el.anchor is not None:
        parts.append(f"Reference: {DOCS_URL}#{el.anchor}")
    return textwrap.indent("\n\n".join(parts) + "\n", " " * 4).strip() + "\n    "


def class_view(schema: ir.Schema, typer: Typer, el: ir.ElementDef) -> ClassView:
    properties = [PropertyView(a.py_name, typer.getter(a), typer.setter(a),
                               _property_doc(typer, el, a)) for a in el.attributes]
    children = [ChildView(schema.elements[c.element].tag, py_name(schema.elements[c.element].tag),
                          schema.elements[c.element].class_name, c.single)
                for c in el.children]
    params = [ParamView(a.py_name, typer.setter(a)) for a in el.attributes]
    is_root = el.name == schema.root
    return ClassView(el.class_name, "_ModelRoot" if is_root else "_Element", _class_doc(el),
                     textwrap.indent(_element_spec(schema, el), " " * 4).strip(), properties,
                     children, params, is_root, el.attachable,
                     el.attachable and all(ch.tag != "attach" for ch in children))


def _environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(TEMPLATES),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )
    return env


def _ordered(schema: ir.Schema) -> list[ir.ElementDef]:
    """Root first, then by class name: a stable order that reads like a reference."""
    rest = sorted((e for e in schema.elements.values() if e.name != schema.root),
                  key=lambda e: e.class_name)
    return [schema.elements[schema.root], *rest]


def render(schema: ir.Schema) -> dict[str, str]:
    """The generated package: file name -> text."""
    typer = Typer(schema)
    env = _environment()
    classes = [class_view(schema, typer, el) for el in _ordered(schema)]
    namespaces = [NamespaceView(ns, " | ".join(cls)) for ns, cls in typer.namespaces().items()]
    context: dict[str, object] = {
        "mujoco_version": schema.mujoco_version,
        "generator_version": GENERATOR_VERSION,
        "classes": classes,
        "namespaces": namespaces,
        "class_names": sorted(c.class_name for c in classes),
    }
    return {
        "elements.py": env.get_template("elements.py.jinja2").render(context),
        "__init__.py": env.get_template("__init__.py.jinja2").render(context),
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
    for stale in sorted(directory.glob("*.py")):
        if stale.name not in files:
            stale.unlink()
            changed.append(stale.name)
    py_typed = directory / "py.typed"
    if not py_typed.exists():
        py_typed.write_text("", encoding="utf-8")
    return changed
