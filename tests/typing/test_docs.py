"""What an editor shows for each keyword of each ``add_<tag>()``, and what ``help()`` shows.

pyright (the engine of VS Code's Pylance) documents keyword ``p`` of a call with one line of
the function's docstring: the first line, after the docstring is dedented, that contains
``@param p`` or ``:param p`` (the text after them) or ``p: `` or ``p (`` (the text from there).
``pyright_parameter_doc`` repeats that rule (``extractParameterDocumentation`` in pyright's
``docStringUtils``), and the tests check, for every keyword of every ``add_<tag>()`` in
``elements.pyi``, that the line found is the keyword's own entry and states the attribute's
facts from the grammar tables: its type, allowed values or length, default or that it is
required. ``help()`` shows the same docstring: one generator writes both.
"""

from __future__ import annotations

import ast
import functools
import inspect
import re
from collections.abc import Iterator
from pathlib import Path
from types import FunctionType

import pytest

import typed_mjcf as mjcf
from tests.support.pyright_docs import clean_and_split, pyright_parameter_doc
from typed_mjcf._core.grammar import AttributeSpec
from typed_mjcf._core.tree import DCLASS, Element, element_classes

STUB = Path(mjcf.__file__).resolve().parent / "_generated" / "elements.pyi"


@functools.cache
def stub_tree() -> ast.Module:
    """The stub parsed, once per process and at run time (0.7 s of CPU: not at collection,
    which every pytest process does)."""
    return ast.parse(STUB.read_text(encoding="utf-8"))


def adders() -> Iterator[tuple[str, ast.FunctionDef]]:
    for node in stub_tree().body:
        if isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef) and item.name.startswith("add_"):
                    yield node.name, item


@functools.cache
def adder_node(class_name: str, name: str) -> ast.FunctionDef:
    return next(f for c, f in adders() if c == class_name and f.name == name)


def adder_names() -> list[tuple[str, str]]:
    """``(class, add_<tag>)`` of each adder in the stub, read line by line for the parameters
    (test_the_stub_has_adders holds it to the parse: ``adders()``)."""
    found: list[tuple[str, str]] = []
    class_name = None
    for line in STUB.read_text(encoding="utf-8").splitlines():
        if line.startswith("class "):
            class_name = re.split(r"[(:]", line[len("class "):], maxsplit=1)[0]
        elif line[:1] not in ("", " ", "@", "#", ")"):
            class_name = None  # a top-level statement ends the class
        elif class_name is not None and line.startswith("    def add_"):
            found.append((class_name, line[len("    def "):].partition("(")[0]))
    return found


ADDERS = adder_names()


def child_spec(class_name: str, adder: str) -> type[Element]:
    parent = element_classes()[class_name]
    child = next(c for c in parent.spec.children.values()
                 if c.tag == adder.removeprefix("add_"))
    return element_classes()[child.class_name]


def expected_facts(spec: AttributeSpec) -> list[str]:
    """What the line must say about the attribute, from the run-time grammar table."""
    facts: list[str] = []
    if spec.keywords:
        facts += list(spec.keywords)
    if spec.is_array:
        facts.append("[]" if spec.hi is None and spec.lo == 0 else f"[{spec.lo}.."
                     if spec.hi is None else f"[{spec.lo}]" if spec.lo == spec.hi
                     else f"[{spec.lo}..{spec.hi}]")
    if spec.namespace is not None:
        facts.append(f"``{spec.namespace}``")
    if spec.default is not None:
        facts.append(f'default "{spec.default}"')
    elif spec.required:
        facts.append("required")
    elif spec.computed:
        facts.append("default computed by MuJoCo")
    else:
        facts.append("no default")
    return facts


def test_the_stub_has_adders() -> None:
    assert len(ADDERS) > 150
    assert ADDERS == [(c, f.name) for c, f in adders()]


