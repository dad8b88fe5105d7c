"""``typed-mjcf to-python``: typed-mjcf code that rebuilds an MJCF model.

The code is one function per file: ``build()`` for the model file, returning the
``RootElement``, and an ``add_<name>(parent)`` for each ``<include>``d file, called where the
file was included. Elements are added with ``add_<tag>()`` calls in the order MuJoCo reads
them, their attributes as keyword arguments in MJCF's order; an element gets a variable only
when later code uses it (to add its children, or where a reference names it), and references
to elements made earlier in the same function are passed as those variables (so type
checkers check them too); the others are passed by name. Once-only sections without
attributes are reached through their properties (``model.worldbody``).

Numbers are written as the file spells them, the way a person would type them (``0.1``,
``2e-6``, ``(0, 0, 1)``), except where Python's double would not round to the same ``float``
MuJoCo reads. File paths are written as the file writes them; the model is built with
``model_dir=str(MODEL_DIR)``, the model file's folder relative to the module's (``HERE``), so
they (and ``meshdir`` and the like) mean what they meant in the file.
"""

from __future__ import annotations

import argparse
import builtins
import os
import re
import textwrap
from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import cast

import numpy as np

from typed_mjcf import tooling
from typed_mjcf.assets import Asset
from typed_mjcf.cli import _pycode
from typed_mjcf.cli._common import BAD_INPUT, OK, BadInput, error, load, shown, where
from typed_mjcf.cli._pycode import INDENT, Items, Value
from typed_mjcf.cli._values import reference_name
from typed_mjcf.tooling import (
    ArrayCodec,
    AttributeSpec,
    Element,
    KeywordCodec,
    ModelBase,
    grammar_facts,
    iter_written,
    make_codec,
    to_float,
)

NAME = "to-python"
HELP = "write typed-mjcf Python code that rebuilds a model"
DESCRIPTION = """\
Write Python that rebuilds MODEL.xml with typed-mjcf: a function build() returning the
model (mjcf.RootElement), add_<tag>() calls with keyword arguments in MJCF's attribute order,
variables for the elements later code uses (references to them are passed as variables, so
mypy and pyright check them), default classes as add_default() blocks, and each <include>d
file as a function of its own. Values are written as a person would type them (0.1, not
0.10000000149011612; tuples for arrays). The code is formatted (lines of at most 100
characters) and passes mypy --strict and pyright's strict mode; running it prints the model.

Paths of the files the model uses (meshes, textures, ...) are written as the model writes
them (file="arm.stl" under meshdir="meshes" stays so), and the model is built with
model_dir=str(MODEL_DIR), MODEL_DIR being the model's folder relative to the output file's
folder (without -o, the current folder): exported again, the model names its files as the
original did.

A model whose element names hold "/" cannot be written: typed-mjcf's Python API keeps "/"
for the names of attached models.

exit status: 0 written, 2 the model cannot be read (or written as Python)."""

_MODEL = "model"  # the root's variable
_HERE = "HERE"
_MODEL_DIR = "MODEL_DIR"


def arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the command's arguments."""
    parser.add_argument("model", metavar="MODEL.xml", help="the model to write as Python")
    parser.add_argument("-o", "--output", metavar="OUT.py",
                        help="the file to write (default: standard output)")
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    output: str | None = args.output
    try:
        model = load(args.model)
        folder = os.path.dirname(os.path.abspath(output)) if output else os.getcwd()
        code = to_python(model, folder)
    except BadInput as problem:
        error("to-python", str(problem))
        return BAD_INPUT
    if output is None:
        print(code, end="")
        return OK
    try:
        with open(output, "w", encoding="utf-8") as f:
            f.write(code)
    except OSError as problem:
        error("to-python", f"{shown(output)}: cannot write: {problem.strerror}")
        return BAD_INPUT
    return OK


def to_python(model: ModelBase, folder: str) -> str:
    """The code of a module that rebuilds ``model`` (read from a file); its files are found
    relative to ``folder``, where the module will be. Raises :class:`BadInput` for a model
    typed-mjcf's Python API cannot build."""
    return _Module(model, folder).text()


# ---------------------------------------------------------------------------- the plan


