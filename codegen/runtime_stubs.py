"""Stubs of the runtime's modules (``src/typed_mjcf/**.py``) for an installed wheel.

A type checker reads every module a user's script reaches: without a ``.pyi`` beside it, the
whole implementation (``_tree.py`` alone is 80 KB), every function body tokenized, parsed and
bound, and every module it imports. The stubs written here keep what a checker needs, taken
from the source's own text so that nothing is re-typed (type aliases, defaults and
annotations are the source's characters):

- every function and method keeps its decorators, signature and docstring; its body is
  ``...``, except a method's that assigns public attributes on ``self`` that its class does
  not declare (checkers infer them from it, in a stub as in a module); an overloaded
  function's implementation goes, its docstring to the overloads that have none;
- classes keep their decorators, bases, docstring and members (annotated fields, private
  too, keep their value where it decides the type or a dataclass's ``__init__``: a literal, a
  name, a ``field(...)`` call; otherwise ``...``; ``__slots__`` goes); unannotated
  assignments (aliases, type variables, constants) are kept whole, so a checker infers what
  it infers from the implementation;
- ``if TYPE_CHECKING:`` blocks are read the way a checker reads them (the block inlined, an
  ``if not TYPE_CHECKING:`` block dropped); other statements with only run-time effects
  (calls, ``raise``) are dropped, and a statement this module does not know is an error;
- private names (``_x``, not dunders) that no kept text of any stub or generated module
  names are dropped, and so are the imports no kept text uses (``__all__``, ``import x as
  x`` and ``*`` imports are re-exports and stay).

The stubs live in ``generated/runtime-pyi/`` (not importable, so this repository's mypy and
pyright still read and check the ``.py`` files) and the wheel puts each beside its module
(pyproject's ``force-include``). ``python -m codegen render`` writes them; ``python -m codegen
check`` and ``tests/codegen/test_runtime_stubs.py`` compare them with a fresh generation, and
``tests/typing/test_runtime_stubs.py`` checks them against the implementation (mypy's
``stubtest``) and type-checks user code against the wheel's layout.
"""

from __future__ import annotations

import ast
import bisect
import io
import tokenize
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

from codegen import folder

ROOT = Path(__file__).resolve().parent.parent
SOURCE_DIR = ROOT / "src" / "typed_mjcf"
STUBS_DIR = ROOT / "generated" / "runtime-pyi"
# generated modules whose imports of the runtime's names keep those names in the stubs
GENERATED_DIR = ROOT / "generated" / "typed_mjcf_generated"
# not stubbed: the generated package (a link to generated/, with its own .pyi files) and the
# `python -m typed_mjcf` script, which nothing imports
SKIPPED = {"_generated", "__main__.py"}
HEADER = ("# Generated from src/typed_mjcf/{source} by codegen/runtime_stubs.py "
          "(python -m codegen render); do not edit.\n")
INDENT = "    "
TYPE_CHECKING_NAMES = {"TYPE_CHECKING", "_TYPE_CHECKING"}
# an annotated field keeps a value of these kinds (the type or the dataclass field depends
# on it); any other value becomes `...`
KEPT_CALLS = {"field", "dataclasses.field"}
BARE_ANNOTATIONS = {"Final", "TypeAlias", "typing.Final", "typing.TypeAlias"}


class StubError(Exception):
    """A statement the stub generator does not know how to read (``path:line: message``)."""


@dataclass
class Entry:
    """One statement of a stub: its text at indent 0 of its block, the names it references
    and (for a definition or assignment) the name it defines."""

    kind: Literal["doc", "import", "def", "class", "assign"]
    text: str
    refs: set[str]
    defines: tuple[str, ...] = ()
    binds: dict[str, bool] = field(default_factory=lambda: {})  # import: name -> re-exported
    members: list[Entry] = field(default_factory=lambda: [])  # a class's body
    keep_private: bool = False  # a Protocol's members are its interface, private or not


