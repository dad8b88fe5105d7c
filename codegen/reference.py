"""The MJCF reference: one Markdown page per grammar row, written from ``schema/``.

MuJoCo's own XML reference is written by hand and says nothing of Python types; these pages
are rendered from the same IR as the classes, so they change with the grammar: for each row
its place in a model (parents, children with their counts), the typed adder's signature, a
short example that runs, and every attribute with its Python type, MuJoCo's default, the
releases that have it and its one-line note (the words of :mod:`codegen.docs`). The docs site
(``docs/``) includes them; ``python -m codegen render`` writes them to
``generated/mjcf-reference/`` and a test fails when they are out of date.
"""

from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass
from pathlib import Path

from codegen import docs, folder, ir, releases
from codegen.render import child_py_name
from codegen.typing_names import Typer

REFERENCE_DIR = Path(__file__).resolve().parent.parent / "generated" / "mjcf-reference"

# The grammar file's cardinalities, in words.
_CARD = {"?": "at most one", "!": "exactly one", "*": "any number", "R": "any number (nested)"}
# Annotation prefixes the typing surface needs and a reader does not.
_PREFIXES = re.compile(r"\b(?:_builtins|_t)\.")


@dataclass(frozen=True)
class Step:
    """One step of the way from the root to a row: the child row and how it is reached."""

    row: ir.ElementDef
    single: bool  # a property created on first use, else an add_<tag>() call


def readable(annotation: str) -> str:
    """A typing-surface annotation as a user writes it (``_t.Real`` -> ``Real``)."""
    return _PREFIXES.sub("", annotation)


def page_name(el: ir.ElementDef) -> str:
    """The page's file name: the row's declaration name (unique, unlike tags)."""
    return f"{el.name}.md"


def _link(el: ir.ElementDef) -> str:
    return f"[`<{el.tag}>` ({el.class_name})]({page_name(el)})"


def way_from_root(schema: ir.Schema) -> dict[str, list[Step]]:
    """For each row, the shortest way to reach it from the root (breadth first, children in
    grammar order, so the way is stable)."""
    ways: dict[str, list[Step]] = {schema.root: []}
    queue = deque([schema.root])
    while queue:
        name = queue.popleft()
        for child in schema.elements[name].children:
            if child.element not in ways:
                ways[child.element] = [*ways[name],
                                       Step(schema.elements[child.element], child.single)]
                queue.append(child.element)
    return ways


def _sample(schema: ir.Schema, a: ir.AttributeDef) -> str:
    """A value of ``a`` for the example: only required attributes get one."""
    if a.kind in ("keyword", "flags"):
        return f'"{schema.enums[a.enum or ""].keywords[0]}"'
    if a.kind in ("int", "real"):
        one = "1" if a.kind == "int" else "1.0"
        if a.arity is None:
            return one
        count = max(a.arity[0], 1)
        return "(" + ", ".join([one] * count) + ("," if count == 1 else "") + ")"
    if a.kind == "bool":
        return "True"
    if a.kind == "file":
        return '"model.xml"'
    return f'"my_{a.name}"'


def _call(schema: ir.Schema, el: ir.ElementDef, names: bool) -> str:
    """``add_<tag>(...)`` with the row's required attributes (and a name where it has one,
    when ``names``)."""
    arguments = [f"{a.py_name}={_sample(schema, a)}" for a in el.attributes if a.required]
    named = next((a for a in el.attributes if a.kind == "id" and not a.required), None)
    if names and named is not None:
        arguments.insert(0, f'{named.py_name}="my_{el.tag}"')
    return f"add_{el.tag}({', '.join(arguments)})"


def example(schema: ir.Schema, el: ir.ElementDef, way: list[Step]) -> str:
    """Python that makes a model holding one ``el`` (its last line names it)."""
    lines = ["import typed_mjcf as mjcf", "", "model = mjcf.RootElement()"]
    if el.name == schema.root:
        lines.append('model.model = "my_model"')
        return "\n".join(lines)
    parent = "model"
    for at, step in enumerate(way):
        variable = child_py_name(step.row.tag).rstrip("_") if at + 1 < len(way) else "element"
        if variable in ("model", parent):
            variable += "_"
        reach = (child_py_name(step.row.tag) if step.single
                 else _call(schema, step.row, names=at + 1 == len(way)))
        lines.append(f"{variable} = {parent}.{reach}")
        parent = variable
    return "\n".join(lines)