@dataclass(eq=False)
class _Function:
    """The code of one file: the elements it adds, and the calls of the files it includes."""

    name: str
    file: str
    param: Element  # the element the file's contents go into (the root for the model file)
    steps: list[Element | _Function] = field(default_factory=lambda: [])
    names: dict[Element, str] = field(default_factory=lambda: {})  # variables
    binds: dict[int, list[Element]] = field(default_factory=lambda: {})  # step -> sections
    links: dict[tuple[Element, str], Element] = field(default_factory=lambda: {})  # by variable


class _Module:
    """Plans the functions of a model's module, then writes them."""

    def __init__(self, model: ModelBase, folder: str) -> None:
        sources = tooling.source_map(model)
        if sources is None:
            raise BadInput("to-python needs a model read from a file")
        self.model = model
        self.folder = folder
        self.sources = sources
        self.main = cast(str, sources.lines[model][0])
        self.base = os.path.dirname(self.main)
        self.needs: set[str] = set()  # imports: "math", "Path"
        self.functions: dict[str, _Function] = {}
        self.reserved = {"mjcf", "math", "Path", _HERE, _MODEL_DIR, "build"}
        written = set(iter_written(model))
        main = _Function("build", self.main, model)
        self.functions[self.main] = main
        for element in sources.lines:
            if element is model or element not in written:
                continue
            _refuse_slash(element)
            function = self.function(sources.lines[element][0])
            if _is_single(element) and not tooling.values(element):
                continue  # reached through its property
            function.steps.append(element)
        for function in self.functions.values():
            self.plan(function)

    def function(self, file: str | None) -> _Function:
        """The function of ``file``, called from its includer's (which is started first)."""
        assert file is not None
        found = self.functions.get(file)
        if found is not None:
            return found
        by, parent = self.sources.includes[file]
        caller = self.function(by)
        stem = os.path.splitext(os.path.basename(file))[0]
        name = self.free(f"add_{_pycode.identifier(stem, 'file')}", self.reserved)
        self.reserved.add(name)
        function = _Function(name, file, parent)
        caller.steps.append(function)
        self.functions[file] = function
        return function

    @staticmethod
    def free(base: str, taken: set[str]) -> str:
        name, n = base, 1
        while name in taken or name in _BUILTINS:
            n += 1
            name = f"{base}_{n}"
        return name

    # --------------------------------------------------------------- variables

    def plan(self, function: _Function) -> None:
        """Which elements get variables, which sections are bound to one, which references
        are passed as variables."""
        made: set[Element] = set()
        uses: Counter[Element] = Counter()
        first: dict[Element, int] = {}

        def use(element: Element, step: int) -> None:
            uses[element] += 1
            first.setdefault(element, step)

        for step, item in enumerate(function.steps):
            if isinstance(item, _Function):
                use(item.param, step)
                continue
            use(cast(Element, item.parent), step)
            stored = tooling.values(item)
            for attribute in item.spec.references:
                target = stored.get(attribute.name)
                if isinstance(target, Element) and target in made and (
                        tooling.reference_namespace(item, attribute) == target.spec.namespace):
                    function.links[(item, attribute.name)] = target
                    use(target, step)
            made.add(item)
        # Sections reached through properties: bound to a variable when used twice or more
        # (a use of an unbound one is a use of its parent), deepest first.
        pending = {e for e in uses if e not in made and e is not function.param}
        while pending:
            deepest = max(pending, key=_depth)
            pending.discard(deepest)
            parent = cast(Element, deepest.parent)
            if uses[deepest] >= 2:
                function.binds.setdefault(first[deepest], []).append(deepest)
                passed = 1
            else:
                passed = uses[deepest]
            uses[parent] += passed
            first[parent] = min(first.get(parent, first[deepest]), first[deepest])
            if parent not in made and parent is not function.param:
                pending.add(parent)
        taken = set(self.reserved)
        function.names[function.param] = self.free(self.variable_base(function.param), taken)
        taken.add(function.names[function.param])
        for step, item in enumerate(function.steps):
            for section in sorted(function.binds.get(step, []), key=_depth):
                self.name(function, section, taken)
            if isinstance(item, Element) and uses[item]:
                self.name(function, item, taken)

    def name(self, function: _Function, element: Element, taken: set[str]) -> None:
        """Give ``element`` a variable: its name, else with its tag (a body and a site may
        share a name), else numbered."""
        base = self.variable_base(element)
        tagged = f"{base}_{element.spec.tag}"
        if (base in taken or base in _BUILTINS) and not base.endswith(f"_{element.spec.tag}") and (
                tagged not in taken and tagged not in _BUILTINS):
            base = tagged
        function.names[element] = self.free(base, taken)
        taken.add(function.names[element])

    def variable_base(self, element: Element) -> str:
        if element is self.model:
            return _MODEL
        tag = element.spec.tag
        name = tooling.element_name(element)
        if name is None:
            return _pycode.identifier(_child_name(element), tag)
        base = _pycode.identifier(name, tag)
        return f"{base}_class" if element.spec.namespace == grammar_facts().class_namespace else base

    # --------------------------------------------------------------- code

    def text(self) -> str:
        body: list[str] = []
        for function in self.functions.values():
            body += ["", "", *self.code(function)]
        head = [*_wrap(f'"""{self.title()}'), "",
                "Written by ``typed-mjcf to-python``; running it prints the model's MJCF.",
                '"""', ""]
        imports = [line for need, line in (("math", "import math"),
                                           ("Path", "from pathlib import Path"))
                   if need in self.needs]
        head += [*imports, "", "import typed_mjcf as mjcf"] if imports else [
            "import typed_mjcf as mjcf"]
        if "Path" in self.needs:
            head += ["", f"{_HERE} = Path(__file__).parent"]
            if self.model_dir() != ".":
                head.append(f"# the folder of {_doc(os.path.basename(self.main))}: its files "
                            "are found from there")
                head += _pycode.assignment("", _MODEL_DIR, f"{_HERE} /", self.model_dir())
        tail = ["", "", 'if __name__ == "__main__":', f"{INDENT}print(build().to_xml_string())"]
        return "\n".join([*head, *body, *tail]) + "\n"

    def title(self) -> str:
        name = tooling.scope_of(self.model).name
        file = _doc(os.path.basename(self.main))
        if isinstance(name, str):
            return f'The MJCF model "{_doc(name)}" ({file}) as typed-mjcf code.'
        return f"The MJCF model of {file} as typed-mjcf code."

    def code(self, function: _Function) -> list[str]:
        indent = INDENT
        param = function.names[function.param]
        if function.param is self.model and function.name == "build":
            source = _doc(os.path.basename(self.main))
            lines = ["def build() -> mjcf.RootElement:",
                     f'{indent}"""The model, built as {source} describes it."""']
            arguments = self.arguments(function, self.model)
            if self.uses_files():  # paths stay as written, relative to the model's folder
                arguments.append(("model_dir", self.model_dir_argument()))
            lines += _pycode.call(indent, param, "mjcf.RootElement", arguments)
        else:
            kind = f"mjcf.{type(function.param).__name__}"
            relative = os.path.relpath(function.file, self.base).replace(os.sep, "/")
            lines = [f"def {function.name}({param}: {kind}) -> None:",
                     f'{indent}"""The elements {_doc(relative)} adds."""']
        section: Element | None = None
        for step, item in enumerate(function.steps):
            for bound in sorted(function.binds.get(step, []), key=_depth):
                lines += self.blank(lines)
                parent = self.expression(function, cast(Element, bound.parent))
                lines.append(f"{indent}{function.names[bound]} = {parent}.{_child_name(bound)}")
                section = _section(bound)
            if isinstance(item, _Function):
                if not lines[-1].startswith(f"{indent}add_"):  # calls in a row stay together
                    lines += self.blank(lines)
                lines.append(f"{indent}{item.name}({self.expression(function, item.param)})")
                section = None
                continue
            if _section(item) is not section or (item in function.names and any(
                    tooling.children(item))):
                lines += self.blank(lines)
            section = _section(item)
            parent = self.expression(function, cast(Element, item.parent))
            lines += _pycode.call(indent, function.names.get(item), f"{parent}.add_{item.tag}",
                                  self.arguments(function, item))
        if function.name == "build":
            lines += ["", f"{indent}return {param}"]
        return lines

    @staticmethod
    def blank(lines: list[str]) -> list[str]:
        return [] if not lines or lines[-1] == "" or lines[-1].endswith('"""') else [""]

    def expression(self, function: _Function, element: Element) -> str:
        """How ``function`` names ``element``: a variable, or properties of one."""
        steps: list[str] = []
        current = element
        while current not in function.names:
            assert _is_single(current), f"{current.path} is not reachable in {function.name}"
            steps.append(_child_name(current))
            parent = current.parent
            if parent is None:  # pragma: no cover - every chain starts at the parameter
                raise AssertionError(f"{element.path} is not reachable in {function.name}")
            current = parent
        return ".".join([function.names[current], *reversed(steps)])

    # --------------------------------------------------------------- values

    def arguments(self, function: _Function, element: Element) -> list[tuple[str | None, Value]]:
        spec = element.spec
        stored = tooling.values(element)
        arguments: list[tuple[str | None, Value]] = []
        for name in sorted(stored, key=spec.order.__getitem__):
            attribute = spec.by_name[name]
            target = function.links.get((element, name))
            if target is not None:
                arguments.append((attribute.py_name, function.names[target]))
            else:
                arguments.append((attribute.py_name, self.value(element, attribute,
                                                                stored[name])))
        return arguments

    def value(self, element: Element, attribute: AttributeSpec, stored: object) -> Value:
        """A stored value as Python source."""
        kind = attribute.kind
        if isinstance(stored, Element):
            return _pycode.string(reference_name(stored))
        if kind == "file":
            return self.file(element, attribute, stored)
        if isinstance(stored, bool):
            return "True" if stored else "False"
        if kind == "keyword":
            codec = cast(KeywordCodec, attribute.codec)
            if codec.takes_bool and stored in ("true", "false"):
                return "True" if stored == "true" else "False"
            return _pycode.string(cast(str, stored))
        if kind == "flags":
            if isinstance(stored, str):  # a keyword taken alone (input="none")
                return _pycode.string(stored)
            words = cast(tuple[str, ...], stored)
            if len(words) == 1:
                return _pycode.string(words[0])
            return Items.of(tuple(_pycode.string(word) for word in words))
        if kind == "int" and not attribute.is_array:
            return str(stored)
        if kind == "real" and not attribute.is_array:
            return self.number(self.real(attribute, stored))
        if kind in ("int", "real"):
            text, count = self.numbers(attribute, stored)
            if count == 1 and attribute.lo <= 1 and (attribute.hi is None or attribute.hi >= 1):
                return text  # one value may be given as a number
            return Items(text, count)
        return _pycode.string(cast(str, stored))

    def number(self, x: float) -> str:
        text = _pycode.number(x)
        if "math." in text:
            self.needs.add("math")
        return text

    @staticmethod
    def real(attribute: AttributeSpec, stored: object) -> float:
        """One real number: as the file spells it, unless Python's double of that text
        would round to another float than MuJoCo reads (for a ``float`` attribute)."""
        if not isinstance(stored, str):
            return float(cast(float, stored))
        x = to_float(stored)
        if attribute.dtype == "float":
            exact = cast(ArrayCodec, make_codec("real", dtype="float", is_array=True, lo=1, hi=1,
                                                keywords=(), pattern=None)).from_text(stored)
            if np.float32(x) != exact[0]:
                x = float(exact[0])
        return x

    def numbers(self, attribute: AttributeSpec, stored: object) -> tuple[str, int]:
        """The numbers' text joined by ``", "``, and how many: made a piece at a time, so a
        long list costs about its text (a list of a million strings took 30x it)."""
        codec = cast(ArrayCodec, attribute.codec)
        pieces: list[str] = []
        count = 0
        if isinstance(stored, str):
            exact = codec.from_text(stored) if codec.single and not codec.is_int else None
            for parts in _pieces(stored):
                if codec.is_int:
                    pieces.append(", ".join(str(int(part)) for part in parts))
                    count += len(parts)
                    continue
                doubles = [to_float(part) for part in parts]
                if exact is not None:
                    here = exact[count:count + len(doubles)]
                    rounded = np.array(doubles, np.float32)
                    for i in np.flatnonzero(rounded.view(np.uint32) != here.view(np.uint32)):
                        doubles[int(i)] = float(here[int(i)])
                pieces.append(", ".join(self.number(x) for x in doubles))
                count += len(doubles)
            return ", ".join(pieces), count
        array = cast(np.ndarray[tuple[int], np.dtype[np.generic]], stored)
        for start in range(0, len(array), _PIECE):
            values = cast(list[float], array[start:start + _PIECE].tolist())
            if codec.is_int:
                pieces.append(", ".join(str(x) for x in values))
            elif array.dtype == np.float32:
                pieces.append(", ".join(self.number(_short_float32(x)) for x in values))
            else:
                pieces.append(", ".join(self.number(float(x)) for x in values))
        return ", ".join(pieces), len(array)

    def file(self, element: Element, attribute: AttributeSpec, stored: object) -> str:
        """The path as the file writes it (relative to the model's folder, ``meshdir`` and
        the like applying as in the file): the model is built with ``model_dir``."""
        if isinstance(stored, Asset):  # pragma: no cover - parsed models hold paths
            raise BadInput(f"{where(element)}: {attribute.name} holds an in-memory file")
        return _pycode.string(cast(str, stored))

    def uses_files(self) -> bool:
        """Whether an element of the model names a file (the model then needs its folder)."""
        return any(element.spec.by_name[name].kind == "file"
                   for element in self.sources.lines for name in tooling.values(element))

    def model_dir_argument(self) -> str:
        """``str(MODEL_DIR)``: the folder the model's relative paths start from."""
        self.needs.add("Path")
        return f"str({_HERE if self.model_dir() == '.' else _MODEL_DIR})"

    def model_dir(self) -> str:
        """The model file's folder, relative to the module's."""
        return _relative(self.base, self.folder)