def is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def names_in(nodes: Iterable[ast.AST | None]) -> set[str]:
    """Every identifier the nodes mention (names, attributes, and the names inside string
    annotations and ``__all__`` entries): over-collecting only keeps an import or a private
    name that could have gone."""
    found: set[str] = set()
    for root in nodes:
        if root is None:
            continue
        for node in ast.walk(root):
            if isinstance(node, ast.Name):
                found.add(node.id)
            elif isinstance(node, ast.Attribute):
                found.add(node.attr)
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                found.add(node.value)
                try:
                    found |= names_in([ast.parse(node.value, mode="eval")])
                except SyntaxError:
                    pass
    return found


class Source:
    """A module's text, its tokens and how to cut statements out of it."""

    def __init__(self, path: Path, relative: str) -> None:
        self.path = path
        self.relative = relative
        self.text = path.read_text(encoding="utf-8")
        self.lines = self.text.splitlines(keepends=True)
        self.tree = ast.parse(self.text, filename=str(path))
        self.tokens = list(tokenize.generate_tokens(io.StringIO(self.text).readline))
        self.starts = [token.start for token in self.tokens]

    def error(self, node: ast.stmt, message: str) -> StubError:
        return StubError(f"src/typed_mjcf/{self.relative}:{node.lineno}: {message}")

    def segment(self, start: tuple[int, int], end: tuple[int, int]) -> str:
        """The text from ``start`` to ``end`` ((line from 1, column)), continuation lines
        as they are in the file."""
        (first, col), (last, end_col) = start, end
        if first == last:
            return self.lines[first - 1][col:end_col]
        parts = [self.lines[first - 1][col:], *self.lines[first:last - 1],
                 self.lines[last - 1][:end_col]]
        return "".join(parts)

    def node_text(self, node: ast.expr | ast.stmt) -> str:
        assert node.end_lineno is not None and node.end_col_offset is not None
        return self.segment((node.lineno, node.col_offset),
                            (node.end_lineno, node.end_col_offset))

    def header(self, node: ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef) -> str:
        """``def name(...) -> T`` / ``class Name(...)``, as written, without its colon."""
        start = (node.lineno, node.col_offset)
        depth = 0
        for token in self.tokens[bisect.bisect_left(self.starts, start):]:
            if token.type != tokenize.OP:
                continue
            if token.string in "([{":
                depth += 1
            elif token.string in ")]}":
                depth -= 1
            elif token.string == ":" and depth == 0:
                return self.segment(start, token.start).rstrip()
        raise self.error(node, "no ':' ends the header")


def reindent(text: str, column: int) -> str:
    """``text`` cut from ``column`` of its first line: its later lines shifted left as far
    (they keep their layout relative to the first)."""
    lines = text.split("\n")
    shifted = [lines[0]]
    for line in lines[1:]:
        spaces = len(line) - len(line.lstrip(" "))
        shifted.append(line[min(spaces, column):])
    return "\n".join(shifted)


def indented(text: str, prefix: str) -> str:
    return "\n".join(prefix + line if line else line for line in text.split("\n"))


def is_type_checking(test: ast.expr) -> bool | None:
    """True for ``TYPE_CHECKING``, False for ``not TYPE_CHECKING``, None otherwise."""
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        inner = is_type_checking(test.operand)
        return None if inner is None else not inner
    if isinstance(test, ast.Name) and test.id in TYPE_CHECKING_NAMES:
        return True
    if (isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
            and isinstance(test.value, ast.Name) and test.value.id == "typing"):
        return True
    return None