def signature(typer: Typer, schema: ir.Schema, el: ir.ElementDef) -> str:
    """``add_<tag>()``'s signature as the typing surface declares it."""
    params = [f"    {a.py_name}: {readable(typer.setter(a))} | None = ...,"
              for a in el.attributes]
    params += [f"    dclass: {readable(typer.setter(a))} | None = ...,"
               for a in el.attributes if a.name == schema.facts().dclass]
    star = ["    *,"] if params else []
    return "\n".join([f"def add_{el.tag}(", "    self,", *star, *params,
                      f") -> {el.class_name}: ..."])


def _cell(text: str) -> str:
    """Text for a Markdown table cell."""
    return text.replace("|", "\\|").replace("\n", " ")


def _default(a: ir.AttributeDef) -> str:
    if a.default is not None:
        return f"`{a.default}`" if a.default else '`""`'
    if a.computed is not None:
        return "computed by MuJoCo"
    return "required" if a.required else "none"


def removed_attributes(schema: ir.Schema, older: dict[str, ir.Schema],
                       row: str) -> dict[str, list[str]]:
    """Attributes older releases' ``row`` has and the newest's lacks: name -> releases."""
    mine: set[str] = ({a.name for a in schema.elements[row].attributes}
                      if row in schema.elements else set())
    found: dict[str, list[str]] = {}
    for version in sorted(older, key=releases.version_key):
        old = older[version].elements.get(row)
        for a in old.attributes if old is not None else []:
            if a.name not in mine:
                found.setdefault(a.name, []).append(version)
    return found


def _children(schema: ir.Schema, gates: releases.Gates, el: ir.ElementDef) -> list[str]:
    lines = ["## Children", ""]
    if not el.children:
        return [*lines, "None.", ""]
    lines += ["| child | how many | in Python |", "|---|---|---|"]
    for c in el.children:
        child = schema.elements[c.element]
        python = (f"`.{child_py_name(child.tag)}` (created on first use)" if c.single
                  else f"`.add_{child.tag}()`, `.{child_py_name(child.tag)}[i]`")
        rels = gates.children.get(el.name, {}).get(child.tag)
        since = f" ({releases.availability(rels, gates.releases)})" if rels else ""
        lines.append(f"| {_link(child)} | {_CARD[c.card]}{since} | {python} |")
    return [*lines, ""]


def _attributes(schema: ir.Schema, typer: Typer, gates: releases.Gates,
                older: dict[str, ir.Schema], el: ir.ElementDef) -> list[str]:
    lines = ["## Attributes", ""]
    if not el.attributes:
        lines.append("None.")
    else:
        lines += ["| attribute | Python type | default | MuJoCo | about |", "|---|---|---|---|---|"]
    for a in el.attributes:
        rels = gates.attribute_releases(el.name, a.name)
        releases_text = releases.availability(rels, gates.releases) if rels else "all"
        note = docs.note(a) or ""
        spellings = ([f"also read as {', '.join(f'{n} ({k})' for k, n in a.numbers.items())}"]
                     if a.numbers else [])
        otherwise = [f"in MuJoCo {', '.join(versions)}: {releases.describe(fields)}"
                     for fields, versions in releases.grouped(
                         gates.types.get(el.name, {}).get(a.name, {}))]
        about = "; ".join([typer.describe(a), *spellings, *otherwise, *(a.bounds or [])]) + (
            f". {note}" if note else ".")
        name = f"`{a.name}`" + (f" (`{a.py_name}`)" if a.py_name != a.name else "")
        lines.append(f"| {name} | `{_cell(readable(typer.setter(a)))}` | {_default(a)} | "
                     f"{releases_text} | {_cell(about)} |")
    removed = removed_attributes(schema, older, el.name)
    if removed:
        lines += ["", ("Attributes older MuJoCo releases have here and "
                  f"{schema.mujoco_version} does not (not typed; read and written as they are "
                  "under those releases):"), ""]
        lines += [f"- `{name}`: MuJoCo {', '.join(versions)}"
                  for name, versions in sorted(removed.items())]
    if el.constraints:
        lines += ["", "Presence constraints (`validate()` checks them):", ""]
        for constraint in el.constraints:
            bundles = " | ".join(" + ".join(f"`{n}`" for n in b) for b in constraint.bundles)
            lines.append(f"- {constraint.kind}: {bundles}")
    return [*lines, ""]