# ---------------------------------------------------------------------------- helpers

_BUILTINS = frozenset(dir(builtins))
_PIECE = 8192  # numbers converted at a time
_SPACE = re.compile(r"\s")


def _pieces(text: str) -> Iterator[list[str]]:
    """The whitespace-separated parts of ``text``, about :data:`_PIECE` at a time (never
    an empty list)."""
    start, size = 0, 8 * _PIECE  # characters: a few per number
    while start < len(text):
        space = _SPACE.search(text, min(start + size, len(text)))
        end = len(text) if space is None else space.start()
        parts = text[start:end].split()
        start = end
        if parts:
            yield parts


def _refuse_slash(element: Element) -> None:
    name = tooling.element_name(element)
    if name is not None and "/" in name:
        raise BadInput(f"{where(element)}: <{element.spec.tag}> name {name!r} holds '/', which "
                       f"typed-mjcf's Python API keeps for the names of attached models; "
                       f"rename it to write this model as Python")


def _is_single(element: Element) -> bool:
    parent = element.parent
    return parent is not None and parent.spec.children[element.spec.tag].single


def _child_name(element: Element) -> str:
    """The property of ``element``'s parent that holds it (``global_`` for ``<global>``)."""
    parent = element.parent
    if parent is None:
        return element.spec.tag
    return parent.spec.children[element.spec.tag].py_name


def _depth(element: Element) -> int:
    depth = 0
    current = element.parent
    while current is not None:
        depth += 1
        current = current.parent
    return depth


def _section(element: Element) -> Element | None:
    """The model's section ``element`` is in (``worldbody``, ``asset``, ...)."""
    current = element
    while current.parent is not None and current.parent.parent is not None:
        current = current.parent
    return current if current.parent is not None else None


def _short_float32(x: float) -> float:
    """The shortest double that rounds to the float32 ``x`` (``0.1`` for float32(0.1))."""
    single = np.float32(x)
    short = float(str(single))
    return short if np.float32(short) == single else x


def _relative(path: str, start: str) -> str:
    """``path`` relative to ``start``, with ``/`` (absolute on another drive)."""
    try:
        return os.path.relpath(path, start).replace(os.sep, "/")
    except ValueError:
        return path.replace(os.sep, "/")


def _wrap(text: str) -> list[str]:
    return textwrap.wrap(text, _pycode.WIDTH, break_long_words=False, break_on_hyphens=False)


def _doc(text: str) -> str:
    """Text for a docstring: backslashes, quotes and control characters escaped."""
    return repr(text)[1:-1].replace('"', '\\"')