def declared(body: list[ast.stmt]) -> set[str]:
    """The names a class body declares (in ``if TYPE_CHECKING:`` blocks too)."""
    names: set[str] = set()
    for statement in body:
        if isinstance(statement, ast.If):
            names |= declared([*statement.body, *statement.orelse])
        elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
            names.add(statement.target.id)
        elif isinstance(statement, ast.Assign):
            names |= {t.id for t in statement.targets if isinstance(t, ast.Name)}
        elif isinstance(statement, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            names.add(statement.name)
    return names


def makes_attributes(function: ast.FunctionDef | ast.AsyncFunctionDef) -> set[str]:
    """The public attributes ``function`` assigns on ``self``."""
    names: set[str] = set()
    for node in ast.walk(function):
        targets = (node.targets if isinstance(node, ast.Assign)
                   else [node.target] if isinstance(node, ast.AnnAssign) else [])
        flat = [e for t in targets for e in (t.elts if isinstance(t, ast.Tuple) else [t])]
        for target in flat:
            if (isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
                    and target.value.id == "self" and not is_private(target.attr)):
                names.add(target.attr)
    return names


def is_overload(decorator: ast.expr) -> bool:
    return ((isinstance(decorator, ast.Name) and decorator.id == "overload")
            or (isinstance(decorator, ast.Attribute) and decorator.attr == "overload"))


def docstring(statement: ast.stmt) -> bool:
    return (isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant)
            and isinstance(statement.value.value, str))