@pytest.mark.parametrize(("class_name", "adder"), ADDERS, ids=[f"{c}.{n}" for c, n in ADDERS])
def test_each_keyword_shows_its_own_facts(class_name: str, adder: str) -> None:
    function = adder_node(class_name, adder)
    doc = ast.get_docstring(function, clean=False)
    assert doc is not None
    cls = child_spec(class_name, adder)
    keywords = [a.arg for a in function.args.kwonlyargs]
    assert {a.py_name for a in cls.spec.attributes.values()} <= set(keywords), (
        f"{class_name}.{adder}")
    for keyword in keywords:
        shown = pyright_parameter_doc(doc, keyword)
        assert shown is not None, f"{class_name}.{adder}({keyword}=): no documentation"
        assert shown.startswith(f"{keyword}: "), \
            f"{class_name}.{adder}({keyword}=) shows another line: {shown!r}"
        own = [line.strip() for line in clean_and_split(doc)
               if line.strip().startswith(f"{keyword}: ")]
        assert shown == own[0], f"{class_name}.{adder}({keyword}=) shows {shown!r}"
        spec = cls.spec.by_key[keyword]
        if keyword == DCLASS:
            assert "class_" in shown
            continue
        for fact in expected_facts(spec):
            assert fact in shown, f"{class_name}.{adder}({keyword}=): {fact!r} not in {shown!r}"


JARGON = re.compile(r"\bsav(e|ed)\b|UNTYPED|compile directive", re.IGNORECASE)


def test_no_note_speaks_of_mujocos_code() -> None:
    """Notes say what an attribute means, not how MuJoCo saves or checks it."""
    found = sorted({m.group(0) for m in JARGON.finditer(STUB.read_text(encoding="utf-8"))})
    assert found == []


def test_help_shows_what_the_editor_shows() -> None:
    """``help(body.add_geom)`` and the editor's docstring are one text."""
    for class_name, function in adders():
        stub = ast.get_docstring(function)
        runtime = inspect.getdoc(getattr(element_classes()[class_name], function.name))
        assert runtime == stub, f"{class_name}.{function.name}"


def attribute_docs(node: ast.ClassDef) -> Iterator[tuple[str, str | None]]:
    """Each attribute a class body declares (``pos: _Attr[...]``) and the docstring that
    follows it (what pyright shows on hover), or None."""
    for item, after in zip(node.body, [*node.body[1:], None]):
        if isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
            doc = (after.value.value if isinstance(after, ast.Expr)
                   and isinstance(after.value, ast.Constant)
                   and isinstance(after.value.value, str) else None)
            yield item.target.id, doc


def test_property_hover_starts_with_the_facts() -> None:
    """An attribute's docstring: its first line is the attribute's line."""
    tree = stub_tree()
    checked = 0
    for node in tree.body:
        if not isinstance(node, ast.ClassDef) or node.name not in element_classes():
            continue
        spec = element_classes()[node.name].spec
        declared = dict(attribute_docs(node))
        names = {a.py_name for a in spec.attributes.values()}
        assert names <= set(declared), (node.name, names - set(declared))
        for name, doc in declared.items():
            if name not in spec.by_key or name == DCLASS:
                continue
            attribute = spec.by_key[name]
            assert doc is not None, (node.name, name)
            first = inspect.cleandoc(doc).splitlines()[0]
            assert first.startswith(f"``{attribute.name}``: "), (node.name, name, first)
            for fact in expected_facts(attribute):
                assert fact in first, (node.name, name, fact, first)
            checked += 1
    assert checked > 1000


def _in_args_block(doc: str, shown: str) -> bool:
    """Whether ``shown`` is an entry of the docstring's ``Args:`` block (a line of its own
    there), not a fragment of prose."""
    inside, indent = False, 0
    for line in clean_and_split(doc):
        depth = len(line) - len(line.lstrip())
        if line.strip() in ("Args:", "Arguments:", "Parameters:"):
            inside, indent = True, depth
        elif inside and line.strip() and depth <= indent:
            inside = False
        if inside and line.strip() == shown:
            return True
    return False


def _public_functions() -> Iterator[tuple[str, FunctionType]]:
    from typed_mjcf import _base

    for name, value in vars(mjcf).items():
        if inspect.isfunction(value) and not name.startswith("_"):
            yield name, value
    for cls in (_base.Element, _base.ModelRoot, _base.Attachable):
        for name, value in vars(cls).items():
            if inspect.isfunction(value) and not name.startswith("_"):
                yield f"{cls.__name__}.{name}", value


def test_hand_written_parameter_docs_show_their_own_entry() -> None:
    """A parameter an editor finds documentation for finds its ``Args:`` entry (``attach``'s
    ``model`` showed a fragment of prose: ``model (find("joint", ...)``)."""
    wrong: list[str] = []
    for name, function in _public_functions():
        doc = inspect.getdoc(function) or ""
        for parameter in inspect.signature(function).parameters:
            shown = pyright_parameter_doc(doc, parameter)
            if shown is not None and not _in_args_block(doc, shown):
                wrong.append(f"{name}({parameter}): {shown[:60]!r}")
    assert wrong == []