def page(schema: ir.Schema, typer: Typer, gates: releases.Gates, older: dict[str, ir.Schema],
         el: ir.ElementDef, way: list[Step]) -> str:
    """The Markdown page of one row: what it is and where, an example, its attributes, its
    children, the adder's signature."""
    lines = [f"# `<{el.tag}>`: {el.class_name}", ""]
    if el.projection_of is not None:
        lines += [(f"The defaults of {_link(schema.elements[el.projection_of])} elements, in a "
                  "`<default>` class."), ""]
    elif el.doc:
        lines += [el.doc[:1].upper() + el.doc[1:] + ("" if el.doc.endswith(".") else "."), ""]
    if el.anchor is not None:
        lines += [f"MuJoCo's reference: <{docs.DOCS_URL}#{el.anchor}>", ""]
    parents = [schema.elements[p] for p in schema.parents_of(el.name)]
    lines.append("**Parents:** " + (", ".join(_link(p) for p in parents) if parents
                                    else "none (the root)") + "  ")
    where = "`" + "/".join([schema.elements[schema.root].tag,
                            *(s.row.tag for s in way)]) + "`"
    lines += [f"**Reached as:** {where}", ""]
    lines += ["## Example", "", "```python", example(schema, el, way), "```", ""]
    lines += _attributes(schema, typer, gates, older, el)
    lines += _children(schema, gates, el)
    if way:
        # a directive, not a ```python block: a declaration to read, not code that runs
        lines += ["## Adding one", "", "```{code-block} python", signature(typer, schema, el),
                  "```", ""]
    return "\n".join(lines).rstrip("\n") + "\n"


def index(schema: ir.Schema, ordered: list[ir.ElementDef]) -> str:
    """The reference's index: every row by tag."""
    lines = ["# MJCF reference", "",
             (f"Every element of MuJoCo {schema.mujoco_version}'s MJCF grammar, one page each, "
             "written by the code generator from `schema/` (as the typed classes are). "
             "A tag may stand in several places with different attributes (`<joint>` in a "
             "body, in `<equality>` and in a `<default>` class): each is a row of its own."), "",
             "| element | class | parents |", "|---|---|---|"]
    for el in ordered:
        parents = ", ".join(f"`<{schema.elements[p].tag}>`" for p in schema.parents_of(el.name))
        lines.append(f"| [`<{el.tag}>`]({page_name(el)}) | `{el.class_name}` | {parents} |")
    toc = ["", "```{toctree}", ":hidden:", "", *(el.name for el in ordered), "```"]
    return "\n".join(lines + toc) + "\n"


def render(schema: ir.Schema, older: dict[str, ir.Schema] | None = None) -> dict[str, str]:
    """The reference's files: name -> Markdown text."""
    older = releases.load_releases() if older is None else older
    typer = Typer(schema)
    gates = releases.gates(schema, older)
    ways = way_from_root(schema)
    ordered = sorted(schema.elements.values(), key=lambda e: (e.tag, e.name))
    files = {page_name(el): page(schema, typer, gates, older, el, ways[el.name])
             for el in ordered if el.name in ways}
    files["index.md"] = index(schema, [el for el in ordered if el.name in ways])
    return files


def stale(files: dict[str, str], directory: Path = REFERENCE_DIR) -> list[str]:
    return folder.stale(files, directory, "*.md")


def write(files: dict[str, str], directory: Path = REFERENCE_DIR) -> list[str]:
    return folder.write(files, directory, "*.md")