class Stubber:
    """Turns one module's statements into ``Entry``s."""

    def __init__(self, source: Source) -> None:
        self.source = source
        # the names each class being read declares in its body (innermost last)
        self.declared: list[set[str]] = []
        # name -> the implementation of overloads, in the block being read
        self.implementations: dict[str, ast.FunctionDef | ast.AsyncFunctionDef] = {}

    def block(self, body: list[ast.stmt], in_class: bool) -> list[Entry]:
        # an overloaded function's implementation is no part of a stub: its docstring goes
        # to the overloads that have none (what an editor shows for each)
        overloaded = {s.name for s in body if isinstance(s, ast.FunctionDef | ast.AsyncFunctionDef)
                      and any(is_overload(d) for d in s.decorator_list)}
        for statement in body:
            if (isinstance(statement, ast.FunctionDef | ast.AsyncFunctionDef)
                    and statement.name in overloaded
                    and not any(is_overload(d) for d in statement.decorator_list)):
                self.implementations[statement.name] = statement
        entries: list[Entry] = []
        previous: Entry | None = None
        for at, statement in enumerate(body):
            if docstring(statement) and (at == 0 or previous is not None):
                text = reindent(self.source.node_text(statement), statement.col_offset)
                if previous is None:  # the block's docstring
                    entries.append(Entry("doc", text, set()))
                else:  # an attribute's, the string after it: goes (or stays) with it
                    previous.text += f"\n{text}"
                continue
            made = list(self.statement(statement, in_class))
            entries += made
            assigned = isinstance(statement, ast.Assign | ast.AnnAssign) and len(made) == 1
            previous = made[0] if assigned else None
        return entries

    def statement(self, node: ast.stmt, in_class: bool) -> Iterator[Entry]:
        source = self.source
        if isinstance(node, ast.If):
            checking = is_type_checking(node.test)
            if checking is None:
                raise source.error(node, "an `if` other than `if TYPE_CHECKING:` (a checker "
                                   "reads both branches; say in the stub what it should see)")
            yield from self.block(node.body if checking else node.orelse, in_class)
        elif isinstance(node, ast.Import | ast.ImportFrom):
            yield self.imported(node)
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            if self.implementations.get(node.name) is not node:
                yield self.function(node, in_class and bool(makes_attributes(node)
                                                           - self.declared[-1]))
        elif isinstance(node, ast.ClassDef):
            yield self.cls(node)
        elif isinstance(node, ast.AnnAssign):
            yield self.annotated(node, in_class)
        elif isinstance(node, ast.Assign):
            flat = [e for t in node.targets
                    for e in (t.elts if isinstance(t, ast.Tuple) else [t])]
            targets = tuple(t.id for t in flat if isinstance(t, ast.Name))
            if len(targets) != len(flat):
                raise source.error(node, "an assignment to something other than names")
            if targets == ("__slots__",):
                return  # for the class's own methods (none in a stub); mypy cannot type
                # it through the import cycle of the stubs and elements.pyi
            text = reindent(source.node_text(node), node.col_offset)
            yield Entry("assign", text, names_in([node.value]), targets)
        elif isinstance(node, ast.AugAssign):
            if not (isinstance(node.target, ast.Name) and node.target.id == "__all__"):
                raise source.error(node, "an augmented assignment other than `__all__ += ...`")
            yield Entry("assign", reindent(source.node_text(node), node.col_offset),
                        names_in([node.value]))
        elif isinstance(node, ast.Expr | ast.Raise | ast.Pass):
            return  # run-time effects only (a call, a docstring out of place, `raise`)
        else:
            raise source.error(node, f"a {type(node).__name__} statement at "
                               f"{'class' if in_class else 'module'} level")

    def imported(self, node: ast.Import | ast.ImportFrom) -> Entry:
        binds: dict[str, bool] = {}
        for alias in node.names:
            if alias.name == "*" or (isinstance(node, ast.ImportFrom)
                                     and node.module == "__future__"):
                binds[alias.name] = True
                continue
            bound = alias.asname or alias.name.partition(".")[0]
            binds[bound] = alias.asname is not None and alias.asname == alias.name
        return Entry("import", reindent(self.source.node_text(node), node.col_offset), set(),
                     binds=binds)

    def function(self, node: ast.FunctionDef | ast.AsyncFunctionDef,
                 keep_body: bool = False) -> Entry:
        source = self.source
        lines = [f"@{reindent(source.node_text(d), node.col_offset + 1)}"
                 for d in node.decorator_list]
        args = node.args
        refs = names_in([*node.decorator_list, node.returns, *args.defaults,
                         *args.kw_defaults, *(a.annotation for a in [
                             *args.posonlyargs, *args.args, *args.kwonlyargs,
                             *([args.vararg] if args.vararg else []),
                             *([args.kwarg] if args.kwarg else [])])])
        if keep_body:  # it makes attributes: checkers infer their types from it
            lines.append(reindent(source.node_text(node), node.col_offset))
            return Entry("def", "\n".join(lines), refs | names_in(node.body), (node.name,))
        head = reindent(source.header(node), node.col_offset)
        documented = node
        if not docstring(node.body[0]) and node.name in self.implementations:
            documented = self.implementations[node.name]
        if docstring(documented.body[0]):
            doc = reindent(source.node_text(documented.body[0]), documented.col_offset)
            lines.append(f"{head}:\n{INDENT}{doc}\n{INDENT}...")
        else:
            lines.append(f"{head}: ...")
        return Entry("def", "\n".join(lines), refs, (node.name,))

    def cls(self, node: ast.ClassDef) -> Entry:
        source = self.source
        lines = [f"@{reindent(source.node_text(d), node.col_offset + 1)}"
                 for d in node.decorator_list]
        lines.append(reindent(source.header(node), node.col_offset) + ":")
        protocol = any("Protocol" in names_in([base]) for base in node.bases)
        refs = names_in([*node.decorator_list, *node.bases, *node.keywords])
        self.declared.append(declared(node.body))
        members = self.block(node.body, in_class=True)
        self.declared.pop()
        return Entry("class", "\n".join(lines), refs, (node.name,), members=members,
                     keep_private=protocol)

    def annotated(self, node: ast.AnnAssign, in_class: bool) -> Entry:
        source = self.source
        if not isinstance(node.target, ast.Name):
            raise source.error(node, "an annotated assignment to something other than a name")
        value = node.value
        annotation = source.node_text(node.annotation)
        keep = value is not None and (
            annotation in BARE_ANNOTATIONS
            or isinstance(value, ast.Constant | ast.Name | ast.Attribute)
            or (isinstance(value, ast.UnaryOp) and isinstance(value.operand, ast.Constant))
            or (isinstance(value, ast.Call) and source.node_text(value.func) in KEPT_CALLS))
        if keep or value is None:
            text = reindent(source.node_text(node), node.col_offset)
        else:
            text = f"{node.target.id}: {reindent(annotation, node.annotation.col_offset)} = ..."
        # a class's annotated names stay, private or not: a dataclass's (or NamedTuple's)
        # fields make its __init__
        return Entry("assign", text, names_in([node.annotation, value if keep else None]),
                     () if in_class else (node.target.id,))


@dataclass
class Module:
    relative: str  # e.g. "_tree.py", "cli/check.py"
    entries: list[Entry]


def modules(source_dir: Path = SOURCE_DIR) -> list[Module]:
    found: list[Module] = []
    for path in sorted(source_dir.rglob("*.py")):
        relative = path.relative_to(source_dir)
        if relative.parts[0] in SKIPPED:
            continue
        source = Source(path, relative.as_posix())
        found.append(Module(relative.as_posix(), Stubber(source).block(source.tree.body,
                                                                      in_class=False)))
    return found


def generated_refs(directory: Path = GENERATED_DIR) -> set[str]:
    """The names the generated modules import from the runtime (checkers read them too)."""
    refs: set[str] = set()
    for path in sorted([*directory.glob("*.py"), *directory.glob("*.pyi")]):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("typed_mjcf"):
                refs |= {alias.name for alias in node.names}
    return refs


def _kept(entries: list[Entry], wanted: set[str], in_protocol: bool = False) -> list[Entry]:
    return [e for e in entries if not e.defines or in_protocol
            or any(not is_private(name) or name in wanted for name in e.defines)]


def _refs(entries: list[Entry], wanted: set[str], in_protocol: bool = False) -> set[str]:
    found: set[str] = set()
    for entry in _kept(entries, wanted, in_protocol):
        found |= entry.refs
        found |= _refs(entry.members, wanted, entry.keep_private)
    return found


def _text(entries: list[Entry], wanted: set[str], used: set[str],
          in_protocol: bool = False) -> list[str]:
    out: list[str] = []
    for entry in _kept(entries, wanted, in_protocol):
        if entry.kind == "import" and not any(again or name in used
                                              for name, again in entry.binds.items()):
            continue  # an import no kept text uses (one kept for any of its names stays
            # whole: an unused name costs a checker next to nothing)
        text = entry.text
        if entry.kind == "class":
            inner = "\n".join(_text(entry.members, wanted, used, entry.keep_private) or ["..."])
            text = f"{text}\n{indented(inner, INDENT)}"
        out.append(text)
    return out


def render(source_dir: Path = SOURCE_DIR, generated: Path = GENERATED_DIR) -> dict[str, str]:
    """``{path inside runtime-pyi/: text}``, one ``.pyi`` per runtime module."""
    found = modules(source_dir)
    outside = generated_refs(generated)
    wanted: set[str] = set(outside)
    while True:  # a private name a kept one names is kept: to a fixed point
        grown = set(outside)
        for module in found:
            grown |= _refs(module.entries, wanted)
        if grown == wanted:
            break
        wanted = grown
    files: dict[str, str] = {}
    for module in found:
        used = _refs(module.entries, wanted)
        # a blank line before each top-level class and function, for the reader
        body = "\n".join(f"\n{text}" if text.startswith(("class ", "def ", "@")) else text
                         for text in _text(module.entries, wanted, used))
        stub = module.relative.removesuffix(".py") + ".pyi"
        files[stub] = HEADER.format(source=module.relative) + body + "\n"
    return files


def stale(files: dict[str, str], directory: Path = STUBS_DIR) -> list[str]:
    """Stubs under ``directory`` that differ from ``files``, are missing or are extra."""
    return folder.stale(files, directory, "*.pyi")


def write(files: dict[str, str], directory: Path = STUBS_DIR) -> list[str]:
    """Make ``directory`` hold exactly ``files``; the stubs that changed."""
    return folder.write(files, directory, "*.pyi")
